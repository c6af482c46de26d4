#include "meshfree/triangle_quadrature.h"

#include "core/error.h"

namespace sg {

namespace {

// Adds the three permutations of the barycentric triple (a, b, b).
void add_orbit(TriangleRule& rule, double a, double weight) {
  const double b = 0.5 * (1.0 - a);
  rule.barycentric.push_back({a, b, b});
  rule.barycentric.push_back({b, a, b});
  rule.barycentric.push_back({b, b, a});
  for (int k = 0; k < 3; ++k)
    rule.weight.push_back(weight);
}

TriangleRule make_rule(int points) {
  TriangleRule rule;
  switch (points) {
    case 1:
      rule.barycentric.push_back({1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0});
      rule.weight.push_back(1.0);
      rule.degree = 1;
      break;
    case 3:
      add_orbit(rule, 2.0 / 3.0, 1.0 / 3.0);
      rule.degree = 2;
      break;
    case 6:
      add_orbit(rule, 0.108103018168070, 0.223381589678011);
      add_orbit(rule, 0.816847572980459, 0.109951743655322);
      rule.degree = 4;
      break;
    case 7:
      rule.barycentric.push_back({1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0});
      rule.weight.push_back(0.225);
      add_orbit(rule, 0.059715871789770, 0.132394152788506);
      add_orbit(rule, 0.797426985353087, 0.125939180544827);
      rule.degree = 5;
      break;
    default:
      SG_THROW("unsupported number of Gauss points per triangle: " << points
                                                                   << " (expected 1, 3, 6 or 7)");
  }
  return rule;
}

}  // namespace

const TriangleRule& triangle_rule(int points) {
  static const TriangleRule rules[4] = {make_rule(1), make_rule(3), make_rule(6), make_rule(7)};
  switch (points) {
    case 1:
      return rules[0];
    case 3:
      return rules[1];
    case 6:
      return rules[2];
    case 7:
      return rules[3];
    default:
      make_rule(points);  // throws with the message
      SG_THROW("unreachable");
  }
}

}  // namespace sg
