// SPDX-License-Identifier: MIT
#include "gltf_loader.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <tiny_gltf.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <new>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <nlohmann/json.hpp>

#include "core/error.h"

namespace frusta {

namespace {

using Json = nlohmann::json;
using Limits = GltfLimits;

constexpr int kTriangles = TINYGLTF_MODE_TRIANGLES;

uint64_t add_saturated(uint64_t a, uint64_t b) {
  return a > std::numeric_limits<uint64_t>::max() - b ? std::numeric_limits<uint64_t>::max()
                                                      : a + b;
}

// ------------------------------------------------------------------ files

// A regular file of at most `limit` bytes, whole. O_NONBLOCK: opening a FIFO nobody
// writes to returns at once (then fstat refuses it) instead of waiting forever.
bool read_regular_file(const std::string& path, size_t limit, bool follow_symlinks,
                       std::vector<unsigned char>* out, std::string* why) {
  const int flags =
      O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY | (follow_symlinks ? 0 : O_NOFOLLOW);
  const int fd = ::open(path.c_str(), flags);
  if (fd < 0) {
    *why = std::strerror(errno);
    return false;
  }
  struct stat st {};
  bool ok = false;
  if (::fstat(fd, &st) != 0) {
    *why = std::strerror(errno);
  } else if (!S_ISREG(st.st_mode)) {
    *why = "not a regular file (a FIFO, device, socket or folder could block or never end)";
  } else if (static_cast<uint64_t>(st.st_size) > limit) {
    *why = std::to_string(st.st_size) + " bytes, more than the " + std::to_string(limit) +
           " bytes the loader reads";
  } else {
    out->clear();
    out->reserve(static_cast<size_t>(st.st_size));
    unsigned char chunk[1 << 16];
    ok = true;
    for (;;) {
      const ssize_t n = ::read(fd, chunk, sizeof chunk);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) {
        *why = std::strerror(errno);
        ok = false;
        break;
      }
      if (n == 0) break;
      if (static_cast<size_t>(n) > limit - out->size()) {  // it grew while being read
        *why = "more than the " + std::to_string(limit) + " bytes the loader reads";
        ok = false;
        break;
      }
      out->insert(out->end(), chunk, chunk + n);
    }
  }
  ::close(fd);
  return ok;
}

// What tinygltf may read besides the input: regular files inside the input's folder.
// It looks a buffer up as base_dir/uri and then ./uri; only the first can pass.
struct Sandbox {
  std::string folder;  // canonical, no trailing slash (unless it is "/")
  size_t budget = 0;   // bytes still allowed

  bool under(const std::string& path) const {
    const std::string prefix = folder == "/" ? folder : folder + "/";
    return path.size() > prefix.size() && path.compare(0, prefix.size(), prefix) == 0;
  }
};

std::string same_path(const std::string& path, void*) { return path; }  // no ~ or $VAR

bool exists_in_folder(const std::string& path, void* user) {
  const Sandbox& box = *static_cast<const Sandbox*>(user);
  struct stat st {};
  return box.under(path) && ::stat(path.c_str(), &st) == 0;  // what it is: read_in_folder says
}

bool read_in_folder(std::vector<unsigned char>* out, std::string* why, const std::string& path,
                    void* user) {
  Sandbox& box = *static_cast<Sandbox*>(user);
  if (!box.under(path)) {
    *why = "not inside the input's folder " + box.folder;
    return false;
  }
  char resolved[PATH_MAX];
  if (::realpath(path.c_str(), resolved) == nullptr) {
    *why = std::strerror(errno);
    return false;
  }
  if (!box.under(resolved)) {
    *why = std::string("it resolves to ") + resolved + ", outside the input's folder " + box.folder;
    return false;
  }
  if (!read_regular_file(resolved, box.budget, false, out, why)) return false;
  box.budget -= out->size();
  return true;
}

bool write_nothing(std::string* why, const std::string&, const std::vector<unsigned char>&, void*) {
  *why = "the loader writes no files";
  return false;
}

// Images are stripped from the JSON before tinygltf sees it; should one get through,
// it is still neither read nor decoded.
bool ignore_image(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                  const unsigned char*, int, void*) {
  return true;
}

// ------------------------------------------------------------------ JSON

// Refuses JSON nested deeper than kMaxJsonDepth or with more than kMaxJsonValues
// values, as it goes: nlohmann's SAX parser keeps its own stack on the heap, so
// hostile nesting stops here instead of in tinygltf's recursion.
class BoundedJson {
 public:
  bool null() { return value(); }
  bool boolean(bool) { return value(); }
  bool number_integer(Json::number_integer_t) { return value(); }
  bool number_unsigned(Json::number_unsigned_t) { return value(); }
  bool number_float(Json::number_float_t, const Json::string_t&) { return value(); }
  bool string(Json::string_t&) { return value(); }
  bool binary(Json::binary_t&) { return value(); }
  bool key(Json::string_t& k) {
    if (depth_ == 1) top_key_ = k;  // names the member a refusal is in
    return value();
  }
  bool start_object(std::size_t) { return open(); }
  bool start_array(std::size_t) { return open(); }
  bool end_object() { return --depth_, true; }
  bool end_array() { return --depth_, true; }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) {
    why_ = e.what();
    return false;
  }
  const std::string& why() const { return why_; }

