#!/usr/bin/env bash
# Whole runs of bench/scenes/imex-cell.toml (13 time units) for the IMEX accuracy and cost
# tables of docs/scenario.md and docs/verification.md: for each case "alpha model integrator
# [seed [imex_tolerance [imex_objective [imex_dense_factors]]]]" given as arguments (or the
# default list), runs it on 2 threads, analyzes it and prints one CSV line: alpha, model,
# integrator, seed, tolerance, objective solve, dense factors, wall seconds, mu, p_wb, solid
# fraction and the IMEX solve counts from run.log. A value of "default" (or none) leaves its key
# out. mu, p_wb and the solid fraction are means over t in [5, 13] (2 time units after the
# shear starts).
#   bash bench/run_imex_accuracy.sh "0.3 objective imex" "0.3 objective explicit"
#   bash bench/run_imex_accuracy.sh "0.3 objective imex 2 default exact"
#   bash bench/run_imex_accuracy.sh "0.02 corotational imex 1 default default false"
set -euo pipefail
cd "${SOFTGRAIN_ROOT:-$(dirname "$0")/..}"
bin=${SOFTGRAIN_BIN:-build-test/app/softgrain}
out=${SOFTGRAIN_BENCH_OUT:-out-bench}
cases=("$@")
[ ${#cases[@]} -eq 0 ] && cases=("0.02 objective explicit" "0.02 objective imex"
                                 "0.3 objective imex" "0.3 corotational imex")
echo "alpha,model,integrator,seed,imex_tolerance,imex_objective,imex_dense_factors,wall_s,mu,p_wb,solid_fraction,imex_note"
for c in "${cases[@]}"; do
  read -r alpha model integrator seed tolerance objective dense <<<"$c"
  seed=${seed:-1}
  [ "$tolerance" = default ] && tolerance=""
  [ "$objective" = default ] && objective=""
  [ "$dense" = default ] && dense=""
  name="imex-cell-a${alpha}-${model}-${integrator}-s${seed}${tolerance:+-tol$tolerance}${objective:+-$objective}${dense:+-dense$dense}"
  tolerance_line=${tolerance:+imex_tolerance = $tolerance}${objective:+\\nimex_objective = \"$objective\"}${dense:+\\nimex_dense_factors = $dense}
  scenario="$out/$name.toml"
  mkdir -p "$out"
  sed -e "0,/^name = .*/s//name = \"$name\"/" -e "s/^damping = .*/damping = $alpha/" \
      -e "s/^damping_model = .*/damping_model = \"$model\"/" \
      -e "s/^integrator = .*/integrator = \"$integrator\"\n$tolerance_line/" -e "s/^seed = .*/seed = $seed/" \
      bench/scenes/imex-cell.toml > "$scenario"
  start=$(date +%s.%N)
  "$bin" run "$scenario" -o "$out" --threads 2 > "$out/$name.stdout" 2>&1
  wall=$(echo "$(date +%s.%N) - $start" | bc)
  "$bin" analyze "$out/$name" --window 5 13 --no-plots --no-agglomerates > /dev/null
  summary="$out/$name/analysis/summary.json"
  read -r mu pwb phi < <(/usr/bin/python3 - "$summary" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
def find(d, key):
    if isinstance(d, dict):
        for k, v in d.items():
            if k == key:
                return v.get("value") if isinstance(v, dict) else v
            r = find(v, key)
            if r is not None: return r
    return None
print(find(s, "mu"), find(s, "bulk_share"), find(s, "solid_fraction"))
PY
)
  note=$(grep -h "^# imex:" "$out/$name/run.log" | sed 's/,/;/g' || true)
  echo "$alpha,$model,$integrator,$seed,${tolerance:-default},${objective:-default},${dense:-default},$wall,$mu,$pwb,$phi,$note"
done
