# SPDX-License-Identifier: MIT
# Shared by tools/demo, tools/test and tools/bench: install what is missing, then
# configure and build one CMake tree. Source it; it sets ROOT.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"

# Debian packages the build needs (docs: /work/shared/deps.md, README "Dependencies").
FRUSTA_PACKAGES=(cmake ninja-build g++ pkg-config libglm-dev libhidapi-dev libusb-1.0-0-dev
                 libembree-dev libtinygltf-dev libbenchmark-dev libgtest-dev)

ensure_packages() {
  local missing=() p
  for p in "${FRUSTA_PACKAGES[@]}"; do
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
