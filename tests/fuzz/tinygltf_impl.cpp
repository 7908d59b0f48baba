// SPDX-License-Identifier: MIT
// tinygltf's implementation, compiled in the fuzz build so that libFuzzer sees (and
// the sanitizers check) the parser the glTF loader calls; see instrument.cmake.
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
