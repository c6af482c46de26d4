#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "render/vtu_reader.h"
#include "report/analyze_steps.h"

namespace sg::report {
namespace {

namespace fs = std::filesystem;

// Mean height of a rigid first body's surface in one field snapshot: its polygon (the
// rough surface's points, io/vtk_writer.h) averaged over its points. NaN if the body is
// not drawn as a polygon (a deformable first body).
double surface_mean_y(const VtuMesh& mesh, int body) {
  const std::vector<double> id = point_scalar(mesh, "body_id");
  for (std::size_t c = 0; c < mesh.cell_count(); ++c) {
    if (mesh.types[c] != kVtkPolygon) continue;
    const auto cell = mesh.cell(c);
    if (cell.empty() || std::lround(id[static_cast<std::size_t>(cell[0])]) != body) continue;
    double sum = 0.0;
    for (const int p : cell)
      sum += mesh.points[static_cast<std::size_t>(p)].y();
    return sum / static_cast<double>(cell.size());
  }
  return kNan;
}

int body_index(const RunInfo& run, const std::string& name) {
  const auto it = std::find(run.body_names.begin(), run.body_names.end(), name);
  return it == run.body_names.end() ? -1 : static_cast<int>(it - run.body_names.begin());
}

std::size_t nearest_row(std::span<const double> time, double t) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < time.size(); ++i)
    if (std::abs(time[i] - t) < std::abs(time[best] - t)) best = i;
  return best;
}

}  // namespace

void measure_gap(AnalyzeResult& r, const Series& series, const RunInfo& run,
                 const fs::path& run_dir) {
  if (std::isfinite(r.parameters.gap) || !run.shear_cell) return;
  const int top = body_index(run, "top"), bottom = body_index(run, "bottom");
  const fs::path pvd = run_dir / "fields.pvd";
  if (top < 0 || bottom < 0 || !series.has("top_y") || !series.has("bottom_y") ||
      !fs::exists(pvd)) {
    r.notes.push_back("gap D not measured: needs fields.pvd and the top and bottom columns");
    return;
  }
  try {
    // The surfaces' mean lines in the first field snapshot, as offsets from the bodies'
    // positions in series.csv at that time; rigid bodies keep them (they do not rotate).
    const PvdEntry first = read_pvd(pvd).at(0);
    const VtuMesh mesh = read_vtu(first.file);
    const double top_line = surface_mean_y(mesh, top), bottom_line = surface_mean_y(mesh, bottom);
    if (!std::isfinite(top_line) || !std::isfinite(bottom_line)) {
      r.notes.push_back("gap D not measured: the first bodies are not rigid (no surface polygon)");
      return;
    }
    const auto time = series.column("time");
    const auto top_y = series.column("top_y"), bottom_y = series.column("bottom_y");
    const std::size_t at = nearest_row(time, first.time);
    const double top_offset = top_line - top_y[at], bottom_offset = bottom_line - bottom_y[at];
    const TimeWindow& w = r.summary.window;
    double sum = 0.0;
    for (std::size_t i = w.first; i <= w.last; ++i)
      sum += (top_y[i] + top_offset) - (bottom_y[i] + bottom_offset);
    const double gap = sum / static_cast<double>(w.size());
    r.parameters.gap = gap;
    for (ParameterSource& p : r.parameter_sources)
      if (p.key == "gap") {
        p.value = gap;
        p.source =
            "measured: mean over the window of the distance between the rough surfaces' mean "
            "lines (series.csv top_y, bottom_y; surfaces from " +
            first.file.filename().string() + ")";
      }
  } catch (const Error& e) {
    r.notes.push_back(std::string("gap D not measured: ") + e.what());
  }
}

}  // namespace sg::report
