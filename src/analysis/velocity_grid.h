#pragma once
#include "meshfree/mls.h"  // cubic_spline_weight
// Grain centre-of-mass velocities carried to the regular grid of the coherence analysis
// (paper 002 §2.2: "interpolated ... cubic, which allows C^2 continuity").
//
// Scheme: moving least squares (Lancaster & Salkauskas 1981, Math. Comp. 37:141-158;
// the EFG approximation of Belytschko, Lu & Gu 1994, IJNME 37:229-256) with a linear
// basis [1, x, y] and the cubic-spline weight of support radius rho (C^2 in space).
// At a grid node p the velocity is the value at p of the linear field fitted to the
// grains within rho by least squares weighted by W(|x_i - p| / rho).
// Why this scheme rather than the alternatives weighed:
//  - it is C^2, as the paper asks (the field is as smooth as the weight);
//  - it reproduces linear fields exactly, so a rigid-body motion or a uniform shear of
//    the grains reaches the grid unchanged: the coherence (eq. 5) of an ideal rotation is
//    exactly +-1, which is the property the detector is built on. A plain kernel
//    average (Shepard) would bias it; Clough-Tocher ("cubic" griddata) is only C^1;
//  - it is local (cost ~ grid nodes x ~12 grains) and exactly periodic: distances along
//    x are taken to the nearest periodic image. A global cubic polyharmonic spline
//    (phi = r^3 plus a linear polynomial, also C^2 and linear-exact) interpolates the data
//    exactly but needs a dense O(N^3) solve per snapshot and is not periodic;
//  - it is the approximation the engine's own discretization uses (docs/method.md §MLS shape
//    functions).
// It approximates rather than interpolates: grid values are local least-squares fits,
// which smooth grain-to-grain noise at the scale rho (default 2 grain diameters, below
// the coherence radius R of 2-3 diameters, so structures are not blurred away).
// A node is marked invalid (no data) if fewer than `min_grains` grains lie in its
// support or the moment matrix is near-singular (grains nearly collinear); coherence
// ignores invalid nodes.
#include <vector>

#include "analysis/grain_snapshot.h"
#include "analysis/regular_grid.h"
#include "geometry/vec2.h"

namespace sg {

struct VelocityGrid {
  RegularGrid grid;
  std::vector<Vec2> velocity;        // per node, flat index grid.index(i, j)
  std::vector<unsigned char> valid;  // 1 where the MLS fit is defined
};

struct VelocityFitParams {
  double support_radius = 2.0;  // rho (length); default 2 mean grain diameters
  int min_grains = 3;           // fewest grains in the support for a defined fit
  // Smallest accepted ratio of eigenvalues of the (scaled) moment matrix; below it the
  // grains are too close to collinear for a linear fit.
  double min_eigen_ratio = 1e-6;
};

// The weight is the same C^2 cubic spline as the meshfree shape functions
// (meshfree/mls.h: cubic_spline_weight).

// Throws sg::Error if rho >= L/2 (a grain would be seen through both periodic images).
VelocityGrid interpolate_velocity_grid(const GrainSnapshot& grains, const RegularGrid& grid,
                                       const VelocityFitParams& params);

}  // namespace sg
