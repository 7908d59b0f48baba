# SPDX-License-Identifier: MIT
# tools/bench paired: two builds of the solver linked into one binary, their steps
# alternated one by one (tests/benchmark/paired). This machine runs the same arithmetic
# 1.25-1.6 times slower in phases of a few milliseconds, so the same build's p99 moved by
# a fifth between runs minutes apart; alternated step by step, both builds meet the same
# phases. Half a is built as it is; half b's libraries have every symbol of namespace
# frusta renamed to frustb (same length, so mangled names stay well formed), and its half
# of the driver is compiled with against its own headers.

# the libraries a half links, under its build tree, and their targets
PAIRED_LIBRARIES=(tests/libfrusta_hand_scenarios.a native/libfrusta_engine.a
                  samples/meshes/libfrusta_sample_meshes.a native/libfrusta_bake_core.a
                  native/libfrusta_base.a)
# (and the baked sample objects the named scenes load: revisions before 2026-12-07 did not
# make the scenarios' library wait for them, and --scene=slide found no tree to load)
PAIRED_TARGETS=(frusta_hand_scenarios frusta_engine frusta_sample_meshes frusta_bake_core frusta_base
                frusta_sample_objects)

# paired_link ROOT_A BUILD_A ROOT_B BUILD_B OUT: OUT, the binary (OUT.d its scratch)
paired_link() {
  local root_a=$1 build_a=$2 root_b=$3 build_b=$4 out=$5
  local scratch="$out.d" lib
  rm -rf "$scratch"
  mkdir -p "$scratch/b"
  for lib in "${PAIRED_LIBRARIES[@]}"; do
    [ -f "$build_a/$lib" ] && [ -f "$build_b/$lib" ] || { echo "frusta: $lib is not built in both trees" >&2; return 2; }
  done
  local driver="$ROOT/tests/benchmark/paired"
  # the same flags as the builds (CMakeLists.txt: no contraction into multiply-adds)
  local flags=(-O2 -DNDEBUG -ffp-contract=off -std=c++17)
  g++ "${flags[@]}" -DFRUSTA_PAIRED_HALF=_a -I"$root_a/native/src" -I"$root_a/tests" \
      -c "$driver/paired_half.cpp" -o "$scratch/half_a.o"
  g++ "${flags[@]}" -DFRUSTA_PAIRED_HALF=_b -Dfrusta=frustb -I"$root_b/native/src" -I"$root_b/tests" \
      -c "$driver/paired_half.cpp" -o "$scratch/half_b.o"
  g++ "${flags[@]}" -I"$ROOT/tests" -c "$driver/paired_main.cpp" -o "$scratch/main.o"
  for lib in "${PAIRED_LIBRARIES[@]}"; do nm "$build_b/$lib" 2>/dev/null | awk '{print $NF}'; done |
    grep '6frusta' | sort -u | awk '{ b = $1; gsub(/6frusta/, "6frustb", b); print $1, b }' > "$scratch/renames"
  local libs_a=() libs_b=()
  for lib in "${PAIRED_LIBRARIES[@]}"; do
    libs_a+=("$build_a/$lib")
    objcopy --redefine-syms="$scratch/renames" "$build_b/$lib" "$scratch/b/$(basename "$lib")"
    libs_b+=("$scratch/b/$(basename "$lib")")
  done
  g++ "$scratch/main.o" "$scratch/half_a.o" "${libs_a[@]}" "$scratch/half_b.o" "${libs_b[@]}" \
      -lembree3 -lpthread -o "$out"
}
