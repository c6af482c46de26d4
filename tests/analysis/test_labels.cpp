#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis/agglomerates.h"
#include "analysis/space_time_labels.h"
#include "core/error.h"

namespace sg {
namespace {

// A space-time sign volume with boxes painted in.
struct Volume {
  int nx, ny, nt;
  std::vector<signed char> sign;
  Volume(int x, int y, int t) : nx(x), ny(y), nt(t), sign(static_cast<std::size_t>(x * y * t), 0) {}
  std::size_t at(int i, int j, int t) const {
    return static_cast<std::size_t>((t * ny + j) * nx + ((i % nx) + nx) % nx);
  }
  // Cells i in [i0, i0 + wi) (wrapping in x), j in [j0, j0 + wj), t in [t0, t1].
  void box(int i0, int wi, int j0, int wj, int t0, int t1, signed char s) {
    for (int t = t0; t <= t1; ++t)
      for (int j = j0; j < j0 + wj; ++j)
        for (int i = i0; i < i0 + wi; ++i)
          sign[at(i, j, t)] = s;
  }
};

TEST(SpaceTimeLabels, BlobsAreCountedWithTheirLifetimesAndDiameters) {
  const RegularGrid grid = make_periodic_grid(0.0, 20.0, 0.0, 9.0, 1.0);  // 20 x 10, h = 1
  Volume v(grid.nx, grid.ny, 12);
  v.box(3, 3, 2, 3, 2, 5, 1);    // A: 3 x 3, frames 2-5, counter-clockwise
  v.box(10, 2, 1, 2, 0, 1, -1);  // B: 2 x 2, frames 0-1, clockwise
  v.box(18, 4, 4, 3, 6, 9, 1);   // C: columns 18, 19, 0, 1 (across the seam), frames 6-9
  v.box(6, 2, 5, 2, 5, 5, 1);    // D: touches A only at a corner (6,5) vs (5,4): separate
  v.box(10, 2, 3, 2, 0, 1, 1);   // E: face-adjacent to B but of the other sign: separate
  const SpaceTimeLabels labels = label_space_time(v.sign, v.nx, v.ny, v.nt);
  ASSERT_EQ(labels.count, 5);
  // Labels in order of first appearance (t, j, i): B (t=0, j=1), E (t=0, j=3), A, D, C.
  EXPECT_EQ(labels.label[v.at(10, 1, 0)], 0);
  EXPECT_EQ(labels.label[v.at(10, 3, 0)], 1);
  EXPECT_EQ(labels.label[v.at(3, 2, 2)], 2);
  EXPECT_EQ(labels.label[v.at(6, 5, 5)], 3);
  EXPECT_EQ(labels.label[v.at(18, 4, 6)], 4);
  EXPECT_EQ(labels.label[v.at(1, 6, 9)], 4);  // the other side of the seam: same structure
  EXPECT_EQ(labels.label[v.at(0, 0, 0)], -1);

  const double period = 0.5;
  const std::vector<Structure> s = measure_structure_extents(labels, v.sign, grid, period);
  ASSERT_EQ(s.size(), 5u);
  auto diameter = [&](double cells) {
    return 2.0 * std::sqrt(cells * grid.hx * grid.hy / std::numbers::pi);
  };
  // B
  EXPECT_EQ(s[0].sign, -1);
  EXPECT_EQ(s[0].frame_count, 2);
  EXPECT_DOUBLE_EQ(s[0].lifetime, 2 * period);
  EXPECT_DOUBLE_EQ(s[0].diameter, diameter(4));
  // A
  EXPECT_EQ(s[2].sign, 1);
  EXPECT_EQ(s[2].first_frame, 2);
  EXPECT_EQ(s[2].last_frame, 5);
  EXPECT_DOUBLE_EQ(s[2].lifetime, 4 * period);
  EXPECT_DOUBLE_EQ(s[2].mean_area, 9.0);
  EXPECT_DOUBLE_EQ(s[2].diameter, diameter(9));
  // D: one frame
  EXPECT_DOUBLE_EQ(s[3].lifetime, period);
  EXPECT_DOUBLE_EQ(s[3].diameter, diameter(4));
  // C across the seam: 4 x 3 cells, 4 frames
  EXPECT_EQ(s[4].frame_count, 4);
  EXPECT_DOUBLE_EQ(s[4].mean_area, 12.0);
  EXPECT_DOUBLE_EQ(s[4].diameter, diameter(12));
}

TEST(SpaceTimeLabels, AMovingBlobStaysOneStructureAndItsAreaIsAveraged) {
  // A blob drifting one column per frame overlaps its previous position: one structure.
  // It grows from 2 x 2 to 2 x 4 halfway: mean area (4 x 4 + 4 x 8) / 8 = 6.
  const RegularGrid grid = make_periodic_grid(0.0, 10.0, 0.0, 5.0, 1.0);
  Volume v(grid.nx, grid.ny, 8);
  for (int t = 0; t < 8; ++t)
    v.box(t, 2, 1, t < 4 ? 2 : 4, t, t, -1);  // wraps after column 9
  const SpaceTimeLabels labels = label_space_time(v.sign, v.nx, v.ny, v.nt);
  ASSERT_EQ(labels.count, 1);
  const std::vector<Structure> s = measure_structure_extents(labels, v.sign, grid, 1.0);
  EXPECT_EQ(s[0].frame_count, 8);
  EXPECT_DOUBLE_EQ(s[0].mean_area, 6.0);
  // Not touching in time: two structures.
  Volume gap(grid.nx, grid.ny, 3);
  gap.box(2, 2, 2, 2, 0, 0, 1);
  gap.box(2, 2, 2, 2, 2, 2, 1);
  EXPECT_EQ(label_space_time(gap.sign, gap.nx, gap.ny, gap.nt).count, 2);
}

TEST(SpaceTimeLabels, ChecksItsInput) {
  EXPECT_THROW(label_space_time(std::vector<signed char>(5, 0), 2, 2, 2), Error);
  EXPECT_EQ(label_space_time({}, 3, 3, 0).count, 0);
}

}  // namespace
}  // namespace sg
