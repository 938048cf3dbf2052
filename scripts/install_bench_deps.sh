#!/usr/bin/env bash
# Installs what only the benchmarks need (Debian 12): python3-vtk9 for VTK's CPU and GPU ray
# casters (scripts/vtk_raycast_bench.py, run by ewaview-compare and ewaview-shearwarp-bench).
# Never run by setup.sh: building, testing and using ewaview do not need VTK.
# Usage: scripts/install_bench_deps.sh
set -euo pipefail

packages=(python3-vtk9 xvfb xauth)  # VTK draws into an X display: xvfb-run when none is set
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "install_bench_deps: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}"
fi
# The benchmarks call /usr/bin/python3: Debian's VTK bindings belong to the system interpreter.
/usr/bin/python3 -c "import vtkmodules.vtkRenderingVolumeOpenGL2" &&
  echo "install_bench_deps: VTK $(/usr/bin/python3 -c 'import vtk; print(vtk.vtkVersion.GetVTKVersion())') ready"
