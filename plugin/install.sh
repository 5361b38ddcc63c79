#!/bin/sh
# Installs the "Medial Axis" FreeCAD workbench and the Python package
# `cadmedial` (with its compiled module) for the current user.
#
#   plugin/install.sh [--build-dir DIR] [--mod-dir DIR] [--no-python-path] [--uninstall]
#
# * The addon goes to <FreeCAD user data>/Mod/MedialAxis, where FreeCAD
#   0.20 looks for user addons: $FREECAD_USER_DATA or $FREECAD_USER_HOME if set
#   (and existing), else ~/.local/share/FreeCAD. The folder is asked from
#   freecadcmd when it is installed. --mod-dir overrides it.
# * The addon folder holds cadmedial/ (pure Python + _native*.so from the
#   build tree) and freecad/medial_axis/ (the workbench). FreeCAD puts
#   Mod/MedialAxis on sys.path, so `import cadmedial` works in freecadcmd and
#   the GUI.
# * For plain /usr/bin/python3 a .pth file in the user site-packages
#   (python3 -m site --user-site) adds Mod/MedialAxis/python, which holds only
#   a symlink to cadmedial/ (not freecad/, which would shadow FreeCAD's own
#   `freecad` package). --no-python-path skips this; then use
#   PYTHONPATH=<Mod>/MedialAxis/python.
# * The new folder is assembled next to the old one and swapped in, so an
#   interrupted install never leaves half a workbench. Idempotent.
set -eu

here=$(cd "$(dirname "$0")" && pwd)
repo=$(dirname "$here")
build_dir=""
mod_dir=""
python_path=1
uninstall=0
python=${CADMEDIAL_PYTHON:-/usr/bin/python3}

die() { echo "install.sh: $*" >&2; exit 1; }

while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) [ $# -ge 2 ] || die "--build-dir needs a value"; build_dir=$2; shift 2 ;;
    --mod-dir) [ $# -ge 2 ] || die "--mod-dir needs a value"; mod_dir=$2; shift 2 ;;
    --no-python-path) python_path=0; shift ;;
    --uninstall) uninstall=1; shift ;;
    -h|--help) sed -n '2,25p' "$0"; exit 0 ;;
    *) die "unknown argument '$1' (see --help)" ;;
  esac
done

# --- where FreeCAD looks for user addons ---------------------------------------
if [ -z "$mod_dir" ]; then
  # FreeCAD 0.20 ignores these variables when the folder does not exist.
  for dir in "${FREECAD_USER_DATA:-}" "${FREECAD_USER_HOME:-}"; do
    [ -n "$dir" ] && mkdir -p "$dir"
  done
  user_data=""
  if command -v freecadcmd >/dev/null 2>&1; then
    user_data=$(freecadcmd -c 'import FreeCAD; print("USERDATA=" + FreeCAD.getUserAppDataDir())' 2>/dev/null \
                | sed -n 's/^USERDATA=//p' | tail -n 1) || user_data=""
  fi
  if [ -z "$user_data" ]; then
    if [ -n "${FREECAD_USER_DATA:-}" ]; then user_data=$FREECAD_USER_DATA
    elif [ -n "${FREECAD_USER_HOME:-}" ]; then user_data=$FREECAD_USER_HOME
    else user_data=$HOME/.local/share/FreeCAD
    fi
  fi
  mod_dir=${user_data%/}/Mod
fi
target=$mod_dir/MedialAxis

user_site=""
if [ -x "$python" ]; then
  user_site=$("$python" -c 'import site; print(site.getusersitepackages())' 2>/dev/null) || user_site=""
fi
pth=${user_site:+$user_site/cadmedial-freecad-addon.pth}

if [ "$uninstall" = 1 ]; then
  rm -rf "$target"
  rm -f "$mod_dir/.MedialAxis.lock"
  [ -n "$pth" ] && rm -f "$pth"
  echo "removed $target${pth:+ and $pth}"
  exit 0
fi

# --- the compiled module -----------------------------------------------------------
if [ -z "$build_dir" ]; then
  for candidate in "$repo/build" "$repo/build-plugin"; do
    if [ -n "$(find "$candidate/plugin/cadmedial" -maxdepth 1 -name '_native*.so' 2>/dev/null)" ]; then
      build_dir=$candidate
      break
    fi
  done
  [ -n "$build_dir" ] || die "no compiled module found under $repo/build or $repo/build-plugin; build the target cadmedial_python or pass --build-dir"
fi
native=$(find "$build_dir/plugin/cadmedial" -maxdepth 1 -name '_native*.so' 2>/dev/null | head -n 1) || true
if [ -z "$native" ] || [ ! -f "$native" ]; then
  die "$build_dir/plugin/cadmedial/_native*.so not found; run: cmake --build $build_dir --target cadmedial_python"
fi

# --- assemble and swap in -------------------------------------------------------------
mkdir -p "$mod_dir"
stage=$mod_dir/.MedialAxis.install-$$
old=$mod_dir/.MedialAxis.old-$$
trap 'rm -rf "$stage" "$old"' EXIT INT TERM
rm -rf "$stage"
mkdir -p "$stage"
cp "$here/package.xml" "$here/README.md" "$stage/"
cp -R "$here/freecad" "$here/cadmedial" "$stage/"
find "$stage" -name '__pycache__' -type d -prune -exec rm -rf {} +
rm -f "$stage"/cadmedial/_native*.so
cp "$native" "$stage/cadmedial/"
mkdir -p "$stage/python"
ln -s ../cadmedial "$stage/python/cadmedial"

# Two installs at once (the setup of two clones) would race on the swap: the
# second `mv` of the old folder failed, or the stage landed inside the new
# target. flock (util-linux) makes them take turns.
if command -v flock >/dev/null 2>&1; then
  exec 9>"$mod_dir/.MedialAxis.lock"
  flock 9
fi
if [ -e "$target" ]; then mv "$target" "$old"; fi
mv "$stage" "$target"
rm -rf "$old"
if command -v flock >/dev/null 2>&1; then flock -u 9; fi

if [ "$python_path" = 1 ] && [ -n "$pth" ]; then
  mkdir -p "$user_site"
  printf '%s\n' "$target/python" > "$pth.tmp-$$"
  mv "$pth.tmp-$$" "$pth"
fi

echo "installed the Medial Axis workbench into $target"
if [ "$python_path" = 1 ] && [ -n "$pth" ]; then
  echo "python3 finds cadmedial through $pth"
else
  echo "for plain python3: PYTHONPATH=$target/python"
fi
