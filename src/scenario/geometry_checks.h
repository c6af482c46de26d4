#pragma once
// Checks of a scenario's geometry and initial state (issue #15; docs/scenario.md, "Safety").
//
// At load (check_scenario_geometry, with the file and key of the offending value):
//   - the run name is a plain file name (core/file_name.h);
//   - with [periodic], every [[grains]] centre and [[walls]] rectangle lies in [x_min, x_max)
//     and no body is as wide as the period or wider;
//   - the node spacing is not too small for a [[grains]] body:
//     h >= D / kMaxDiameterPerSpacing for equivalent diameter D (meshfree/domain_mesh.h).
// On the built model (check_initial_state, before the first step):
//   - periodic models: every closed body's x range is narrower than the period with its
//     middle in [x_min, x_max); every open (first-body) contour closes over exactly one
//     period. Errors: these are states the contact search cannot represent.
//   - warnings (returned as run.log lines "# warning: ...", and printed to `progress`):
//     overlapping grains (one of them deformable) when contacts are on, with the pair and
//     the depth; an initial stretch beyond [1/kMaxInitialStretch, kMaxInitialStretch].
#include <ostream>
#include <string>

#include "meshfree/domain_mesh.h"
#include "model/model.h"
#include "scenario/scenario.h"
#include "scenario/toml_reader.h"
#include "solver/step_controller.h"

namespace sg {

// Bound of the initial-stretch warning: a stretch ratio outside [1/2, 2].
inline constexpr double kMaxInitialStretch = 2.0;

// Throws (file:line: key ...) on the first violation; `root` is the scenario's root table.
void check_scenario_geometry(const ScenarioDef& scenario, const TomlReader& root);

// Throws on impossible periodic geometry; returns the warnings as run.log lines (empty:
// none) and prints them to `progress` when it is set.
std::string check_initial_state(const ScenarioDef& scenario, const Model& model, bool contacts_on,
                                std::ostream* progress);

// The warning for a stable step estimate `now` below the run's first estimate divided by
// kStepCollapseFactor (StepControlParams::on_step_collapse):
// names the limiting body and the cause.
std::string describe_step_collapse(const Model& model, const StableStep& now, double first_dt);

}  // namespace sg
