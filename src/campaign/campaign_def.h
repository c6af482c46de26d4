#pragma once
// A campaign: one base scenario and the parameters to vary, expanded into runs
// (docs/campaigns.md). The campaign file names parameters by their dotted path in the
// scenario TOML ("materials.0.young", array indices as numbers), so a campaign can vary any
// key without this code knowing the scenario's structure:
//
//   name = "mu-map"
//   scenario = "shear-cell-small.toml"      # relative to the campaign file
//   [grid]                                  # cartesian product, first key varies slowest
//   "materials.0.young" = [10.0, 100.0]
//   "contact_laws.0.cohesion" = [0.0, 0.5]
//   [[list]]                                # or explicit sets, one run each
//   "time.duration" = 2.0
//
// or by the papers' coordinates stiffness_tilde, cohesion_tilde, viscosity_tilde, which set
// the grain material's E, alpha and its contact laws' c (campaign/paper_coordinates.h).
//
// Each run's scenario is the base scenario's text with the varied values replaced in place
// (comments and layout kept, so `diff base.toml runs/<id>/scenario.toml` shows exactly what
// the campaign changed), `name` set to the run id and [output] directory to "runs", the
// campaign folder's runs/ (runs are started from the campaign folder).
#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "campaign/slurm_settings.h"

namespace sg {

struct CampaignParameter {
  std::string key;       // dotted path into the scenario: "materials.0.young"
  std::string label;     // shortest unique tail of the key, used in run ids: "young"
  std::size_t line = 0;  // where the campaign file names it
  // stiffness_tilde, cohesion_tilde or viscosity_tilde: not a scenario key, but the papers'
  // coordinate that sets physical keys (campaign/paper_coordinates.h).
  bool paper_coordinate = false;
};

struct CampaignRun {
  std::size_t index = 0;
  std::string id;  // stable and readable: "run-000_young=10_cohesion=0"
  // One per parameter, as TOML values ("10.0", "\"soft\"", "[0.0, -1.0]"); also the CSV cells.
  std::vector<std::string> values;
  // The scenario keys its paper coordinates set, with their values as TOML text.
  std::vector<std::pair<std::string, std::string>> derived;
  std::string scenario_text;  // the complete scenario file of this run
};

struct CampaignDef {
  std::filesystem::path file;      // the campaign file
  std::string name;                // default: the file's stem
  std::filesystem::path scenario;  // the base scenario (resolved against the campaign file)
  // Where campaign folders go; a relative `output` is relative to the campaign file.
  std::filesystem::path output_root = "out/campaigns";
  int parallel = 1;                          // runs at a time
  int threads = 0;                           // OpenMP threads per run; 0: cores / parallel
  std::vector<std::string> analyze_options;  // extra options of `softgrain analyze`
  std::size_t analyze_options_line = 0;      // where the campaign file gives them
  SlurmSettings slurm;                       // [slurm]: how `sweep --slurm` submits it
  std::vector<CampaignParameter> parameters;
  std::vector<CampaignRun> runs;

  std::filesystem::path folder() const { return output_root / name; }
};

// The run folders are <campaign folder>/runs/<id>/; the run's output root is "runs".
inline constexpr const char* kCampaignRunsFolder = "runs";

// Reads the campaign file and the base scenario and expands the runs. Every error names the
// campaign file, the line and the key:
//   mu.toml:7: key 'materials.2.young' in [grid]: the base scenario 'shear.toml' has no
//   'materials.2' ('materials' has 2 entries)
CampaignDef load_campaign(const std::filesystem::path& file);

}  // namespace sg
