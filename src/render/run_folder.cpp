#include "render/run_folder.h"

#include <algorithm>
#include <cmath>
#include <fstream>

#include "core/error.h"
#include "geometry/packing.h"
#include "geometry/polygon.h"
#include "scenario/scenario.h"

namespace sg {
namespace {

std::vector<std::string> body_names(const ScenarioDef& s) {
  std::vector<std::string> names;
  for (const GrainSpec& g : s.grains)
    names.push_back(g.name);
  // The generated grains' names in the drawn order: the model holds them along x
  // (geometry/packing.h order_along_x), which only a packing would tell; nothing reads a
  // generated grain's place in this list, only those of the other bodies.
  if (s.shear_cell) {  // scenario/shear_cell.cpp: bottom, top, then the grains
    names.push_back("bottom");
    names.push_back("top");
    for (int i = 0; i < s.shear_cell->grains; ++i)
      names.push_back("grain_" + std::to_string(i));
  }
  if (s.compaction_box) {  // scenario/compaction_box.cpp: the four walls, then the grains
    for (const char* wall : {"bottom", "left", "right", "lid"})
      names.push_back(wall);
    for (int i = 0; i < s.compaction_box->grains; ++i)
      names.push_back("grain_" + std::to_string(i));
  }
  for (const WallDef& w : s.walls)
    names.push_back(w.name);
  for (const StripDef& strip : s.strips)  // scenario.cpp build_model: strips last
    names.push_back(strip.name);
  return names;
}

// E, alpha, c of the grains: the shear cell's grain material, or the one material all
// explicit deformable grains share.
void grain_material_parameters(const ScenarioDef& s, RunInfo& info) {
  std::string material;
  if (s.shear_cell) {
    material = s.shear_cell->grain_material;
  } else if (s.compaction_box) {
    material = s.compaction_box->grain_material;  // empty when every component names its own
  } else {
    for (const GrainSpec& g : s.grains) {
      if (g.rigid) continue;
      if (material.empty()) {
        material = g.material;
      } else if (g.material != material) {
        info.notes.push_back(
            "E, alpha, c: the deformable grains use several materials; pass "
            "--young, --alpha, --cohesion");
        return;
      }
    }
  }
  if (material.empty()) return;
  for (const MaterialDef& m : s.materials)
    if (m.name == material) {
      info.parameters.young_modulus = m.young;
      info.parameters.damping_alpha = m.damping;
    }
  for (const ContactLawDef& law : s.contact_laws)
    if (law.material_a == material && law.material_b == material)
      // c = sigma_c (papers 001/002 take sigma_c = tau_c = c); 0 for a law without cohesion.
      info.parameters.cohesion =
          law.params.kind == ContactLawKind::cohesive ? law.params.adhesion : 0.0;
}

// As scenario/shear_cell.cpp builds the cell: the load or the closing ends at the compaction
// time; deformable first bodies switch from closing to sliding over a ramp centred on it, of
// the strip's fundamental shear period 4 H / c_s (at most the compaction time); a drive given
// in the scenario ends its history at its last point.
double shear_cell_loading_end(const ScenarioDef& s) {
  const ShearCellDef& c = *s.shear_cell;
  double end = c.compaction_time;
  if (c.first_bodies == FirstBodyKind::deformable)
    for (const MaterialDef& m : s.materials)
      if (m.name == c.first_body_material && m.density > 0.0) {
        const double shear_speed = std::sqrt(m.young / (2.0 * (1.0 + m.poisson) * m.density));
        end += 0.5 * std::min(4.0 * c.first_body_thickness / shear_speed, c.compaction_time);
      }
  for (const DriveDef* drive : {&c.top_drive, &c.bottom_drive})
    for (const auto& axis : drive->axis)
      if (axis && !axis->history.times.empty()) end = std::max(end, axis->history.times.back());
  return end;
}

}  // namespace

RunInfo read_run_info(const std::filesystem::path& run_dir) {
  RunInfo info;
  std::ifstream log(run_dir / "run.log");
  if (!log) {
    info.note = "no run.log in '" + run_dir.string() + "'";
    return info;
  }
  std::string line;
  while (std::getline(log, line)) {
    const std::string key = "scenario = ";
    if (line.rfind(key, 0) == 0) {
      info.source = line.substr(key.size());
      break;
    }
  }
  if (info.source.empty()) {
    info.note = "run.log names no scenario";
    return info;
  }
  // A relative path was relative to where `softgrain run` started; try it as is, then
  // beside the output root (out/<name>/ next to the scenario).
  std::filesystem::path file = info.source;
  if (!std::filesystem::exists(file) && file.is_relative()) {
    const auto beside = run_dir.parent_path().parent_path() / file.filename();
    if (std::filesystem::exists(beside)) file = beside;
  }
  if (!std::filesystem::exists(file)) {
    info.note = "scenario '" + info.source.string() + "' (named in run.log) not found";
    return info;
  }
  ScenarioDef s;
  try {
    s = load_scenario(file);
  } catch (const Error& e) {
    info.note = "scenario '" + file.string() + "' could not be read: " + e.what();
    return info;
  }
  info.has_scenario = true;
  info.name = s.name;
  info.body_names = body_names(s);
  for (const WallDef& w : s.walls)
    info.walls.push_back(w.name);
  for (const StripDef& strip : s.strips)  // first bodies, not grains
    info.walls.push_back(strip.name);
  if (s.compaction_box) info.walls.insert(info.walls.end(), {"bottom", "left", "right", "lid"});
  info.shear_cell = s.shear_cell.has_value();
  if (const auto& box = s.compaction_box) {
    // As add_compaction_box builds it: inner floor at y = 0, walls one mean grain size thick
    // unless given, the grains regenerated from the mixture and seed (generate_grains is
    // deterministic; packing moves them rigidly, so their areas are those of the run at t = 0).
    CompactionBoxGeometry g;
    g.width = box->width;
    g.lid_thickness =
        box->wall_thickness > 0.0 ? box->wall_thickness : compaction_box_grain_size(*box);
    g.floor_y = 0.0;
    const double h = s.discretization.mesh.spacing;
    try {
      double area = 0.0;
      for (const GrainDef& grain :
           generate_grains(compaction_box_mixture(*box, h), box->grains, box->seed))
        area += signed_area(grain.contour);
      g.generated_grain_area = area;
    } catch (const Error& e) {  // a fallback only: the snapshots' areas are the measurement
      info.notes.push_back(std::string("compaction box: grains not regenerated: ") + e.what());
    }
    info.compaction_box = g;
  }
  if (s.shear_cell) {
    info.loading_end = shear_cell_loading_end(s);
    info.periodic = std::make_pair(0.0, s.shear_cell->length);
    info.parameters.length = s.shear_cell->length;
    info.parameters.velocity = s.shear_cell->velocity;
    // D is the scenario's under gap loading; an output under pressure loading or with
    // gap = 0 (90% of the packed height), measured by `analyze` from series.csv.
    if (s.shear_cell->normal_load == NormalLoad::gap && s.shear_cell->gap > 0.0)
      info.parameters.gap = s.shear_cell->gap;
    // p on the top under pressure loading, unless a drive of the scenario replaces it: the
    // sigma_n of E~ and c~ (analysis/pressure_loading.h).
    if (s.shear_cell->normal_load == NormalLoad::pressure && !s.shear_cell->top_drive.axis[1])
      info.parameters.pressure = s.shear_cell->pressure;
  } else if (s.periodic_x) {
    info.periodic = std::make_pair(s.x_min, s.x_max);
    info.parameters.length = s.x_max - s.x_min;
  }
  grain_material_parameters(s, info);
  return info;
}

}  // namespace sg
