#pragma once
// Around the drawing of a picture: the title (run, field, time) and frame number, a length
// scale bar, and the colour key (render/colour_bar.h).
#include <cairo.h>

#include <string>

#include "render/frame_style.h"
#include "render/picture_layout.h"

namespace sg {

void draw_decorations(cairo_t* cr, const Layout& l, const Style& s, const Frame& f);

// A number as the pictures and their notes print it (3 significant digits).
std::string format_number(double v);

// Text at (x, y) (the baseline), `align` 0 left, 1 right of x; leaves the current point at its
// end.
void draw_text(cairo_t* cr, double x, double y, const std::string& text, double size,
               double align = 0.0);

}  // namespace sg
