#pragma once
// The coherence field of paper 002 §2.2, eq. 5: at each grid node P, how much the
// velocity field in the disc S of radius R around P looks like a rigid rotation,
//
//   C(P, R) = sum_{M in S} (V - V_ave) . V_circ
//             / ( sqrt(sum_{M in S} |V - V_ave|^2) sqrt(sum_{M in S} |V_circ|^2) )
//
// with V_ave the mean of V over S and V_circ = e_z x (M - P) the velocity of a unit
// counter-clockwise rotation about P. The integrals of eq. 5 become sums over grid nodes
// (the cell area dS = hx hy cancels). C = +1: rigid counter-clockwise rotation (positive);
// C = -1: clockwise. By the Cauchy-Schwarz inequality |C| <= 1.
//
// Conventions this implementation makes explicit:
//  - x is periodic: the disc wraps across the seam (R < L/2 is required). Along y the
//    disc is cut by the grid's edges; only valid nodes (velocity defined) count.
//  - A node is *undefined* (defined = 0, value 0) if it is itself invalid or if fewer than
//    `min_valid_fraction` of its disc's nodes are valid: a disc mostly in a pore or
//    outside the layer says nothing about rotation.
//  - Uniform translation (V - V_ave = 0 on the disc, to a relative tolerance): eq. 5 is
//    0/0; we define C = 0 (defined = 1). A translating region is not rotating, and
//    ranking it as coherent would flag every wall-attached grain row as an agglomerate.
//    "Uniform" means sum |V - V_ave|^2 <= tol^2 * sum |V|^2 (tol = 1e-10, well above the
//    rounding of the MLS fit, far below any physical rotation); a disc at rest is C = 0.
//  - Simple shear V = (g y, 0): C = -sign(g)/sqrt(2) on a full disc centred on a node.
#include <vector>

#include "analysis/velocity_grid.h"

namespace sg {

struct CoherenceParams {
  double radius = 2.5;               // R (length); paper 002: 2 to 3 grain diameters
  double min_valid_fraction = 0.5;   // see above
  double uniform_tolerance = 1e-10;  // see above
};

struct CoherenceField {
  RegularGrid grid;
  std::vector<double> value;           // C per node, in [-1, 1]
  std::vector<unsigned char> defined;  // 1 where C is defined
};

// Throws sg::Error if R <= 0 or if the disc would overlap itself across the period.
CoherenceField compute_coherence(const VelocityGrid& velocity, const CoherenceParams& params);

}  // namespace sg
