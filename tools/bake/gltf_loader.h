// SPDX-License-Identifier: MIT
// Every triangle of a glTF 2.0 scene (.gltf or .glb, through tinygltf), in metres,
// with node transforms applied. Primitives that are not triangles are skipped
// with a warning. Every accessor is checked before it is read.
#pragma once

#include <string>
#include <vector>

#include "bake/triangle_mesh.h"

namespace frusta {

struct GltfLoadResult {
  TriangleMesh mesh;
  std::vector<std::string> warnings;
  int primitives = 0;  // triangle primitives read
};

// FRUSTA_ERROR_IO when the file cannot be read, FRUSTA_ERROR_FILE_FORMAT when it is
// not valid glTF or its data is inconsistent; the message names the file and the
// part (mesh, primitive, accessor) at fault.
frusta_result load_gltf_triangles(const std::string& path, GltfLoadResult* out);

}  // namespace frusta
