#!/bin/sh
# SPDX-License-Identifier: MIT
# wine-run (the Windows build's emulator) with /bin/sh in Wine's place and a program that
# fails to start its first N times, as Wine's rare failed starts do: a listing comes
# through its failed starts, once, and a run of the tests is started once, its failure
# left to ctest.
set -eu
wine_run="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cat >"$work/program" <<'PROGRAM'
# fails (exit 1, no output) while $work/failures counts down, then prints a listing
n="$(cat "$(dirname "$0")/failures")"
if [ "$n" -gt 0 ]; then echo $((n - 1)) >"$(dirname "$0")/failures"; exit 1; fi
echo "Suite."; echo "  One"
PROGRAM
fail() { echo "wine_run_test: $*" >&2; exit 1; }

echo 2 >"$work/failures"
listing="$("$wine_run" /bin/sh "$work/program" --gtest_list_tests 2>/dev/null)" ||
  fail "a listing that fails twice did not come through"
[ "$listing" = "$(printf 'Suite.\n  One')" ] || fail "the listing came through as: $listing"

echo 3 >"$work/failures"
if "$wine_run" /bin/sh "$work/program" --gtest_list_tests >/dev/null 2>&1; then
  fail "a listing that fails three times passed"
fi

echo 1 >"$work/failures"
if "$wine_run" /bin/sh "$work/program" --gtest_filter=Suite.One >/dev/null 2>&1; then
  fail "a run of tests was started again"
fi
[ "$(cat "$work/failures")" = 0 ] || fail "a run of tests was not started"
echo "wine-run: listings started again, runs not"
