#pragma once
// Contour generators for grain shapes. Every generator returns a counter-clockwise
// polygon with vertices on the exact curve, at an arc-length spacing close to `spacing`.
#include "geometry/polygon.h"

namespace sg {

Polygon make_disc(const Vec2& center, double radius, double spacing);
// Ellipse of semi-axes a (along the rotated x axis) and b, rotated by `angle` (rad).
Polygon make_ellipse(const Vec2& center, double a, double b, double angle, double spacing);
// Axis-aligned rectangle, corners included, edges subdivided at about `spacing`.
Polygon make_rectangle(const Vec2& lower_left, const Vec2& upper_right, double spacing);

}  // namespace sg
