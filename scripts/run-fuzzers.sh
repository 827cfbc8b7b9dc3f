#!/usr/bin/env bash
# Runs every fuzz target built in BUILD_DIR (default build/sanitize) for SECONDS (default 60) each:
# over a scratch copy of fuzz/corpus/<name>/ (the repository's corpus does not grow) plus the
# kept crash inputs in fuzz/regressions/<name>/. Crash inputs go to BUILD_DIR/crashes/<name>/,
# logs to BUILD_DIR/logs/<name>.log. A crash counts when its input crashes again run on its
# own; one that does not is reported with its input and does not fail the run. Exits 1 after
# all targets ran if any crash counted, naming each target, its input file, the input in base64
# and the fault's first lines. FUZZ_SEED=N fixes libFuzzer's random seed (CI does); a crash CI
# found with it has still not always come back elsewhere, hence the base64.
# FUZZ_JOBS targets (default: one a core) run at once; each fuzzer is one process on one core.
set -uo pipefail
build="${1:-build/sanitize}"
seconds="${2:-60}"
jobs="${FUZZ_JOBS:-$(nproc)}"
root="$(cd "$(dirname "$0")/.." && pwd)"
results="$build/results"
rm -rf "$results"
mkdir -p "$results"

# The lines that say what went wrong: a broken promise (fuzz_check.h), a sanitizer's report, an
# assertion, an exception nothing caught, libFuzzer's own verdict.
faults='fuzz check failed|==ERROR|ERROR: libFuzzer|runtime error|Assertion|terminate called|what\(\)'

# Fuzzes one target; prints what it found and, after a crash, leaves its summary lines in
# $results/<target> (a failure) or $results/unrepeated-<target> (its input ran clean alone).
fuzz_target() {
  local target="$1"
  local name="${target%_fuzz}"
  local binary="$build/fuzz/$target"
  if [ ! -x "$binary" ]; then
    echo "$target: not built ($binary)" >"$results/$target"
    return
  fi
  local work="$build/work/$name"
  local crashes="$build/crashes/$name"
  local log="$build/logs/$name.log"
  rm -rf "$work"
  mkdir -p "$work" "$crashes" "$(dirname "$log")"
  if [ -d "$root/fuzz/corpus/$name" ]; then cp -R "$root/fuzz/corpus/$name/." "$work/"; fi
  local inputs=("$work")
  if [ -d "$root/fuzz/regressions/$name" ]; then inputs+=("$root/fuzz/regressions/$name"); fi
  local seed=()
  if [ -n "${FUZZ_SEED:-}" ]; then seed=(-seed="$FUZZ_SEED"); fi
  echo "fuzz: $target for ${seconds} s ..."
  # -timeout: an input taking 10 s is a hang, reported like a crash. -rss_limit_mb and
  # -malloc_limit_mb: asking for more than 2 GB is a bug (a header trusted too far).
  ASAN_SYMBOLIZER_PATH="$(command -v llvm-symbolizer-16 || command -v llvm-symbolizer || true)" \
    "$binary" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=2048 \
    -artifact_prefix="$crashes/" -print_final_stats=1 "${seed[@]}" "${inputs[@]}" >"$log" 2>&1
  local status=$?
  local runs
  runs="$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$')"
  if [ "$status" -ne 0 ]; then
    local input details=""
    input="$(grep -o 'Test unit written to .*' "$log" | tail -n 1 | sed 's/Test unit written to //')"
    # The input itself, so a failure seen only in a CI log can be replayed elsewhere.
    if [ -n "$input" ] && [ -f "$input" ] && [ "$(stat -c %s "$input")" -le 4096 ]; then
      details="    the input, base64: $(base64 -w 0 "$input")"$'\n'
      details+="$(grep -m 2 -E "$faults" "$log" | sed 's/^/    /')"
    fi
    echo "fuzz: $target crashed:"
    grep -m 1 -A 12 -E "$faults" "$log" |
      sed 's/^/  /'
    # A crash is a failure when its input crashes again on its own (with the same limits: a
    # hang hangs again), as a failing test is when it fails twice (the Makefile's
    # test-sanitize): LeakSanitizer's tracer, which libFuzzer's leak checks also run, has
    # crashed once in a passing test.
    local result="$results/$target"
    if [ -n "$input" ] && [ -f "$input" ] &&
      "$binary" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=2048 "$input" \
        >"$log.replay" 2>&1; then
      echo "fuzz: $target: its input ran clean on its own ($log.replay): reported, not failed"
      result="$results/unrepeated-$target"
      echo "$target: a crash its input does not repeat: $input (exit $status; log $log)" >"$result"
    else
      echo "$target: ${input:-no input written} (exit $status; log $log)" >"$result"
    fi
    [ -z "$details" ] || echo "$details" >>"$result"
  else
    echo "fuzz: $target: ${runs:-?} inputs, no crash"
  fi
}

for source in "$root"/fuzz/*_fuzz.cpp; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n; done
  fuzz_target "$(basename "$source" .cpp)" &
done
wait

failures=()
unrepeated=()
for result in "$results"/*; do
  [ -e "$result" ] || continue
  case "$(basename "$result")" in
    unrepeated-*) unrepeated+=("$(cat "$result")") ;;
    *) failures+=("$(cat "$result")") ;;
  esac
done
if [ ${#unrepeated[@]} -gt 0 ]; then
  echo "fuzz: crashes whose inputs ran clean on their own (look into them; not failures):" >&2
  printf '  %s\n' "${unrepeated[@]}" >&2
fi
if [ ${#failures[@]} -gt 0 ]; then
  echo "fuzz: FAILED" >&2
  printf '  %s\n' "${failures[@]}" >&2
  echo "Keep each input as a regression: fix the bug, then copy it to fuzz/regressions/<name>/." >&2
  exit 1
fi
if [ ${#unrepeated[@]} -gt 0 ]; then
  echo "fuzz: every target ran ${seconds} s; no crash repeated on its own input"
else
  echo "fuzz: every target ran ${seconds} s without a crash"
fi
