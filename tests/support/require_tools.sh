# Sourced by the test scripts that start programs `make test` installs (Blender, xvfb-run):
# `require_tools TOOL...` returns when every one is on PATH; otherwise it exits 77 (ctest's
# SKIP_RETURN_CODE), except under CI (CI set), where make test has installed them and a skip
# would hide the gap: there it exits 1.
require_tools() {
  for tool in "$@"; do
    if ! command -v "$tool" >/dev/null 2>&1; then
      if [ -n "${CI:-}" ]; then
        echo "$tool not found on PATH (make test installs it: scripts/install-deps.sh --tests)"
        exit 1
      fi
      echo "$tool not found on PATH: skipped"
      exit 77
    fi
  done
}
