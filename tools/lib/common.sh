# SPDX-License-Identifier: MIT
# Shared by tools/demo, tools/test and tools/bench: install what is missing, then
# configure and build one CMake tree. Source it; it sets ROOT.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"

# Debian packages the build needs (docs: /work/shared/deps.md, README "Dependencies");
# python3 runs the C# binding's generator and the test that it is up to date; valgrind
# counts the instructions of tools/bench instructions (and its test).
FRUSTA_PACKAGES=(cmake ninja-build g++ pkg-config python3 ccache libglm-dev libhidapi-dev
                 libembree-dev libtinygltf-dev nlohmann-json3-dev libbenchmark-dev libgtest-dev
                 valgrind)

# ensure_packages [PACKAGE...]: those (default: FRUSTA_PACKAGES) installed
ensure_packages() {
  local wanted=("$@") missing=() p
  [ ${#wanted[@]} -eq 0 ] && wanted=("${FRUSTA_PACKAGES[@]}")
  for p in "${wanted[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  local line="apt-get install -y --no-install-recommends ${missing[*]}"
  if [ "$(id -u)" -ne 0 ]; then
    echo "frusta: missing Debian packages. As root, run:" >&2
    echo "  apt-get update && $line" >&2
    exit 1
  fi
  echo "frusta: installing ${missing[*]}" >&2
  DEBIAN_FRONTEND=noninteractive apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $line -qq >/dev/null
}

# Linux arm64 cross builds: Debian's cross compiler, qemu to run the tests, and the
# arm64 builds of the libraries (multiarch; GLM is header-only, shared with the host)
FRUSTA_ARM64_PACKAGES=(g++-aarch64-linux-gnu qemu-user-static libhidapi-dev:arm64
                       libgtest-dev:arm64 libbenchmark-dev:arm64)

ensure_arm64_packages() {
  if ! dpkg --print-foreign-architectures | grep -qx arm64; then
    [ "$(id -u)" -eq 0 ] || { echo "frusta: as root, run: dpkg --add-architecture arm64" >&2; exit 1; }
    dpkg --add-architecture arm64
    DEBIAN_FRONTEND=noninteractive apt-get update -qq
  fi
  ensure_packages "${FRUSTA_ARM64_PACKAGES[@]}"
}

# host_objects HOST_DIR: sets HOST_OBJECTS, the cmake arguments that point a build at
# the sample objects and test boxes the build in HOST_DIR baked (cross builds have no
# baker; sanitizer builds would bake for minutes)
host_objects() {
  HOST_OBJECTS=(-DFRUSTA_SAMPLE_OBJECTS_DIR="$ROOT/$1/samples/objects"
                -DFRUSTA_TEST_OBJECTS_DIR="$ROOT/$1/tests/objects")
}

# Cross trees are run (qemu, Wine) and packed stripped, never debugged here: their
# RelWithDebInfo goes without the debug info, which cost a third of their compile time
# and most of MinGW's link (the code is the same: -O2, NDEBUG)
FRUSTA_CROSS_FLAGS=("-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O2 -DNDEBUG"
                    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -DNDEBUG")

# build_arm64_tree DIR BUILD_TYPE [cmake args...]: the runtime, tests and benchmarks for
# Linux arm64, without the baker (no Embree there); pass host_objects' arguments, the
# objects a host build baked. Builds $FRUSTA_BUILD_TARGETS when set.
build_arm64_tree() {
  local dir="$1" type="$2"
  shift 2
  build_tree "$dir" "$type" \
    -DCMAKE_TOOLCHAIN_FILE="$ROOT/native/cmake/toolchains/aarch64-linux-gnu.cmake" \
    -DFRUSTA_BUILD_BAKER=OFF -DFRUSTA_BUILD_SAMPLES=OFF "${FRUSTA_CROSS_FLAGS[@]}" "$@"
}

# run_arm64 PROGRAM [args...]: an arm64 program under qemu
run_arm64() {
  qemu-aarch64-static -L /usr/aarch64-linux-gnu "$@"
}

# Windows x64 cross builds: Debian's mingw-w64 (posix threads, for std::thread) and
# Wine to run the tests. hidapi has no MinGW package in Debian: its Debian source is
# built for Windows by build_windows_libraries.
FRUSTA_WINDOWS_PACKAGES=(g++-mingw-w64-x86-64-posix wine64 make bzip2)
FRUSTA_WINDOWS_TOOLCHAIN="$ROOT/native/cmake/toolchains/x86_64-w64-mingw32.cmake"
FRUSTA_WINE_DIR=/usr/lib/wine  # Debian's wine64 puts wine64 and wineserver here, not on PATH

ensure_windows_packages() {
  ensure_packages "${FRUSTA_WINDOWS_PACKAGES[@]}"
}

# deb_src_sources DIR: the deb-src twin of every source the machine's apt uses (the
# same URIs, suites, components and keys, one-line and deb822 files alike), written
# into DIR, so sources come from wherever this machine gets its packages
deb_src_sources() {
  local dir="$1" SOURCELIST SOURCEPARTS f
  eval "$(apt-config shell SOURCELIST Dir::Etc::sourcelist/f SOURCEPARTS Dir::Etc::sourceparts/d)"
  for f in "$SOURCELIST" "$SOURCEPARTS"*.list; do
    [ -f "$f" ] || continue
    sed -n 's/^[[:space:]]*deb[[:space:]]/deb-src /p' "$f" >"$dir/$(basename "$f" .list)-src.list"
  done
  for f in "$SOURCEPARTS"*.sources; do
    [ -f "$f" ] || continue
    # paragraph by paragraph: binary types become deb-src, disabled ones stay out
    awk 'BEGIN { RS = ""; ORS = "\n\n" }
         /(^|\n)Enabled:[[:space:]]*no/ { next }
         /(^|\n)Types:[^\n]*deb([[:space:]]|$)/ { sub(/Types:[^\n]*/, "Types: deb-src"); print }' \
      "$f" >"$dir/$(basename "$f" .sources)-src.sources"
  done
}

# fetch_debian_source DIR PACKAGE=VERSION: a Debian source package's upstream tarball
# (checked against the signed index) into DIR, through a private source list: the
# machine's apt configuration is left as it was. The tarball only: the builds here
# apply no Debian patch, and a mirror may lack the .debian.tar (embree's did)
fetch_debian_source() {
  local work="$1" package="$2"
  mkdir -p "$work/apt/lists/partial" "$work/apt/sources"
  deb_src_sources "$work/apt/sources"
  local apt=(apt-get -qq -o Dir::Etc::SourceList=/dev/null -o Dir::Etc::SourceParts="$work/apt/sources"
             -o Dir::State::Lists="$work/apt/lists" -o APT::Sandbox::User=root)
  echo "frusta: fetching Debian's ${package%%=*} source to build it for Windows" >&2
  # a repository of the machine's without sources fails its part only; apt-get source
  # below says so if what it needs is missing
  "${apt[@]}" update || echo "frusta: some deb-src indexes could not be fetched" >&2
  (cd "$work" && "${apt[@]}" source --download-only --tar-only "$package" >/dev/null)
}

# build_windows_libraries PREFIX: hidapi (its Windows backend, with its own CMake) from
# Debian's source package (bookworm's version, as on Linux), static, into PREFIX. Done
# once per PREFIX.
build_windows_libraries() {
  local prefix="$1"
  [ -f "$prefix/lib/libhidapi.a" ] && return 0
  local work="$prefix/src"
  rm -rf "$prefix" && mkdir -p "$work"
  fetch_debian_source "$work" hidapi=0.13.1-1
  tar -xzf "$work/hidapi_0.13.1.orig.tar.gz" -C "$work"
  cmake -S "$work/hidapi-hidapi-0.13.1" -B "$work/hidapi-build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_TOOLCHAIN_FILE="$FRUSTA_WINDOWS_TOOLCHAIN" -DBUILD_SHARED_LIBS=OFF \
        -DHIDAPI_BUILD_HIDTEST=OFF -DCMAKE_INSTALL_PREFIX="$prefix" >/dev/null
  cmake --build "$work/hidapi-build" >/dev/null
  cmake --install "$work/hidapi-build" >/dev/null
  # hidapi.h marks its functions dllexport on Windows unconditionally; linked into
  # frusta.dll they must stay inside it: drop the objects' export directives
  x86_64-w64-mingw32-objcopy --remove-section=.drectve "$prefix/lib/libhidapi.a"
}

# build_windows_embree PREFIX: Embree 3 for the Windows baker, from Debian's source
# package (bookworm's 3.13.5, as on Linux), static, into PREFIX; done once per PREFIX.
# Only what the baker calls (bake/mesh_queries.cpp: triangles, point queries, single
# rays), with Embree's own task scheduler instead of TBB and SSE2 kernels alone: 69
# build steps instead of the 276 of its defaults up to AVX2 (every geometry, ray
# packets), ~320 CPU seconds (README, "Platforms").
build_windows_embree() {
  local prefix="$1"
  [ -f "$prefix/lib/libembree3.a" ] && return 0
  local work="$prefix/src"
  rm -rf "$prefix" && mkdir -p "$work"
  fetch_debian_source "$work" embree=3.13.5+dfsg-2
  tar -xJf "$work/embree_3.13.5+dfsg.orig.tar.xz" -C "$work"
  local src="$work/embree-3.13.5"
  # Embree takes MSVC's flags for any Windows compiler whose front end CMake does not
  # call GNU, and CMake names none for MinGW's g++: MinGW is GNU-like too
  sed -i 's/^\(  ELSEIF(\)\${CMAKE_CXX_COMPILER_FRONTEND_VARIANT} MATCHES "GNU")/\1MINGW OR "${CMAKE_CXX_COMPILER_FRONTEND_VARIANT}" MATCHES "GNU")/' \
    "$src/CMakeLists.txt"
  grep -q '^  ELSEIF(MINGW OR ' "$src/CMakeLists.txt" ||
    { echo "frusta: Embree's compiler test was not where expected: patch it anew" >&2; exit 1; }
  # its version resource is UTF-16, which MinGW's windres cannot read
  iconv -f UTF-16 -t UTF-8 "$src/kernels/embree.rc" >"$src/kernels/embree.rc.utf8"
  mv "$src/kernels/embree.rc.utf8" "$src/kernels/embree.rc"
  cmake -S "$src" -B "$work/embree-build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_TOOLCHAIN_FILE="$FRUSTA_WINDOWS_TOOLCHAIN" -DCMAKE_INSTALL_PREFIX="$prefix" \
        -DEMBREE_STATIC_LIB=ON -DEMBREE_TASKING_SYSTEM=INTERNAL -DEMBREE_MAX_ISA=SSE2 \
        -DEMBREE_ISPC_SUPPORT=OFF -DEMBREE_TUTORIALS=OFF -DEMBREE_RAY_PACKETS=OFF \
        -DEMBREE_FILTER_FUNCTION=OFF -DEMBREE_GEOMETRY_QUAD=OFF -DEMBREE_GEOMETRY_CURVE=OFF \
        -DEMBREE_GEOMETRY_SUBDIVISION=OFF -DEMBREE_GEOMETRY_USER=OFF -DEMBREE_GEOMETRY_INSTANCE=OFF \
        -DEMBREE_GEOMETRY_GRID=OFF -DEMBREE_GEOMETRY_POINT=OFF >/dev/null
  echo "frusta: building Embree for Windows (minutes)" >&2
  cmake --build "$work/embree-build" --parallel "$(nproc)" >/dev/null
  # the headers, the static libraries and the CMake package ("lib" would add the
  # documentation, whose PDF Debian's tarball leaves out)
  cmake --install "$work/embree-build" --component devel >/dev/null
}

# build_windows_tree DIR BUILD_TYPE [cmake args...]: the runtime and tests for Windows
# x64, without the baker (no Embree for Windows here). Builds $FRUSTA_BUILD_TARGETS.
build_windows_tree() {
  local dir="$1" type="$2"
  shift 2
  build_windows_libraries "$ROOT/build/windows-libs"
  # the build lists each test program's tests by running it under Wine
  WINEPREFIX="$ROOT/build/windows/wine-prefix" WINEDEBUG=-all \
  build_tree "$dir" "$type" -DCMAKE_TOOLCHAIN_FILE="$FRUSTA_WINDOWS_TOOLCHAIN" \
    -DFRUSTA_WINDOWS_LIBS="$ROOT/build/windows-libs" -DFRUSTA_BUILD_BAKER=OFF \
    -DFRUSTA_BUILD_SAMPLES=OFF -DFRUSTA_BUILD_BENCHMARKS=OFF "${FRUSTA_CROSS_FLAGS[@]}" "$@"
}

# build_windows_baker_tree DIR BUILD_TYPE [cmake args...]: the baker for Windows x64
# (frusta_bake.dll, with Embree linked in) and what tests it, in a tree of its own: the
# runtime's tree (build_windows_tree) stays without Embree, whose build takes minutes
# (README, "Platforms"). Pass host_objects' arguments. Builds $FRUSTA_BUILD_TARGETS.
build_windows_baker_tree() {
  local dir="$1" type="$2"
  shift 2
  build_windows_embree "$ROOT/build/windows-embree"
  # the later -D wins over build_windows_tree's FRUSTA_BUILD_BAKER=OFF; no frusta-bake
  # (tinygltf is not built for Windows): the editor bakes through the C ABI
  build_windows_tree "$dir" "$type" -DFRUSTA_BUILD_BAKER=ON -DFRUSTA_BUILD_TOOLS=OFF \
    -Dembree_DIR="$ROOT/build/windows-embree/lib/cmake/embree-3.13.5" "$@"
}

# start_wine: the Wine prefix of build/windows made (once), and one Wine server kept up
# until stop_wine, so each test starts under a live server rather than racing one that
# is shutting down. Wine's services inherit the output of the program that starts
# them: they start here, off any pipe a caller waits on.
start_wine() {
  export WINEPREFIX="$ROOT/build/windows/wine-prefix" WINEDEBUG=-all
  mkdir -p "$WINEPREFIX"
  # refused (2) where a server runs already: that one serves
  "$FRUSTA_WINE_DIR/wineserver" -p </dev/null >/dev/null 2>&1 || true
  "$FRUSTA_WINE_DIR/wine64" wineboot -i </dev/null >/dev/null 2>&1
}

stop_wine() {
  "$FRUSTA_WINE_DIR/wineserver" -k 2>/dev/null || true  # none running is fine
  unset WINEPREFIX WINEDEBUG
}

# run_windows PROGRAM [args...]: a Windows program under Wine, in the prefix of
# build/windows (made on first use); a start Wine failed without output is made again
# (native/cmake/toolchains/wine-run)
run_windows() {
  WINEPREFIX="$ROOT/build/windows/wine-prefix" WINEDEBUG=-all \
    "$ROOT/native/cmake/toolchains/wine-run" --again-if-silent "$FRUSTA_WINE_DIR/wine64" "$@"
}

# build_tree DIR BUILD_TYPE [extra cmake args...]: configure (once) and build (only
# $FRUSTA_BUILD_TARGETS when set). Every tree compiles through ccache, so a tree that
# compiles what another already did with the same flags (tools/test's build without the
# tests, a rebuild after a checkout) reads the objects back: the cache keys on absolute
# paths and not on the tree's directory, and lives in build/ccache unless CCACHE_DIR says.
build_tree() {
  local dir="$1" type="$2"
  shift 2
  local werror=OFF
  [ "${CI:-}" = "true" ] && werror=ON
  export CCACHE_DIR="${CCACHE_DIR:-$ROOT/build/ccache}" CCACHE_NOHASHDIR=1
  export CCACHE_MAXSIZE="${CCACHE_MAXSIZE:-4G}"
  # the tests' precompiled header (tests/CMakeLists.txt): ccache caches what uses one only so
  export CCACHE_SLOPPINESS="${CCACHE_SLOPPINESS:-pch_defines,time_macros}"
  # RelWithDebInfo keeps line tables only (-g1): the package strips debug information,
  # a backtrace still names files and lines, and full -g was 9 % of the tree's compile
  # (415 -> 377 CPU s). A caller's own flags (the cross trees') come after and win.
  cmake -S "$ROOT" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE="$type" \
        -DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache \
        "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" \
        -DFRUSTA_WARNINGS_AS_ERRORS="$werror" "$@" >/dev/null
  local targets=()
  [ -n "${FRUSTA_BUILD_TARGETS:-}" ] && targets=(--target ${FRUSTA_BUILD_TARGETS})
  cmake --build "$dir" --parallel "$(nproc)" "${targets[@]}"
}
