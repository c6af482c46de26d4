#pragma once
// How a driven body moves, per degree of freedom (x, y, theta), as written in a scenario
// (docs/scenario.md "Drives"): free; an imposed velocity, a piecewise-linear history of
// (t, v) points, constant before the first and after the last (two points at the same t are a
// jump); or an imposed force history F(t) (a pressure p on a strip's back face is F = -+p L),
// with an optional servo damping c (the viscous force -c v of DriveMode::load, model.h).
// Applied to a rigid body's RigidDrive or a deformable strip's NodeDrive (x, y only).
#include <array>
#include <optional>
#include <string>

#include "model/model.h"

namespace sg {

class TomlReader;

enum class AxisDriveKind { free, velocity, force, pressure };

struct AxisDrive {
  AxisDriveKind kind = AxisDriveKind::free;
  PiecewiseLinear history;     // velocity (length/time, rad/time), force/torque, or pressure
  double servo_damping = 0.0;  // force, pressure: c (force / velocity); 0: a pure force
};

// Unset axes keep the body kind's default (docs/scenario.md).
struct DriveDef {
  std::array<std::optional<AxisDrive>, 3> axis;  // x, y, theta
  bool any() const { return axis[0] || axis[1] || axis[2]; }
};

// Reads a drive table ([walls.drive], [[strips]].drive, ...): keys x, y, theta (theta only
// when `allow_theta`), each "free", or an inline table with one of velocity, force or
// pressure (a number or a list of [t, value] points; pressure only when `allow_pressure`)
// and, with force or pressure, servo_damping.
DriveDef read_drive(const TomlReader& t, bool allow_theta, bool allow_pressure);

// A velocity history from (t, v) points: times non-decreasing, at most two points at one t.
// Throws sg::Error naming `what` otherwise.
PiecewiseLinear history_from_points(const std::vector<Vec2>& points, const std::string& what);

// Sets the axes given in `def` on a rigid body's drive. `pressure_force` converts a pressure
// into the force on the body (-L for a strip above its surface, +L below).
void apply_drive(const DriveDef& def, RigidDrive& drive, double pressure_force);
// The same on a strip's back face (x and y).
void apply_drive(const DriveDef& def, NodeDrive& drive, double pressure_force);

}  // namespace sg
