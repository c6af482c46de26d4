#include "meshfree/contour_rows.h"

#include <algorithm>
#include <tuple>

#include "core/error.h"

namespace sg {

HatQuadrature hat_quadrature(const Vec2& point, const Vec2& previous, const Vec2& next) {
  // Gauss-Legendre, 4 points on [0, 1].
  static constexpr std::array<double, 4> xi = {0.0694318442029737, 0.3300094782075719,
                                               0.6699905217924281, 0.9305681557970263};
  static constexpr std::array<double, 4> wi = {0.1739274225337269, 0.3260725774662731,
                                               0.3260725774662731, 0.1739274225337269};
  HatQuadrature hat;
  double total = 0.0;
  Vec2 moment = Vec2::Zero();
  std::size_t k = 0;
  for (const Vec2& neighbour : {previous, next}) {
    const Vec2 d = neighbour - point;
    const double length = d.norm();
    for (std::size_t g = 0; g < xi.size(); ++g, ++k) {
      // x = point + xi d; the hat is 1 at the point and 0 at the neighbour.
      hat.point[k] = point + xi[g] * d;
      hat.weight[k] = wi[g] * length * (1.0 - xi[g]);
      total += hat.weight[k];
      moment += hat.weight[k] * hat.point[k];
    }
  }
  SG_VERIFY(total > 0.0, "contour point (" << point.x() << ", " << point.y()
                                           << ") coincides with both its neighbours");
  hat.centroid = moment / total;
  return hat;
}

void append_contour_row(const ShapeRows& at_quadrature, std::span<const std::int8_t> images,
                        const HatQuadrature& hat, ShapeRows& out,
                        std::vector<std::int8_t>* out_images) {
  SG_ASSERT(at_quadrature.points() == HatQuadrature::size,
            at_quadrature.points() << " rows for " << HatQuadrature::size << " hat points");
  SG_ASSERT(images.empty() || images.size() == at_quadrature.entries(),
            images.size() << " images for " << at_quadrature.entries() << " entries");
  double total = 0.0;
  for (const double w : hat.weight)
    total += w;
  struct Entry {
    std::int32_t node;
    std::int8_t image;
    double value, dndx, dndy;
  };
  std::vector<Entry> entries;
  entries.reserve(at_quadrature.entries());
  for (std::size_t k = 0; k < HatQuadrature::size; ++k) {
    const double w = hat.weight[k] / total;
    for (auto e = static_cast<std::size_t>(at_quadrature.offset[k]);
         e < static_cast<std::size_t>(at_quadrature.offset[k + 1]); ++e) {
      const double gx = at_quadrature.dndx[e], gy = at_quadrature.dndy[e];
      entries.push_back({at_quadrature.node[e], images.empty() ? std::int8_t{0} : images[e],
                         w * at_quadrature.value[e], w * gx, w * gy});
    }
  }
  std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return std::tie(a.node, a.image) < std::tie(b.node, b.image);
  });
  for (std::size_t i = 0; i < entries.size();) {
    Entry sum = entries[i];
    std::size_t j = i + 1;
    // Summed in quadrature order (stable sort): deterministic.
    for (; j < entries.size() && entries[j].node == sum.node && entries[j].image == sum.image;
         ++j) {
      sum.value += entries[j].value;
      sum.dndx += entries[j].dndx;
      sum.dndy += entries[j].dndy;
    }
    out.node.push_back(sum.node);
    out.value.push_back(sum.value);
    out.dndx.push_back(sum.dndx);
    out.dndy.push_back(sum.dndy);
    if (out_images != nullptr) out_images->push_back(sum.image);
    i = j;
  }
  out.offset.push_back(static_cast<std::int32_t>(out.node.size()));
}

}  // namespace sg
