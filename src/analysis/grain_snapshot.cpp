#include "analysis/grain_snapshot.h"

#include <algorithm>

#include "analysis/run_csv_table.h"
#include "core/error.h"

namespace sg {

GrainSnapshot read_grain_snapshot(const std::string& path, double time) {
  const RunCsvTable table = read_run_csv_table(path);
  const int c_body = table.column_index("body");
  const int c_x = table.column_index("x");
  const int c_y = table.column_index("y");
  const int c_vx = table.column_index("vx");
  const int c_vy = table.column_index("vy");
  const int c_area = table.column_index("area");
  GrainSnapshot s;
  s.time = time;
  const std::size_t n = table.rows.size();
  s.body.reserve(n);
  s.position.reserve(n);
  s.velocity.reserve(n);
  s.area.reserve(n);
  for (std::size_t r = 0; r < n; ++r) {
    s.body.push_back(table.rows[r][static_cast<std::size_t>(c_body)]);
    s.position.emplace_back(table.number(r, c_x), table.number(r, c_y));
    s.velocity.emplace_back(table.number(r, c_vx), table.number(r, c_vy));
    const double area = table.number(r, c_area);
    SG_VERIFY(area > 0.0, path << ":" << table.row_lines[r] << ": column 'area': " << area
                               << " is not positive");
    s.area.push_back(area);
  }
  return s;
}

GrainSnapshot without_bodies(const GrainSnapshot& snapshot, const std::vector<std::string>& names) {
  GrainSnapshot out;
  out.time = snapshot.time;
  for (std::size_t i = 0; i < snapshot.size(); ++i) {
    if (std::find(names.begin(), names.end(), snapshot.body[i]) != names.end()) continue;
    out.body.push_back(snapshot.body[i]);
    out.position.push_back(snapshot.position[i]);
    out.velocity.push_back(snapshot.velocity[i]);
    out.area.push_back(snapshot.area[i]);
  }
  return out;
}

}  // namespace sg
