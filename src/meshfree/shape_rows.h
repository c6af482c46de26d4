#pragma once
// Shape-function rows in compressed (CSR) form: for evaluation point p, the nodes
// node[offset[p] .. offset[p+1]) with their values N and reference gradients dN/dX, dN/dY.
// Node indices are local to the body. Structure of arrays: the internal-force kernel
// streams through dndx/dndy/node contiguously.
#include <cstdint>
#include <vector>

namespace sg {

struct ShapeRows {
  std::vector<std::int32_t> offset{0};  // size = points + 1
  std::vector<std::int32_t> node;
  std::vector<double> value;
  std::vector<double> dndx;
  std::vector<double> dndy;

  std::size_t points() const { return offset.size() - 1; }
  std::size_t entries() const { return node.size(); }
  void append(const ShapeRows& other);  // concatenates rows (same node numbering)
};

}  // namespace sg
