#include "fuzz/csv_seed.h"

namespace sg::fuzz {

std::vector<SeedFile> csv_seed_files() {
  return {{"csv-seed.toml", R"(name = "csv-seed"
[time]
duration = 0.05
[output]
field_period = 0.025
[discretization]
node_spacing = 0.1
[[materials]]
name = "soft"
young = 10.0
[periodic]
x_min = 0.0
x_max = 4.0
[[strips]]
material = "soft"
surface_y = 0.0
back_y = -1.0
[strips.profile]
kind = "points"
file = "profile.csv"
[[grains]]
shape = "contour"
contour_file = "contour.csv"
material = "soft"
[[contact_laws]]
materials = ["soft", "soft"]
law = "frictionless"
normal_stiffness = 100.0
)"},
          {"contour.csv", "x,y\n1.5,0.5\n2.5,0.5\n2.5,1.5\n1.5,1.5\n"},
          {"profile.csv", "x,y\n0.0,0.0\n1.0,0.05\n2.0,0.0\n3.0,-0.05\n"}};
}

}  // namespace sg::fuzz
