#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# tools/bench paired with this build as both halves: the halves link into one binary
# holding both solvers (half b's symbols renamed), each steps the grasp of a small ball
# through every step of two runs, and, being the same build, they make the same hands
# and contacts to the bit.
set -euo pipefail
ROOT="$1"
build="$2"
out="$3"
source "$ROOT/tools/lib/paired.sh"
paired_link "$ROOT" "$build" "$ROOT" "$build" "$out"
# both builds' solvers are in the binary, each under its own name
symbols="$(nm "$out")"
for space in 6frusta 6frustb; do
  grep -q " [tT] _ZN${space}10HandSolver4step" <<<"$symbols" ||
    { echo "paired_test: no HandSolver::step of namespace $space in $out" >&2; exit 1; }
done
json="$("$out" 2 100)"
PYTHONPATH="$(dirname "$0")/.." python3 - "$json" <<'PYTHON'
from suite_document import document
d, check = document("paired_test")
check(d["suite"] == "paired" and d["scene"] == "ball_grasp" and d["leaves"] == 100, "the suite and its ball")
check(d["steps"] == 500 and d["runs"] == 2, "every step of both runs")
for half in ("a", "b"):
    h = d[half]
    check(0 <= h["p50_us"] <= h["p99_us"] <= h["max_us"] <= h["sum_us"], f"half {half}'s figures in order")
check(d["same_hands"] is True, "one build in both halves makes the same hands")
check(d["b_over_a_dearest_30_q25"] <= d["b_over_a_dearest_30_median"] <= d["b_over_a_dearest_30_q75"],
      "the ratios' quartiles in order")
check(d["b_over_a_sum"] > 0, "the sums' ratio")
PYTHON
