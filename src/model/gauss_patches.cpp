#include "model/gauss_patches.h"

#include <cstdlib>
#include <string>

namespace sg {

GaussPatches gauss_patches(const BodyDiscretization& d) {
  GaussPatches out;
  const std::size_t points = d.gauss_weight.size();
  out.patch.resize(points);
  // TEMPORARY (measurement of the patch choice): SOFTGRAIN_FBAR_PATCH=N groups N consecutive
  // points (one triangle of an N-point rule).
  if (const char* env = std::getenv("SOFTGRAIN_FBAR_PATCH")) {
    const int n = std::stoi(env);
    for (std::size_t g = 0; g < points; ++g)
      out.patch[g] = static_cast<int>(g) / n;
    out.count = static_cast<int>((points + static_cast<std::size_t>(n) - 1) / static_cast<std::size_t>(n));
    return out;
  }
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
