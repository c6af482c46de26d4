#include "analysis/space_time_labels.h"

#include "analysis/union_find.h"
#include "core/error.h"

namespace sg {

SpaceTimeLabels label_space_time(const std::vector<signed char>& sign, int nx, int ny, int nt) {
  SG_VERIFY(nx >= 1 && ny >= 1 && nt >= 0,
            "labelling: bad dimensions " << nx << " x " << ny << " x " << nt);
  const std::size_t total =
      static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) * static_cast<std::size_t>(nt);
  SG_VERIFY(sign.size() == total, "labelling: " << sign.size() << " cells, expected " << total);
  auto cell = [&](int i, int j, int t) {
    return (static_cast<std::size_t>(t) * static_cast<std::size_t>(ny) +
            static_cast<std::size_t>(j)) *
               static_cast<std::size_t>(nx) +
           static_cast<std::size_t>(i);
  };
  UnionFind sets(total);
  // Each cell joins its backward neighbours (i-1 periodic, j-1, t-1); with the forward ones
  // visited from the other side, that covers all 6 face neighbours.
  for (int t = 0; t < nt; ++t)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const std::size_t c = cell(i, j, t);
        const signed char s = sign[c];
        if (s == 0) continue;
        if (nx > 1) {
          const std::size_t w = cell(i == 0 ? nx - 1 : i - 1, j, t);  // periodic seam
          if (sign[w] == s) sets.unite(c, w);
        }
        if (j > 0 && sign[cell(i, j - 1, t)] == s) sets.unite(c, cell(i, j - 1, t));
        if (t > 0 && sign[cell(i, j, t - 1)] == s) sets.unite(c, cell(i, j, t - 1));
      }
  SpaceTimeLabels out;
  out.nx = nx;
  out.ny = ny;
  out.nt = nt;
  out.label.assign(total, -1);
  std::vector<int> root_label(total, -1);
  for (std::size_t c = 0; c < total; ++c) {
    if (sign[c] == 0) continue;
    const std::size_t r = sets.find(c);
    if (root_label[r] < 0) root_label[r] = out.count++;
    out.label[c] = root_label[r];
  }
  return out;
}

}  // namespace sg
