// SPDX-License-Identifier: MIT
// frusta-bake: glTF 2.0 mesh in, sphere tree (.frtree) out, with its measured error.
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>

#include "bake/baker.h"
#include "core/error.h"
#include "gltf_loader.h"
#include "spheretree/tree_file.h"

namespace {

enum ExitCode {
  kOk = 0,
  kUsage = 2,
  kUnreadableInput = 3,
  kBakeFailed = 4,
  kWriteFailed = 5,
  kTargetMissed = 6,
};

const char* const kHelp = R"(usage: frusta-bake [options] INPUT.gltf|INPUT.glb

Builds the sphere tree of every triangle in the glTF scene (node transforms
applied, metres) and writes it to a .frtree file. Leaves are spheres fitted to the
surface from the inside plus inscribed spheres filling the interior.

Both error figures are measured on fresh random points after the bake:
  uncovered   the largest distance from the mesh surface to the leaves: how far a
              finger can sink into the true surface before it touches a leaf
  protruding  the largest distance a leaf stands out of the mesh: how far above
              the true surface a finger stops

options (a value outside its range is refused with exit code 2):
  -o, --output PATH    where to write the tree (default: INPUT with .frtree)
  --max-error MM       target for both error figures, millimetres, 0.01..1000
                       (default 1)
  --max-leaves N       leaf budget, 1..16777216; a target it does not fit is
                       coarsened until the cover fits (the figures say how far;
                       default 200000)
  --branching N        children per tree node, 2..16 (default 4)
  --max-depth N        refuse trees deeper than this, 1..40 (default 40)
  --samples N          points behind each error figure, 1000..10000000; >= 100000
                       recommended (default 100000)
  --seed N             random seed of the sampling, 0..2^64-1 (default 1): same
                       input, same tree
  --reproducible       store 0 as the bake's time in the file, so that the same
                       input and options give the same bytes (the sample objects)
  --json               print one JSON object on stdout instead of the summary
  -q, --quiet          no summary and no progress bar
  -h, --help           this text

The input's buffers must be data: URIs, the GLB's own chunk, or regular files in
the input's folder; images are never read. See README "Sphere trees and baking"
for the loader's limits.

exit codes:
  0 written, both figures within the target
  2 bad usage          3 unreadable or invalid input
  4 bake failed        5 the output could not be written
  6 written, but a figure misses the target (the leaf budget did not fit it)
)";

struct Options {
  std::string input, output;
  frusta::BakeParams params;
  bool json = false, quiet = false, reproducible = false;
  std::map<frusta::BakeField, std::string> given;  // option and text behind each field
};

int usage(const std::string& message) {
  std::fprintf(stderr, "frusta-bake: %s\n(run frusta-bake --help for the options)\n",
               message.c_str());
  return kUsage;
}

bool real_number(const char* text, double* out) {
  char* end = nullptr;
  *out = std::strtod(text, &end);
  return end != text && *end == '\0';
}

// integers as integers: "1e30", "nan" and "4.5" are not, nor is what overflows 64 bits
bool integer(const char* text, int64_t* out) {
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(text, &end, 10);
  if (end == text || *end != '\0' || errno == ERANGE) return false;
  *out = v;
  return true;
}

bool unsigned_integer(const char* text, uint64_t* out) {
  if (*text < '0' || *text > '9') return false;  // strtoull would take "-1" as 2^64 - 1
  char* end = nullptr;
  errno = 0;
  const unsigned long long v = std::strtoull(text, &end, 10);
  if (*end != '\0' || errno == ERANGE) return false;
  *out = v;
  return true;
}

int parse(int argc, char** argv, Options* o) {
  using frusta::BakeField;
  const std::map<std::string, BakeField> integers = {{"--max-leaves", BakeField::kLeaves},
                                                     {"--branching", BakeField::kBranching},
                                                     {"--max-depth", BakeField::kDepth},
                                                     {"--samples", BakeField::kSamples}};
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-h" || a == "--help") {
      std::fputs(kHelp, stdout);
      std::exit(kOk);
    }
    if (a == "--json") { o->json = true; continue; }
    if (a == "--reproducible") { o->reproducible = true; continue; }
    if (a == "-q" || a == "--quiet") { o->quiet = true; continue; }
    if (a.rfind("-", 0) == 0) {
      if (i + 1 >= argc) return usage(a + " needs a value");
      const char* value = argv[++i];
      if (a == "-o" || a == "--output") { o->output = value; continue; }
      const std::string given = a + " " + value;
      if (a == "--max-error") {
        double mm = 0.0;
        if (!real_number(value, &mm)) return usage(a + " needs a number, got '" + value + "'");
        o->params.target_error = mm * 1e-3;
        o->given[BakeField::kTarget] = given + " (mm)";
      } else if (a == "--seed") {
        if (!unsigned_integer(value, &o->params.seed))
          return usage(a + " needs an integer 0..2^64-1, got '" + value + "'");
      } else if (const auto field = integers.find(a); field != integers.end()) {
        int64_t v = 0;
        if (!integer(value, &v)) return usage(a + " needs an integer, got '" + value + "'");
        switch (field->second) {
          case BakeField::kLeaves:
            o->params.max_leaves = v;
            break;
          case BakeField::kBranching:
            o->params.branching = v;
            break;
          case BakeField::kDepth:
            o->params.max_depth = v;
            break;
          default:
            o->params.error_samples = v;
            break;
        }
        o->given[field->second] = given;
      } else {
        return usage("unknown option " + a);
      }
      continue;
    }
    if (!o->input.empty()) return usage("only one input file");
    o->input = a;
  }
  // the ranges: the same check as the C ABI's (bake/bake_params.h)
  BakeField field = BakeField::kNone;
  if (frusta::check_bake_params(o->params, &field) != FRUSTA_OK)
    return usage(o->given[field] + ": " + frusta::last_error_message());
  if (o->input.empty()) return usage("no input file");
  if (o->output.empty()) {
    const size_t dot = o->input.find_last_of('.');
    const size_t slash = o->input.find_last_of('/');
    o->output = (dot != std::string::npos && (slash == std::string::npos || dot > slash)
                     ? o->input.substr(0, dot) : o->input) + ".frtree";
  }
  return kOk;
}

