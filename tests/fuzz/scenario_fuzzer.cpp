// The scenario fuzzer (issue #15; docs/scenario.md, "Safety"): from every file in examples/,
// deterministic mutations (fuzz/mutations.h) are run through the real executable with a tiny
// run (`softgrain run --max-steps 2`, or `softgrain sweep --dry-run` for a campaign), one
// sandbox per case and a time bound per case. Every case must run (exit 0) or be refused
// (exit 1, with exactly one "softgrain: error:" line, the last one); never crash, hang or
// write anywhere but its run folder <output root>/<name>/, nor write a non-finite number in
// any CSV table or JSON summary under it (fuzz/case_runner.h). A scenario that names CSV files
// (grains, contour, profile) also gets cases mutating each of them (fuzz/mutations.h,
// csv_mutations_of; a scenario of its own, fuzz/csv_seed.h, names a contour and a profile
// file, which no example does); a run folder of free-grains.toml is then tried in odd states
// (fuzz_run_folders), and a tiny campaign over it (fuzz/campaign_cases.h) is swept for real,
// unchanged and mutated (fuzz_campaign_runs): runs, analyses and campaign.csv checked alike
// (a sweep may also end in 3, runs done without mu, or 1 listing its failed runs).
//
//   scenario_fuzzer SOFTGRAIN EXAMPLES_DIR
// Environment (CI uses the defaults):
//   SOFTGRAIN_FUZZ_CASES   cases per example file, sampled with the seed (default 10; "all":
//                          every mutation, about 3000 cases, one to two hours on 2 cores)
//   SOFTGRAIN_FUZZ_SEED    seed of the sampling (default 15)
//   SOFTGRAIN_FUZZ_TIMEOUT seconds allowed per case (default 60)
//   SOFTGRAIN_FUZZ_FULL    1: include the large examples, *-full and *-paper001* (each case
//                          of those builds a paper-sized sample or a layer of the papers'
//                          thickness: one to several minutes per case, ten under ASan)
// Prints the counts of cases run and refused; exits 1 if any case failed.
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <random>
#include <sstream>

#include "fuzz/campaign_cases.h"
#include "fuzz/case_runner.h"
#include "fuzz/csv_seed.h"
#include "fuzz/mutations.h"

namespace fs = std::filesystem;
using namespace sg::fuzz;

