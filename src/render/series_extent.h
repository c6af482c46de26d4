#pragma once
// What a series of pictures shares (render/snapshot_renderer.h), measured over the frames drawn
// (render/frame_selection.h): the box that holds them, and the field's coloured values (the
// contact rates on the outlines included) from which render/colour_range.h picks the range.
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "geometry/bounding_box.h"
#include "render/frame_style.h"
#include "render/snapshot_renderer.h"
#include "render/vtu_reader.h"

namespace sg {

// Pass 1, over the frames drawn: the drawing box, and (for a field read from the .vtu with no
// given range) the range of the coloured values with every value for the robust range.
struct SeriesExtent {
  BoundingBox world;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  std::vector<double> values;
  std::string contact_note;  // why the contact rates are not drawn (render/contact_outlines.h)
};

SeriesExtent measure_series(const std::vector<PvdEntry>& entries, const Style& style,
                            const RenderOptions& options, const std::filesystem::path& pvd);

}  // namespace sg
