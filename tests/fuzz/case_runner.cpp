#include "fuzz/case_runner.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <set>
#include <sstream>
#include <string_view>
#include <thread>

namespace sg::fuzz {

namespace fs = std::filesystem;

namespace {

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::set<std::string> entries(const fs::path& dir) {
  std::set<std::string> names;
  std::error_code error;
  for (fs::directory_iterator it(dir, error), end; !error && it != end; it.increment(error))
    names.insert(it->path().filename().string());
  return names;
}

bool plain_name(const std::string& n) {
  if (n.empty() || n == "." || n == "..") return false;
  for (char c : n)
    if (!std::isalnum(static_cast<unsigned char>(c)) &&
        std::string_view("._-+=,").find(c) == std::string_view::npos)
      return false;
  return true;
}

// Empty if the case wrote only inside <output root>/<one plain name>/ and its inputs.
std::string stray_writes(const Sandbox& s, const std::set<std::string>& inputs) {
  for (const std::string& n : entries(s.root))
    if (n != "case" && n != "logs") return "wrote '" + (s.root / n).string() + "'";
  for (const std::string& n : entries(s.case_dir()))
    if (n != "work" && n != "root") return "wrote '" + (s.case_dir() / n).string() + "'";
  for (const std::string& n : entries(s.work_dir()))
    if (!inputs.count(n)) return "wrote '" + (s.work_dir() / n).string() + "' (the cwd)";
  const std::set<std::string> runs = entries(s.output_root());
  if (runs.size() > 1)
    return "wrote " + std::to_string(runs.size()) + " folders in the output root";
  for (const std::string& n : runs) {
    if (!plain_name(n)) return "wrote the folder '" + n + "' in the output root";
    if (!fs::is_directory(s.output_root() / n) || fs::is_symlink(s.output_root() / n))
      return "wrote '" + n + "' in the output root, not a folder";
  }
  return "";
}

// Every file under the output root (run folders, a campaign's runs), in a stable order.
std::vector<fs::path> files_under(const fs::path& root) {
  std::vector<fs::path> files;
  std::error_code error;
  for (fs::recursive_directory_iterator it(root, error), end; !error && it != end;
       it.increment(error))
    if (it->is_regular_file(error) && !it->is_symlink(error)) files.push_back(it->path());
  std::sort(files.begin(), files.end());
  return files;
}

// The line without the contents of its JSON strings: a path such as the run folder's may
// hold "NaN" (a temporary folder's random name did, in CI), which is text, not a number.
std::string outside_json_strings(const std::string& line) {
  std::string kept;
  bool in_string = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (in_string && c == '\\') {
      ++i;  // an escaped character, '\"' included
      continue;
    }
    if (c == '"') in_string = !in_string;
    if (!in_string && c != '"') kept += c;
  }
  return kept;
}

// Empty if no CSV table (series.csv(.partial), grains/, analysis/, a campaign.csv) or JSON
// summary under the output root holds a non-finite number (a run that "ran" while writing
// NaN energies, as a density of 1e300 did, is a failure: issue #26).
std::string non_finite_output(const Sandbox& s) {
  for (const fs::path& file : files_under(s.output_root())) {
    const std::string name = file.filename().string();
    const bool csv = file.extension() == ".csv" || name == "series.csv.partial";
    const bool json = file.extension() == ".json";
    if (!csv && !json) continue;
    std::ifstream in(file, std::ios::binary);
    int line_number = 0;
    for (std::string line; std::getline(in, line);) {
      ++line_number;
      const std::string where = " in " + file.lexically_relative(s.output_root()).string() +
                                " line " + std::to_string(line_number);
      if (json) {
        const std::string numbers = outside_json_strings(line);
        for (const char* bad : {"NaN", "Infinity"})
          if (numbers.find(bad) != std::string::npos)
            return "wrote '" + std::string(bad) + "'" + where;
        continue;
      }
      // analysis/profiles.csv: a bin no grain visited has no mean (count 0, then nan) by
      // design (analysis/profiles.cpp); any other nan there is a failure.
      if (name == "profiles.csv" && line.find(",0,") != std::string::npos &&
          line.find(",0,") == line.find(','))
        continue;
      std::istringstream cells(line);
      for (std::string cell; std::getline(cells, cell, ',');)
        if (cell == "nan" || cell == "-nan" || cell == "inf" || cell == "-inf")
          return "wrote '" + cell + "'" + where;
    }
  }
  return "";
}

// Empty if every file that a .pvd under the output root lists exists (a resumed run whose
// snapshots were deleted listed them all the same: issue #26).
std::string missing_snapshots(const Sandbox& s) {
  for (const fs::path& index : files_under(s.output_root())) {
    if (index.extension() != ".pvd") continue;
    const std::string text = read_text(index);
    constexpr std::string_view kFile = "file=\"";
    for (auto at = text.find(kFile); at != std::string::npos; at = text.find(kFile, at + 1)) {
      const auto begin = at + kFile.size(), end = text.find('"', begin);
      const std::string file = text.substr(begin, end - begin);
      if (!fs::is_regular_file(index.parent_path() / file))
        return index.lexically_relative(s.output_root()).string() + " lists " + file +
               ", which is missing";
    }
  }
  return "";
}

struct Exit {
  bool timed_out = false;
  int status = 0;
};

Exit spawn_and_wait(const Sandbox& s, const fs::path& executable,
                    const std::vector<std::string>& args, double timeout_seconds) {
  const std::string out = (s.root / "logs" / "stdout").string();
  const std::string err = (s.root / "logs" / "stderr").string();
  const std::string cwd = s.work_dir().string();
  std::vector<std::string> argv_text = {executable.string()};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text)
    argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    setpgid(0, 0);
    const int o = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (o < 0 || e < 0 || chdir(cwd.c_str()) != 0) _exit(126);
    dup2(o, 1);
    dup2(e, 2);
    execv(argv[0], argv.data());
    _exit(127);
  }
  Exit result;
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_seconds);
  while (waitpid(pid, &result.status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      result.timed_out = true;
      kill(-pid, SIGKILL);
      waitpid(pid, &result.status, 0);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return result;
}

// The lines of `text` that are not empty.
std::vector<std::string> non_empty_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) {
    const auto cr = l.find_last_not_of("\r ");
    if (cr != std::string::npos) lines.push_back(l.substr(0, cr + 1));
  }
  return lines;
}

}  // namespace

