// The rigid bodies' phase of Stepper::step: velocities and positions of the rigid
// degrees of freedom, free, force-loaded, velocity-driven or servo-loaded. See
// stepper.h.
#include "solver/stepper.h"

namespace sg {

Stepper::RigidUpdate Stepper::advance_rigid_bodies(const StepSizes& steps,
                                                   const ServoPower& carriers) {
  RigidState& r = model_.rigid;
  RigidUpdate update;
  // Servo-loaded DOFs: sums of F_n . v and (c v_n+1/2) . v over v_n-1/2 and v_n+1/2, the node
  // carriers' first.
  update.servo = carriers;
  ServoPower& servo = update.servo;
  const double h = steps.velocity_interval, dt = steps.next;
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
        servo.load_old += load * v_old;
        servo.load_new += load * *velocity[d];
        servo.servo_old += c * *velocity[d] * v_old;
        servo.servo_new += c * *velocity[d] * *velocity[d];
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
  return update;
}

}  // namespace sg
