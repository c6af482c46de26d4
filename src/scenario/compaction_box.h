#pragma once
// The compaction box (paper 000 §4, "Mixed powders compaction"): a granular sample of
// realistic shapes, some grains rigid and some deformable, "positioned between four rigid
// walls, and the upper wall is submitted to an imposed downwards velocity"; "Coulomb
// friction with a coefficient of 0.5 is considered for all the contacts" (the friction is a
// [[contact_laws]] setting, not the builder's).
//
// Geometry (inner box [0, width] x [0, height], y up):
//
//        left            lid (moves down)            right
//       |####|  |##################################|  |####|
//       |####|  +----------------------------------+  |####|   y = height (t = 0)
//       |####|                                        |####|
//       |####|     grains (packed without overlap)    |####|
//       |####|                                        |####|
//       |####|                                        |####|
//                                                             y = wall_clearance
//   |##############################################################|  y = 0
//   |########################## bottom ############################|  y = -thickness
//
// The four walls are rigid bodies driven by imposed velocities (zero for bottom, left and
// right), named "bottom", "left", "right" and "lid", so series.csv holds bottom_fy, lid_fy,
// lid_y, ... Walls never touch one another: two driven rigid bodies in contact would exchange
// penalty forces that pollute the wall forces and the contact energy. So the side walls start
// `clearance` above the bottom wall and the lid spans [clearance, width - clearance]; the
// clearance (the node spacing) is far below a grain size, so no grain can slip through.
//
// The grains are generated as in the shear cell (geometry/packing.h: a mixture by number
// fraction of discs, ellipses and Fourier-descriptor shapes, each component rigid or
// deformable) and placed by the box mode of the packing generator: random sequential
// addition in the box, then (settle = true) annealed Monte Carlo settling onto the floor, a
// poured powder; the lid then starts just above the deposit unless `height` is given.
//
// The lid's downward speed follows a trapezoid: 0 -> V over `lid_ramp_time`, V, then V -> 0
// over the same ramp, stopping either where the lid's lower face reaches `final_height` or
// at `compaction_time`; it then holds its position (the box stays closed: a relaxation
// stage if the run lasts longer).
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "geometry/packing.h"
#include "meshfree/body_discretization.h"
#include "model/model.h"

namespace sg {

class TomlReader;

struct CompactionBoxDef {
  double width = 10.0;  // inner width between the side walls (length)
  // Inner height at t = 0 (the lid's lower face, length); 0: the packed top of the settled
  // grains plus 2% of a grain size (settle = true only).
  double height = 0.0;
  int grains = 40;
  // The mixture; an empty material uses grain_material. Contour spacings are set to the node
  // spacing (a deformable grain's boundary nodes).
  std::vector<GrainComponentDef> components;
  std::string grain_material;   // a [[materials]] name
  std::string wall_material;    // a [[materials]] name (walls are rigid: its density only)
  double wall_thickness = 0.0;  // length; 0: one mean grain size
  bool settle = true;           // Monte Carlo settling onto the floor after placement
  double lid_velocity = 0.1;    // V > 0, downward speed of the lid (length / time)
  double lid_ramp_time = 0.0;   // time to reach V (and to stop from it); 0: V from t = 0
  // Where the motion stops: exactly one of final_height > 0 (length) or compaction_time > 0
  // (time, the motion's duration including both ramps).
  double final_height = 0.0;
  double compaction_time = 0.0;
  std::uint64_t seed = 1;  // every random choice (shapes, sizes, placement)
};

struct CompactionBoxInfo {
  double height = 0.0;          // inner height at t = 0 (the lid's lower face)
  double final_height = 0.0;    // inner height when the lid stops
  double stop_time = 0.0;       // when the lid stops
  double grain_area = 0.0;      // sum of the grains' areas
  double solid_fraction = 0.0;  // grain_area / (width height) at t = 0
  double packed_top = 0.0;      // highest grain point after packing
  double clearance = 0.0;       // gap between walls (length)
  int rigid_grains = 0, deformable_grains = 0;
  std::vector<GrainDef> grains;  // as generated (local contours, drawn sizes, components)
};

// The number-weighted mean size of the components (disc and Fourier: the mid diameter;
// ellipse: the mid short axis), which scales the packing clearances and the default wall
// thickness.
double compaction_box_grain_size(const CompactionBoxDef& def);

// The mixture add_compaction_box generates: the components, contour spacing = `spacing`.
MixtureDef compaction_box_mixture(const CompactionBoxDef& def, double spacing);

// The lid's downward velocity history (length / time, positive down) for a travel of
// `travel` (final_height set) or a duration (compaction_time set); `stop_time` receives the
// end of the motion and `travelled` the distance covered by then. Throws if the ramps do
// not fit in the motion.
PiecewiseLinear lid_speed_history(const CompactionBoxDef& def, double initial_height,
                                  double& stop_time, double& travelled);

// Adds the box and its grains to `model` (not periodic). Component materials are looked up
// by name in model.material_defs. Errors name the [compaction_box] key at fault.
CompactionBoxInfo add_compaction_box(Model& model, const CompactionBoxDef& def,
                                     MaterialId grain_material, MaterialId wall_material,
                                     const DiscretizationParams& params);

// Reads a [compaction_box] table (docs/scenario.md); `materials` are the defined names.
CompactionBoxDef read_compaction_box(const TomlReader& table,
                                     const std::set<std::string>& materials);

// Reads one grain component table (a [[<section>.components]] entry): shape "disc",
// "ellipse" or "fourier" with its size keys, fraction, material, rigid.
GrainComponentDef read_grain_component(const TomlReader& t, const std::set<std::string>& materials);

}  // namespace sg
