#!/usr/bin/env bash
# Install the Debian 12 packages ydry needs (DESIGN section 7). Idempotent: installs only
# what is missing, and runs `apt-get update` first when anything is.
#   scripts/install-deps.sh                  build, test, plotting and rendering dependencies
#   scripts/install-deps.sh --with-paraview  also the ParaView GUI
#   scripts/install-deps.sh --with-clang     also clang and libFuzzer (`make fuzz`)
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libeigen3-dev libmetis-dev libvtk9-dev catch2 libtomlplusplus-dev libcli11-dev
  gmsh
  python3 python3-numpy python3-matplotlib python3-vtk9
  xvfb  # Debian's VTK renders through X only: scripts/render_frame.py runs under xvfb-run
)
for arg in "$@"; do
  case "$arg" in
    # Debian 12's python3-paraview (pvpython) conflicts with python3-vtk9, which libvtk9-dev
    # needs: installing it removes the build dependencies. Only the GUI comes here.
    --with-paraview) packages+=(paraview) ;;
    --with-clang) packages+=(clang libclang-rt-dev) ;;
    -h|--help) sed -n '2,6p' "$0"; exit 0 ;;
    *) echo "install-deps.sh: unknown option '$arg'" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
