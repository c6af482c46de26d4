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

// Rotation of a deformable body as a whole: the polar angle theta of its mean deformation
// gradient F = I + sum_J u_J (x) c_J (Model::mean_gradient_x/y), theta = atan2(F21 - F12,
// F11 + F22), kept as (a, b) = (F11 + F22, F21 - F12): cos = a / r, sin = b / r, r = |(a, b)|.
// Exact for a rigid rotation of any size. Contour points rotate their hat offset with it
// (meshfree/contour_rows.h). (The rotation of each point's own averaged gradient is exact too
// but couples a block's corner point to the local rotation there: bonded blocks then broke at
// 0.84 of sigma_c L instead of 0.975.)
struct BodyRotation {
  double a = 2.0, b = 0.0;
  double r2() const { return a * a + b * b; }
  Vec2 rotate(const Vec2& d) const;  // Q(theta) d
  Mat2 matrix() const;               // Q(theta)
};
BodyRotation body_rotation(const Model& model, BodyId body);
// The same from given displacement parameters of the body's nodes (local numbering): the
// corotational damping model's R at the state the force kernel evaluates.
BodyRotation body_rotation(const Model& model, const Body& body, const double* ux,
                           const double* uy);

// Physical position and velocity of node `node` (global): x_I = X_I + sum_J N_J(X_I) u_J for
// an interior node; a contour node of a deformable body uses its contact-consistent row R_J
// (meshfree/contour_rows.h) and its hat offset d (Model::contour_hat_offset) turned with the
// body: x_I = X_I + sum_J R_J u_J + (Q(theta) - I) d, exact for any rigid motion.
Vec2 node_position(const Model& model, int node);
Vec2 node_velocity(const Model& model, int node);
// The same for contour node `node` of `body`, whose rotation is given (computed once per body).
Vec2 contour_node_position(const Model& model, const Body& body, int node,
                           const BodyRotation& rotation);

// Spreads the force `f` applied at a deformable contour node's position to the MLS
// parameters with the transpose of dx_I/du_J (so that it does exactly the work f . dx_I):
// adds R_J f to the nodes of the row, and returns the moment f . dx_I/dtheta that the caller
// sums per body and passes to add_body_rotation_moment.
double add_contour_node_force(Model& model, const Body& body, int node, const Vec2& f,
                              const BodyRotation& rotation);
// Adds moment * dtheta/du_J to every node of `body` (dtheta/du_J from the mean gradients).
void add_body_rotation_moment(Model& model, const Body& body, double moment,
                              const BodyRotation& rotation);
// Deformation gradient and its rate at node `node` (global), from the node's own row.
Mat2 node_deformation_gradient(const Model& model, int node);

// Deformation gradient at Gauss point g (global index) of `body`.
Mat2 gauss_deformation_gradient(const Model& model, BodyId body, int g);
// Reference position of Gauss point g: sum_J N_J(x_g) X_J (exact by linear reproduction).
Vec2 gauss_reference_position(const Model& model, BodyId body, int g);

// Current positions of all contour points (Model::contour_body order): boundary-node
// positions of deformable bodies, rigidly moved points of rigid bodies. Parallel over bodies.
// `rotations` (when not null) receives body_rotation of every body (identity for rigid ones).
void compute_contour_positions(const Model& model, std::vector<Vec2>& positions,
                               std::vector<BodyRotation>* rotations = nullptr);

// Totals over all nodes (parameters carry the lumped masses).
double total_mass(const Model& model);
Vec2 linear_momentum(const Model& model);
// Angular momentum about the origin, from the physical positions and parameter velocities:
// sum_I m_I (x_I x v_I). With lumped masses this is the discrete quantity the scheme conserves
// when forces are central; see the momentum test.
double angular_momentum(const Model& model);
double kinetic_energy(const Model& model);

}  // namespace sg
