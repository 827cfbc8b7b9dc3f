#!/bin/sh
# Runs one of the add-on's headless tests in Blender: exit 77 (ctest's SKIP_RETURN_CODE) without
# Blender, except under CI (CI set), where a missing Blender is a failure, not a skip.
#   usage: run_blender_test.sh SCRIPT ARGS...   (ARGS reach the script after "--")
set -u
. "$(dirname "$0")/../../../tests/support/require_tools.sh"
require_tools blender
script="$1"
shift
exec blender -b --factory-startup --python-exit-code 1 --python "$script" -- "$@"
