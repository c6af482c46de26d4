#include "render/composite_snapshots.h"

#include <exception>

#include "render/run_folder.h"
#include "render/snapshot_renderer.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

// Each snapshot fills one of the composite's three rows on its left (about 9 x 2.4 inches at
// 110 dpi, scripts/plot_run.py): wide and low like the layer.
constexpr int kSnapshotWidth = 1200, kSnapshotHeight = 300;

RenderOptions snapshot_options(const RunInfo& run, const std::string& field) {
  RenderOptions o;
  o.field = field;
  o.width = kSnapshotWidth;
  o.height = kSnapshotHeight;
  o.last_frame_only = true;
  o.movie = false;
  set_from_run(o, run);
  // velocity_x over +-V/2, the first bodies' velocities (render/colour_range.h); the strain
  // rate on a log scale, three decades below its 99th percentile (linear, the shear bands
  // leave the grains' interiors one colour); the stress over its 1st-99th percentiles.
  o.robust_range = !(field == "velocity_x" && o.shear_velocity);  // robust overrides +-V/2
  o.log_scale = field == "strain_rate";
  return o;
}

}  // namespace

const std::vector<std::string>& composite_fields() {
  static const std::vector<std::string> fields = {"velocity_x", "strain_rate", "von_mises"};
  return fields;
}

CompositeSnapshots render_composite_snapshots(const fs::path& run_dir) {
  CompositeSnapshots out;
  if (!fs::exists(run_dir / "fields.pvd")) {
    out.notes.push_back("no field snapshot: the run wrote no fields.pvd");
    return out;
  }
  const RunInfo run = read_run_info(run_dir);
  if (!run.has_scenario) {
    out.notes.push_back("no snapshot: " + run.note);
    return out;
  }
  if (!run.shear_cell) {
    out.notes.push_back("no snapshot: not a shear cell (the composite is the shear cell's)");
    return out;
  }
  for (const std::string& field : composite_fields()) {
    try {
      const RenderResult r = render_run(run_dir, snapshot_options(run, field));
      if (r.images.empty())
        out.notes.push_back("no " + field + " snapshot: nothing drawn");
      else
        out.pictures.emplace_back(field, r.images.back());
    } catch (const std::exception& e) {  // sg::Error, or a file system error: said, not fatal
      out.notes.push_back("no " + field + " snapshot: " + e.what());
    }
  }
  return out;
}

}  // namespace sg
