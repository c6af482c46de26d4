#!/usr/bin/env bash
# The step's cost at the papers' size in shear, in about a minute per measurement instead of a
# 13-minute run: examples/shear-cell-full.toml (2,000 grains, 317,175 nodes) resumed from a
# checkpoint taken in its shear (t = 22.5 by default, 12.5 time units after its compaction) for
# one time unit (about 500 steps), once per executable given and round, interleaved, so that
# versions are compared in the same state of the machine. Prints one CSV line per run: the
# executable, the round, threads, wall seconds (the model's build and the factorizations
# included), seconds in the loop, ms per step, the run.log profile's phases and the md5 of
# series.csv (equal md5: the same trajectory).
#
# The checkpoint comes from a first run of the example up to the start (about 10 minutes on 2
# cores, by the first executable given), kept in SOFTGRAIN_BENCH_OUT and reused by later calls
# with the same damping model; every executable compared must read it (the same checkpoint
# format and model: a refused checkpoint shows in that run's stdout in the folder).
#   bash bench/run_paper_shear.sh build/app/softgrain            # one run, reference_stiffness
#   ROUNDS=3 bash bench/run_paper_shear.sh old/softgrain new/softgrain
#   DAMPING_MODEL=objective THREADS=1 bash bench/run_paper_shear.sh build/app/softgrain
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${SOFTGRAIN_BENCH_OUT:-$root/out-bench/paper-shear}
model=${DAMPING_MODEL:-reference_stiffness}
threads=${THREADS:-2}
rounds=${ROUNDS:-1}
start=${START:-22.5}
span=${SPAN:-1.0}
binaries=("$@")
[ ${#binaries[@]} -eq 0 ] && binaries=("$root/build/app/softgrain")
name="paper-shear-$model"

# The example with this damping model, this duration and a checkpoint at `start`.
scenario() {
  sed -e "0,/^name = .*/s//name = \"$name\"/" -e "s/^duration = .*/duration = $1/" \
      -e "s/^damping = \(.*\)/damping = \1\ndamping_model = \"$model\"/" \
      -e "s/^field_period = .*/field_period = $start\ncheckpoint_period = $start/" \
      "$root/examples/shear-cell-full.toml"
}

base="$out/base-$model"
if [ ! -f "$base/$name/checkpoint.bin" ]; then
  echo "# first: the example up to t = $start for its checkpoint (${binaries[0]}, $threads threads)" >&2
  rm -rf "$base" && mkdir -p "$base"
  # A little past the start, so that the checkpoint at the start is written and kept.
  scenario "$(echo "$start + 0.01" | bc)" > "$base/scenario.toml"
  OMP_WAIT_POLICY=PASSIVE "${binaries[0]}" run "$base/scenario.toml" -o "$base" \
    --threads "$threads" > "$base/stdout" 2>&1
fi

# The seconds of a phase in the run.log profile of the run at hand ($log).
phase() { grep -E "^#   $1 " "$log" | awk '{print $(NF-2)}'; }

echo "binary,round,threads,wall_s,loop_s,ms_per_step,contacts_s,internal_forces_s,velocities_s,series_md5"
for round in $(seq 1 "$rounds"); do
  for bin in "${binaries[@]}"; do
    run="$out/run"
    rm -rf "$run" && mkdir -p "$run"
    cp -r "$base/$name" "$run/"
    # The copy resumes as a run stopped at its checkpoint: its rows after the checkpoint are
    # cut, and the snapshots it lists are not needed.
    mv "$run/$name/series.csv" "$run/$name/series.csv.partial"
    rm -rf "$run/$name"/{fields,contacts,grains,analysis} "$run/$name"/*.pvd
    scenario "$(echo "$start + $span" | bc)" > "$run/scenario.toml"
    t0=$(date +%s.%N)
    OMP_WAIT_POLICY=PASSIVE "$bin" run --resume "$run/scenario.toml" -o "$run" \
      --threads "$threads" > "$run/stdout" 2>&1
    wall=$(echo "$(date +%s.%N) - $t0" | bc)
    log="$run/$name/run.log"
    loop=$(grep -o '[0-9.]* s in the loop' "$log" | cut -d' ' -f1)
    # "... N steps (resumed at step M), ...": this run's steps are N - M.
    done_steps=$(sed -n 's/.* \([0-9]*\) steps (resumed at step \([0-9]*\)).*/\1 - \2/p' "$run/stdout" | bc)
    printf '%s,%s,%s,%.1f,%s,%.1f,%s,%s,%s,%s\n' "$bin" "$round" "$threads" "$wall" "$loop" \
      "$(echo "1000 * $loop / $done_steps" | bc -l)" "$(phase contacts)" \
      "$(phase 'internal forces')" "$(phase velocities)" \
      "$(md5sum "$run/$name/series.csv" | cut -c1-8)"
  done
done
