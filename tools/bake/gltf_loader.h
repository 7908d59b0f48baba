// SPDX-License-Identifier: MIT
// Every triangle of a glTF 2.0 scene (.gltf or .glb, through tinygltf), in metres,
// with node transforms applied. Primitives that are not triangles are skipped
// with a warning. Every accessor is checked before it is read.
//
// The file may be hostile. The loader reads only the input (a regular file) and
// the buffers it names that are regular files inside the input's folder (symlinks
// resolved), besides data: URIs and the GLB's own chunk; it never opens images.
// Everything it allocates is bounded by the limits below, checked before the
// allocation: the JSON's size, nesting and value count before tinygltf parses it,
// the scene's instanced nodes, triangles and vertices before any buffer is read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "bake/triangle_mesh.h"

namespace frusta {

struct GltfLimits {
  // bytes read from disk: the input, each buffer, and all of them together
  static constexpr size_t kMaxFileBytes = size_t{512} << 20;
  static constexpr size_t kMaxJsonBytes = size_t{256} << 20;
  // glTF's own structure nests 8 deep; this leaves extras room to spare
  static constexpr int kMaxJsonDepth = 64;
  static constexpr size_t kMaxJsonValues = size_t{1} << 22;
  // scene graph: node nesting (deeper is taken for a cycle), and what instancing a
  // node many times (children listed more than once, shared subtrees) may ask for
  static constexpr int kMaxNodeDepth = 64;
  static constexpr uint64_t kMaxNodeInstances = uint64_t{1} << 20;
  static constexpr uint64_t kMaxTriangles = uint64_t{1} << 24;
  static constexpr uint64_t kMaxVertices = uint64_t{1} << 25;  // indices are uint32
};

struct GltfLoadResult {
  TriangleMesh mesh;
  std::vector<std::string> warnings;
  int primitives = 0;  // triangle primitives read
};

// FRUSTA_ERROR_IO when the input cannot be read (missing, not a regular file, over
// kMaxFileBytes), FRUSTA_ERROR_FILE_FORMAT when it is not valid glTF, breaks a
// limit, names a buffer it may not read, or its data is inconsistent; the message
// names the file and the part (buffer, mesh, primitive, accessor, node) at fault.
frusta_result load_gltf_triangles(const std::string& path, GltfLoadResult* out);

}  // namespace frusta
