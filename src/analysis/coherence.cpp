#include "analysis/coherence.h"

#include <cmath>

#include "core/error.h"

namespace sg {
namespace {

struct Offset {
  int di, dj;
  double rx, ry;  // M - P (length)
};

// The nodes of a disc of radius R around a node, as index offsets. A relative slack keeps
// nodes exactly on the circle in, whatever the rounding of (di hx)^2 + (dj hy)^2.
std::vector<Offset> disc_stencil(const RegularGrid& g, double radius) {
  const int mi = static_cast<int>(std::floor(radius / g.hx));
  const int mj = static_cast<int>(std::floor(radius / g.hy));
  std::vector<Offset> s;
  const double r2 = radius * radius * (1.0 + 1e-12);
  for (int dj = -mj; dj <= mj; ++dj)
    for (int di = -mi; di <= mi; ++di) {
      const double rx = di * g.hx, ry = dj * g.hy;
      if (rx * rx + ry * ry <= r2) s.push_back({di, dj, rx, ry});
    }
  return s;
}

}  // namespace

CoherenceField compute_coherence(const VelocityGrid& velocity, const CoherenceParams& params) {
  const RegularGrid& g = velocity.grid;
  SG_VERIFY(params.radius > 0.0, "coherence: radius " << params.radius << " is not positive");
  SG_VERIFY(2 * static_cast<int>(std::floor(params.radius / g.hx)) + 1 <= g.nx,
            "coherence: radius " << params.radius << " too large for the period " << g.length
                                 << " (the disc would wrap onto itself)");
  const std::vector<Offset> stencil = disc_stencil(g, params.radius);
  CoherenceField out;
  out.grid = g;
  out.value.assign(g.size(), 0.0);
  out.defined.assign(g.size(), 0);
  const double tol2 = params.uniform_tolerance * params.uniform_tolerance;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const std::size_t centre = g.index(i, j);
      if (!velocity.valid[centre]) continue;
      // First pass: V_ave over the valid nodes of the disc.
      Vec2 sum = Vec2::Zero();
      std::size_t n = 0;
      for (const auto& o : stencil) {
        const int jj = j + o.dj;
        if (jj < 0 || jj >= g.ny) continue;
        const std::size_t m = g.index(g.wrap_i(i + o.di), jj);
        if (!velocity.valid[m]) continue;
        sum += velocity.velocity[m];
        ++n;
      }
      if (static_cast<double>(n) < params.min_valid_fraction * static_cast<double>(stencil.size()))
        continue;
      const Vec2 v_ave = sum / static_cast<double>(n);
      // Second pass: the three sums of eq. 5 (paper 002).
      double num = 0.0, dev2 = 0.0, circ2 = 0.0, speed2 = 0.0;
      for (const auto& o : stencil) {
        const int jj = j + o.dj;
        if (jj < 0 || jj >= g.ny) continue;
        const std::size_t m = g.index(g.wrap_i(i + o.di), jj);
        if (!velocity.valid[m]) continue;
        const Vec2 dev = velocity.velocity[m] - v_ave;
        const Vec2 circ(-o.ry, o.rx);  // e_z x (M - P), unit angular velocity
        num += dev.dot(circ);
        dev2 += dev.squaredNorm();
        circ2 += circ.squaredNorm();
        speed2 += velocity.velocity[m].squaredNorm();
      }
      out.defined[centre] = 1;
      // Uniform translation or rest: 0/0 in eq. 5, defined as C = 0 (see header).
      if (dev2 <= tol2 * speed2 || dev2 == 0.0 || circ2 == 0.0) continue;
      out.value[centre] = num / (std::sqrt(dev2) * std::sqrt(circ2));
    }
  return out;
}

}  // namespace sg
