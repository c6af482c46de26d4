#!/usr/bin/env bash
# The one-definition-rule check (SOFTGRAIN_ODR_CHECK, app/softgrain_odr_check) catches what it
# is for: two classes of one qualified name, compiled and linked as that check does (fat LTO
# objects, -flto -Werror=odr at the link), fail the link naming the rule; the same pair with
# distinct names links. Usage: check_odr.sh CXX WORK_FOLDER
set -euo pipefail
cxx=$1
work=$2
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$work"
flags=(-std=c++20 -O1 -flto -ffat-lto-objects)
for unit in table_a table_b table_b_distinct; do
  "$cxx" "${flags[@]}" -c "$here/$unit.cpp" -o "$work/$unit.o"
done
if "$cxx" -flto=auto -Werror=odr "$work/table_a.o" "$work/table_b.o" -o "$work/duplicated" \
    2> "$work/duplicated.err"; then
  echo "FAILED: two classes sg::Table linked without an error"
  exit 1
fi
if ! grep -q "violates the C++ One Definition Rule" "$work/duplicated.err"; then
  echo "FAILED: the link failed, but not on the one-definition rule:"
  cat "$work/duplicated.err"
  exit 1
fi
"$cxx" -flto=auto -Werror=odr "$work/table_a.o" "$work/table_b_distinct.o" -o "$work/distinct"
"$work/distinct"
echo "the duplicated class fails the link:"
grep "violates" "$work/duplicated.err"