 private:
  bool value() {
    if (++values_ <= Limits::kMaxJsonValues) return true;
    why_ = "more than " + std::to_string(Limits::kMaxJsonValues) + " JSON values";
    return false;
  }
  bool open() {
    if (++depth_ > Limits::kMaxJsonDepth) {
      why_ = "JSON nested more than " + std::to_string(Limits::kMaxJsonDepth) +
             " levels deep (in \"" + top_key_.substr(0, 64) + "\")";
      return false;
    }
    return value();
  }
  int depth_ = 0;
  size_t values_ = 0;
  std::string top_key_, why_;
};

// The JSON as a tree, once it is known to be bounded.
bool parse_json(const char* text, size_t size, Json* out, std::string* why) {
  if (size > Limits::kMaxJsonBytes) {
    *why = "its JSON is " + std::to_string(size) + " bytes, more than " +
           std::to_string(Limits::kMaxJsonBytes);
    return false;
  }
  BoundedJson bounds;
  if (!Json::sax_parse(text, text + size, &bounds)) {
    *why = bounds.why();
    return false;
  }
  *out = Json::parse(text, text + size, nullptr, false);
  if (out->is_discarded()) {
    *why = "JSON the parser refused";  // the SAX pass accepted it: not expected
    return false;
  }
  return true;
}

// ------------------------------------------------------------------ GLB

uint32_t le32(const unsigned char* p) {
  return static_cast<uint32_t>(p[0]) | static_cast<uint32_t>(p[1]) << 8 |
         static_cast<uint32_t>(p[2]) << 16 | static_cast<uint32_t>(p[3]) << 24;
}

void put_le32(std::vector<unsigned char>* out, uint32_t v) {
  for (int k = 0; k < 4; ++k) out->push_back(static_cast<unsigned char>(v >> (8 * k)));
}

struct GlbParts {
  const unsigned char* json = nullptr;
  size_t json_size = 0;
  const unsigned char* bin = nullptr;  // null: no BIN chunk
  size_t bin_size = 0;
};

// The chunks of a GLB, every length checked against the bytes that are there.
bool split_glb(const std::vector<unsigned char>& b, GlbParts* out, std::string* why) {
  if (b.size() < 20) {
    *why = "a GLB shorter than its 20-byte header";
    return false;
  }
  const uint64_t length = le32(&b[8]);
  if (le32(&b[4]) != 2) {
    *why = "GLB version " + std::to_string(le32(&b[4])) + ", not 2";
    return false;
  }
  if (length > b.size()) {
    *why = "the GLB header says " + std::to_string(length) + " bytes, the file has " +
           std::to_string(b.size());
    return false;
  }
  const uint64_t json_size = le32(&b[12]);
  if (le32(&b[16]) != 0x4E4F534Au || 20 + json_size > length) {
    *why = "the GLB's first chunk is not JSON within the file";
    return false;
  }
  out->json = &b[20];
  out->json_size = static_cast<size_t>(json_size);
  const uint64_t next = 20 + json_size;
  if (next + 8 <= length && le32(&b[next + 4]) == 0x004E4942u) {  // "BIN\0"
    const uint64_t bin_size = le32(&b[next]);
    if (next + 8 + bin_size > length) {
      *why = "the GLB's BIN chunk of " + std::to_string(bin_size) + " bytes runs past its end";
      return false;
    }
    out->bin = &b[next + 8];
    out->bin_size = static_cast<size_t>(bin_size);
  }
  return true;
}

