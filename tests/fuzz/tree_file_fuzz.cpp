// SPDX-License-Identifier: MIT
// libFuzzer target: the tree loader must refuse or accept any bytes without a
// crash, a sanitizer report or an unbounded allocation; what it accepts must
// re-encode to the same bytes.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "spheretree/tree_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  frusta::TreeFile file;
  if (frusta::decode_tree_file(data, size, "fuzz", &file) == FRUSTA_OK) {
    const std::vector<uint8_t> again = frusta::encode_tree_file(file);
    if (again.size() != size || !std::equal(again.begin(), again.end(), data)) std::abort();
  }
  return 0;
}
