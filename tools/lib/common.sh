# SPDX-License-Identifier: MIT
# Shared by tools/demo, tools/test and tools/bench: install what is missing, then
# configure and build one CMake tree. Source it; it sets ROOT.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"

# Debian packages the build needs (docs: /work/shared/deps.md, README "Dependencies").
FRUSTA_PACKAGES=(cmake ninja-build g++ pkg-config libglm-dev libhidapi-dev libusb-1.0-0-dev
                 libembree-dev libtinygltf-dev libbenchmark-dev libgtest-dev)

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
                       libusb-1.0-0-dev:arm64 libgtest-dev:arm64 libbenchmark-dev:arm64)

ensure_arm64_packages() {
  if ! dpkg --print-foreign-architectures | grep -qx arm64; then
    [ "$(id -u)" -eq 0 ] || { echo "frusta: as root, run: dpkg --add-architecture arm64" >&2; exit 1; }
    dpkg --add-architecture arm64
    DEBIAN_FRONTEND=noninteractive apt-get update -qq
  fi
  ensure_packages "${FRUSTA_ARM64_PACKAGES[@]}"
}

# build_arm64_tree DIR BUILD_TYPE [cmake args...]: the runtime, tests and benchmarks for
# Linux arm64, without the baker (no Embree there); pass FRUSTA_SAMPLE_OBJECTS_DIR, the
# sample objects a host build baked. Builds $FRUSTA_BUILD_TARGETS when set.
build_arm64_tree() {
  local dir="$1" type="$2"
  shift 2
  build_tree "$dir" "$type" \
    -DCMAKE_TOOLCHAIN_FILE="$ROOT/native/cmake/toolchains/aarch64-linux-gnu.cmake" \
    -DFRUSTA_BUILD_BAKER=OFF -DFRUSTA_BUILD_SAMPLES=OFF "$@"
}

# run_arm64 PROGRAM [args...]: an arm64 program under qemu
run_arm64() {
  qemu-aarch64-static -L /usr/aarch64-linux-gnu "$@"
}

# build_tree DIR BUILD_TYPE [extra cmake args...]: configure (once) and build (only
# $FRUSTA_BUILD_TARGETS when set)
build_tree() {
  local dir="$1" type="$2"
  shift 2
  local werror=OFF
  [ "${CI:-}" = "true" ] && werror=ON
  cmake -S "$ROOT" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE="$type" \
        -DFRUSTA_WARNINGS_AS_ERRORS="$werror" "$@" >/dev/null
  local targets=()
  [ -n "${FRUSTA_BUILD_TARGETS:-}" ] && targets=(--target ${FRUSTA_BUILD_TARGETS})
  cmake --build "$dir" --parallel "$(nproc)" "${targets[@]}"
}