// A GLB tinygltf can take at its word: the given JSON, then the BIN chunk, each padded
// to 4 bytes, and lengths that are the true ones.
std::vector<unsigned char> make_glb(const std::string& json, const GlbParts& parts) {
  const size_t json_padded = (json.size() + 3) / 4 * 4;
  const size_t bin_padded = parts.bin ? std::max<size_t>(4, (parts.bin_size + 3) / 4 * 4) : 0;
  const size_t total = 20 + json_padded + (parts.bin ? 8 + bin_padded : 0);
  std::vector<unsigned char> glb;
  glb.reserve(total);
  glb.insert(glb.end(), {'g', 'l', 'T', 'F'});
  put_le32(&glb, 2);
  put_le32(&glb, static_cast<uint32_t>(total));
  put_le32(&glb, static_cast<uint32_t>(json_padded));
  put_le32(&glb, 0x4E4F534Au);
  glb.insert(glb.end(), json.begin(), json.end());
  glb.resize(20 + json_padded, ' ');
  if (parts.bin) {
    put_le32(&glb, static_cast<uint32_t>(bin_padded));
    put_le32(&glb, 0x004E4942u);
    glb.insert(glb.end(), parts.bin, parts.bin + parts.bin_size);
    glb.resize(total, 0);
  }
  return glb;
}

// ------------------------------------------------------------------ scene budget

// What instancing the scene asks for, counted on the JSON before any buffer is read.
// Integers are read as tinygltf reads them (any JSON integer, cast to int), so the
// count describes the model the Reader will walk.
class ScenePlan {
 public:
  ScenePlan(const Json& root, const std::string& path) : root_(root), path_(path) {}

  frusta_result check() {
    const Json* nodes = array(root_, "nodes");
    node_count_ = nodes ? nodes->size() : 0;
    state_.assign(node_count_, kNew);
    memo_.assign(node_count_, {});
    std::vector<int> roots;
    const Json* scenes = array(root_, "scenes");
    if (scenes && !scenes->empty()) {
      int scene = 0;
      if (const Json* s = member(root_, "scene")) integer(*s, &scene);
      if (scene < 0) scene = 0;
      if (static_cast<size_t>(scene) >= scenes->size()) return FRUSTA_OK;  // the loader says so
      roots = integers((*scenes)[static_cast<size_t>(scene)], "nodes");
    } else {
      for (size_t i = 0; i < node_count_; ++i) roots.push_back(static_cast<int>(i));
    }
    Totals total;
    for (int r : roots) {
      Totals t;
      if (frusta_result e = visit(r, 0, &t)) return e;
      total.add(t);
    }
    if (total.instances > Limits::kMaxNodeInstances)
      return over("node instances", total.instances, Limits::kMaxNodeInstances);
    if (total.triangles > Limits::kMaxTriangles)
      return over("triangles", total.triangles, Limits::kMaxTriangles);
    if (total.vertices > Limits::kMaxVertices)
      return over("vertices", total.vertices, Limits::kMaxVertices);
    return FRUSTA_OK;
  }

 private:
  struct Totals {
    uint64_t instances = 0, triangles = 0, vertices = 0;
    int height = 0;  // levels below
    void add(const Totals& t) {
      instances = add_saturated(instances, t.instances);
      triangles = add_saturated(triangles, t.triangles);
      vertices = add_saturated(vertices, t.vertices);
    }
  };
  enum State : uint8_t { kNew, kOpen, kDone };

