#pragma once
// Building the explicitly described bodies of a scenario (grains, walls, strips) into a
// Model: build_model's helpers (scenario.h), internal to the scenario stage.
#include "model/model.h"
#include "scenario/scenario.h"

namespace sg {

// A grain's contour at about the node spacing h: a disc or an ellipse sampled at h, or the
// given contour with every edge subdivided into pieces of at most h (its vertices kept).
Polygon grain_contour(const GrainSpec& g, double h);

// Adds a rigid grain with its initial velocities and drive (a velocity-driven axis starts at
// its history's value at t = 0).
void add_rigid_grain(Model& model, const GrainSpec& g, MaterialId material, double h);

// Adds a [[walls]] rectangle, held or moving at its velocity, then its drive's axes.
void add_wall(Model& model, const WallDef& w, MaterialId material, double h);

// Adds a [[strips]] strip spanning [x_min, x_max): rigid (mass and inertia of the region
// between the surface line and the back face, as the shear cell's first bodies) or
// deformable (meshfree/periodic_strip.h, its back face driven); every axis held unless its
// drive says otherwise.
void add_strip(Model& model, const StripDef& strip, MaterialId material, double x_min, double x_max,
               const DiscretizationParams& params);

}  // namespace sg
