#include "campaign/paper_coordinates.h"

#include <toml++/toml.h>

#include <cmath>

#include "campaign/campaign_def.h"
#include "io/atomic_file.h"
#include "model/kinematics.h"
#include "scenario/scenario.h"

namespace sg {
namespace {

// The packed height of the base scenario's cell at t = 0: mean y of the top's surface minus
// the bottom's (rigid first bodies: their contour is the rough surface). NaN otherwise. The
// first bodies alone are built: the grains' discretization does not move them.
double packed_height(const std::filesystem::path& base_file, std::string& why) {
  const Model model = build_model(load_scenario(base_file), ShearCellParts::first_bodies);
  std::vector<Vec2> positions;
  compute_contour_positions(model, positions);
  double mean[2] = {NAN, NAN};
  const char* names[2] = {"top", "bottom"};
  for (int k = 0; k < 2; ++k)
    for (const Body& b : model.bodies) {
      if (b.name != names[k]) continue;
      if (b.kind != BodyKind::rigid) {
        why = "the first bodies are deformable (D is taken from rigid surfaces only)";
        return NAN;
      }
      double sum = 0.0;
      for (int p = b.contour_begin; p < b.contour_end; ++p)
        sum += positions[static_cast<std::size_t>(p)].y();
      mean[k] = sum / b.contour_count();
    }
  if (!std::isfinite(mean[0]) || !std::isfinite(mean[1])) why = "no first bodies 'top', 'bottom'";
  return mean[0] - mean[1];
}

}  // namespace

bool is_paper_coordinate(std::string_view key) {
  return key == "stiffness_tilde" || key == "cohesion_tilde" || key == "viscosity_tilde";
}

PaperFrame read_paper_frame(
    const toml::table& base, const std::filesystem::path& base_file,
    const std::vector<std::string>& used,
    const std::function<void(const std::string&, const std::string&)>& fail) {
  const auto uses = [&](const char* key) {
    for (const std::string& u : used)
      if (u == key) return true;
    return false;
  };
  const toml::table* cell = base["shear_cell"].as_table();
  const std::string first = used.front();
  if (!cell) fail(first, "needs a [shear_cell] in the base scenario (sigma_n, V, D)");
  PaperFrame f;
  const std::string load = (*cell)["normal_load"].value_or(std::string("gap"));
  f.velocity = (*cell)["velocity"].value_or(1.0);
  if (load == "pressure") f.pressure = (*cell)["pressure"].value_or(0.0);
  for (const char* key : {"stiffness_tilde", "cohesion_tilde"})
    if (uses(key) && !(f.pressure > 0.0))
      fail(key,
           "needs normal_load = \"pressure\" in the base scenario's [shear_cell] (sigma_n = p); "
           "under gap loading sigma_n is an output of the run");
  const std::string grain = (*cell)["grain_material"].value_or(std::string());
  const toml::array* materials = base["materials"].as_array();
  for (std::size_t m = 0; materials && m < materials->size(); ++m) {
    const toml::table* material = (*materials)[m].as_table();
    if (!material || (*material)["name"].value_or(std::string()) != grain) continue;
    const std::string prefix = "materials." + std::to_string(m) + ".";
    f.young_key = prefix + "young";
    f.damping_key = prefix + "damping";
    if (uses("viscosity_tilde") && !material->contains("damping"))
      fail("viscosity_tilde",
           "sets " + f.damping_key + ", which the base scenario must write (e.g. damping = 0.0)");
  }
  if (f.young_key.empty())
    fail(first, "the base scenario has no [[materials]] named '" + grain + "' (grain_material)");
  const toml::array* laws = base["contact_laws"].as_array();
  for (std::size_t l = 0; laws && l < laws->size(); ++l) {
    const toml::table* law = (*laws)[l].as_table();
    if (!law) continue;
    const toml::array* pair = (*law)["materials"].as_array();
    bool grains = false;
    for (std::size_t k = 0; pair && k < pair->size(); ++k)
      grains = grains || (*pair)[k].value_or(std::string()) == grain;
    if (grains && law->contains("cohesion"))
      f.cohesion_keys.push_back("contact_laws." + std::to_string(l) + ".cohesion");
  }
  if (uses("cohesion_tilde") && f.cohesion_keys.empty())
    fail("cohesion_tilde",
         "the base scenario has no contact law of '" + grain + "' that sets `cohesion`");
  if (uses("viscosity_tilde")) {
    if (load == "pressure") {
      std::string why;
      f.gap = packed_height(base_file, why);
      if (!std::isfinite(f.gap))
        fail("viscosity_tilde", "D unknown under pressure loading: " + why);
      f.gap_source = "the packed height of the base scenario's cell at t = 0";
    } else {
      f.gap = (*cell)["gap"].value_or(0.0);
      if (!(f.gap > 0.0))
        fail("viscosity_tilde", "needs the [shear_cell] gap D (gap = 0 lets the cell choose it)");
      f.gap_source = "the [shear_cell] gap";
    }
  }
  return f;
}

std::vector<std::pair<std::string, double>> paper_values(const PaperFrame& f, std::string_view key,
                                                         double value) {
  const double scale = std::pow(10.0, value);
  if (key == "stiffness_tilde") return {{f.young_key, f.pressure * scale}};
  if (key == "viscosity_tilde") return {{f.damping_key, scale * f.gap / f.velocity}};
  std::vector<std::pair<std::string, double>> out;
  for (const std::string& k : f.cohesion_keys)
    out.emplace_back(k, f.pressure * scale);
  return out;
}

std::string requested_coordinates_csv(const CampaignDef& campaign) {
  std::vector<std::size_t> coordinates;
  for (std::size_t p = 0; p < campaign.parameters.size(); ++p)
    if (campaign.parameters[p].paper_coordinate) coordinates.push_back(p);
  if (coordinates.empty()) return {};
  std::string text = "id";
  for (std::size_t p : coordinates)
    text += "," + campaign.parameters[p].key;
  text += "\n";
  for (const CampaignRun& run : campaign.runs) {
    text += run.id;
    for (std::size_t p : coordinates)
      text += "," + run.values[p];
    text += "\n";
  }
  return text;
}

void write_requested_coordinates(const CampaignDef& campaign,
                                 const std::filesystem::path& campaign_folder) {
  const std::string text = requested_coordinates_csv(campaign);
  if (!text.empty()) write_file_atomically(campaign_folder / kRequestedCoordinatesFile, text);
}

}  // namespace sg
