#pragma once
// The three snapshots of a run's composite figure (scripts/plot_run.py composite.png), in the
// manner of paper 001 Figs 6-12: the layer at the last field snapshot, coloured by the
// horizontal velocity, by the strain rate and by the von Mises stress. `softgrain analyze
// --plots` draws them with render_run (render/snapshot_renderer.h) into RUN_DIR/render/
// and hands their paths to plot_run.py, which places them beside mu(t), the velocity
// profiles and the run's place in (E~, c~, alpha~).
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace sg {

struct CompositeSnapshots {
  // (field, PNG) of every snapshot drawn, in the composite's order.
  std::vector<std::pair<std::string, std::filesystem::path>> pictures;
  // Why a field has no picture (no fields.pvd, a field the snapshots lack, ...): shown in
  // the composite in its place.
  std::vector<std::string> notes;
};

// The fields of the composite, top to bottom.
const std::vector<std::string>& composite_fields();

// Draws the last frame of RUN_DIR/fields.pvd in each of composite_fields(), no movie; never
// throws for a run that cannot be drawn: each failure becomes a note.
// velocity_x is drawn over [-V/2, V/2] (the first bodies' velocities) when V is known; the
// strain rate and the stress over the 1st-99th percentiles of their values (a few contact
// nodes otherwise squeeze every grain into one colour).
CompositeSnapshots render_composite_snapshots(const std::filesystem::path& run_dir);

}  // namespace sg
