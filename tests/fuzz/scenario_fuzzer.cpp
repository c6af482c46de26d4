// The scenario fuzzer (issue #15; docs/scenario.md, "Safety"): from every file in examples/,
// deterministic mutations (fuzz/mutations.h) are run through the real executable with a tiny
// run (`softgrain run --max-steps 2`, or `softgrain sweep --dry-run` for a campaign), one
// sandbox per case and a time bound per case. Every case must run (exit 0) or be refused
// (exit 1, with exactly one "softgrain: error:" line, the last one); never crash, hang or
// write anywhere but its run folder <output root>/<name>/, nor write a non-finite number in
// series.csv (fuzz/case_runner.h). A scenario that names CSV files (grains, contour, profile)
// also gets as many cases mutating each of them (fuzz/mutations.h, csv_mutations_of).
//
//   scenario_fuzzer SOFTGRAIN EXAMPLES_DIR
// Environment (CI uses the defaults):
//   SOFTGRAIN_FUZZ_CASES   cases per example file, sampled with the seed (default 10; "all":
//                          every mutation, about 3000 cases, one to two hours on 2 cores)
//   SOFTGRAIN_FUZZ_SEED    seed of the sampling (default 15)
//   SOFTGRAIN_FUZZ_TIMEOUT seconds allowed per case (default 60)
//   SOFTGRAIN_FUZZ_FULL    1: include the *-full examples (each case of those builds a
//                          paper-sized sample: 1 to several minutes per case)
// Prints the counts of cases run and refused; exits 1 if any case failed.
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <sstream>

#include "fuzz/case_runner.h"
#include "fuzz/mutations.h"

namespace fs = std::filesystem;
using namespace sg::fuzz;

