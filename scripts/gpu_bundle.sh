#!/usr/bin/env bash
# Packs the headless programs of a build with the libraries they need into one folder, for a
# machine (a GPU box) that has an NVIDIA EGL driver but not this project's Debian packages.
# OSMesa (with LLVM) and FFmpeg are replaced by stubs whose functions return 0: there the
# programs render through --backend egl, and a turntable video fails cleanly.
# Usage: scripts/gpu_bundle.sh BUILD OUT   then on the target: LD_LIBRARY_PATH=OUT/lib OUT/bin/...
set -euo pipefail
build="$1"
out="$2"
rm -rf "$out"
mkdir -p "$out/bin" "$out/lib" "$out/stub-src"
programs=(ewaview ewaview-compare ewaview-bench ewaview-interact-bench ewaview-classify-bench
          ewa_render_tests ewa_unit_tests)
for p in "${programs[@]}"; do cp "$build/$p" "$out/bin/"; done
# Stubs: every function the programs import from these libraries, under the same versions.
stubbed=(libOSMesa.so.8 libavformat.so.59 libavcodec.so.59 libswscale.so.6 libavutil.so.57
         libswresample.so.4)
for lib in "${stubbed[@]}"; do
  real="/lib/x86_64-linux-gnu/$lib"
  [ -e "$real" ] || continue
  src="$out/stub-src/${lib%%.so*}"
  nm -D --defined-only --with-symbol-versions "$real" | awk '$2 ~ /[TtWi]/ {print $3}' |
    sed 's/@@\?.*//' | sort -u >"$src.defined"
  versions=$(nm -D --defined-only --with-symbol-versions "$real" | grep -o '@@[A-Z0-9_]*' |
    sed 's/@@//' | sort -u || true)
  for p in "${programs[@]}"; do nm -D --undefined-only "$out/bin/$p" | awk '{print $2}'; done |
    sed 's/@.*//' | sort -u | grep -F -x -f "$src.defined" >"$src.used" || true
  { echo '/* generated stub */'; while read -r f; do echo "long $f(void) { return 0; }"; done \
      <"$src.used"; } >"$src.c"
  if [ -n "$versions" ]; then
    { for v in $versions; do echo "$v { global: *; };"; done; } >"$src.map"
    cc -shared -fPIC -o "$out/lib/$lib" "$src.c" -Wl,-soname,"$lib" -Wl,--version-script,"$src.map"
  else
    cc -shared -fPIC -o "$out/lib/$lib" "$src.c" -Wl,-soname,"$lib"
  fi
done
# The rest: every library the programs load (with the stubs in place), but the C library and
# the GL vendor-neutral dispatch (libglvnd), which the target's driver brings.
skip='^(libc|libm|libdl|libpthread|librt|ld-linux-x86-64|libEGL|libGL|libGLX|libGLdispatch|libOpenGL|libGLESv2)\.so'
for p in "${programs[@]}"; do LD_LIBRARY_PATH="$out/lib" ldd "$out/bin/$p"; done |
  awk '$3 ~ /^\// {print $1, $3}' | sort -u | while read -r name path; do
    [[ "$name" =~ $skip ]] && continue
    [ -e "$out/lib/$name" ] || cp -L "$path" "$out/lib/$name"
  done
rm -rf "$out/stub-src"
# The test programs name files by this checkout's absolute paths (references, outputs, the
# programs they run, ../shared/data): gpu_measure.sh recreates them there from this file.
(cd "$(dirname "$0")/.." && pwd) >"$out/source_root"
basename "$(cd "$build" && pwd)" >"$out/build_dir"
# libglvnd's dispatch libraries, for a machine whose driver came without them (an H200 image had
# no libEGL.so.1): gpu_measure.sh adds lib/glvnd to the path only where the system has none.
mkdir -p "$out/lib/glvnd"
for lib in libEGL.so.1 libGLdispatch.so.0 libOpenGL.so.0 libGL.so.1 libGLX.so.0; do
  [ -e "/lib/x86_64-linux-gnu/$lib" ] && cp -L "/lib/x86_64-linux-gnu/$lib" "$out/lib/glvnd/"
done
strip --strip-unneeded "$out"/bin/* "$out"/lib/*.so* "$out"/lib/glvnd/*
du -sh "$out"
