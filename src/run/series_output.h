#pragma once
// series.csv: one row per series period, each describing one instant t_n: the ledger and the
// driven bodies' forces of the step's force evaluation at t_n (written after the step), and
// the driven bodies' positions at t_n (taken before it). Rows are appended and flushed one by
// one to series.csv.partial (rows already written survive a crash), renamed series.csv when
// the run completes. The loop state counts the file's bytes exactly: what a resume cuts it
// back to.
#include <fstream>
#include <sstream>
#include <vector>

#include "run/driven_bodies.h"
#include "run/run_observer.h"

namespace sg {

class SeriesOutput : public RunObserver {
 public:
  explicit SeriesOutput(RunContext& context);

  void begin(bool resumed) override;
  void prepare(const RunInstant& now) override;
  void commit(const StepTaken& step) override;
  void finish() override;

  // Shear cells: the friction coefficient seen by the top first body over the second half of
  // the run, mu = -<Fx> / <Fy> (the full analysis: softgrain analyze); false if none.
  bool top_friction(double& mu, double& mean_normal_force) const;

 private:
  RunContext& context_;
  DrivenBodies driven_;
  std::ofstream file_;
  std::ostringstream row_;           // one row, appended whole
  bool row_due_ = false;             // prepare() took the positions of a due row
  std::vector<Vec2> row_positions_;  // the driven bodies' positions at t_n
  double last_dt_ = 0.0;             // the dt column: the step that was last accepted

  void append_row();
  void write_header();
};

}  // namespace sg
