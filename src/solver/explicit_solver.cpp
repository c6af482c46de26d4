#include "solver/explicit_solver.h"

#include <cmath>

#include "core/error.h"
#include "model/internal_forces.h"

namespace sg {

double EnergyLedger::residual() const {
  return external_work - (kinetic - initial_kinetic) - (elastic - initial_elastic) -
         damping_dissipated - contact_dissipated;
}

void ExplicitSolver::step(double dt) {
  NodeState& n = model_.nodes;
  const std::size_t count = n.size();
  const double gx = model_.gravity.x(), gy = model_.gravity.y();

  // External forces first: with lumped (row-sum) masses, the consistent gravity load on the
  // parameter I is integral(N_I rho g) = m_I g.
  for (std::size_t i = 0; i < count; ++i) {
    n.fx[i] = n.mass[i] * gx;
    n.fy[i] = n.mass[i] * gy;
  }
  InternalForceResult internal;
  try {
    internal = add_internal_forces(model_);
  } catch (const Error& e) {
    SG_THROW(e.what() << " at step " << state_.step << ", time " << state_.time);
  }

  double kinetic = 0.0, external_power = 0.0;
  double finite_probe = 0.0;  // becomes NaN iff some updated value is not finite (0 * inf = NaN)
  for (std::size_t i = 0; i < count; ++i) {
    const double vx_old = n.vx[i], vy_old = n.vy[i];
    n.vx[i] += dt * n.inverse_mass[i] * n.fx[i];
    n.vy[i] += dt * n.inverse_mass[i] * n.fy[i];
    n.ux[i] += dt * n.vx[i];
    n.uy[i] += dt * n.vy[i];
    kinetic += 0.5 * n.mass[i] * (vx_old * n.vx[i] + vy_old * n.vy[i]);
    external_power += n.mass[i] * (gx * n.vx[i] + gy * n.vy[i]);
    finite_probe += 0.0 * (n.ux[i] + n.uy[i] + n.vx[i] + n.vy[i]);
  }

  // The ledger describes the configuration u_n: work and dissipation up to t_n (the increments
  // of the previous step), kinetic and elastic energy at t_n.
  EnergyLedger& e = state_.energy;
  e.external_work += pending_external_work_;
  e.damping_dissipated += pending_damping_dissipation_;
  e.kinetic = kinetic;
  e.elastic = internal.elastic_energy;
  if (state_.step == 0) {
    e.initial_kinetic = kinetic;
    e.initial_elastic = internal.elastic_energy;
  }
  // Increments over [t_n, t_n+1]: the work of f_ext along u_n+1 - u_n = dt v_n+1/2 is exact.
  pending_external_work_ = dt * external_power;
  pending_damping_dissipation_ = dt * internal.damping_power;

  state_.time += dt;
  ++state_.step;
  if (finite_probe != 0.0 || !std::isfinite(finite_probe)) check_finite_velocities();
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
