#include "analysis/regular_grid.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace sg {

RegularGrid make_periodic_grid(double x0, double length, double y_min, double y_max,
                               double spacing) {
  SG_VERIFY(length > 0.0, "grid: period length " << length << " is not positive");
  SG_VERIFY(spacing > 0.0, "grid: spacing " << spacing << " is not positive");
  SG_VERIFY(y_max >= y_min, "grid: y_max " << y_max << " < y_min " << y_min);
  RegularGrid g;
  g.x0 = x0;
  g.length = length;
  g.y0 = y_min;
  g.nx = std::max(1, static_cast<int>(std::lround(length / spacing)));
  g.hx = length / g.nx;
  g.hy = spacing;
  // A relative tolerance so that a span that is an exact multiple of the spacing, up to
  // rounding, gets its last row.
  g.ny = 1 + static_cast<int>(std::floor((y_max - y_min) / spacing * (1.0 + 1e-12)));
  return g;
}

}  // namespace sg
