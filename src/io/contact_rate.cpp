#include "io/contact_rate.h"

#include <cmath>

#include "core/error.h"
#include "model/kinematics.h"

namespace sg {

void compute_contour_velocities(const Model& model, std::vector<Vec2>& velocities) {
  velocities.resize(model.contour_point_count());
  for (const Body& body : model.bodies) {
    if (body.kind == BodyKind::rigid) {
      const auto r = static_cast<std::size_t>(body.rigid_index);
      const Vec2 v(model.rigid.vx[r], model.rigid.vy[r]);
      const Mat2 q = rotation(model.rigid.theta[r]);
      for (int k = body.contour_begin; k < body.contour_end; ++k) {
        const auto p = static_cast<std::size_t>(k);
        velocities[p] = v + model.rigid.omega[r] * perp(q * model.rigid_contour_offset[p]);
      }
    } else {
      for (int k = body.contour_begin; k < body.contour_end; ++k)
        velocities[static_cast<std::size_t>(k)] =
            node_velocity(model, body.node_begin + (k - body.contour_begin));
    }
  }
}

ContactRate contact_rate(const Model& model, const ContactRecord& r,
                         std::span<const Vec2> contour_velocity, double global_strain_rate) {
  SG_VERIFY(contour_velocity.size() == model.contour_point_count(),
            "contact rate: " << contour_velocity.size() << " contour velocities for "
                             << model.contour_point_count() << " contour points");
  const Body& master = model.body(r.master_body);
  // The segment's end point, as the contact stage numbers it (contact_system.cpp).
  const int a = r.master_segment;
  const int b = master.contour_begin + (a - master.contour_begin + 1) % master.contour_count();
  const Vec2 v_master = (1.0 - r.t) * contour_velocity[static_cast<std::size_t>(a)] +
                        r.t * contour_velocity[static_cast<std::size_t>(b)];
  ContactRate out;
  out.relative_velocity = contour_velocity[static_cast<std::size_t>(r.slave_point)] - v_master;
  const double opening = out.relative_velocity.dot(r.normal);
  const double slip = out.relative_velocity.dot(perp(r.normal));
  const double unit = global_strain_rate > 0.0 ? global_strain_rate : 1.0;
  out.rate =
      r.length > 0.0 ? std::sqrt(opening * opening + 0.5 * slip * slip) / r.length / unit : 0.0;
  return out;
}

}  // namespace sg
