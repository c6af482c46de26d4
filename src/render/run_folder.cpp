#include "render/run_folder.h"

#include <fstream>

#include "core/error.h"

namespace sg {

RunScenario load_run_scenario(const std::filesystem::path& run_dir) {
  RunScenario r;
  std::ifstream log(run_dir / "run.log");
  if (!log) {
    r.note = "no run.log in '" + run_dir.string() + "'";
    return r;
  }
  std::string line;
  while (std::getline(log, line)) {
    const std::string key = "scenario = ";
    if (line.rfind(key, 0) == 0) {
      r.source = line.substr(key.size());
      break;
    }
  }
  if (r.source.empty()) {
    r.note = "run.log names no scenario";
    return r;
  }
  // A relative path was relative to where `softgrain run` started; try it as is, then next
  // to the run folder's parent (the usual layout: out/<name>/ beside the scenario).
  std::filesystem::path file = r.source;
  if (!std::filesystem::exists(file) && file.is_relative()) {
    const auto beside = run_dir.parent_path().parent_path() / file.filename();
    if (std::filesystem::exists(beside)) file = beside;
  }
  if (!std::filesystem::exists(file)) {
    r.note = "scenario '" + r.source.string() + "' (from run.log) not found";
    return r;
  }
  try {
    r.scenario = load_scenario(file);
  } catch (const Error& e) {
    r.note = std::string("scenario '") + file.string() + "' could not be read: " + e.what();
  }
  return r;
}

std::vector<std::string> body_names(const ScenarioDef& s) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < s.grains.size(); ++i)
    names.push_back(s.grains[i].name);
  if (s.shear_cell) {
    names.push_back("bottom");
    names.push_back("top");
    for (int i = 0; i < s.shear_cell->grains; ++i)
      names.push_back("grain_" + std::to_string(i));
  }
  for (const WallDef& w : s.walls)
    names.push_back(w.name);
  return names;
}

std::optional<std::pair<double, double>> periodic_span(const ScenarioDef& s) {
  if (s.shear_cell) return std::make_pair(0.0, s.shear_cell->length);
  if (s.periodic_x) return std::make_pair(s.x_min, s.x_max);
  return std::nullopt;
}

}  // namespace sg
