#include "solver/stable_time_step.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "core/parallel.h"
#include "model/internal_forces.h"
#include "model/kinematics.h"
#include "solver/implicit_viscosity.h"

namespace sg {

double critical_time_step(double omega, double alpha) {
  const double xi = 0.5 * alpha * omega;
  return 2.0 / omega * (std::sqrt(1.0 + xi * xi) - xi);
}

namespace {

// sqrt(lambda_max(M^-1/2 K M^-1/2)) of one body by power iteration, `apply_k(x, y, kx, ky)`
// setting (kx, ky) = K M^-1/2 (x, y) on the body's parameters.
template <class ApplyK>
double power_iteration_frequency(const Model& model, const Body& body, int iterations,
                                 ApplyK&& apply_k) {
  const auto n = static_cast<std::size_t>(body.node_count());
  const auto o = static_cast<std::size_t>(body.node_begin);
  const NodeState& s = model.nodes;
  std::vector<double> px(n), py(n), kx(n), ky(n);
  // Start vector: a deterministic alternating pattern, rich in high frequencies.
  for (std::size_t i = 0; i < n; ++i) {
    px[i] = static_cast<double>((i * 7919) % 13) / 13.0 - 0.5;
    py[i] = static_cast<double>((i * 104729) % 17) / 17.0 - 0.5;
  }
  // Iterate on y = M^-1/2 K M^-1/2 x (symmetric), so the Rayleigh quotient is an eigenvalue bound.
  double lambda = 0.0;
  for (int it = 0; it < iterations; ++it) {
    double norm = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      norm += px[i] * px[i] + py[i] * py[i];
    norm = std::sqrt(norm);
    if (norm == 0.0) break;
    for (std::size_t i = 0; i < n; ++i) {
      px[i] /= norm;
      py[i] /= norm;
    }
    apply_k(px, py, kx, ky);
    double rayleigh = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double r = std::sqrt(s.inverse_mass[o + i]);
      const double x = kx[i] * r, y = ky[i] * r;
      rayleigh += x * px[i] + y * py[i];
      px[i] = x;
      py[i] = y;
    }
    lambda = rayleigh;
  }
  SG_VERIFY(lambda > 0.0 && std::isfinite(lambda),
            "body '" << body.name << "': cannot estimate its highest frequency (got " << lambda
                     << "): expected a positive, finite value; the body is inverted, or its "
                        "stiffness over its mass (young over density) is beyond what the "
                        "arithmetic holds");
  return std::sqrt(lambda);
}

}  // namespace

double estimate_max_frequency(const Model& model, BodyId body_id, int iterations) {
  const Body& body = model.body(body_id);
  const auto n = static_cast<std::size_t>(body.node_count());
  const auto o = static_cast<std::size_t>(body.node_begin);
  const NodeState& s = model.nodes;
  std::vector<double> ux(s.ux.begin() + static_cast<long>(o),
                         s.ux.begin() + static_cast<long>(o + n));
  std::vector<double> uy(s.uy.begin() + static_cast<long>(o),
                         s.uy.begin() + static_cast<long>(o + n));
  const std::vector<double> zero(n, 0.0);
  std::vector<double> f0x(n, 0.0), f0y(n, 0.0), fx(n), fy(n), ux_p(n), uy_p(n);
  add_body_internal_forces(model, body_id, ux.data(), uy.data(), zero.data(), zero.data(),
                           f0x.data(), f0y.data(), false);
  // The displacement probe is eps * M^-1/2 x with |x| = 1: scaled so that its largest nodal
  // component is 1e-7 of the body size (linear regime) whatever the units of the masses (in SI
  // a node weighs ~1e-16 kg and M^-1/2 alone would move it by light years).
  double max_inverse_root_mass = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    max_inverse_root_mass = std::max(max_inverse_root_mass, std::sqrt(s.inverse_mass[o + i]));
  const double eps = 1e-7 * std::sqrt(body.reference_area) / max_inverse_root_mass;
  return power_iteration_frequency(model, body, iterations,
                                   [&](const std::vector<double>& x, const std::vector<double>& y,
                                       std::vector<double>& kx, std::vector<double>& ky) {
                                     for (std::size_t i = 0; i < n; ++i) {
                                       const double r = std::sqrt(s.inverse_mass[o + i]);
                                       ux_p[i] = ux[i] + eps * r * x[i];
                                       uy_p[i] = uy[i] + eps * r * y[i];
                                       fx[i] = 0.0;
                                       fy[i] = 0.0;
                                     }
                                     add_body_internal_forces(model, body_id, ux_p.data(),
                                                              uy_p.data(), zero.data(), zero.data(),
                                                              fx.data(), fy.data(), false);
                                     // K x = -(f(u + eps x) - f(u)) / eps
                                     for (std::size_t i = 0; i < n; ++i) {
                                       kx[i] = -(fx[i] - f0x[i]) / eps;
                                       ky[i] = -(fy[i] - f0y[i]) / eps;
                                     }
                                   });
}

