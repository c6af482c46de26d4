#include "scenario/drive_def.h"

#include "core/error.h"
#include "scenario/toml_reader.h"

namespace sg {

namespace {

// The mode of one axis, the history and the servo's damping, on a DOF with the given slots.
void set_axis(const AxisDrive& a, DriveMode& mode, PiecewiseLinear& velocity, PiecewiseLinear& load,
              double& damping, double pressure_force) {
  switch (a.kind) {
    case AxisDriveKind::free:
      mode = DriveMode::free;
      return;
    case AxisDriveKind::velocity:
      mode = DriveMode::velocity;
      velocity = a.history;
      return;
    case AxisDriveKind::force:
    case AxisDriveKind::pressure:
      mode = DriveMode::load;
      load = a.history;
      if (a.kind == AxisDriveKind::pressure)
        for (double& v : load.values)
          v *= pressure_force;
      damping = a.servo_damping;
      return;
  }
}

AxisDrive read_axis(const TomlReader& parent, const char* key, bool allow_pressure) {
  AxisDrive a;
  if (!parent.is_table(key)) {
    if (parent.string(key) != "free")
      parent.fail(key, "expected \"free\" or a table {velocity = ...}, {force = ...}" +
                           std::string(allow_pressure ? " or {pressure = ...}" : ""));
    return a;
  }
  const TomlReader t = *parent.table(key);
  t.reject_unknown_keys({"velocity", "force", "pressure", "servo_damping"});
  int given = 0;
  const char* value_key = "velocity";
  for (const char* k : {"velocity", "force", "pressure"})
    if (t.has(k)) {
      ++given;
      value_key = k;
    }
  if (given != 1) t.fail("velocity", "expected exactly one of velocity, force or pressure");
  const std::string which = value_key;
  if (which == "pressure" && !allow_pressure)
    t.fail("pressure", "a pressure applies to a strip's y only (use force)");
  a.kind = which == "velocity" ? AxisDriveKind::velocity
           : which == "force"  ? AxisDriveKind::force
                               : AxisDriveKind::pressure;
  if (t.is_array(value_key)) {
    try {
      a.history = history_from_points(t.pairs(value_key, 1), "history");
    } catch (const Error& e) {
      t.fail(value_key, e.what());
    }
  } else {
    a.history = PiecewiseLinear::constant(t.number(value_key));
  }
  if (a.kind == AxisDriveKind::velocity && t.has("servo_damping"))
    t.fail("servo_damping", "applies only to a force or pressure");
  a.servo_damping = t.non_negative("servo_damping", 0.0);
  return a;
}

}  // namespace

PiecewiseLinear history_from_points(const std::vector<Vec2>& points, const std::string& what) {
  SG_VERIFY(!points.empty(), what << ": expected at least one [t, value] point");
  PiecewiseLinear f;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double t = points[i].x();
    SG_VERIFY(i == 0 || t >= f.times.back(), what << ": point " << i + 1
                                                  << ": times must not decrease, got t = " << t
                                                  << " after " << f.times.back());
    SG_VERIFY(i < 2 || !(t == f.times[i - 1] && t == f.times[i - 2]),
              what << ": point " << i + 1 << ": at most two points at t = " << t << " (a jump)");
    f.times.push_back(t);
    f.values.push_back(points[i].y());
  }
  return f;
}

DriveDef read_drive(const TomlReader& t, bool allow_theta, bool allow_pressure) {
  if (allow_theta)
    t.reject_unknown_keys({"x", "y", "theta"});
  else
    t.reject_unknown_keys({"x", "y"});
  DriveDef d;
  const char* keys[3] = {"x", "y", "theta"};
  for (int k = 0; k < 3; ++k)
    if (t.has(keys[k]))
      d.axis[static_cast<std::size_t>(k)] = read_axis(t, keys[k], allow_pressure && k == 1);
  return d;
}

void apply_drive(const DriveDef& def, RigidDrive& drive, double pressure_force) {
  for (int k = 0; k < 3; ++k)
    if (const auto& a = def.axis[static_cast<std::size_t>(k)])
      set_axis(*a, drive.mode[k], drive.velocity[k], drive.load[k], drive.load_damping[k],
               pressure_force);
}

void apply_drive(const DriveDef& def, NodeDrive& drive, double pressure_force) {
  SG_VERIFY(!def.axis[2], "a strip's back face has no rotation to drive");
  for (int k = 0; k < 2; ++k)
    if (const auto& a = def.axis[static_cast<std::size_t>(k)])
      set_axis(*a, drive.mode[k], drive.velocity[k], drive.load[k], drive.load_damping[k],
               pressure_force);
}

}  // namespace sg
