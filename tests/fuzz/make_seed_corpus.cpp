// SPDX-License-Identifier: MIT
// Writes a few valid tree files into DIR: the fuzzer's starting points.
#include <cstdio>
#include <fstream>
#include <random>
#include <string>

#include "spheretree/tree_builder.h"
#include "spheretree/tree_file.h"

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-0.1, 0.1), r(0.001, 0.01);
  for (int count : {1, 2, 7, 40}) {
    std::vector<frusta::Sphere> leaves;
    for (int i = 0; i < count; ++i) leaves.push_back({frusta::vec3(u(rng), u(rng), u(rng)), r(rng)});
    frusta::TreeFile file;
    if (frusta::build_sphere_tree(leaves, {3}, &file.tree) != FRUSTA_OK) return 1;
    const std::vector<uint8_t> bytes = frusta::encode_tree_file(file);
    std::ofstream(std::string(argv[1]) + "/seed" + std::to_string(count) + ".frtree", std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  }
  return 0;
}
