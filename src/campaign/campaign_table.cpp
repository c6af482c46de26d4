#include "campaign/campaign_table.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>

#include "core/error.h"
#include "io/atomic_file.h"

namespace sg {
namespace {

// RFC 4180: a field with a comma, a quote or a line break is quoted, quotes doubled.
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s)
    out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string csv_number(double v) {
  if (!std::isfinite(v)) return "";
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, result.ptr);
}

}  // namespace

SummaryRecord read_summary_record(const std::filesystem::path& path) {
  std::ifstream in(path);
  SG_VERIFY(in, "cannot read '" << path.string() << "'");
  nlohmann::ordered_json doc;
  try {
    doc = nlohmann::ordered_json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    SG_THROW(path.string() << ": not valid JSON: " << e.what());
  }
  SG_VERIFY(doc.value("format", "") == "softgrain-analysis-summary",
            path.string() << ": not an analysis summary (format is not "
                             "\"softgrain-analysis-summary\")");
  SG_VERIFY(doc.value("version", 0) == 1, path.string()
                                              << ": summary version " << doc.value("version", 0)
                                              << " is not known to this softgrain (expected 1)");
  SummaryRecord out;
  for (const auto& [key, quantity] : doc.at("quantities").items()) {
    const auto& value = quantity.at("value");
    out.quantities.emplace_back(
        key, value.is_number() ? value.get<double>() : std::numeric_limits<double>::quiet_NaN());
  }
  // Summaries written before softgrain recorded itself have no "softgrain": left empty.
  if (const auto s = doc.find("softgrain"); s != doc.end() && s->is_object())
    out.software = s->value("version", "?") + " " + s->value("commit", "unknown");
  if (const auto u = doc.find("unmeasured"); u != doc.end() && u->is_array())
    for (const auto& item : *u)
      out.unmeasured += (out.unmeasured.empty() ? "" : "; ") + item.value("quantity", "?") + ": " +
                        item.value("reason", "no reason given");
  if (const auto w = doc.find("warnings"); w != doc.end() && w->is_array())
    for (const auto& item : *w)
      out.warnings += (out.warnings.empty() ? "" : "; ") + item.value("check", "?");
  return out;
}

std::vector<std::pair<std::string, double>> read_summary_quantities(
    const std::filesystem::path& path) {
  return read_summary_record(path).quantities;
}

double row_quantity(const CampaignRow& row, const std::string& key) {
  for (const auto& [k, v] : row.summary.quantities)
    if (k == key) return v;
  return std::numeric_limits<double>::quiet_NaN();
}

std::string campaign_table_csv(const std::vector<std::string>& parameter_keys,
                               const std::vector<CampaignRow>& rows) {
  std::vector<std::string> quantity_keys;
  std::set<std::string> seen;
  for (const CampaignRow& row : rows)
    for (const auto& [k, v] : row.summary.quantities)
      if (seen.insert(k).second) quantity_keys.push_back(k);

  std::string csv = "id";
  for (const std::string& k : parameter_keys)
    csv += "," + csv_field(k);
  csv += ",status,softgrain,unmeasured,warnings";
  for (const std::string& k : quantity_keys)
    csv += "," + csv_field(k);
  csv += "\n";
  for (const CampaignRow& row : rows) {
    SG_ASSERT(row.values.size() == parameter_keys.size(), "one value per parameter");
    csv += csv_field(row.id);
    for (const std::string& v : row.values)
      csv += "," + csv_field(v);
    csv += "," + row.status + "," + csv_field(row.summary.software) + "," +
           csv_field(row.summary.unmeasured) + "," + csv_field(row.summary.warnings);
    for (const std::string& k : quantity_keys)
      csv += "," + csv_number(row_quantity(row, k));
    csv += "\n";
  }
  return csv;
}

void write_campaign_table(const std::filesystem::path& path,
                          const std::vector<std::string>& parameter_keys,
                          const std::vector<CampaignRow>& rows) {
  write_file_atomically(path, campaign_table_csv(parameter_keys, rows));
}

}  // namespace sg
