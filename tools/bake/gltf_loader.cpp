// SPDX-License-Identifier: MIT
#include "gltf_loader.h"

#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <new>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>

#include "core/error.h"
#include "glb_container.h"
#include "gltf_error.h"
#include "gltf_files.h"
#include "gltf_json.h"
#include "gltf_scene_budget.h"

namespace frusta {

namespace {

constexpr int kTriangles = TINYGLTF_MODE_TRIANGLES;

// Images are stripped from the JSON before tinygltf sees it; should one get through,
// it is still neither read nor decoded.
bool ignore_image(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                  const unsigned char*, int, void*) {
  return true;
}

glm::dmat4 local_transform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    glm::dmat4 m;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) m[c][r] = node.matrix[static_cast<size_t>(4 * c + r)];
    return m;
  }
  glm::dmat4 m(1.0);
  if (node.translation.size() == 3)
    m[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
  if (node.rotation.size() == 4)  // glTF stores x y z w
    m = m * glm::mat4_cast(glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1],
                                      node.rotation[2]));
  if (node.scale.size() == 3) m = m * glm::scale(glm::dmat4(1.0), glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
  return m;
}

class Reader {
 public:
  Reader(const tinygltf::Model& model, const std::string& path, GltfLoadResult& out)
      : model_(model), path_(path), out_(out) {}

  // the bytes of an accessor's elements, checked against its view and buffer; every
  // sum and product of file values is checked before it is formed
  frusta_result view(int index, const char* role, const unsigned char** data, size_t* stride,
                     size_t element_bytes) {
    if (index < 0 || static_cast<size_t>(index) >= model_.accessors.size())
      return bad("%s accessor %d does not exist (%zu accessors)", role, index, model_.accessors.size());
    const tinygltf::Accessor& a = model_.accessors[static_cast<size_t>(index)];
    if (a.sparse.isSparse) return bad("%s accessor %d is sparse, which is not supported", role, index);
    if (a.bufferView < 0 || static_cast<size_t>(a.bufferView) >= model_.bufferViews.size())
      return bad("%s accessor %d has no buffer view (%d)", role, index, a.bufferView);
    const tinygltf::BufferView& v = model_.bufferViews[static_cast<size_t>(a.bufferView)];
    if (v.buffer < 0 || static_cast<size_t>(v.buffer) >= model_.buffers.size())
      return bad("buffer view %d names buffer %d of %zu", a.bufferView, v.buffer, model_.buffers.size());
    const tinygltf::Buffer& b = model_.buffers[static_cast<size_t>(v.buffer)];
    if (v.byteOffset > b.data.size() || v.byteLength > b.data.size() - v.byteOffset)
      return bad("buffer view %d spans bytes [%zu, +%zu) of a %zu-byte buffer %d (missing or short "
                 "buffer)", a.bufferView, v.byteOffset, v.byteLength, b.data.size(), v.buffer);
    *stride = v.byteStride ? v.byteStride : element_bytes;
    if (*stride < element_bytes) return bad("%s accessor %d has stride %zu < %zu", role, index, *stride, element_bytes);
    // count elements need (count - 1) * stride + element_bytes bytes after the offset
    if (a.count > 0 &&
        (a.byteOffset > v.byteLength || element_bytes > v.byteLength - a.byteOffset ||
         a.count - 1 > (v.byteLength - a.byteOffset - element_bytes) / *stride))
      return bad("%s accessor %d reads %zu elements past the end of buffer view %d", role, index,
                 a.count, a.bufferView);
    *data = b.data.data() + v.byteOffset + a.byteOffset;
    return FRUSTA_OK;
  }

