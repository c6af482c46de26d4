#include "analysis/structure_cylinders.h"

#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>

#include "io/atomic_file.h"

namespace sg {
namespace {

// Visits every labelled cell: frame t, node (i, j), label.
template <typename Visit>
void for_each_marked_cell(const SpaceTimeLabels& labels, Visit&& visit) {
  for (int t = 0; t < labels.nt; ++t)
    for (int j = 0; j < labels.ny; ++j)
      for (int i = 0; i < labels.nx; ++i) {
        const int label =
            labels.label[static_cast<std::size_t>((t * labels.ny + j) * labels.nx + i)];
        if (label >= 0) visit(t, i, j, label);
      }
}

std::string cell(double v) {
  if (!std::isfinite(v)) return "";
  std::ostringstream s;
  s << std::setprecision(12) << v;
  return s.str();
}

}  // namespace

std::vector<StructureCylinder> structure_cylinders(const AgglomerateResult& result,
                                                   double first_time) {
  const RegularGrid& g = result.grid;
  const std::size_t n = result.structures.size();
  // Circular mean in x: the mean of the unit vectors at angle 2 pi (x - x0) / L.
  std::vector<double> cos_sum(n, 0.0), sin_sum(n, 0.0), y_sum(n, 0.0), cells(n, 0.0);
  for_each_marked_cell(result.labels, [&](int, int i, int j, int label) {
    const auto k = static_cast<std::size_t>(label);
    const double angle = 2.0 * std::numbers::pi * (g.x(i) - g.x0) / g.length;
    cos_sum[k] += std::cos(angle);
    sin_sum[k] += std::sin(angle);
    y_sum[k] += g.y(j);
    cells[k] += 1.0;
  });
  std::vector<StructureCylinder> out;
  const double T = result.frame_period;
  for (std::size_t k = 0; k < n; ++k) {
    const Structure& s = result.structures[k];
    StructureCylinder c;
    c.label = static_cast<int>(k);
    c.sign = s.sign;
    double angle = std::atan2(sin_sum[k], cos_sum[k]);
    if (angle < 0.0) angle += 2.0 * std::numbers::pi;
    c.x_center = g.x0 + angle / (2.0 * std::numbers::pi) * g.length;
    c.y_center = cells[k] > 0.0 ? y_sum[k] / cells[k] : std::nan("");
    c.t_bottom = first_time + (s.first_frame - 0.5) * T;
    c.height = s.lifetime;
    c.diameter = s.diameter;
    c.omega_tilde = s.omega_normalized;
    out.push_back(c);
  }
  return out;
}

void write_space_time_csv(const std::string& path, const AgglomerateResult& result,
                          double first_time) {
  const RegularGrid& g = result.grid;
  std::ostringstream out;
  out << "frame,time,x,y,sign,label\n";
  for_each_marked_cell(result.labels, [&](int t, int i, int j, int label) {
    out << t << ',' << cell(first_time + t * result.frame_period) << ',' << cell(g.x(i)) << ','
        << cell(g.y(j)) << ',' << result.structures[static_cast<std::size_t>(label)].sign << ','
        << label << '\n';
  });
  write_file_atomically(path, out.str());
}

void write_cylinders_csv(const std::string& path, const std::vector<StructureCylinder>& cylinders) {
  std::ostringstream out;
  out << "label,sign,x_center,y_center,t_bottom,height,diameter,omega_tilde\n";
  for (const StructureCylinder& c : cylinders)
    out << c.label << ',' << c.sign << ',' << cell(c.x_center) << ',' << cell(c.y_center) << ','
        << cell(c.t_bottom) << ',' << cell(c.height) << ',' << cell(c.diameter) << ','
        << cell(c.omega_tilde) << '\n';
  write_file_atomically(path, out.str());
}

}  // namespace sg
