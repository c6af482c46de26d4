#include "io/run_directory.h"

#include <array>
#include <fstream>
#include <string_view>

#include "core/error.h"
#include "core/file_name.h"

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
  static constexpr std::array<std::string_view, 15> known = {
      "run.log",       "series.csv",   "series.csv.partial",
      "fields.pvd",    "contacts.pvd", "checkpoint.bin",
      "fields",        "grains",       "contacts",
      "sample",        "render",       "analysis",
      "scenario.toml", "sweep.log",    "sweep.failed"};
  for (std::string_view k : known)
    if (name == k) return true;
  return false;
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

fs::path prepare_run_directory(const fs::path& output_root, const std::string& name, bool resume) {
  require_plain_file_name(name, "run name (the run folder <output>/<name>/)");
  const fs::path dir = output_root / name;
  std::error_code error;
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
  }
  if (!resume) fs::remove(dir / "checkpoint.bin");  // only ever this file, only in `dir`
  fs::create_directories(dir, error);
  SG_VERIFY(!error, "cannot create run folder '" << dir.string() << "': " << error.message());
  return dir;
}

}  // namespace sg
