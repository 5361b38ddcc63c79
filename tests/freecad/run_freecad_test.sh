#!/bin/sh
# Runs one FreeCAD test with the Medial Axis addon installed into a throw-away
# HOME and FREECAD_USER_HOME, so the test leaves nothing behind.
#
#   run_freecad_test.sh BUILD_DIR MODE SCRIPT
#
# MODE: cmd    freecadcmd SCRIPT
#       gui    xvfb-run -a freecad SCRIPT   (the script ends FreeCAD with its exit code)
#       python /usr/bin/python3 SCRIPT      (plain Python, cadmedial found through the .pth)
# The script gets CADMEDIAL_SOURCE_DIR, CADMEDIAL_TEST_TMP and, if set by the
# caller, CADMEDIAL_SCREENSHOT in its environment.
set -eu
build=$1
mode=$2
script=$3
here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../.." && pwd)

tmp=$(mktemp -d "${TMPDIR:-/tmp}/cadmedial-freecad-test.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
export HOME="$tmp/home"
export FREECAD_USER_HOME="$tmp/freecad"
export CADMEDIAL_TEST_TMP="$tmp/work"
export CADMEDIAL_SOURCE_DIR="$repo"
export QTWEBENGINE_DISABLE_SANDBOX=1
export XDG_RUNTIME_DIR="$tmp/xdg"
# FreeCAD's GUI leaves a single-instance socket and Start-page thumbnail folders
# in the temporary directory; keep them in ours.
export TMPDIR="$tmp/tmp"
mkdir -p "$HOME" "$FREECAD_USER_HOME" "$CADMEDIAL_TEST_TMP" "$XDG_RUNTIME_DIR" "$TMPDIR"
chmod 700 "$XDG_RUNTIME_DIR"
"$repo/plugin/install.sh" --build-dir "$build"

status=0
case "$mode" in
  cmd) freecadcmd "$script" || status=$? ;;
  gui) xvfb-run -a -s "-screen 0 1600x1200x24" freecad "$script" || status=$? ;;
  python) /usr/bin/python3 "$script" || status=$? ;;
  *) echo "run_freecad_test.sh: unknown mode '$mode'" >&2; exit 2 ;;
esac
exit "$status"