CaseResult run_case(const Sandbox& s, const fs::path& executable,
                    const std::vector<std::string>& args, const std::string& file_name,
                    const std::string& text, const std::vector<fs::path>& companions,
                    double timeout_seconds, const std::function<void()>& prepare) {
  fs::remove_all(s.case_dir());
  fs::create_directories(s.work_dir());
  fs::create_directories(s.root / "logs");
  std::set<std::string> inputs = {file_name};
  for (const fs::path& c : companions) {
    fs::copy_file(c, s.work_dir() / c.filename(), fs::copy_options::overwrite_existing);
    inputs.insert(c.filename().string());
  }
  std::ofstream(s.work_dir() / file_name, std::ios::binary) << text;
  if (prepare) prepare();
  const auto start = std::chrono::steady_clock::now();
  const Exit exit = spawn_and_wait(s, executable, args, timeout_seconds);
  CaseResult r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::vector<std::string> err = non_empty_lines(read_text(s.root / "logs" / "stderr"));
  std::string last = err.empty() ? "(no output)" : err.back();
  const bool sweep = !args.empty() && args.front() == "sweep";
  std::string sweep_failure;  // a sweep's first "failed: <run>: why" line, if it has no error
  if (sweep) {
    int error_lines = 0;
    for (const std::string& l : err)
      if (l.rfind("softgrain: error: ", 0) == 0) ++error_lines;
    for (const std::string& l : non_empty_lines(read_text(s.root / "logs" / "stdout")))
      if (error_lines == 0 && sweep_failure.empty() && l.rfind("  failed: ", 0) == 0)
        sweep_failure = l;
    bool marked = false;
    for (const fs::path& f : files_under(s.output_root()))
      marked = marked || f.filename() == "sweep.failed";
    if (!marked) sweep_failure.clear();
  }
  if (exit.timed_out) {
    r.detail = "no end within " + std::to_string(timeout_seconds) + " s (hang?); last: " + last;
  } else if (WIFSIGNALED(exit.status)) {
    r.detail = "killed by signal " + std::to_string(WTERMSIG(exit.status)) + "; last: " + last;
  } else if (WEXITSTATUS(exit.status) == 0 || (sweep && WEXITSTATUS(exit.status) == 3)) {
    // A sweep's 3: its runs done, their analysis could not measure mu (not a shear cell).
    r.outcome = CaseResult::Outcome::ran;
  } else if (sweep && WEXITSTATUS(exit.status) == 1 && !sweep_failure.empty()) {
    // A sweep whose runs failed: it lists them ("  failed: <id>: why") and marks each
    // folder (sweep.failed); no "softgrain: error:" line.
    r.outcome = CaseResult::Outcome::refused;
    r.detail = sweep_failure;
    r.names_file = sweep_failure.find("key '") != std::string::npos;
  } else if (WEXITSTATUS(exit.status) != 1) {
    r.detail = "exit status " + std::to_string(WEXITSTATUS(exit.status)) + "; last: " + last;
  } else {
    int error_lines = 0;
    for (const std::string& l : err)
      if (l.rfind("softgrain: error: ", 0) == 0) ++error_lines;
    if (error_lines != 1 || last.rfind("softgrain: error: ", 0) != 0) {
      r.detail = "exit 1 with " + std::to_string(error_lines) +
                 " 'softgrain: error:' lines, last: " + last;
    } else {
      r.outcome = CaseResult::Outcome::refused;
      r.detail = last;
      // A CSV file's messages name its line and column instead of a key.
      r.names_file = last.find(file_name) != std::string::npos &&
                     (last.find("key '") != std::string::npos ||
                      last.find("TOML syntax error") != std::string::npos ||
                      last.find(": column ") != std::string::npos ||
                      last.find("header row") != std::string::npos ||
                      last.find("no data rows") != std::string::npos);
    }
  }
  if (r.outcome == CaseResult::Outcome::ran)
    for (const std::string& bad : {non_finite_output(s), missing_snapshots(s)})
      if (!bad.empty()) {
        r.outcome = CaseResult::Outcome::failed;
        r.detail = bad;
        break;
      }
  if (const std::string stray = stray_writes(s, inputs); !stray.empty()) {
    r.outcome = CaseResult::Outcome::failed;
    r.detail = stray + (r.detail.empty() ? "" : "; " + r.detail);
  }
  return r;
}

}  // namespace sg::fuzz
