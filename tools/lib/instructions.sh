# SPDX-License-Identifier: MIT
# instructions_suite BINARY [--leaves=N]: the deep grasp's steps counted in instructions
# under callgrind, as one JSON document: per-step percentiles over every step, and where
# the work went by stage, over every step and over the steps at or above the p99. Beside
# the instructions, the branches callgrind's branch predictor mispredicts, per step and
# over those costliest steps: a count that a change trading predictable instructions for
# mispredicted branches moves the other way (a walk that reported its leaves without a
# branch per child ran 12 % faster on 6 % more instructions; what one costs depends on the
# work behind it, so the time is still the measure).
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
    callgrind_annotate --inclusive=yes --show=Ir --threshold=100 --auto=no "$f" 2>/dev/null | awk '
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

# column_percentiles FILE COLUMN: a column's p50, p90, p99, max and sum over FILE's lines,
# as a JSON object
column_percentiles() {
  sort -n -k "$2,$2" "$1" | awk -v c="$2" '{ a[NR] = $c; s += $c }
    END { printf "{\"p50\": %d, \"p90\": %d, \"p99\": %d, \"max\": %d, \"total\": %d}",
          a[int(NR * 0.5) + 1], a[int(NR * 0.9) + 1], a[int(NR * 0.99) + 1], a[NR], s }'
}

instructions_suite() {
  local binary=$1; shift
  if [ ! -x "$binary" ]; then  # configured before valgrind's header was there
    echo "frusta: $binary was not built; reconfigure its tree (cmake $(dirname "$(dirname "$binary")"))" >&2
    return 2
  fi
  local dir; dir=$(mktemp -d)
  valgrind --tool=callgrind --branch-sim=yes --collect-atstart=no --callgrind-out-file="$dir/step" \
    "$binary" "$@" > "$dir/run.json" 2> "$dir/valgrind.log" || { cat "$dir/valgrind.log" >&2; rm -rf "$dir"; return 1; }
  valgrind --tool=callgrind --collect-atstart=no --callgrind-out-file="$dir/whole" \
    "$binary" "$@" --whole > /dev/null 2>> "$dir/valgrind.log" || { cat "$dir/valgrind.log" >&2; rm -rf "$dir"; return 1; }
  # each dump: its step's instructions and mispredicted branches (summary: Ir Bc Bcm Bi
  # Bim, conditional and indirect) and the file
  local f
  for f in "$dir"/step.*; do
    sed -n 's/^summary: //p' "$f" | awk -v f="$f" '{ print $1, $3 + $5, f }'
  done | sort -n > "$dir/steps"
  local p99
  p99=$(awk -v n="$(wc -l < "$dir/steps")" 'NR == int(n * 0.99) + 1 { print $1 }' "$dir/steps")
  local tail=() ir missed tail_missed=0
  while read -r ir missed f; do
    if [ "$ir" -ge "$p99" ]; then tail+=("$f"); tail_missed=$((tail_missed + missed)); fi
  done < "$dir/steps"
  local run; run=$(sed 's/^{//; s/}$//' "$dir/run.json")
  echo "{\"suite\": \"instructions\", $run, \"ir_per_step\": $(column_percentiles "$dir/steps" 1)," \
       "\"mispredicted_per_step\": $(column_percentiles "$dir/steps" 2), \"profile_every_step\": {$(stage_profile "$dir/whole")}," \
       "\"profile_steps_at_or_above_p99\": {\"steps\": ${#tail[@]}, \"mispredicted\": $tail_missed," \
       "$(stage_profile "${tail[@]}")}}"
  rm -rf "$dir"
}
