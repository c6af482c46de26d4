#pragma once
// The Model owns everything the solver advances: bodies (cold descriptions), node state
// (hot structure-of-arrays), and the precomputed discretization (streamed rows).
//
//   Body        cold: name, kind, material, index ranges. Never touched per node.
//   NodeState   hot: one entry per field node, all bodies concatenated, each body a
//               contiguous range [node_begin, node_end) whose first nodes are its contour.
//   gauss_rows  streamed: per Gauss point, the MLS row (local node index, N, dN/dX, dN/dY);
//               body b owns Gauss points [gauss_begin, gauss_end).
//
// Node indices inside rows are local to their body, so a body's kernel works on pointers
// to its own slice of the node arrays (and the same kernel runs on scratch copies, e.g. in
// the stable-step estimate). Bodies refer to materials by index (ids, not pointers).
//
// On purpose, NodeState and RigidState hold fixed data (masses, inertias, drives) beside the
// evolving state, where docs/architecture.md §Conventions 3 keeps parameters and state apart: the
// velocity update streams m, v and f of a node together. Which arrays are state is listed once,
// in solver/state_snapshot.h (what a checkpoint saves); the fixed ones enter the checkpoint's
// fingerprint (io/checkpoint.h). Model's add_* functions are members because they keep the
// global arrays (node ranges, rows, contour arrays) consistent with each other.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/polygon.h"
#include "material/material.h"
#include "meshfree/body_discretization.h"
#include "meshfree/periodic_strip.h"
#include "meshfree/shape_rows.h"

namespace sg {

using BodyId = int;
using MaterialId = int;

enum class BodyKind : std::uint8_t { deformable, rigid };

struct Body {
  std::string name;
  BodyKind kind = BodyKind::deformable;
  MaterialId material = 0;
  int node_begin = 0, node_end = 0;  // global node range (deformable; empty for rigid)
  int boundary_end = 0;              // [node_begin, boundary_end): contour nodes, CCW
  int gauss_begin = 0, gauss_end = 0;
  int triangle_begin = 0, triangle_end = 0;
  // F-bar patches of its Gauss points (Model::gauss_patch, model/gauss_patches.h).
  int patch_count = 0;
  // Contour points of every body, concatenated (Model::contour_*): for a deformable body,
  // contour point k is boundary node node_begin + (k - contour_begin); for a rigid body the
  // points follow the rigid motion.
  int contour_begin = 0, contour_end = 0;
  // Open contour: a strip spanning the periodic cell in x (first body), whose last point
  // connects to its first point shifted by one period. Closed otherwise.
  bool open_contour = false;
  double closing_shift_x = 0.0;  // open contours: the last point joins the first + (this, 0)
  int rigid_index = -1;          // index into Model::rigid (rigid bodies)
  // Deformable strips: index into Model::node_drives of the drive of its back face (-1: none).
  int node_drive = -1;
  double reference_area = 0.0;
  // Mass scaling (solver/mass_scaling.h): the body's inertia (nodal masses, or rigid mass and
  // moment of inertia) is this factor times the physical one; gravity still acts on the
  // physical mass. 1: not scaled.
  double mass_scale = 1.0;

