#pragma once
// Everything a run steps: the model built from the scenario, its contact system, mass
// scaling, the solver and the adaptive step controller, and the fingerprint a checkpoint of
// this run must carry. Built in that order (mass scaling before any estimate, the first step
// estimated on the built, not yet restored, model: part of what a checkpoint must match).
#include <memory>
#include <string>

#include "io/checkpoint.h"
#include "scenario/scenario.h"
#include "solver/explicit_solver.h"
#include "solver/step_controller.h"

namespace sg {

class Simulation {
 public:
  explicit Simulation(const ScenarioDef& scenario);
  Simulation(const Simulation&) = delete;  // the solver and the controller hold references
  Simulation& operator=(const Simulation&) = delete;

  Model model;
  std::unique_ptr<ContactSystem> contacts;  // null: no contact laws
  std::string mass_scaling_note;            // "# ...\n" for run.log, empty without scaling
  ExplicitSolver solver;
  StepController controller;
  StableStep first_estimate;  // the controller's estimate of the built model
  double first_dt = 0.0;      // the first step
  CheckpointFingerprint fingerprint;
};

// What a checkpoint must match besides the model: settings that change what the steps
// compute or what the outputs mean.
std::vector<double> run_settings(const ScenarioDef& scenario, double first_dt);

}  // namespace sg
