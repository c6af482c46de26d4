#include "run/run_length.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/error.h"

namespace sg {

std::string zero_step_problem(const Simulation& sim) {
  if (sim.first_dt > 0.0 && std::isfinite(sim.first_dt)) return "";
  std::ostringstream why;
  why << "the stable step estimate is " << sim.first_dt;
  const StableStep& e = sim.first_estimate;
  if (e.limiting_body >= 0)
    why << " (body '" << sim.model.body(e.limiting_body).name << "', highest frequency "
        << e.omega_max << ")";
  why << ": the stiffness-to-mass ratio (with the damping) is beyond what the arithmetic "
         "holds; check the materials' young, density and damping and the contact laws' "
         "normal_stiffness";
  return why.str();
}

std::string run_length_problem(const ScenarioDef& s, const Simulation& sim) {
  if (const std::string zero = zero_step_problem(sim); !zero.empty()) return zero;
  const double steps = s.duration / sim.first_dt;
  // Rigid bodies have no nodes: count each as one.
  const double points =
      static_cast<double>(std::max(sim.model.node_count(), sim.model.bodies.size()));
  const double node_steps = steps * points;
  if (steps <= kMaxRunSteps && node_steps <= kMaxRunNodeSteps) return "";
  std::ostringstream why;
  why << "the first step " << sim.first_dt << " is absurdly small for duration " << s.duration
      << std::setprecision(3) << ": about " << steps << " steps of " << points << " nodes ("
      << node_steps << " node-steps), beyond the limit of " << kMaxRunSteps << " steps and "
      << kMaxRunNodeSteps << " node-steps (over a year at 10^7 node-steps/s)";
  return why.str();
}

void refuse_endless_run(const ScenarioDef& s, const Simulation& sim) {
  // A step of 0 never ends the run, whatever allow_long_run says.
  if (const std::string zero = zero_step_problem(sim); !zero.empty())
    SG_THROW(s.source.string() << ": " << zero);
  if (s.allow_long_run) return;
  const std::string problem = run_length_problem(s, sim);
  SG_VERIFY(problem.empty(), s.source.string()
                                 << ": key 'time.duration': " << problem
                                 << "; check the stiffnesses, densities and node spacing, or set "
                                    "[time] allow_long_run = true to run it anyway");
}

}  // namespace sg
