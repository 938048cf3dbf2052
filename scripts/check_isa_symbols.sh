#!/bin/sh
# Checks that the CPU splatter's AVX2 object defines no function but its own namespace's: a weak
# copy of a shared inline function compiled for AVX2 could be the one the linker keeps for every
# caller, and would crash machines without AVX2. Arguments: ewa_core's object files.
set -eu
# CMake passes $<TARGET_OBJECTS> as one argument, the paths separated by ';'.
for object in $(printf '%s\n' "$@" | tr ';' '\n'); do
  case "$object" in
    *tile_compositor_avx2.cpp.o) found=$object ;;
  esac
done
if [ -z "${found:-}" ]; then
  echo "check_isa_symbols: no tile_compositor_avx2.cpp.o among the objects" >&2
  exit 1
fi
foreign=$(nm -C --defined-only "$found" | awk '$2 ~ /^[TWVu]$/' |
  grep -v -e ' ewa::tile_kernel::avx2::' -e ' DW.ref.' || true)
if [ -n "$foreign" ]; then
  echo "check_isa_symbols: $found defines functions outside ewa::tile_kernel::avx2:" >&2
  echo "$foreign" >&2
  exit 1
fi
echo "check_isa_symbols: $found defines only ewa::tile_kernel::avx2 functions"
