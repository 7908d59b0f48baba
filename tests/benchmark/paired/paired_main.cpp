// SPDX-License-Identifier: MIT
// tools/bench paired: two builds of the solver in one process (paired_half.cpp, half a
// the baseline, half b the tree as it stands), their steps alternated one by one so that
// this machine's slow phases (1.25-1.6 times, 2-8 ms long: the solver suite's
// machine_noise_fixed_work) fall on both alike. Each step's least time over the runs, then
// the figures of each half and b's time over a's: what one build's own runs, minutes
// apart, could not tell below some 5 %.
// Arguments: RUNS LEAVES [SCENE] (SCENE: a hand scenario instead of the ball of LEAVES).
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "benchmark/percentile.h"

extern "C" {
void* paired_make_a(int32_t leaves, const char* scene);
int32_t paired_steps_a(void* half);
void paired_restart_a(void* half);
double paired_step_a(void* half, int32_t t);
uint64_t paired_hash_a(void* half);
void* paired_make_b(int32_t leaves, const char* scene);
int32_t paired_steps_b(void* half);
void paired_restart_b(void* half);
double paired_step_b(void* half, int32_t t);
uint64_t paired_hash_b(void* half);
}

namespace {

using frusta::bench::percentile;

double sum(const std::vector<double>& v) {
  double total = 0.0;
  for (double x : v) total += x;
  return total;
}

void print_half(const char* name, const std::vector<double>& us) {
  std::printf("\"%s\": {\"p50_us\": %.2f, \"p99_us\": %.2f, \"max_us\": %.2f, \"sum_us\": %.0f}, ", name,
              percentile(us, 0.5), percentile(us, 0.99), percentile(us, 1.0), sum(us));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s RUNS LEAVES [SCENE]\n", argv[0]);
    return 2;
  }
  const int runs = std::max(1, std::atoi(argv[1]));
  const int32_t leaves = std::atoi(argv[2]);
  const std::string scene = argc > 3 ? argv[3] : "";
  void* a = paired_make_a(leaves, scene.c_str());
  void* b = paired_make_b(leaves, scene.c_str());
  const int32_t steps = paired_steps_a(a);
  if (paired_steps_b(b) != steps) {
    std::fprintf(stderr, "the two builds script the scenario differently\n");
    return 1;
  }
  std::vector<double> least_a(static_cast<size_t>(steps), 1e300), least_b = least_a;
  bool same_hands = true;
  for (int r = 0; r < runs; ++r) {
    paired_restart_a(a);
    paired_restart_b(b);
    for (int32_t t = 0; t < steps; ++t) {
      const size_t i = static_cast<size_t>(t);
      // which half goes first alternates too: the second finds the caches as the first left them
      if ((t + r) % 2 == 0) {
        least_a[i] = std::min(least_a[i], paired_step_a(a, t));
        least_b[i] = std::min(least_b[i], paired_step_b(b, t));
      } else {
        least_b[i] = std::min(least_b[i], paired_step_b(b, t));
        least_a[i] = std::min(least_a[i], paired_step_a(a, t));
      }
    }
    same_hands = same_hands && paired_hash_a(a) == paired_hash_b(b);
  }
  // b's time over a's for a's 30 dearest steps (the tail a p99 comes from), and over all
  std::vector<size_t> order(least_a.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t x, size_t y) { return least_a[x] > least_a[y]; });
  std::vector<double> ratios;
  for (size_t k = 0; k < std::min<size_t>(30, order.size()); ++k) ratios.push_back(least_b[order[k]] / least_a[order[k]]);
  std::printf("{\"suite\": \"paired\", \"scene\": \"%s\", \"leaves\": %d, \"steps\": %d, \"runs\": %d, ",
              scene.empty() ? "ball_grasp" : scene.c_str(), scene.empty() ? leaves : 0, steps, runs);
  print_half("a", least_a);
  print_half("b", least_b);
  std::printf("\"b_over_a_dearest_30_median\": %.4f, \"b_over_a_dearest_30_q25\": %.4f, "
              "\"b_over_a_dearest_30_q75\": %.4f, \"b_over_a_sum\": %.4f, \"same_hands\": %s}\n",
              percentile(ratios, 0.5), percentile(ratios, 0.25), percentile(ratios, 0.75),
              sum(least_b) / sum(least_a), same_hands ? "true" : "false");
  return 0;
}