namespace {

// Sampled mutations of the tiny campaign run whole (each a sweep of two short runs and their
// analyses: about 1 s, 5 s under the sanitizers); SOFTGRAIN_FUZZ_CASES=all runs them all.
constexpr std::size_t kCampaignRunCases = 4;

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

// The examples whose model takes minutes to build (the papers' sizes): left out unless
// SOFTGRAIN_FUZZ_FULL=1.
bool is_large_example(const fs::path& file) {
  const std::string stem = file.stem().string();
  return stem.find("-full") != std::string::npos || stem.find("paper001") != std::string::npos;
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
  double slowest = 0.0, seconds = 0.0;  // the slowest case; all cases together
  std::string slowest_case;
};

void count(const CaseResult& r, const std::string& what, Counts& counts,
           std::map<std::string, int>& unnamed, int& failed) {
  counts.seconds += r.seconds;
  if (r.seconds > counts.slowest) {
    counts.slowest = r.seconds;
    counts.slowest_case = what;
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
      ++failed;
      std::cout << "FAILED " << what << ": " << r.detail << "\n";
      break;
  }
}

// Run folders in odd states (issue #26): a run of `example` stopped after its first checkpoint
// is the seed; each case copies it into the output root, changes one thing, and runs
// `softgrain run` there again. A damaged checkpoint (a byte flipped, the file truncated) must
// be refused or resume; a deleted snapshot must resume (and the .pvd then list only files
// present: case_runner's check); a linked fields/ and the folder of another scenario's run
// must be refused. `sampled`: how many flipped bytes (0: every 97th byte).
void fuzz_run_folders(const Sandbox& sandbox, const fs::path& executable, const fs::path& example,
                      std::size_t sampled, std::mt19937_64& random, double timeout, Counts& counts,
                      std::map<std::string, int>& unnamed) {
  const std::string name = example.filename().string();
  const std::string text = read_text(example);
  const fs::path seed = sandbox.root.string() + "-seed";
  std::string run_name;
  // The seed: longer and longer stops until the folder holds a checkpoint (free-grains.toml
  // writes its first between steps 200 and 1000: a try at 200 was a run for nothing).
  for (const char* steps : {"1000", "5000"}) {
    run_case(sandbox, executable, {"run", name, "-o", "../root", "--max-steps", steps}, name, text,
             {}, timeout);
    for (const auto& e : fs::directory_iterator(sandbox.output_root()))
      run_name = e.path().filename().string();
    if (!run_name.empty() && fs::exists(sandbox.output_root() / run_name / "checkpoint.bin")) break;
  }
  const fs::path seed_run = sandbox.output_root() / run_name;
  if (run_name.empty() || !fs::exists(seed_run / "checkpoint.bin")) {
    std::cout << "FAILED run folders: no checkpoint from " << name << "\n";
    ++counts.failed;
    return;
  }
  fs::remove_all(seed);
  fs::copy(seed_run, seed, fs::copy_options::recursive);
  const std::string checkpoint = read_text(seed / "checkpoint.bin");

  struct FolderCase {
    std::string what;
    bool resume = true;
    bool must_refuse = false;
    std::function<void(const fs::path& run)> change;
  };
  std::vector<FolderCase> cases;
  auto write = [](const fs::path& p, const std::string& bytes) {
    std::ofstream(p, std::ios::binary | std::ios::trunc) << bytes;
  };
  std::vector<std::size_t> positions;
  if (sampled == 0) {
    for (std::size_t at = 0; at < checkpoint.size(); at += 97)
      positions.push_back(at);
  } else {
    std::uniform_int_distribution<std::size_t> byte(0, checkpoint.size() - 1);
    for (std::size_t k = 0; k < sampled; ++k)
      positions.push_back(byte(random));
  }
  for (std::size_t at : positions)
    cases.push_back({"checkpoint byte " + std::to_string(at) + " flipped", true, false,
                     [=](const fs::path& run) {
                       std::string bytes = checkpoint;
                       bytes[at] = static_cast<char>(~bytes[at]);
                       write(run / "checkpoint.bin", bytes);
                     }});
  for (int c = 0; c < 4; ++c) {
    const std::size_t at = checkpoint.size() * static_cast<std::size_t>(c) / 4;
    cases.push_back(
        {"checkpoint truncated at byte " + std::to_string(at), true, false,
         [=](const fs::path& run) { write(run / "checkpoint.bin", checkpoint.substr(0, at)); }});
  }
  cases.push_back({"snapshot fields/000001.vtu deleted", true, false,
                   [](const fs::path& run) { fs::remove(run / "fields" / "000001.vtu"); }});
  cases.push_back({"series.csv.partial deleted", true, false,
                   [](const fs::path& run) { fs::remove(run / "series.csv.partial"); }});
  const fs::path outside = sandbox.escape_target();  // must stay unwritten (stray_writes)
  for (const char* sub : {"fields", "grains"})
    for (const bool resume : {false, true})
      cases.push_back(
          {std::string(sub) + "/ replaced by a link outside" + (resume ? " (resume)" : ""), resume,
           true, [=](const fs::path& run) {
             fs::remove_all(run / sub);
             fs::create_directory_symlink(outside, run / sub);
           }});
  cases.push_back({"run.log of another scenario", false, true, [](const fs::path& run) {
                     std::string log = read_text(run / "run.log");
                     const auto line = log.find("scenario = ");
                     log.replace(line, log.find('\n', line) - line, "scenario = another.toml");
                     std::ofstream(run / "run.log", std::ios::binary | std::ios::trunc) << log;
                   }});

  int failed = 0;
  const double started = counts.seconds;
  for (const FolderCase& c : cases) {
    std::vector<std::string> args = {"run",         name, "-o",        "../root",
                                     "--max-steps", "2",  "--threads", "1"};
    if (c.resume) args.push_back("--resume");
    const CaseResult r = run_case(sandbox, executable, args, name, text, {}, timeout, [&] {
      fs::create_directories(sandbox.output_root());
      fs::copy(seed, sandbox.output_root() / run_name, fs::copy_options::recursive);
      c.change(sandbox.output_root() / run_name);
    });
    if (c.must_refuse && r.outcome == CaseResult::Outcome::ran) {
      CaseResult wrong = r;
      wrong.outcome = CaseResult::Outcome::failed;
      wrong.detail = "ran, where it must be refused";
      count(wrong, "run folder: " + c.what, counts, unnamed, failed);
    } else {
      count(r, "run folder: " + c.what, counts, unnamed, failed);
    }
  }
  fs::remove_all(seed);
  std::cout << "run folders of " << name << ": " << cases.size() << " cases, " << failed
            << " failed, " << counts.seconds - started << " s\n"
            << std::flush;
}

// The tiny campaign (fuzz/campaign_cases.h) run for real: `sampled` of its mutations (0:
// all), each a whole `softgrain sweep` (runs, analyses, campaign.csv) checked like any case.
void fuzz_campaign_runs(const Sandbox& sandbox, const fs::path& executable,
                        const fs::path& free_grains, std::size_t sampled, const std::string& escape,
                        std::mt19937_64& random, double timeout, Counts& counts,
                        std::map<std::string, int>& unnamed) {
  const CampaignSeed seed = tiny_campaign(read_text(free_grains));
  // The base scenario waits outside the sandbox root (whose every entry is checked).
  const fs::path seeds = sandbox.root.string() + "-campaign";
  fs::create_directories(seeds);
  std::ofstream(seeds / seed.base_file, std::ios::binary) << seed.base_text;
  std::vector<Mutation> cases = mutations_of(seed.campaign_text, escape);
  const std::size_t total = cases.size();
  std::shuffle(cases.begin(), cases.end(), random);
  if (sampled > 0 && cases.size() > sampled) cases.resize(sampled);
  cases.insert(cases.begin(), Mutation{"unchanged", seed.campaign_text});  // must run
  int failed = 0;
  const double started = counts.seconds;
  for (const Mutation& m : cases) {
    const CaseResult r =
        run_case(sandbox, executable, {"sweep", seed.campaign_file, "-o", "../root", "--no-plot"},
                 seed.campaign_file, m.text, {seeds / seed.base_file}, timeout);
    if (m.what == "unchanged" && r.outcome != CaseResult::Outcome::ran) {
      CaseResult wrong = r;
      wrong.outcome = CaseResult::Outcome::failed;
      wrong.detail = "the unchanged campaign did not run: " + r.detail;
      count(wrong, "campaign run: unchanged", counts, unnamed, failed);
    } else {
      count(r, "campaign run: " + m.what, counts, unnamed, failed);
    }
  }
  fs::remove_all(seeds);
  std::cout << "campaign runs of " << seed.campaign_file << ": " << cases.size() << " cases ("
            << cases.size() - 1 << " of " << total << " mutations), " << failed << " failed, "
            << counts.seconds - started << " s\n"
            << std::flush;
}

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
    if (e.path().extension() == ".toml" && (full || !is_large_example(e.path())))
      files.push_back(e.path());
  std::sort(files.begin(), files.end());
  // The fuzzer's own scenario naming a contour and a profile file (fuzz/csv_seed.h), last;
  // it waits outside the sandbox root (whose every entry is checked).
  const fs::path csv_seed = sandbox.root.string() + "-csv-seed";
  fs::create_directories(csv_seed);
  for (const SeedFile& f : csv_seed_files())
    std::ofstream(csv_seed / f.name, std::ios::binary) << f.text;
  files.push_back(csv_seed / csv_seed_files().front().name);

