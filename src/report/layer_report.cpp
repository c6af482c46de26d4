#include <algorithm>
#include <cmath>

#include "analysis/activated_thickness.h"
#include "analysis/profiles.h"
#include "core/error.h"
#include "report/analyze_steps.h"

namespace sg::report {
namespace {

namespace fs = std::filesystem;

// The span of the grain centres over the window, and the grains' extent (mean lowest
// grain bottom, mean highest grain top; a grain's radius from its area).
struct LayerSpan {
  double centre_lo = INFINITY, centre_hi = -INFINITY;
  double extent_lo = 0.0, extent_hi = 0.0;
};

LayerSpan layer_span(std::span<const GrainSnapshot> window_snaps) {
  LayerSpan span;
  for (const GrainSnapshot& snap : window_snaps) {
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t i = 0; i < snap.size(); ++i) {
      const double y = snap.position[i].y(), radius = std::sqrt(snap.area[i] / M_PI);
      span.centre_lo = std::min(span.centre_lo, y);
      span.centre_hi = std::max(span.centre_hi, y);
      lo = std::min(lo, y - radius);
      hi = std::max(hi, y + radius);
    }
    span.extent_lo += lo;
    span.extent_hi += hi;
  }
  span.extent_lo /= static_cast<double>(window_snaps.size());
  span.extent_hi /= static_cast<double>(window_snaps.size());
  return span;
}

// Profiles: over the given layer, else over the span of the grain centres.
// The profile's y range and bins: the given layer, else the span of the grain centres;
// the given bins, else two per mean diameter.
struct ProfileRange {
  double y0 = 0.0, y1 = 0.0;
  int bins = 20;
};

ProfileRange profile_range(const AnalyzeResult& r, const LayerSpan& span,
                           const AnalyzeOptions& options) {
  const RunParameters& p = r.parameters;
  ProfileRange range;
  range.y0 = options.layer ? options.layer->first : span.centre_lo;
  range.y1 = options.layer ? options.layer->second : span.centre_hi;
  range.bins = options.profile_bins;
  if (range.bins <= 0)
    range.bins =
        std::isfinite(p.mean_diameter) && p.mean_diameter > 0.0
            ? std::clamp(
                  static_cast<int>(std::lround(2.0 * (range.y1 - range.y0) / p.mean_diameter)), 4,
                  200)
            : 20;
  return range;
}

void analyze_profile(AnalyzeResult& r, std::span<const GrainSnapshot> window_snaps,
                     const LayerSpan& span, const AnalyzeOptions& options,
                     const fs::path& run_dir) {
  const ProfileRange range = profile_range(r, span, options);
  const double y0 = range.y0, y1 = range.y1;
  const int bins = range.bins;
  try {
    r.profile = compute_velocity_profile(window_snaps, y0, y1, bins);
    r.profile_path = run_dir / "analysis" / "profiles.csv";
    write_velocity_profile_csv(r.profile_path.string(), *r.profile);
    if (!options.layer)
      r.notes.push_back("profile: " + std::to_string(bins) +
                        " bins over the span of the grain "
                        "centres [" +
                        number(y0) + ", " + number(y1) + "] (pass --layer)");
  } catch (const Error& e) {
    r.notes.push_back(std::string("velocity profile not computed: ") + e.what());
    r.profile.reset();
  }
}

// Solid fraction: over L x layer; the layer from the grains' extent if not given.
void analyze_solid_fraction(AnalyzeResult& r, std::span<const GrainSnapshot> window_snaps,
                            const LayerSpan& span, const RunInfo& run,
                            const AnalyzeOptions& options) {
  const double l0 = options.layer ? options.layer->first : span.extent_lo;
  const double l1 = options.layer ? options.layer->second : span.extent_hi;
  if (!std::isfinite(r.parameters.length)) {
    r.notes.push_back(run.compaction_box
                          ? "solid fraction null: a layer's, for periodic runs; the box's is "
                            "compaction_*_solid_fraction (analysis/compaction.csv)"
                          : "solid fraction null: L unknown (not a periodic run; pass --length)");
    return;
  }
  try {
    r.summary.solid_fraction = mean_solid_fraction(window_snaps, r.parameters.length, l0, l1);
    if (!options.layer)
      r.notes.push_back("solid fraction over the grains' extent [" + number(l0) + ", " +
                        number(l1) +
                        "] (mean lowest grain bottom to highest grain top; the "
                        "papers use the rough surfaces' mean lines: pass --layer)");
  } catch (const Error& e) {
    r.notes.push_back(std::string("solid fraction not computed: ") + e.what());
  }
}

// Activated thickness (paper 003 §3.4) per snapshot: the jump from -V/2 to +V/2, H = D (else
// the grains' extent), the profile's range and bins.
void analyze_att(AnalyzeResult& r, std::span<const GrainSnapshot> window_snaps,
                 const LayerSpan& span, const AnalyzeOptions& options, const fs::path& run_dir) {
  const RunParameters& p = r.parameters;
  if (!std::isfinite(p.velocity) || !(p.velocity != 0.0)) {
    r.notes.push_back("activated thickness null: V unknown (pass --velocity)");
    return;
  }
  double H = p.gap;
  r.att_layer_source = "the gap D";
  if (!(H > 0.0)) {
    H = span.extent_hi - span.extent_lo;
    r.att_layer_source = "the grains' extent (D unknown)";
    r.notes.push_back("activated thickness from the velocity map: H = the grains' extent " +
                      number(H) + " (D unknown)");
  }
  const ProfileRange range = profile_range(r, span, options);
  try {
    AttSeries att = activated_thickness_series(window_snaps, -0.5 * p.velocity, 0.5 * p.velocity, H,
                                               range.y0, range.y1, range.bins, options.att);
    r.summary.att_map = att.mean_from_grains;
    r.summary.att_profile = att.mean_from_profile;
    r.att_path = run_dir / "analysis" / "att.csv";
    write_att_csv(r.att_path.string(), att);
    r.att = std::move(att);
  } catch (const Error& e) {
    r.notes.push_back(std::string("activated thickness not computed: ") + e.what());
  }
}

}  // namespace

void analyze_layer(AnalyzeResult& r, std::span<const GrainSnapshot> window_snaps,
                   const RunInfo& run, const AnalyzeOptions& options, const fs::path& run_dir) {
  const LayerSpan span = layer_span(window_snaps);
  analyze_profile(r, window_snaps, span, options, run_dir);
  analyze_solid_fraction(r, window_snaps, span, run, options);
  analyze_att(r, window_snaps, span, options, run_dir);
}

}  // namespace sg::report
