#!/usr/bin/env bash
# The one-definition-rule check (SOFTGRAIN_ODR_CHECK, app/softgrain_odr_check) catches what it
# is for: two classes of one qualified name, compiled and merged as that check does (fat LTO
# objects, a relocatable link -r under -flto -Werror=odr), fail the merge naming the rule; the
# same pair with distinct names merges, and links into a program that runs.
# Usage: check_odr.sh CXX WORK_FOLDER
set -euo pipefail
cxx=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$work"
flags=(-std=c++20 -O1 -flto -ffat-lto-objects)
for unit in table_a table_b table_b_distinct; do
  "$cxx" "${flags[@]}" -c "$here/$unit.cpp" -o "$work/$unit.o"
done
odr_merge=(-flto=auto -r -nostdlib -Werror=odr -Werror=lto-type-mismatch)
if "$cxx" "${odr_merge[@]}" "$work/table_a.o" "$work/table_b.o" -o "$work/duplicated.o" \
    2> "$work/duplicated.err"; then
  echo "FAILED: two classes sg::Table linked without an error"
  exit 1
fi
if ! grep -q "violates the C++ One Definition Rule" "$work/duplicated.err"; then
  echo "FAILED: the link failed, but not on the one-definition rule:"
  cat "$work/duplicated.err"
  exit 1
fi
"$cxx" "${odr_merge[@]}" "$work/table_a.o" "$work/table_b_distinct.o" -o "$work/distinct.o"
"$cxx" -flto=auto "$work/distinct.o" -o "$work/distinct"
"$work/distinct"
echo "the duplicated class fails the link:"
grep "violates" "$work/duplicated.err"
