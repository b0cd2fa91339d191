#!/usr/bin/env bash
# Install the Debian 12 packages ydry needs. Idempotent: installs only
# what is missing, and runs `apt-get update` first when anything is.
#   scripts/install-deps.sh                  build, test, plotting and rendering dependencies
#   scripts/install-deps.sh --with-paraview  also ParaView and its Python client, pvpython
#   scripts/install-deps.sh --with-clang     also clang and libFuzzer (`make fuzz`)
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libeigen3-dev libmetis-dev libvtk9-dev catch2 libtomlplusplus-dev libcli11-dev
  gmsh
  python3 python3-numpy python3-matplotlib python3-vtk9
  xvfb  # Debian's VTK renders through X only: scripts/virtual_display.py starts an Xvfb
)
with_paraview=0
for arg in "$@"; do
  case "$arg" in
    # The GUI and pvbatch. Debian 12's python3-paraview (pvpython and ParaView's Python
    # modules) conflicts with python3-vtk9, which libvtk9-dev needs: installing it removes the
    # build dependencies, and so would apt's default of installing what paraview recommends.
    --with-paraview) packages+=(paraview); with_paraview=1 ;;
    --with-clang) packages+=(clang libclang-rt-dev) ;;
    -h|--help) sed -n '2,6p' "$0"; exit 0 ;;
    *) echo "install-deps.sh: unknown option '$arg'" >&2; exit 2 ;;
  esac
done

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  sudo="sudo"
fi
need_root() {
  [ -z "$sudo" ] || command -v sudo >/dev/null || { echo "install-deps: need root or sudo to $1" >&2; exit 1; }
}

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
else
  need_root "install: ${missing[*]}"
  echo "install-deps: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# pvpython without python3-paraview: its files unpacked, outside dpkg, under $prefix (the
# same version as paraview), and a `pvpython` that runs a script with paraview's pvbatch on
# them. Debian's own pvpython would not do here: it puts /usr/lib/python3/dist-packages, where
# python3-vtk9's VTK 9.1 lives, ahead of ParaView's modules, and crashes on importing them.
prefix=/opt/python3-paraview
launcher=/usr/local/bin/pvpython
if [ "$with_paraview" -eq 1 ] && ! dpkg-query -W -f='${Status}' python3-paraview 2>/dev/null | grep -q "install ok installed"; then
  version=$(dpkg-query -W -f='${Version}' paraview)
  if [ "$(cat "$prefix/VERSION" 2>/dev/null)" != "$version" ] || [ ! -x "$launcher" ]; then
    need_root "unpack python3-paraview into $prefix"
    echo "install-deps: unpacking python3-paraview $version into $prefix (not installed with dpkg)"
    download=$(mktemp -d)
    chmod 755 "$download"  # apt-get download fetches as the _apt user
    $sudo apt-get update -qq
    (cd "$download" && apt-get download -qq "python3-paraview=$version")
    $sudo rm -rf "$prefix"
    $sudo dpkg-deb -x "$download"/python3-paraview_*.deb "$prefix"
    rm -rf "$download"
    echo "$version" | $sudo tee "$prefix/VERSION" >/dev/null
    $sudo tee "$launcher" >/dev/null <<EOF
#!/bin/sh
# pvpython for Debian 12 beside python3-vtk9, written by ydry's scripts/install-deps.sh:
# ParaView's pvbatch running a script on python3-paraview $version, unpacked in $prefix.
# Without a display, run it as \`scripts/virtual_display.py pvpython SCRIPT.py\` (in ydry).
PYTHONPATH=$prefix/usr/lib/python3/dist-packages\${PYTHONPATH:+:\$PYTHONPATH} exec /usr/bin/pvbatch "\$@"
EOF
    $sudo chmod 755 "$launcher"
  fi
fi
