#include "io/run_directory.h"

#include <array>
#include <fstream>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "core/file_name.h"
#include "io/atomic_file.h"

namespace sg {

namespace fs = std::filesystem;

namespace {

// The first line of every run.log (run/run_log.cpp).
constexpr std::string_view kRunLogHeader = "softgrain run log";

// What softgrain commands write into a run folder (run, generate, render, analyze, sweep).
bool written_by_softgrain(std::string name) {
  constexpr std::string_view kTemporary = ".tmp";  // io/atomic_file.h, after a kill
  if (name.size() > kTemporary.size() && name.ends_with(kTemporary))
    name.resize(name.size() - kTemporary.size());
  // scenario.toml, sweep.log, sweep.failed: a campaign run's folder (campaign/sweep.cpp).
  static constexpr std::array<std::string_view, 16> known = {
      "run.lock",   "run.log",       "series.csv",     "series.csv.partial",
      "fields.pvd", "contacts.pvd",  "checkpoint.bin", "fields",
      "grains",     "contacts",      "sample",         "render",
      "analysis",   "scenario.toml", "sweep.log",      "sweep.failed"};
  for (std::string_view k : known)
    if (name == k) return true;
  return false;
}

// The subfolders a softgrain command writes into (run, generate, render, analyze).
constexpr std::array<std::string_view, 6> kSubfolders = {"fields", "grains", "contacts",
                                                         "sample", "render", "analysis"};

void refuse_links_in(const fs::path& dir) {
  std::error_code error;
  for (fs::directory_iterator it(dir, error), end; !error && it != end; it.increment(error))
    SG_VERIFY(!it->is_symlink(error), "run folder entry '"
                                          << it->path().string()
                                          << "' is a symbolic link: refusing to write through it "
                                             "(remove the link, or choose another name or output "
                                             "folder)");
  SG_VERIFY(!error, "cannot list folder '" << dir.string() << "': " << error.message());
}

// The scenario file a run.log names ("scenario = <path>", in its header lines; run/run_log.cpp),
// empty if there is none.
fs::path scenario_of_run_log(const fs::path& dir) {
  std::ifstream in(dir / "run.log", std::ios::binary);
  std::string header, line;
  constexpr std::string_view kKey = "scenario = ";
  if (!in || !std::getline(in, header) || header != kRunLogHeader) return {};
  // The key lines before the first blank line (the version and commit come first).
  while (std::getline(in, line) && !line.empty())
    if (line.starts_with(kKey)) return line.substr(kKey.size());
  return {};
}

// Whether the run.log's `recorded` scenario is `scenario_file`. The run.log holds the path as
// given to that run, maybe relative to another working folder: when it does not lead to a
// file from here, the file names are compared.
bool same_scenario(const fs::path& recorded, const fs::path& scenario_file) {
  std::error_code error;
  if (!fs::exists(recorded, error)) return recorded.filename() == scenario_file.filename();
  return fs::equivalent(recorded, scenario_file, error) && !error;
}

// --overwrite: the run outputs of `dir` (written_by_softgrain, but a campaign's own files).
void remove_run_outputs(const fs::path& dir) {
  std::vector<fs::path> doomed;
  std::error_code error;
  for (fs::directory_iterator it(dir, error), end; !error && it != end; it.increment(error)) {
    std::string name = it->path().filename().string();
    if (name.starts_with("scenario.toml") || name.starts_with("sweep.") || name == kRunLockFile)
      continue;
    if (written_by_softgrain(name)) doomed.push_back(it->path());
  }
  SG_VERIFY(!error, "cannot list run folder '" << dir.string() << "': " << error.message());
  for (const fs::path& p : doomed) {
    fs::remove_all(p, error);  // a link is removed, never followed (checked before anyway)
    SG_VERIFY(!error, "--overwrite: cannot remove '" << p.string() << "': " << error.message());
  }
}

bool has_our_run_log(const fs::path& dir) {
  std::ifstream in(dir / "run.log", std::ios::binary);
  std::string first_line;
  return in && std::getline(in, first_line) && first_line == kRunLogHeader;
}

}  // namespace

bool is_softgrain_run_folder(const fs::path& dir) {
  if (has_our_run_log(dir)) return true;
  std::error_code error;
  for (fs::directory_iterator it(dir, error), end; !error && it != end; it.increment(error))
    if (!written_by_softgrain(it->path().filename().string())) return false;
  SG_VERIFY(!error, "cannot list run folder '" << dir.string() << "': " << error.message());
  return true;
}

void refuse_links_in_run_folder(const fs::path& dir) {
  std::error_code error;
  if (!fs::is_directory(fs::symlink_status(dir, error))) return;  // nothing there yet
  guard_run_folder(dir);  // and no link followed by any later write there (io/atomic_file.h)
  refuse_links_in(dir);
  for (std::string_view sub : kSubfolders)
    if (fs::is_directory(fs::symlink_status(dir / sub, error))) refuse_links_in(dir / sub);
}

fs::path make_run_subfolder(const fs::path& dir, const std::string& name) {
  const fs::path sub = dir / name;
  std::error_code error;
  const fs::file_status status = fs::symlink_status(sub, error);
  SG_VERIFY(!fs::is_symlink(status), "run folder entry '"
                                         << sub.string()
                                         << "' is a symbolic link: refusing to write through it "
                                            "(remove the link)");
  if (!fs::exists(status)) {
    fs::create_directory(sub, error);
    SG_VERIFY(!error, "cannot create folder '" << sub.string() << "': " << error.message());
  } else {
    SG_VERIFY(fs::is_directory(status),
              "run folder entry '" << sub.string() << "' exists and is not a folder");
  }
  return sub;
}

fs::path prepare_run_directory(const fs::path& output_root, const std::string& name, bool resume,
                               const fs::path& scenario_file, bool overwrite, RunFolderLock* lock) {
  require_plain_file_name(name, "run name (the run folder <output>/<name>/)");
  std::error_code error;
  // `-o` naming a plain file used to end in "unexpected error: filesystem error".
  if (fs::exists(fs::status(output_root, error)))
    SG_VERIFY(fs::is_directory(fs::status(output_root, error)),
              "output folder '" << output_root.string()
                                << "' exists and is not a folder (option -o or [output] "
                                   "directory)");
  const fs::path dir = output_root / name;
  SG_VERIFY(!fs::is_symlink(fs::symlink_status(dir, error)),
            "run folder '" << dir.string()
                           << "' is a symbolic link: refusing to write through it (remove the "
                              "link or choose another name)");
  if (fs::exists(dir, error)) {
    SG_VERIFY(fs::is_directory(dir, error),
              "run folder '" << dir.string() << "' exists and is not a folder");
    if (!resume)
      SG_VERIFY(is_softgrain_run_folder(dir),
                "run folder '" << dir.string()
                               << "' is not empty and is not a softgrain run folder (no run.log "
                                  "written by softgrain): refusing to write or delete there; "
                                  "choose another name or output folder, or empty it");
    refuse_links_in_run_folder(dir);
    if (!resume && !scenario_file.empty()) {
      const fs::path recorded = scenario_of_run_log(dir);
      SG_VERIFY(overwrite || recorded.empty() || same_scenario(recorded, scenario_file),
                "run folder '" << dir.string() << "' holds the run of another scenario ('"
                               << recorded.string() << "', its run.log), not '"
                               << scenario_file.string()
                               << "': refusing to mix their files; choose another name or output "
                                  "folder, or give --overwrite to remove the old run's outputs");
    }
  }
  if (lock) {
    fs::create_directories(dir, error);
    SG_VERIFY(!error, "cannot create run folder '" << dir.string() << "': " << error.message());
    lock->acquire(dir);
  }
  if (!resume && overwrite && fs::exists(dir, error)) remove_run_outputs(dir);
  if (!resume) fs::remove(dir / "checkpoint.bin", error);  // only ever this file, only in `dir`
  SG_VERIFY(!error, "cannot remove the old checkpoint '" << (dir / "checkpoint.bin").string()
                                                         << "': " << error.message());
  fs::create_directories(dir, error);
  SG_VERIFY(!error, "cannot create run folder '" << dir.string() << "': " << error.message());
  guard_run_folder(dir);  // every later write there: no link followed (io/atomic_file.h)
  return dir;
}

}  // namespace sg
