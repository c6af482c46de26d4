#pragma once
// The campaign's results in one table, <campaign>/campaign.csv: one row per run with its id,
// the varied parameters (one column each, named by their dotted key, values as written in
// TOML), its status (done, failed, pending), the softgrain version and commit that analysed
// it (column "softgrain"), what its analysis could not measure and why (column "unmeasured":
// "mu: <reason>" for a run done without mu, else empty), the steadiness checks its window
// failed (column "warnings", analysis/steadiness.h) and every scalar of its
// analysis/summary.json (empty when null or not yet computed). Columns of the quantities are the
// union over the runs, in the order of the first summary that has them.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace sg {

// What campaign.csv takes from a run's analysis/summary.json.
struct SummaryRecord {
  std::vector<std::pair<std::string, double>> quantities;  // NaN: null in summary.json
  std::string software;  // "0.1.0 <commit>": the softgrain that analysed it; "" if not said
  // What the run asks for and its analysis could not measure ("mu: <reason>", several joined
  // by "; "), from the summary's "unmeasured"; empty when everything was measured.
  std::string unmeasured;
  // The window's failed steadiness checks, from the summary's "warnings" (check names, e.g.
  // "mu_trend; stress_imbalance"); empty when none failed.
  std::string warnings;
};

struct CampaignRow {
  std::string id;
  std::vector<std::string> values;  // one per parameter
  std::string status;               // "done", "failed", "pending"
  SummaryRecord summary;            // empty unless done
};

// An analysis/summary.json (format "softgrain-analysis-summary", version 1): its scalars in
// file order (null values are NaN) and what else the table shows. Throws naming the file if
// it is not such a summary.
SummaryRecord read_summary_record(const std::filesystem::path& summary_json);
// Its scalars only.
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
