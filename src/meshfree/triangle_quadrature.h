#pragma once
// Gauss (symmetric Dunavant) rules on triangles, exact for polynomials up to a degree:
//   1 point: degree 1, 3 points: degree 2, 6 points: degree 4, 7 points: degree 5.
// Dunavant, "High degree efficient symmetrical Gaussian quadrature rules for the triangle",
// IJNME 21 (1985), table I. Weights sum to 1 (multiply by the triangle area).
#include <array>
#include <vector>

namespace sg {

struct TriangleRule {
  std::vector<std::array<double, 3>> barycentric;
  std::vector<double> weight;
  int degree = 0;
};

// Throws sg::Error for an unsupported point count (supported: 1, 3, 6, 7).
const TriangleRule& triangle_rule(int points);

}  // namespace sg
