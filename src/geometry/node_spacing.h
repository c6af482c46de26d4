#pragma once
// A body's own node spacings (issue #32): the spacing of its contour nodes and the spacing its
// mesh coarsens to inwards (deepest point of a closed grain, back face of a periodic strip).
// Set per material or per grain component of a builder in a scenario (docs/scenario.md,
// "Node spacing per body"); a value of 0 leaves the scenario's [discretization] spacing.
// Here, in the geometry stage, because the grain components of a mixture carry it
// (grain_population.h) before anything is meshed (meshfree/domain_mesh.h).
namespace sg {

struct NodeSpacing {
  double contour = 0.0;   // spacing of the contour nodes (length); 0: not set
  double interior = 0.0;  // spacing deep inside (length), >= contour; 0: same as contour
  bool graded() const { return interior > contour; }
};

}  // namespace sg
