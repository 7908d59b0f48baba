// SPDX-License-Identifier: MIT
#include "runtime/world.h"

#include <chrono>

#include "core/error.h"
#include "core/periodic_clock.h"

namespace frusta {

namespace {

// the share of a period the hands' solves may take on the own thread; the rest is for
// the forces, the objects and the snapshot
constexpr double kStepBudget = 0.7;

}  // namespace

World::World(const WorldDef& def)
    : def_(def),
      host_objects_(def.max_objects, def.command_capacity),
      scene_objects_(def.max_objects) {
  WorldSnapshot prototype;
  prototype.objects.resize(static_cast<size_t>(def.max_objects));
  output_.reset(prototype);
}

World::~World() { stop(); }

frusta_result World::add_hand(const HandModel& model, int32_t* out_hand) {
  if (running() || step_ > 0)
    return fail(FRUSTA_ERROR_WRONG_STATE, "hands are added before the world's first step");
  if (frusta_result r = HandSolver::check_params(def_.solver, model)) return r;
  hands_.push_back(std::make_unique<HandPipeline>(model, def_.solver, def_.max_contacts_per_hand,
                                                  def_.max_objects, hand_count(), def_.rate_hz));
  WorldSnapshot prototype;
  prototype.hands.resize(hands_.size());
  for (HandSnapshot& h : prototype.hands) {
    h.contacts.resize(static_cast<size_t>(def_.max_contacts_per_hand));
    h.forces.resize(static_cast<size_t>(def_.max_contacts_per_hand));
  }
  prototype.objects.resize(static_cast<size_t>(def_.max_objects));
  output_.reset(prototype);
  *out_hand = static_cast<int32_t>(hands_.size()) - 1;
  return FRUSTA_OK;
}

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

frusta_result World::set_haptic(int32_t hand, const HandState& haptic) {
  if (hand < 0 || hand >= hand_count())
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "hand is %d, the world has %d", hand, hand_count());
  return hands_[static_cast<size_t>(hand)]->port().set_input(haptic, HandPort::Driver::kHost);
}

frusta_result World::step() {
  if (running())
    return fail(FRUSTA_ERROR_WRONG_STATE, "the world's own thread is stepping it: stop() it first");
  step_once(1.0 / def_.rate_hz, false, 0);
  return FRUSTA_OK;
}

frusta_result World::start() { return start(def_.rate_hz, def_.spin_us); }

frusta_result World::start(double rate_hz, double spin_us) {
  return thread_.start(rate_hz, spin_us,
                       [this](double dt, int64_t tick_ns) { step_once(dt, true, tick_ns); });
}

void World::stop() { thread_.stop(); }

const WorldSnapshot& World::read() {
  host_read_ns_.store(steady_ns(), std::memory_order_relaxed);
  host_objects_.release_retired();
  return output_.read();
}

void World::apply_commands() {
  ObjectCommand c;
  uint64_t applied = 0;
  while (host_objects_.commands().pop(c)) {
    scene_objects_.apply(c);
    if (c.kind == ObjectCommandKind::kRemove)
      for (auto& hand : hands_) hand->forget(c.slot);
    ++applied;
  }
  if (applied == 0) return;
  scene_objects_.rebuild_active();
  host_objects_.mark_applied(applied);
}

void World::step_once(double dt, bool paced, int64_t tick_ns) {
  const auto start = std::chrono::steady_clock::now();
  apply_commands();
  scene_objects_.clear_reactions();
  WorldSnapshot& out = output_.write_slot();
  HandStepContext context;
  context.dt = dt;
  context.paced = paced;
  context.tick_ns = tick_ns;
  context.device_limits = def_.device_limits;
  context.max_contacts = def_.max_contacts_per_hand;
  const int64_t host_read_ns = host_read_ns_.load(std::memory_order_relaxed);
  for (size_t h = 0; h < hands_.size(); ++h) {
    // on the own thread each hand may take its share of most of a period, so a hand
    // caught in a tangle of contacts lags for a step instead of stalling the thread
    context.deadline =
        paced ? start + std::chrono::duration_cast<HandSolver::Clock::duration>(std::chrono::duration<double>(
                            kStepBudget * dt * static_cast<double>(h + 1) / static_cast<double>(hands_.size())))
              : HandSolver::Clock::time_point::max();
    if (!hands_[h]->step(context, scene_objects_, out.hands[h])) ++rejected_;
    hands_[h]->publish_feed(out.hands[h], step_ + 1, host_read_ns);
  }
  scene_objects_.publish(out.objects);
  scene_objects_.end_step(def_.gravity, dt);
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
  output_.publish();
}

}  // namespace frusta
