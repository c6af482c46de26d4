#pragma once
// A scenario: everything one simulation needs, as checked definitions (STYLE.md habit 7:
// definition structs with defaults and units). The scenario layer turns TOML into these;
// the engine never sees a file. docs/scenario.md documents every key.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "contact/contact_system.h"
#include "geometry/surface_profile.h"
#include "material/material.h"
#include "meshfree/body_discretization.h"
#include "model/model.h"
#include "scenario/compaction_box.h"
#include "scenario/contact_law_def.h"
#include "scenario/drive_def.h"
#include "scenario/shear_cell.h"
#include "solver/default_integrator.h"
#include "solver/integrator_params.h"

#include <optional>

namespace sg {

// A grain is a disc, an ellipse or any simple closed contour (points inline or from a CSV).
enum class GrainShape { disc, ellipse, contour };

// [output] field_format: how the .vtu files of fields/ and contacts/ hold their arrays
// (io/vtu_document.h): zlib-compressed binary appended data (the default) or text.
enum class FieldFormat { binary, ascii };

struct GrainSpec {
  std::string name;
  GrainShape shape = GrainShape::disc;
  Vec2 center = Vec2::Zero();       // length
  double radius = 0.5;              // disc radius (length)
  Vec2 semi_axes = Vec2(0.5, 0.5);  // ellipse semi-axes (length)
  double angle = 0.0;               // ellipse orientation (rad)
  std::string material;
  Vec2 velocity = Vec2::Zero();   // initial velocity (length / time)
  double spin = 0.0;              // initial angular velocity (rad / time)
  Vec2 stretch = Vec2(1.0, 1.0);  // initial homogeneous stretch along x and y (1 = none)
  bool rigid = false;             // rigid grain (3 DOF) instead of a meshfree continuum
  // shape = contour: the vertices as given (absolute coordinates, CCW after loading), each
  // edge subdivided at the node spacing when the body is built.
  Polygon contour;
  DriveDef drive;  // rigid grains: driven axes (unset: free)
  // Its node spacings: its material's (resolved at load; 0: the [discretization] spacing).
  NodeSpacing spacing;
};

// A rigid wall: a rectangle, fixed or moving at an imposed velocity.
struct WallDef {
  std::string name;
  Vec2 lower_left = Vec2::Zero(), upper_right = Vec2::Zero();  // length
  std::string material;
  Vec2 velocity = Vec2::Zero();  // imposed velocity (length / time); rotation is held
  DriveDef drive;                // axes driven otherwise than by `velocity` (docs/scenario.md)
  NodeSpacing spacing;           // its material's contour spacing (0: [discretization]'s)
};

// A periodic strip (a first body) spanning the periodic cell [x_min, x_max) outside a
// [shear_cell]: its contact surface is a profile about the line y = surface_y, its flat back
// face at y = back_y (below the surface for a strip under the gap, above for one over it).
struct StripDef {
  std::string name;
  std::string material;
  bool rigid = true;
  double surface_y = 0.0, back_y = -1.0;  // length
  SurfaceProfileDef profile;
  DriveDef drive;       // unset axes: held (velocity 0)
  NodeSpacing spacing;  // its material's: surface spacing and back-face spacing (0: none)
  bool above() const { return back_y > surface_y; }  // the strip is above the gap
};

// [time] integrator as written.
enum class ScenarioIntegrator { automatic, explicit_integrator, imex };

struct ScenarioDef {
  std::filesystem::path source;  // the scenario file
  std::string name;              // run name: outputs go to <output_root>/<name>/
  // [time]
  double duration = 1.0;            // simulated time
  double time_step_safety = 0.8;    // fraction of the estimated critical step
  double fixed_time_step = 0.0;     // > 0: use this step instead of the estimate
  long reestimate_interval = 2000;  // accepted steps between critical-step estimates
  // |energy residual change| per step / energy scale; 0: off; < 0 (the key is absent): off,
  // except when the integrator is chosen imex by default (resolve_integrator).
  double step_tolerance = -1.0;
  double mass_scaling_step = 0.0;  // > 0: scale masses so that the step reaches this (time)
  // Run even when the step is absurdly small for the duration (run/run_length.h).
  bool allow_long_run = false;
  // integrator = "imex": the bulk damping of damped deformable bodies implicit in the velocity
  // (solver/implicit_viscosity.h), the step no longer limited by it; "explicit": every force
  // explicit; absent (automatic): whichever is faster, chosen on the built model
  // (resolve_integrator, solver/default_integrator.h).
  ScenarioIntegrator integrator = ScenarioIntegrator::automatic;
  // Relative residual of the objective model's iterative solves; 1e-5 moves mu and p_wb by
  // about 1e-5 from 1e-9 at a third fewer iterations (docs/scenario.md "Integrators").
  double imex_tolerance = 1e-5;
  // The objective model's preconditioner is rebuilt when a grain's stretch has moved by more
  // than this since it was built (solver/implicit_viscosity.h).
  double imex_refactor_threshold = 0.1;
  // Dense factors for the objective model's grains (solver/implicit_viscosity.h); false: sparse
  // factors for every body, the arithmetic of the versions before them.
  bool imex_dense_factors = true;
  // imex_objective: "split" (true) solves the objective model's damping with its reference
  // operator implicit and the rest explicit, at the price of the other models; "exact" (false)
  // by conjugate gradients (solver/implicit_viscosity.h, docs/scenario.md "Integrators").
  bool imex_objective_split = true;
  // [output]
  std::filesystem::path output_root = "out";
  double series_period = 0.0;  // time between rows of series.csv (0: 1/200 of duration)
  double field_period = 0.0;   // time between VTK snapshots (0: 1/20 of duration)
  FieldFormat field_format = FieldFormat::binary;
  // Time between checkpoints <run>/checkpoint.bin (io/checkpoint.h); 0: none; < 0 (the key
  // is absent): 1/10 of the duration, resolved at load.
  double checkpoint_period = -1.0;
  // [discretization]
  DiscretizationParams discretization;
  // [physics]
  Vec2 gravity = Vec2::Zero();
  std::vector<MaterialDef> materials;
  // Per materials[i]: the node spacings of the bodies of that material (issue #32), resolved
  // at load: its node_spacing / interior_spacing keys, else [discretization]'s.
  std::vector<NodeSpacing> material_spacing;
  std::vector<GrainSpec> grains;
  std::vector<WallDef> walls;
  std::vector<StripDef> strips;  // [[strips]] (requires [periodic])
  // [[contact_laws]] and [contact]: no laws, no contacts.
  std::vector<ContactLawDef> contact_laws;
  // 0: a quarter of the finest contour spacing (finest_contour_spacing), at least 1.5 times
  // the cohesive reach.
  double contact_cutoff = 0.0;
  double contact_skin = 0.0;  // 0: equal to the cutoff
  // [shear_cell]: the third-body cell builder (periodic over [0, length)).
  std::optional<ShearCellDef> shear_cell;
  // [compaction_box]: four rigid walls, the lid driven down (scenario/compaction_box.h).
  std::optional<CompactionBoxDef> compaction_box;
  // [periodic]: periodic in x over [x_min, x_max) when set.
  bool periodic_x = false;
  double x_min = 0.0, x_max = 0.0;
};

// The finest contour node spacing of a scenario: [discretization] node_spacing, or a finer one
// set for a material or a builder's grain component (issue #32). The default contact cutoff
// follows it.
double finest_contour_spacing(const ScenarioDef& scenario);

// The material-pair table of a scenario (requires contact laws).
MaterialPairTable contact_law_table(const ScenarioDef& scenario);
ContactSettings contact_settings(const ScenarioDef& scenario);
// The IMEX integrator with the scenario's [time] imex_* settings (whichever integrator it
// runs: `softgrain info` compares both).
IntegratorParams imex_integrator(const ScenarioDef& scenario);
// The integrator a run of `scenario` steps with on `model` (built, masses not yet scaled), for
// the stepper, the stable step and mass scaling, and its step check: as written in [time], or,
// when `integrator` is absent, imex where it is faster (solver/default_integrator.h; this
// estimates the model's frequencies once). `contact_stiffness`: the largest contact penalty.
IntegratorChoice resolve_integrator(const ScenarioDef& scenario, const Model& model,
                                    double contact_stiffness);

// Reads and validates a scenario file. Errors: "<file>:<line>: key '<key>': <expected>".
ScenarioDef load_scenario(const std::filesystem::path& file);
// The same from TOML text, named `file` in messages; relative file keys (grain CSV files)
// resolve against the folder of `file` (the Python module's Scenario.from_dict).
ScenarioDef load_scenario_text(std::string_view text, const std::filesystem::path& file);

// Builds the model (discretizes every grain, sets initial velocities and stretches). With
// ShearCellParts::first_bodies, a [shear_cell]'s grains are left out (shear_cell.h): the
// model of its first bodies at t = 0, for what depends on them alone (the gap of a campaign
// in the papers' coordinates, campaign/paper_coordinates.h).
Model build_model(const ScenarioDef& scenario, ShearCellParts parts = ShearCellParts::whole);

}  // namespace sg
