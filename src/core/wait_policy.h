#pragma once
// How softgrain's OpenMP threads wait at the end of a parallel loop: they spin for a moment
// (libgomp's GOMP_SPINCOUNT) or go to sleep at once (OMP_WAIT_POLICY=PASSIVE).
//
// A step of a cell runs six parallel loops; a thread that sleeps between them must be woken
// for the next, which took about 40 us per loop on the 2-core machine of
// bench/results/debian12-2core. Measured there on bench/scenes/imex-cell.toml
// (reference_stiffness imex, 13 time units, 2 threads, interleaved runs): 5.5-5.8 s in the
// loop sleeping, 4.4 s spinning for 3,000 pauses (GOMP_SPINCOUNT=3000), 4.7-4.8 s for 1,000.
// Spinning threads take cores that other processes need, though: with two busy processes
// beside it, the same run shortened to 6 time units took 3.8 s sleeping and 7.2 s spinning
// 3,000 pauses, and two such runs side by side 4.1 s sleeping, 5.4-5.6 s spinning 3,000 pauses,
// 9.3 s with libgomp's default of 300,000 (OMP_WAIT_POLICY=ACTIVE, which never sleeps, was ten
// times slower on a shared machine: README, "Several runs on one machine").
//
// So a process spins only where it would not take a core from another: a `run` (the one
// subcommand whose loops are short and many; and `info`, which times steps to predict a run's
// cost), on more than one thread, when the processes ready to run on the machine at its start
// leave a core per thread. (The load average would not do: it remembers the previous run of a
// script for minutes.) Everything else sleeps, and so do the runs a `sweep` starts (they
// inherit its choice). A choice the user made in the environment (OMP_WAIT_POLICY or
// GOMP_SPINCOUNT) is kept. The wait policy changes the time a run takes, never its results.
#include <string>
#include <string_view>

namespace sg {

inline constexpr int kBarrierSpinCount = 3000;  // pauses (GOMP_SPINCOUNT) of a spinning wait
// Where the program leaves the reason of its choice for run.log (current_wait_policy).
inline constexpr const char* kWaitPolicyReasonVariable = "SOFTGRAIN_WAIT_POLICY_REASON";

struct WaitPolicyChoice {
  bool spin = false;   // spin kBarrierSpinCount pauses, else sleep at once
  std::string reason;  // why, for run.log
};

// `subcommand`: the first word of the command line; `threads`: the OpenMP threads the process
// will use; `cores`: the machine's online cores; `other_runnable`: the processes (threads)
// ready to run on it besides this one (/proc/loadavg).
WaitPolicyChoice choose_wait_policy(std::string_view subcommand, int threads, int cores,
                                    int other_runnable);

// The wait policy this process runs with, from its environment (for run.log and the first
// line of a run): "spin 3000" (GOMP_SPINCOUNT), "passive", "active" or "default".
std::string current_wait_policy();
// Why: the program's reason when it chose (kWaitPolicyReasonVariable), else "set in the
// environment".
std::string wait_policy_reason();

}  // namespace sg
