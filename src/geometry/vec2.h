#pragma once
// 2D vectors and 2x2 tensors: Eigen's fixed-size types, so the algebra is well tested
// and vectorizes; a few helpers that 2D mechanics needs and Eigen does not name.
#include <Eigen/Core>
#include <Eigen/LU>  // determinant() and inverse() of fixed-size matrices

#include <cmath>

namespace sg {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

// z-component of the 3D cross product of two in-plane vectors.
inline double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// The vector rotated by +90 degrees.
inline Vec2 perp(const Vec2& a) {
  return Vec2(-a.y(), a.x());
}

inline Mat2 rotation(double angle) {
  Mat2 r;
  const double c = std::cos(angle), s = std::sin(angle);
  r << c, -s, s, c;
  return r;
}

}  // namespace sg
