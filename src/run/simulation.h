#pragma once
// Everything a run steps: the model built from the scenario, its contact system, mass
// scaling, the solver and the adaptive step controller, and the fingerprint a checkpoint of
// this run must carry. Built in that order (mass scaling before any estimate, the first step
// estimated on the built, not yet restored, model: part of what a checkpoint must match).
#include <memory>
#include <ostream>
#include <string>

#include "io/checkpoint.h"
#include "scenario/scenario.h"
#include "solver/step_controller.h"
#include "solver/stepper.h"

namespace sg {

class Simulation {
 public:
  // Warnings about the initial state (and a collapsing step, later) go to `progress` when set.
  Simulation(const ScenarioDef& scenario, std::ostream* progress = nullptr);
  Simulation(const Simulation&) = delete;  // the solver and the controller hold references
  Simulation& operator=(const Simulation&) = delete;

  Model model;
  std::unique_ptr<ContactSystem> contacts;  // null: no contact laws
  // The integrator and its step check, as written or chosen on the built model before mass
  // scaling (scenario.h resolve_integrator); run.log and the run's first line say which.
  IntegratorChoice integrator;
  std::string mass_scaling_note;  // "# ...\n" for run.log, empty without scaling
  // Impossible periodic geometry is refused, suspicious initial states are warned about
  // (scenario/geometry_checks.h): the warnings, "# ...\n" lines for run.log.
  std::string initial_state_note;
  Stepper solver;
  StepController controller;
  StableStep first_estimate;  // the controller's estimate of the built model
  double first_dt = 0.0;      // the first step
  // A fixed_step beyond the estimated stability limit (run/integration_checks.h): the warning,
  // a "# warning: ...\n" line for run.log; empty otherwise.
  std::string fixed_step_note;
  CheckpointFingerprint fingerprint;
};

// What a checkpoint must match besides the model: settings that change what the steps
// compute or what the outputs mean.
std::vector<double> run_settings(const ScenarioDef& scenario, const IntegratorChoice& integrator,
                                 double first_dt);

}  // namespace sg
