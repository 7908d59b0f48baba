// SPDX-License-Identifier: MIT
// frusta-bake-trace OUT.txt | --compare REFERENCE.txt
// A bake through the C ABI as the Unity editor's bake window makes it (frusta_start_bake,
// then frusta_finish_bake_job: the runtime loads the baker library from beside itself),
// written at full precision to compare across platforms: the sample mug (the mesh the
// sample generator writes as mug.gltf; a handle through the wall: concave, with a
// hole, so both the point queries and the rays decide) and the box. tools/test-windows-baker writes the trace with the Linux libraries, then
// runs the Windows build under Wine with --compare against the DLLs of the package's
// tarball: the same tree shape, every leaf within kTolerance, or the first difference
// named. The two bakers run one source with the same seed; they differ in their Embree
// (Debian's, AVX2, on Linux; SSE2 only, built for Windows) and C library.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "frusta/frusta.h"
#include "meshes/meshes.h"

namespace {

using namespace frusta;

// metres: leaves and error figures may differ by a few float ulps of the mesh's
// coordinates (Embree's ray distances are floats, its kernels differ by ISA); measured
// between Linux and Wine: 7.7e-10 m, the same leaf and node counts (2026-12-03)
constexpr double kTolerance = 1e-6;

struct Object {
  const char* name;
  TriangleMesh mesh;
};

std::vector<Object> objects() {
  return {{"mug", scenes::make_mug(0.04, 0.09, 0.006, 48)},
          {"box", scenes::make_box(vec3(0.08, 0.05, 0.03))}};
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

// "object NAME leaves N nodes N depth N uncovered E protruding E", then one line per leaf
bool bake(const Object& o, std::ostream& out) {
  std::vector<float> vertices;
  for (const vec3& v : o.mesh.vertices)
    for (int i = 0; i < 3; ++i) vertices.push_back(static_cast<float>(v[i]));
  std::vector<int32_t> indices;
  for (const auto& t : o.mesh.triangles)
    for (uint32_t i : t) indices.push_back(static_cast<int32_t>(i));
  frusta_bake_def def = frusta_default_bake_def();
  def.target_error = 0.002;
  def.error_samples = 20000;
  frusta_bake_job_id job{};
  frusta_tree_id tree{};
  frusta_result r = frusta_start_bake(vertices.data(), static_cast<int32_t>(vertices.size() / 3),
                                      indices.data(), static_cast<int32_t>(indices.size()), &def, &job);
  if (r == FRUSTA_OK) r = frusta_finish_bake_job(job, &tree);
  if (r != FRUSTA_OK) {
    std::fprintf(stderr, "baking %s failed: %s\n", o.name, frusta_last_error());
    return false;
  }
  frusta_sphere_tree_info info{};
  info.struct_size = static_cast<int32_t>(sizeof info);
  int32_t count = 0;
  frusta_sphere_tree_get_info(tree, &info);
  std::vector<frusta_sphere> leaves(static_cast<size_t>(info.leaf_count));
  frusta_sphere_tree_get_leaves(tree, leaves.data(), info.leaf_count, &count);
  frusta_destroy_sphere_tree(tree);
  out << "object " << o.name << " leaves " << info.leaf_count << " nodes " << info.node_count
      << " depth " << info.depth << " uncovered " << number(info.uncovered_error)
      << " protruding " << number(info.protruding_error) << '\n';
  for (const frusta_sphere& s : leaves)
    out << "leaf " << number(s.center[0]) << ' ' << number(s.center[1]) << ' '
        << number(s.center[2]) << ' ' << number(s.radius) << '\n';
  std::printf("%s: %d leaves, %d nodes, depth %d, uncovered %.3g mm, protruding %.3g mm, %.2f s\n",
              o.name, info.leaf_count, info.node_count, info.depth, info.uncovered_error * 1e3,
              info.protruding_error * 1e3, info.bake_seconds);
  return true;
}

// Same words, numbers within kTolerance; prints the largest difference seen.
int compare(const std::string& reference_path, const std::string& trace) {
  std::ifstream reference(reference_path);
  if (!reference) {
    std::fprintf(stderr, "cannot read %s\n", reference_path.c_str());
    return 1;
  }
  std::istringstream ours(trace);
  std::string want_line, got_line;
  double largest = 0.0;
  int lines = 0;
  while (true) {
    const bool more_want = static_cast<bool>(std::getline(reference, want_line));
    const bool more_got = static_cast<bool>(std::getline(ours, got_line));
    if (!more_want && !more_got) break;
    ++lines;
    if (more_want != more_got) {
      std::fprintf(stderr, "line %d: %s ends first\n", lines, more_want ? "this bake" : "the reference");
      return 1;
    }
    std::istringstream want_words(want_line), got_words(got_line);
    std::string want, got;
    while (want_words >> want) {
      if (!(got_words >> got)) got.clear();
      if (want == got) continue;
      char* want_end = nullptr;
      char* got_end = nullptr;
      const double w = std::strtod(want.c_str(), &want_end);
      const double g = std::strtod(got.c_str(), &got_end);
      // counts (leaves, nodes, depth) and names must match exactly: only reals may differ
      const bool real = want.find_first_of(".e") != std::string::npos && *want_end == 0 && *got_end == 0;
      if (!real || !(std::fabs(w - g) <= kTolerance)) {
        std::fprintf(stderr, "line %d differs: want \"%s\", got \"%s\"\n", lines, want_line.c_str(),
                     got_line.c_str());
        return 1;
      }
      largest = std::fmax(largest, std::fabs(w - g));
    }
    if (got_words >> got) {
      std::fprintf(stderr, "line %d has more words than the reference: \"%s\"\n", lines, got_line.c_str());
      return 1;
    }
  }
  std::printf("%d lines match the reference; largest difference %.3g m (tolerance %.0e m)\n", lines,
              largest, kTolerance);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const bool comparing = argc == 3 && std::string(argv[1]) == "--compare";
  if (argc != 2 && !comparing) {
    std::fprintf(stderr, "usage: frusta-bake-trace OUT.txt | --compare REFERENCE.txt\n");
    return 2;
  }
  std::ostringstream trace;
  for (const Object& o : objects())
    if (!bake(o, trace)) return 1;
  if (comparing) return compare(argv[2], trace.str());
  std::ofstream out(argv[1], std::ios::binary);
  out << trace.str();
  return out ? 0 : 1;
}