  int node_count() const { return node_end - node_begin; }
  int boundary_count() const { return boundary_end - node_begin; }
  int contour_count() const { return contour_end - contour_begin; }
};

// How one degree of freedom (x, y or theta) of a rigid body is driven.
enum class DriveMode : std::uint8_t {
  free,      // integrated from the forces it receives
  velocity,  // velocity imposed (piecewise-linear history); the reaction force is measured
  force,     // a constant imposed force (or torque) added to the contact forces
  // Servo-controlled load: an imposed force history F(t) plus a linear viscous force
  // -c v on the same degree of freedom, so that the body settles where the force it
  // receives balances F instead of bouncing on the granular layer (a confining pressure:
  // F = -p L on the top first body's y). The viscous force is treated implicitly (no time
  // step limit) and its work is booked as servo dissipation in the energy ledger. There is
  // no target velocity: the servo holds the body at rest on average, and over a window in
  // which the body does not drift the mean force received equals the mean of F.
  load,
};

// A piecewise-linear function of time, constant beyond its ends (imposed velocities).
struct PiecewiseLinear {
  std::vector<double> times;  // non-decreasing; two equal times are a jump (value after: the 2nd)
  std::vector<double> values;
  double operator()(double t) const;
  static PiecewiseLinear constant(double value) { return {{0.0}, {value}}; }
};

struct RigidDrive {
  DriveMode mode[3] = {DriveMode::free, DriveMode::free, DriveMode::free};  // x, y, theta
  PiecewiseLinear velocity[3];         // used when mode == velocity (length/time, rad/time)
  double force[3] = {0, 0, 0};         // used when mode == force (force, force, torque)
  PiecewiseLinear load[3];             // used when mode == load: F(t) (force, force, torque)
  double load_damping[3] = {0, 0, 0};  // mode == load: c (force/velocity; torque.time/rad)
};

// Imposed motion of field nodes of one deformable body: the back face of a deformable strip
// (first body), driven as RigidDrive drives a rigid first body. Each component is
//  - free: every node integrated from the forces it receives;
//  - velocity (piecewise linear in time): the velocity *parameters* of the nodes are imposed
//    (MLS does not interpolate: the physical velocity at the back face follows through the
//    rows);
//  - load (servo, as DriveMode::load on a rigid degree of freedom): the nodes move as one in
//    this component, a "carrier" of mass M = sum of their masses m_I (as scaled by mass
//    scaling) and momentum P = sum m_I v_I, under the sum of the forces f_I they receive plus
//    the imposed force F(t) and the viscous servo force -c v (implicit):
//      (M + dt c) v_n+1/2 = P_n-1/2 + dt (sum_I f_I + F(t_n)),
//    every node then getting v_n+1/2. The carrier is not extra state: its velocity is the
//    nodes' common velocity (checkpointed with them). A pressure p on the back face of the
//    upper strip is F = -p L on y.
// The solver measures the reaction the drive applies and books its work
// (solver/stepper.h). Mode force is not supported on nodes.
struct NodeDrive {
  BodyId body = -1;
  std::vector<int> nodes;  // global node indices, all in `body`, increasing
  DriveMode mode[2] = {DriveMode::free, DriveMode::free};  // x, y: free, velocity or load
  PiecewiseLinear velocity[2];                             // mode == velocity (length/time)
  PiecewiseLinear load[2];          // mode == load: F(t) on the carrier (force)
  double load_damping[2] = {0, 0};  // mode == load: c (force/velocity)
  // Recomputed at every step (like RigidState::fx): the total force the drive applied to its
  // nodes at the last force evaluation, R = sum_I (m_I (v_n+1/2 - v_n-1/2) / dt - f_I); under
  // load, R = F(t_n) - c v_n+1/2 up to round-off (the carrier's equation).
  Vec2 reaction = Vec2::Zero();
  bool drives_any() const { return mode[0] != DriveMode::free || mode[1] != DriveMode::free; }
};

// Rigid bodies: a few scalars each (structure of arrays, one entry per rigid body).
struct RigidState {
  std::vector<double> x, y, theta;     // centre of mass and orientation (checkpointed)
  std::vector<double> vx, vy, omega;   // velocities (checkpointed)
  std::vector<double> fx, fy, torque;  // forces received this step (contacts, gravity)
  std::vector<double> mass, inertia;   // from contour and density (times mass_scale)
  std::vector<double> mass_scale;      // Body::mass_scale of each rigid body (1: not scaled)
  std::vector<RigidDrive> drive;
  std::size_t size() const { return x.size(); }
};

// Hot per-node arrays (structure of arrays). u and v are the MLS *parameters*: the physical
// displacement at X is sum_J N_J(X) u_J, not u_I at X_I.
struct NodeState {
  std::vector<double> ref_x, ref_y;  // reference position X
  std::vector<double> ux, uy;        // displacement parameters (checkpointed)
  std::vector<double> vx, vy;        // velocity parameters (checkpointed)
  std::vector<double> fx, fy;        // total force on each parameter (recomputed each step)
  std::vector<double> viscous_fx, viscous_fy;  // its bulk-damping part (energy bookkeeping)
  std::vector<double> mass;                    // lumped mass rho * integral of N_I
  std::vector<double> inverse_mass;
  // Index into Model::node_drives of the drive that owns the node, or -1 (read in the update
  // loop only for bodies with Body::node_drive >= 0).
  std::vector<int> drive;

