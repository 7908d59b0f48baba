#!/bin/sh
# SPDX-License-Identifier: MIT
# wine-run (the Windows build's emulator) with /bin/sh in Wine's place and a program that
# fails to start its first N times, as Wine's rare failed starts do: a listing comes
# through its failed starts, once, and a run of the tests is started once, its failure
# left to ctest; with --again-if-silent a run comes through its silent failed starts,
# and a failure that prints anything is not started again.
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

# --again-if-silent (tools/test's single starts): any start that failed without output
echo 2 >"$work/failures"
out="$("$wine_run" --again-if-silent /bin/sh "$work/program" --run 2>/dev/null)" ||
  fail "a run that failed twice without output did not come through"
[ "$out" = "$(printf 'Suite.\n  One')" ] || fail "the run's output came through as: $out"
echo 3 >"$work/failures"
if "$wine_run" --again-if-silent /bin/sh "$work/program" --run >/dev/null 2>&1; then
  fail "a run that failed three times passed"
fi
cat >"$work/loud" <<'LOUD'
# fails, saying why, while $work/failures counts down
n="$(cat "$(dirname "$0")/failures")"
echo $((n - 1)) >"$(dirname "$0")/failures"
echo "it failed" >&2
exit 3
LOUD
echo 2 >"$work/failures"
status=0
said="$("$wine_run" --again-if-silent /bin/sh "$work/loud" 2>&1 >/dev/null)" || status=$?
[ "$status" = 3 ] || fail "a failure that said why ended with $status, not its own 3"
[ "$said" = "it failed" ] || fail "a failure that said why came through as: $said"
[ "$(cat "$work/failures")" = 1 ] || fail "a failure that said why was started again"
echo "wine-run: listings and silent failures started again, runs and failures that speak not"