double estimate_viscous_frequency(const Model& model, BodyId body_id, int iterations) {
  const Body& body = model.body(body_id);
  const MaterialParams& material = model.material_of(body_id);
  SG_VERIFY(model.is_damped(body_id), "body '" << body.name << "' has no bulk damping");
  const auto o = static_cast<std::size_t>(body.node_begin);
  const double* ux = model.nodes.ux.data() + o;
  const double* uy = model.nodes.uy.data() + o;
  std::vector<Mat2> gradients;
  body_deformation_gradients(model, body_id, ux, uy, gradients);
  const Mat2 rotation = material.damping_model == DampingModel::corotational
                            ? body_rotation(model, body, ux, uy).matrix()
                            : Mat2::Identity();
  return power_iteration_frequency(model, body, iterations,
                                   [&](const std::vector<double>& x, const std::vector<double>& y,
                                       std::vector<double>& kx, std::vector<double>& ky) {
                                     std::vector<double> rx(x.size()), ry(y.size());
                                     for (std::size_t i = 0; i < x.size(); ++i) {
                                       const double r = std::sqrt(model.nodes.inverse_mass[o + i]);
                                       rx[i] = r * x[i];
                                       ry[i] = r * y[i];
                                     }
                                     apply_viscous_operator(model, body_id, gradients, rotation,
                                                            rx.data(), ry.data(), kx.data(),
                                                            ky.data());
                                     for (std::size_t i = 0; i < kx.size(); ++i) {
                                       kx[i] /= material.damping;
                                       ky[i] /= material.damping;
                                     }
                                   });
}

double wave_speed_frequency_bound(const Model& model, BodyId body_id) {
  const Body& body = model.body(body_id);
  double h_min = std::numeric_limits<double>::infinity();
  // Nearest-neighbour distance from the triangulation edges (each node's edges).
  for (int t = body.triangle_begin; t < body.triangle_end; ++t) {
    const auto& tri = model.triangles[static_cast<std::size_t>(t)];
    for (int e = 0; e < 3; ++e) {
      const auto a = static_cast<std::size_t>(tri[static_cast<std::size_t>(e)]);
      const auto b = static_cast<std::size_t>(tri[static_cast<std::size_t>((e + 1) % 3)]);
      h_min = std::min(h_min, std::hypot(model.nodes.ref_x[a] - model.nodes.ref_x[b],
                                         model.nodes.ref_y[a] - model.nodes.ref_y[b]));
    }
  }
  return 2.0 * p_wave_speed(model.material(body.material)) / h_min;
}

