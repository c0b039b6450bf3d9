#!/usr/bin/env bash
# Installs the Debian packages deploydyn builds and runs with. Idempotent: quiet and quick
# when everything is already there. Needs root (or sudo) only when something is missing.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libyaml-cpp-dev libyaml-dev libsimdjson-dev libcli11-dev libfmt-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev libbenchmark-dev libsuitesparse-dev libmetis-dev libspectra-dev libnova-dev libfcl-dev libembree-dev
  clang libclang-rt-14-dev
  python3 python3-numpy python3-matplotlib
  python3-dev pybind11-dev python3-pytest python3-pil python3-yaml python3-pysolar
  libjs-three chromium chromium-driver python3-selenium
  libopenmpi-dev openmpi-bin python3-mpi4py libhdf5-dev python3-h5py xvfb xauth
  # ParaView's Python (pvpython) also provides VTK's (vtkmodules); it conflicts with python3-vtk9.
  python3-paraview
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "install-deps: installing ${missing[*]}" >&2
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
