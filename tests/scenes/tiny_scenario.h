#pragma once
// The body of a tiny scenario shared by tests (everything after the [time] and [output]
// tables, which each test writes itself): two materials, three contact laws, a floor, a soft
// disc thrown down and a rigid disc.
#include <string>

namespace sg::scenes {

inline constexpr const char* kTinyScenarioBody = R"([discretization]
node_spacing = 0.15
[[materials]]
name = "soft"
young = 10.0
poisson = 0.3
damping = 0.01
[[materials]]
name = "hard"
young = 100.0
[[contact_laws]]
materials = ["soft", "hard"]
law = "coulomb"
normal_stiffness = 1000.0
friction = 0.3
[[contact_laws]]
materials = ["soft", "soft"]
law = "cohesive"
normal_stiffness = 1000.0
cohesion = 0.5
[[contact_laws]]
materials = ["hard", "hard"]
law = "frictionless"
normal_stiffness = 1000.0
[[walls]]
name = "floor"
lower_left = [-2.0, -1.0]
upper_right = [2.0, -0.5]
material = "hard"
[[grains]]
center = [0.0, 0.0]
radius = 0.5
material = "soft"
velocity = [0.0, -1.0]
[[grains]]
center = [1.2, 0.0]
radius = 0.4
material = "hard"
rigid = true
)";

// Two materials (soft disc grains, hard walls and rigid grains) and Coulomb 0.5 between all
// of them, spacing 0.15: the body of the tiny compaction-box and generate scenarios (each
// test adds [time], [output] and its builder section).
inline constexpr const char* kSoftHardCoulomb = R"([discretization]
node_spacing = 0.15
[[materials]]
name = "soft"
young = 10.0
poisson = 0.4
damping = 0.01
[[materials]]
name = "hard"
young = 1000.0
[[contact_laws]]
materials = ["soft", "soft"]
law = "coulomb"
normal_stiffness = 1000.0
friction = 0.5
[[contact_laws]]
materials = ["soft", "hard"]
law = "coulomb"
normal_stiffness = 1000.0
friction = 0.5
[[contact_laws]]
materials = ["hard", "hard"]
law = "coulomb"
normal_stiffness = 1000.0
friction = 0.5
)";

// Appended to kTinyScenarioBody: the scene made periodic over [-3, 3) with two more soft
// grains that meet across the seam x = 3 (one thrown at 4 in +x) and bond.
inline constexpr const char* kSeamGrains = R"([periodic]
x_min = -3.0
x_max = 3.0
[[grains]]
name = "crossing"
center = [2.4, -0.1]
radius = 0.3
material = "soft"
velocity = [4.0, 0.0]
[[grains]]
name = "waiting"
center = [-2.6, -0.1]
radius = 0.3
material = "soft"
)";

// The whole tiny scenario named "tiny": `duration`, a series row every 0.005 and fields every
// 0.01, then kTinyScenarioBody.
inline std::string tiny_scenario(const std::string& duration) {
  return "name = \"tiny\"\n[time]\nduration = " + duration +
         "\n[output]\nseries_period = 0.005\nfield_period = 0.01\n" + kTinyScenarioBody;
}

}  // namespace sg::scenes
