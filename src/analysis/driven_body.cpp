#include "analysis/driven_body.h"

namespace sg {

std::vector<DrivenBody> shear_cell_bodies() {
  return {DrivenBody{"top", 1.0, 1.0}, DrivenBody{"bottom", -1.0, -1.0}};
}

}  // namespace sg
