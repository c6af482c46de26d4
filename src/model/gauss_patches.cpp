#include "model/gauss_patches.h"

namespace sg {

GaussPatches gauss_patches(const BodyDiscretization& d) {
  GaussPatches out;
  const std::size_t points = d.gauss_weight.size();
  out.patch.resize(points);
  if (d.gauss_node.size() != points) {
    for (std::size_t g = 0; g < points; ++g)
      out.patch[g] = static_cast<int>(g);
    out.count = static_cast<int>(points);
    return out;
  }
  std::vector<int> patch_of_node(d.mesh.nodes.size(), -1);
  for (std::size_t g = 0; g < points; ++g) {
    int& p = patch_of_node[static_cast<std::size_t>(d.gauss_node[g])];
    if (p < 0) p = out.count++;
    out.patch[g] = p;
  }
  return out;
}

}  // namespace sg
