#pragma once
// What a run folder says about itself beyond its data files: the scenario it was run from
// (the `scenario = <path>` line of run.log, re-read if the file is still there), reduced to
// what analysis and pictures need: the run parameters of the papers, the periodic span,
// and the body names in the engine's order (grains/NNNNNN.csv and body_id in the .vtu
// files number bodies, they do not name them).
//
// The header deliberately does not include scenario/scenario.h: meshfree/mls.h (through
// the scenario) and analysis/velocity_grid.h both define sg::VelocityFitParams, so one translation
// unit cannot include both.
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/compaction_curve.h"
#include "analysis/run_parameters.h"

namespace sg {

struct RunInfo {
  bool has_scenario = false;
  std::string note;                // why there is no scenario
  std::filesystem::path source;    // the scenario file, as named in run.log
  std::string name;                // run name
  RunParameters parameters;        // L, D, V, E, c, alpha the scenario gives (NaN otherwise)
  std::vector<std::string> notes;  // parameters it cannot give, and why
  std::optional<std::pair<double, double>> periodic;  // [x_min, x_max) if periodic in x
  bool shear_cell = false;
  // The end of what the scenario drives on purpose before a steady state can start (time):
  // the shear cell's compaction or load ramp (compaction_time; with deformable first bodies
  // also the half of the back faces' velocity ramp after it) and the last breakpoint of a
  // history given to the top's or the bottom's drive. NaN: nothing known.
  double loading_end = RunParameters::kUnknown;
  // Body names in the order build_model creates them: explicit grains, the shear cell
  // ("bottom", "top", then its grains), then walls. The generated grains (grain_<i>) are listed
  // in the drawn order, not the model's (along x): read only the other bodies' places.
  std::vector<std::string> body_names;
  std::vector<std::string> walls;  // wall names (not grains)
  // [compaction_box]: width, lid thickness, floor and the generated grains' area, as the
  // builder (scenario/compaction_box.cpp) makes them; unset for other runs.
  std::optional<CompactionBoxGeometry> compaction_box;
};

// Never throws for a missing or unreadable run.log or scenario: the reason lands in `note`.
RunInfo read_run_info(const std::filesystem::path& run_dir);

}  // namespace sg
