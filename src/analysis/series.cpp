#include "analysis/series.h"

#include <array>

#include "analysis/run_csv_table.h"
#include "core/error.h"

namespace sg {
namespace {

constexpr std::array<std::string_view, 9> kRequired = {"time",
                                                       "step",
                                                       "dt",
                                                       "kinetic_energy",
                                                       "elastic_energy",
                                                       "external_work",
                                                       "damping_dissipation",
                                                       "contact_dissipation",
                                                       "energy_residual"};

constexpr std::array<std::string_view, 4> kBodySuffixes = {"_fx", "_fy", "_x", "_y"};

bool ends_with(std::string_view s, std::string_view suffix) {
  return s.size() > suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

}  // namespace

std::span<const std::string_view> required_series_columns() {
  return kRequired;
}

bool Series::has(std::string_view name) const {
  for (const auto& c : columns)
    if (c == name) return true;
  return false;
}

std::span<const double> Series::column(std::string_view name) const {
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c] == name) return values[c];
  SG_THROW(path << ": missing column '" << name << "'");
}

void check_series(const Series& series) {
  for (const auto name : kRequired)
    SG_VERIFY(series.has(name), series.path << ": missing column '" << name << "'");
  for (const auto& body : series.body_names)
    for (const auto suffix : kBodySuffixes) {
      const std::string name = body + std::string(suffix);
      SG_VERIFY(series.has(name), series.path << ": missing column '" << name
                                              << "' for driven body '" << body << "'");
    }
  const auto time = series.column("time");
  for (std::size_t i = 1; i < time.size(); ++i)
    SG_VERIFY(time[i] > time[i - 1], series.path << ": row " << i + 1 << ": time " << time[i]
                                                 << " does not increase (previous " << time[i - 1]
                                                 << ")");
}

Series read_series(const std::string& path) {
  const RunCsvTable table = read_run_csv_table(path);
  Series series;
  series.path = path;
  series.columns = table.columns;
  series.values.assign(table.columns.size(), std::vector<double>(table.rows.size()));
  for (std::size_t r = 0; r < table.rows.size(); ++r)
    for (std::size_t c = 0; c < table.columns.size(); ++c)
      series.values[c][r] = table.number(r, static_cast<int>(c));
  // Driven bodies are discovered from the header: any B with a B_fx column (or any of
  // the four) is one; check_series then demands all four.
  for (const auto& name : table.columns)
    for (const auto suffix : kBodySuffixes)
      if (ends_with(name, suffix)) {
        std::string body = name.substr(0, name.size() - suffix.size());
        bool known = false;
        for (const auto& b : series.body_names)
          known = known || b == body;
        if (!known) series.body_names.push_back(std::move(body));
        break;
      }
  // Time must increase: check here first, where the file line of the offending row is
  // known; check_series repeats it for in-memory series, with the row number only.
  if (table.has_column("time")) {
    const auto time = series.column("time");
    for (std::size_t i = 1; i < time.size(); ++i)
      SG_VERIFY(time[i] > time[i - 1],
                path << ":" << table.row_lines[i] << ": column 'time': " << time[i]
                     << " does not increase (previous " << time[i - 1] << ")");
  }
  check_series(series);
  return series;
}

}  // namespace sg