namespace {

std::string env_or(const char* name, const std::string& fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::string(v) : fallback;
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The CSV files of `examples` that a scenario's text names ("grains.csv" in any key).
std::vector<fs::path> csv_files_named(const std::string& text, const fs::path& examples) {
  std::vector<fs::path> found;
  for (std::size_t at = text.find(".csv\""); at != std::string::npos;
       at = text.find(".csv\"", at + 1)) {
    const std::size_t open = text.rfind('"', at);
    if (open == std::string::npos) continue;
    const fs::path f = examples / text.substr(open + 1, at + 4 - open - 1);
    if (fs::is_regular_file(f) && std::find(found.begin(), found.end(), f) == found.end())
      found.push_back(f);
  }
  return found;
}

bool is_campaign(const std::string& text) {
  return text.find("\n[grid]") != std::string::npos || text.find("\n[[list]]") != std::string::npos;
}

struct Counts {
  int ran = 0, refused_with_key = 0, refused_other = 0, failed = 0;
  double slowest = 0.0;
  std::string slowest_case;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: scenario_fuzzer SOFTGRAIN EXAMPLES_DIR\n";
    return 2;
  }
  const fs::path executable = fs::absolute(argv[1]);
  const fs::path examples = fs::absolute(argv[2]);
  const std::string cases_setting = env_or("SOFTGRAIN_FUZZ_CASES", "10");
  const bool all = cases_setting == "all";
  const std::size_t per_file = all ? 0 : std::stoul(cases_setting);
  const auto seed = std::stoull(env_or("SOFTGRAIN_FUZZ_SEED", "15"));
  const double timeout = std::stod(env_or("SOFTGRAIN_FUZZ_TIMEOUT", "60"));
  const bool full = env_or("SOFTGRAIN_FUZZ_FULL", "0") == "1";

  std::string pattern = (fs::temp_directory_path() / "softgrain-fuzz-XXXXXX").string();
  if (!mkdtemp(pattern.data())) {
    std::cerr << "cannot create a temporary folder\n";
    return 2;
  }
  Sandbox sandbox{pattern};
  std::vector<fs::path> files;
  for (const fs::directory_entry& e : fs::directory_iterator(examples))
    if (e.path().extension() == ".toml" &&
        (full || e.path().stem().string().find("-full") == std::string::npos))
      files.push_back(e.path());
  std::sort(files.begin(), files.end());

  Counts counts;
  std::map<std::string, int> unnamed;  // refusals without file and key: message -> count
  std::mt19937_64 random(seed);
  for (const fs::path& file : files) {
    const std::string text = read_text(file);
    std::vector<Mutation> cases = mutations_of(text, sandbox.escape_target().string());
    const std::size_t total = cases.size();
    std::shuffle(cases.begin(), cases.end(), random);
    if (!all && cases.size() > per_file) cases.resize(per_file);
    const std::string name = file.filename().string();
    std::vector<std::string> args;
    std::vector<fs::path> companions, csv_files;
    if (is_campaign(text)) {
      args = {"sweep", name, "-o", "../root", "--dry-run", "--no-plot"};
      for (const fs::path& f : files)
        if (f != file) companions.push_back(f);  // the base scenario it names
    } else {
      args = {"run", name, "-o", "../root", "--max-steps", "2", "--threads", "1"};
      csv_files = csv_files_named(text, examples);  // the data files it points to
      companions = csv_files;
    }
    // The cases: mutations of the file itself, then of each CSV file it names (issue #26),
    // with the file itself intact; `target` is the file a case mutates.
    struct Case {
      Mutation mutation;
      std::string target;
      std::vector<fs::path> companions;
    };
    std::vector<Case> all_cases;
    for (Mutation& m : cases)
      all_cases.push_back({std::move(m), name, companions});
    for (const fs::path& csv : csv_files) {
      std::vector<Mutation> csv_cases = csv_mutations_of(read_text(csv));
      std::shuffle(csv_cases.begin(), csv_cases.end(), random);
      if (!all && csv_cases.size() > per_file) csv_cases.resize(per_file);
      std::vector<fs::path> others = {file};
      for (const fs::path& c : companions)
        if (c != csv) others.push_back(c);
      for (Mutation& m : csv_cases) {
        m.what = csv.filename().string() + ": " + m.what;
        all_cases.push_back({std::move(m), csv.filename().string(), others});
      }
    }
    int file_failed = 0;
    for (const Case& c : all_cases) {
      const Mutation& m = c.mutation;
      const CaseResult r =
          run_case(sandbox, executable, args, c.target, m.text, c.companions, timeout);
      if (r.seconds > counts.slowest) {
        counts.slowest = r.seconds;
        counts.slowest_case = name + " " + m.what;
      }
      switch (r.outcome) {
        case CaseResult::Outcome::ran:
          ++counts.ran;
          break;
        case CaseResult::Outcome::refused:
          if (r.names_file) {
            ++counts.refused_with_key;
          } else {
            ++counts.refused_other;
            ++unnamed[r.detail.substr(0, 200)];
          }
          break;
        case CaseResult::Outcome::failed:
          ++counts.failed;
          ++file_failed;
          std::cout << "FAILED " << name << " " << m.what << ": " << r.detail << "\n";
          break;
      }
    }
    std::cout << name << ": " << all_cases.size() << " cases (" << cases.size() << " of " << total
              << " mutations of the file, " << all_cases.size() - cases.size()
              << " of its CSV files), " << file_failed << " failed\n"
              << std::flush;
  }
  fs::remove_all(sandbox.root);
  for (const auto& [message, n] : unnamed)
    std::cout << "refused without naming the file and key (" << n << "x): " << message << "\n";
  std::cout << "scenario fuzzer (seed " << seed
            << "): " << counts.ran + counts.refused_with_key + counts.refused_other + counts.failed
            << " cases: " << counts.ran << " ran, " << counts.refused_with_key
            << " refused naming the file and key, " << counts.refused_other
            << " refused otherwise, " << counts.failed << " failed; slowest " << counts.slowest
            << " s (" << counts.slowest_case << ")\n";
  return counts.failed == 0 ? 0 : 1;
}