void json_string(const std::string& s) {
  std::putchar('"');
  for (char c : s) {
    if (c == '"' || c == '\\') std::printf("\\%c", c);
    else if (static_cast<unsigned char>(c) < 0x20) std::printf("\\u%04x", c);
    else std::putchar(c);
  }
  std::putchar('"');
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (int code = parse(argc, argv, &o)) return code;

  frusta::GltfLoadResult input;
  if (frusta::load_gltf_triangles(o.input, &input) != FRUSTA_OK) {
    std::fprintf(stderr, "frusta-bake: %s\n", frusta::last_error_message());
    return kUnreadableInput;
  }
  for (const std::string& w : input.warnings) std::fprintf(stderr, "frusta-bake: warning: %s\n", w.c_str());
  if (frusta::check_mesh(input.mesh, o.input.c_str()) != FRUSTA_OK) {
    std::fprintf(stderr, "frusta-bake: %s\n", frusta::last_error_message());
    return kUnreadableInput;
  }

  const bool bar = !o.quiet && isatty(STDERR_FILENO);
  const frusta::ProgressFn progress = [bar](double fraction) {
    if (bar) {
      const int filled = static_cast<int>(fraction * 40.0);
      std::fprintf(stderr, "\r  baking [%.*s%*s] %3d%%", filled, "########################################",
                   40 - filled, "", static_cast<int>(fraction * 100.0));
    }
    return true;
  };
  frusta::TreeFile file;
  bool met = false;
  const frusta_result r = frusta::bake_sphere_tree(input.mesh, o.params, progress, &file, &met);
  if (bar) std::fputs("\r\033[K", stderr);
  if (r != FRUSTA_OK) {
    std::fprintf(stderr, "frusta-bake: %s: %s\n", o.input.c_str(), frusta::last_error_message());
    return kBakeFailed;
  }
  // the time is the only part of a bake that differs between runs
  const double seconds = file.bake.bake_seconds;
  if (o.reproducible) file.bake.bake_seconds = 0.0;
  if (frusta::save_tree_file(o.output, file) != FRUSTA_OK) {
    std::fprintf(stderr, "frusta-bake: %s\n", frusta::last_error_message());
    return kWriteFailed;
  }

  const frusta::BakeRecord& b = file.bake;
  if (o.json) {
    std::printf("{\"input\": ");
    json_string(o.input);
    std::printf(", \"output\": ");
    json_string(o.output);
    std::printf(", \"triangles\": %zu, \"leaves\": %zu, \"nodes\": %zu, \"depth\": %d, "
                "\"branching\": %d, \"bake_seconds\": %.4f, \"target_error_mm\": %.4f, "
                "\"uncovered_error_mm\": %.4f, \"protruding_error_mm\": %.4f, "
                "\"error_samples\": %lld, \"target_met\": %s, \"warnings\": %zu}\n",
                input.mesh.triangles.size(), file.tree.leaves.size(), file.tree.nodes.size(),
                file.tree.depth, file.tree.branching, seconds, b.target_error * 1e3,
                b.uncovered_error * 1e3, b.protruding_error * 1e3,
                static_cast<long long>(b.error_samples), met ? "true" : "false",
                input.warnings.size());
  } else if (!o.quiet) {
    std::printf("%s -> %s\n  %zu triangles, %zu leaves, depth %d (branching %d), %.2f s\n"
                "  uncovered  %.3f mm  (surface to leaves)\n"
                "  protruding %.3f mm  (leaves above the surface)\n"
                "  measured on %lld points each; target %.3f mm: %s\n",
                o.input.c_str(), o.output.c_str(), input.mesh.triangles.size(),
                file.tree.leaves.size(), file.tree.depth, file.tree.branching, seconds,
                b.uncovered_error * 1e3, b.protruding_error * 1e3,
                static_cast<long long>(b.error_samples), b.target_error * 1e3,
                met ? "met" : "NOT met (raise --max-leaves or --max-error)");
  }
  if (!met) {
    if (o.quiet || o.json)
      std::fprintf(stderr, "frusta-bake: %s: target %.3f mm not met within %lld leaves\n",
                   o.input.c_str(), b.target_error * 1e3, static_cast<long long>(b.max_leaves));
    return kTargetMissed;
  }
  return kOk;
}
