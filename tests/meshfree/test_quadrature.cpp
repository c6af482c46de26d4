// Triangle rules integrate every monomial up to their degree exactly, and not the next one.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "meshfree/triangle_quadrature.h"

namespace sg {
namespace {

// Exact integral of x^i y^j over the reference triangle (0,0),(1,0),(0,1): i! j! / (i+j+2)!.
double exact_monomial(int i, int j) {
  return std::tgamma(i + 1) * std::tgamma(j + 1) / std::tgamma(i + j + 3);
}

double rule_monomial(const TriangleRule& rule, int i, int j) {
  double sum = 0.0;
  for (std::size_t q = 0; q < rule.weight.size(); ++q) {
    const double x = rule.barycentric[q][1], y = rule.barycentric[q][2];
    sum += 0.5 * rule.weight[q] * std::pow(x, i) * std::pow(y, j);  // area of the triangle = 1/2
  }
  return sum;
}

TEST(TriangleQuadrature, ExactUpToDegree) {
  for (int points : {1, 3, 6, 7}) {
    const TriangleRule& rule = triangle_rule(points);
    ASSERT_EQ(rule.weight.size(), static_cast<std::size_t>(points));
    double weight_sum = 0.0;
    for (double w : rule.weight)
      weight_sum += w;
    EXPECT_NEAR(weight_sum, 1.0, 1e-14);
    for (int degree = 0; degree <= rule.degree; ++degree)
      for (int i = 0; i <= degree; ++i)
        EXPECT_NEAR(rule_monomial(rule, i, degree - i), exact_monomial(i, degree - i), 1e-14)
            << points << " points, x^" << i << " y^" << degree - i;
    // The rules are not exact one degree higher (checks the degree claim is tight).
    double worst = 0.0;
    const int next = rule.degree + 1;
    for (int i = 0; i <= next; ++i)
      worst =
          std::max(worst, std::abs(rule_monomial(rule, i, next - i) - exact_monomial(i, next - i)));
    EXPECT_GT(worst, 1e-6) << points << " points";
  }
}

TEST(TriangleQuadrature, UnsupportedCountIsAnError) {
  EXPECT_THROW(triangle_rule(4), Error);
}

}  // namespace
}  // namespace sg
