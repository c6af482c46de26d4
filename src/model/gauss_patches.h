#pragma once
// The patches of Gauss points over which the F-bar formulation averages det F
// (material.h VolumetricFormulation::fbar, model/force_kernel_impl.h).
//
// A patch is the set of Gauss points nearest to one node (BodyDiscretization::gauss_node): with
// 3 points per triangle each point of a triangle goes to a different vertex, so a node's patch
// is its median-dual cell, about 6 points over the triangles around it. That gives one
// volumetric constraint per node against two displacement parameters, the ratio of the Q1/P0
// element that does not lock; the Gauss points of one triangle as a patch would give one per
// triangle, about two per node, one per parameter, and cured half as much (docs/method.md
// "Nearly incompressible grains: F-bar": at nu = 0.495, D/8, 3 points, a squeezed disc +5.6% /
// +8.0% too stiff at 20% / 35% compression with triangle patches, +2.9% / +6.2% with node
// patches, +12.1% / +10.5% standard).
#include <vector>

#include "meshfree/body_discretization.h"

namespace sg {

struct GaussPatches {
  std::vector<int> patch;  // per Gauss point of the body: its patch, numbered from 0
  int count = 0;
};

// Patches numbered in the order of their first Gauss point. A discretization without
// gauss_node (assembled by hand) gets one patch per point: F-bar is then the standard form.
GaussPatches gauss_patches(const BodyDiscretization& d);

}  // namespace sg