namespace {

// Highest contact frequency of a body's contour nodes (see the header).
double contact_frequency(const Model& model, const Body& body, double k) {
  if (k <= 0.0) return 0.0;
  const NodeState& n = model.nodes;
  if (body.kind == BodyKind::rigid) {
    const auto r = static_cast<std::size_t>(body.rigid_index);
    double length = 0.0;
    const int count = body.contour_count();
    for (int i = 0; i + 1 < count || (!body.open_contour && i < count); ++i) {
      const Vec2 a = model.rigid_contour_offset[static_cast<std::size_t>(body.contour_begin + i)];
      const Vec2 b =
          model
              .rigid_contour_offset[static_cast<std::size_t>(body.contour_begin + (i + 1) % count)];
      length += (b - a).norm();
    }
    const double radius2 = model.rigid.inertia[r] / model.rigid.mass[r];
    double max_arm2 = 0.0;
    for (int i = 0; i < count; ++i)
      max_arm2 = std::max(
          max_arm2, model.rigid_contour_offset[static_cast<std::size_t>(body.contour_begin + i)]
                        .squaredNorm());
    // translation and rotation: k_eff / m and k_eff r_max^2 / I
    return std::sqrt(2.0 * k * length / model.rigid.mass[r] * std::max(1.0, max_arm2 / radius2));
  }
  // Deformable body. Contour node I (tributary length l_I) sits at x_I = sum_J N_J(X_I) u_J
  // (its MLS row r_I, model.node_rows), so a penalty spring on it is the rank-one stiffness
  // 2 k l_I r_I r_I^T on the parameters (both passes), in x and in y alike (k bounds both
  // k_n and k_t). With the whole contour loaded against an immovable partner,
  //   K_c = sum_I 2 k l_I r_I r_I^T,
  // and this body's own contact frequency is sqrt(lambda_max(M^-1/2 K_c M^-1/2)), found by
  // power iteration on the boundary rows. No floor at the per-node value 2 k l_I / m_I (the
  // row taken as a Kronecker delta): the contour rows are hat averages over the node's two
  // segments (meshfree/contour_rows.h), which spread a contact force over more parameters
  // than a point row and really lower the frequency; with the floor the bonded-blocks
  // estimate was 713 against an assembled 569 (steps 20% smaller than needed), without it
  // 625 (test_contact_stable_step.cpp).
  const int count = body.boundary_count();
  const auto o = static_cast<std::size_t>(body.node_begin);
  const auto n_nodes = static_cast<std::size_t>(body.node_count());
  std::vector<double> weight(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    const auto a = static_cast<std::size_t>(body.node_begin + i);
    const auto prev = static_cast<std::size_t>(body.node_begin + (i + count - 1) % count);
    const auto next = static_cast<std::size_t>(body.node_begin + (i + 1) % count);
    // An open contour (a deformable strip) closes across the periodic seam: the last node's
    // next point is the first shifted by closing_shift_x (not the far end of the cell).
    const double shift_next = body.open_contour && i == count - 1 ? body.closing_shift_x : 0.0;
    const double shift_prev = body.open_contour && i == 0 ? -body.closing_shift_x : 0.0;
    const double l =
        0.5 * (std::hypot(n.ref_x[next] + shift_next - n.ref_x[a], n.ref_y[next] - n.ref_y[a]) +
               std::hypot(n.ref_x[prev] + shift_prev - n.ref_x[a], n.ref_y[prev] - n.ref_y[a]));
    weight[static_cast<std::size_t>(i)] = 2.0 * k * l;
  }
  const ShapeRows& rows = model.node_rows;
  std::vector<double> p(n_nodes), y(n_nodes), inverse_root_mass(n_nodes);
  for (std::size_t j = 0; j < n_nodes; ++j) {
    p[j] = static_cast<double>((j * 7919) % 13) / 13.0 - 0.5;
    inverse_root_mass[j] = std::sqrt(n.inverse_mass[o + j]);
  }
  double lambda = 0.0;
  for (int it = 0; it < 100; ++it) {
    double norm = 0.0;
    for (double v : p)
      norm += v * v;
    norm = std::sqrt(norm);
    if (norm == 0.0) break;
    std::fill(y.begin(), y.end(), 0.0);
    for (int i = 0; i < count; ++i) {
      const auto row = static_cast<std::size_t>(body.node_begin + i);
      const auto begin = static_cast<std::size_t>(rows.offset[row]);
      const auto end = static_cast<std::size_t>(rows.offset[row + 1]);
      double r_dot = 0.0;  // r_I . M^-1/2 p
      for (std::size_t e = begin; e < end; ++e) {
        const auto j = static_cast<std::size_t>(rows.node[e]);
        r_dot += rows.value[e] * inverse_root_mass[j] * p[j];
      }
      const double scaled = weight[static_cast<std::size_t>(i)] * r_dot / norm;
      for (std::size_t e = begin; e < end; ++e) {
        const auto j = static_cast<std::size_t>(rows.node[e]);
        y[j] += rows.value[e] * inverse_root_mass[j] * scaled;
      }
    }
    double rayleigh = 0.0;
    for (std::size_t j = 0; j < n_nodes; ++j)
      rayleigh += y[j] * p[j] / norm;
    lambda = rayleigh;
    p.swap(y);
  }
  return std::sqrt(std::max(0.0, lambda));
}

}  // namespace

