#pragma once
// Moving Least Squares shape functions (element-free Galerkin style) on the reference
// configuration of one body.
//
// Linear basis p = [1, X, Y]; cubic-spline weight w_J(x) = w(|x - X_J| / rho_J) of compact
// support rho_J per node (Belytschko, Lu & Gu 1994, "Element-free Galerkin methods", eqs. 3-12):
//   A(x)   = sum_J w_J(x) p(X_J) p(X_J)^T           (moment matrix, 3x3)
//   N_J(x) = p(x)^T A(x)^-1 p(X_J) w_J(x)
// The basis is shifted to the evaluation point and scaled by the mean support radius, which
// keeps A well conditioned (the values are unchanged: MLS is invariant to affine changes of
// the basis). MLS reproduces linear fields exactly; N_J(X_I) != delta_IJ (not interpolating).
//
// MlsShapeFunctions is a class because it holds what every evaluation of one body shares (the
// nodes, their support radii and a neighbour grid, built once); it runs at model build only,
// never in a time step, which streams the ShapeRows it produced (docs/architecture.md §Data
// layout).
#include <span>
#include <string>
#include <vector>

#include "geometry/point_grid.h"
#include "geometry/vec2.h"
#include "meshfree/shape_rows.h"

namespace sg {

// Support size. Larger supports smooth more: MLS parameters are not nodal values, and a
// parameter pattern that oscillates from node to node is nearly annihilated by a wide
// support, so it costs almost no strain energy while still carrying lumped mass: a spurious
// low-frequency mode. Measured on a free disc (radius 1, h = 0.1, nu = 0.3; lowest analytic
// mode omega = 4.605): k = 10 with factor 1.3 gives a spurious mode at omega = 1.5; k = 12 with
// factor 1.0 one at 3.2; k = 8 or 10 with factor 1.0 give a clean spectrum (4.586, doubly
// degenerate). k = 5 is too few near the contour (singular moment matrices). Hence the defaults
// k = 8, factor 1.0 (about 10 nodes cover a Gauss point); test_vibration.cpp guards this.
struct MlsParams {
  int neighbours = 8;           // k: the support of node I reaches its k-th nearest neighbour ...
  double support_factor = 1.0;  // ... times this factor (see the note above)
  // Reciprocal condition number of A below which an evaluation point is refused.
  double min_reciprocal_condition = 1e-8;
};

// Cubic spline weight (Belytschko 1994 eq. 9) of r = d / rho, and its derivative dw/dr.
double cubic_spline_weight(double r);
double cubic_spline_weight_derivative(double r);

class MlsShapeFunctions {
 public:
  // `nodes`: reference positions of the body's field nodes. `body_name` goes into errors.
  // `min_support` (empty, or one radius per node): a floor under each node's support radius,
  // for node sets whose k nearest neighbours may all lie on one line (the rows of a strip
  // graded in depth, meshfree/periodic_strip.h); empty leaves the k-th neighbour rule alone.
  MlsShapeFunctions(std::span<const Vec2> nodes, const MlsParams& params, std::string body_name,
                    std::span<const double> min_support = {});

  // Appends to `rows` one row: the nodes whose support covers `point`, with N, dN/dX, dN/dY.
  // Throws sg::Error naming the body and the point if fewer than 3 nodes cover it or the
  // moment matrix is ill conditioned.
  void evaluate(const Vec2& point, ShapeRows& rows) const;

  const std::vector<double>& support_radius() const { return support_radius_; }

 private:
  std::vector<Vec2> nodes_;
  std::vector<double> support_radius_;
  double max_support_ = 0.0;
  double basis_scale_ = 1.0;
  MlsParams params_;
  std::string body_name_;
  PointGrid grid_;
};

}  // namespace sg
