#include "render/series_extent.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "render/contact_outlines.h"
#include "render/frame_decorations.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

// Min and max of the field over the points of the cells it colours (each value also
// appended to `values` when given).
void accumulate_range(const VtuMesh& mesh, const std::string& field, double& lo, double& hi,
                      std::vector<double>* values) {
  const std::vector<double> value = point_scalar(mesh, field);
  const bool rigid_too = field_defined_on_rigid(field);
  for (std::size_t c = 0; c < mesh.cell_count(); ++c) {
    if (mesh.types[c] != kVtkTriangle && !(rigid_too && mesh.types[c] == kVtkPolygon)) continue;
    for (int p : mesh.cell(c)) {
      const double v = value[static_cast<std::size_t>(p)];
      if (!std::isfinite(v)) continue;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
      if (values) values->push_back(v);
    }
  }
}

double quantile(std::vector<double>& v, double q) {
  const auto k = static_cast<std::size_t>(std::lround(q * static_cast<double>(v.size() - 1)));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

// The contact rates drawn on the outlines are coloured with the field's map: they count in
// its range.
void accumulate_contact_range(const fs::path& field_file, std::size_t points, SeriesExtent& e) {
  for (const double v : contact_rates_on_points(field_file, points, e.contact_note)) {
    if (!std::isfinite(v)) continue;
    e.lo = std::min(e.lo, v);
    e.hi = std::max(e.hi, v);
    e.values.push_back(v);
  }
}

}  // namespace

SeriesExtent measure_series(const std::vector<PvdEntry>& entries, const Style& style,
                            const RenderOptions& options, const fs::path& pvd) {
  SeriesExtent e;
  const bool coherence = options.field == "coherence";
  for (const auto& entry : entries) {
    const VtuMesh m = read_vtu(entry.file);
    for (const Vec2& p : m.points)
      e.world.add(p);
    if (coherence) continue;  // computed from the grain snapshots below; range fixed
    if (!style.categorical && !options.range) {
      accumulate_range(m, options.field, e.lo, e.hi, &e.values);
      if (field_shows_contact_rates(options.field))
        accumulate_contact_range(entry.file, m.points.size(), e);
    } else
      (void)point_scalar(m, options.field);  // fail early on an unknown field
  }
  SG_VERIFY(!e.world.empty(), pvd.string() << ": the snapshots hold no point");
  if (options.periodic) {
    e.world.lo.x() = options.periodic->first;
    e.world.hi.x() = options.periodic->second;
  }
  return e;
}

void choose_range(SeriesExtent& e, Style& style, const RenderOptions& options,
                  RenderResult& result) {
  const bool coherence = options.field == "coherence";
  double lo = e.lo, hi = e.hi;
  if (coherence) {
    // C lies in [-1, 1] (Cauchy-Schwarz, coherence.h): one fixed range for every run.
    lo = -1.0;
    hi = 1.0;
  }
  if (options.range) {
    lo = options.range->first;
    hi = options.range->second;
  } else if (!e.values.empty() && !coherence) {
    const double q01 = quantile(e.values, 0.01), q99 = quantile(e.values, 0.99);
    if (options.robust_range) {
      lo = q01;
      hi = q99;
    } else if (hi > lo && q99 - q01 < 0.2 * (hi - lo)) {
      result.note = "98% of the values lie in [" + format_number(q01) + ", " + format_number(q99) +
                    "], a fifth of the full range: try --robust or --range";
    }
  }
  SG_VERIFY(hi >= lo, "field '" << options.field << "': no point of any snapshot is coloured by it"
                                << " (rigid bodies only?)");
  style.lo = lo;
  style.hi = hi;
  result.has_range = true;
  result.range_min = lo;
  result.range_max = hi;
}

}  // namespace sg
