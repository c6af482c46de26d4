#include "run/run.h"

#include "run/run_session.h"

namespace sg {

RunSummary run_scenario(const ScenarioDef& scenario, const RunOptions& options) {
  RunSession run(scenario, options);
  try {
    while (!run.reached_end()) {
      if (options.stop_after_steps >= 0 &&
          run.simulation().solver.state().step - run.first_step() >= options.stop_after_steps)
        break;  // close() leaves the folder as a killed run leaves it
      run.step();
    }
    return run.close();
  } catch (const std::exception& error) {
    run.stop_with_error(error);
  }
}

}  // namespace sg
