"""Checks that every test of a build tree belongs to one test tier and has a timeout within
that tier's bound (cmake/test_tiers.cmake): a test that is not labelled `slow` may run for at
most the build's ANIMKIT_TEST_TIMEOUT seconds, so no minute-long test hides in `make check` or
in the sanitizer suite.

Usage: check_test_tiers.py CTEST BUILD_DIR TEST_TIMEOUT SLOW_TEST_TIMEOUT
Reads `ctest --show-only=json-v1` (https://cmake.org/cmake/help/v3.25/manual/ctest.1.html).
"""
import json
import subprocess
import sys

TIERS = {"fast", "slow", "cli", "render", "python", "blender", "fuzz"}


def main() -> int:
    ctest, build_dir, test_timeout, slow_timeout = sys.argv[1], sys.argv[2], *map(float, sys.argv[3:5])
    listing = subprocess.run([ctest, "--show-only=json-v1"], cwd=build_dir, check=True,
                             capture_output=True, text=True).stdout
    problems = []
    counts = {tier: 0 for tier in TIERS}
    for test in json.loads(listing)["tests"]:
        if test["name"].endswith("_NOT_BUILT"):
            continue  # GoogleTest's stand-in for a test binary not built yet (`make check`)
        properties = {p["name"]: p["value"] for p in test.get("properties", [])}
        labels = set(properties.get("LABELS", []))
        tiers = labels & TIERS
        if len(tiers) != 1:
            problems.append(f"{test['name']}: labels {sorted(labels)}, want one of {sorted(TIERS)}")
            continue
        tier = tiers.pop()
        counts[tier] += 1
        bound = slow_timeout if tier == "slow" else test_timeout
        timeout = properties.get("TIMEOUT")
        if timeout is None or not 0 < float(timeout) <= bound:
            problems.append(f"{test['name']}: timeout {timeout} s in tier {tier}, want at most {bound:g} s")
    print("tests per tier:", ", ".join(f"{t} {n}" for t, n in sorted(counts.items())))
    for problem in problems:
        print(problem)
    if counts["fast"] == 0:
        problems.append("no test in the fast tier")
        print("no test in the fast tier")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
