#!/usr/bin/env bash
# Runs the benchmark programs whose output the performance page shows (docs/performance.md)
# and writes one JSON file per program into bench/results/ (Google Benchmark's own format, with
# the commit added to its context), then regenerates the page from them:
#
#   make bench    (or, after make build: bash scripts/run-benchmarks.sh [BUILD_DIR]; about 20
#                 minutes on 2 cores)
#
# BUILD_DIR is the Release tree (build/release by default). Close other programs first: the
# tables are only as steady as the machine was.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build/release}"
results=bench/results
mkdir -p "$results"
commit="$(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
if [ -n "$(git status --porcelain --untracked-files=no 2>/dev/null)" ]; then
  commit="$commit+changes"
fi

build_type="$(sed -n 's/^CMAKE_BUILD_TYPE:STRING=//p' "$build/CMakeCache.txt")"

# program, then its options: repetitions where one run is short, a filter where the whole
# program would take an hour (the drape's 101 x 101 runs).
run() {
  local program="$1"
  shift
  echo "== $program $*"
  "$build/bench/$program" --benchmark_out="$results/$program.json.tmp" \
    --benchmark_out_format=json --benchmark_context="commit=$commit,animkit_build=$build_type" "$@"
  if ! grep -q '"run_name"' "$results/$program.json.tmp"; then
    echo "run-benchmarks: $program ran no benchmark (a filter that matches none?)" >&2
    rm -f "$results/$program.json.tmp"
    exit 1
  fi
  mv "$results/$program.json.tmp" "$results/$program.json"
}

run ik_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
run tree_ik_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
run footlock_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
run cloth_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
run multigrid_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
run parallel_bench
run fast_collider_bench
run broad_phase_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
run scenes_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
run drape_bench --benchmark_filter='^drape/(animkit/41x41(/fast)?|bullet/41x41)/iterations'
python3 scripts/performance-page.py "$results" docs/performance.md
echo "wrote $results/*.json and docs/performance.md"
