// SPDX-License-Identifier: MIT
// libFuzzer target: the tree loader must refuse or accept any bytes without a
// crash, a sanitizer report or an unbounded allocation; what it accepts must
// re-encode to the same bytes and survive the queries the engine runs on it.
//
// Random bytes almost never carry a valid checksum, so a plain fuzzer stops at it.
// The custom mutator repairs what stands in front of the structural checks: it
// resizes the file to match its node and leaf counts (half the time) and rewrites
// the checksum (15 times in 16: the rest keep the checksum check itself covered).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <random>
#include <vector>

#include "spheretree/sphere_tree.h"
#include "spheretree/tree_file.h"

extern "C" size_t LLVMFuzzerMutate(uint8_t* data, size_t size, size_t max_size);

namespace {

// the layout in tree_file.cpp: counts at 32 and 40, then 24-byte nodes, 32-byte leaves
constexpr size_t kNodeCountOffset = 32, kLeafCountOffset = 40;
constexpr size_t kNodeBytes = 24, kLeafBytes = 32;
static_assert(sizeof(frusta::TreeNode) == kNodeBytes, "nodes are stored as is");

int64_t read_count(const uint8_t* data, size_t offset) {
  int64_t value;
  std::memcpy(&value, data + offset, sizeof value);
  return value;
}

// the size the counts ask for, or 0 when that cannot fit in max_size
size_t size_for_counts(const uint8_t* data, size_t max_size) {
  const int64_t nodes = read_count(data, kNodeCountOffset),
                leaves = read_count(data, kLeafCountOffset);
  const int64_t room = static_cast<int64_t>(max_size - frusta::kTreeHeaderBytes);
  if (nodes < 1 || leaves < 1 || nodes > room / static_cast<int64_t>(kNodeBytes) ||
      leaves > room / static_cast<int64_t>(kLeafBytes))
    return 0;
  const size_t size = frusta::kTreeHeaderBytes + static_cast<size_t>(nodes) * kNodeBytes +
                      static_cast<size_t>(leaves) * kLeafBytes;
  return size <= max_size ? size : 0;
}

}  // namespace

extern "C" size_t LLVMFuzzerCustomMutator(uint8_t* data, size_t size, size_t max_size,
                                          unsigned int seed) {
  size = LLVMFuzzerMutate(data, size, max_size);
  if (size < frusta::kTreeHeaderBytes || max_size < frusta::kTreeHeaderBytes) return size;
  std::minstd_rand rng(seed);
  if (rng() % 2 == 0) {
    if (const size_t wanted = size_for_counts(data, max_size)) {
      if (wanted > size) std::memset(data + size, 0, wanted - size);
      size = wanted;
    }
  }
  if (rng() % 16 != 0) {
    const uint64_t sum = frusta::tree_file_checksum(data, size);
    std::memcpy(data + frusta::kTreeChecksumOffset, &sum, sizeof sum);
  }
  return size;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  frusta::TreeFile file;
  if (frusta::decode_tree_file(data, size, "fuzz", &file) != FRUSTA_OK) return 0;
  const std::vector<uint8_t> again = frusta::encode_tree_file(file);
  if (again.size() != size || !std::equal(again.begin(), again.end(), data)) std::abort();
  // an accepted tree is one the engine walks: a query that reaches every leaf, one
  // cut by level and by radius, and the distance search
  const frusta::SphereTree& t = file.tree;
  const frusta::Sphere everything{t.leaves[0].center, 1e300};  // leaves lie in float nodes
  std::vector<frusta::TreeHit> hits(t.leaves.size() + t.nodes.size());
  const int32_t capacity = static_cast<int32_t>(hits.size());
  frusta::TreeQueryStats all = frusta::query_sphere(t, everything, 0.0, {}, hits.data(), capacity);
  if (all.hits != static_cast<int32_t>(t.leaves.size())) std::abort();  // each leaf once
  frusta::query_sphere(t, t.leaves.back(), 1e-3, frusta::TreeCut(1, 1e-2), hits.data(), capacity);
  frusta::distance_to_leaves(t, t.leaves[0].center);
  // a segment from the first leaf to the last: the loose walk (detection's) makes every
  // hit of the exact one, in its order, which holds only where each leaf's node bounds it
  const frusta::SegmentFrame frame =
      frusta::make_segment_frame({t.leaves[0].center, t.leaves.back().center, 0.01, 0.005});
  std::vector<frusta::TreeHit> loose(hits.size());
  const int32_t exact = frusta::query_segment(t, frame, 1e-3, {}, hits.data(), capacity).hits;
  const int32_t kept = frusta::query_segment_loose(t, frame, 1e-3, {}, loose.data(), capacity).hits;
  int32_t next = 0;
  for (int32_t k = 0; k < kept && next < exact; ++k)
    if (loose[static_cast<size_t>(k)].node == hits[static_cast<size_t>(next)].node) ++next;
  if (next != exact) std::abort();
  return 0;
}
