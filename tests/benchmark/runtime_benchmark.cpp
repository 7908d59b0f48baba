// SPDX-License-Identifier: MIT
// tools/bench runtime: what the 1 kHz thread's plumbing costs, in one run.
//  - wake-up lateness of the periodic clock at 1 kHz for several spin windows (0 =
//    sleep only), with the CPU time each costs, so jitter and burnt CPU sit side by side;
//  - the cost of reading the output snapshot (a triple buffer) in nanoseconds, with the
//    writer idle and with it publishing flat out.
// The world's step time with hands and objects joins this suite with the world.
#include <atomic>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <thread>

#include "runtime/periodic_clock.h"
#include "runtime/step_histogram.h"
#include "runtime/triple_buffer.h"

namespace frusta {
namespace {

using Clock = std::chrono::steady_clock;

double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void wake_up(int spin_us, bool last) {
  PeriodicClock clock(std::chrono::milliseconds(1), std::chrono::microseconds(spin_us));
  StepHistogram lateness;
  constexpr int kTicks = 2000;
  const double cpu0 = thread_cpu_seconds();
  clock.start();
  for (int i = 0; i < kTicks; ++i)
    lateness.record(std::chrono::duration<double, std::micro>(clock.wait()).count());
  const double cpu = thread_cpu_seconds() - cpu0;
  std::printf("  {\"spin_us\": %d, \"ticks\": %d, \"late_p50_us\": %.2f, \"late_p99_us\": %.2f, "
              "\"late_max_us\": %.2f, \"missed\": %lld, \"cpu_share\": %.3f}%s\n",
              spin_us, kTicks, lateness.percentile(0.5), lateness.percentile(0.99), lateness.max(),
              static_cast<long long>(clock.missed()), cpu / (kTicks * 1e-3), last ? "" : ",");
}

// a snapshot the size the world will publish: two hands, contacts, forces (~8 KB)
struct Snapshot {
  uint64_t step;
  double payload[1024];
};

double read_ns(bool writer_busy) {
  static TripleBuffer<Snapshot> buffer;
  std::atomic<bool> done{false};
  std::thread writer;
  if (writer_busy)
    writer = std::thread([&] {
      for (uint64_t s = 0; !done.load(std::memory_order_relaxed); ++s) {
        buffer.write_slot().step = s;
        buffer.publish();
      }
    });
  constexpr int kReads = 2000000;
  uint64_t sum = 0;
  const Clock::time_point start = Clock::now();
  for (int i = 0; i < kReads; ++i) sum += buffer.read().step;
  const double ns = std::chrono::duration<double, std::nano>(Clock::now() - start).count() / kReads;
  done = true;
  if (writer.joinable()) writer.join();
  if (sum == 1) std::printf(" ");  // keeps the reads from being optimised away
  return ns;
}

}  // namespace
}  // namespace frusta

int main() {
  using namespace frusta;
  std::printf("{\n\"suite\": \"runtime\",\n\"hardware_threads\": %u,\n\"wake_up_1khz\": [\n",
              std::thread::hardware_concurrency());
  const int spins[] = {0, 50, 200, 1000};
  for (size_t i = 0; i < std::size(spins); ++i) wake_up(spins[i], i + 1 == std::size(spins));
  std::printf("],\n\"snapshot_read_ns\": {\"writer_idle\": %.2f, \"writer_publishing\": %.2f, \"snapshot_bytes\": %zu}\n}\n",
              read_ns(false), read_ns(true), sizeof(Snapshot));
  return 0;
}
