#include "analysis/profiles.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "core/error.h"
#include "io/atomic_file.h"

namespace sg {

VelocityProfile compute_velocity_profile(std::span<const GrainSnapshot> snapshots, double y_min,
                                         double y_max, int bin_count) {
  SG_VERIFY(y_max > y_min, "velocity profile: y_max " << y_max << " <= y_min " << y_min);
  SG_VERIFY(bin_count >= 1, "velocity profile: bin count " << bin_count << " < 1");
  VelocityProfile p;
  p.y_min = y_min;
  p.y_max = y_max;
  const auto nb = static_cast<std::size_t>(bin_count);
  const double width = (y_max - y_min) / bin_count;
  // Accumulate sums of deviations from a per-bin shift (the first sample) rather than raw
  // sums of squares: velocities with a large common drift would otherwise lose the
  // fluctuations to cancellation.
  std::vector<double> sx(nb, 0.0), sxx(nb, 0.0), sy(nb, 0.0), syy(nb, 0.0), kx(nb, 0.0),
      ky(nb, 0.0);
  p.bins.resize(nb);
  for (const auto& s : snapshots)
    for (std::size_t i = 0; i < s.size(); ++i) {
      const double y = s.position[i].y();
      if (!(y >= y_min && y <= y_max)) {
        ++p.outside;
        continue;
      }
      const auto b = std::min(nb - 1, static_cast<std::size_t>((y - y_min) / width));
      if (p.bins[b].count == 0) {
        kx[b] = s.velocity[i].x();
        ky[b] = s.velocity[i].y();
      }
      const double dx = s.velocity[i].x() - kx[b], dy = s.velocity[i].y() - ky[b];
      sx[b] += dx;
      sxx[b] += dx * dx;
      sy[b] += dy;
      syy[b] += dy * dy;
      ++p.bins[b].count;
    }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t b = 0; b < nb; ++b) {
    ProfileBin& bin = p.bins[b];
    bin.y_center = y_min + (static_cast<double>(b) + 0.5) * width;
    if (bin.count == 0) {
      bin.vx_mean = bin.vx_std = bin.vy_mean = bin.vy_std = nan;
      continue;
    }
    const double n = static_cast<double>(bin.count);
    bin.vx_mean = kx[b] + sx[b] / n;
    bin.vy_mean = ky[b] + sy[b] / n;
    if (bin.count > 1) {
      bin.vx_std = std::sqrt(std::max(0.0, (sxx[b] - sx[b] * sx[b] / n) / (n - 1.0)));
      bin.vy_std = std::sqrt(std::max(0.0, (syy[b] - sy[b] * sy[b] / n) / (n - 1.0)));
    }
  }
  return p;
}

void write_velocity_profile_csv(const std::string& path, const VelocityProfile& profile) {
  std::ostringstream out;
  out << std::setprecision(17);
  out << "y_center,count,vx_mean,vx_std,vy_mean,vy_std\n";
  for (const auto& b : profile.bins)
    out << b.y_center << ',' << b.count << ',' << b.vx_mean << ',' << b.vx_std << ',' << b.vy_mean
        << ',' << b.vy_std << '\n';
  write_file_atomically(path, out.str());
}

double solid_fraction(const GrainSnapshot& snapshot, double length, double y_min, double y_max) {
  SG_VERIFY(length > 0.0 && y_max > y_min, "solid fraction: layer " << length << " x [" << y_min
                                                                    << ", " << y_max
                                                                    << "] has no area");
  double matter = 0.0;
  for (const double a : snapshot.area)
    matter += a;
  return matter / (length * (y_max - y_min));  // paper 002 §3.3, S_F
}

double mean_solid_fraction(std::span<const GrainSnapshot> snapshots, double length, double y_min,
                           double y_max) {
  SG_VERIFY(!snapshots.empty(), "solid fraction: no snapshot");
  double sum = 0.0;
  for (const auto& s : snapshots)
    sum += solid_fraction(s, length, y_min, y_max);
  return sum / static_cast<double>(snapshots.size());
}

}  // namespace sg
