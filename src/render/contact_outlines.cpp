#include "render/contact_outlines.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

#include "core/error.h"

namespace sg {

namespace fs = std::filesystem;

bool field_shows_contact_rates(const std::string& field) {
  return field == "strain_rate" || field == "strain_rate_instant";
}

std::vector<double> contact_rates_on_points(const fs::path& field_file, std::size_t point_count,
                                            std::string& note) {
  // fields/NNNNNN.vtu -> contacts/NNNNNN.vtu (written with every field snapshot).
  const fs::path contacts =
      field_file.parent_path().parent_path() / "contacts" / field_file.filename();
  if (!fs::exists(contacts)) return {};
  const VtuMesh m = read_vtu(contacts);
  const VtuArray* rate = m.find("contact_rate");
  const VtuArray* point = m.find("field_point");
  if (rate == nullptr || point == nullptr) {
    note = "'" + contacts.string() +
           "' has no contact_rate (written by an older softgrain): outlines not coloured";
    return {};
  }
  std::vector<double> out(point_count, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    const double p = point->values[i];
    SG_VERIFY(p >= 0.0 && p < static_cast<double>(point_count),
              contacts.string() << ": contact " << i << " names field point " << p << ", '"
                                << field_file.string() << "' has " << point_count << " points");
    double& v = out[static_cast<std::size_t>(p)];
    if (std::isfinite(rate->values[i]) && !(v >= rate->values[i])) v = rate->values[i];
  }
  return out;
}

std::vector<std::pair<int, int>> boundary_edges(const VtuMesh& m, bool with_polygons) {
  // Counted in a hash map (millions of edges on the papers' samples), the result sorted: a
  // drawing order that does not depend on the hash.
  std::unordered_map<std::uint64_t, int> count;
  count.reserve(3 * m.cell_count());
  auto key = [](int a, int b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
           static_cast<std::uint32_t>(b);
  };
  for (std::size_t c = 0; c < m.cell_count(); ++c) {
    if (m.types[c] != kVtkTriangle) continue;
    const auto cell = m.cell(c);
    for (std::size_t k = 0; k < 3; ++k)
      ++count[key(cell[k], cell[(k + 1) % 3])];
  }
  std::vector<std::pair<int, int>> out;
  for (const auto& [e, n] : count)
    if (n == 1) out.emplace_back(static_cast<int>(e >> 32), static_cast<int>(e & 0xffffffffu));
  std::sort(out.begin(), out.end());
  auto edge = [](int a, int b) { return a < b ? std::make_pair(a, b) : std::make_pair(b, a); };
  if (with_polygons) {
    for (std::size_t c = 0; c < m.cell_count(); ++c) {
      if (m.types[c] != kVtkPolygon) continue;
      const auto cell = m.cell(c);
      for (std::size_t k = 0; k < cell.size(); ++k)
        out.push_back(edge(cell[k], cell[(k + 1) % cell.size()]));
    }
  }
  return out;
}

}  // namespace sg