BodyFrequencies estimate_body_frequencies(const Model& model, double contact_stiffness,
                                          const IntegratorParams& integrator) {
  // Bodies are independent: estimate in parallel, each into its own slot.
  const std::size_t count = model.bodies.size();
  std::vector<double> body_omega(count, 0.0), contact_omega(count, 0.0);
  parallel_for(static_cast<int>(count), [&](int b) {
    const Body& body = model.body(b);
    double& omega = body_omega[static_cast<std::size_t>(b)];
    omega = body.kind == BodyKind::deformable ? estimate_max_frequency(model, b) : 0.0;
    // An F-bar body's viscous operator keeps the standard volumetric stiffness (its viscous
    // stress uses F, model/fbar_kernel_impl.h), stiffer than its elastic one: where that
    // viscosity is explicit, the step must hold for both (see the header).
    if (body.kind == BodyKind::deformable &&
        model.material_of(b).volumetric == VolumetricFormulation::fbar &&
        body_damping(model, b, integrator) > 0.0)
      omega = std::max(omega, estimate_viscous_frequency(model, b));
    contact_omega[static_cast<std::size_t>(b)] = contact_frequency(model, body, contact_stiffness);
  });
  // The partner's side of a contact. With D the contact springs' (weighted) gap rows, the
  // contact stiffness is K_c = D^T D and, split by body, D = [D_A D_B]:
  //   lambda_max(M^-1/2 K_c M^-1/2) = lambda_max(D_A M_A^-1 D_A^T + D_B M_B^-1 D_B^T)
  //                                 <= omega_A^2 + omega_B^2,
  // omega_A being A's contact frequency with B held fixed (contact_frequency above). Two
  // deformable bodies bonded face to face with matching nodes reach the bound: the relative
  // mode of two boundary nodes of mass m on a spring 2 k l has omega^2 = 2 k l (2 / m), twice
  // what one side alone gives. The partner is unknown before contacts form, so each body takes
  // the largest contact frequency of any other body that can move: a rigid body whose three
  // degrees of freedom are all velocity-driven (a fixed wall, a driven plate) has no partner
  // side (its own value, kept for the minimum as before, is not a frequency of the system).
  double first = 0.0, second = 0.0;
  std::size_t first_body = count;
  for (std::size_t b = 0; b < count; ++b) {
    const Body& body = model.bodies[b];
    if (body.kind == BodyKind::rigid) {
      const RigidDrive& drive = model.rigid.drive[static_cast<std::size_t>(body.rigid_index)];
      if (drive.mode[0] == DriveMode::velocity && drive.mode[1] == DriveMode::velocity &&
          drive.mode[2] == DriveMode::velocity)
        continue;
    }
    if (contact_omega[b] > first) {
      second = first;
      first = contact_omega[b];
      first_body = b;
    } else {
      second = std::max(second, contact_omega[b]);
    }
  }
  BodyFrequencies result{std::vector<double>(count, 0.0), std::vector<double>(count, 0.0)};
  for (std::size_t b = 0; b < count; ++b) {
    const double partner = b == first_body ? second : first;
    const double omega2 =
        body_omega[b] * body_omega[b] + contact_omega[b] * contact_omega[b] + partner * partner;
    result.omega[b] = std::sqrt(omega2);
    if (omega2 > 0.0) result.contact_share[b] = 1.0 - body_omega[b] * body_omega[b] / omega2;
  }
  return result;
}

double body_damping(const Model& model, BodyId body_id, const IntegratorParams& integrator) {
  if (!model.is_damped(body_id)) return 0.0;
  // An implicit viscosity (IMEX) is stable at any alpha for omega dt <= 2
  // (solver/implicit_viscosity.h): it does not limit the step.
  if (integrator.implicit_viscosity && has_implicit_viscosity(model, body_id)) return 0.0;
  return model.material_of(body_id).damping;
}

std::string contact_share_note(const StableStep& stable) {
  std::ostringstream s;
  s << "contact penalties carry " << std::lround(100.0 * stable.contact_share)
    << "% of its omega^2";
  return s.str();
}

StableStep estimate_stable_time_step(const Model& model, double safety, double contact_stiffness,
                                     const IntegratorParams& integrator) {
  SG_VERIFY(safety > 0.0 && safety <= 1.0,
            "time step safety factor " << safety << " must be in (0, 1]");
  return stable_time_step(model, estimate_body_frequencies(model, contact_stiffness, integrator),
                          safety, integrator);
}

StableStep stable_time_step(const Model& model, const BodyFrequencies& frequencies, double safety,
                            const IntegratorParams& integrator) {
  const std::vector<double>& omega = frequencies.omega;
  StableStep best;
  best.dt = std::numeric_limits<double>::infinity();
  // Pick the minimum in body order (deterministic whatever the thread count).
  const int count = static_cast<int>(model.bodies.size());
  for (int b = 0; b < count; ++b) {
    if (omega[static_cast<std::size_t>(b)] <= 0.0) continue;
    const double alpha = body_damping(model, b, integrator);
    const double dt = safety * critical_time_step(omega[static_cast<std::size_t>(b)], alpha);
    if (dt < best.dt) {
      best.dt = dt;
      best.limiting_body = b;
      best.omega_max = omega[static_cast<std::size_t>(b)];
      best.damping_limited = 0.5 * alpha * best.omega_max > 1.0;
      best.contact_share = frequencies.contact_share[static_cast<std::size_t>(b)];
    }
  }
  return best;
}

}  // namespace sg
