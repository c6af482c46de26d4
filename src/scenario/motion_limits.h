#pragma once
// Limits on what a scenario asks of the arithmetic before anything is built (issue #26):
//   - how far a velocity may carry a body over the run: the contact grid spans the bodies'
//     reach, and a wall driven at 1e10 made it larger than a vector can hold ("cannot create
//     std::vector larger than max_size()" at step 1, naming no input);
//   - how fast a material may vibrate: the stable-step estimate (a power iteration on the
//     body's stiffness) overflows beyond a squared frequency of about 1e154, and a young of
//     1e80 over a density of 1e-80 said "cannot estimate its highest frequency (got 0); is
//     the body inverted?".
// Each fails on the key that sets the value, naming the body or material and the limit.
#include <string>

#include "scenario/drive_def.h"
#include "scenario/scenario.h"
#include "scenario/toml_reader.h"

namespace sg {

// A body may travel at most this many node spacings over the run's duration.
inline constexpr double kMaxTravelInNodeSpacings = 1e6;
// A material's P-wave speed over the node spacing (about half its highest frequency) may be
// at most this: the estimate's squared frequency then stays far below its overflow at ~1e154
// (and the step, ~1e-70 of a time unit, is refused as absurd anyway unless allowed).
inline constexpr double kMaxWaveFrequency = 1e70;

class TravelLimit {
 public:
  // From the scenario's duration and node spacing (read first).
  explicit TravelLimit(const ScenarioDef& s);
  // Fails on `key` of `t` if `speed` carries `body` beyond the limit over the duration.
  void check_speed(const TomlReader& t, const std::string& key, double speed,
                   const std::string& body) const;
  // The same for the velocity axes of the drive table `t` (its x, y).
  void check_drive(const TomlReader& t, const DriveDef& drive, const std::string& body) const;

 private:
  double duration_, node_spacing_;
};

// Fails on the material's `young` if its wave frequency exceeds kMaxWaveFrequency with the
// scenario's node spacing.
void check_material_frequency(const TomlReader& t, const MaterialDef& m, double node_spacing);

}  // namespace sg
