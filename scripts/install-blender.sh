#!/usr/bin/env bash
# Installs animkit into your own Blender, no root needed: the Python module (from the Release
# build) into Blender's user modules folder and the add-on into its user add-ons folder, both
# under ${XDG_CONFIG_HOME:-~/.config}/blender/<version>/scripts, then enables the add-on in your
# Blender preferences. Run again after a rebuild to update both.
#   usage: install-blender.sh [BUILD_DIR]   (default build/release)
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$here/build/release}"
module="$build/python/animkit"
addon="$here/python/blender/animkit_blender"

command -v blender >/dev/null || { echo "install-blender: blender is not on PATH" >&2; exit 1; }
[ -f "$module/__init__.py" ] ||
  { echo "install-blender: no Python module in $module (run make demo or make build first)" >&2; exit 1; }
# "Blender 3.4.1" -> 3.4: the folder Blender reads user scripts from.
version="$(blender --version 2>/dev/null | sed -n 's/^Blender \([0-9]*\.[0-9]*\).*/\1/p' | head -1)"
[ -n "$version" ] || { echo "install-blender: cannot read Blender's version" >&2; exit 1; }
scripts="${XDG_CONFIG_HOME:-$HOME/.config}/blender/$version/scripts"
mkdir -p "$scripts/modules" "$scripts/addons"
# Whole folders replaced, so nothing of an older install is left mixed in.
rm -rf "$scripts/modules/animkit" "$scripts/addons/animkit_blender"
cp -r "$module" "$scripts/modules/animkit"
cp -r "$addon" "$scripts/addons/animkit_blender"
find "$scripts/addons/animkit_blender" -name __pycache__ -prune -exec rm -rf {} +
blender -b --python-exit-code 1 --python-expr "
import addon_utils, bpy
addon_utils.enable('animkit_blender', default_set=True, handle_error=None)
bpy.ops.wm.save_userpref()
import animkit
print('install-blender: animkit', animkit.__file__)
" >/dev/null
echo "install-blender: the animkit module and add-on are in $scripts (Blender $version), enabled"
