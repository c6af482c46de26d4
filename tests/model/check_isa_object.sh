#!/bin/sh
# check_isa_object.sh <object file> <namespace>: the object file of a kernel compiled for a wider
# instruction set (src/model/force_kernel_avx2.cpp) defines no inline code outside <namespace>
# and no static initializer. Inline functions and template instances are weak symbols, of which
# the linker keeps one copy for the whole program: an AVX2 copy of, say, a std::vector member
# could be the one every caller runs, on processors without AVX2 too. A static initializer
# would run at start-up on every processor.
set -eu
object=$1
namespace=$2
[ -f "$object" ] || { echo "check_isa_object.sh: no object file '$object'"; exit 1; }
# nm: W/V weak, u unique, i indirect, v weak object; DW.ref.__gxx_personality_v0 is data.
shared=$(nm -C --defined-only "$object" | awk '$2 ~ /^[WVuiv]$/' |
  grep -v -F "$namespace::" | grep -v -F "DW.ref.__gxx_personality_v0" || true)
if [ -n "$shared" ]; then
  echo "$object defines inline code outside $namespace (move it out of the kernel unit):"
  echo "$shared"
  exit 1
fi
if objdump -h "$object" | grep -q -E '\.init_array|\.ctors'; then
  echo "$object has a static initializer (it would run on every processor)"
  exit 1
fi
count=$(nm -C --defined-only "$object" | awk '$2 ~ /^[WVuiv]$/' | grep -c -F "$namespace::" || true)
echo "$object: $count inline functions, all in $namespace; no static initializer"
