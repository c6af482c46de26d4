#pragma once
// Colour maps for field pictures, all of them. Sequential fields use viridis (van der Walt &
// Smith, matplotlib 2015): perceptually uniform, readable in grey and by colour-blind readers,
// so equal steps of stress look like equal steps of colour. Signed fields around zero (the
// coherence C) use Moreland's cool-warm diverging map. Bodies (categorical) use the Tableau 10
// palette, cycled. The agglomerate view (paper 002 Fig. 8B) uses the diverging map's two ends
// and greys. A field is placed on its map by a linear or a logarithmic scale (ColourScale).
#include <array>
#include <vector>

namespace sg {

struct Rgb {
  double r = 0.0, g = 0.0, b = 0.0;  // in [0, 1]
};

// t in [0, 1] (clamped; NaN gives grey).
Rgb viridis(double t);

// Moreland's cool-warm diverging map: t in [0, 1] (clamped) from blue through light grey to
// red; NaN gives a dark grey (undefined).
Rgb cool_warm(double t);

// Colour of category k (k >= 0), cycling through 10 distinct colours.
Rgb category_colour(int k);

// The agglomerate view of paper 002 Fig. 8B: a grain's class +1 (C above the threshold:
// counter-clockwise, red), -1 (C below minus the threshold: clockwise, blue) or 0 (any other
// grain: light grey); NaN (a body that is not a grain): the dark grey of an undefined C.
Rgb agglomerate_colour(double grain_class);

// Where a value lies on a colour bar over [lo, hi]: 0 at lo, 1 at hi, not clamped (the map
// clamps). Linear, or logarithmic in the value (lo > 0): equal ratios take equal steps, so a
// field spanning decades (the strain rate inside grains and at their contacts) keeps its
// contrast at every scale; a value <= 0 lies below every positive one (-infinity: the bottom
// colour). NaN stays NaN (undefined: grey).
struct ColourScale {
  double lo = 0.0, hi = 1.0;
  bool log = false;
  double fraction(double v) const;
  double value_at(double fraction) const;  // the inverse, for the colour bar's ticks
};

// The powers of ten within [lo, hi] (0 < lo < hi), ascending: a log colour bar's labelled ticks.
std::vector<double> decades_within(double lo, double hi);

}  // namespace sg
