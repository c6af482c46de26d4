#include "core/wait_policy.h"

#include <cstdlib>
#include <sstream>

namespace sg {

WaitPolicyChoice choose_wait_policy(std::string_view subcommand, int threads, int cores,
                                    int other_runnable) {
  std::ostringstream why;
  // `info` times steps to predict a run's cost: it waits as the run would.
  if (subcommand != "run" && subcommand != "info") {
    why << "'" << subcommand << "' and what it starts sleep at barriers (only a lone run spins)";
    return {false, why.str()};
  }
  if (threads <= 1) return {false, "one thread: no barrier to wait at"};
  const bool free_cores = other_runnable + threads <= cores;
  why << other_runnable << " other runnable processes, " << threads << " threads on " << cores
      << " cores: " << (free_cores ? "a free core per thread" : "cores shared with others");
  return {free_cores, why.str()};
}

std::string current_wait_policy() {
  // libgomp takes GOMP_SPINCOUNT over OMP_WAIT_POLICY when both are set.
  const char* spin = std::getenv("GOMP_SPINCOUNT");
  if (spin && *spin) return "spin " + std::string(spin);
  const char* policy = std::getenv("OMP_WAIT_POLICY");
  const std::string p = policy ? policy : "";
  if (p == "PASSIVE" || p == "passive") return "passive";
  if (p == "ACTIVE" || p == "active") return "active";
  return "default";
}

std::string wait_policy_reason() {
  const char* reason = std::getenv(kWaitPolicyReasonVariable);
  return reason && *reason ? reason : "set in the environment";
}

}  // namespace sg
