#include "analysis/activated_thickness.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/error.h"
#include "io/atomic_file.h"

namespace sg {
namespace {

void check(double v_bottom, double v_top, const AttThresholds& t) {
  SG_VERIFY(
      std::isfinite(v_bottom) && std::isfinite(v_top) && v_top != v_bottom,
      "activated thickness: no velocity jump (v_bottom " << v_bottom << ", v_top " << v_top << ")");
  SG_VERIFY(t.lo < t.hi, "activated thickness: thresholds " << t.lo << " >= " << t.hi);
}

bool activated(double vx, double v_bottom, double v_top, const AttThresholds& t) {
  const double u = (vx - v_bottom) / (v_top - v_bottom);
  return u >= t.lo && u <= t.hi;
}

}  // namespace

double activated_thickness_from_grains(const GrainSnapshot& snapshot, double v_bottom, double v_top,
                                       double layer_thickness, const AttThresholds& thresholds) {
  check(v_bottom, v_top, thresholds);
  SG_VERIFY(layer_thickness > 0.0,
            "activated thickness: layer thickness " << layer_thickness << " <= 0");
  SG_VERIFY(snapshot.size() > 0, "activated thickness: no grain at t = " << snapshot.time);
  double total = 0.0, active = 0.0;
  for (std::size_t i = 0; i < snapshot.size(); ++i) {
    total += snapshot.area[i];
    if (activated(snapshot.velocity[i].x(), v_bottom, v_top, thresholds))
      active += snapshot.area[i];
  }
  return layer_thickness * active / total;
}

double activated_thickness_from_profile(const VelocityProfile& profile, double v_bottom,
                                        double v_top, const AttThresholds& thresholds) {
  check(v_bottom, v_top, thresholds);
  SG_VERIFY(!profile.bins.empty(), "activated thickness: empty profile");
  const double height = (profile.y_max - profile.y_min) / static_cast<double>(profile.bins.size());
  double thickness = 0.0;
  for (const ProfileBin& bin : profile.bins)
    if (bin.count > 0 && activated(bin.vx_mean, v_bottom, v_top, thresholds)) thickness += height;
  return thickness;
}

AttSeries activated_thickness_series(std::span<const GrainSnapshot> snapshots, double v_bottom,
                                     double v_top, double layer_thickness, double y_min,
                                     double y_max, int bins, const AttThresholds& thresholds) {
  SG_VERIFY(!snapshots.empty(), "activated thickness: no snapshot");
  AttSeries s;
  s.thresholds = thresholds;
  s.layer_thickness = layer_thickness;
  s.profile_bins = bins;
  for (const GrainSnapshot& snap : snapshots) {
    AttSample a;
    a.time = snap.time;
    a.from_grains =
        activated_thickness_from_grains(snap, v_bottom, v_top, layer_thickness, thresholds);
    const VelocityProfile p =
        compute_velocity_profile(std::span<const GrainSnapshot>(&snap, 1), y_min, y_max, bins);
    a.from_profile = activated_thickness_from_profile(p, v_bottom, v_top, thresholds);
    s.mean_from_grains += a.from_grains;
    s.mean_from_profile += a.from_profile;
    s.samples.push_back(a);
  }
  s.mean_from_grains /= static_cast<double>(s.samples.size());
  s.mean_from_profile /= static_cast<double>(s.samples.size());
  return s;
}

void write_att_csv(const std::string& path, const AttSeries& series) {
  std::ostringstream out;
  out << std::setprecision(12) << "time,att_map,att_profile\n";
  for (const AttSample& a : series.samples)
    out << a.time << ',' << a.from_grains << ',' << a.from_profile << '\n';
  write_file_atomically(path, out.str());
}

}  // namespace sg