  frusta_result primitive(const tinygltf::Primitive& p, const glm::dmat4& world, int mesh, int k) {
    const int mode = p.mode < 0 ? kTriangles : p.mode;
    if (mode != kTriangles) {
      out_.warnings.push_back(path_ + ": mesh " + std::to_string(mesh) + " primitive " +
                              std::to_string(k) + " has mode " + std::to_string(mode) +
                              " (not triangles): skipped");
      return FRUSTA_OK;
    }
    const auto position = p.attributes.find("POSITION");
    if (position == p.attributes.end()) return bad("mesh %d primitive %d has no POSITION", mesh, k);
    const tinygltf::Accessor* found = accessor(position->second);
    if (!found)
      return bad("mesh %d primitive %d: POSITION accessor %d does not exist", mesh, k, position->second);
    const tinygltf::Accessor& pa = *found;
    if (pa.type != TINYGLTF_TYPE_VEC3 || pa.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
      return bad("mesh %d primitive %d: POSITION must be float VEC3 (type %d, component %d)", mesh,
                 k, pa.type, pa.componentType);
    const unsigned char* data = nullptr;
    size_t stride = 0;
    if (frusta_result r = view(position->second, "POSITION", &data, &stride, 12)) return r;
    // the scene's budget was checked on the JSON; this keeps the vertex numbers in
    // uint32 whatever the file says
    if (pa.count > GltfLimits::kMaxVertices - out_.mesh.vertices.size())
      return bad("mesh %d primitive %d: %zu more vertices exceed the budget of %llu", mesh, k,
                 pa.count, static_cast<unsigned long long>(GltfLimits::kMaxVertices));
    const uint32_t base = static_cast<uint32_t>(out_.mesh.vertices.size());
    for (size_t i = 0; i < pa.count; ++i) {
      float v[3];
      std::memcpy(v, data + i * stride, sizeof v);
      if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
        return bad("mesh %d primitive %d: vertex %zu is not finite", mesh, k, i);
      out_.mesh.vertices.push_back(glm::dvec3(world * glm::dvec4(v[0], v[1], v[2], 1.0)));
    }
    // a mirroring transform turns the winding inside out
    const bool flip = glm::determinant(glm::dmat3(world)) < 0.0;
    std::vector<uint32_t> indices;
    if (p.indices < 0) {
      for (size_t i = 0; i < pa.count; ++i) indices.push_back(static_cast<uint32_t>(i));
    } else {
      const tinygltf::Accessor* ia = accessor(p.indices);
      if (!ia) return bad("mesh %d primitive %d: index accessor %d does not exist", mesh, k, p.indices);
      const size_t size = ia->componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 1
                          : ia->componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                          : ia->componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT   ? 4 : 0;
      if (size == 0 || ia->type != TINYGLTF_TYPE_SCALAR)
        return bad("mesh %d primitive %d: indices must be unsigned scalars (component %d)", mesh, k,
                   ia->componentType);
      if (frusta_result r = view(p.indices, "index", &data, &stride, size)) return r;
      if (ia->count / 3 > GltfLimits::kMaxTriangles - out_.mesh.triangles.size())
        return bad("mesh %d primitive %d: %zu more triangles exceed the budget of %llu", mesh, k,
                   ia->count / 3, static_cast<unsigned long long>(GltfLimits::kMaxTriangles));
      for (size_t i = 0; i < ia->count; ++i) {
        uint32_t index = 0;
        std::memcpy(&index, data + i * stride, size);  // little-endian, as glTF is
        if (index >= pa.count)
          return bad("mesh %d primitive %d: index %zu is %u but there are %zu vertices", mesh, k, i,
                     index, pa.count);
        indices.push_back(index);
      }
    }
    if (indices.size() % 3 != 0)
      out_.warnings.push_back(path_ + ": mesh " + std::to_string(mesh) + " primitive " +
                              std::to_string(k) + ": " + std::to_string(indices.size() % 3) +
                              " trailing indices ignored");
    for (size_t i = 0; i + 2 < indices.size(); i += 3) {
      std::array<uint32_t, 3> t{base + indices[i], base + indices[i + 1], base + indices[i + 2]};
      if (flip) std::swap(t[1], t[2]);
      out_.mesh.triangles.push_back(t);
    }
    ++out_.primitives;
    return FRUSTA_OK;
  }

  frusta_result node(int index, const glm::dmat4& parent, int depth) {
    if (index < 0 || static_cast<size_t>(index) >= model_.nodes.size())
      return bad("node %d does not exist (%zu nodes)", index, model_.nodes.size());
    if (depth > GltfLimits::kMaxNodeDepth)
      return bad("node %d is nested more than %d deep (a cycle?)", index, GltfLimits::kMaxNodeDepth);
    if (++instances_ > GltfLimits::kMaxNodeInstances)  // ScenePlan refused such scenes already
      return bad("more than %llu node instances",
                 static_cast<unsigned long long>(GltfLimits::kMaxNodeInstances));
    const tinygltf::Node& n = model_.nodes[static_cast<size_t>(index)];
    const glm::dmat4 world = parent * local_transform(n);
    if (n.mesh >= 0) {
      if (static_cast<size_t>(n.mesh) >= model_.meshes.size())
        return bad("node %d uses mesh %d of %zu", index, n.mesh, model_.meshes.size());
      const tinygltf::Mesh& m = model_.meshes[static_cast<size_t>(n.mesh)];
      for (size_t k = 0; k < m.primitives.size(); ++k)
        if (frusta_result r = primitive(m.primitives[k], world, n.mesh, static_cast<int>(k))) return r;
    }
    for (int child : n.children)
      if (frusta_result r = node(child, world, depth + 1)) return r;
    return FRUSTA_OK;
  }

 private:
  const tinygltf::Accessor* accessor(int index) const {
    if (index < 0 || static_cast<size_t>(index) >= model_.accessors.size()) return nullptr;
    return &model_.accessors[static_cast<size_t>(index)];
  }

  template <class... Args>
  frusta_result bad(const char* format, Args... args) {
    return gltf_format_error(path_, format, args...);
  }

  const tinygltf::Model& model_;
  const std::string& path_;
  GltfLoadResult& out_;
  uint64_t instances_ = 0;
};

std::string folder_of(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

frusta_result load(const std::string& path, GltfLoadResult* out) {
  std::vector<unsigned char> bytes;
  std::string why;
  if (!read_regular_file(path, GltfLimits::kMaxFileBytes, true, &bytes, &why))
    return fail(FRUSTA_ERROR_IO, "%s: cannot read it: %s", path.c_str(), why.c_str());
  char folder[PATH_MAX];
  if (::realpath(folder_of(path).c_str(), folder) == nullptr)
    return fail(FRUSTA_ERROR_IO, "%s: cannot resolve its folder: %s", path.c_str(),
                std::strerror(errno));
  auto not_gltf = [&](const std::string& detail) {
    return fail(FRUSTA_ERROR_FILE_FORMAT, "%s: not readable as glTF 2.0: %s", path.c_str(),
                detail.c_str());
  };

  // the JSON, bounded, without images (baking needs none: not one is opened)
  const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  GlbParts glb;
  if (binary && !split_glb(bytes, &glb, &why)) return not_gltf(why);
  const char* text = reinterpret_cast<const char*>(binary ? glb.json : bytes.data());
  Json json;
  if (!parse_bounded_json(text, binary ? glb.json_size : bytes.size(), &json, &why)) return not_gltf(why);
  if (json.is_object()) json.erase("images");
  if (frusta_result r = check_scene_budget(json, path)) return r;
  const std::string stripped = json.dump(-1, ' ', false, Json::error_handler_t::replace);
  json = Json();
  std::vector<unsigned char> container;
  if (binary) container = make_glb(stripped, glb);
  Sandbox sandbox{folder, GltfLimits::kMaxFileBytes - bytes.size()};
  std::vector<unsigned char>().swap(bytes);  // glb points into it no more

  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks(sandboxed_files(&sandbox));
  loader.SetImageLoader(&ignore_image, nullptr);
  tinygltf::Model model;
  std::string error, warning;
  const bool ok =
      binary ? loader.LoadBinaryFromMemory(&model, &error, &warning, container.data(),
                                           static_cast<unsigned int>(container.size()), folder)
             : loader.LoadASCIIFromString(&model, &error, &warning, stripped.data(),
                                          static_cast<unsigned int>(stripped.size()), folder);
  if (!ok) {
    while (!error.empty() && error.back() == '\n') error.pop_back();
    return not_gltf(error.empty() ? "no detail from the parser" : error);
  }
  GltfLoadResult result;
  if (!warning.empty()) result.warnings.push_back(path + ": " + warning);
  Reader reader(model, path, result);
  std::vector<int> roots;
  if (!model.scenes.empty()) {
    const size_t scene = model.defaultScene >= 0 ? static_cast<size_t>(model.defaultScene) : 0;
    if (scene >= model.scenes.size())
      return fail(FRUSTA_ERROR_FILE_FORMAT, "%s: default scene %d does not exist", path.c_str(),
                  model.defaultScene);
    roots = model.scenes[scene].nodes;
  } else {
    for (size_t i = 0; i < model.nodes.size(); ++i) roots.push_back(static_cast<int>(i));
  }
  for (int root : roots)
    if (frusta_result r = reader.node(root, glm::dmat4(1.0), 0)) return r;
  if (result.mesh.triangles.empty())
    return fail(FRUSTA_ERROR_FILE_FORMAT, "%s: no triangles in the scene (%d triangle primitives, "
                "%zu warnings)", path.c_str(), result.primitives, result.warnings.size());
  *out = std::move(result);
  return FRUSTA_OK;
}

}  // namespace

frusta_result load_gltf_triangles(const std::string& path, GltfLoadResult* out) {
  try {
    return load(path, out);
  } catch (const std::bad_alloc&) {
    return fail(FRUSTA_ERROR_OUT_OF_MEMORY, "%s: out of memory while loading it", path.c_str());
  } catch (const std::exception& e) {
    return fail(FRUSTA_ERROR_INTERNAL, "%s: %s", path.c_str(), e.what());
  }
}

}  // namespace frusta
