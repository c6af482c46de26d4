#include "campaign/slurm_script.h"

#include <sstream>

#include "core/exit_status.h"
#include "core/wait_policy.h"

namespace sg {
namespace {

// POSIX shell single quotes: safe for any text.
std::string shell_quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s)
    out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

std::string slurm_array_spec(const std::vector<std::size_t>& indices, int max_running) {
  std::ostringstream s;
  for (std::size_t i = 0; i < indices.size();) {
    std::size_t j = i;
    while (j + 1 < indices.size() && indices[j + 1] == indices[j] + 1)
      ++j;
    s << (i ? "," : "") << indices[i];
    if (j > i) s << "-" << indices[j];
    i = j + 1;
  }
  if (max_running > 0) s << "%" << max_running;
  return s.str();
}

std::string slurm_array_script(const CampaignDef& campaign, const SlurmSettings& settings,
                               const SlurmScriptSpec& spec) {
  std::string analyze_options;
  for (const std::string& o : campaign.analyze_options)
    analyze_options += " " + shell_quoted(o);
  const std::string run = "\"$SOFTGRAIN\" --threads \"$threads\" run \"$dir/scenario.toml\" -o " +
                          std::string(kCampaignRunsFolder);
  std::ostringstream s;
  s << "#!/bin/bash\n"
    << "# Slurm job array of campaign '" << campaign.name << "' (" << campaign.runs.size()
    << " runs): array task i runs line i+1 of runs.txt.\n"
    << "# Written by `softgrain sweep`, which submits it itself with --slurm (the unfinished runs\n"
    << "# only) and reports on it with --status (docs/campaigns.md). By hand, from this folder:\n"
    << "#   sbatch slurm-array.sh\n"
    << "# A task whose run is finished (analysis/summary.json) leaves it untouched; a run with a\n"
    << "# checkpoint continues from it (softgrain run --resume); any other starts from scratch.\n"
    << "#SBATCH --job-name=" << campaign.name << "\n"
    << "#SBATCH --array=" << spec.array << "\n"
    << "#SBATCH --cpus-per-task=" << spec.threads << "\n"
    << "#SBATCH --output=" << kSlurmOutputFolder << "/%A_%a.out\n"
    << "#SBATCH --open-mode=append\n"
    << "#SBATCH " << (settings.requeue ? "--requeue" : "--no-requeue") << "\n";
  if (!spec.time_limit.empty()) s << "#SBATCH --time=" << spec.time_limit << "\n";
  if (!settings.partition.empty()) s << "#SBATCH --partition=" << settings.partition << "\n";
  if (!settings.account.empty()) s << "#SBATCH --account=" << settings.account << "\n";
  if (!settings.qos.empty()) s << "#SBATCH --qos=" << settings.qos << "\n";
  if (!settings.memory.empty()) s << "#SBATCH --mem=" << settings.memory << "\n";
  for (const std::string& line : settings.extra)
    s << "#SBATCH " << line << "\n";
  s << "set -uo pipefail\n"
    << "cd \"${SLURM_SUBMIT_DIR:-.}\"\n"
    << "SOFTGRAIN=${SOFTGRAIN:-" << shell_quoted(spec.executable.string()) << "}\n"
    << "threads=${SLURM_CPUS_PER_TASK:-" << spec.threads << "}\n";
  // The job inherits the environment of the sweep that submitted it, where softgrain chose to
  // sleep at barriers (core/wait_policy.h): the run chooses again on its own cores. A choice
  // the user made (without softgrain's reason beside it) is kept.
  s << "if [ -n \"${" << kWaitPolicyReasonVariable << ":-}\" ]; then\n"
    << "  unset OMP_WAIT_POLICY GOMP_SPINCOUNT " << kWaitPolicyReasonVariable << "\n"
    << "fi\n"
    << "task=\"${SLURM_ARRAY_JOB_ID:-?}_${SLURM_ARRAY_TASK_ID}\"\n"
    << "id=$(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" runs.txt)\n"
    << "if [ -z \"$id\" ]; then\n"
    << "  echo \"task $task: runs.txt has no line $((SLURM_ARRAY_TASK_ID + 1))\" >&2\n"
    << "  exit 1\n"
    << "fi\n"
    << "dir=\"" << kCampaignRunsFolder << "/$id\"\n"
    << "log=\"$dir/sweep.log\"\n"
    << "if [ -f \"$dir/analysis/summary.json\" ]; then\n"
    << "  echo \"$id: finished earlier, left untouched\"\n"
    << "  exit 0\n"
    << "fi\n"
    << "note() {  # on a line of its own (softgrain's progress line ends with a carriage return)\n"
    << "  [ -s \"$log\" ] && echo >> \"$log\"\n"
    << "  echo \"softgrain sweep: Slurm task $task on $(hostname) (restart "
       "${SLURM_RESTART_COUNT:-0}): $*\" >> \"$log\"\n"
    << "}\n"
    << "# A killed task (cancel, time limit) dies with its commands and writes nothing here.\n"
    << "failed() {  # the command, its exit status (empty: it exited with 0)\n"
    << "  local why=\"wrote no analysis/summary.json\"\n"
    << "  if [ -n \"$2\" ]; then\n"
    << "    why=\"exited with status $2\"\n"
    << "    [ \"$2\" -gt 128 ] && why=\"was killed by signal $(($2 - 128))\"\n"
    << "  fi\n"
    << "  echo \"\\`softgrain $1\\` $why in Slurm task $task; log: $log\" > \"$dir/sweep.failed\"\n"
    << "  exit 1\n"
    << "}\n"
    << "rm -f \"$dir/sweep.failed\"\n"
    << "if [ ! -f \"$dir/series.csv\" ]; then\n"
    << "  if [ -f \"$dir/checkpoint.bin\" ] && [ -f \"$dir/series.csv.partial\" ]; then\n"
    << "    note \"resumes $id from its checkpoint\"\n"
    << "    " << run << " --resume >> \"$log\" 2>&1\n"
    << "    status=$?\n"
    << "    if [ $status -ne 0 ]; then\n"
    << "      # A resumed run that fails would fail the same way every time: the next attempt\n"
    << "      # starts from scratch (a killed one keeps its checkpoint).\n"
    << "      [ $status -le 128 ] && rm -f \"$dir/checkpoint.bin\"\n"
    << "      failed \"run --resume\" $status\n"
    << "    fi\n"
    << "  else\n"
    << "    # From scratch: nothing of an interrupted attempt may survive into this one.\n"
    << "    find \"$dir\" -mindepth 1 -maxdepth 1 ! -name scenario.toml -exec rm -rf {} +\n"
    << "    note \"starts $id\"\n"
    << "    " << run << " >> \"$log\" 2>&1 || failed run $?\n"
    << "  fi\n"
    << "else\n"
    << "  note \"analyses $id (its simulation finished)\"\n"
    << "fi\n"
    << "# Status " << kExitUnmeasured
    << ": analysed, but what the run asks for (mu) could not be "
       "measured: the run is\n# done without it (--status and --gather say why), not a failed "
       "task.\n"
    << "analyze_status=0\n"
    << "\"$SOFTGRAIN\" --threads \"$threads\" analyze \"$dir\"" << analyze_options
    << " >> \"$log\" 2>&1 || analyze_status=$?\n"
    << "[ $analyze_status -eq 0 ] || [ $analyze_status -eq " << kExitUnmeasured
    << " ] || failed analyze $analyze_status\n"
    << "[ -f \"$dir/analysis/summary.json\" ] || failed analyze \"\"\n";
  return s.str();
}

}  // namespace sg
