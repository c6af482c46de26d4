#pragma once
// Around the drawing of a picture: the title (run, field, time) and frame number, a length
// scale bar, and the colour bar with the field's name, unit and range.
#include <cairo.h>

#include <string>

#include "render/frame_style.h"
#include "render/picture_layout.h"

namespace sg {

void draw_decorations(cairo_t* cr, const Layout& l, const Style& s, const Frame& f);

// A number as the pictures and their notes print it (3 significant digits).
std::string format_number(double v);

}  // namespace sg
