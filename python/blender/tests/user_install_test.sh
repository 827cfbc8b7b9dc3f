#!/bin/sh
# ctest's blender.user_install: scripts/install-blender.sh puts the module and the add-on into
# a fresh user folder (HOME in the test's own directory: no root, nothing of the machine's
# user touched), then Blender, started as a user would, checks what it finds there
# (user_install_check.py). Exit 77 without Blender unless CI is set.
#   usage: user_install_test.sh SOURCE_DIR BUILD_DIR DATA_DIR OUT_DIR
set -u
. "$(dirname "$0")/../../../tests/support/require_tools.sh"
require_tools blender
rm -rf "$4" && mkdir -p "$4/home" || exit 1
export HOME="$4/home"
unset XDG_CONFIG_HOME
bash "$1/scripts/install-blender.sh" "$2" || exit 1
exec blender -b --python-exit-code 1 --python "$1/python/blender/tests/user_install_check.py" -- \
  "$3" "$4/out"
