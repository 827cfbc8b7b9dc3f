#!/bin/sh
# Runs one of the add-on's tests in a Blender with a window (on Xvfb's virtual display), for
# what background mode cannot do: modal operators and keyboard events (Blender's
# --enable-event-simulate lets the script send them). Exit 77 (ctest's SKIP_RETURN_CODE)
# without Blender or xvfb-run, except under CI (CI set), where that is a failure.
#   usage: run_blender_window_test.sh SCRIPT ARGS...   (ARGS reach the script after "--")
set -u
. "$(dirname "$0")/../../../tests/support/require_tools.sh"
require_tools blender xvfb-run
script="$1"
shift
exec xvfb-run -a blender --factory-startup --enable-event-simulate --python-exit-code 1 \
  --python "$script" -- "$@"
