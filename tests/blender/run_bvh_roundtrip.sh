#!/bin/sh
# ctest's BvhBlenderRoundTrip: animkit writes a BVH and the positions it expects, Blender
# imports the file and compares. Exit 77 (ctest SKIP_RETURN_CODE) without Blender or the data,
# except under CI (CI set), where `make test` has installed Blender: there a skip would hide it.
#   usage: run_bvh_roundtrip.sh FIXTURE IN.bvh OUT_DIR CHECK_SCRIPT
set -u
. "$(dirname "$0")/../support/require_tools.sh"
require_tools blender
if [ ! -f "$2" ]; then
  echo "$2 not found: skipped"
  exit 77
fi
"$1" "$2" "$3" || exit 1
exec blender -b --factory-startup --python-exit-code 1 --python "$4" -- \
  "$3/roundtrip.bvh" "$3/roundtrip.json"
