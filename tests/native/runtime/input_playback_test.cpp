// SPDX-License-Identifier: MIT
// Timed input, through a world the test steps on its step clock: a scripted haptic
// trajectory sampled at 1 kHz, stamped with noisy times and delivered late in bursts
// after host stalls of 5, 10, 20 and 50 ms, is played input_delay behind each step
// exactly as the trajectory (piecewise linear: exact between samples of one piece);
// past the newest sample it is extrapolated for max_extrapolation, then held, and
// rejoins the samples without a jump when they come; and the playback itself.
#include "runtime/input_playback.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "core/error.h"
#include "hand/anthropometry.h"
#include "hand/hand_model.h"
#include "runtime/world.h"
#include "scenes/hand_scenarios.h"
#include "scenes/jittery_host.h"
#include "allocation_counter.h"

namespace frusta {
namespace {

constexpr double kDt = 1e-3;

// The scripted hand: the palm moves straight, turning its velocity every 300 ms (at
// 125, 425, ... ms: never within a stall's extrapolation), turns about z at a constant
// rate, and the index curls and uncurls at a constant rate between the same kinks.
double kink(int64_t k) { return 0.125 + 0.3 * static_cast<double>(k); }

vec3 velocity_of_piece(int64_t k) {
  return vec3(0.10 * std::cos(1.3 * static_cast<double>(k)), 0.08 * std::sin(0.7 * static_cast<double>(k)),
              k % 2 == 0 ? 0.05 : -0.05);
}

HandState trajectory(double t) {
  HandState s = scenes::open_hand();
  vec3 p(0.0);
  double curl = 0.2, edge = 0.0;
  for (int64_t k = -1;; ++k) {
    const double end = k < 0 ? 0.125 : kink(k + 1);
    const double run = std::min(t, end) - edge;
    if (run > 0.0) {
      p += velocity_of_piece(k) * run;
      curl += (k % 2 == 0 ? 0.4 : -0.4) * run;
    }
    if (t <= end) break;
    edge = end;
  }
  s.palm_position = p;
  s.palm_rotation = glm::angleAxis(0.5 * t, vec3(0.0, 0.0, 1.0));
  s.angles[4] = curl;  // the index's MCP flexion
  return s;
}

// whether a kink of the trajectory lies within [a, b]
bool kink_between(double a, double b) {
  for (int64_t k = 0; kink(k) <= b; ++k)
    if (kink(k) >= a) return true;
  return false;
}

double palm_error(const HandState& a, const HandState& b) {
  return glm::length(a.palm_position - b.palm_position);
}

double rotation_error(const HandState& a, const HandState& b) {
  return 2.0 * std::acos(std::min(1.0, std::fabs(glm::dot(a.palm_rotation, b.palm_rotation))));
}

struct Played {
  HandState haptic;
  bool late = false;
  double newest = -1.0;  // the stamp of the newest sample delivered before the step, s
};

// One run: the host's samples of the trajectory delivered as `host` says, the world
// stepped `steps` times, what each step played (index: the step, 1..steps); the host
// stops sending after `last_sample`.
std::vector<Played> run(const scenes::JitteryHost& host, int64_t steps, int64_t last_sample,
                        const WorldDef& def = WorldDef{}) {
  World world(def);
  HandHandle hand;
  EXPECT_EQ(world.add_hand(make_hand_model(default_hand_def()), &hand), FRUSTA_OK);
  std::vector<Played> played(static_cast<size_t>(steps + 1));
  std::vector<int64_t> samples;
  double newest = -1.0;
  for (int64_t n = 1; n <= steps; ++n) {
    host.delivered_before(n, &samples);
    for (int64_t j : samples) {
      if (j > last_sample) continue;
      const double t = host.stamp(j);
      newest = t;
      EXPECT_EQ(world.set_haptic_at(hand, trajectory(t), static_cast<int64_t>(std::llround(t * 1e9))),
                FRUSTA_OK)
          << last_error_message();
    }
    world.step();
    const HandSnapshot* snap = world.read().hand(hand);
    played[static_cast<size_t>(n)] = {snap->haptic, snap->input_late, newest};
  }
  return played;
}

TEST(InputPlayback, SamplesDeliveredLateInBurstsArePlayedAsTheTrajectory) {
  const WorldDef def;
  ASSERT_DOUBLE_EQ(def.input_delay, 0.010);
  ASSERT_DOUBLE_EQ(def.max_extrapolation, 0.040);
  for (uint32_t seed = 1; seed <= 4; ++seed) {
    // a stall every 150 ms, shifted per run; stamps off by up to 0.3 ms
    const scenes::JitteryHost host(scenes::JitteryHost::stall_cycle(200 + 7 * seed, 1900, 150),
                                   0.0003, seed);
    const std::vector<Played> played = run(host, 2000, 2000);
    int late = 0;
    int64_t last_late = -1000;
    double worst = 0.0, worst_late = 0.0, worst_turn = 0.0, worst_rejoin = 0.0;
    for (int64_t n = 20; n <= 2000; ++n) {
      const double at = static_cast<double>(n) * kDt - def.input_delay;
      const Played& p = played[static_cast<size_t>(n)];
      const HandState want = trajectory(at);
      // between two samples of one piece the interpolation is exact; across a kink it
      // is off by at most the change of velocity times a quarter of the samples' gap
      const double tolerance = kink_between(at - 0.002, at + 0.002) ? 2e-4 : 1e-9;
      if (p.late) {
        // extrapolated from the newest sample for at most max_extrapolation, then held
        ++late;
        last_late = n;
        const double reached = std::min(at, p.newest + def.max_extrapolation);
        worst_late = std::max(worst_late, palm_error(p.haptic, trajectory(reached)));
      } else if (n - last_late <= InputPlayback::kRejoinNs / 1'000'000) {
        // the samples came at last: what the extrapolation was off by fades out
        worst_rejoin = std::max(worst_rejoin, palm_error(p.haptic, want));
      } else {
        worst = std::max(worst, palm_error(p.haptic, want) / tolerance);
        EXPECT_NEAR(p.haptic.angles[4], want.angles[4], tolerance * 10.0) << "step " << n;
      }
      if (n - last_late > InputPlayback::kRejoinNs / 1'000'000)
        worst_turn = std::max(
            worst_turn, rotation_error(p.haptic, trajectory(std::min(at, p.newest + def.max_extrapolation))));
    }
    EXPECT_LE(worst, 1.0) << "seed " << seed << ": played off the trajectory (in tolerances)";
    // 50 ms stalls outrun the 10 ms delay by up to 40 ms, which extrapolation bridges:
    // each piece is straight, so the extrapolated palm is the trajectory too
    EXPECT_GT(late, 60) << "seed " << seed;
    EXPECT_LT(worst_late, 1e-6) << "seed " << seed << ": extrapolated off the trajectory";
    EXPECT_LT(worst_turn, 1e-6) << "seed " << seed << ": the palm's turn";
    // the 50 ms stalls run 40 ms past the newest sample, all of it extrapolated, on a
    // straight piece exactly; the stamps' noise puts the last steps up to 0.3 ms past
    // that, held: a few hundredths of a millimetre to fade out
    EXPECT_LT(worst_rejoin, 1e-4) << "seed " << seed << ": the rejoin";
  }
}

TEST(InputPlayback, WithinTheDelayAStallIsNeverLate) {
  // stalls of 5 ms only: every sample a step plays has arrived
  const scenes::JitteryHost host({{300, 5}, {600, 5}, {900, 5}}, 0.0003, 9);
  const std::vector<Played> played = run(host, 1000, 1000);
  for (int64_t n = 20; n <= 1000; ++n) EXPECT_FALSE(played[static_cast<size_t>(n)].late) << n;
}

TEST(InputPlayback, AStreamThatStopsIsExtrapolatedHeldAndThenGoesBackToItsNewestSample) {
  const WorldDef def;
  const scenes::JitteryHost host({}, 0.0, 3);
  const std::vector<Played> played = run(host, 1400, 1100);  // the last sample: 1.100 s
  // step n plays n ms - 10 ms: past 1.100 s from step 1111 on, extrapolated until 1.140 s
  // (the trajectory is straight from 1.025 s to 1.325 s), held there for kStopNs
  EXPECT_FALSE(played[1110].late);
  EXPECT_TRUE(played[1111].late);
  EXPECT_LT(palm_error(played[1130].haptic, trajectory(1.120)), 1e-9) << "extrapolated";
  EXPECT_LT(palm_error(played[1150].haptic, trajectory(1.140)), 1e-9) << "as far as max_extrapolation";
  EXPECT_LT(palm_error(played[1250].haptic, trajectory(1.140)), 1e-9) << "then held";
  EXPECT_NEAR(played[1250].haptic.angles[4], trajectory(1.140).angles[4], 1e-9);
  EXPECT_LT(rotation_error(played[1250].haptic, trajectory(1.140)), 1e-9);
  // then it has stopped: back to the newest sample over kRejoinNs, never in a jump
  const int64_t back = 1251 + InputPlayback::kRejoinNs / 1'000'000;
  for (int64_t n = 1251; n <= back; ++n)
    EXPECT_LT(palm_error(played[static_cast<size_t>(n)].haptic, played[static_cast<size_t>(n - 1)].haptic), 3e-4);
  EXPECT_LT(palm_error(played[1400].haptic, trajectory(1.100)), 1e-12);
  EXPECT_LT(rotation_error(played[1400].haptic, trajectory(1.100)), 1e-9);
  // with no extrapolation, held at the newest at once
  WorldDef hold = def;
  hold.max_extrapolation = 0.0;
  const std::vector<Played> held = run(host, 1200, 1100, hold);
  EXPECT_LT(palm_error(held[1200].haptic, trajectory(1.100)), 1e-12);
}

TEST(InputPlayback, AfterAStallLongerThanItsBridgeTheHandRejoinsItsSamplesWithoutAJump) {
  // a 100 ms stall on a straight piece: 10 ms of delay and 40 of extrapolation bridge
  // half of it, then the hand holds; when the burst comes it rejoins over kRejoinNs,
  // never moving further in a step than the trajectory's speed plus the fade
  const scenes::JitteryHost host({{500, 100}}, 0.0, 4);
  const std::vector<Played> played = run(host, 800, 800);
  double worst_step = 0.0;
  for (int64_t n = 450; n <= 800; ++n)
    worst_step = std::max(worst_step, palm_error(played[static_cast<size_t>(n)].haptic,
                                                 played[static_cast<size_t>(n - 1)].haptic));
  // held 50 ms short at the trajectory's 0.077 m/s: 3.8 mm to make up in 20 ms
  EXPECT_LT(worst_step, 0.0003) << "at most 0.3 mm a step";
  EXPECT_TRUE(played[599].late);
  EXPECT_FALSE(played[600].late);
  const int64_t rejoined = 600 + InputPlayback::kRejoinNs / 1'000'000;
  EXPECT_LT(palm_error(played[static_cast<size_t>(rejoined)].haptic, trajectory(rejoined * kDt - 0.010)), 1e-9);
  EXPECT_GT(palm_error(played[600].haptic, trajectory(0.590)), 0.001) << "not jumped";
}

TEST(InputPlayback, ZeroDelayPlaysTheNewestSampleOfAnEvenHost) {
  WorldDef def;
  def.input_delay = 0.0;
  const scenes::JitteryHost host({}, 0.0, 1);
  const std::vector<Played> played = run(host, 500, 500, def);
  for (int64_t n = 1; n <= 500; ++n) {
    EXPECT_FALSE(played[static_cast<size_t>(n)].late);
    EXPECT_LT(palm_error(played[static_cast<size_t>(n)].haptic, trajectory(static_cast<double>(n) * kDt)), 1e-12);
  }
}

TEST(InputPlayback, UntimedInputsOfAHostThatStepsAreTakenAsTheyAre) {
  World world(WorldDef{});
  HandHandle hand;
  ASSERT_EQ(world.add_hand(make_hand_model(default_hand_def()), &hand), FRUSTA_OK);
  for (int n = 1; n <= 50; ++n) {
    ASSERT_EQ(world.set_haptic(hand, trajectory(0.01 * n)), FRUSTA_OK);
    world.step();
    EXPECT_EQ(world.read().hand(hand)->haptic.palm_position, trajectory(0.01 * n).palm_position);
    EXPECT_FALSE(world.read().hand(hand)->input_late);
  }
  // a timed sample after them starts the hand's playback over, and an untimed one after
  // that is again taken as it is
  ASSERT_EQ(world.set_haptic_at(hand, trajectory(3.0), 3'000'000'000), FRUSTA_OK);
  world.step();
  EXPECT_EQ(world.read().hand(hand)->haptic.palm_position, trajectory(3.0).palm_position);
  ASSERT_EQ(world.set_haptic(hand, trajectory(4.0)), FRUSTA_OK);
  world.step();
  EXPECT_EQ(world.read().hand(hand)->haptic.palm_position, trajectory(4.0).palm_position);
}

TEST(InputPlayback, TimedSamplesOutOfOrderAreRefused) {
  World world(WorldDef{});
  HandHandle hand;
  ASSERT_EQ(world.add_hand(make_hand_model(default_hand_def()), &hand), FRUSTA_OK);
  ASSERT_EQ(world.set_haptic_at(hand, trajectory(0.0), 5'000'000), FRUSTA_OK);
  EXPECT_EQ(world.set_haptic_at(hand, trajectory(0.0), 5'000'000), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_NE(std::string(last_error_message()).find("previous sample"), std::string::npos);
  EXPECT_EQ(world.set_haptic_at(hand, trajectory(0.0), 4'000'000), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_EQ(world.set_haptic_at(hand, trajectory(0.0), 5'000'001), FRUSTA_OK);
}

TEST(InputPlayback, ABurstLargerThanThePortsQueueKeepsItsNewest) {
  // 200 samples between two steps: the port keeps 64 in order and the newest
  World world(WorldDef{});
  HandHandle hand;
  ASSERT_EQ(world.add_hand(make_hand_model(default_hand_def()), &hand), FRUSTA_OK);
  for (int j = 1; j <= 200; ++j)
    ASSERT_EQ(world.set_haptic_at(hand, trajectory(j * kDt), j * 1'000'000), FRUSTA_OK);
  for (int n = 1; n <= 300; ++n) world.step();
  // step 300 plays 290 ms: past the newest (200 ms) by more than max_extrapolation
  const HandSnapshot* snap = world.read().hand(hand);
  EXPECT_TRUE(snap->input_late);
  EXPECT_LT(palm_error(snap->haptic, trajectory(0.200)), 0.01) << "held near the newest";
}

TEST(InputPlayback, TimedStepsAllocateNothing) {
  World world(WorldDef{});
  HandHandle hand;
  ASSERT_EQ(world.add_hand(make_hand_model(default_hand_def()), &hand), FRUSTA_OK);
  const scenes::JitteryHost host(scenes::JitteryHost::stall_cycle(100, 3000, 150), 0.0003, 5);
  std::vector<int64_t> samples;
  samples.reserve(64);
  int64_t before = 0;
  for (int64_t n = 1; n <= 3000; ++n) {
    if (n == 300) before = allocation_count();  // warmed up
    host.delivered_before(n, &samples);
    for (int64_t j : samples)
      world.set_haptic_at(hand, trajectory(host.stamp(j)), static_cast<int64_t>(std::llround(host.stamp(j) * 1e9)));
    world.step();
  }
  EXPECT_EQ(allocation_count() - before, 0);
}

// The playback on its own: a sample set twice (queue and newest) is taken once.
TEST(InputPlayback, TheSameSampleTwiceIsTakenOnce) {
  InputPlayback playback;
  TimedInput a;
  a.sequence = 1;
  a.time_ns = 10;
  a.timed = true;
  EXPECT_TRUE(playback.push(a));
  EXPECT_FALSE(playback.push(a));
  a.sequence = 2;
  a.time_ns = 20;
  EXPECT_TRUE(playback.push(a));
  EXPECT_EQ(playback.size(), 2u);
}

// A stream that keeps coming, but later than max_extrapolation + kStopNs: at each step
// its newest sample lies just past that bound (the stream has stopped), yet at the time
// played the step before it did not (that newest is later than the one then). The
// samples' answer for the time played before must follow the step's own rule: read as
// extrapolated while the step's answer held the newest, every new sample was taken for
// a jump of max_extrapolation's worth and the fades piled up, the hand running backwards
// 9 cm past its first sample within a few steps (the threaded World test met it under
// load). The hand stays between its first sample and the newest's extrapolation.
TEST(InputPlayback, AStreamLaggingPastItsStopNeverRunsAway) {
  constexpr int64_t kMs = 1'000'000, kMaxExtrapolation = 40 * kMs;
  auto sample = [](int64_t j) {  // 1 mm a millisecond
    TimedInput in;
    in.sequence = static_cast<uint64_t>(j);
    in.time_ns = j * kMs;
    in.timed = true;
    in.state.palm_position = vec3(1e-3 * static_cast<double>(j), 0.0, 0.0);
    return in;
  };
  InputPlayback playback;
  int64_t newest = 0;
  while (newest < 50) playback.push(sample(++newest));
  double lowest = INFINITY, highest = -INFINITY;
  int64_t behind = 0;  // steps whose samples ended more than the bound before them
  for (int64_t at = 50 * kMs; at <= 600 * kMs; at += kMs) {
    // the stream stalls, then keeps a millisecond past the bound behind the steps
    while (at - newest * kMs > kMaxExtrapolation + InputPlayback::kStopNs + kMs)
      playback.push(sample(++newest));
    behind += at - newest * kMs > kMaxExtrapolation + InputPlayback::kStopNs;
    bool late = false;
    const double x = playback.play(at, kMaxExtrapolation, &late).palm_position.x;
    lowest = std::min(lowest, x);
    highest = std::max(highest, x - 1e-3 * static_cast<double>(newest));
  }
  EXPECT_GT(behind, 400);
  EXPECT_GE(lowest, 1e-3 - 1e-12) << "behind the first sample";
  EXPECT_LE(highest, 1e-3 * 40.0 + 1e-12) << "beyond the newest's extrapolation";
}

}  // namespace
}  // namespace frusta

namespace frusta {
namespace {

// Samples stamped when they were set (a glove's, a host's untimed ones) are played by
// those times but never extrapolated: a burst squeezes them together, and their
// velocity would fling the hand.
TEST(InputPlayback, UnstampedSamplesAreHeldPastTheNewestNotExtrapolated) {
  InputPlayback playback;
  for (int j = 1; j <= 100; ++j) {
    TimedInput in;
    in.state = trajectory(j * kDt);  // 100 ms of motion, arrived within 100 us
    in.sequence = static_cast<uint64_t>(j);
    in.time_ns = in.set_ns = 1'000'000'000 + j * 1'000;
    in.timed = false;
    ASSERT_TRUE(playback.push(in));
  }
  bool late = false;
  const HandState held = playback.play(1'000'000'000 + 30'000'000, 40'000'000, &late);
  EXPECT_TRUE(late);
  EXPECT_LT(palm_error(held, trajectory(0.100)), 1e-12);
}

}  // namespace
}  // namespace frusta
