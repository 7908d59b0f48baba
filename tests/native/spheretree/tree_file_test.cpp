// SPDX-License-Identifier: MIT
#include "spheretree/tree_file.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>

#include "core/error.h"
#include "scenes/random_trees.h"
#include "spheretree/tree_builder.h"

namespace frusta {
namespace {

TreeFile sample_file(int leaves = 500) {
  std::mt19937_64 rng(42);
  TreeFile f;
  EXPECT_EQ(build_sphere_tree(testing::random_leaves(rng, leaves, 1), {4}, &f.tree), FRUSTA_OK);
  f.bounds_min = vec3(-0.1);
  f.bounds_max = vec3(0.1);
  f.bake = {0.001, 4096, 12, 3456, 0.0009, 0.0007, 100000, 0.25};
  return f;
}

std::string temp_path(const char* name) {
  return std::string(::testing::TempDir()) + "frusta_" + name + ".frtree";
}

void write_bytes(const std::string& path, const std::vector<uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

// rewrite the checksum so a tampered file gets past it and meets the deeper checks
void reseal(std::vector<uint8_t>& b) {
  uint64_t h = 0xcbf29ce484222325ull;
  auto mix = [&](size_t from, size_t to) {
    for (size_t i = from; i < to; ++i) h = (h ^ b[i]) * 0x100000001b3ull;
  };
  mix(0, 152);
  mix(160, b.size());
  std::memcpy(b.data() + 152, &h, 8);
}

TEST(TreeFile, WriteThenReadIsLossless) {
  const TreeFile original = sample_file();
  const std::string path = temp_path("roundtrip");
  ASSERT_EQ(save_tree_file(path, original), FRUSTA_OK) << frusta::last_error_message();
  TreeFile loaded;
  ASSERT_EQ(load_tree_file(path, &loaded), FRUSTA_OK) << frusta::last_error_message();
  // byte-identical re-encoding covers every field, nodes and leaves
  EXPECT_EQ(encode_tree_file(loaded), encode_tree_file(original));
  EXPECT_EQ(loaded.bake.triangle_count, 3456);
  EXPECT_EQ(loaded.bake.uncovered_error, 0.0009);
  EXPECT_EQ(loaded.tree.leaves.size(), 500u);
  // not stored but derived on load, as the builder did
  EXPECT_EQ(loaded.tree.node_error, original.tree.node_error);
  EXPECT_EQ(loaded.tree.node_error.size(), loaded.tree.nodes.size());
  std::remove(path.c_str());
}

struct Damage {
  const char* name;
  frusta_result expected;
  const char* message;  // a fragment the error must contain
  std::function<void(std::vector<uint8_t>&)> apply;
};

// The corpus of damaged files, each written to disk and loaded like a user's file.
TEST(TreeFile, DamagedFilesAreRefusedWithTheirOwnError) {
  const TreeFile f = sample_file();
  const std::vector<uint8_t> good = encode_tree_file(f);
  const size_t node0 = 160, leaf0 = 160 + f.tree.nodes.size() * 24;
  size_t first_leaf_node = 0;
  while (f.tree.nodes[first_leaf_node].count != 0) ++first_leaf_node;
  auto set_i32 = [](std::vector<uint8_t>& b, size_t at, int32_t v) { std::memcpy(&b[at], &v, 4); };
  auto set_f32 = [](std::vector<uint8_t>& b, size_t at, float v) { std::memcpy(&b[at], &v, 4); };
  auto set_f64 = [](std::vector<uint8_t>& b, size_t at, double v) { std::memcpy(&b[at], &v, 8); };
  auto set_i64 = [](std::vector<uint8_t>& b, size_t at, int64_t v) { std::memcpy(&b[at], &v, 8); };
  const std::vector<Damage> corpus = {
      {"empty", FRUSTA_ERROR_FILE_FORMAT, "not a Frusta", [](auto& b) { b.clear(); }},
      {"short header", FRUSTA_ERROR_FILE_FORMAT, "not a Frusta", [](auto& b) { b.resize(100); }},
      {"wrong magic", FRUSTA_ERROR_FILE_FORMAT, "not a Frusta", [](auto& b) { b[0] = 'G'; }},
      {"future version", FRUSTA_ERROR_FILE_FORMAT, "format version 2",
       [&](auto& b) { set_i32(b, 8, 2); }},
      {"record size", FRUSTA_ERROR_FILE_FORMAT, "record sizes", [&](auto& b) { set_i32(b, 16, 48); }},
      {"truncated payload", FRUSTA_ERROR_CORRUPT_FILE, "truncated", [](auto& b) { b.resize(b.size() - 7); }},
      {"junk appended", FRUSTA_ERROR_CORRUPT_FILE, "junk", [](auto& b) { b.push_back(0); }},
      {"flipped payload bit", FRUSTA_ERROR_CORRUPT_FILE, "checksum",
       [&](auto& b) { b[leaf0 + 3] ^= 0x10; }},
      {"flipped header figure", FRUSTA_ERROR_CORRUPT_FILE, "checksum", [](auto& b) { b[121] ^= 1; }},
      {"huge counts", FRUSTA_ERROR_CORRUPT_FILE, "outside",
       [&](auto& b) { set_i64(b, 40, int64_t{1} << 40); reseal(b); }},
      {"negative count", FRUSTA_ERROR_CORRUPT_FILE, "outside",
       [&](auto& b) { set_i64(b, 32, -1); reseal(b); }},
      {"bad branching", FRUSTA_ERROR_CORRUPT_FILE, "branching",
       [&](auto& b) { set_i32(b, 24, 99); reseal(b); }},
      {"nan bound", FRUSTA_ERROR_CORRUPT_FILE, "not finite",
       [&](auto& b) { set_f64(b, 48, std::nan("")); reseal(b); }},
      {"nan node", FRUSTA_ERROR_CORRUPT_FILE, "node 0",
       [&](auto& b) { set_f32(b, node0, std::nanf("")); reseal(b); }},
      {"negative leaf radius", FRUSTA_ERROR_CORRUPT_FILE, "leaf 0",
       [&](auto& b) { set_f64(b, leaf0 + 24, -1.0); reseal(b); }},
      {"child index backwards (cycle)", FRUSTA_ERROR_CORRUPT_FILE, "children",
       [&](auto& b) { set_i32(b, node0 + 16, 0); reseal(b); }},
      {"child range past the end", FRUSTA_ERROR_CORRUPT_FILE, "children",
       [&](auto& b) { set_i32(b, node0 + 16, 1 << 30); reseal(b); }},
      {"leaf outside its bound", FRUSTA_ERROR_CORRUPT_FILE, "sticks out",
       [&](auto& b) { set_f64(b, leaf0, 5.0); reseal(b); }},
      // a walk culls a leaf by its own node's sphere before testing the leaf itself
      {"leaf outside its own node", FRUSTA_ERROR_CORRUPT_FILE, "sticks out",
       [&](auto& b) { set_f32(b, node0 + 24 * first_leaf_node, 5.0f); reseal(b); }},
      {"depth understated", FRUSTA_ERROR_CORRUPT_FILE, "deeper",
       [&](auto& b) { set_i32(b, 28, 1); reseal(b); }},
  };
  const std::string path = temp_path("damaged");
  for (const Damage& d : corpus) {
    std::vector<uint8_t> bytes = good;
    d.apply(bytes);
    write_bytes(path, bytes);
    TreeFile out;
    out.bake.triangle_count = -99;  // must stay untouched on failure
    EXPECT_EQ(load_tree_file(path, &out), d.expected) << d.name << ": " << frusta::last_error_message();
    EXPECT_NE(std::string(frusta::last_error_message()).find(d.message), std::string::npos)
        << d.name << ": " << frusta::last_error_message();
    EXPECT_NE(std::string(frusta::last_error_message()).find(path), std::string::npos) << d.name;
    EXPECT_EQ(out.bake.triangle_count, -99) << d.name;
  }
  std::remove(path.c_str());
}

TEST(TreeFile, EveryTruncationAndEveryByteFlipIsRefused) {
  const std::vector<uint8_t> good = encode_tree_file(sample_file(40));
  for (size_t size = 0; size < good.size(); ++size) {
    TreeFile out;
    EXPECT_NE(decode_tree_file(good.data(), size, "t", &out), FRUSTA_OK) << size;
  }
  for (size_t i = 0; i < good.size(); ++i) {
    std::vector<uint8_t> b = good;
    b[i] ^= 0x01;
    TreeFile out;
    EXPECT_NE(decode_tree_file(b.data(), b.size(), "t", &out), FRUSTA_OK) << "byte " << i;
  }
}

TEST(TreeFile, MissingFileIsAnIoError) {
  TreeFile out;
  EXPECT_EQ(load_tree_file("/nonexistent/x.frtree", &out), FRUSTA_ERROR_IO);
  EXPECT_NE(std::string(frusta::last_error_message()).find("/nonexistent/x.frtree"), std::string::npos);
}

TEST(TreeFile, SaveLeavesNoPartialFileBehind) {
  const std::string path = temp_path("atomic");
  ASSERT_EQ(save_tree_file(path, sample_file()), FRUSTA_OK);
  EXPECT_FALSE(std::ifstream(path + ".partial").good());
  EXPECT_EQ(save_tree_file("/nonexistent/dir/x.frtree", sample_file()), FRUSTA_ERROR_IO);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace frusta
