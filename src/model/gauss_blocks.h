#pragma once
// The Gauss points of the deformable bodies in blocks of kSimdWidth (material/simd.h), the
// layout the force kernel computes with (model/internal_forces.cpp): W = kSimdWidth
// consecutive Gauss points of one body per block, their rows padded to the block's longest
// with zero-gradient entries, stored entry by entry across the lanes (structure of arrays
// within a block), so that row entry r of the W points is one aligned load of W gradients.
// A body's last block is filled with padding lanes (weight 0, no entries) when its number of
// Gauss points is not a multiple of W. The Gauss points keep their order (block b, lane l is
// the body's Gauss point b W + l), so sums over them can be done in the order of the rows.
//
// Built from Model::gauss_rows when a body is added (model.cpp); the CSR rows stay the
// reference for every other reader.
#include <cstdint>
#include <vector>

#include "material/simd.h"
#include "meshfree/shape_rows.h"

namespace sg {

struct GaussBlocks {
  static constexpr int width = kSimdWidth;
  // Block b has the padded rows [row_offset[b], row_offset[b + 1]); entry (row r, lane l) is
  // at r * width + l of node, dndx and dndy.
  std::vector<std::int32_t> row_offset{0};
  AlignedVector<std::int32_t> node;  // local node index; padding: the lane's last real node
  AlignedVector<double> dndx, dndy;  // reference gradients; 0 for padding entries
  AlignedVector<double> weight;      // per lane (b * width + l): Gauss weight, 0 for padding
  std::vector<std::int32_t> length;  // per lane: real entries of its row (0 for padding lanes)
  std::vector<std::int32_t> gauss;   // per lane: global Gauss point index, -1 for padding lanes

  std::size_t blocks() const { return row_offset.size() - 1; }
  std::size_t padded_entries() const { return node.size(); }
  // Appends the blocks of the Gauss points [0, rows.points()) of a body, whose first Gauss
  // point has the global index `gauss_begin`.
  void append_body(const ShapeRows& rows, const std::vector<double>& gauss_weight, int gauss_begin);
};

}  // namespace sg
