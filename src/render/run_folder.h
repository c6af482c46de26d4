#pragma once
// What a run folder says about itself beyond its data files: the scenario it was run from
// (the `scenario = <path>` line of run.log, re-read if the file is still there) and the
// body names in the engine's order (grains/NNNNNN.csv and body_id in the .vtu files
// number bodies, they do not name them).
//
// Lives in render/ because it needs the scenario layer and render is the first stage above
// io; the analysis stage does not link the scenario.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "scenario/scenario.h"

namespace sg {

struct RunScenario {
  std::optional<ScenarioDef> scenario;  // absent if run.log or the scenario cannot be read
  std::filesystem::path source;         // as named in run.log ("" if none)
  std::string note;                     // why it is absent
};

// Never throws for a missing or unreadable scenario: the reason lands in `note`.
RunScenario load_run_scenario(const std::filesystem::path& run_dir);

// Body names in the order build_model creates them: explicit grains, the shear cell
// ("bottom", "top", "grain_0" ...), then walls.
std::vector<std::string> body_names(const ScenarioDef& scenario);

// The period [x_min, x_max) if the scenario is periodic in x (a shear cell is periodic
// over [0, L)); nullopt otherwise.
std::optional<std::pair<double, double>> periodic_span(const ScenarioDef& scenario);

}  // namespace sg
