// SPDX-License-Identifier: MIT
#include "runtime/world.h"

#include <algorithm>
#include <chrono>

#include "core/error.h"
#include "runtime/periodic_clock.h"

namespace frusta {

World::World(const WorldDef& def)
    : def_(def),
      host_generation_(static_cast<size_t>(def.max_objects), 1u),
      host_trees_(static_cast<size_t>(def.max_objects)),
      commands_(static_cast<size_t>(def.command_capacity)),
      slots_(static_cast<size_t>(def.max_objects)) {
  for (int32_t s = def.max_objects - 1; s >= 0; --s) host_free_.push_back(s);
  active_.reserve(static_cast<size_t>(def.max_objects));
  active_slot_.reserve(static_cast<size_t>(def.max_objects));
}

frusta_result World::add_hand(const HandModel& model, int32_t* out_hand) {
  if (running() || step_ > 0)
    return fail(FRUSTA_ERROR_WRONG_STATE, "hands are added before the world's first step");
  if (frusta_result r = HandSolver::check_params(def_.solver, model)) return r;
  hands_.push_back(std::make_unique<HandSlot>(model, def_.solver, HandState{}));
  WorldSnapshot prototype;
  prototype.hands.resize(hands_.size());
  for (HandSnapshot& h : prototype.hands) h.contacts.resize(static_cast<size_t>(def_.max_contacts_per_hand));
  output_.reset(prototype);
  *out_hand = static_cast<int32_t>(hands_.size()) - 1;
  return FRUSTA_OK;
}

frusta_result World::queue(const Command& command) {
  if (!commands_.push(command))
    return fail(FRUSTA_ERROR_CAPACITY, "the world's command queue is full (%zu): step the world",
                commands_.capacity());
  ++pushed_;
  return FRUSTA_OK;
}

void World::release_retired() {
  const uint64_t applied = applied_.load(std::memory_order_acquire);
  retired_.erase(std::remove_if(retired_.begin(), retired_.end(),
                                [&](const auto& r) { return r.first <= applied; }),
                 retired_.end());
}

frusta_result World::check_handle(ObjectHandle object) const {
  if (object.slot < 0 || object.slot >= def_.max_objects ||
      host_generation_[static_cast<size_t>(object.slot)] != object.generation ||
      !host_trees_[static_cast<size_t>(object.slot)])
    return fail(FRUSTA_ERROR_STALE_ID, "object {slot=%d, generation=%u} names no object in this world",
                object.slot, object.generation);
  return FRUSTA_OK;
}

frusta_result World::add_object(std::shared_ptr<const TreeFile> tree, const RigidPose& pose,
                                ObjectHandle* out) {
  release_retired();
  if (!tree) return fail(FRUSTA_ERROR_NULL_POINTER, "tree is null");
  if (host_free_.empty())
    return fail(FRUSTA_ERROR_CAPACITY, "the world holds max_objects (%d) objects", def_.max_objects);
  const int32_t slot = host_free_.back();
  Command c;
  c.kind = CommandKind::kAdd;
  c.slot = slot;
  c.pose = pose;
  c.tree = tree.get();
  if (frusta_result r = queue(c)) return r;
  host_free_.pop_back();
  host_trees_[static_cast<size_t>(slot)] = std::move(tree);
  *out = {slot, host_generation_[static_cast<size_t>(slot)]};
  return FRUSTA_OK;
}

frusta_result World::remove_object(ObjectHandle object) {
  release_retired();
  if (frusta_result r = check_handle(object)) return r;
  Command c;
  c.kind = CommandKind::kRemove;
  c.slot = object.slot;
  if (frusta_result r = queue(c)) return r;
  const size_t slot = static_cast<size_t>(object.slot);
  // the stepping thread may use the tree until it applies this command
  retired_.emplace_back(pushed_, std::move(host_trees_[slot]));
  host_trees_[slot].reset();
  host_generation_[slot] = host_generation_[slot] + 1 == 0 ? 1 : host_generation_[slot] + 1;
  host_free_.push_back(object.slot);
  return FRUSTA_OK;
}

frusta_result World::set_object_pose(ObjectHandle object, const RigidPose& pose) {
  if (frusta_result r = check_handle(object)) return r;
  Command c;
  c.kind = CommandKind::kPose;
  c.slot = object.slot;
  c.pose = pose;
  return queue(c);
}

frusta_result World::set_haptic(int32_t hand, const HandState& haptic) {
  if (hand < 0 || hand >= hand_count())
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "hand is %d, the world has %d", hand, hand_count());
  HandSlot& h = *hands_[static_cast<size_t>(hand)];
  h.input.write_slot() = haptic;
  h.input.publish();
  return FRUSTA_OK;
}

