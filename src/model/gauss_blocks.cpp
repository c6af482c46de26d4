#include "model/gauss_blocks.h"

#include <algorithm>

#include "core/error.h"

namespace sg {

void GaussBlocks::append_body(const ShapeRows& rows, const std::vector<double>& gauss_weight,
                              int gauss_begin) {
  SG_VERIFY(gauss_weight.size() == rows.points(),
            "Gauss blocks: " << gauss_weight.size() << " weights for " << rows.points()
                             << " rows, expected one per row");
  const auto points = static_cast<int>(rows.points());
  for (int first = 0; first < points; first += width) {
    const int lanes = std::min(width, points - first);
    int padded = 0;
    for (int l = 0; l < lanes; ++l)
      padded = std::max(padded, rows.offset[first + l + 1] - rows.offset[first + l]);
    const std::size_t base = node.size();
    const std::size_t size = base + static_cast<std::size_t>(padded * width);
    node.resize(size, 0);
    dndx.resize(size, 0.0);
    dndy.resize(size, 0.0);
    for (int l = 0; l < width; ++l) {
      const bool real = l < lanes;
      const int g = first + l;
      const int begin = real ? rows.offset[g] : 0, count = real ? rows.offset[g + 1] - begin : 0;
      // Padding entries repeat a node of the lane's own row: a non-finite displacement there
      // is one the lane reads anyway (0 * inf would otherwise poison a lane that does not
      // touch that node).
      const std::int32_t pad_node = count > 0 ? rows.node[begin + count - 1] : 0;
      for (int r = 0; r < padded; ++r) {
        const std::size_t e = base + static_cast<std::size_t>(r * width + l);
        if (r < count) {
          node[e] = rows.node[begin + r];
          dndx[e] = rows.dndx[begin + r];
          dndy[e] = rows.dndy[begin + r];
        } else {
          node[e] = pad_node;
        }
      }
      weight.push_back(real ? gauss_weight[static_cast<std::size_t>(g)] : 0.0);
      length.push_back(count);
      gauss.push_back(real ? gauss_begin + g : -1);
    }
    row_offset.push_back(row_offset.back() + padded);
  }
}

}  // namespace sg
