// SPDX-License-Identifier: MIT
// frusta-solver-trace OUT.txt | --compare REFERENCE.txt
// The engine's results at full precision, to compare across architectures: the exact
// distance of 20000 seeded segment/sphere cases of every family, and every graphic hand
// of every hand scenario (its scripted steps, then 100 held). tools/test writes the
// x86_64 trace, then runs the arm64 build under qemu with --compare: the same results,
// to the tolerances below, or the first difference named. Both builds use
// -ffp-contract=off and SSE2/NEON doubles (no x87), so they should differ only where
// the C library's transcendental functions round differently.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "geometry/exact_distance.h"
#include "geometry/segment_frame.h"
#include "hand/anthropometry.h"
#include "hand/hand_model.h"
#include "scenes/hand_scenarios.h"
#include "scenes/random_cases.h"
#include "solver/hand_solver.h"

namespace {

using namespace frusta;

// metres and radians: a few hundred ulps; measured 3e-17 m and 6e-15 (2026-12-02)
constexpr double kDistanceTolerance = 1e-14;
constexpr double kHandTolerance = 1e-12;
constexpr int kGeometryCases = 20000;
constexpr int kHeldSteps = 100;

void write_geometry(std::ostream& out) {
  for (const scenes::Case& c : scenes::make_cases(kGeometryCases, 7)) {
    char line[64];
    std::snprintf(line, sizeof line, "distance %.17g\n", exact_distance(make_segment_frame(c.segment), c.sphere));
    out << line;
  }
}

void write_hand(std::ostream& out, const std::string& name, int32_t step, const HandState& s) {
  out << "hand " << name << ' ' << step;
  char number[32];
  const double values[] = {s.palm_position.x, s.palm_position.y, s.palm_position.z,
                           s.palm_rotation.w, s.palm_rotation.x, s.palm_rotation.y,
                           s.palm_rotation.z};
  for (double v : values) {
    std::snprintf(number, sizeof number, " %.17g", v);
    out << number;
  }
  for (double a : s.angles) {
    std::snprintf(number, sizeof number, " %.17g", a);
    out << number;
  }
  out << '\n';
}

void write_scenarios(std::ostream& out) {
  const HandModel model = make_hand_model(default_hand_def());
  for (const std::string& name : scenes::hand_scenario_names()) {
    const scenes::HandScenario s = scenes::make_hand_scenario(name);
    HandSolver solver(model, SolverParams{});
    const auto step = [&](int32_t t, const HandState& haptic) {
      StepStats stats;
      if (solver.step(haptic, s.objects.data(), static_cast<int32_t>(s.objects.size()), &stats) != FRUSTA_OK)
        out << "refused " << name << ' ' << t << '\n';
      else
        write_hand(out, name, t, solver.graphic());
    };
    for (int32_t t = 0; t < s.steps; ++t) step(t, s.haptic(t));
    for (int32_t t = 0; t < kHeldSteps; ++t) step(s.steps + t, s.held);
  }
}

// Same words, numbers within tolerance; prints the largest differences seen.
int compare(const std::string& reference_path, const std::string& trace) {
  std::ifstream reference(reference_path);
  if (!reference) {
    std::fprintf(stderr, "cannot read %s\n", reference_path.c_str());
    return 2;
  }
  std::istringstream ours(trace);
  std::string a, b;
  double worst_distance = 0.0, worst_hand = 0.0;
  for (int64_t line = 1;; ++line) {
    const bool more_a = static_cast<bool>(std::getline(reference, a));
    const bool more_b = static_cast<bool>(std::getline(ours, b));
    if (!more_a && !more_b) break;
    if (more_a != more_b) {
      std::fprintf(stderr, "line %lld: one trace ends early\n", static_cast<long long>(line));
      return 1;
    }
    std::istringstream wa(a), wb(b);
    std::string x, y;
    std::string kind;
    for (int word = 0; wa >> x; ++word) {
      if (!(wb >> y)) y.clear();
      if (word == 0) kind = x;
      char* end_x = nullptr;
      char* end_y = nullptr;
      const double vx = std::strtod(x.c_str(), &end_x), vy = std::strtod(y.c_str(), &end_y);
      const bool numbers = *end_x == 0 && *end_y == 0 && !x.empty() && !y.empty() && word > 0 &&
                           !(kind == "hand" && word <= 2);
      if (!numbers) {
        if (x != y) {
          std::fprintf(stderr, "line %lld: \"%s\" here, \"%s\" in the reference\n",
                       static_cast<long long>(line), b.c_str(), a.c_str());
          return 1;
        }
        continue;
      }
      const double difference = std::fabs(vx - vy);
      const bool distance = kind == "distance";
      double& worst = distance ? worst_distance : worst_hand;
      worst = std::fmax(worst, difference);
      if (!(difference <= (distance ? kDistanceTolerance : kHandTolerance))) {
        std::fprintf(stderr, "line %lld, value %d: %.17g here, %.17g in the reference\n",
                     static_cast<long long>(line), word, vy, vx);
        return 1;
      }
    }
  }
  std::printf("{\"geometry_max_difference_m\": %.3g, \"solver_max_difference\": %.3g, "
              "\"tolerances\": [%.0e, %.0e]}\n",
              worst_distance, worst_hand, kDistanceTolerance, kHandTolerance);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const bool comparing = argc == 3 && std::string(argv[1]) == "--compare";
  if (argc != 2 && !comparing) {
    std::fprintf(stderr, "usage: frusta-solver-trace OUT.txt | --compare REFERENCE.txt\n");
    return 2;
  }
  std::ostringstream trace;
  write_geometry(trace);
  write_scenarios(trace);
  if (comparing) return compare(argv[2], trace.str());
  std::ofstream out(argv[1]);
  out << trace.str();
  return out.good() ? 0 : 1;
}
