#!/usr/bin/env bash
# Installs the Debian 12 packages ewaview needs (only those missing), then configures and builds
# the viewer and the Python module only (the tests and benchmarks: scripts/test.sh), so that
# `scripts/setup.sh && ./build/ewaview` opens the window in minutes on two cores.
# Usage: scripts/setup.sh [build-dir]   (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"

packages=(build-essential cmake pkg-config ccache
  libglfw3-dev libglm-dev libosmesa6-dev libegl-dev libegl1-mesa-dev libgl-dev libgl1-mesa-dri
  libimgui-dev libstb-dev libcli11-dev nlohmann-json3-dev zlib1g-dev libbz2-dev libgtest-dev
  libgdcm-dev libtiff-dev  # DICOM series, TIFF stacks
  libarchive-dev  # volumes in .zip, .tar.gz, .7z archives
  libblosc-dev libzstd-dev libhdf5-dev  # OME-Zarr chunks, HDF5 files
  python3-zarr python3-h5py  # the OME-Zarr and HDF5 tests write their files with them
  libtbb-dev  # the CPU splatter's tasks (--splatter cpu)
  libopenmpi-dev openmpi-bin  # distributed rendering (ewaview-mpi, IceT in third_party/icet)
  xvfb xauth xdotool imagemagick  # tests/window/window_test.sh
  unzip  # the DICOM test series in a zip
  clang libclang-rt-14-dev  # scripts/fuzz.sh: clang with libFuzzer
  clang-format  # scripts/check_format.sh
  libavformat-dev libavcodec-dev libswscale-dev libavutil-dev  # turntable videos (.mp4, .webm)
  pybind11-dev python3-dev python3-numpy python3-pytest)  # Python module in build/python
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}"
fi

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release
targets=(ewaview)
# The module's target exists only where pybind11 and the Python headers were found.
if [ -d "$build/CMakeFiles/ewaview_python.dir" ]; then targets+=(ewaview_python); fi
cmake --build "$build" -j"$(nproc)" --target "${targets[@]}"
