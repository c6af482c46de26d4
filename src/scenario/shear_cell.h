#pragma once
// The third-body shear cell (papers 001/002 §2; 003): two rough rigid first bodies, periodic
// in x over [0, L), and N grains between them. The top body first moves down to the
// requested mean gap D during the compaction time (motion-driven normal loading), then the
// top slides at +V/2 and the bottom at -V/2. Bodies are named "bottom" and "top" (series.csv
// columns bottom_fx ... top_y).
#include <cstdint>
#include <string>

#include "geometry/size_distribution.h"
#include "meshfree/body_discretization.h"
#include "model/model.h"

namespace sg {

struct ShearCellDef {
  double length = 20.0;                                 // L, the period (length)
  int grains = 60;                                      // N
  SizeRangeDef diameter{0.85, 1.15, SizeLaw::uniform};  // paper 001
  std::string grain_material;                           // a [[materials]] name
  std::string first_body_material;                      // a [[materials]] name
  double roughness_rms = 0.3;                           // RMS height of both surfaces (length)
  double hurst = 0.8;                 // Hurst exponent of the self-affine surfaces
  double first_body_thickness = 2.0;  // for the first bodies' mass (length)
  double gap = 0.0;                   // D, mean gap after compaction; 0: 90% of the packed height
  double compaction_time = 1.0;       // time to close the gap (time)
  double velocity = 1.0;              // V, sliding velocity (top +V/2, bottom -V/2)
  std::uint64_t seed = 1;             // every random choice (sizes, packing, roughness)
};

struct ShearCellInfo {
  double bottom_mean_y = 0.0, top_mean_y = 0.0;  // mean surface heights at t = 0
  double gap = 0.0;                              // D
  double packed_solid_fraction = 0.0;
};

// Adds the cell to `model` (which must be empty of periodic settings) and makes it periodic.
ShearCellInfo add_shear_cell(Model& model, const ShearCellDef& def, MaterialId grain_material,
                             MaterialId first_body_material, const DiscretizationParams& params);

}  // namespace sg
