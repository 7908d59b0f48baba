// SPDX-License-Identifier: MIT
// The GLB container (glTF 2.0 binary): a 12-byte header, a JSON chunk, an optional
// BIN chunk. Taken apart with every length checked, and put back together with the
// JSON the loader chose (images removed) and lengths that are the true ones.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace frusta {

struct GlbParts {
  const unsigned char* json = nullptr;  // points into the bytes split_glb was given
  size_t json_size = 0;
  const unsigned char* bin = nullptr;  // null: no BIN chunk
  size_t bin_size = 0;
};

// The chunks of a GLB, every length checked against the bytes that are there; false
// with the reason in *why otherwise.
bool split_glb(const std::vector<unsigned char>& bytes, GlbParts* out, std::string* why);

// A GLB tinygltf can take at its word: `json`, then parts' BIN chunk, each padded to
// 4 bytes.
std::vector<unsigned char> make_glb(const std::string& json, const GlbParts& parts);

}  // namespace frusta
