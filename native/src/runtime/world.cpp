// SPDX-License-Identifier: MIT
#include "runtime/world.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/error.h"
#include "core/periodic_clock.h"

namespace frusta {

namespace {

// after a stall of the world's own thread, the hands play 1 + 1/kCatchUpDivisor periods
// of their inputs a step until they are input_delay behind again; beyond kMaxPlayLagNs
// behind (a world stopped and started again), they jump
constexpr int64_t kCatchUpDivisor = 4;
constexpr int64_t kMaxPlayLagNs = 500'000'000;

}  // namespace

World::World(const WorldDef& def)
    : def_(def),
      commands_(def.command_capacity),
      host_objects_(def.max_objects, commands_),
      host_hands_(def, commands_, sample_arrived_.open() ? &sample_arrived_ : nullptr),
      scene_objects_(def.max_objects),
      hands_(static_cast<size_t>(def.max_hands), nullptr),
      hand_generation_(static_cast<size_t>(def.max_hands), 0) {
  present_hands_.reserve(static_cast<size_t>(def.max_hands));
  WorldSnapshot prototype;
  prototype.hands.resize(static_cast<size_t>(def.max_hands));
  prototype.objects.resize(static_cast<size_t>(def.max_objects));
  output_.reset(prototype);
}

World::~World() { stop(); }

frusta_result World::add_hand(const HandModel& model, HandHandle* out) {
  return host_hands_.add(model, out);
}

frusta_result World::remove_hand(HandHandle hand) { return host_hands_.remove(hand); }

frusta_result World::add_object(std::shared_ptr<const TreeFile> tree, const ObjectDef& def,
                                ObjectHandle* out) {
  return host_objects_.add(std::move(tree), def, out);
}

frusta_result World::add_object(std::shared_ptr<const TreeFile> tree, const RigidPose& pose,
                                ObjectHandle* out) {
  ObjectDef def;
  def.pose = pose;
  return add_object(std::move(tree), def, out);
}

frusta_result World::remove_object(ObjectHandle object) { return host_objects_.remove(object); }

frusta_result World::set_object_pose(ObjectHandle object, const RigidPose& pose) {
  return host_objects_.set_pose(object, pose);
}

frusta_result World::set_object_dynamic(ObjectHandle object, bool dynamic) {
  return host_objects_.set_dynamic(object, dynamic);
}

frusta_result World::set_haptic(HandHandle hand, const HandState& haptic) {
  if (hand.slot < 0 || hand.slot >= def_.max_hands)
    return fail(FRUSTA_ERROR_STALE_ID, "hand {slot=%d} names no hand of this world (it has %d hand slots)",
                hand.slot, def_.max_hands);
  return host_hands_.port(hand.slot).set_input(haptic, HandPort::Driver::kHost, hand.generation);
}

frusta_result World::set_haptic_at(HandHandle hand, const HandState& haptic, int64_t time_ns) {
  if (hand.slot < 0 || hand.slot >= def_.max_hands)
    return fail(FRUSTA_ERROR_STALE_ID, "hand {slot=%d} names no hand of this world (it has %d hand slots)",
                hand.slot, def_.max_hands);
  return host_hands_.port(hand.slot).set_input_at(haptic, time_ns, HandPort::Driver::kHost,
                                                  hand.generation);
}

frusta_result World::step() {
  if (running())
    return fail(FRUSTA_ERROR_WRONG_STATE, "the world's own thread is stepping it: stop() it first");
  step_once(1.0 / def_.rate_hz, false, 0);
  return FRUSTA_OK;
}

frusta_result World::start() { return start(def_.rate_hz, def_.spin_us); }

frusta_result World::start(double rate_hz, double spin_us) {
  return thread_.start(
      rate_hz, spin_us, [this](double dt, int64_t tick_ns) { return step_once(dt, true, tick_ns); },
      &sample_arrived_, def_.realtime_priority);
}

void World::stop() { thread_.stop(); }

const WorldSnapshot& World::read() {
  host_read_ns_.store(steady_ns(), std::memory_order_relaxed);
  const WorldSnapshot& latest = output_.read();
  // what no step reaches any more, and no snapshot from now on shows
  host_objects_.release(latest.commands_applied);
  host_hands_.release(latest.commands_applied);
  return latest;
}

void World::apply_commands() {
  WorldCommand c;
  bool objects_changed = false, hands_changed = false;
  while (commands_.pop(c)) {
    ++applied_;
    const size_t slot = static_cast<size_t>(c.slot);
    switch (c.kind) {
      case CommandKind::kAddHand:
        hands_[slot] = c.hand;
        hand_generation_[slot] = c.generation;
        hands_changed = true;
        break;
      case CommandKind::kRemoveHand:
        hands_[slot] = nullptr;
        scene_objects_.forget_hand(c.slot);
        hands_changed = true;
        break;
      case CommandKind::kRemoveObject:
        for (HandPipeline* hand : hands_)
          if (hand) hand->forget(c.slot);
        [[fallthrough]];
      default:
        objects_changed |= scene_objects_.apply(c);
        break;
    }
  }
  if (objects_changed) scene_objects_.rebuild_active();
  if (!hands_changed) return;
  present_hands_.clear();  // within the capacity reserved up front
  for (size_t slot = 0; slot < hands_.size(); ++slot)
    if (hands_[slot]) present_hands_.push_back(static_cast<int32_t>(slot));
}

int64_t World::step_once(double dt, bool paced, int64_t tick_ns) {
  const auto start = std::chrono::steady_clock::now();
  apply_commands();
  scene_objects_.clear_reactions();
  WorldSnapshot& out = output_.write_slot();
  HandStepContext context;
  context.dt = dt;
  context.paced = paced;
  // the world's clock: the steady clock's tick on the own thread, the step count's time
  // when the host steps (its samples are stamped on it: deterministic). The hands play
  // their inputs input_delay behind it, one period of them a step: a world thread that
  // stalled and dropped ticks plays on from where it was and catches up at most
  // kCatchUp - 1 periods a step, rather than jump the hands (and what they hold) ahead
  const int64_t period_ns = static_cast<int64_t>(std::llround(1e9 * dt));
  const int64_t target =
      (paced ? tick_ns
             : static_cast<int64_t>(std::llround(static_cast<double>(step_ + 1) * 1e9 / def_.rate_hz))) -
      static_cast<int64_t>(std::llround(def_.input_delay * 1e9));
  if (!playing_ || target < play_ns_ || target - play_ns_ > kMaxPlayLagNs)
    play_ns_ = target;  // the first step, or a clock that changed (host to own thread)
  else
    play_ns_ = std::min(target, play_ns_ + period_ns + period_ns / kCatchUpDivisor);
  playing_ = true;
  context.play_ns = play_ns_;
  context.max_extrapolation_ns = static_cast<int64_t>(std::llround(def_.max_extrapolation * 1e9));
  context.device_limits = def_.device_limits;
  context.max_contacts = def_.max_contacts_per_hand;
  const int64_t host_read_ns = host_read_ns_.load(std::memory_order_relaxed);
  // each hand fills its own snapshot for this buffer; the slots say which are there
  const int buffer = output_.write_index();
  for (HandSlot& slot : out.hands) slot = HandSlot{};
  const size_t present = present_hands_.size();
  int64_t glove_sample_ns = 0;  // the first glove-driven hand's newest sample
  for (size_t h = 0; h < present; ++h) {
    const size_t slot = static_cast<size_t>(present_hands_[h]);
    HandPipeline& hand = *hands_[slot];
    HandSnapshot& snap = hand.snapshot(buffer);
    // on the own thread each hand may take its share of most of a period, so a hand
    // caught in a tangle of contacts lags for a step instead of stalling the thread
    context.deadline =
        paced ? start + std::chrono::duration_cast<HandSolver::Clock::duration>(std::chrono::duration<double>(
                            kStepBudgetShare * dt * static_cast<double>(h + 1) / static_cast<double>(present)))
              : HandSolver::Clock::time_point::max();
    if (!hand.step(context, scene_objects_, snap)) ++rejected_;
    if (glove_sample_ns == 0) glove_sample_ns = hand.live_sample_ns();
    hand.publish_feed(snap, step_ + 1, host_read_ns);
    out.hands[slot] = HandSlot{true, hand_generation_[slot], &snap};
  }
  scene_objects_.publish(out.objects, buffer);
  scene_objects_.end_step(def_.gravity, dt);
  out.commands_applied = applied_;
  out.step = ++step_;
  out.time = time_ += dt;
  out.rejected_inputs = rejected_;
  out.step_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
  histogram_.record(out.step_us);
  out.step_us_p50 = histogram_.percentile(0.5);
  out.step_us_p99 = histogram_.percentile(0.99);
  out.step_us_max = histogram_.max();
  out.wake_late_us_p50 = thread_.lateness().percentile(0.5);
  out.wake_late_us_p99 = thread_.lateness().percentile(0.99);
  out.wake_late_us_max = thread_.lateness().max();
  out.overruns = thread_.overruns();
  out.achieved_rate_hz = thread_.achieved_rate_hz();
  out.realtime = paced && thread_.realtime();
  output_.publish();
  // the ticks follow the first glove's samples (StepThread; they cannot follow two)
  return glove_sample_ns;
}

}  // namespace frusta
