#pragma once
// One snapshot of the grains' rigid-body kinematics, as the engine will write it: a CSV
// with columns body,x,y,vx,vy,area (centre of mass, its velocity, current area). This
// is what the coherence analysis (paper 002 §2.2) and the velocity profiles need: the
// paper interpolates centre-of-mass velocities, the deformation part being small.
#include <string>
#include <string_view>
#include <vector>

#include "geometry/vec2.h"

namespace sg {

struct GrainSnapshot {
  double time = 0.0;              // simulation time of the snapshot
  std::vector<std::string> body;  // body name or id, as written
  std::vector<Vec2> position;     // centre of mass
  std::vector<Vec2> velocity;     // centre-of-mass velocity
  std::vector<double> area;       // current area (> 0)

  std::size_t size() const { return position.size(); }
};

// Reads a snapshot file; `time` is supplied by the caller (from the snapshot index).
// Throws sg::Error naming the file, line and column for a missing column, a malformed
// number or a non-positive area.
GrainSnapshot read_grain_snapshot(const std::string& path, double time);

// The snapshot without the listed bodies (e.g. the first bodies "top", "bottom" if the
// engine writes them in the same file).
GrainSnapshot without_bodies(const GrainSnapshot& snapshot, const std::vector<std::string>& names);

}  // namespace sg
