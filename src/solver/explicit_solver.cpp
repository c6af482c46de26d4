#include "solver/explicit_solver.h"

#include <cmath>
#include <type_traits>

#include "core/error.h"
#include "model/internal_forces.h"

namespace sg {

double EnergyLedger::residual() const {
  return external_work + step_change - (kinetic - initial_kinetic) -
         (elastic + contact_elastic - initial_elastic) - damping_dissipated - contact_dissipated -
         servo_dissipated;
}

void ExplicitSolver::step(double dt) {
  // The interval [t_n-1, t_n] that ends here was dt_prev long (at the first step there is none:
  // the initial velocities are v_-1/2, as for a constant step dt); velocities advance over
  // h = t_n+1/2 - t_n-1/2 = (dt_prev + dt) / 2, which is dt bitwise when the step does not
  // change (0.5 * (dt + dt) is exact).
  const double dt_prev = state_.previous_dt > 0.0 ? state_.previous_dt : dt;
  const double h = 0.5 * (dt_prev + dt);
  NodeState& n = model_.nodes;
  const double gx = model_.gravity.x(), gy = model_.gravity.y();

  // External forces first: with lumped (row-sum) masses, the consistent gravity load on the
  // parameter I is integral(N_I rho g) = m_I g. Loops over nodes run per body in parallel,
  // sums are kept per body and added in body order: the result does not depend on the
  // number of threads.
  const int body_count = static_cast<int>(model_.bodies.size());
#pragma omp parallel for schedule(static)
  for (int b = 0; b < body_count; ++b) {
    const Body& body = model_.bodies[static_cast<std::size_t>(b)];
    // Gravity acts on the physical mass (mass scaling changes the inertia only).
    const double bgx = gx / body.mass_scale, bgy = gy / body.mass_scale;
    for (int k = body.node_begin; k < body.node_end; ++k) {
      const auto i = static_cast<std::size_t>(k);
      n.fx[i] = n.mass[i] * bgx;
      n.fy[i] = n.mass[i] * bgy;
    }
  }
  RigidState& rigid = model_.rigid;
  std::fill(rigid.fx.begin(), rigid.fx.end(), 0.0);
  std::fill(rigid.fy.begin(), rigid.fy.end(), 0.0);
  std::fill(rigid.torque.begin(), rigid.torque.end(), 0.0);
  ContactStepResult contact;
  if (contacts_) contact = contacts_->add_contact_forces(model_, dt_prev);

  InternalForceResult internal;
  try {
    internal = add_internal_forces(model_);
  } catch (const Error& e) {
    SG_THROW(e.what() << " at step " << state_.step << ", time " << state_.time);
  }

  // Per body: kinetic energy (time-centred), power of gravity, f_v . v_n+1/2, a probe
  // that becomes NaN iff some updated value is not finite (0 * inf = NaN), and of the total
  // force F_n on each parameter F_n . v_n+1/2 and F_n . F_n / m (the kinetic energies K_n^+
  // and K_n^- of the header, as corrections of the time-centred one). Then per node
  // drive: the imposed velocities at t_n+1/2 (2: the drive's history, or the carrier's new
  // velocity under load), the reaction (2) and R . v_n-1/2, R . v_n+1/2 (2, velocity-driven
  // components only). A drive's nodes are in one body: one thread writes its sums.
  const std::size_t drive_count = model_.node_drives.size();
  constexpr std::size_t kBodySums = 6;
  body_sums_.assign(kBodySums * model_.bodies.size() + 6 * drive_count, 0.0);
  double* const drive_data = body_sums_.data() + kBodySums * model_.bodies.size();
  const double t_mid = state_.time + 0.5 * dt;  // velocities live at half steps
  for (std::size_t d = 0; d < drive_count; ++d)
    for (int c = 0; c < 2; ++c)
      if (model_.node_drives[d].mode[c] == DriveMode::velocity)
        drive_data[6 * d + static_cast<std::size_t>(c)] = model_.node_drives[d].velocity[c](t_mid);
  const ServoPower carrier_power = advance_node_carriers(h, drive_data);
#pragma omp parallel for schedule(static)
  for (int b = 0; b < body_count; ++b) {
    const Body& body = model_.bodies[static_cast<std::size_t>(b)];
    const double bgx = gx / body.mass_scale, bgy = gy / body.mass_scale;
    double kinetic = 0.0, external_power = 0.0, viscous_work = 0.0, finite_probe = 0.0,
           force_power = 0.0, force_square = 0.0;
    // Two instances of the node loop: grains (no driven nodes, the hot case) never look at
    // NodeState::drive; a strip with a driven back face checks each node.
    auto advance_nodes = [&](auto has_driven_nodes) {
      for (int k = body.node_begin; k < body.node_end; ++k) {
        const auto i = static_cast<std::size_t>(k);
        const double vx_old = n.vx[i], vy_old = n.vy[i];
        const int drive = decltype(has_driven_nodes)::value ? n.drive[i] : -1;
        if (drive < 0) {
          n.vx[i] += h * n.inverse_mass[i] * n.fx[i];
          n.vy[i] += h * n.inverse_mass[i] * n.fy[i];
        } else {
          const NodeDrive& nd = model_.node_drives[static_cast<std::size_t>(drive)];
          double* sums = drive_data + 6 * static_cast<std::size_t>(drive);
          double* velocity[2] = {&n.vx[i], &n.vy[i]};
          double* force[2] = {&n.fx[i], &n.fy[i]};
          for (std::size_t c = 0; c < 2; ++c) {
            if (nd.mode[c] == DriveMode::free) {
              *velocity[c] += h * n.inverse_mass[i] * *force[c];
              continue;
            }
            const double v_old = *velocity[c], v_new = sums[c];
            const double reaction = n.mass[i] * (v_new - v_old) / h - *force[c];
            *force[c] += reaction;  // fx, fy: the total force on the parameter
            *velocity[c] = v_new;
            sums[2 + c] += reaction;
            if (nd.mode[c] == DriveMode::velocity) {  // a carrier's work: as a servo load's
              sums[4] += reaction * v_old;
              sums[5] += reaction * v_new;
            }
          }
        }
        n.ux[i] += dt * n.vx[i];
        n.uy[i] += dt * n.vy[i];
        kinetic += 0.5 * n.mass[i] * (vx_old * n.vx[i] + vy_old * n.vy[i]);
        force_power += n.fx[i] * n.vx[i] + n.fy[i] * n.vy[i];
        force_square += n.inverse_mass[i] * (n.fx[i] * n.fx[i] + n.fy[i] * n.fy[i]);
        viscous_work += n.viscous_fx[i] * n.vx[i] + n.viscous_fy[i] * n.vy[i];
        external_power += n.mass[i] * (bgx * n.vx[i] + bgy * n.vy[i]);
        finite_probe += 0.0 * (n.ux[i] + n.uy[i] + n.vx[i] + n.vy[i]);
      }
    };
    if (body.node_drive < 0)
      advance_nodes(std::false_type{});
    else
      advance_nodes(std::true_type{});
    double* sums = body_sums_.data() + kBodySums * static_cast<std::size_t>(b);
    sums[0] = kinetic;
    sums[1] = external_power;
    sums[2] = viscous_work;
    sums[3] = finite_probe;
    sums[4] = force_power;
    sums[5] = force_square;
  }
  double kinetic = 0.0, external_power = 0.0, viscous_work_new = 0.0, finite_probe = 0.0,
         force_power = 0.0, force_square = 0.0;
  for (std::size_t b = 0; b < model_.bodies.size(); ++b) {
    const double* sums = body_sums_.data() + kBodySums * b;
    kinetic += sums[0];
    external_power += sums[1];
    viscous_work_new += sums[2];
    finite_probe += sums[3];
    force_power += sums[4];
    force_square += sums[5];
  }

  const RigidUpdate rigid_update = advance_rigid_bodies(dt, dt_prev, carrier_power);
  kinetic += rigid_update.kinetic;
  external_power += rigid_update.external_power;
  force_power += rigid_update.force_power;
  force_square += rigid_update.force_square;

  // Bulk damping, booked so that the ledger closes exactly for a linear system under this
  // scheme: over [t_n, t_n+1] the energy K^+_n + E(u_n) becomes K^-_n+1 + E(u_n+1), changed
  // by the trapezoidal work 1/2 dt v_n+1/2 . (f_v,n + f_v,n+1) (header). The half pairing
  // f_v,n with v_n-1/2 (the power at the force evaluation) completes the interval that ends
  // here, with its step dt_prev; the half pairing it with v_n+1/2 opens the next one (dt).
  EnergyLedger& e = state_.energy;
  e.external_work += pending_external_work_;
  e.damping_dissipated += pending_damping_dissipation_;
  if (state_.step > 0) e.damping_dissipated += 0.5 * dt_prev * internal.damping_power;
  // Contact dissipation of this evaluation belongs to the increment that led to u_n.
  e.contact_dissipated += contact.dissipated;
  e.contact_elastic = contact.stored_energy;
  // The kinetic energy that opens [t_n, t_n+1], K_n^+ = tc + 1/4 (dt_prev - dt) F . v_n+1/2
  // with tc the time-centred sum, and the step change K_n^+ - K_n^- =
  // -1/8 (dt^2 - dt_prev^2) F . F / m (header): both exactly 0 for a constant step.
  e.kinetic = kinetic;
  if (dt != dt_prev) {  // (not 0 * F . F: the ledger of a constant step is the same bits)
    e.kinetic += 0.25 * (dt_prev - dt) * force_power;
    e.step_change += -0.125 * ((dt - dt_prev) * (dt + dt_prev)) * force_square;
  }
  e.elastic = internal.elastic_energy;
  if (state_.step == 0) {
    e.initial_kinetic = kinetic;
    e.initial_elastic = internal.elastic_energy + contact.stored_energy;
  }
  // Increments over [t_n, t_n+1]: the work of f_ext along u_n+1 - u_n = dt v_n+1/2 is exact.
  pending_external_work_ = dt * external_power;
  pending_damping_dissipation_ = -0.5 * dt * viscous_work_new;
  // Work of the node drives' reactions, split as the servo loads' (see the header).
  double drive_work_old = 0.0, drive_work_new = 0.0;
  for (std::size_t d = 0; d < drive_count; ++d) {
    const double* sums = drive_data + 6 * d;
    model_.node_drives[d].reaction = Vec2(sums[2], sums[3]);
    drive_work_old += sums[4];
    drive_work_new += sums[5];
  }
  e.external_work += pending_drive_work_;
  if (state_.step > 0) e.external_work += 0.5 * dt_prev * drive_work_old;
  pending_drive_work_ = 0.5 * dt * drive_work_new;

  state_.previous_dt = dt;
  state_.time += dt;
  ++state_.step;
  if (model_.periodic_x) wrap_periodic_bodies();
  if (finite_probe != 0.0 || !std::isfinite(finite_probe)) check_finite_velocities();
}

ExplicitSolver::ServoPower ExplicitSolver::advance_node_carriers(double h,
                                                                 double* drive_data) const {
  ServoPower power;
  const NodeState& n = model_.nodes;
  for (std::size_t d = 0; d < model_.node_drives.size(); ++d) {
    const NodeDrive& nd = model_.node_drives[d];
    for (std::size_t c = 0; c < 2; ++c) {
      SG_VERIFY(nd.mode[c] != DriveMode::force,
                "body '" << model_.bodies[static_cast<std::size_t>(nd.body)].name
                         << "': a node drive cannot impose a constant force (use load)");
      if (nd.mode[c] != DriveMode::load) continue;
      SG_VERIFY(!nd.nodes.empty(), "body '" << model_.bodies[static_cast<std::size_t>(nd.body)].name
                                            << "': a load-driven node drive has no nodes");
      // The carrier: mass, momentum and received force of its nodes, summed in node order
      // (serial: the same bits on any number of threads).
      const std::vector<double>& v = c == 0 ? n.vx : n.vy;
      const std::vector<double>& f = c == 0 ? n.fx : n.fy;
      double mass = 0.0, momentum = 0.0, received = 0.0;
      for (int k : nd.nodes) {
        const auto i = static_cast<std::size_t>(k);
        mass += n.mass[i];
        momentum += n.mass[i] * v[i];
        received += f[i];
      }
      // M (v_n+1/2 - v_n-1/2) = h (received + F(t_n) - c v_n+1/2), as a servo-loaded rigid
      // degree of freedom (advance_rigid_bodies), with M v_n-1/2 the carrier's momentum.
      const double load = nd.load[c](state_.time);
      const double damping = nd.load_damping[c];
      const double v_old = momentum / mass;
      const double v_new = (momentum + h * (received + load)) / (mass + h * damping);
      drive_data[6 * d + c] = v_new;
      power.load_old += load * v_old;
      power.load_new += load * v_new;
      power.servo_old += damping * v_new * v_old;
      power.servo_new += damping * v_new * v_new;
    }
  }
  return power;
}

ExplicitSolver::RigidUpdate ExplicitSolver::advance_rigid_bodies(double dt, double dt_prev,
                                                                 ServoPower servo) {
  RigidState& r = model_.rigid;
  RigidUpdate update;
  const double h = 0.5 * (dt_prev + dt);  // as in step()
  // Servo-loaded DOFs: sums of F_n . v and (c v_n+1/2) . v over v_n-1/2 and v_n+1/2, the node
  // carriers' first.
  double load_work_old = servo.load_old, load_work_new = servo.load_new,
         servo_old = servo.servo_old, servo_new = servo.servo_new;
  const double t_mid = state_.time + 0.5 * dt;  // velocities live at half steps
  for (std::size_t i = 0; i < r.size(); ++i) {
    const RigidDrive& drive = r.drive[i];
    double* velocity[3] = {&r.vx[i], &r.vy[i], &r.omega[i]};
    double* position[3] = {&r.x[i], &r.y[i], &r.theta[i]};
    const double received[3] = {r.fx[i], r.fy[i], r.torque[i]};
    const double inertia[3] = {r.mass[i], r.mass[i], r.inertia[i]};
    const double weight = r.mass[i] / r.mass_scale[i];  // physical mass (mass scaling)
    const double gravity[3] = {weight * model_.gravity.x(), weight * model_.gravity.y(), 0.0};
    for (int d = 0; d < 3; ++d) {
      const double v_old = *velocity[d];
      if (drive.mode[d] == DriveMode::velocity) {
        // A velocity-driven degree of freedom is part of the driver, not of the system: its
        // kinetic energy is not counted, and the work it does on the system is that of the
        // forces it exerts through the contacts, -received . v.
        *velocity[d] = drive.velocity[d](t_mid);
        *position[d] += dt * *velocity[d];
        update.external_power -= received[d] * *velocity[d];
        continue;
      }
      double force = 0.0;  // the total force F_n of the update v_n+1/2 = v_n-1/2 + h F_n / m
      if (drive.mode[d] == DriveMode::load) {
        // Servo: the imposed force F(t_n) and the viscous force -c v, the latter implicit in
        // the new velocity so that no value of c limits the step:
        //   m (v_n+1/2 - v_n-1/2) = h (received + gravity + F - c v_n+1/2).
        const double load = drive.load[d](state_.time);
        const double c = drive.load_damping[d];
        *velocity[d] =
            (inertia[d] * v_old + h * (received[d] + gravity[d] + load)) / (inertia[d] + h * c);
        force = received[d] + gravity[d] + load - c * *velocity[d];
        update.external_power += gravity[d] * *velocity[d];
        load_work_old += load * v_old;
        load_work_new += load * *velocity[d];
        servo_old += c * *velocity[d] * v_old;
        servo_new += c * *velocity[d] * *velocity[d];
      } else {
        const double external =
            gravity[d] + (drive.mode[d] == DriveMode::force ? drive.force[d] : 0.0);
        force = received[d] + external;
        *velocity[d] = v_old + h * force / inertia[d];
        update.external_power += external * *velocity[d];
      }
      *position[d] += dt * *velocity[d];
      update.kinetic += 0.5 * inertia[d] * v_old * *velocity[d];
      update.force_power += force * *velocity[d];
      update.force_square += force * force / inertia[d];
    }
  }
  // A force f_n that depends on time or on v_n+1/2 is booked as
  // 1/2 dt_prev f_n . v_n-1/2 + 1/2 dt f_n . v_n+1/2, the same split as the bulk damping in
  // step(): the kinetic energy changes over [t_n-1, t_n] by the trapezoidal work
  // 1/2 dt_prev v_n-1/2 . (F_n-1 + F_n) (K_n^- - K_n-1^+, header), so the half with v_n-1/2
  // closes the interval that ends now, with its step, and the half with v_n+1/2 opens the next.
  EnergyLedger& e = state_.energy;
  e.external_work += pending_load_work_;
  e.servo_dissipated += pending_servo_dissipation_;
  if (state_.step > 0) {
    e.external_work += 0.5 * dt_prev * load_work_old;
    e.servo_dissipated += 0.5 * dt_prev * servo_old;
  }
  pending_load_work_ = 0.5 * dt * load_work_new;
  pending_servo_dissipation_ = 0.5 * dt * servo_new;
  return update;
}

void ExplicitSolver::wrap_periodic_bodies() {
  const double period = model_.x_max - model_.x_min;
  NodeState& n = model_.nodes;
  for (const Body& body : model_.bodies) {
    double shift = 0.0;
    if (body.kind == BodyKind::rigid) {
      double& x = model_.rigid.x[static_cast<std::size_t>(body.rigid_index)];
      if (x < model_.x_min)
        shift = period;
      else if (x >= model_.x_max)
        shift = -period;
      x += shift;
      continue;
    }
    // A deformable body is moved by one period through its reference positions: u, v and
    // every precomputed row are invariant under a translation of the reference frame.
    const auto first = static_cast<std::size_t>(body.node_begin);
    double x = n.ref_x[first] + n.ux[first];
    if (body.open_contour) {
      // A strip spans the cell: its first contour node sits at one end, where round-off would
      // wrap it back and forth every step. Its middle (between its two ends) is kept in the
      // cell instead: a strip drifting along x moves by a period once it has drifted L/2.
      const auto last = static_cast<std::size_t>(body.boundary_end - 1);
      x = 0.5 * (x + n.ref_x[last] + n.ux[last]);
    }
    if (x < model_.x_min)
      shift = period;
    else if (x >= model_.x_max)
      shift = -period;
    if (shift != 0.0)
      for (int i = body.node_begin; i < body.node_end; ++i)
        n.ref_x[static_cast<std::size_t>(i)] += shift;
  }
}

void ExplicitSolver::check_finite_velocities() const {
  const NodeState& n = model_.nodes;
  for (const Body& body : model_.bodies)
    for (int i = body.node_begin; i < body.node_end; ++i) {
      const auto k = static_cast<std::size_t>(i);
      if (!std::isfinite(n.vx[k]) || !std::isfinite(n.vy[k]) || !std::isfinite(n.ux[k]) ||
          !std::isfinite(n.uy[k]))
        SG_THROW("body '" << body.name << "', node " << i - body.node_begin
                          << ": non-finite velocity or displacement after step " << state_.step
                          << " (time " << state_.time
                          << "): the time step is too large or the input is inconsistent");
    }
}

}  // namespace sg
