#!/usr/bin/env bash
# Run by with_slurm.sh: the test cluster runs a batch job (a 2-task array, one CPU each) to
# completion, and scontrol reports it so. Fails with what it saw otherwise.
set -euo pipefail
work=$(mktemp -d "${TMPDIR:-/tmp}/softgrain-slurm-check.XXXXXX")
trap 'rm -rf "$work"' EXIT
cd "$work"
job=$(sbatch --parsable --array=0-1 --cpus-per-task=1 --output=task-%a.out \
  --wrap 'echo "task $SLURM_ARRAY_TASK_ID on $SLURM_CPUS_PER_TASK CPU"')
job=${job%%;*}  # --parsable prints "id" or "id;cluster"
for _ in $(seq 1 120); do
  states=$(scontrol show job "$job" | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' | sort | uniq | tr '\n' ' ')
  [ "$states" = "COMPLETED " ] && break
  sleep 0.5
done
if [ "$states" != "COMPLETED " ]; then
  echo "check_cluster.sh: job $job: states '$states' after 60 s" >&2
  scontrol show job "$job" >&2
  exit 1
fi
for t in 0 1; do
  if [ "$(cat "task-$t.out")" != "task $t on 1 CPU" ]; then
    echo "check_cluster.sh: task $t wrote '$(cat "task-$t.out" 2>&1)'" >&2
    exit 1
  fi
done
echo "check_cluster.sh: job array $job ran its 2 tasks"
