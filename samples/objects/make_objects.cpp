// SPDX-License-Identifier: MIT
// frusta-make-objects OUTDIR: writes the sample objects as binary glTF (.glb), made
// from the same procedural meshes the tests use. The build bakes each into a tree.
#include <tiny_gltf.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "meshes/meshes.h"

namespace {

// one mesh, one node, one buffer with float positions and uint32 indices
tinygltf::Model to_gltf(const frusta::TriangleMesh& mesh) {
  tinygltf::Model model;
  tinygltf::Buffer buffer;
  const size_t vertex_bytes = mesh.vertices.size() * 12, index_bytes = mesh.triangles.size() * 12;
  buffer.data.resize(vertex_bytes + index_bytes);
  std::vector<double> lo(3, 1e300), hi(3, -1e300);
  for (size_t i = 0; i < mesh.vertices.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const float v = static_cast<float>(mesh.vertices[i][k]);
      std::memcpy(&buffer.data[i * 12 + static_cast<size_t>(k) * 4], &v, 4);
      lo[static_cast<size_t>(k)] = std::min(lo[static_cast<size_t>(k)], static_cast<double>(v));
      hi[static_cast<size_t>(k)] = std::max(hi[static_cast<size_t>(k)], static_cast<double>(v));
    }
  std::memcpy(&buffer.data[vertex_bytes], mesh.triangles.data(), index_bytes);
  model.buffers.push_back(buffer);

  tinygltf::BufferView positions, indices;
  positions.buffer = indices.buffer = 0;
  positions.byteLength = vertex_bytes;
  positions.target = TINYGLTF_TARGET_ARRAY_BUFFER;
  indices.byteOffset = vertex_bytes;
  indices.byteLength = index_bytes;
  indices.target = TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER;
  model.bufferViews = {positions, indices};

  tinygltf::Accessor position_accessor, index_accessor;
  position_accessor.bufferView = 0;
  position_accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  position_accessor.type = TINYGLTF_TYPE_VEC3;
  position_accessor.count = mesh.vertices.size();
  position_accessor.minValues = lo;
  position_accessor.maxValues = hi;
  index_accessor.bufferView = 1;
  index_accessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  index_accessor.type = TINYGLTF_TYPE_SCALAR;
  index_accessor.count = mesh.triangles.size() * 3;
  model.accessors = {position_accessor, index_accessor};

  tinygltf::Primitive primitive;
  primitive.attributes["POSITION"] = 0;
  primitive.indices = 1;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  tinygltf::Mesh m;
  m.primitives.push_back(primitive);
  model.meshes.push_back(m);
  tinygltf::Node node;
  node.mesh = 0;
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes.push_back(0);
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  model.asset.version = "2.0";
  model.asset.generator = "frusta-make-objects";
  return model;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: frusta-make-objects OUTDIR\n");
    return 2;
  }
  using frusta::vec3;
  namespace s = frusta::scenes;
  const struct {
    const char* name;
    frusta::TriangleMesh mesh;
  } objects[] = {
      {"ball", s::make_sphere(0.04, 32)},                 // a 8 cm ball to grasp
      {"marble", s::make_sphere(s::kMarbleRadius, 24)},   // to pinch and carry
      {"box", s::make_box(vec3(0.10, 0.06, 0.04), 2)},    // flat faces, right angles
      {"plate", s::make_box(vec3(0.12, 0.08, 0.004), 1)}, // thin: pinch it
      {"tile", s::make_box(vec3(0.03, 0.03, 0.004), 1)},  // the plate of the pinch scenarios
      {"bowl", s::make_bowl(0.06, 0.006, 24)},            // concave
      {"mug", s::make_mug(0.04, 0.09, 0.006, 48)},        // a handle through the wall
      {"octahedron", s::make_octahedron(0.05)},           // sharp edges
      {"table", s::make_box(vec3(0.60, 0.90, 0.03), 1)},  // the Unity sample's table top
      {"stand", s::make_box(vec3(0.008, 0.008, 0.011814), 1)},  // holds the marble up there
  };
  tinygltf::TinyGLTF writer;
  for (const auto& o : objects) {
    const std::string path = std::string(argv[1]) + "/" + o.name + ".glb";
    tinygltf::Model model = to_gltf(o.mesh);
    if (!writer.WriteGltfSceneToFile(&model, path, true, true, false, true)) {
      std::fprintf(stderr, "frusta-make-objects: cannot write %s\n", path.c_str());
      return 1;
    }
  }
  return 0;
}
