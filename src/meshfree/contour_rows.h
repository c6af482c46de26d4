#pragma once
// Rows of a deformable body's contour points, consistent with the contact forces they carry.
//
// A contact puts a traction p_i on contour point i over its tributary length l_i
// (contact/node_segment.h). Read as a traction interpolated linearly between contour points,
// the Galerkin-consistent force on field node J is  F_J = sum_i p_i  int phi_i N_J ds
// (phi_i the hat function of point i on its two adjacent segments), not  p_i l_i N_J(X_i),
// the point load at X_i. With the point load, a uniform traction on a face is not balanced by
// a uniform stress (MLS shape functions are not integrated exactly by a two-point rule along
// the face): two deformable blocks bonded face to face and pulled apart carried 12-14% more
// than the mean traction on the second contour point from each corner, and the brittle
// cohesive law unzipped the interface at 0.90 of sigma_c L, at every node spacing tried
// (tests/solver/test_contact_deformable.cpp).
//
// The contour row of point i is therefore the hat-weighted average of the MLS rows along its
// two segments:
//
//   R_J = sum_k w_k N_J(x_k) / sum_k w_k,   w_k = (Gauss weight) |segment| phi_i(x_k),
//
// used for both the point's displacement and the spreading of its force, so that the two are
// work-conjugate (energy balance) and contacts keep action = reaction. Bonded blocks then
// separate at 0.956 / 0.978 / 0.941 of sigma_c L for node spacings 0.1 / 0.05 / 0.025 with 3
// Gauss points per triangle, 0.963 / 0.975 / 0.973 with 6. Partition of unity carries over (sum_J
// R_J = 1: translations are exact), but the average of a linear field is its value at the hat
// centroid Xbar_i = sum w x / sum w, which lies inside a curved or cornered contour: a rigid
// rotation Q would move the point by (Q - I) Xbar_i instead of (Q - I) X_i, and a disc turned half
// a revolution would look inflated by 2 |X_i - Xbar_i| ~ h^2 / (3 r). The position therefore adds
// the offset d_i = X_i - Xbar_i rotated with the material around it (model/kinematics.h):
//
//   x_i = X_i + sum_J R_J u_J + (Q(theta) - I) d_i,  theta the polar rotation angle of the
//   body's mean deformation gradient F = I + sum_J u_J (x) c_J, c_J = (1/A) int grad N_J dA
//   (Model::mean_gradient_x/y; one angle per body, its moment spread once per body),
//
// exact for any rigid motion. (Turning d_i with the point's own hat-averaged F instead
// couples the corner points to the local rotation: the bonded blocks broke at 0.84.) (A linear
// correction (X_i - Xbar_i) . grad R_J in the row itself is exact too but stiffens the corner
// points of a block: the bonded blocks then broke at 0.79 of sigma_c L.) On a straight stretch d_i
// = 0 and the row is the consistent row itself. Gradients of the row: hat-weighted averages of grad
// N_J.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/vec2.h"
#include "meshfree/shape_rows.h"

namespace sg {

// Quadrature of the hat function of contour point `point` over its segments [previous,
// point] and [point, next]: 4 Gauss-Legendre points per segment (exact for polynomials of
// degree 7 along a segment; an MLS row is smooth at the scale of its support, ~2-3 spacings).
struct HatQuadrature {
  static constexpr std::size_t size = 8;
  std::array<Vec2, size> point{};
  std::array<double, size> weight{};  // phi(x) ds; they sum to the tributary length
  Vec2 centroid = Vec2::Zero();       // Xbar = sum w x / sum w
};
HatQuadrature hat_quadrature(const Vec2& point, const Vec2& previous, const Vec2& next);

// Appends to `out` the contour row of a point (formula above) from `at_quadrature`, whose
// rows [0, HatQuadrature::size) are the MLS rows at hat.point[k]. The point's offset d_i is
// point - hat.centroid. `images` is empty, or (a
// periodic strip) holds the periodic image of each entry of `at_quadrature`; entries of the
// same node and image are merged, in increasing node order, and the image of each output
// entry goes to `out_images` (when not null).
void append_contour_row(const ShapeRows& at_quadrature, std::span<const std::int8_t> images,
                        const HatQuadrature& hat, ShapeRows& out,
                        std::vector<std::int8_t>* out_images);

}  // namespace sg