  Counts counts;
  std::map<std::string, int> unnamed;  // refusals without file and key: message -> count
  std::mt19937_64 random(seed);
  for (const fs::path& file : files) {
    const std::string text = read_text(file);
    std::vector<Mutation> cases = mutations_of(text, sandbox.escape_target().string());
    const std::size_t total = cases.size();
    std::shuffle(cases.begin(), cases.end(), random);
    // A campaign example is only expanded (--dry-run): half its share, the other half going
    // to the tiny campaign run whole (fuzz_campaign_runs), within the same time.
    const std::size_t sampled = is_campaign(text) ? (per_file + 1) / 2 : per_file;
    if (!all && cases.size() > sampled) cases.resize(sampled);
    if (file.parent_path() == csv_seed) cases.clear();  // only its CSV files are inputs here
    const std::string name = file.filename().string();
    std::vector<std::string> args;
    std::vector<fs::path> companions, csv_files;
    if (is_campaign(text)) {
      // --no-plan: the planner builds and steps every run for a second (the models of the
      // run cases), which would add minutes to the fuzzer under the sanitizers.
      args = {"sweep", name, "-o", "../root", "--dry-run", "--no-plot", "--no-plan"};
      for (const fs::path& f : files)
        if (f != file) companions.push_back(f);  // the base scenario it names
    } else {
      args = {"run", name, "-o", "../root", "--max-steps", "2", "--threads", "1"};
      csv_files = csv_files_named(text, file.parent_path());  // the data files it points to
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
      // Half a file's share each: the grains, contour and profile readers share one CSV
      // table (scenario/csv_table.h), and three files at the full share would add a third
      // to the fuzzer's time.
      if (!all && csv_cases.size() > (per_file + 1) / 2) csv_cases.resize((per_file + 1) / 2);
      std::vector<fs::path> others = {file};
      for (const fs::path& c : companions)
        if (c != csv) others.push_back(c);
      for (Mutation& m : csv_cases) {
        m.what = csv.filename().string() + ": " + m.what;
        all_cases.push_back({std::move(m), csv.filename().string(), others});
      }
    }
    int file_failed = 0;
    const double started = counts.seconds;
    for (const Case& c : all_cases) {
      const Mutation& m = c.mutation;
      const CaseResult r =
          run_case(sandbox, executable, args, c.target, m.text, c.companions, timeout);
      count(r, name + " " + m.what, counts, unnamed, file_failed);
    }
    std::cout << name << ": " << all_cases.size() << " cases (" << cases.size() << " of " << total
              << " mutations of the file, " << all_cases.size() - cases.size()
              << " of its CSV files), " << file_failed << " failed, " << counts.seconds - started
              << " s\n"
              << std::flush;
  }
  // The smallest example's run folder in odd states (sampled like a file's mutations), and a
  // tiny campaign over it run whole.
  if (const fs::path free_grains = examples / "free-grains.toml"; fs::exists(free_grains)) {
    fuzz_run_folders(sandbox, executable, free_grains, all ? 0 : per_file, random, timeout, counts,
                     unnamed);
    fuzz_campaign_runs(sandbox, executable, free_grains, all ? 0 : kCampaignRunCases,
                       sandbox.escape_target().string(), random, timeout, counts, unnamed);
  }
  fs::remove_all(sandbox.root);
  fs::remove_all(csv_seed);
  for (const auto& [message, n] : unnamed)
    std::cout << "refused without naming the file and key (" << n << "x): " << message << "\n";
  std::cout << "scenario fuzzer (seed " << seed
            << "): " << counts.ran + counts.refused_with_key + counts.refused_other + counts.failed
            << " cases: " << counts.ran << " ran, " << counts.refused_with_key
            << " refused naming the file and key, " << counts.refused_other
            << " refused otherwise, " << counts.failed << " failed; " << counts.seconds
            << " s in cases; slowest " << counts.slowest << " s (" << counts.slowest_case << ")\n";
  return counts.failed == 0 ? 0 : 1;
}
