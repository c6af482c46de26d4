#include "render/colour_range.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>

#include "core/error.h"
#include "render/frame_decorations.h"

namespace sg {
namespace {

struct ColourRange {
  double lo = 0.0, hi = 0.0;
  std::string source;
  std::string note;  // a hint for the command's output
};

double quantile(std::vector<double>& v, double q) {
  const auto k = static_cast<std::size_t>(std::lround(q * static_cast<double>(v.size() - 1)));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

double below_by_decades(double top) {
  return top * std::pow(10.0, -kLogDecades);
}

std::string decades_text() {
  return format_number(kLogDecades) + " decades";
}

// Item 3 of colour_range.h, when it applies.
std::optional<ColourRange> shear_cell_velocity_range(const RenderOptions& o) {
  if (!o.shear_velocity || !(*o.shear_velocity > 0.0) || o.robust_range) return std::nullopt;
  const double half = 0.5 * *o.shear_velocity;
  const std::string v = "V = " + format_number(*o.shear_velocity);
  if (o.field == "velocity_x" || o.field == "velocity_y")
    return ColourRange{-half, half, "\u00b1V/2 of the shear cell, " + v, ""};
  if (o.field == "velocity") {
    // The speed: 0 in the layer's middle, V/2 at the first bodies; faster grains (rare
    // fluctuations) take the top colour.
    if (o.log_scale)
      return ColourRange{below_by_decades(half), half,
                         "V/2 of the shear cell and " + decades_text() + " below, " + v, ""};
    return ColourRange{0.0, half, "0 to V/2 of the shear cell, " + v, ""};
  }
  return std::nullopt;
}

// Item 4, log scale: the top from the positive values.
ColourRange log_range_from_values(const SeriesExtent& e, const RenderOptions& o) {
  std::vector<double> positive;
  std::copy_if(e.values.begin(), e.values.end(), std::back_inserter(positive),
               [](double v) { return v > 0.0; });
  SG_VERIFY(!positive.empty(), "render --log: field '" << o.field
                                                       << "' has no positive value in the frames "
                                                          "drawn: nothing to place on a log scale");
  const double top = o.robust_range ? quantile(positive, 0.99)
                                    : *std::max_element(positive.begin(), positive.end());
  return {below_by_decades(top), top,
          (o.robust_range ? "99th percentile of the positive values over the frames drawn and "
                          : "maximum over the frames drawn and ") +
              decades_text() + " below",
          ""};
}

// Item 4, linear scale.
ColourRange range_from_values(SeriesExtent& e, const RenderOptions& o) {
  ColourRange r{e.lo, e.hi, "min-max over the frames drawn", ""};
  if (e.values.empty()) return r;
  const double q01 = quantile(e.values, 0.01), q99 = quantile(e.values, 0.99);
  if (o.robust_range) return {q01, q99, "1st-99th percentile over the frames drawn", ""};
  if (r.hi > r.lo && q99 - q01 < 0.2 * (r.hi - r.lo))
    r.note = "98% of the values lie in [" + format_number(q01) + ", " + format_number(q99) +
             "], a fifth of the full range: try --robust or --range";
  return r;
}

ColourRange pick_range(SeriesExtent& e, const RenderOptions& o) {
  if (o.range) return {o.range->first, o.range->second, "given", ""};
  // C lies in [-1, 1] (Cauchy-Schwarz, analysis/coherence.h): one fixed range for every run.
  if (o.field == "coherence") return {-1.0, 1.0, "fixed: C in [-1, 1]", ""};
  if (auto shear = shear_cell_velocity_range(o)) return *shear;
  return o.log_scale ? log_range_from_values(e, o) : range_from_values(e, o);
}

}  // namespace

void choose_range(SeriesExtent& e, Style& style, const RenderOptions& options,
                  RenderResult& result) {
  const ColourRange r = pick_range(e, options);
  SG_VERIFY(r.hi >= r.lo, "field '" << options.field
                                    << "': no point of any snapshot drawn is coloured by it"
                                    << " (rigid bodies only?)");
  style.lo = r.lo;
  style.hi = r.hi;
  style.log = options.log_scale;
  result.has_range = true;
  result.range_min = r.lo;
  result.range_max = r.hi;
  result.range_source = r.source;
  if (!r.note.empty()) result.note += (result.note.empty() ? "" : "; ") + r.note;
}

}  // namespace sg
