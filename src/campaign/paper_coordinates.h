#pragma once
// Campaigns in the papers' coordinates (paper 001 eqs 2-4): a campaign may vary
//   stiffness_tilde = E~ = log10(E / sigma_n),  cohesion_tilde = c~ = log10(c / sigma_n),
//   viscosity_tilde = alpha~ = log10(alpha V / D)
// directly, as keys of [grid] or [[list]]. Each run's scenario then gets the physical values
//   E = p 10^E~   (materials.<grain material>.young)
//   c = p 10^c~   (contact_laws.<each cohesive law of the grain material>.cohesion)
//   alpha = 10^alpha~ D / V   (materials.<grain material>.damping)
// with p the [shear_cell] pressure: sigma_n = p needs normal_load = "pressure" (under gap
// loading sigma_n is an output, so E~ and c~ cannot be imposed). D is the gap under gap
// loading, and under pressure loading the cell's packed height at t = 0 (the mean distance of
// the rough surfaces' mean lines of the base scenario's cell as built): an estimate, since the
// layer compacts under the load. D is an output of the run: `analyze` measures it, and
// campaign.csv reports the realized alpha~ (viscosity_tilde) next to the requested one
// (viscosity_tilde_requested).
//
// The requested coordinates of every run are also written to <campaign folder>/
// paper_coordinates.csv (columns: id, then each varied coordinate in the campaign's order; one
// row per run, values as written in the campaign file), where `softgrain analyze` of a run
// folder <campaign folder>/runs/<id>/ finds them for its summary.json ("campaign":
// report/campaign_request.cpp), however the run was started (locally, or by Slurm).
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <toml++/toml.h>

namespace sg {

struct CampaignDef;

inline constexpr const char* kRequestedCoordinatesFile = "paper_coordinates.csv";

bool is_paper_coordinate(std::string_view key);

// What the coordinates map to in a base scenario.
struct PaperFrame {
  double pressure = 0.0;  // sigma_n; 0 under gap loading
  double velocity = 0.0, gap = 0.0;
  std::string gap_source;  // how D was obtained
  std::string young_key, damping_key;
  std::vector<std::string> cohesion_keys;
};

// `used`: the coordinates the campaign varies. `fail(key, message)` reports an error and
// does not return.
PaperFrame read_paper_frame(
    const toml::table& base, const std::filesystem::path& base_file,
    const std::vector<std::string>& used,
    const std::function<void(const std::string&, const std::string&)>& fail);

// The scenario keys and their values (as TOML numbers) for one coordinate's value.
std::vector<std::pair<std::string, double>> paper_values(const PaperFrame& frame,
                                                         std::string_view key, double value);

// The text of paper_coordinates.csv; empty if the campaign varies no coordinate.
std::string requested_coordinates_csv(const CampaignDef& campaign);
// Writes it atomically into the campaign folder (nothing if the campaign varies none).
void write_requested_coordinates(const CampaignDef& campaign,
                                 const std::filesystem::path& campaign_folder);

}  // namespace sg
