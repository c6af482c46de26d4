#include "render/frame_decorations.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "render/contact_outlines.h"

namespace sg {
namespace {

std::string unit_of(const std::string& field, const std::string& rate_unit) {
  if (field == "coherence") return "1";
  if (field.rfind("velocity", 0) == 0) return "length/time";
  if (field.rfind("displacement", 0) == 0) return "length";
  if (field == "green_lagrange_norm") return "1";
  if (field_shows_contact_rates(field)) return rate_unit.empty() ? "V/D or 1/time" : rate_unit;
  if (field == "von_mises" || field == "pressure" || field.rfind("sigma_", 0) == 0) return "stress";
  return "";
}

// 1, 2 or 5 times a power of ten, close to `target` from below.
double nice_length(double target) {
  const double p = std::pow(10.0, std::floor(std::log10(target)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * p <= target) return m * p;
  return p;
}

void draw_text(cairo_t* cr, double x, double y, const std::string& text, double size,
               double align = 0.0) {
  cairo_set_font_size(cr, size);
  cairo_text_extents_t e;
  cairo_text_extents(cr, text.c_str(), &e);
  cairo_move_to(cr, x - align * e.x_advance, y);
  cairo_show_text(cr, text.c_str());
}

}  // namespace

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

  // Scale bar under the drawing, bottom left.
  const double world_width = l.world.hi.x() - l.world.lo.x();
  const double length = nice_length(world_width / 5.0);
  const double bar_px = length * l.scale;
  const double bx = std::max(l.plot_x0, l.px(l.world.lo.x()));
  const double by = l.plot_y1 + 1.1 * l.font;
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

  if (!l.colour_bar) return;
  // Colour bar, right: the map sampled finely, the range at its ends, a few ticks between.
  const double cx = l.plot_x1 + 1.2 * l.font, cw = 1.3 * l.font;
  const double top = l.plot_y0 + 2.4 * l.font, bottom = l.plot_y1 - 0.5 * l.font;
  cairo_pattern_t* bar = cairo_pattern_create_linear(0, bottom, 0, top);
  for (int k = 0; k <= 20; ++k) {
    const Rgb c = s.diverging ? cool_warm(k / 20.0) : viridis(k / 20.0);
    cairo_pattern_add_color_stop_rgb(bar, k / 20.0, c.r, c.g, c.b);
  }
  cairo_rectangle(cr, cx, top, cw, bottom - top);
  cairo_set_source(cr, bar);
  cairo_fill_preserve(cr);
  cairo_pattern_destroy(bar);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  cairo_set_line_width(cr, 1.0);
  cairo_stroke(cr);
  const std::string unit = unit_of(s.field, s.rate_unit);
  draw_text(cr, cx, top - 1.5 * l.font, s.field, 0.85 * l.font);
  if (!unit.empty()) draw_text(cr, cx, top - 0.5 * l.font, "(" + unit + ")", 0.75 * l.font);
  const int ticks = 5;
  for (int k = 0; k < ticks; ++k) {
    const double t = static_cast<double>(k) / (ticks - 1);
    const double y = bottom - t * (bottom - top);
    cairo_move_to(cr, cx + cw, y);
    cairo_line_to(cr, cx + cw + 0.35 * l.font, y);
    cairo_stroke(cr);
    draw_text(cr, cx + cw + 0.55 * l.font, y + 0.3 * l.font,
              format_number(s.lo + t * (s.hi - s.lo)), 0.8 * l.font);
  }
}

}  // namespace sg
