#pragma once
// One picture of a series as a PNG file: the bodies and the decorations drawn on a white
// Cairo image, the softgrain version recorded in it (render/png_text.h), written atomically
// (io/atomic_file.h): a reader never sees half a picture.
#include <filesystem>

#include "render/frame_style.h"
#include "render/picture_layout.h"

namespace sg {

void write_png(const Layout& l, const Style& s, const Frame& f, const std::filesystem::path& path);

}  // namespace sg
