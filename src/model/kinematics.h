#pragma once
// Kinematic set-up and read-out of bodies: imposing rigid or affine fields on the MLS
// parameters (exact, since MLS reproduces linear fields) and evaluating physical positions,
// velocities and deformation gradients at the nodes.
#include "model/model.h"

namespace sg {

// Sets the velocity parameters of `body` to the rigid field v + omega x (x - c), x the current
// position and c the current centre of mass. Exact everywhere in the body.
void set_rigid_velocity(Model& model, BodyId body, const Vec2& velocity, double angular_velocity);

// Sets the displacement parameters so that the deformation is x = c + F (X - c) (c the mass
// centroid): every Gauss point then sees exactly F (linear reproduction of MLS).
void set_affine_deformation(Model& model, BodyId body, const Mat2& deformation_gradient);

// Mass-weighted centroid of the reference nodes of a body.
Vec2 reference_mass_centroid(const Model& model, BodyId body);

// Physical position x_I = X_I + sum_J N_J(X_I) u_J and velocity of node `node` (global).
Vec2 node_position(const Model& model, int node);
Vec2 node_velocity(const Model& model, int node);
// Deformation gradient and its rate at node `node` (global), from the node's own row.
Mat2 node_deformation_gradient(const Model& model, int node);

// Deformation gradient at Gauss point g (global index) of `body`.
Mat2 gauss_deformation_gradient(const Model& model, BodyId body, int g);
// Reference position of Gauss point g: sum_J N_J(x_g) X_J (exact by linear reproduction).
Vec2 gauss_reference_position(const Model& model, BodyId body, int g);

// Current positions of all contour points (Model::contour_body order): boundary-node
// positions of deformable bodies, rigidly moved points of rigid bodies. Parallel over bodies.
void compute_contour_positions(const Model& model, std::vector<Vec2>& positions);

// Totals over all nodes (parameters carry the lumped masses).
double total_mass(const Model& model);
Vec2 linear_momentum(const Model& model);
// Angular momentum about the origin, from the physical positions and parameter velocities:
// sum_I m_I (x_I x v_I). With lumped masses this is the discrete quantity the scheme conserves
// when forces are central; see the momentum test.
double angular_momentum(const Model& model);
double kinetic_energy(const Model& model);

}  // namespace sg
