#include "campaign/slurm_commands.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <sstream>

#include "core/error.h"

namespace sg {
namespace {

std::string trimmed(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r\n");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r\n") - a + 1);
}

std::vector<std::string> split(const std::string& s, char separator) {
  std::vector<std::string> parts(1);
  for (char c : s)
    if (c == separator)
      parts.emplace_back();
    else
      parts.back() += c;
  return parts;
}

bool is_number(const std::string& s) {
  if (s.empty()) return false;
  for (char c : s)
    if (c < '0' || c > '9') return false;
  return true;
}

// The first line of a command's complaint, for an error message.
std::string first_line(const CommandResult& r) {
  const std::string text = trimmed(r.err.empty() ? r.out : r.err);
  return text.substr(0, text.find('\n'));
}

}  // namespace

CommandResult run_command(const std::vector<std::string>& args,
                          const std::filesystem::path& working_directory) {
  SG_ASSERT(!args.empty(), "a command needs a program");
  // Everything the child needs is prepared before fork(): only async-signal-safe calls
  // between fork() and exec().
  std::vector<char*> argv;
  for (const std::string& a : args)
    argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const std::string directory = working_directory.string();
  int out_pipe[2], err_pipe[2];
  SG_VERIFY(::pipe2(out_pipe, O_CLOEXEC) == 0 && ::pipe2(err_pipe, O_CLOEXEC) == 0,
            "cannot run '" << args[0] << "': " << std::strerror(errno));
  // The child reports a failed exec() through this pipe (closed by a successful exec).
  int exec_pipe[2];
  SG_VERIFY(::pipe2(exec_pipe, O_CLOEXEC) == 0,
            "cannot run '" << args[0] << "': " << std::strerror(errno));
  const pid_t pid = ::fork();
  SG_VERIFY(pid >= 0, "cannot run '" << args[0] << "': " << std::strerror(errno));
  if (pid == 0) {
    const int in = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
    if (in >= 0) ::dup2(in, 0);
    ::dup2(out_pipe[1], 1);
    ::dup2(err_pipe[1], 2);
    if (!directory.empty() && ::chdir(directory.c_str()) != 0) {
      const int e = errno;
      const ssize_t ignored = ::write(exec_pipe[1], &e, sizeof e);
      (void)ignored;
      ::_exit(127);
    }
    ::execvp(argv[0], argv.data());
    const int e = errno;
    const ssize_t ignored = ::write(exec_pipe[1], &e, sizeof e);
    (void)ignored;
    ::_exit(127);
  }
  ::close(out_pipe[1]);
  ::close(err_pipe[1]);
  ::close(exec_pipe[1]);

  CommandResult result;
  std::array<pollfd, 2> fds = {pollfd{out_pipe[0], POLLIN, 0}, pollfd{err_pipe[0], POLLIN, 0}};
  std::array<std::string*, 2> into = {&result.out, &result.err};
  int open_fds = 2;
  char buffer[4096];
  while (open_fds > 0) {
    if (::poll(fds.data(), fds.size(), -1) < 0) {
      if (errno == EINTR) continue;
      break;
    }
    for (std::size_t i = 0; i < fds.size(); ++i) {
      if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      const ssize_t n = ::read(fds[i].fd, buffer, sizeof buffer);
      if (n > 0) {
        into[i]->append(buffer, static_cast<std::size_t>(n));
      } else if (n == 0 || errno != EINTR) {
        ::close(fds[i].fd);
        fds[i].fd = -1;
        --open_fds;
      }
    }
  }
  int exec_errno = 0;
  const bool exec_failed = ::read(exec_pipe[0], &exec_errno, sizeof exec_errno) > 0;
  ::close(exec_pipe[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  result.started = !exec_failed;
  if (exec_failed) result.err = args[0] + ": " + std::strerror(exec_errno);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::optional<std::string> parse_sbatch_job_id(const std::string& output) {
  // --parsable: "<id>" or "<id>;<cluster>" on the last line (site filters may print above).
  std::istringstream in(output);
  std::string last;
  for (std::string line; std::getline(in, line);)
    if (!trimmed(line).empty()) last = trimmed(line);
  const std::string id = last.substr(0, last.find(';'));
  if (!is_number(id)) return std::nullopt;
  return id;
}

std::string sbatch_submit(const std::filesystem::path& working_directory,
                          const std::vector<std::string>& arguments,
                          const std::filesystem::path& script) {
  std::vector<std::string> args = {"sbatch", "--parsable"};
  args.insert(args.end(), arguments.begin(), arguments.end());
  args.push_back(script.string());
  const CommandResult r = run_command(args, working_directory);
  SG_VERIFY(r.started, "cannot run sbatch (" << r.err << "): is Slurm installed here?");
  SG_VERIFY(r.exit_code == 0,
            "sbatch failed (exit status " << r.exit_code << "): " << trimmed(r.err + r.out));
  const std::optional<std::string> id = parse_sbatch_job_id(r.out);
  SG_VERIFY(id, "sbatch printed no job id: '" << trimmed(r.out) << "'");
  return *id;
}

double parse_squeue_elapsed(const std::string& text) {
  long days = 0;
  std::string rest = trimmed(text);
  if (const auto dash = rest.find('-'); dash != std::string::npos) {
    if (!is_number(rest.substr(0, dash))) return 0;
    days = std::stol(rest.substr(0, dash));
    rest = rest.substr(dash + 1);
  }
  double seconds = 0;
  for (const std::string& part : split(rest, ':')) {
    if (!is_number(part)) return 0;
    seconds = seconds * 60 + std::stod(part);
  }
  return seconds + 86400.0 * static_cast<double>(days);
}

std::map<std::size_t, SlurmTask> parse_squeue_tasks(const std::string& output,
                                                    const std::string& job_id) {
  std::map<std::size_t, SlurmTask> tasks;
  std::istringstream in(output);
  for (std::string line; std::getline(in, line);) {
    const std::vector<std::string> f = split(trimmed(line), '|');
    if (f.size() < 6 || f[0] != job_id || !is_number(f[1])) continue;
    SlurmTask t;
    t.state = f[2];
    t.elapsed = parse_squeue_elapsed(f[3]);
    t.cpus = is_number(f[4]) ? std::stoi(f[4]) : 0;
    t.reason = f[5];
    tasks[std::stoul(f[1])] = t;
  }
  return tasks;
}

std::map<std::size_t, SlurmTask> parse_sacct_tasks(const std::string& output,
                                                   const std::string& job_id) {
  std::map<std::size_t, SlurmTask> tasks;
  std::istringstream in(output);
  for (std::string line; std::getline(in, line);) {
    const std::vector<std::string> f = split(trimmed(line), '|');
    if (f.size() < 4) continue;
    const std::string prefix = job_id + "_";
    if (f[0].rfind(prefix, 0) != 0 || !is_number(f[0].substr(prefix.size()))) continue;
    SlurmTask t;
    t.state = f[1].substr(0, f[1].find(' '));  // "CANCELLED by 0"
    t.elapsed = is_number(f[2]) ? std::stod(f[2]) : 0.0;
    t.cpus = is_number(f[3]) ? std::stoi(f[3]) : 0;
    t.reason = "None";
    tasks[std::stoul(f[0].substr(prefix.size()))] = t;
  }
  return tasks;
}

std::optional<std::map<std::size_t, SlurmTask>> query_array_tasks(const std::string& job_id) {
  const CommandResult q =
      run_command({"squeue", "-h", "-t", "all", "-r", "-j", job_id, "-o", "%F|%K|%T|%M|%C|%r"});
  SG_VERIFY(q.started, "cannot run squeue (" << q.err << "): is Slurm installed here?");
  // squeue exits with 1 and "Invalid job id specified" for a job the controller forgot.
  if (q.exit_code == 0) {
    auto tasks = parse_squeue_tasks(q.out, job_id);
    if (!tasks.empty()) return tasks;
  } else if (q.err.find("Invalid job id") == std::string::npos) {
    SG_THROW("squeue failed (exit status " << q.exit_code << "): " << first_line(q));
  }
  const CommandResult a = run_command(
      {"sacct", "-n", "-P", "-X", "-j", job_id, "-o", "JobID,State,ElapsedRaw,AllocCPUS"});
  if (a.started && a.exit_code == 0) {
    auto tasks = parse_sacct_tasks(a.out, job_id);
    if (!tasks.empty()) return tasks;
  }
  return std::nullopt;
}

}  // namespace sg
