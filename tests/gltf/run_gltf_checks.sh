#!/bin/sh
# ctest's glTF checks of the files the CLI writes:
#   run_gltf_checks.sh files ANIMKIT_CLI DATA_DIR OUT_DIR
#       writes cloth.glb for every built-in cloth scene (their first frames) and fixed.glb,
#       reached.glb for the CMU walk into OUT_DIR (the other checks' fixture)
#   run_gltf_checks.sh validator OUT_DIR      the Khronos glTF Validator: 0 errors, 0 warnings
#   run_gltf_checks.sh threejs OUT_DIR        three.js against the point cache and the BVH
#   run_gltf_checks.sh blender OUT_DIR PYTHON_DIR   Blender 3.4's importer against the same
# Exit 77 (ctest's SKIP_RETURN_CODE) without Node.js, the npm packages (scripts/install-deps.sh
# --tests installs them) or Blender, except under CI (CI set), where a skip would hide them.
set -u
here="$(cd "$(dirname "$0")" && pwd)"
CMU_SCALE=0.056444
SCENES="lab drape-sphere tablecloth flag spinning-sphere fold"

skip() {
  if [ -n "${CI:-}" ]; then
    echo "$1 (make test installs it: scripts/install-deps.sh --tests)"
    exit 1
  fi
  echo "$1: skipped"
  exit 77
}

need_node() {
  command -v node >/dev/null 2>&1 || skip "node not found on PATH"
  [ -d "$here/node_modules/gltf-validator" ] && [ -d "$here/node_modules/three" ] ||
    skip "the npm packages gltf-validator and three are not in $here/node_modules"
}

case "$1" in
files)
  cli="$2" data="$3" out="$4"
  rm -rf "$out" && mkdir -p "$out" || exit 1
  for scene in $SCENES; do
    "$cli" cloth --scene "$scene" --frames 3 --no-picture --out "$out/$scene" >/dev/null || exit 1
  done
  walk="$data/cmu/131_01.bvh"
  [ -f "$walk" ] || { echo "$walk not found"; exit 1; }
  "$cli" footlock --in "$walk" --scale $CMU_SCALE --out "$out/walk" >/dev/null || exit 1
  "$cli" reach --in "$walk" --scale $CMU_SCALE --frame 0 --target 0.3 1.2 0.4 \
    --out "$out/reach" >/dev/null || exit 1
  ;;
validator)
  need_node
  # shellcheck disable=SC2046
  exec node "$here/validate.mjs" $(find "$2" -name '*.glb' | sort)
  ;;
threejs)
  need_node
  for scene in $SCENES; do
    node "$here/three_check.mjs" cloth "$2/$scene/cloth.glb" "$2/$scene/cloth.pc2" || exit 1
  done
  exec node "$here/three_check.mjs" skeleton "$2/walk/fixed.glb" "$2/walk/fixed.bvh" $CMU_SCALE
  ;;
blender)
  command -v blender >/dev/null 2>&1 || skip "blender not found on PATH"
  fps=$(python3 -c "import json,sys; print(round(1/json.load(open(sys.argv[1]))['options']['dt']))" \
    "$2/drape-sphere/metrics.json") || exit 1
  exec blender -b --factory-startup --python-exit-code 1 --python "$here/blender_check.py" -- \
    "$3" "$2/drape-sphere/cloth.glb" "$2/drape-sphere/cloth.pc2" "$fps" \
    "$2/walk/fixed.glb" "$2/walk/fixed.bvh" $CMU_SCALE
  ;;
*)
  echo "usage: run_gltf_checks.sh files|validator|threejs|blender ..."
  exit 2
  ;;
esac
