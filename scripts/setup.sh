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
  apt_when_free $sudo apt-get update -qq
  apt_when_free $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

# Runs an apt-get command, waiting while another apt or dpkg holds its lock
# (a fresh machine's unattended upgrades, a second setup run): apt-get update
# fails at once on a held lock instead of waiting. Other failures end setup.
apt_when_free() {
  local attempt errors
  errors="$(mktemp)"
  for attempt in $(seq 1 90); do
    if "$@" 2>"$errors"; then
      cat "$errors" >&2; rm -f "$errors"; return 0
    fi
    cat "$errors" >&2
    if ! grep -q "Could not get lock" "$errors"; then
      rm -f "$errors"; return 1
    fi
    echo "setup: apt is busy with another install; waiting ($attempt/90)" >&2
    sleep 10
  done
  rm -f "$errors"
  echo "setup: apt stayed busy for 15 min; run setup again when it is free" >&2
  return 1
}

build_project() {
  cmake -S "$repo" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=/usr/bin/python3 >/dev/null
  cmake --build "$build" -j "$jobs"
}

# The FreeCAD workbench and the `cadmedial` Python module, for this user.
install_addon() {
  "$repo/plugin/install.sh" --build-dir "$build"
}

install_missing_packages
build_project
install_addon

if [ "$mode" = demo ]; then
  model="$repo/models/flange.step"
  "$build/cli/cadmedial" run "$model" -o "$out/flange"
  "$build/cli/cadmedial" eval "$model" "$out/flange"
  fcstd="$out/flange/flange_medial.FCStd"
  rm -f "$fcstd"
  CADMEDIAL_DEMO_MODEL="$model" CADMEDIAL_DEMO_FCSTD="$fcstd" freecadcmd "$repo/scripts/demo_document.py"
  [ -f "$fcstd" ] || { echo "setup: the FreeCAD document was not written" >&2; exit 1; }
  echo "setup: done. Outputs in $out/flange: medial.ply/.obj/.ma, summary.json, eval.json per solid, and"
  echo "       $fcstd (open it in FreeCAD; the Medial Axis workbench is installed)."
else
  cd "$build"
  ctest --output-on-failure -j "$jobs"
fi
