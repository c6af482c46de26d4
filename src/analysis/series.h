#pragma once
// The run's time series (`series.csv`), as the engine writes it (docs/scenario.md [output],
// docs/method.md §Energy ledger):
//   time,step,dt,kinetic_energy,elastic_energy,external_work,damping_dissipation,
//   contact_dissipation,servo_dissipation,energy_residual, then per driven body B:
//   B_fx,B_fy,B_x,B_y
// (force B receives from the granular layer, and B's position). Energies and
// dissipations are cumulative since t = 0. One row per output period.
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sg {

struct Series {
  std::string path;                         // for error messages
  std::vector<std::string> columns;         // header order
  std::vector<std::vector<double>> values;  // values[c][row], column-major
  std::vector<std::string> body_names;      // driven bodies found (B of B_fx ... B_y)

  std::size_t size() const { return values.empty() ? 0 : values.front().size(); }
  bool has(std::string_view name) const;
  // Throws sg::Error naming the file and the column if it is absent.
  std::span<const double> column(std::string_view name) const;
};

// The columns every series.csv must hold.
std::span<const std::string_view> required_series_columns();

// Reads and checks a series.csv: required columns present, every body that has one of
// B_fx, B_fy, B_x, B_y has all four, every value a finite number, time strictly
// increasing. Throws sg::Error naming the file, line and column.
Series read_series(const std::string& path);

// The same checks on a series built in memory (tests, future in-process analysis).
void check_series(const Series& series);

}  // namespace sg
