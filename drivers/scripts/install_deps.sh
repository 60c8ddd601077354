#!/usr/bin/env bash
# Installs the Debian 12 packages picdem builds and runs with (as root; skipped when present).
# usage: install_deps.sh [--tests]
set -euo pipefail
packages=(
  build-essential cmake ccache git
  trilinos-all-dev libptscotch-dev
  libcgal-dev libgmp-dev libmpfr-dev
  libhdf5-openmpi-dev hdf5-tools libopenmpi-dev openmpi-bin
  libgtest-dev libcairo2-dev fonts-dejavu-core ffmpeg
  python3 python3-numpy python3-matplotlib python3-h5py python3-meshio python3-yaml
)
# --tests: also ParaView (pvpython) and a virtual X server, with which the test suite opens the
# output in ParaView's XDMF readers and renders a frame (tests/mpi/output: without them those two
# tests report themselves skipped).
if [ "${1:-}" = "--tests" ]; then
  packages+=(paraview python3-paraview xvfb xauth)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
