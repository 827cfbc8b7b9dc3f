#!/bin/sh
# Runs one of the add-on's headless tests in Blender: exit 77 (ctest's SKIP_RETURN_CODE) without
# Blender, except under CI (CI set), where a missing Blender is a failure, not a skip.
#   usage: run_blender_test.sh SCRIPT ARGS...   (ARGS reach the script after "--")
set -u
if ! command -v blender >/dev/null 2>&1; then
  if [ -n "${CI:-}" ]; then
    echo "blender not found on PATH (make test installs it: scripts/install-deps.sh --tests)"
    exit 1
  fi
  echo "blender not found on PATH: skipped"
  exit 77
fi
script="$1"
shift
exec blender -b --factory-startup --python-exit-code 1 --python "$script" -- "$@"
