#pragma once
// Synthetic inputs shared by the analysis tests: a reproducible Gaussian noise source, a
// scratch folder, and an in-memory series.csv.
#include <unistd.h>
#include <cmath>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "analysis/series.h"

namespace sg::test {

// Box-Muller on mt19937_64: unlike std::normal_distribution, whose algorithm the
// standard leaves to the library, this gives the same numbers on every platform, so the
// tolerances below are checked against the same samples everywhere.
class Gaussian {
 public:
  explicit Gaussian(std::uint64_t seed) : engine_(seed) {}
  double operator()() {
    const double u1 = (static_cast<double>(engine_() >> 11) + 1.0) * 0x1.0p-53;  // (0, 1]
    const double u2 = static_cast<double>(engine_() >> 11) * 0x1.0p-53;          // [0, 1)
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

 private:
  std::mt19937_64 engine_;
};

// A fresh folder under the system temp folder, removed at the end of the test.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name)
      : path_(std::filesystem::temp_directory_path() /
              ("softgrain_test_analysis_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() { std::filesystem::remove_all(path_); }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  std::string write(const std::string& name, const std::string& content) const {
    std::ofstream(file(name)) << content;
    return file(name);
  }

 private:
  std::filesystem::path path_;
};

// A shear-cell series in memory: every required column zero, bodies top and bottom.
// Fill the columns you need through column_values().
inline Series make_series(const std::vector<double>& time) {
  Series s;
  s.path = "synthetic series.csv";
  for (const auto name : required_series_columns())
    s.columns.emplace_back(name);
  for (const std::string body : {"top", "bottom"}) {
    s.body_names.push_back(body);
    for (const std::string suffix : {"_fx", "_fy", "_x", "_y"})
      s.columns.push_back(body + suffix);
  }
  s.values.assign(s.columns.size(), std::vector<double>(time.size(), 0.0));
  s.values[0] = time;
  return s;
}

inline std::vector<double>& column_values(Series& s, const std::string& name) {
  for (std::size_t c = 0; c < s.columns.size(); ++c)
    if (s.columns[c] == name) return s.values[c];
  throw std::runtime_error("no column " + name);
}

}  // namespace sg::test
