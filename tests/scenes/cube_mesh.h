// SPDX-License-Identifier: MIT
// The smallest mesh a bake test needs: a 2 cm cube centred at the origin, its 12
// triangles counter-clockwise seen from outside.
#pragma once

#include <cstdint>

namespace frusta_test {

constexpr int32_t kCubeVertexCount = 8;
constexpr int32_t kCubeIndexCount = 36;
constexpr float kCubeVertices[3 * kCubeVertexCount] = {
    -0.01f, -0.01f, -0.01f, 0.01f, -0.01f, -0.01f, 0.01f, 0.01f, -0.01f, -0.01f, 0.01f, -0.01f,
    -0.01f, -0.01f, 0.01f,  0.01f, -0.01f, 0.01f,  0.01f, 0.01f, 0.01f,  -0.01f, 0.01f, 0.01f};
constexpr int32_t kCubeIndices[kCubeIndexCount] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7,
                                                   0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5,
                                                   2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};

}  // namespace frusta_test
