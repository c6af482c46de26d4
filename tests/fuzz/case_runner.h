#pragma once
// Runs one fuzz case: the softgrain executable on a mutated file, in a sandbox folder, with
// a time bound; then checks what it wrote and what it printed.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace sg::fuzz {

struct CaseResult {
  enum class Outcome { ran, refused, failed } outcome = Outcome::failed;
  std::string detail;       // failed: why; refused: the error line
  bool names_file = false;  // refused: the error line names the scenario file and a key
  double seconds = 0.0;
};

struct Sandbox {
  std::filesystem::path root;  // fuzz root: holds case/ (rebuilt per case) and logs/
  std::filesystem::path case_dir() const { return root / "case"; }
  std::filesystem::path work_dir() const { return case_dir() / "work"; }  // the cwd
  std::filesystem::path output_root() const { return case_dir() / "root"; }
  std::filesystem::path escape_target() const { return root / "abs-escape"; }
};

// Writes `text` as work/<file_name> (plus `companions`, copied next to it), runs
// `executable args...` from work/ with stdout and stderr in logs/, kills it after
// `timeout_seconds`, and checks the outcome and the sandbox: besides the exit and the
// messages, a case that ran must have written no non-finite number in series.csv and no .pvd
// entry whose file is missing. `prepare`, if set, runs just before the executable (it may put
// a run folder in some state into the output root).
CaseResult run_case(const Sandbox& sandbox, const std::filesystem::path& executable,
                    const std::vector<std::string>& args, const std::string& file_name,
                    const std::string& text, const std::vector<std::filesystem::path>& companions,
                    double timeout_seconds, const std::function<void()>& prepare = {});

}  // namespace sg::fuzz
