#include "model/internal_forces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/error.h"
#include "model/block_kernel.h"
#include "model/kinematics.h"

namespace sg {

namespace {

using namespace block_kernel;

// Per-thread scratch for a block's force terms (grows to the longest block, then stays).
double* term_scratch(int rows, int tensors) {
  thread_local AlignedVector<double> scratch;
  const auto size = static_cast<std::size_t>(2 * tensors * rows * W);
  if (scratch.size() < size) scratch.resize(size);
  return scratch.data();
}

struct BlockStress {
  Tensor2B total;    // w P
  Tensor2B viscous;  // w P_v (damped bodies)
};

// The stresses of one block's lanes at F = I + H with rate `rate` (damped), the energies
// added to `result` lane by lane.
BlockStress block_stress(const MaterialParams& material, const BlockRows& rows, const Tensor2B& f,
                         const Tensor2B* rate, const Mat2& rotation, BodyForceResult& result) {
  const DoubleBatch w = DoubleBatch::load_aligned(rows.weight);
  const ElasticBatch elastic = elastic_response(material, f);
  add_lanes(rows, w * elastic.energy_density, result.elastic_energy);
  Tensor2B p = elastic.first_piola;
  BlockStress out;
  if (rate) {
    const ViscousBatch viscous = viscous_response(material, f, *rate, rotation);
    p = {p.xx + viscous.first_piola.xx, p.xy + viscous.first_piola.xy,
         p.yx + viscous.first_piola.yx, p.yy + viscous.first_piola.yy};
    add_lanes(rows, w * viscous.power_density, result.damping_power);
    out.viscous = weighted(w, viscous.first_piola);
  }
  out.total = weighted(w, p);
  return out;
}

}  // namespace

BodyForceResult add_body_internal_forces(const Model& model, BodyId body_id, const double* ux,
                                         const double* uy, const double* vx, const double* vy,
                                         double* fx, double* fy, bool with_damping,
                                         double* viscous_fx, double* viscous_fy) {
  const Body& body = model.bodies[static_cast<std::size_t>(body_id)];
  const MaterialParams& material = model.materials[static_cast<std::size_t>(body.material)];
  const bool damped = with_damping && material.damping > 0.0;
  // The corotational damping model turns its strain rate with the body's mean rotation at u.
  const Mat2 rotation = damped && material.damping_model == DampingModel::corotational
                            ? body_rotation(model, body, ux, uy).matrix()
                            : Mat2::Identity();
  BodyForceResult result;
  const bool split_viscous = damped && viscous_fx != nullptr;
  if (viscous_fx) std::fill(viscous_fx, viscous_fx + body.node_count(), 0.0);
  if (viscous_fy) std::fill(viscous_fy, viscous_fy + body.node_count(), 0.0);
  for (int b = body.block_begin; b < body.block_end; ++b) {
    const BlockRows rows = block_rows(model.gauss_blocks, b);
    // Displacement gradient H = F - I and its rate, in one pass over the rows.
    Tensor2B h, rate;
    if (damped)
      gradient_sums(rows, ux, uy, vx, vy, h, rate);
    else
      h = gradient_sum(rows, ux, uy);
    const Tensor2B f = identity_plus(h);
    const DoubleBatch jacobian = f.xx * f.yy - f.yx * f.xy;
    if (const int bad = first_bad_lane(rows, jacobian); bad >= 0) {
      result.bad_gauss_point = rows.gauss[bad];
      result.bad_jacobian = jacobian.get(static_cast<std::size_t>(bad));
      return result;
    }
    const BlockStress stress =
        block_stress(material, rows, f, damped ? &rate : nullptr, rotation, result);
    // f_J -= w P grad0 N_J (and the viscous part apart, for the energy ledger).
    double* terms = term_scratch(rows.rows, 2);
    if (split_viscous) {
      force_terms<2>(rows, {&stress.total, &stress.viscous}, terms);
      scatter<true, 2>(rows, terms, {fx, fy, viscous_fx, viscous_fy});
    } else {
      force_terms<1>(rows, {&stress.total}, terms);
      scatter<true, 1>(rows, terms, {fx, fy});
    }
  }
  return result;
}

void body_deformation_gradients(const Model& model, BodyId body_id, const double* ux,
                                const double* uy, std::vector<Mat2>& gradients) {
  const Body& body = model.bodies[static_cast<std::size_t>(body_id)];
  gradients.resize(static_cast<std::size_t>(body.gauss_end - body.gauss_begin));
  for (int b = body.block_begin; b < body.block_end; ++b) {
    const BlockRows rows = block_rows(model.gauss_blocks, b);
    const Tensor2B f = identity_plus(gradient_sum(rows, ux, uy));
    for (int l = 0; l < W; ++l) {
      if (rows.gauss[l] < 0) continue;
      const auto i = static_cast<std::size_t>(l);
      Mat2& out = gradients[static_cast<std::size_t>(rows.gauss[l] - body.gauss_begin)];
      out << f.xx.get(i), f.xy.get(i), f.yx.get(i), f.yy.get(i);
    }
  }
}

namespace {

// The deformation gradients of a block's lanes from the stored per-point ones (identity in
// padding lanes).
Tensor2B load_gradients(const BlockRows& rows, const std::vector<Mat2>& gradients,
                        int gauss_begin) {
  alignas(kSimdAlignment) std::array<std::array<double, W>, 4> c;
  for (int l = 0; l < W; ++l) {
    const auto i = static_cast<std::size_t>(l);
    const Mat2 f = rows.gauss[l] >= 0
                       ? gradients[static_cast<std::size_t>(rows.gauss[l] - gauss_begin)]
                       : Mat2::Identity();
    c[0][i] = f(0, 0);
    c[1][i] = f(0, 1);
    c[2][i] = f(1, 0);
    c[3][i] = f(1, 1);
  }
  return {DoubleBatch::load_aligned(c[0].data()), DoubleBatch::load_aligned(c[1].data()),
          DoubleBatch::load_aligned(c[2].data()), DoubleBatch::load_aligned(c[3].data())};
}

}  // namespace

void apply_viscous_operator(const Model& model, BodyId body_id, const std::vector<Mat2>& gradients,
                            const Mat2& rotation, const double* x, const double* y, double* out_x,
                            double* out_y) {
  const Body& body = model.bodies[static_cast<std::size_t>(body_id)];
  const MaterialParams& material = model.materials[static_cast<std::size_t>(body.material)];
  std::fill(out_x, out_x + body.node_count(), 0.0);
  std::fill(out_y, out_y + body.node_count(), 0.0);
  for (int b = body.block_begin; b < body.block_end; ++b) {
    const BlockRows rows = block_rows(model.gauss_blocks, b);
    const Tensor2B f_rate = gradient_sum(rows, x, y);
    const Tensor2B f = load_gradients(rows, gradients, body.gauss_begin);
    const Tensor2B p = weighted(DoubleBatch::load_aligned(rows.weight),
                                viscous_response(material, f, f_rate, rotation).first_piola);
    double* terms = term_scratch(rows.rows, 1);
    force_terms<1>(rows, {&p}, terms);
    scatter<false, 1>(rows, terms, {out_x, out_y});
  }
}

InternalForceResult add_internal_forces(Model& model) {
  const int body_count = static_cast<int>(model.bodies.size());
  std::vector<BodyForceResult> per_body(model.bodies.size());
  NodeState& n = model.nodes;
#pragma omp parallel for schedule(dynamic, 8)
  for (int b = 0; b < body_count; ++b) {
    const Body& body = model.bodies[static_cast<std::size_t>(b)];
    if (body.kind != BodyKind::deformable) continue;
    const auto o = static_cast<std::size_t>(body.node_begin);
    per_body[static_cast<std::size_t>(b)] = add_body_internal_forces(
        model, b, n.ux.data() + o, n.uy.data() + o, n.vx.data() + o, n.vy.data() + o,
        n.fx.data() + o, n.fy.data() + o, true, n.viscous_fx.data() + o, n.viscous_fy.data() + o);
  }
  InternalForceResult total;
  for (int b = 0; b < body_count; ++b) {
    const BodyForceResult& r = per_body[static_cast<std::size_t>(b)];
    if (r.bad_gauss_point >= 0) {
      const Body& body = model.bodies[static_cast<std::size_t>(b)];
      SG_THROW("body '" << body.name << "': invalid deformation at Gauss point "
                        << r.bad_gauss_point - body.gauss_begin << " (det F = " << r.bad_jacobian
                        << "): the body is inverted or the step exploded");
    }
    total.elastic_energy += r.elastic_energy;
    total.damping_power += r.damping_power;
  }
  return total;
}

}  // namespace sg
