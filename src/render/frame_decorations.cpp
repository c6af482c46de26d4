#include "render/frame_decorations.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "render/colour_bar.h"

namespace sg {
namespace {

// 1, 2 or 5 times a power of ten, close to `target` from below.
double nice_length(double target) {
  const double p = std::pow(10.0, std::floor(std::log10(target)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * p <= target) return m * p;
  return p;
}

}  // namespace

void draw_text(cairo_t* cr, double x, double y, const std::string& text, double size,
               double align) {
  cairo_set_font_size(cr, size);
  cairo_text_extents_t e;
  cairo_text_extents(cr, text.c_str(), &e);
  cairo_move_to(cr, x - align * e.x_advance, y);
  cairo_show_text(cr, text.c_str());
}

std::string format_number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

void draw_decorations(cairo_t* cr, const Layout& l, const Style& s, const Frame& f) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  // Title: run, field, time.
  std::ostringstream title;
  if (!s.title.empty()) title << s.title << "   ";
  title << s.field << "   t = " << format_number(f.time);
  draw_text(cr, l.plot_x0, 1.4 * l.font, title.str(), l.font);
  draw_text(cr, l.width - l.font, 1.4 * l.font, "frame " + f.label, 0.8 * l.font, 1.0);

  // Scale bar under the drawing (not under the drawing area when the drawing is narrower and
  // centred in it), left.
  const double world_width = l.world.hi.x() - l.world.lo.x();
  const double length = nice_length(world_width / 5.0);
  const double bar_px = length * l.scale;
  const double bx = std::max(l.plot_x0, l.px(l.world.lo.x()));
  const double by = std::min(l.plot_y1, l.py(l.world.lo.y())) + 1.1 * l.font;
  cairo_rectangle(cr, bx, by, bar_px, 0.35 * l.font);
  cairo_fill(cr);
  for (double x : {bx, bx + bar_px}) {
    cairo_move_to(cr, x, by - 0.25 * l.font);
    cairo_line_to(cr, x, by + 0.6 * l.font);
  }
  cairo_set_line_width(cr, 1.0);
  cairo_stroke(cr);
  draw_text(cr, bx + bar_px + 0.6 * l.font, by + 0.45 * l.font, format_number(length) + " (length)",
            0.85 * l.font);

  draw_colour_key(cr, l, s);
}

}  // namespace sg
