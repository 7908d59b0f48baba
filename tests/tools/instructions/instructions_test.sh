#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# tools/bench instructions on a small ball (the real bench binary under valgrind): one
# JSON document whose per-step percentiles (instructions, mispredicted branches) are in
# order, whose stages lie within what holds them, and whose steps counted one by one add
# up to the whole run's count.
set -euo pipefail
lib="$1"
binary="$2"
source "$lib"
json="$(instructions_suite "$binary" --leaves=100)"
PYTHONPATH="$(dirname "$0")/.." python3 - "$json" <<'PYTHON'
from suite_document import document
d, check = document("instructions_test")
check(d["suite"] == "instructions" and d["leaves"] == 100, "the suite and its ball")
check(d["steps"] == 500 and d["failed_steps"] == 0 and d["under_callgrind"], "every step ran, counted")
s = d["ir_per_step"]
check(0 < s["p50"] <= s["p90"] <= s["p99"] <= s["max"] <= s["total"], "percentiles in order")
m = d["mispredicted_per_step"]
check(0 < m["p50"] <= m["p90"] <= m["p99"] <= m["max"] <= m["total"] < s["total"],
      "mispredicted branches' percentiles in order, fewer than the instructions")
check(0 < d["profile_steps_at_or_above_p99"]["mispredicted"] <= m["total"],
      "the costliest steps' mispredicted branches within every step's")
for name in ("profile_every_step", "profile_steps_at_or_above_p99"):
    p = d[name]
    check(p["step"] > 0, f"{name}: steps counted")
    check(p["tree_walks"] <= p["detection"] <= p["step"], f"{name}: walks within detection within steps")
    check(p["finger_linearise"] + p["finger_trials"] <= p["finger_stages"] <= p["step"],
          f"{name}: linearisations and trials within the finger stages")
    check(p["report_contacts"] + p["detection"] + p["finger_stages"] + p["palm_stages"] <= p["step"],
          f"{name}: stages within steps")
every, tail = d["profile_every_step"], d["profile_steps_at_or_above_p99"]
# the finger segments' walks are counted (a third of the detection here; a renamed walk
# once dropped out of the profile, leaving the palm's, a four-hundredth)
check(every["tree_walks"] >= 0.1 * every["detection"], "the segments' walks counted")
check(tail["steps"] >= 5, "the steps at or above the p99 of 500")
check(all(tail[k] <= every[k] for k in every), "the costliest steps within every step")
# the same steps, counted one by one and in one dump: only the counting's own requests differ
check(abs(s["total"] - every["step"]) <= 0.01 * every["step"], "steps one by one and whole")
PYTHON
