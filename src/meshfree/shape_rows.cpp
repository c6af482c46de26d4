#include "meshfree/shape_rows.h"

namespace sg {

void ShapeRows::append(const ShapeRows& other) {
  const std::int32_t base = offset.back();
  for (std::size_t p = 1; p < other.offset.size(); ++p)
    offset.push_back(base + other.offset[p]);
  node.insert(node.end(), other.node.begin(), other.node.end());
  value.insert(value.end(), other.value.begin(), other.value.end());
  dndx.insert(dndx.end(), other.dndx.begin(), other.dndx.end());
  dndy.insert(dndy.end(), other.dndy.begin(), other.dndy.end());
}

}  // namespace sg
