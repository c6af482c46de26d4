#include "fuzz/campaign_cases.h"

#include <stdexcept>

namespace sg::fuzz {

namespace {

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos)
    throw std::runtime_error("fuzz: '" + from + "' not found in examples/free-grains.toml");
  return text.replace(at, from.size(), to);
}

}  // namespace

CampaignSeed tiny_campaign(const std::string& free_grains_text) {
  CampaignSeed seed;
  seed.base_file = "tiny-base.toml";
  // 0.04 time units: a handful of steps, three snapshots and series rows.
  std::string base = replaced(free_grains_text, "duration = 6.0", "duration = 0.04");
  base = replaced(base, "field_period = 0.2", "field_period = 0.02");
  seed.base_text = base;
  seed.campaign_file = "tiny-campaign.toml";
  // A [grid] and a [[list]], analysis without plots: every key of a campaign file.
  seed.campaign_text = R"(name = "tiny"
scenario = "tiny-base.toml"
output = "out"
parallel = 2
threads = 1
analyze_options = ["--no-agglomerates", "--no-plots"]

[grid]
"materials.0.young" = [10.0, 20.0]

[[list]]
"materials.0.damping" = 0.005
)";
  return seed;
}

}  // namespace sg::fuzz
