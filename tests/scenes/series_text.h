#pragma once
// A run's series.csv read whole for end-to-end tests: the raw text (for byte comparisons) and
// the numbers by column name.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace sg::scenes {

struct SeriesText {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  std::string text;
  std::size_t column(const std::string& name) const {
    for (std::size_t i = 0; i < columns.size(); ++i)
      if (columns[i] == name) return i;
    ADD_FAILURE() << "no column " << name;
    return 0;
  }
};

inline SeriesText read_series_text(const std::filesystem::path& file) {
  SeriesText s;
  std::ifstream in(file);
  std::stringstream buffer;
  buffer << in.rdbuf();
  s.text = buffer.str();
  std::istringstream lines(s.text);
  std::string line, cell;
  std::getline(lines, line);
  for (std::istringstream header(line); std::getline(header, cell, ',');)
    s.columns.push_back(cell);
  while (std::getline(lines, line)) {
    std::vector<double> row;
    for (std::istringstream fields(line); std::getline(fields, cell, ',');)
      row.push_back(std::stod(cell));
    s.rows.push_back(row);
  }
  return s;
}

// The energy ledger at a run's last row: external work, ledger residual, bulk dissipation.
struct FinalLedger {
  double work = 0.0, residual = 0.0, bulk = 0.0;
};

inline FinalLedger final_ledger(const SeriesText& s) {
  const std::vector<double>& last = s.rows.back();
  return {last[s.column("external_work")], last[s.column("energy_residual")],
          last[s.column("damping_dissipation")]};
}

}  // namespace sg::scenes
