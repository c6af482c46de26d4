#pragma once
// The campaign the fuzzer runs for real (issue #26, item 2): the example campaigns are only
// expanded (`sweep --dry-run`: their runs take minutes each), so their mutations never reach
// the sweep's life: run folders made and run, analysed, gathered into campaign.csv. This one
// sweeps two runs of a tiny scene (examples/free-grains.toml cut to a few steps, no plots),
// each run and its analysis a second or so; its mutations (fuzz/mutations.h) run whole.
#include <string>

namespace sg::fuzz {

struct CampaignSeed {
  std::string base_file, base_text;          // the base scenario the campaign names
  std::string campaign_file, campaign_text;  // the campaign file (what the cases mutate)
};

// From the text of examples/free-grains.toml.
CampaignSeed tiny_campaign(const std::string& free_grains_text);

}  // namespace sg::fuzz
