#pragma once
// How a driven (first) body's force columns map to normal and tangential forces.
//
// series.csv gives B_fx, B_fy: the force body B receives from the granular layer. In the
// shear cell the top body slides at +V/2 along x and the layer pushes it up (+y); the
// bottom slides at -V/2 and is pushed down. The forces that friction is made of are
//   Fn = normal_sign * B_fy   (> 0 when the layer is compressed),
//   Ft = -slide_sign * B_fx   (> 0 when the layer resists the sliding).
#include <string>
#include <vector>

namespace sg {

struct DrivenBody {
  std::string name;
  double slide_sign = 1.0;   // sign of the body's sliding velocity along x
  double normal_sign = 1.0;  // sign of the y direction pointing from the layer to the body
};

// {"top", +1, +1} and {"bottom", -1, -1}: the shear-cell contract.
std::vector<DrivenBody> shear_cell_bodies();

}  // namespace sg
