// SPDX-License-Identifier: MIT
//
// Layout, version 1, all little-endian:
//   offset  size  field
//        0     8  magic "FRUSTREE"
//        8     4  u32 format version (1)
//       12     4  u32 header bytes (160)
//       16     4  u32 node bytes (24: f32 centre[3], f32 radius, i32 first, i32 count)
//       20     4  u32 leaf bytes (32: f64 centre[3], f64 radius)
//       24     4  i32 branching
//       28     4  i32 depth
//       32     8  i64 node count
//       40     8  i64 leaf count
//       48    48  f64 bounds min[3], max[3]
//       96     8  f64 target error (m)      104  8  i64 max leaves
//      112     4  i32 max depth             116  4  i32 triangle count
//      120     8  f64 uncovered error (m)   128  8  f64 protruding error (m)
//      136     8  i64 error samples         144  8  f64 bake seconds
//      152     8  u64 FNV-1a 64 of bytes [0, 152) and of the payload
//      160        nodes, then leaves
#include "spheretree/tree_file.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/file_read.h"
#include "spheretree/node_error.h"
#include "spheretree/tree_limits.h"

namespace frusta {

namespace {

#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "tree files are read by memcpy: port the codec before building big-endian"
#endif

constexpr char kMagic[8] = {'F', 'R', 'U', 'S', 'T', 'R', 'E', 'E'};
constexpr size_t kHeaderBytes = kTreeHeaderBytes;
constexpr size_t kChecksumOffset = kTreeChecksumOffset;
constexpr size_t kNodeBytes = 24;
constexpr size_t kLeafBytes = 32;
static_assert(sizeof(TreeNode) == kNodeBytes, "TreeNode is stored as is");
static_assert(kMaxTreeFileBytes == kHeaderBytes + static_cast<size_t>(kMaxNodes) * kNodeBytes +
                                       static_cast<size_t>(kMaxLeaves) * kLeafBytes,
              "the header's limit and the layout agree");

uint64_t fnv1a(uint64_t hash, const uint8_t* data, size_t size) {
  for (size_t i = 0; i < size; ++i) hash = (hash ^ data[i]) * 0x100000001b3ull;
  return hash;
}
constexpr uint64_t kFnvBasis = 0xcbf29ce484222325ull;

uint64_t checksum(const uint8_t* data, size_t size) {
  uint64_t h = fnv1a(kFnvBasis, data, kChecksumOffset);
  return fnv1a(h, data + kHeaderBytes, size - kHeaderBytes);
}

template <class T>
void put(std::vector<uint8_t>& out, size_t offset, T value) {
  std::memcpy(out.data() + offset, &value, sizeof value);
}

template <class T>
T get(const uint8_t* data, size_t offset) {
  T value;
  std::memcpy(&value, data + offset, sizeof value);
  return value;
}

bool finite_all(const double* v, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

// The structural checks: each node reached once from the root, children after
// their parent, every leaf numbered once, every leaf inside its node and its ancestors.
frusta_result check_structure(const SphereTree& t, const char* name) {
  const size_t nodes = t.nodes.size(), leaves = t.leaves.size();
  std::vector<uint8_t> node_seen(nodes, 0), leaf_seen(leaves, 0);
  struct Entry {
    int32_t node, level;
  };
  std::vector<Entry> stack{{0, 0}};
  std::vector<Entry> path;  // the current node's ancestors, root first
  node_seen[0] = 1;
  while (!stack.empty()) {
    const Entry e = stack.back();
    stack.pop_back();
    while (!path.empty() && path.back().level >= e.level) path.pop_back();
    const TreeNode& n = t.nodes[static_cast<size_t>(e.node)];
    if (e.level > t.depth)
      return fail(FRUSTA_ERROR_CORRUPT_FILE, "%s: node %d lies at level %d, deeper than the "
                  "recorded depth %d", name, e.node, e.level, t.depth);
    if (n.count == 0) {
      if (n.first < 0 || static_cast<size_t>(n.first) >= leaves)
        return fail(FRUSTA_ERROR_CORRUPT_FILE, "%s: leaf node %d names leaf %d of %zu", name,
                    e.node, n.first, leaves);
      if (leaf_seen[static_cast<size_t>(n.first)]++)
        return fail(FRUSTA_ERROR_CORRUPT_FILE, "%s: leaf %d appears twice", name, n.first);
      // its own node too: a walk culls a leaf by its node's sphere before testing it
      const Sphere& leaf = t.leaves[static_cast<size_t>(n.first)];
      path.push_back(e);
      for (const Entry& a : path) {
        const Sphere bound = t.node_sphere(a.node);
        const double reach = glm::length(leaf.center - bound.center) + leaf.radius;
        if (reach > bound.radius * (1.0 + 1e-6) + 1e-9)
          return fail(FRUSTA_ERROR_CORRUPT_FILE, "%s: leaf %d sticks out of node %d by %g m",
                      name, n.first, a.node, reach - bound.radius);
      }
      path.pop_back();
      continue;
    }
    if (n.count < 0 || n.count > t.branching || n.first <= e.node ||
        static_cast<int64_t>(n.first) + n.count > static_cast<int64_t>(nodes))
      return fail(FRUSTA_ERROR_CORRUPT_FILE, "%s: node %d has children [%d, +%d), outside "
                  "(%d, %zu) or more than the branching %d", name, e.node, n.first, n.count,
                  e.node, nodes, t.branching);
    path.push_back(e);
    for (int32_t c = 0; c < n.count; ++c) {
      const size_t child = static_cast<size_t>(n.first + c);
      if (node_seen[child]++)
        return fail(FRUSTA_ERROR_CORRUPT_FILE, "%s: node %zu has two parents", name, child);
      stack.push_back({n.first + c, e.level + 1});
    }
  }
  for (size_t i = 0; i < nodes; ++i)
    if (!node_seen[i])
      return fail(FRUSTA_ERROR_CORRUPT_FILE, "%s: node %zu is not reachable from the root", name, i);
  for (size_t i = 0; i < leaves; ++i)
    if (!leaf_seen[i])
      return fail(FRUSTA_ERROR_CORRUPT_FILE, "%s: leaf %zu is in no node", name, i);
  return FRUSTA_OK;
}

}  // namespace

uint64_t tree_file_checksum(const uint8_t* data, size_t size) { return checksum(data, size); }

std::vector<uint8_t> encode_tree_file(const TreeFile& file) {
  const SphereTree& t = file.tree;
  std::vector<uint8_t> out(kHeaderBytes + t.nodes.size() * kNodeBytes + t.leaves.size() * kLeafBytes);
  std::memcpy(out.data(), kMagic, sizeof kMagic);
  put<uint32_t>(out, 8, kTreeFormatVersion);
  put<uint32_t>(out, 12, kHeaderBytes);
  put<uint32_t>(out, 16, kNodeBytes);
  put<uint32_t>(out, 20, kLeafBytes);
  put<int32_t>(out, 24, t.branching);
  put<int32_t>(out, 28, t.depth);
  put<int64_t>(out, 32, static_cast<int64_t>(t.nodes.size()));
  put<int64_t>(out, 40, static_cast<int64_t>(t.leaves.size()));
  for (int k = 0; k < 3; ++k) {
    put<double>(out, 48 + 8 * k, file.bounds_min[k]);
    put<double>(out, 72 + 8 * k, file.bounds_max[k]);
  }
  const BakeRecord& b = file.bake;
  put<double>(out, 96, b.target_error);
  put<int64_t>(out, 104, b.max_leaves);
  put<int32_t>(out, 112, b.max_depth);
  put<int32_t>(out, 116, b.triangle_count);
  put<double>(out, 120, b.uncovered_error);
  put<double>(out, 128, b.protruding_error);
  put<int64_t>(out, 136, b.error_samples);
  put<double>(out, 144, b.bake_seconds);
  size_t offset = kHeaderBytes;
  std::memcpy(out.data() + offset, t.nodes.data(), t.nodes.size() * kNodeBytes);
  offset += t.nodes.size() * kNodeBytes;
  for (const Sphere& s : t.leaves) {
    const double v[4] = {s.center.x, s.center.y, s.center.z, s.radius};
    std::memcpy(out.data() + offset, v, sizeof v);
    offset += kLeafBytes;
  }
  put<uint64_t>(out, kChecksumOffset, checksum(out.data(), out.size()));
  return out;
}

frusta_result decode_tree_file(const uint8_t* data, size_t size, const char* name, TreeFile* out) {
  if (size < kHeaderBytes || std::memcmp(data, kMagic, sizeof kMagic) != 0)
    return fail(FRUSTA_ERROR_FILE_FORMAT, "%s: not a Frusta sphere-tree file (%zu bytes, no "
                "FRUSTREE header)", name, size);
  const uint32_t version = get<uint32_t>(data, 8);
  if (version != kTreeFormatVersion)
    return fail(FRUSTA_ERROR_FILE_FORMAT, "%s: format version %u, this library reads version %u: "
                "bake the mesh again", name, version, kTreeFormatVersion);
  if (get<uint32_t>(data, 12) != kHeaderBytes || get<uint32_t>(data, 16) != kNodeBytes ||
      get<uint32_t>(data, 20) != kLeafBytes)
    return fail(FRUSTA_ERROR_FILE_FORMAT, "%s: record sizes %u/%u/%u, expected %zu/%zu/%zu", name,
                get<uint32_t>(data, 12), get<uint32_t>(data, 16), get<uint32_t>(data, 20),
                kHeaderBytes, kNodeBytes, kLeafBytes);
  const int64_t nodes = get<int64_t>(data, 32), leaves = get<int64_t>(data, 40);
  if (leaves < 1 || leaves > kMaxLeaves || nodes < 1 || nodes > kMaxNodes)
    return fail(FRUSTA_ERROR_CORRUPT_FILE, "%s: %lld nodes and %lld leaves, outside 1..%lld and "
                "1..%lld", name, static_cast<long long>(nodes), static_cast<long long>(leaves),
                static_cast<long long>(kMaxNodes), static_cast<long long>(kMaxLeaves));
  // the counts are now small enough that this cannot overflow
  const size_t expected = kHeaderBytes + static_cast<size_t>(nodes) * kNodeBytes +
                          static_cast<size_t>(leaves) * kLeafBytes;
  if (size != expected)
    return fail(FRUSTA_ERROR_CORRUPT_FILE, "%s: %zu bytes but its counts need %zu: the file is %s",
                name, size, expected, size < expected ? "truncated" : "followed by junk");
  const uint64_t stored = get<uint64_t>(data, kChecksumOffset), actual = checksum(data, size);
  if (stored != actual)
    return fail(FRUSTA_ERROR_CORRUPT_FILE, "%s: checksum %016llx, content hashes to %016llx: the "
                "file is damaged", name, static_cast<unsigned long long>(stored),
                static_cast<unsigned long long>(actual));

  TreeFile f;
  SphereTree& t = f.tree;
  t.branching = get<int32_t>(data, 24);
  t.depth = get<int32_t>(data, 28);
  if (t.branching < 2 || t.branching > kMaxBranching || t.depth < 0 || t.depth > kMaxTreeDepth)
    return fail(FRUSTA_ERROR_CORRUPT_FILE, "%s: branching %d and depth %d, outside 2..%d and "
                "0..%d", name, t.branching, t.depth, kMaxBranching, kMaxTreeDepth);
  double header_reals[6 + 5];
  for (int k = 0; k < 6; ++k) header_reals[k] = get<double>(data, 48 + 8 * static_cast<size_t>(k));
  BakeRecord& b = f.bake;
  b.target_error = get<double>(data, 96);
  b.max_leaves = get<int64_t>(data, 104);
  b.max_depth = get<int32_t>(data, 112);
  b.triangle_count = get<int32_t>(data, 116);
  b.uncovered_error = get<double>(data, 120);
  b.protruding_error = get<double>(data, 128);
  b.error_samples = get<int64_t>(data, 136);
  b.bake_seconds = get<double>(data, 144);
  const double bake_reals[5] = {b.target_error, b.uncovered_error, b.protruding_error,
                                b.bake_seconds, 0.0};
  std::memcpy(header_reals + 6, bake_reals, sizeof bake_reals);
  if (!finite_all(header_reals, 11))
    return fail(FRUSTA_ERROR_CORRUPT_FILE, "%s: a bound or bake figure is not finite", name);
  f.bounds_min = vec3(header_reals[0], header_reals[1], header_reals[2]);
  f.bounds_max = vec3(header_reals[3], header_reals[4], header_reals[5]);

  t.nodes.resize(static_cast<size_t>(nodes));
  std::memcpy(t.nodes.data(), data + kHeaderBytes, static_cast<size_t>(nodes) * kNodeBytes);
  for (size_t i = 0; i < t.nodes.size(); ++i) {
    const TreeNode& n = t.nodes[i];
    const float* v = n.center;
    if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]) ||
        !std::isfinite(n.radius) || n.radius < 0.0f)
      return fail(FRUSTA_ERROR_CORRUPT_FILE, "%s: node %zu has a non-finite or negative sphere",
                  name, i);
  }
  t.leaves.resize(static_cast<size_t>(leaves));
  const uint8_t* leaf_data = data + kHeaderBytes + static_cast<size_t>(nodes) * kNodeBytes;
  for (size_t i = 0; i < t.leaves.size(); ++i) {
    double v[4];
    std::memcpy(v, leaf_data + i * kLeafBytes, sizeof v);
    if (!finite_all(v, 4) || v[3] < 0.0)
      return fail(FRUSTA_ERROR_CORRUPT_FILE, "%s: leaf %zu has a non-finite or negative sphere",
                  name, i);
    t.leaves[i] = {vec3(v[0], v[1], v[2]), v[3]};
  }
  if (frusta_result r = check_structure(t, name)) return r;
  compute_node_errors(t);  // not stored: derived, and a file could lie about it
  *out = std::move(f);
  return FRUSTA_OK;
}

frusta_result save_tree_file(const std::string& path, const TreeFile& file) {
  const std::vector<uint8_t> bytes = encode_tree_file(file);
  const std::string temporary = path + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!out)
      return fail(FRUSTA_ERROR_IO, "%s: cannot write %zu bytes", temporary.c_str(), bytes.size());
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    return fail(FRUSTA_ERROR_IO, "%s: cannot replace it with %s", path.c_str(), temporary.c_str());
  }
  return FRUSTA_OK;
}

frusta_result load_tree_file(const std::string& path, TreeFile* out) {
  std::vector<uint8_t> bytes;
  if (frusta_result r = read_file(path, kMaxTreeFileBytes, "any valid tree takes", &bytes))
    return r;
  return decode_tree_file(bytes.data(), bytes.size(), path.c_str(), out);
}

}  // namespace frusta
