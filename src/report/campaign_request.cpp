// What a campaign asked of this run: the papers' coordinates a campaign that varies them
// requested (campaign/paper_coordinates.h writes <campaign folder>/paper_coordinates.csv), for
// summary.json's "campaign" beside the realized values. The report stage does not link the
// campaign stage, so the file's small format is read here: a header "id,<coordinate>,...",
// then one row per run, values as numbers.
#include <cmath>
#include <fstream>
#include <sstream>

#include "report/analyze_steps.h"

namespace sg::report {
namespace {

namespace fs = std::filesystem;

constexpr const char* kRequestedCoordinatesFile = "paper_coordinates.csv";

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  for (std::string f; std::getline(in, f, ',');)
    fields.push_back(f);
  return fields;
}

}  // namespace

void read_campaign_request(AnalyzeResult& r, const fs::path& run_dir) {
  // A campaign's run folder: <campaign folder>/runs/<id>/.
  const fs::path run = fs::absolute(run_dir).lexically_normal();
  const fs::path dir = run.filename().empty() ? run.parent_path() : run;
  if (dir.parent_path().filename() != "runs") return;
  const fs::path campaign = dir.parent_path().parent_path();
  const fs::path file = campaign / kRequestedCoordinatesFile;
  std::ifstream in(file);
  if (!in) return;
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = split_fields(line);
  while (std::getline(in, line)) {
    const std::vector<std::string> row = split_fields(line);
    if (row.empty() || row[0] != dir.filename().string()) continue;
    CampaignRequest request;
    request.campaign = campaign.filename().string();
    request.run = row[0];
    for (std::size_t k = 1; k < header.size(); ++k) {
      double value = kNan;
      try {
        value = k < row.size() ? std::stod(row[k]) : kNan;
      } catch (const std::exception&) {
      }
      request.requested.emplace_back(header[k], value);
    }
    r.campaign = std::move(request);
    return;
  }
  r.notes.push_back(file.string() + " has no row for run '" + dir.filename().string() +
                    "': no requested coordinates");
}

}  // namespace sg::report
