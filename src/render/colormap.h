#pragma once
// Colour maps for field pictures, all of them. Sequential fields use viridis (van der Walt &
// Smith, matplotlib 2015): perceptually uniform, readable in grey and by colour-blind readers,
// so equal steps of stress look like equal steps of colour. Signed fields around zero (the
// coherence C) use Moreland's cool-warm diverging map. Bodies (categorical) use the Tableau 10
// palette, cycled.
#include <array>

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

}  // namespace sg