  std::size_t size() const { return ref_x.size(); }
  void resize(std::size_t n);
};

struct Model {
  std::vector<Body> bodies;
  std::vector<MaterialDef> material_defs;
  std::vector<MaterialParams> materials;
  NodeState nodes;
  ShapeRows gauss_rows;              // local node numbering per body
  std::vector<double> gauss_weight;  // reference area of each Gauss point
  // Each Gauss point's F-bar patch, numbered from 0 in its body (model/gauss_patches.h); read
  // for materials with VolumetricFormulation::fbar only.
  std::vector<int> gauss_patch;
  ShapeRows node_rows;                        // row of each node at its own reference position
  std::vector<std::array<int, 3>> triangles;  // global node numbering
  // Contour points of all bodies (see Body::contour_begin). For rigid bodies: the offset of
  // each point from the centre of mass in the body frame (zero for deformable bodies).
  std::vector<Vec2> rigid_contour_offset;
  std::vector<BodyId> contour_body;  // owner of each contour point
  // Deformable bodies' contour points: d = X - Xbar, the offset of the point from the centroid
  // of its hat, which the position rotates with the body (meshfree/contour_rows.h,
  // model/kinematics.h BodyRotation); zero for rigid bodies.
  std::vector<Vec2> contour_hat_offset;
  // Per node of a deformable body: c_J = (1 / A) integral of grad N_J over the body, so that
  // the body's mean deformation gradient is I + sum_J u_J (x) c_J (kinematics.h).
  std::vector<double> mean_gradient_x, mean_gradient_y;
  RigidState rigid;
  std::vector<NodeDrive> node_drives;
  // (The time integrator is no part of the model: solver/integrator_params.h.)
  Vec2 gravity = Vec2::Zero();  // acceleration (length / time^2)
  // Periodic boundary in x over [x_min, x_max) when periodic_x is set.
  bool periodic_x = false;
  double x_min = 0.0, x_max = 0.0;

  MaterialId add_material(const MaterialDef& def);
  // Discretizes `contour` (CCW, simple; sampled at about the node spacing) and appends the
  // body. Errors name the body.
  BodyId add_deformable_body(const std::string& name, const Polygon& contour, MaterialId material,
                             const DiscretizationParams& params);
  // Appends an already discretized body (tests, imported meshes).
  BodyId add_deformable_body(const std::string& name, const BodyDiscretization& d,
                             MaterialId material);

  // A rigid body with the given contour (CCW, simple; closed, or open for a periodic strip
  // whose ends meet across the seam: then the area, centroid and inertia are those of the
  // region between the contour and its closing). Mass and inertia from density.
  BodyId add_rigid_body(const std::string& name, const Polygon& contour, MaterialId material);
  // A rigid periodic strip (first body): `surface` is its contact surface only, with the
  // body's material on the left of the direction of travel; the last point joins the first
  // shifted by (closing_shift_x, 0) = (+-period, 0). Mass and inertia are given (strips are
  // normally driven), its reference point is the mean of the surface points.
  BodyId add_rigid_strip(const std::string& name, const Polygon& surface, MaterialId material,
                         double closing_shift_x, double mass, double inertia);

  // A deformable periodic strip (first body): discretized by discretize_periodic_strip
  // (meshfree/periodic_strip.h) between the rough `surface` and a flat back face at y =
  // back_y. Its contour is the surface only, open, closed across the seam by closing_shift_x,
  // as for add_rigid_strip; the back-face nodes get a NodeDrive (free until its modes are set).
  BodyId add_deformable_strip(const std::string& name, const Polygon& surface,
                              double closing_shift_x, double back_y, MaterialId material,
                              const DiscretizationParams& params);
  BodyId add_deformable_strip(const std::string& name, const PeriodicStripDiscretization& strip,
                              MaterialId material);

  std::size_t node_count() const { return nodes.size(); }

  // Handles by id (ids index `bodies` and `materials`; no bounds check beyond the vector's).
  const Body& body(BodyId id) const { return bodies[static_cast<std::size_t>(id)]; }
  Body& body(BodyId id) { return bodies[static_cast<std::size_t>(id)]; }
  const MaterialParams& material(MaterialId id) const {
    return materials[static_cast<std::size_t>(id)];
  }
  const MaterialParams& material_of(BodyId id) const { return material(body(id).material); }
  // The material as the scenario defined it (its name, its constants as written).
  const MaterialDef& material_def(MaterialId id) const {
    return material_defs[static_cast<std::size_t>(id)];
  }
  // The one definition of a damped body: a deformable body whose material has bulk
  // (Kelvin-Voigt) damping, alpha > 0, whatever its damping model (material.h DampingModel).
  // Rigid bodies carry no viscous force. Whether the integrator treats that viscosity
  // implicitly is the integrator's choice (solver/implicit_viscosity.h).
  bool is_damped(BodyId id) const;

 private:
  void check_new_body(const std::string& name, MaterialId material) const;
  BodyId append_rigid(Body body, const std::string& name, const Polygon& points,
                      MaterialId material, const Vec2& reference, double mass, double inertia);

 public:
  std::size_t contour_point_count() const { return contour_body.size(); }
  std::size_t gauss_point_count() const { return gauss_weight.size(); }
};

}  // namespace sg
