#pragma once
// run.log: the softgrain version and commit (core/version.h), every parameter as resolved,
// the discretization, the first step, the mass scaling, the resume point; rewritten (atomically) at
// the end with the step control's record and the profile of the run's phases. render/ reads the
// scenario's path from it.
#include <filesystem>
#include <string>

#include "run/simulation.h"
#include "scenario/scenario.h"

namespace sg {

// `notes`: lines ("# ...\n") appended after the resolved parameters.
void write_run_log(const std::filesystem::path& path, const ScenarioDef& scenario,
                   const Simulation& simulation, const std::string& notes);

// The step controller's record of this session ("# steps: ...").
std::string describe_step_control(const StepStatistics& statistics);

// The IMEX integrator's solves ("" for the explicit one).
std::string describe_viscous_solves(const ViscousSolveStatistics& statistics);

// The contact broad phase: how often its candidate list was rebuilt over the run's `steps`
// ("" without contacts).
std::string describe_contacts(const ContactSystem* contacts, long steps);

// The profile: wall seconds and share per phase, and the time per step.
std::string describe_profile(const StepProfile& profile, double wall_seconds);

}  // namespace sg
