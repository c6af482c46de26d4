#include "render/colour_bar.h"

#include <cmath>

#include "render/contact_outlines.h"
#include "render/frame_decorations.h"

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

std::vector<BarTick> log_ticks(const ColourScale& scale) {
  std::vector<BarTick> ticks;
  const std::vector<double> decades = decades_within(scale.lo, scale.hi);
  const auto add = [&](double v, std::string label, std::string exponent) {
    ticks.push_back({v, scale.fraction(v), std::move(label), std::move(exponent)});
  };
  if (decades.size() < 2) add(scale.lo, format_number(scale.lo), "");
  for (const double d : decades) {
    add(d, "10", std::to_string(static_cast<int>(std::lround(std::log10(d)))));
    for (int m = 2; m <= 9; ++m)
      if (m * d < scale.hi) add(m * d, "", "");
  }
  // Minor ticks in the part-decade below the first power of ten.
  const double below =
      decades.empty() ? std::pow(10.0, std::floor(std::log10(scale.lo))) : decades.front() / 10.0;
  for (int m = 2; m <= 9; ++m)
    if (m * below > scale.lo && m * below < scale.hi &&
        (decades.empty() || m * below < decades.front()))
      add(m * below, "", "");
  if (decades.size() < 2) add(scale.hi, format_number(scale.hi), "");
  return ticks;
}

void draw_tick(cairo_t* cr, const Layout& l, double x, double y, const BarTick& t) {
  const double length = t.label.empty() ? 0.2 * l.font : 0.35 * l.font;
  cairo_move_to(cr, x, y);
  cairo_line_to(cr, x + length, y);
  cairo_stroke(cr);
  if (t.label.empty()) return;
  const double size = 0.8 * l.font;
  draw_text(cr, x + 0.55 * l.font, y + 0.3 * l.font, t.label, size);
  if (t.exponent.empty()) return;
  // The exponent raised and smaller after the label's current point (10^-3).
  double cx = 0.0, cy = 0.0;
  cairo_get_current_point(cr, &cx, &cy);
  draw_text(cr, cx + 0.05 * l.font, cy - 0.4 * l.font, t.exponent, 0.6 * l.font);
}

void draw_field_bar(cairo_t* cr, const Layout& l, const Style& s, double cx, double top,
                    double bottom) {
  const double cw = 1.3 * l.font;
  // The map sampled finely; a log scale changes where values sit, not the bar's colours.
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
  for (const BarTick& t : colour_bar_ticks(s))
    draw_tick(cr, l, cx + cw, bottom - t.fraction * (bottom - top), t);
}

// The agglomerate view's legend: a swatch and a line or two per colour.
void draw_agglomerate_legend(cairo_t* cr, const Layout& l, const Style& s, double cx, double top) {
  const std::string c = format_number(s.threshold);
  const struct {
    double grain_class;
    std::string line1, line2;
  } rows[] = {{1.0, "C > " + c, "anticlockwise"},
              {-1.0, "C < -" + c, "clockwise"},
              {0.0, "|C| <= " + c, "other grains"},
              {std::nan(""), "not a grain", ""}};
  double y = top;
  for (const auto& row : rows) {
    const Rgb colour = agglomerate_colour(row.grain_class);
    cairo_rectangle(cr, cx, y, 1.3 * l.font, 1.3 * l.font);
    cairo_set_source_rgb(cr, colour.r, colour.g, colour.b);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_set_line_width(cr, 1.0);
    cairo_stroke(cr);
    draw_text(cr, cx + 1.8 * l.font, y + 0.6 * l.font, row.line1, 0.8 * l.font);
    if (!row.line2.empty())
      draw_text(cr, cx + 1.8 * l.font, y + 1.45 * l.font, row.line2, 0.65 * l.font);
    y += 2.4 * l.font;
  }
}

}  // namespace

std::vector<BarTick> colour_bar_ticks(const Style& s) {
  const ColourScale scale = scale_of(s);
  if (s.log) return log_ticks(scale);
  std::vector<BarTick> ticks;
  const int count = 5;
  for (int k = 0; k < count; ++k) {
    const double f = static_cast<double>(k) / (count - 1);
    const double v = scale.value_at(f);
    ticks.push_back({v, f, format_number(v), ""});
  }
  return ticks;
}

void draw_colour_key(cairo_t* cr, const Layout& l, const Style& s) {
  if (!l.colour_bar) return;
  const double cx = l.plot_x1 + 1.2 * l.font;
  const double top = l.plot_y0 + 2.4 * l.font, bottom = l.plot_y1 - 0.5 * l.font;
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  draw_text(cr, cx, top - 1.5 * l.font, s.field, 0.85 * l.font);
  if (s.agglomerates) {
    draw_agglomerate_legend(cr, l, s, cx, top);
    return;
  }
  const std::string unit = unit_of(s.field, s.rate_unit);
  if (!unit.empty())
    draw_text(cr, cx, top - 0.5 * l.font, "(" + unit + (s.log ? ", log scale)" : ")"),
              0.75 * l.font);
  else if (s.log)
    draw_text(cr, cx, top - 0.5 * l.font, "(log scale)", 0.75 * l.font);
  draw_field_bar(cr, l, s, cx, top, bottom);
}

}  // namespace sg
