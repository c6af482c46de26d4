#pragma once
// The third-body shear cell (papers 001/002 §2; 003): two rough first bodies, rigid or
// deformable (paper 000 §3), periodic in x over [0, L), and N grains between them. Bodies are
// named "bottom" and "top" (series.csv columns bottom_fx ... top_y). Two ways to load the layer
// normally:
//  - gap (papers 001/002): the top first moves down to the requested mean gap D during the
//    compaction time (motion-driven), then holds it;
//  - pressure (paper 003, "a constant normal pressure of 1 GPa imposed onto the upper border
//    of the upper first body"): the top's y is servo-loaded (DriveMode::load) by F = -p L,
//    ramped from 0 over the compaction time, with a viscous servo force -c v_y so that it
//    settles on the layer instead of bouncing; the gap is then an output.
// After the compaction time the top slides at +V/2 and the bottom at -V/2 in both cases.
// Deformable first bodies are driven through their back faces (NodeDrive). Under pressure
// loading the top strip's back-face nodes move as one in y, a carrier (of their mass) loaded
// by the same F and servo force -c v_y (DriveMode::load on the NodeDrive's y), while they slide
// as imposed in x; c is the same estimate, for the strip's mass.
// The grains are a mixture of discs and ellipses by number fraction (paper 003: as many
// circles of 0.3-0.5 um diameter as ellipses of 1-2 x 0.6-1.2 um), deformable or rigid.
#include <cstdint>
#include <string>
#include <vector>

#include <optional>

#include "geometry/packing.h"
#include "geometry/size_distribution.h"
#include "geometry/surface_profile.h"
#include "meshfree/body_discretization.h"
#include "model/model.h"
#include "scenario/drive_def.h"

namespace sg {

enum class NormalLoad { gap, pressure };

// The first bodies: rigid strips (papers 001-003), or deformable periodic strips meshed like
// the grains (paper 000 §3: "two deformable bodies (so-called first bodies) ... The lower
// boundary is fixed, the upper boundary is submitted to an imposed vertical displacement ...
// and to a horizontal velocity"): their back faces (at first_body_thickness from the mean
// surface) are driven as the rigid bodies would be, the rest of each strip deforms.
enum class FirstBodyKind { rigid, deformable };

struct ShearCellDef {
  double length = 20.0;                                 // L, the period (length)
  int grains = 60;                                      // N
  SizeRangeDef diameter{0.85, 1.15, SizeLaw::uniform};  // paper 001 (when no components)
  // Grain mixture; empty: discs of `diameter` in grain_material. A component with an empty
  // material uses grain_material; its contour spacing is its own node spacing (its
  // GrainComponentDef::spacing, else grain_spacing for the default discs), else the node
  // spacing of the discretization.
  std::vector<GrainComponentDef> components;
  // Node spacings (issue #32; 0: the discretization's), set at load from the materials: of the
  // default discs (grain_material's) and of the first bodies (first_body_material's: their
  // surface sampling, and a deformable strip's grading towards its back face).
  NodeSpacing grain_spacing, first_body_spacing;
  std::string grain_material;       // a [[materials]] name
  std::string first_body_material;  // a [[materials]] name
  double roughness_rms = 0.3;       // RMS height of both surfaces (length)
  double hurst = 0.8;               // Hurst exponent of the self-affine surfaces
  // The first bodies' surfaces about their mean lines (geometry/surface_profile.h); unset:
  // self-affine of roughness_rms and hurst, seeds 2 seed + 1 (bottom) and 2 seed + 2 (top).
  std::optional<SurfaceProfileDef> bottom_profile, top_profile;
  // Axes of the first bodies (or of their back faces) driven otherwise than by the built-in
  // histories below (scenario/drive_def.h); unset axes keep them. A pressure on the top is
  // F = -p L, on the bottom +p L.
  DriveDef bottom_drive, top_drive;
  // Rigid: for the first bodies' mass; deformable: the strips' thickness, from the mean
  // surface to the back face (length). Either way, the top's mass in the servo estimate is
  // density L thickness.
  double first_body_thickness = 2.0;
  FirstBodyKind first_bodies = FirstBodyKind::rigid;
  NormalLoad normal_load = NormalLoad::gap;
  double gap = 0.0;  // gap loading: D, mean gap after compaction; 0: 90% of the packed height
  // Pressure loading: p, force per unit length (a stress times the unit depth of 2D).
  double pressure = 0.0;
  // Pressure loading: c of the servo's viscous force (force / velocity); 0: critical damping
  // of the top on the layer, 2 sqrt(k_eff m), see servo_damping_estimate().
  double servo_damping = 0.0;
  // Normal penalty stiffness k_n (traction / gap) between the grains and the first bodies,
  // for the servo estimate; filled in by build_model from the contact laws (0: unknown).
  double contact_stiffness = 0.0;
  double compaction_time = 1.0;  // time to close the gap, or to ramp the load up (time)
  double velocity = 1.0;         // V, sliding velocity (top +V/2, bottom -V/2)
  std::uint64_t seed = 1;        // every random choice (sizes, packing, roughness)
};

struct ShearCellInfo {
  double bottom_mean_y = 0.0, top_mean_y = 0.0;  // mean surface heights at t = 0
  double gap = 0.0;  // D (gap loading), or the packed height top - bottom at t = 0 (pressure)
  double packed_solid_fraction = 0.0;
  double normal_force = 0.0;   // pressure loading: the final load p L on the top (force)
  double servo_damping = 0.0;  // pressure loading: c used (force / velocity)
};

// A typical grain size (length): the number-weighted mean of the components' mid sizes
// (disc diameter, ellipse short axis). Sets the packing clearances, and is 1 for papers
// 001/002.
double shear_cell_grain_size(const ShearCellDef& def);

// The mixture add_shear_cell generates: the components, or one disc component of `diameter`;
// contour spacing = each component's own (its spacing.contour), else `contour_spacing`.
MixtureDef shear_cell_mixture(const ShearCellDef& def, double contour_spacing);

// Critical damping of the servo-loaded top (mass m) on the layer: c = 2 zeta sqrt(k_eff m)
// with zeta = 1, and k_eff the stiffness of the layer and of the contacts with the top, in
// series (they carry the same force):
//   k_layer    = E / (1 - nu^2) L / H  an elastic slab of the grains' plane-strain modulus
//                                      and thickness H (the packed height): an upper bound,
//                                      since a packing is softer than its solid;
//   k_contacts = k_n h L / d           the L/d grains that touch the top, each over at least
//                                      one node's tributary length h (d: grain size).
// Both overestimate the stiffness, so the estimate errs on the overdamped side (no bounce);
// too large a c would bias the mean force while the layer dilates (the bias is c times the
// drift velocity of the top), which the critical value keeps small.
double servo_damping_estimate(double young, double poisson, double height, double length,
                              double contact_stiffness, double node_spacing, double grain_size,
                              double mass);

// What add_shear_cell adds: the whole cell, or its first bodies alone (the grains generated
// and packed, which sets where the top goes, but not discretized): the first bodies of a cell
// are the same either way, at a fraction of the cost (the paper-size cell's 2000 grains took
// half of its build).
enum class ShearCellParts { whole, first_bodies };

// Adds the cell to `model` (which must be empty of periodic settings) and makes it periodic.
// Component materials are looked up by name in model.material_defs.
ShearCellInfo add_shear_cell(Model& model, const ShearCellDef& def, MaterialId grain_material,
                             MaterialId first_body_material, const DiscretizationParams& params,
                             ShearCellParts parts = ShearCellParts::whole);

}  // namespace sg
