// SPDX-License-Identifier: MIT
// Baked sphere-tree files (.frtree). Little-endian; layout in tree_file.cpp.
// Writing then reading is lossless. The reader checks every count, offset and
// value before use, so a truncated, corrupt or hostile file is refused with a
// message and never causes an allocation larger than the file itself.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/base.h"
#include "spheretree/sphere_tree.h"
#include "spheretree/tree_limits.h"

namespace frusta {

// How a tree was baked and how well it fits its mesh, kept with the tree.
struct BakeRecord {
  double target_error = 0.0;      // metres, the requested bound
  int64_t max_leaves = 0;         // the requested leaf budget
  int32_t max_depth = 0;          // the requested depth limit
  int32_t triangle_count = 0;     // of the source mesh
  double uncovered_error = 0.0;   // metres: largest gap from the surface to the leaves
  double protruding_error = 0.0;  // metres: largest height of the leaves above the surface
  int64_t error_samples = 0;      // points behind the two figures
  double bake_seconds = 0.0;
};

struct TreeFile {
  SphereTree tree;
  BakeRecord bake;
  vec3 bounds_min{0.0}, bounds_max{0.0};  // of the leaf spheres, object frame
};

constexpr uint32_t kTreeFormatVersion = 1;
constexpr size_t kTreeHeaderBytes = 160;
constexpr size_t kTreeChecksumOffset = 152;
// The largest file a valid tree makes (the header, then 24 bytes per node and 32 per
// leaf at the limits): larger input is refused unread.
constexpr size_t kMaxTreeFileBytes =
    kTreeHeaderBytes + static_cast<size_t>(kMaxNodes) * 24 + static_cast<size_t>(kMaxLeaves) * 32;

// The checksum a file of size >= kTreeHeaderBytes stores at kTreeChecksumOffset,
// computed over its other bytes. Public so the fuzzer can repair the files it mutates.
uint64_t tree_file_checksum(const uint8_t* data, size_t size);

// Encode/decode in memory (the file functions wrap these; tests use them too).
std::vector<uint8_t> encode_tree_file(const TreeFile& file);
frusta_result decode_tree_file(const uint8_t* data, size_t size, const char* name, TreeFile* out);

// Write atomically (to a temporary beside the path, then rename) and read back.
frusta_result save_tree_file(const std::string& path, const TreeFile& file);
frusta_result load_tree_file(const std::string& path, TreeFile* out);

}  // namespace frusta
