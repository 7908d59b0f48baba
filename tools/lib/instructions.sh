# SPDX-License-Identifier: MIT
# instructions_suite BINARY [--leaves=N]: the deep grasp's steps counted in instructions
# under callgrind, as one JSON document: per-step percentiles over every step, and where
# the work went by stage, over every step and over the steps at or above the p99.
# Stages are inclusive counts of the functions that do them (stage_profile): the tree
# walks are part of the detection, linearisations, QPs and trials part of the stages
# (the QPs' count is the palm's and the fingers' together); the clearances are every
# body's exact gap over all its candidates: each sub-step's start, and the trials that
# check every candidate (a step kept beyond its rows' radius, a bisection), which the
# trials' count holds too.

# stage_profile FILE...: "name": instructions for each stage, summed over callgrind dumps
stage_profile() {
  local f
  # a build with debug information splits a function's row by the files inlined into it,
  # its own file's row holding the whole: the largest row of each dump is the function's
  for f in "$@"; do
    callgrind_annotate --inclusive=yes --threshold=100 --auto=no "$f" 2>/dev/null | awk '
      $2 ~ /^\(/ { n = $1; gsub(",", "", n); n += 0; sub(/^ *[0-9,]+ +\([^)]*\) +/, ""); sub(/ \[[^]]*\]$/, "")
                   sub(/^[^:]*:/, ""); if (n > most[$0]) most[$0] = n }
      END { for (fn in most) printf "%d (x) :%s\n", most[fn], fn }'
  done | awk '
    function add(name, n) { total[name] += n }
    $2 ~ /^\(/ {
      n = $1; gsub(",", "", n); line = $0
      if (line ~ /:frusta::HandSolver::step\(/) add("step", n)
      else if (line ~ /:frusta::CandidateCache::detect\(/) add("detection", n)
      else if (line ~ /:frusta::query_segment(_loose)?\(|namespace\)::detect_palm\(/) add("tree_walks", n)
      else if (line ~ /frusta::solve_stage<frusta::PalmStage>/) add("palm_stages", n)
      else if (line ~ /frusta::solve_stage<frusta::FingerStage>/) add("finger_stages", n)
      else if (line ~ /:frusta::FingerStage::linearise\(/) add("finger_linearise", n)
      else if (line ~ /:frusta::solve_projection_qp\(/) add("qp", n)
      else if (line ~ /:frusta::FingerStage::try_(step|step_anywhere|between)\(/) add("finger_trials", n)
      else if (line ~ /:frusta::body_clearance\(/) add("clearances", n)
      else if (line ~ /:frusta::HandSolver::report_contacts\(/) add("report_contacts", n)
    }
    END {
      split("step detection tree_walks palm_stages finger_stages finger_linearise qp finger_trials clearances report_contacts", order, " ")
      for (i = 1; i <= 10; ++i) printf "%s\"%s\": %d", (i > 1 ? ", " : ""), order[i], total[order[i]]
    }'
}

instructions_suite() {
  local binary=$1; shift
  if [ ! -x "$binary" ]; then  # configured before valgrind's header was there
    echo "frusta: $binary was not built; reconfigure its tree (cmake $(dirname "$(dirname "$binary")"))" >&2
    return 2
  fi
  local dir; dir=$(mktemp -d)
  valgrind --tool=callgrind --collect-atstart=no --callgrind-out-file="$dir/step" \
    "$binary" "$@" > "$dir/run.json" 2> "$dir/valgrind.log" || { cat "$dir/valgrind.log" >&2; rm -rf "$dir"; return 1; }
  valgrind --tool=callgrind --collect-atstart=no --callgrind-out-file="$dir/whole" \
    "$binary" "$@" --whole > /dev/null 2>> "$dir/valgrind.log" || { cat "$dir/valgrind.log" >&2; rm -rf "$dir"; return 1; }
  # each dump: its step's instructions (summary) and the file
  local f
  for f in "$dir"/step.*; do echo "$(sed -n 's/^summary: //p' "$f") $f"; done | sort -n > "$dir/steps"
  local n p50 p90 p99 max total
  n=$(wc -l < "$dir/steps")
  read -r p50 p90 p99 max total < <(awk -v n="$n" '{ a[NR] = $1; s += $1 }
    END { printf "%d %d %d %d %d\n", a[int(n * 0.5) + 1], a[int(n * 0.9) + 1], a[int(n * 0.99) + 1], a[n], s }' "$dir/steps")
  local tail=() ir f
  while read -r ir f; do if [ "$ir" -ge "$p99" ]; then tail+=("$f"); fi; done < "$dir/steps"
  local run; run=$(sed 's/^{//; s/}$//' "$dir/run.json")
  echo "{\"suite\": \"instructions\", $run, \"ir_per_step\": {\"p50\": $p50, \"p90\": $p90, \"p99\": $p99," \
       "\"max\": $max, \"total\": $total}, \"profile_every_step\": {$(stage_profile "$dir/whole")}," \
       "\"profile_steps_at_or_above_p99\": {\"steps\": ${#tail[@]}, $(stage_profile "${tail[@]}")}}"
  rm -rf "$dir"
}
