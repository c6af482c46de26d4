#include "model/internal_forces.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.h"
#include "model/kinematics.h"

namespace sg {

BodyForceResult add_body_internal_forces(const Model& model, BodyId body_id, const double* ux,
                                         const double* uy, const double* vx, const double* vy,
                                         double* fx, double* fy, bool with_damping,
                                         double* viscous_fx, double* viscous_fy,
                                         const ForceKernel* kernel, Mat2* gradients) {
  const Body& body = model.body(body_id);
  const MaterialParams& material = model.material_of(body_id);
  const bool damped = with_damping && model.is_damped(body_id);
  // The corotational damping model turns its strain rate with the body's mean rotation at u.
  const Mat2 rotation = damped && material.damping_model == DampingModel::corotational
                            ? body_rotation(model, body, ux, uy).matrix()
                            : Mat2::Identity();
  if (viscous_fx) std::fill(viscous_fx, viscous_fx + body.node_count(), 0.0);
  if (viscous_fy) std::fill(viscous_fy, viscous_fy + body.node_count(), 0.0);
  const bool split_viscous = damped && viscous_fx != nullptr && viscous_fy != nullptr;
  const BodyArrays arrays{ux,
                          uy,
                          vx,
                          vy,
                          fx,
                          fy,
                          split_viscous ? viscous_fx : nullptr,
                          split_viscous ? viscous_fy : nullptr,
                          gradients};
  return (kernel ? *kernel : force_kernel()).body_forces(model, body, arrays, damped, rotation);
}

void body_deformation_gradients(const Model& model, BodyId body_id, const double* ux,
                                const double* uy, std::vector<Mat2>& gradients) {
  const Body& body = model.body(body_id);
  gradients.resize(static_cast<std::size_t>(body.gauss_end - body.gauss_begin));
  force_kernel().deformation_gradients(model, body, ux, uy, gradients.data());
}

void apply_viscous_operator(const Model& model, BodyId body_id, const std::vector<Mat2>& gradients,
                            const Mat2& rotation, const double* x, const double* y, double* out_x,
                            double* out_y) {
  const Body& body = model.body(body_id);
  force_kernel().viscous_operator(model, body, gradients.data(), rotation, x, y, out_x, out_y);
}

BodyForceResult add_body_internal_forces(Model& model, BodyId body_id, Mat2* gradients) {
  const Body& body = model.body(body_id);
  if (body.kind != BodyKind::deformable) return {};
  NodeState& n = model.nodes;
  const auto o = static_cast<std::size_t>(body.node_begin);
  return add_body_internal_forces(model, body_id, n.ux.data() + o, n.uy.data() + o, n.vx.data() + o,
                                  n.vy.data() + o, n.fx.data() + o, n.fy.data() + o, true,
                                  n.viscous_fx.data() + o, n.viscous_fy.data() + o, nullptr,
                                  gradients);
}

InternalForceResult sum_internal_forces(const Model& model,
                                        const std::vector<BodyForceResult>& per_body) {
  InternalForceResult total;
  for (std::size_t b = 0; b < per_body.size(); ++b) {
    const BodyForceResult& r = per_body[b];
    if (r.bad_gauss_point >= 0) {
      const Body& body = model.bodies[b];
      SG_THROW("body '" << body.name << "': invalid deformation at Gauss point "
                        << r.bad_gauss_point - body.gauss_begin << " (det F = " << r.bad_jacobian
                        << "): the body is inverted or the step exploded");
    }
    total.elastic_energy += r.elastic_energy;
    total.damping_power += r.damping_power;
  }
  return total;
}

InternalForceResult add_internal_forces(Model& model, const std::vector<Mat2*>* gradients) {
  const int body_count = static_cast<int>(model.bodies.size());
  std::vector<BodyForceResult> per_body(model.bodies.size());
  force_kernel();  // chosen here, outside the threads: a bad SOFTGRAIN_SIMD throws to the caller
#pragma omp parallel for schedule(dynamic, 8)
  for (int b = 0; b < body_count; ++b)
    per_body[static_cast<std::size_t>(b)] = add_body_internal_forces(
        model, b, gradients ? (*gradients)[static_cast<std::size_t>(b)] : nullptr);
  return sum_internal_forces(model, per_body);
}

}  // namespace sg
