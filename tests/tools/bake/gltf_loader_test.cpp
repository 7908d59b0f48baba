// SPDX-License-Identifier: MIT
#include "gltf_loader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

namespace frusta {
namespace {

std::string dir() { return ::testing::TempDir(); }

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
  ASSERT_EQ(load_gltf_triangles(g.write("ok"), &r), FRUSTA_OK) << frusta_last_error();
  ASSERT_EQ(r.mesh.triangles.size(), 1u);
  EXPECT_EQ(r.mesh.vertices[1], vec3(3, 2, 3));  // (1,0,0) scaled by 2, moved by (1,2,3)
  EXPECT_EQ(r.primitives, 1);
}

TEST(GltfLoader, MirroringTransformKeepsTheOutsideOutside) {
  Gltf g;
  g.node = R"("mesh": 0, "scale": [-1, 1, 1])";
  GltfLoadResult r;
  ASSERT_EQ(load_gltf_triangles(g.write("mirror"), &r), FRUSTA_OK) << frusta_last_error();
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
  EXPECT_NE(std::string(frusta_last_error()).find("no triangles"), std::string::npos);

  Gltf plain;
  plain.primitive = R"("attributes": {"POSITION": 0})";  // no indices, default mode
  ASSERT_EQ(load_gltf_triangles(plain.write("plain"), &r), FRUSTA_OK) << frusta_last_error();
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
    EXPECT_EQ(load_gltf_triangles(path, &r), b.expected) << b.name << ": " << frusta_last_error();
    const std::string message = frusta_last_error();
    EXPECT_NE(message.find(b.fragment), std::string::npos) << b.name << ": " << message;
    EXPECT_NE(message.find(path), std::string::npos) << b.name << ": " << message;
  }
  GltfLoadResult r;
  EXPECT_EQ(load_gltf_triangles(dir() + "does-not-exist.gltf", &r), FRUSTA_ERROR_IO);
}

}  // namespace
}  // namespace frusta
