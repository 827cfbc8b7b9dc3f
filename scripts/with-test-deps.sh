#!/usr/bin/env bash
# Runs a command (the Release build) while the test packages (install-deps.sh --tests: Blender,
# clang, pytest) install beside it: apt waits on the network and the disk, the compiler on the
# cores, so on a fresh machine the download costs no wall-clock time. Nothing the build does
# needs those packages; the tests that run after it do, so this script waits for the install
# and fails if either failed.
#   usage: with-test-deps.sh COMMAND [ARGS...]
# When apt would need a password (sudo without a cached credential), the install runs first, in
# the foreground, so that its prompt is not lost among the compiler's lines.
set -uo pipefail
here="$(cd "$(dirname "$0")" && pwd)"

if [ "$(id -u)" -ne 0 ] && ! sudo -n true 2>/dev/null; then
  bash "$here/install-deps.sh" --tests || exit 1
  exec "$@"
fi

log="$(mktemp -t animkit-test-deps.XXXXXX)"
trap 'rm -f "$log"' EXIT
bash "$here/install-deps.sh" --tests >"$log" 2>&1 &
install_pid=$!
"$@"
command_status=$?
wait "$install_pid"
install_status=$?
# The install's output after the build's, whole, rather than interleaved with it.
cat "$log"
if [ "$install_status" -ne 0 ]; then
  echo "with-test-deps: installing the test packages failed (exit $install_status)" >&2
  exit "$install_status"
fi
exit "$command_status"
