#pragma once
// The readers load_scenario (scenario.h) is made of, one per part of a scenario file, each
// filling its part of the ScenarioDef and failing with "<file>:<line>: key '<key>': ..."
// (toml_reader.h). Internal to the scenario stage; docs/scenario.md documents the keys.
#include <set>
#include <string>

#include "scenario/scenario.h"
#include "scenario/toml_reader.h"

namespace sg {

// [time], [output], [discretization], [physics]: the run's settings.
void read_time(const TomlReader& root, ScenarioDef& s);
void read_output(const TomlReader& root, ScenarioDef& s);
void read_discretization(const TomlReader& root, ScenarioDef& s);
void read_physics(const TomlReader& root, ScenarioDef& s);
// [contact] (after the laws: the cutoff must reach their cohesive reach) and [periodic].
void read_contact_settings(const TomlReader& root, ScenarioDef& s, double cohesive_reach);
void read_periodic(const TomlReader& root, ScenarioDef& s);

// [[materials]]: returns the set of material names (each defined once).
std::set<std::string> read_materials(const TomlReader& root, ScenarioDef& s);
// [[grains]] and [[walls]]: materials must exist, body names are unique.
void read_grains(const TomlReader& root, ScenarioDef& s,
                 const std::set<std::string>& material_names, std::set<std::string>& body_names);
void read_walls(const TomlReader& root, ScenarioDef& s, const std::set<std::string>& material_names,
                std::set<std::string>& body_names);

// [[strips]] (after [periodic] and [discretization]: their profiles are checked on the
// period), and a surface profile table ([strips.profile], [shear_cell.top_profile], ...)
// whose unset keys keep `defaults`.
void read_strips(const TomlReader& root, ScenarioDef& s,
                 const std::set<std::string>& material_names, std::set<std::string>& body_names);
SurfaceProfileDef read_profile(const TomlReader& t, const SurfaceProfileDef& defaults);
// Fails on `t` (naming the file and line) if `profile` is not valid over the period.
void check_profile(const TomlReader& t, const SurfaceProfileDef& profile, double x_begin,
                   double period);

// [shear_cell].
ShearCellDef read_shear_cell(const TomlReader& t, const std::set<std::string>& material_names);

// Node spacings (scenario_spacing.cpp, issue #32). The spacings table `t` sets with its keys
// node_spacing and interior_spacing on top of `inherited`: node_spacing alone makes the body
// uniform at it; interior_spacing below the contour spacing it applies to is refused.
NodeSpacing read_node_spacing(const TomlReader& t, const NodeSpacing& inherited);
// The resolved spacings of a material's bodies (empty for an unknown name).
NodeSpacing material_spacing(const ScenarioDef& s, const std::string& material);
// The shear cell's (`t`: its table): default discs and first bodies from their materials,
// each component from its own keys over its material's.
void resolve_shear_cell_spacing(const TomlReader& t, ScenarioDef& s);
// A [compaction_box] meshes with [discretization]: node spacings on its materials are refused.
void refuse_material_spacing_in_compaction_box(const TomlReader& root, const ScenarioDef& s);

}  // namespace sg
