#include "run/series_output.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <iomanip>

#include "core/error.h"

namespace sg {

namespace {

// Cuts series.csv.partial back to what it held when the checkpoint was taken (a killed run
// may have written rows after it), after checking that it is the same file.
void cut_series_back(const std::filesystem::path& partial, const RunLoopState& loop) {
  const std::string where = "cannot resume from '" + partial.string() + "': ";
  SG_VERIFY(std::filesystem::exists(partial), where << "the file is missing");
  const std::uintmax_t size = std::filesystem::file_size(partial);
  SG_VERIFY(size >= loop.series_bytes, where << "it has " << size << " bytes, fewer than the "
                                             << loop.series_bytes
                                             << " written when the checkpoint was taken");
  std::string kept(static_cast<std::size_t>(loop.series_bytes), '\0');
  {
    std::ifstream in(partial, std::ios::binary);
    in.read(kept.data(), static_cast<std::streamsize>(kept.size()));
    SG_VERIFY(in, where << "cannot read its first " << loop.series_bytes << " bytes");
  }
  const auto lines = std::count(kept.begin(), kept.end(), '\n');
  SG_VERIFY(!kept.empty() && kept.back() == '\n' && lines == loop.series_rows + 1,
            where << "its first " << loop.series_bytes << " bytes hold " << lines
                  << " lines, the checkpoint expects a header and " << loop.series_rows << " rows");
  std::filesystem::resize_file(partial, loop.series_bytes);
}

}  // namespace

SeriesOutput::SeriesOutput(RunContext& context)
    : context_(context),
      driven_(context.simulation.model),
      row_positions_(driven_.bodies().size()),
      last_dt_(context.simulation.first_dt) {
  row_ << std::setprecision(12);
}

void SeriesOutput::begin(bool resumed) {
  const std::filesystem::path partial = context_.folder.partial_series();
  if (resumed) {
    cut_series_back(partial, context_.loop);
    file_.open(partial, std::ios::binary | std::ios::app);
  } else {
    file_.open(partial, std::ios::binary | std::ios::trunc);
  }
  SG_VERIFY(file_, "cannot write '" << partial.string() << "'");
  if (!resumed) write_header();
}

void SeriesOutput::write_header() {
  const Model& model = context_.simulation.model;
  row_ << "time,step,dt,kinetic_energy,elastic_energy,external_work,damping_dissipation,"
          "contact_dissipation,servo_dissipation,energy_residual";
  for (BodyId b : driven_.bodies()) {
    const std::string& name = model.body(b).name;
    row_ << ',' << name << "_fx," << name << "_fy," << name << "_x," << name << "_y";
  }
  row_ << '\n';
  append_row();
}

void SeriesOutput::prepare(const RunInstant& now) {
  row_due_ = now.time >= context_.loop.next_series_time - context_.time_tolerance;
  if (!row_due_) return;
  for (std::size_t k = 0; k < driven_.bodies().size(); ++k)
    row_positions_[k] = driven_.position(driven_.bodies()[k]);
}

void SeriesOutput::commit(const StepTaken& step) {
  last_dt_ = step.dt;
  if (!row_due_) return;
  RunLoopState& loop = context_.loop;
  const double t = step.start.time;
  const EnergyLedger& e = context_.simulation.solver.state().energy;
  row_ << t << ',' << step.start.step << ',' << last_dt_ << ',' << e.kinetic << ',' << e.elastic
       << ',' << e.external_work << ',' << e.damping_dissipated << ',' << e.contact_dissipated
       << ',' << e.servo_dissipated << ',' << e.residual();
  if (driven_.top() >= 0 && t >= 0.5 * context_.scenario.duration) {
    const Vec2 f = driven_.force(driven_.top());
    loop.top_force_sum_x += f.x();
    loop.top_force_sum_y += f.y();
    ++loop.top_force_rows;
  }
  for (std::size_t k = 0; k < driven_.bodies().size(); ++k) {
    const Vec2 f = driven_.force(driven_.bodies()[k]), x = row_positions_[k];
    row_ << ',' << f.x() << ',' << f.y() << ',' << x.x() << ',' << x.y();
  }
  row_ << '\n';
  append_row();
  ++loop.series_rows;
  loop.next_series_time += context_.scenario.series_period;
}

void SeriesOutput::append_row() {
  const std::string text = row_.str();
  errno = 0;
  file_.write(text.data(), static_cast<std::streamsize>(text.size()));
  file_.flush();
  SG_VERIFY(file_, "failed writing '" << context_.folder.partial_series().string() << "': "
                                      << (errno != 0 ? std::strerror(errno) : "disk full?"));
  context_.loop.series_bytes += text.size();
  row_.str("");
}

void SeriesOutput::finish() {
  file_.close();
  std::filesystem::rename(context_.folder.partial_series(), context_.folder.series());
}

bool SeriesOutput::top_friction(double& mu, double& mean_normal_force) const {
  const RunLoopState& loop = context_.loop;
  if (driven_.top() < 0 || loop.top_force_sum_y == 0.0) return false;
  mu = -loop.top_force_sum_x / loop.top_force_sum_y;
  mean_normal_force = std::abs(loop.top_force_sum_y) / static_cast<double>(loop.top_force_rows);
  return true;
}

}  // namespace sg
