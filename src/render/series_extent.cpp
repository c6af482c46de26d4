#include "render/series_extent.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "render/coherence_arrays.h"
#include "render/contact_outlines.h"

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
  const bool from_grains = field_from_grain_snapshots(options.field);
  for (const auto& entry : entries) {
    const VtuMesh m = read_vtu(entry.file);
    for (const Vec2& p : m.points)
      e.world.add(p);
    if (from_grains) continue;  // computed from the grain snapshots; range fixed
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

}  // namespace sg