  static const Json* member(const Json& o, const char* key) {
    if (!o.is_object()) return nullptr;
    const auto it = o.find(key);
    return it == o.end() ? nullptr : &*it;
  }
  static const Json* array(const Json& o, const char* key) {
    const Json* a = member(o, key);
    return a && a->is_array() ? a : nullptr;
  }
  static bool integer(const Json& v, int* out) {
    if (!v.is_number_integer()) return false;
    *out = static_cast<int>(v.get<int64_t>());
    return true;
  }
  // an integer array as tinygltf keeps it: the elements up to the first non-integer
  static std::vector<int> integers(const Json& o, const char* key) {
    std::vector<int> out;
    if (const Json* a = array(o, key))
      for (const Json& v : *a) {
        int i = 0;
        if (!integer(v, &i)) break;
        out.push_back(i);
      }
    return out;
  }
  // an accessor's count, 0 when there is no such accessor (the loader reports it)
  uint64_t accessor_count(int index) const {
    const Json* accessors = array(root_, "accessors");
    if (!accessors || index < 0 || static_cast<size_t>(index) >= accessors->size()) return 0;
    const Json* count = member((*accessors)[static_cast<size_t>(index)], "count");
    return count && count->is_number_unsigned() ? count->get<uint64_t>() : 0;
  }

  // the triangles and vertices one instance of a mesh adds, as the Reader reads them;
  // a single accessor over the whole budget is named (its count may be 2^62)
  frusta_result mesh_totals(int mesh, Totals* t) {
    const Json* meshes = array(root_, "meshes");
    if (!meshes || mesh < 0 || static_cast<size_t>(mesh) >= meshes->size()) return FRUSTA_OK;
    const Json* primitives = array((*meshes)[static_cast<size_t>(mesh)], "primitives");
    if (!primitives) return FRUSTA_OK;
    int k = -1;
    for (const Json& p : *primitives) {
      const Json* attributes = member(p, "attributes");
      if (!attributes || !attributes->is_object()) continue;  // tinygltf drops it
      bool all_integers = true;
      for (const Json& a : *attributes) all_integers = all_integers && a.is_number_integer();
      if (!all_integers) continue;
      ++k;
      int mode = kTriangles, indices = -1, position = -1;
      if (const Json* m = member(p, "mode")) integer(*m, &mode);
      if (mode >= 0 && mode != kTriangles) continue;
      if (const Json* i = member(p, "indices")) integer(*i, &indices);
      if (const Json* pos = member(*attributes, "POSITION")) integer(*pos, &position);
      const uint64_t vertices = accessor_count(position);
      if (vertices > Limits::kMaxVertices)
        return bad(
            "mesh %d primitive %d: POSITION accessor %d has %llu elements, more than the "
            "%llu vertices the loader takes",
            mesh, k, position, static_cast<unsigned long long>(vertices),
            static_cast<unsigned long long>(Limits::kMaxVertices));
      const uint64_t triangles = (indices >= 0 ? accessor_count(indices) : vertices) / 3;
      if (triangles > Limits::kMaxTriangles)
        return bad(
            "mesh %d primitive %d: index accessor %d has %llu elements, more than the "
            "%llu triangles the loader takes",
            mesh, k, indices, static_cast<unsigned long long>(accessor_count(indices)),
            static_cast<unsigned long long>(Limits::kMaxTriangles));
      t->vertices = add_saturated(t->vertices, vertices);
      t->triangles = add_saturated(t->triangles, triangles);
    }
    return FRUSTA_OK;
  }

