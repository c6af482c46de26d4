#pragma once
// What a run can finish: a scenario whose step is absurdly small for its duration (a normal
// stiffness of 1e15 gave a step of 2.5e-15, a duration of 1 and an ETA of "over 10000 days",
// with no word) is refused before its first step, unless it says [time] allow_long_run = true
// (docs/scenario.md, "Safety"; issue #26). Refused: more than kMaxRunSteps steps (a step
// below 1e-9 of the duration), or more than kMaxRunNodeSteps node-steps (over a year at
// 10^7 node-steps/s, about eight times the rate measured for the paper-size shear cell on
// 2 cores; that cell's 400 time units are 10^12 node-steps).
#include <string>

#include "run/simulation.h"
#include "scenario/scenario.h"

namespace sg {

inline constexpr double kMaxRunSteps = 1e9;
inline constexpr double kMaxRunNodeSteps = 3e14;

// Why the run cannot run at all ("" if it can): a first step of 0 or not finite (a young of
// 1e90 with some damping: the damped limit underflows), naming the body that sets it. Refused even
// with allow_long_run.
std::string zero_step_problem(const Simulation& simulation);

// Why the run is refused ("" if it is not): the steps, node-steps and the limit passed.
std::string run_length_problem(const ScenarioDef& scenario, const Simulation& simulation);

// Throws sg::Error naming the scenario file and the key [time] allow_long_run.
void refuse_endless_run(const ScenarioDef& scenario, const Simulation& simulation);

}  // namespace sg