void World::apply_commands() {
  Command c;
  bool changed = false;
  uint64_t applied = 0;
  while (commands_.pop(c)) {
    ObjectSlot& slot = slots_[static_cast<size_t>(c.slot)];
    if (c.kind == CommandKind::kAdd) slot = {c.tree, c.pose};
    if (c.kind == CommandKind::kRemove) slot.tree = nullptr;
    if (c.kind == CommandKind::kPose) slot.pose = c.pose;
    changed = true;
    ++applied;
  }
  if (!changed) return;
  active_.clear();  // within the capacity reserved up front: no allocation
  active_slot_.clear();
  for (size_t s = 0; s < slots_.size(); ++s)
    if (slots_[s].tree) {
      active_.push_back({&slots_[s].tree->tree, slots_[s].pose});
      active_slot_.push_back(static_cast<int32_t>(s));
    }
  applied_.fetch_add(applied, std::memory_order_release);
}

World::~World() { stop(); }

frusta_result World::step() {
  if (running())
    return fail(FRUSTA_ERROR_WRONG_STATE, "the world's own thread is stepping it: stop() it first");
  step_once();
  return FRUSTA_OK;
}

frusta_result World::start(double rate_hz, double spin_us) {
  if (!(rate_hz >= 1.0 && rate_hz <= 100000.0))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "rate is %g Hz, must be 1..100000", rate_hz);
  if (!(spin_us >= 0.0 && spin_us <= 1e6 / rate_hz))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "spin is %g us, must be 0..one period", spin_us);
  if (running()) return fail(FRUSTA_ERROR_WRONG_STATE, "the world's thread is already running");
  running_.store(true, std::memory_order_release);
  thread_ = std::thread([this, rate_hz, spin_us] { run(rate_hz, spin_us); });
  return FRUSTA_OK;
}

void World::stop() {
  running_.store(false, std::memory_order_release);
  if (thread_.joinable()) thread_.join();
}

void World::run(double rate_hz, double spin_us) {
  using namespace std::chrono;
  PeriodicClock clock(duration_cast<PeriodicClock::Clock::duration>(duration<double>(1.0 / rate_hz)),
                      duration_cast<PeriodicClock::Clock::duration>(duration<double, std::micro>(spin_us)));
  clock.start();
  while (running_.load(std::memory_order_acquire)) {
    lateness_.record(duration<double, std::micro>(clock.wait()).count());
    overruns_ = clock.missed();
    step_once();
  }
}

void World::step_once() {
  const auto start = std::chrono::steady_clock::now();
  apply_commands();
  WorldSnapshot& out = output_.write_slot();
  for (size_t h = 0; h < hands_.size(); ++h) {
    HandSlot& hand = *hands_[h];
    HandSnapshot& snap = out.hands[h];
    if (hand.input.fresh()) hand.has_input = true;
    const HandState& haptic = hand.input.read();
    if (!hand.has_input) continue;  // nothing to solve before the first input
    StepStats stats;
    if (hand.solver.step(haptic, active_.data(), static_cast<int32_t>(active_.size()), &stats) != FRUSTA_OK)
      ++rejected_;  // the graphic hand stays as it was
    snap.haptic = haptic;
    snap.graphic = hand.solver.graphic();
    snap.stats = stats;
    snap.solved = hand.solver.started();
    const std::vector<SolverContact>& contacts = hand.solver.contacts();
    snap.contact_count = static_cast<int32_t>(contacts.size());
    const size_t kept = std::min(contacts.size(), snap.contacts.size());
    for (size_t i = 0; i < kept; ++i) {
      snap.contacts[i] = contacts[i];
      snap.contacts[i].object = active_slot_[static_cast<size_t>(contacts[i].object)];  // a slot
    }
  }
  out.step = ++step_;
  out.rejected_inputs = rejected_;
  histogram_.record(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
  out.step_us_p50 = histogram_.percentile(0.5);
  out.step_us_p99 = histogram_.percentile(0.99);
  out.step_us_max = histogram_.max();
  out.wake_late_us_p50 = lateness_.percentile(0.5);
  out.wake_late_us_p99 = lateness_.percentile(0.99);
  out.wake_late_us_max = lateness_.max();
  out.overruns = overruns_;
  output_.publish();
}

const WorldSnapshot& World::read() {
  release_retired();
  return output_.read();
}

}  // namespace frusta
