#!/usr/bin/env bash
# Checks that src/gl/gl_api.h and gl_api.cpp are what scripts/gen_gl_api.py writes from this
# machine's glcorearb.h: a hand edit of the generated loader fails here.
# Usage: scripts/check_gl_api.sh
set -euo pipefail
cd "$(dirname "$0")/.."
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
python3 scripts/gen_gl_api.py --out "$out" >/dev/null
status=0
for f in gl_api.h gl_api.cpp; do
  if ! diff -u "src/gl/$f" "$out/$f"; then
    echo "check_gl_api: src/gl/$f differs from what scripts/gen_gl_api.py writes" >&2
    status=1
  fi
done
[ "$status" -eq 0 ] && echo "check_gl_api: src/gl/gl_api.h and gl_api.cpp are generated"
exit "$status"
