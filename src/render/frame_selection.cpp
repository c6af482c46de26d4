#include "render/frame_selection.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/error.h"

namespace sg {

namespace fs = std::filesystem;

std::vector<PvdEntry> select_frames(const std::vector<PvdEntry>& entries,
                                    const std::optional<std::pair<double, double>>& window,
                                    bool last_only, const fs::path& pvd) {
  std::vector<PvdEntry> out;
  for (const PvdEntry& e : entries) {
    // The .pvd and summary.json print times to a few digits fewer than they were computed.
    const double slack = 1e-9 * (1.0 + std::abs(e.time));
    if (!window || (e.time >= window->first - slack && e.time <= window->second + slack))
      out.push_back(e);
  }
  if (out.empty()) {
    SG_VERIFY(window.has_value(), pvd.string() << ": no snapshot listed");
    SG_THROW(pvd.string() << ": no snapshot at a time in [" << window->first << ", "
                          << window->second << "] (the snapshots are at t = "
                          << entries.front().time << " to " << entries.back().time << ")");
  }
  if (last_only) out.erase(out.begin(), out.end() - 1);
  return out;
}

std::pair<double, double> analysed_window(const fs::path& run_dir) {
  const fs::path path = run_dir / "analysis" / "summary.json";
  SG_VERIFY(fs::exists(path), "'" << path.string()
                                  << "' is missing: the analysed window comes from it (run "
                                     "`softgrain analyze` on the run first, or give --from/--to)");
  std::ifstream in(path);
  SG_VERIFY(in, "cannot read '" << path.string() << "'");
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    SG_THROW(path.string() << ": not valid JSON: " << e.what());
  }
  SG_VERIFY(doc.is_object() && doc.value("format", "") == "softgrain-analysis-summary",
            path.string() << ": not an analysis summary (format is not "
                             "\"softgrain-analysis-summary\")");
  const auto bound = [&](const char* key) {
    const auto q = doc.find("quantities");
    SG_VERIFY(q != doc.end() && q->is_object() && q->contains(key) && (*q)[key].is_object() &&
                  (*q)[key].contains("value") && (*q)[key]["value"].is_number(),
              path.string() << ": quantities." << key
                            << ".value is not a number (the analysis found no window)");
    return (*q)[key]["value"].get<double>();
  };
  const std::pair<double, double> window{bound("window_begin"), bound("window_end")};
  SG_VERIFY(window.second >= window.first, path.string()
                                               << ": window_end " << window.second
                                               << " before window_begin " << window.first);
  return window;
}

}  // namespace sg
