// SPDX-License-Identifier: MIT
#include "gltf_loader.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "corpus_fixture.h"

namespace frusta {
namespace {

// Each test's own folder: ctest runs this file's tests as processes side by side, and a
// buffer one test was rewriting (tri.bin, which most of them write) was read short by
// another (`ctest -R GltfLoader --parallel 8 --repeat until-fail:40` failed in its first
// rounds).
std::string dir() {
  const std::string folder = ::testing::TempDir() + "frusta_gltf_" +
                             ::testing::UnitTest::GetInstance()->current_test_info()->name() + "/";
  std::filesystem::create_directories(folder);
  return folder;
}

void write_file(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// A unit right triangle's three float positions then three uint16 indices (+2 pad).
std::string triangle_bin(float x = 1.0f) {
  const float p[9] = {0, 0, 0, x, 0, 0, 0, 1, 0};
  const uint16_t i[4] = {0, 1, 2, 0};
  std::string b(reinterpret_cast<const char*>(p), sizeof p);
  b.append(reinterpret_cast<const char*>(i), sizeof i);
  return b;
}

struct Gltf {
  std::string bin = triangle_bin();
  std::string bin_uri = "tri.bin";
  int buffer_length = 44;
  std::string position = R"("type": "VEC3", "componentType": 5126, "count": 3)";
  std::string indices = R"("type": "SCALAR", "componentType": 5123, "count": 3)";
  std::string primitive = R"("attributes": {"POSITION": 0}, "indices": 1, "mode": 4)";
  std::string node = R"("mesh": 0)";
  bool write_bin = true;

  std::string json() const {
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{)" + node + R"(}],
  "meshes": [{"primitives": [{)" + primitive + R"(}]}],
  "buffers": [{"uri": ")" + bin_uri + R"(", "byteLength": )" + std::to_string(buffer_length) + R"(}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                  {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "accessors": [{"bufferView": 0, )" + position + R"(},
                {"bufferView": 1, )" + indices + R"(}]})";
  }
  std::string write(const std::string& name) const {
    const std::string path = dir() + name + ".gltf";
    write_file(path, json());
    if (write_bin) write_file(dir() + bin_uri, bin);
    return path;
  }
};

TEST(GltfLoader, ReadsATriangleWithItsNodeTransform) {
  Gltf g;
  g.node = R"("mesh": 0, "translation": [1, 2, 3], "scale": [2, 2, 2])";
  GltfLoadResult r;
  ASSERT_EQ(load_gltf_triangles(g.write("ok"), &r), FRUSTA_OK) << frusta::last_error_message();
  ASSERT_EQ(r.mesh.triangles.size(), 1u);
  EXPECT_EQ(r.mesh.vertices[1], vec3(3, 2, 3));  // (1,0,0) scaled by 2, moved by (1,2,3)
  EXPECT_EQ(r.primitives, 1);
}

TEST(GltfLoader, MirroringTransformKeepsTheOutsideOutside) {
  Gltf g;
  g.node = R"("mesh": 0, "scale": [-1, 1, 1])";
  GltfLoadResult r;
  ASSERT_EQ(load_gltf_triangles(g.write("mirror"), &r), FRUSTA_OK) << frusta::last_error_message();
  const auto& t = r.mesh.triangles[0];
  const vec3 n = glm::cross(r.mesh.vertices[t[1]] - r.mesh.vertices[t[0]],
                            r.mesh.vertices[t[2]] - r.mesh.vertices[t[0]]);
  EXPECT_GT(n.z, 0.0);  // the unmirrored triangle faces +z; the mirror must too
}

TEST(GltfLoader, NonTriangleAndNonIndexedPrimitives) {
  Gltf points;
  points.primitive = R"("attributes": {"POSITION": 0}, "mode": 0)";
  GltfLoadResult r;
  EXPECT_EQ(load_gltf_triangles(points.write("points"), &r), FRUSTA_ERROR_FILE_FORMAT);
  EXPECT_NE(std::string(frusta::last_error_message()).find("no triangles"), std::string::npos);

  Gltf plain;
  plain.primitive = R"("attributes": {"POSITION": 0})";  // no indices, default mode
  ASSERT_EQ(load_gltf_triangles(plain.write("plain"), &r), FRUSTA_OK) << frusta::last_error_message();
  EXPECT_EQ(r.mesh.triangles.size(), 1u);
}

struct Broken {
  const char* name;
  frusta_result expected;
  const char* fragment;
  Gltf gltf;
  std::string raw;  // when set, written instead of the glTF
};

TEST(GltfLoader, BrokenFilesGiveTheirOwnError) {
  std::vector<Broken> corpus;
  auto add = [&](const char* name, frusta_result code, const char* fragment, auto edit) {
    Broken b{name, code, fragment, Gltf{}, ""};
    edit(b);
    corpus.push_back(b);
  };
  add("not json", FRUSTA_ERROR_FILE_FORMAT, "not readable as glTF", [](Broken& b) { b.raw = "{nope"; });
  add("truncated glb", FRUSTA_ERROR_FILE_FORMAT, "not readable as glTF",
      [](Broken& b) { b.raw = std::string("glTF\x02\x00\x00\x00\xff\x00\x00\x00", 12); });
  add("missing buffer", FRUSTA_ERROR_FILE_FORMAT, "File not found : absent.bin",
      [](Broken& b) { b.gltf.bin_uri = "absent.bin"; b.gltf.write_bin = false; });
  add("short buffer", FRUSTA_ERROR_FILE_FORMAT, "File size mismatch",
      [](Broken& b) { b.gltf.bin = b.gltf.bin.substr(0, 20); b.gltf.bin_uri = "short.bin"; });
  add("accessor past its view", FRUSTA_ERROR_FILE_FORMAT, "past the end",
      [](Broken& b) { b.gltf.position = R"("type": "VEC3", "componentType": 5126, "count": 30)"; });
  add("positions not vec3", FRUSTA_ERROR_FILE_FORMAT, "POSITION must be float VEC3",
      [](Broken& b) { b.gltf.position = R"("type": "VEC2", "componentType": 5126, "count": 3)"; });
  add("index out of range", FRUSTA_ERROR_FILE_FORMAT, "but there are 3 vertices", [](Broken& b) {
    b.gltf.bin = triangle_bin();
    b.gltf.bin[38] = 9;  // second index -> 9
    b.gltf.bin_uri = "badindex.bin";
  });
  add("nan vertex", FRUSTA_ERROR_FILE_FORMAT, "not finite", [](Broken& b) {
    b.gltf.bin = triangle_bin(std::nanf(""));
    b.gltf.bin_uri = "nan.bin";
  });
  add("float indices", FRUSTA_ERROR_FILE_FORMAT, "unsigned scalars",
      [](Broken& b) { b.gltf.indices = R"("type": "SCALAR", "componentType": 5126, "count": 3)"; });
  add("no position", FRUSTA_ERROR_FILE_FORMAT, "no POSITION",
      [](Broken& b) { b.gltf.primitive = R"("attributes": {"NORMAL": 0}, "indices": 1)"; });
  add("mesh index out of range", FRUSTA_ERROR_FILE_FORMAT, "uses mesh 7", [](Broken& b) { b.gltf.node = R"("mesh": 7)"; });
  add("only points", FRUSTA_ERROR_FILE_FORMAT, "no triangles",
      [](Broken& b) { b.gltf.primitive = R"("attributes": {"POSITION": 0}, "mode": 0)"; });
  ASSERT_GE(corpus.size(), 10u);
  for (size_t i = 0; i < corpus.size(); ++i) {
    const Broken& b = corpus[i];
    const std::string path = dir() + "broken" + std::to_string(i) + ".gltf";
    if (!b.raw.empty()) write_file(path, b.raw);
    else {
      write_file(path, b.gltf.json());
      if (b.gltf.write_bin) write_file(dir() + b.gltf.bin_uri, b.gltf.bin);
    }
    GltfLoadResult r;
    EXPECT_EQ(load_gltf_triangles(path, &r), b.expected) << b.name << ": " << frusta::last_error_message();
    const std::string message = frusta::last_error_message();
    EXPECT_NE(message.find(b.fragment), std::string::npos) << b.name << ": " << message;
    EXPECT_NE(message.find(path), std::string::npos) << b.name << ": " << message;
  }
  GltfLoadResult r;
  EXPECT_EQ(load_gltf_triangles(dir() + "does-not-exist.gltf", &r), FRUSTA_ERROR_IO);
}

// The hostile corpus (corpus/cases.tsv; issue 16): each file ends in its documented
// result with a message naming the file and the part at fault, and no file beside
// the input's folder is opened, by the buffers, the images or tinygltf's search of
// the working folder.
TEST(GltfLoaderCorpus, EveryFileEndsInItsResultAndNothingOutsideTheFolderIsOpened) {
  corpus::Folder folder;
  corpus::OpenWatch outside(folder.root());
  for (const corpus::Case& c : corpus::Folder::all_cases()) {
    const std::string path = folder.in(c.file);
    GltfLoadResult r;
    const frusta_result got = load_gltf_triangles(path, &r);
    const std::string message = got == FRUSTA_OK ? "" : frusta::last_error_message();
    EXPECT_EQ(frusta::result_name(got), c.result) << c.file << ": " << message;
    if (got == FRUSTA_OK) {
      EXPECT_EQ(r.mesh.triangles.size(), 4u) << c.file;
    } else {
      EXPECT_NE(message.find(c.fragment), std::string::npos) << c.file << ": " << message;
      EXPECT_NE(message.find(path), std::string::npos) << c.file << ": " << message;
      EXPECT_EQ(message.find("FRUSTA_ERROR", 1), std::string::npos)
          << "the code twice: " << message;
    }
    for (const std::string& name : outside.take())
      ADD_FAILURE() << c.file << ": " << name << " beside the input's folder was opened";
  }
}

TEST(GltfLoaderCorpus, EveryCorpusFileHasItsCase) {
  std::set<std::string> listed;
  for (const corpus::Case& c : corpus::Folder::cases()) listed.insert(c.file);
  for (const auto& entry : std::filesystem::directory_iterator(FRUSTA_GLTF_CORPUS_DIR)) {
    const std::string ext = entry.path().extension().string();
    if (ext == ".gltf" || ext == ".glb") {
      EXPECT_EQ(listed.count(entry.path().filename().string()), 1u) << entry.path();
    }
  }
  EXPECT_GE(listed.size(), 25u);
}

// the input itself: a FIFO would block an open for ever, a device never end
TEST(GltfLoaderCorpus, TheInputMustBeARegularFileWithinTheLimit) {
  corpus::Folder folder;
  const std::string fifo = folder.in("input_fifo.gltf");
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  struct Input {
    std::string path;
    const char* fragment;
  };
  for (const Input& input :
       {Input{fifo, "not a regular file"}, Input{"/dev/zero", "not a regular file"},
        Input{folder.in("sub"), "not a regular file"},
        Input{folder.in("huge.bin"), "bytes the loader reads"}}) {
    GltfLoadResult r;
    EXPECT_EQ(load_gltf_triangles(input.path, &r), FRUSTA_ERROR_IO) << input.path;
    const std::string message = frusta::last_error_message();
    EXPECT_NE(message.find(input.fragment), std::string::npos) << message;
    EXPECT_NE(message.find(input.path), std::string::npos) << message;
  }
}

// limits the corpus does not reach cheaply: the JSON's value count, nesting exactly at
// the limit, and instancing just within the node budget
TEST(GltfLoaderCorpus, LimitsHoldAtTheirEdges) {
  corpus::Folder folder;
  const std::vector<unsigned char> tetra = corpus::tetra_bin();
  GltfLoadResult r;
  // 64 levels (the root object is one) load
  const std::string at_limit = folder.in("depth_64.glb");
  corpus::write_file(at_limit,
                     corpus::glb_of(corpus::deep_gltf(GltfLimits::kMaxJsonDepth - 1, true), tetra));
  EXPECT_EQ(load_gltf_triangles(at_limit, &r), FRUSTA_OK) << frusta::last_error_message();
  // too many values, however flat
  std::string values = "[0";
  for (size_t i = 0; i < GltfLimits::kMaxJsonValues; ++i) values += ",0";
  std::string many = corpus::deep_gltf(1, true);
  many.replace(many.find("[0]"), 3, values + "]");
  corpus::write_file(folder.in("values.glb"), corpus::glb_of(many, tetra));
  EXPECT_EQ(load_gltf_triangles(folder.in("values.glb"), &r), FRUSTA_ERROR_FILE_FORMAT);
  EXPECT_NE(std::string(frusta::last_error_message()).find("JSON values"), std::string::npos)
      << frusta::last_error_message();
  // L doubling levels instance 2^(L+1) - 1 nodes: 18 are within the budget (and load
  // 2^18 tetrahedra), 20 are over it
  for (int levels : {18, 20}) {
    std::string nodes = "[";
    for (int i = 0; i < levels; ++i)
      nodes += "{\"children\": [" + std::to_string(i + 1) + ", " + std::to_string(i + 1) + "]}, ";
    nodes += "{\"mesh\": 0}]";
    std::string json = corpus::deep_gltf(1, true);
    json.replace(json.find("[{\"mesh\": 0}]"), 13, nodes);
    const std::string path = folder.in("levels" + std::to_string(levels) + ".glb");
    corpus::write_file(path, corpus::glb_of(json, tetra));
    const frusta_result got = load_gltf_triangles(path, &r);
    if (levels == 18) {
      ASSERT_EQ(got, FRUSTA_OK) << frusta::last_error_message();
      EXPECT_EQ(r.mesh.triangles.size(), 4u << 18);
    } else {
      EXPECT_EQ(got, FRUSTA_ERROR_FILE_FORMAT);
      EXPECT_NE(std::string(frusta::last_error_message()).find("budget of 1048576"), std::string::npos)
          << frusta::last_error_message();
    }
  }
}

}  // namespace
}  // namespace frusta
