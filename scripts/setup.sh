#!/usr/bin/env bash
# One-command setup for a fresh Debian 12 machine (run as root, or with sudo):
#   scripts/setup.sh demo   install what is missing, build (Release), run the main job on a bundled model
#   scripts/setup.sh test   install what is missing, build (Release), run the whole test suite (ctest)
# Idempotent: installs only missing packages and rebuilds incrementally.
set -euo pipefail

mode="${1:-demo}"
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${CADMEDIAL_BUILD_DIR:-$repo/build}"
out="${CADMEDIAL_OUT_DIR:-$repo/out}"
jobs="$(nproc 2>/dev/null || echo 2)"

case "$mode" in
  demo|test) ;;
  *) echo "usage: scripts/setup.sh demo|test" >&2; exit 2 ;;
esac

install_missing_packages() {
  local wanted missing=()
  mapfile -t wanted < <(grep -v '^\s*#' "$repo/scripts/debian-packages.txt" | grep -v '^\s*$')
  for pkg in "${wanted[@]}"; do
    dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
  done
  if [ "${#missing[@]}" -eq 0 ]; then
    echo "setup: all ${#wanted[@]} Debian packages present"
    return
  fi
  echo "setup: installing ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

build_project() {
  cmake -S "$repo" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3 >/dev/null
  cmake --build "$build" -j "$jobs"
}

install_missing_packages
build_project

if [ "$mode" = demo ]; then
  model="$repo/models/flange.step"
  "$build/cli/cadmedial" sample "$model" -o "$out/flange"
  echo "setup: done. Open $out/flange/solid_0/samples.ply and boundary.ply in MeshLab or ParaView."
else
  cd "$build"
  ctest --output-on-failure -j "$jobs"
fi
