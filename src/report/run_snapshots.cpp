#include <algorithm>
#include <cmath>
#include <map>

#include "render/vtu_reader.h"
#include "report/analyze_steps.h"

namespace sg::report {

namespace fs = std::filesystem;

Snapshots read_snapshots(const fs::path& run_dir, const std::vector<std::string>& exclude,
                         std::vector<std::string>& notes) {
  Snapshots out;
  const fs::path dir = run_dir / "grains";
  if (!fs::is_directory(dir)) {
    notes.push_back("no grains/ folder: no velocity profile, solid fraction or agglomerates");
    return out;
  }
  std::map<std::string, double> time_of;  // snapshot number -> time, from fields.pvd
  if (fs::exists(run_dir / "fields.pvd"))
    for (const PvdEntry& e : read_pvd(run_dir / "fields.pvd"))
      time_of[e.file.stem().string()] = e.time;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().extension() == ".csv") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  bool missing_time = false;
  for (const fs::path& f : files) {
    const auto t = time_of.find(f.stem().string());
    if (t == time_of.end()) {
      missing_time = true;
      continue;
    }
    out.all.push_back(without_bodies(read_grain_snapshot(f.string(), t->second), exclude));
    ++out.files;
  }
  if (missing_time)
    notes.push_back("some grains/*.csv have no time in fields.pvd and were skipped");
  std::sort(out.all.begin(), out.all.end(),
            [](const GrainSnapshot& a, const GrainSnapshot& b) { return a.time < b.time; });
  return out;
}

std::vector<GrainSnapshot> window_snapshots(const Snapshots& snaps, const TimeWindow& window) {
  std::vector<GrainSnapshot> out;
  const double eps = 1e-9 * std::max(1.0, std::abs(window.t_end));
  for (const GrainSnapshot& snap : snaps.all)
    if (snap.time >= window.t_begin - eps && snap.time <= window.t_end + eps && snap.size() > 0)
      out.push_back(snap);
  return out;
}

}  // namespace sg::report
