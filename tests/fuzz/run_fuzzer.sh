#!/bin/sh
# SPDX-License-Identifier: MIT
# run_fuzzer.sh FUZZER WORKDIR [libFuzzer options...] [seed folders...]: runs FUZZER for
# $FRUSTA_FUZZ_SECONDS (default 60) on WORKDIR/corpus (kept between runs) and the seeds,
# then prints libFuzzer's final figures, or its report and the crashing input on a finding.
# A hang (-timeout) or a blow-up (-rss_limit_mb) counts as a finding too.
set -u
fuzzer="$1" work="$2"
shift 2
mkdir -p "$work/corpus" "$work/artifacts"
seconds="${FRUSTA_FUZZ_SECONDS:-60}"
log="$work/log.txt"
echo "fuzz: $(basename "$fuzzer") for ${seconds} s; log $log"
"$fuzzer" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -print_final_stats=1 \
  -artifact_prefix="$work/artifacts/" "$work/corpus" "$@" 2>"$log"
status=$?
if [ "$status" -ne 0 ]; then
  tail -n 60 "$log"
  echo "fuzz: $(basename "$fuzzer") FOUND a problem (exit $status); inputs: $(ls "$work/artifacts")"
  exit "$status"
fi
grep -E '^#[0-9]+[[:space:]]+DONE' "$log" | tail -n 1
grep -E '^stat::(number_of_executed_units|average_exec_per_sec|new_units_added|peak_rss_mb)' "$log"
echo "fuzz: $(basename "$fuzzer"): corpus $(ls "$work/corpus" | wc -l) files, no crash"
