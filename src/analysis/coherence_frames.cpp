#include "analysis/coherence_frames.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>

#include "analysis/velocity_grid.h"
#include "core/error.h"

namespace sg {

CoherenceSetup choose_coherence_setup(std::span<const GrainSnapshot> snapshots,
                                      double mean_diameter,
                                      std::optional<std::pair<double, double>> periodic,
                                      std::optional<std::pair<double, double>> layer) {
  SG_VERIFY(mean_diameter > 0.0,
            "coherence: mean grain diameter " << mean_diameter << " is not positive");
  CoherenceSetup s;
  const double d = mean_diameter;
  s.params.grid_spacing = d;                        // paper 002 §2.2: Delta x = 1 diameter
  s.params.interpolation.support_radius = 2.0 * d;  // below R, see velocity_grid.h
  s.params.coherence.radius = 2.5 * d;              // paper 002 §2.2: 2 to 3 diameters
  s.params.threshold = 0.8;                         // paper 002 §2.2
  double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo;
  double y_lo = x_lo, y_hi = -x_lo;
  for (const GrainSnapshot& snap : snapshots)
    for (const Vec2& p : snap.position) {
      x_lo = std::min(x_lo, p.x());
      x_hi = std::max(x_hi, p.x());
      y_lo = std::min(y_lo, p.y());
      y_hi = std::max(y_hi, p.y());
    }
  SG_VERIFY(x_hi >= x_lo, "coherence: no grain in any snapshot");
  if (layer) {
    y_lo = layer->first;
    y_hi = layer->second;
  }
  std::ostringstream note;
  if (periodic) {
    s.periodic = true;
    s.grid = make_periodic_grid(periodic->first, periodic->second - periodic->first, y_lo, y_hi, d);
    note << "periodic grid over x in [" << periodic->first << ", " << periodic->second << ")";
  } else {
    // Padding beyond the reach of the fit and of the disc, plus one cell for rounding.
    const double pad =
        std::max(s.params.interpolation.support_radius, s.params.coherence.radius) + 2.0 * d;
    s.grid = make_periodic_grid(x_lo - pad, (x_hi - x_lo) + 2.0 * pad, y_lo, y_hi, d);
    note << "not periodic: grid over the grains' x span [" << x_lo << ", " << x_hi << "] padded by "
         << pad << " on both sides (nothing wraps)";
  }
  note << ", y in [" << y_lo << ", " << y_hi << "] ("
       << (layer ? "given layer" : "span of the grain centres") << "), " << s.grid.nx << " x "
       << s.grid.ny << " nodes, spacing " << s.grid.hx << " x " << s.grid.hy;
  s.note = note.str();
  return s;
}

double coherence_at(const CoherenceField& field, const Vec2& p) {
  const RegularGrid& g = field.grid;
  const double fx = (p.x() - g.x0) / g.hx;
  const double fy = (p.y() - g.y0) / g.hy;
  const double jf = std::floor(fy);
  // Half a cell of slack beyond the first and last rows (a grain centre just outside the
  // span of the centres cannot occur, but a given layer may cut grains).
  if (fy < -0.5 || fy > (g.ny - 1) + 0.5) return std::numeric_limits<double>::quiet_NaN();
  const double i_floor = std::floor(fx);
  const double ax = fx - i_floor;
  const double ay = std::clamp(fy - jf, 0.0, 1.0);
  const int i0 = g.wrap_i(static_cast<int>(std::fmod(i_floor, static_cast<double>(g.nx))));
  const int j0 = static_cast<int>(jf);
  double sum = 0.0, weight = 0.0;
  for (int dj = 0; dj <= 1; ++dj)
    for (int di = 0; di <= 1; ++di) {
      const int j = j0 + dj;
      if (j < 0 || j >= g.ny) continue;
      const std::size_t n = g.index(g.wrap_i(i0 + di), j);
      if (!field.defined[n]) continue;
      const double w = (di ? ax : 1.0 - ax) * (dj ? ay : 1.0 - ay);
      sum += w * field.value[n];
      weight += w;
    }
  // A corner weight can be 0 exactly (p on a grid line): then only the others count.
  if (!(weight > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return sum / weight;
}

double mean_equivalent_diameter(const GrainSnapshot& snapshot) {
  if (snapshot.size() == 0) return std::numeric_limits<double>::quiet_NaN();
  double sum = 0.0;
  for (double a : snapshot.area)
    sum += 2.0 * std::sqrt(a / std::numbers::pi);
  return sum / static_cast<double>(snapshot.size());
}

GrainCoherence grain_coherence(std::span<const GrainSnapshot> snapshots, double mean_diameter,
                               std::optional<std::pair<double, double>> periodic) {
  const CoherenceSetup setup = choose_coherence_setup(snapshots, mean_diameter, periodic, {});
  GrainCoherence out;
  out.note = setup.note;
  for (const GrainSnapshot& snap : snapshots) {
    const CoherenceField c =
        compute_coherence(interpolate_velocity_grid(snap, setup.grid, setup.params.interpolation),
                          setup.params.coherence);
    std::vector<double> by_body;
    for (std::size_t g = 0; g < snap.size(); ++g) {
      int id = -1;
      try {
        id = std::stoi(snap.body[g]);
      } catch (const std::exception&) {
        SG_THROW("coherence at the grains: grain snapshot at t = "
                 << snap.time << ": body '" << snap.body[g] << "' is not a body number");
      }
      SG_VERIFY(id >= 0 && id < (1 << 24), "coherence at the grains: body number " << id);
      if (by_body.size() <= static_cast<std::size_t>(id))
        by_body.resize(static_cast<std::size_t>(id) + 1, std::numeric_limits<double>::quiet_NaN());
      by_body[static_cast<std::size_t>(id)] = coherence_at(c, snap.position[g]);
    }
    out.by_body.push_back(std::move(by_body));
  }
  return out;
}

}  // namespace sg
