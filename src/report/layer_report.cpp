#include <algorithm>
#include <cmath>

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
void analyze_profile(AnalyzeResult& r, std::span<const GrainSnapshot> window_snaps,
                     const LayerSpan& span, const AnalyzeOptions& options,
                     const fs::path& run_dir) {
  const RunParameters& p = r.parameters;
  const double y0 = options.layer ? options.layer->first : span.centre_lo;
  const double y1 = options.layer ? options.layer->second : span.centre_hi;
  int bins = options.profile_bins;
  if (bins <= 0)
    bins =
        std::isfinite(p.mean_diameter) && p.mean_diameter > 0.0
            ? std::clamp(static_cast<int>(std::lround(2.0 * (y1 - y0) / p.mean_diameter)), 4, 200)
            : 20;
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

}  // namespace

void analyze_layer(AnalyzeResult& r, std::span<const GrainSnapshot> window_snaps,
                   const RunInfo& run, const AnalyzeOptions& options, const fs::path& run_dir) {
  const LayerSpan span = layer_span(window_snaps);
  analyze_profile(r, window_snaps, span, options, run_dir);
  analyze_solid_fraction(r, window_snaps, span, run, options);
}

}  // namespace sg::report
