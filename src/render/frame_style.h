#pragma once
// What one picture of a series draws (Frame: a snapshot, its time and contact rates) and how
// (Style: the field, its colour map and range, the periodic span), shared by the drawing of the
// bodies (render/frame_drawing.h) and of the title, scale and colour bars
// (render/frame_decorations.h).
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "render/colormap.h"
#include "render/vtu_reader.h"

namespace sg {

struct Frame {
  const VtuMesh* mesh = nullptr;
  double time = 0.0;
  std::string label;                  // snapshot number
  std::vector<double> contact_value;  // per point: its contact rate (NaN: none); may be empty
};

struct Style {
  std::string field;
  std::string rate_unit;  // RenderOptions::strain_rate_unit
  bool categorical = false;
  bool diverging = false;     // cool-warm instead of viridis
  bool agglomerates = false;  // the values are grain classes (agglomerate_colour)
  double threshold = 0.8;     // agglomerates: the |C| a grain's class was cut at
  double lo = 0.0, hi = 1.0;
  bool log = false;  // logarithmic colour scale over [lo, hi] (lo > 0)
  std::optional<std::pair<double, double>> periodic;
  std::string title;
};

inline ColourScale scale_of(const Style& s) {
  return {s.lo, s.hi, s.log};
}

// The colour of value v: by category or agglomerate class, or on the field's map over
// [lo, hi].
inline Rgb colour_of(const Style& s, double v) {
  if (s.categorical) return category_colour(static_cast<int>(std::lround(v)));
  if (s.agglomerates) return agglomerate_colour(v);
  const double t = scale_of(s).fraction(v);
  return s.diverging ? cool_warm(t) : viridis(t);
}

}  // namespace sg
