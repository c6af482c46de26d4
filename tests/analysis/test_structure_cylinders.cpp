#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include "analysis/structure_cylinders.h"
#include "synthetic.h"

namespace sg {
namespace {

// A labelled space-time volume as detect_agglomerates leaves it, from painted boxes.
AgglomerateResult painted(const RegularGrid& grid, int nt, double period,
                          const std::vector<std::array<int, 7>>& boxes) {
  std::vector<signed char> sign(grid.size() * static_cast<std::size_t>(nt), 0);
  for (const auto& [i0, wi, j0, wj, t0, t1, s] : boxes)
    for (int t = t0; t <= t1; ++t)
      for (int j = j0; j < j0 + wj; ++j)
        for (int i = i0; i < i0 + wi; ++i)
          sign[static_cast<std::size_t>(t) * grid.size() + grid.index(grid.wrap_i(i), j)] =
              static_cast<signed char>(s);
  AgglomerateResult a;
  a.grid = grid;
  a.frame_period = period;
  a.labels = label_space_time(sign, grid.nx, grid.ny, nt);
  a.structures = measure_structure_extents(a.labels, sign, grid, period);
  return a;
}

// A blob 4 columns wide crossing the seam of a 20-column cell (columns 18, 19, 0, 1), 3 rows
// high, frames 2-5: one cylinder standing on the seam (x = 0 up to the period, not x = 10,
// where a plain mean of its columns would put it), height 4 periods, diameter of 12 cells.
TEST(StructureCylinders, ABlobCrossingTheSeamIsOneCylinderOnTheSeam) {
  const RegularGrid grid = make_periodic_grid(0.0, 20.0, 0.0, 9.0, 1.0);
  const double period = 0.5, t0 = 10.0;
  const AgglomerateResult a = painted(grid, 8, period, {{18, 4, 3, 3, 2, 5, -1}});
  ASSERT_EQ(a.structures.size(), 1u);
  const std::vector<StructureCylinder> c = structure_cylinders(a, t0);
  ASSERT_EQ(c.size(), 1u);
  // Columns 18, 19, 0, 1 at x = 18, 19, 0, 1: symmetric about x = 19.5 on the circle.
  const double x = std::fmod(c[0].x_center + 0.5, 20.0);  // distance past 19.5, mod L
  EXPECT_NEAR(std::min(x, 20.0 - x), 0.0, 1e-9) << c[0].x_center;
  EXPECT_NEAR(c[0].y_center, 4.0, 1e-12);  // rows 3, 4, 5
  EXPECT_EQ(c[0].sign, -1);
  EXPECT_NEAR(c[0].height, 4 * period, 1e-12);
  EXPECT_NEAR(c[0].t_bottom, t0 + 1.5 * period, 1e-12);
  EXPECT_NEAR(c[0].diameter, 2.0 * std::sqrt(12.0 / std::numbers::pi), 1e-12);
  // Two separate blobs: two cylinders, in order of first appearance.
  const AgglomerateResult b =
      painted(grid, 8, period, {{18, 4, 3, 3, 2, 5, -1}, {8, 2, 1, 2, 0, 0, 1}});
  const std::vector<StructureCylinder> two = structure_cylinders(b, t0);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_EQ(two[0].sign, 1);
  EXPECT_NEAR(two[0].x_center, 8.5, 1e-9);
  EXPECT_NEAR(two[0].height, period, 1e-12);
}

TEST(StructureCylinders, SpaceTimeCsvHasOneRowPerMarkedCell) {
  const RegularGrid grid = make_periodic_grid(0.0, 20.0, 0.0, 9.0, 1.0);
  const AgglomerateResult a = painted(grid, 8, 0.5, {{18, 4, 3, 3, 2, 5, -1}});
  test::ScratchDir dir("space_time");
  write_space_time_csv(dir.file("st.csv"), a, 0.0);
  std::ifstream in(dir.file("st.csv"));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "frame,time,x,y,sign,label");
  int rows = 0;
  while (std::getline(in, line))
    ++rows;
  EXPECT_EQ(rows, 4 * 3 * 4);
}

}  // namespace
}  // namespace sg
