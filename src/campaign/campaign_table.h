#pragma once
// The campaign's results in one table, <campaign>/campaign.csv: one row per run with its id,
// the varied parameters (one column each, named by their dotted key, values as written in
// TOML), its status (done, failed, pending) and every scalar of its analysis/summary.json
// (empty when null or not yet computed). Columns of the quantities are the union over the
// runs, in the order of the first summary that has them.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace sg {

struct CampaignRow {
  std::string id;
  std::vector<std::string> values;                         // one per parameter
  std::string status;                                      // "done", "failed", "pending"
  std::vector<std::pair<std::string, double>> quantities;  // NaN: null in summary.json
};

// The scalars of an analysis/summary.json (format "softgrain-analysis-summary", version 1),
// in file order; null values are NaN. Throws naming the file if it is not such a summary.
std::vector<std::pair<std::string, double>> read_summary_quantities(
    const std::filesystem::path& summary_json);

// The value of `key` in a row, NaN if absent or null.
double row_quantity(const CampaignRow& row, const std::string& key);

// campaign.csv as text; written atomically by write_campaign_table.
std::string campaign_table_csv(const std::vector<std::string>& parameter_keys,
                               const std::vector<CampaignRow>& rows);
void write_campaign_table(const std::filesystem::path& path,
                          const std::vector<std::string>& parameter_keys,
                          const std::vector<CampaignRow>& rows);

}  // namespace sg
