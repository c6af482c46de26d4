#pragma once
// The colour key at the right of a picture: for a field, a bar of its map with the field's name,
// unit and ticks (evenly spaced values on a linear scale; the powers of ten, labelled 10^k,
// with unlabelled 2..9 between them, on a log scale); for the agglomerate view, a legend of its
// three grain colours and the threshold.
#include <cairo.h>

#include <string>
#include <vector>

#include "render/frame_style.h"
#include "render/picture_layout.h"

namespace sg {

struct BarTick {
  double value = 0.0;
  double fraction = 0.0;  // along the bar, 0 at the bottom (lo), 1 at the top (hi)
  std::string label;      // empty: a minor tick
  std::string exponent;   // drawn raised after the label (the k of 10^k); may be empty
};

// The ticks of a field's colour bar. Linear: 5, lo to hi. Log: every power of ten within
// [lo, hi] (labelled) and 2..9 times them (not); the ends labelled too when fewer than two
// powers of ten fall inside.
std::vector<BarTick> colour_bar_ticks(const Style& s);

// Draws the key into the layout's right band (nothing when the layout has no colour bar).
void draw_colour_key(cairo_t* cr, const Layout& l, const Style& s);

}  // namespace sg
