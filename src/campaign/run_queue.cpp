#include "campaign/run_queue.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <map>
#include <thread>

#include "core/error.h"

namespace sg {
namespace {

volatile std::sig_atomic_t interrupted = 0;

extern "C" void on_interrupt(int) {
  interrupted = 1;
}

// Catches SIGINT and SIGTERM for the lifetime of the queue, then restores what was there.
class InterruptGuard {
 public:
  InterruptGuard() {
    interrupted = 0;
    struct sigaction action {};
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &old_int_);
    sigaction(SIGTERM, &action, &old_term_);
  }
  ~InterruptGuard() {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
  }
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

 private:
  struct sigaction old_int_ {
  }, old_term_{};
};

void write_message(int fd, const char* message) {
  const ssize_t ignored = ::write(fd, message, std::strlen(message));
  (void)ignored;
}

pid_t spawn(const ProcessJob& job, std::size_t step) {
  // Everything the child needs is prepared before fork(): between fork() and exec() only
  // async-signal-safe calls are allowed (the parent may have other threads).
  const std::vector<std::string>& args = job.steps.at(step);
  SG_ASSERT(!args.empty(), "a job step needs a command");
  std::vector<char*> argv;
  for (const std::string& a : args)
    argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const std::string directory = job.working_directory.string();
  const std::string log = job.log.string();
  const int log_flags = O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC | (step == 0 ? O_TRUNC : 0);

  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  SG_VERIFY(pid >= 0, "cannot start '" << args[0] << "': " << std::strerror(errno));
  if (pid == 0) {
    // The child dies with the caller, even when the caller alone is killed (SIGKILL leaves no
    // chance to terminate it): an orphaned run would go on writing its folder while a
    // restarted sweep starts the same run there (issue #26). The signal survives exec; the
    // test after it catches a caller that died before it was set.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(125);
    const int out = ::open(log.c_str(), log_flags, 0644);
    if (out < 0) {
      write_message(2, "softgrain sweep: cannot open the run's log file\n");
      ::_exit(126);
    }
    const int in = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
    if (in >= 0) ::dup2(in, 0);
    ::dup2(out, 1);
    ::dup2(out, 2);
    if (::chdir(directory.c_str()) != 0) {
      write_message(2, "softgrain sweep: cannot enter the campaign folder\n");
      ::_exit(126);
    }
    ::execv(argv[0], argv.data());
    write_message(2, "softgrain sweep: cannot execute the command\n");
    ::_exit(127);
  }
  return pid;
}

struct Running {
  std::size_t job = 0, step = 0;
  std::chrono::steady_clock::time_point start;
};

void terminate_all(std::map<pid_t, Running>& running) {
  for (const auto& [pid, r] : running)
    ::kill(pid, SIGTERM);
  for (const auto& [pid, r] : running) {
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
  }
  running.clear();
}

}  // namespace

bool run_process_queue(const std::vector<ProcessJob>& jobs, int parallel,
                       const QueueEvents& events) {
  SG_VERIFY(parallel >= 1, "parallel runs: expected at least 1, got " << parallel);
  const InterruptGuard guard;
  std::map<pid_t, Running> running;
  std::size_t next = 0;
  for (;;) {
    if (interrupted) {
      terminate_all(running);
      return false;
    }
    while (running.size() < static_cast<std::size_t>(parallel) && next < jobs.size()) {
      running[spawn(jobs[next], 0)] = {next, 0, std::chrono::steady_clock::now()};
      if (events.started) events.started(next, running.size());
      ++next;
    }
    if (running.empty()) return true;

    // Poll our own children only (waitpid(-1) could reap a process someone else in this
    // program is waiting for); a blocking wait would also miss a signal arriving just
    // before it. 20 ms is nothing next to a run.
    bool any = false;
    for (auto it = running.begin(); it != running.end();) {
      int status = 0;
      const pid_t done = ::waitpid(it->first, &status, WNOHANG);
      if (done == 0 || (done < 0 && errno == EINTR)) {
        ++it;
        continue;
      }
      SG_VERIFY(done == it->first,
                "waiting for process " << it->first << ": " << std::strerror(errno));
      any = true;
      const Running r = it->second;
      it = running.erase(it);
      const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
      if (ok && r.step + 1 < jobs[r.job].steps.size()) {
        running[spawn(jobs[r.job], r.step + 1)] = {r.job, r.step + 1, r.start};
        continue;
      }
      JobOutcome outcome;
      outcome.job = r.job;
      outcome.success = ok;
      outcome.step = r.step;
      outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      outcome.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
      outcome.seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - r.start).count();
      if (events.finished) events.finished(outcome, running.size());
    }
    if (!any) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

}  // namespace sg
