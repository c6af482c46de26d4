#pragma once
// The contact-level strain rate: how fast the velocity jump between two grains is
// accommodated at a contact (sliding, opening), on the scale of the strain rate inside the
// grains (io/vtk_writer.h strain_rate), so that one picture shows deformation inside grains
// and between them (papers 001 §3.2 and 003 §3.1 read their strain-rate pictures so:
// "accommodated by interparticle motions", "fractures on their inclined contours").
//
// At an active contact (contact/contact_system.h ContactRecord) the relative velocity of the
// slave contour point against the master segment's point it projects on,
//   dv = v_slave - ((1 - t) v_a + t v_b),
// v_a, v_b the velocities of the segment's end points and t the projection parameter (the
// contact's own interpolation; exact for a rigid master), is split along the master's
// outward normal n: dv_n = dv . n (opening, closing) and dv_t = dv . perp(n) (slip). The rate
// is the norm of the strain rate of a band of thickness l carrying that jump as a continuum,
//   D = sym(dv (x) n) / l,   |D| = sqrt(dv_n^2 + dv_t^2 / 2) / l,
// with l the slave point's tributary length (ContactRecord::length: the length of contour the
// contact stands for, about the node spacing), divided by V/D like strain_rate (NaN or <= 0:
// in 1/time). Under small strain the nodal |E'| across such a band would be |D|, which is why
// this norm and not |dv| / l (sqrt(2) larger for a pure slip): the two rates compare on one
// colour scale. It is instantaneous, the velocities of the contact network's instant; the
// nodal strain_rate is an increment over the output interval.
#include <span>
#include <vector>

#include "contact/contact_system.h"
#include "model/model.h"

namespace sg {

// Physical velocities of every contour point (Model::contour_body order): a deformable body's
// boundary nodes (model/kinematics.h node_velocity), a rigid body's points moving with it.
void compute_contour_velocities(const Model& model, std::vector<Vec2>& velocities);

struct ContactRate {
  Vec2 relative_velocity = Vec2::Zero();  // dv (length/time)
  double rate = 0.0;                      // |D| over the global strain rate
};

// The rate of contact `r` from the contour velocities of its instant. The model gives the
// master's contour range only (its state may have moved on since).
ContactRate contact_rate(const Model& model, const ContactRecord& r,
                         std::span<const Vec2> contour_velocity, double global_strain_rate);

}  // namespace sg
