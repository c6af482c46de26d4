#!/usr/bin/env bash
# Bitwise comparison of two softgrain executables on five scenarios: the check that a
# restructuring kept results identical (docs/architecture.md, "Developing softgrain").
#
#   bash scripts/compare-runs.sh OLD_SOFTGRAIN NEW_SOFTGRAIN [DURATION|full] [THREADS]
#
# Runs examples/shear-cell-small.toml, shear-cell-explicit.toml, compaction-box.toml,
# shear-cell-deformable-pressure.toml and bench/scenes/imex-cell.toml with `[time]
# integrator = "imex"` (the others with `integrator = "explicit"` where they name none: the
# default integrator is chosen on the model since issue #30), each shortened to DURATION time
# units (default 2; `full`: as written), with both executables, and compares every file they
# write (series.csv, fields/, contacts/, grains/, checkpoint.bin, the .pvd indexes) byte for
# byte. run.log is left out: it records wall-clock times. Prints one line per scenario and
# exits 1 if any file differs.
#
# The .vtu files of fields/ and contacts/ are compared byte for byte when both executables
# know [output] field_format (binary, zlib-compressed, by default; io/vtu_document.h). An old
# executable that does not (asked with `info` on a small probe scenario) wrote them as text
# with 9 significant digits, which no encoding of the new one reproduces byte for byte; those
# are then compared by their decoded arrays (scripts/compare_vtu.py, /usr/bin/python3): the
# same points, cells and array names, every value equal to the old text once the new double is
# rounded to 9 digits as the old writer did. That still checks every snapshot, and
# checkpoint.bin and series.csv, compared byte for byte as always, hold the state bitwise.
# Build the old executable from a checkout of the old commit, e.g.
#   git worktree add /tmp/old <commit> && cmake -S /tmp/old -B /tmp/old/build && \
#   cmake --build /tmp/old/build --target softgrain
set -euo pipefail
if [[ $# -lt 2 ]]; then
  sed -n '2,26p' "$0" >&2
  exit 2
fi
old=$(realpath "$1")
new=$(realpath "$2")
duration=${3:-2}
threads=${4:-2}
repo=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/softgrain-compare.XXXXXX")
trap 'rm -rf "$work"' EXIT

scenarios=(examples/shear-cell-small.toml examples/shear-cell-explicit.toml
           examples/compaction-box.toml examples/shear-cell-deformable-pressure.toml
           bench/scenes/imex-cell.toml)
mkdir -p "$work/scenarios"
cp "$repo"/examples/*.csv "$work/scenarios/"
for s in "${scenarios[@]}"; do
  copy="$work/scenarios/$(basename "$s")"
  cp "$repo/$s" "$copy"
  if [[ "$duration" != full ]]; then
    sed -i "0,/^duration *=.*/s//duration = $duration/" "$copy"
  fi
done
sed -i 's/^integrator *=.*/integrator = "imex"/' "$work/scenarios/imex-cell.toml"
# Without [time] integrator a scenario's integrator is chosen on the built model (imex where it
# is faster, docs/scenario.md "Integrators"), which an older executable did not do: the
# others are pinned to `integrator = "explicit"`, what the key's absence meant before, so that
# the explicit path is compared bitwise whatever the default chooses.
for s in "${scenarios[@]}"; do
  copy="$work/scenarios/$(basename "$s")"
  if ! grep -q '^integrator *=' "$copy"; then
    sed -i '0,/^\[time\]/s//[time]\nintegrator = "explicit"/' "$copy"
  fi
done

# Does the old executable know [output] field_format? (An unknown key is an error at load.)
cat > "$work/probe.toml" <<'PROBE'
name = "probe"
[time]
duration = 0.01
[output]
field_format = "binary"
[[materials]]
name = "m"
young = 10.0
[[grains]]
center = [0.0, 0.0]
radius = 0.5
material = "m"
PROBE
vtu_bytes=1
if ! "$old" info "$work/probe.toml" > "$work/probe.out" 2>&1; then
  if grep -q field_format "$work/probe.out"; then
    vtu_bytes=0
    echo "(the old executable has no [output] field_format: .vtu files compared by their arrays)"
  else
    echo "the old executable failed on the probe scenario:"
    tail -5 "$work/probe.out"
    exit 1
  fi
fi

status=0
for s in "${scenarios[@]}"; do
  name=$(basename "$s" .toml)
  for side in old new; do
    exe=$old
    [[ $side == new ]] && exe=$new
    if ! "$exe" run "$work/scenarios/$name.toml" --threads "$threads" -o "$work/$side/$name" \
        > "$work/$side-$name.out" 2>&1; then
      echo "$name: the $side executable failed:"
      tail -5 "$work/$side-$name.out"
      status=1
      continue 2
    fi
  done
  excluded=(--exclude=run.log)
  [[ $vtu_bytes == 0 ]] && excluded+=(--exclude='*.vtu')
  if differences=$(diff -rq "${excluded[@]}" "$work/old/$name" "$work/new/$name") &&
      { [[ $vtu_bytes == 1 ]] ||
        differences=$(/usr/bin/python3 "$repo/scripts/compare_vtu.py" "$work/old/$name" \
                        "$work/new/$name"); }; then
    files=$(cd "$work/new/$name" && find . -type f ! -name run.log | wc -l)
    how="identical"
    [[ $vtu_bytes == 0 ]] && how="identical, .vtu arrays equal"
    echo "$name: $how ($files files)"
  else
    echo "$name: DIFFERENT"
    echo "$differences" | head -20
    status=1
  fi
done
exit $status