  // Memoised: a subtree shared by many parents is counted once and added per use,
  // so 2^24 instances cost 24 visits. Recursion stops at kMaxNodeDepth.
  frusta_result visit(int index, int depth, Totals* out) {
    if (index < 0 || static_cast<size_t>(index) >= node_count_) return FRUSTA_OK;  // reported later
    const size_t i = static_cast<size_t>(index);
    if (state_[i] == kOpen)
      return bad("node %d is its own descendant (its children lead back to it)", index);
    if (state_[i] == kNew) {
      state_[i] = kOpen;
      const Json& node = (*array(root_, "nodes"))[i];
      Totals t;
      t.instances = 1;
      int mesh = -1;
      if (const Json* m = member(node, "mesh")) integer(*m, &mesh);
      if (frusta_result e = mesh_totals(mesh, &t)) return e;
      if (depth >= Limits::kMaxNodeDepth && !integers(node, "children").empty())
        return bad("node %d is nested more than %d deep", index, Limits::kMaxNodeDepth);
      for (int child : integers(node, "children")) {
        Totals c;
        if (frusta_result e = visit(child, depth + 1, &c)) return e;
        t.add(c);
        t.height = std::max(t.height, c.height + (c.instances > 0 ? 1 : 0));
      }
      memo_[i] = t;
      state_[i] = kDone;
    }
    if (depth + memo_[i].height > Limits::kMaxNodeDepth)
      return bad("node %d is nested more than %d deep", index, Limits::kMaxNodeDepth);
    *out = memo_[i];
    return FRUSTA_OK;
  }

  frusta_result over(const char* what, uint64_t asked, uint64_t budget) {
    const std::string count = asked == std::numeric_limits<uint64_t>::max()
                                  ? std::string("2^64 or more")
                                  : std::to_string(asked);
    return bad(
        "the scene asks for %s %s once its nodes are instanced (nodes used more than "
        "once repeat their meshes), over the loader's budget of %llu",
        count.c_str(), what, static_cast<unsigned long long>(budget));
  }

  template <class... Args>
  frusta_result bad(const char* format, Args... args) {
    char message[400];
    std::snprintf(message, sizeof message, format, args...);
    return fail(FRUSTA_ERROR_FILE_FORMAT, "%s: %s", path_.c_str(), message);
  }

  const Json& root_;
  const std::string& path_;
  size_t node_count_ = 0;
  std::vector<State> state_;
  std::vector<Totals> memo_;
};

// ------------------------------------------------------------------ the model

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
    if (pa.count > Limits::kMaxVertices - out_.mesh.vertices.size())
      return bad("mesh %d primitive %d: %zu more vertices exceed the budget of %llu", mesh, k,
                 pa.count, static_cast<unsigned long long>(Limits::kMaxVertices));
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
      if (ia->count / 3 > Limits::kMaxTriangles - out_.mesh.triangles.size())
        return bad("mesh %d primitive %d: %zu more triangles exceed the budget of %llu", mesh, k,
                   ia->count / 3, static_cast<unsigned long long>(Limits::kMaxTriangles));
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
    if (depth > Limits::kMaxNodeDepth)
      return bad("node %d is nested more than %d deep (a cycle?)", index, Limits::kMaxNodeDepth);
    if (++instances_ > Limits::kMaxNodeInstances)  // ScenePlan refused such scenes already
      return bad("more than %llu node instances",
                 static_cast<unsigned long long>(Limits::kMaxNodeInstances));
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
    char message[400];
    std::snprintf(message, sizeof message, format, args...);
    return fail(FRUSTA_ERROR_FILE_FORMAT, "%s: %s", path_.c_str(), message);
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
  if (!read_regular_file(path, Limits::kMaxFileBytes, true, &bytes, &why))
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
  if (!parse_json(text, binary ? glb.json_size : bytes.size(), &json, &why)) return not_gltf(why);
  if (json.is_object()) json.erase("images");
  if (frusta_result r = ScenePlan(json, path).check()) return r;
  const std::string stripped = json.dump(-1, ' ', false, Json::error_handler_t::replace);
  json = Json();
  std::vector<unsigned char> container;
  if (binary) container = make_glb(stripped, glb);
  Sandbox sandbox{folder, Limits::kMaxFileBytes - bytes.size()};
  std::vector<unsigned char>().swap(bytes);  // glb points into it no more

  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks({&exists_in_folder, &same_path, &read_in_folder, &write_nothing, &sandbox});
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
