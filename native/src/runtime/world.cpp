// SPDX-License-Identifier: MIT
#include "runtime/world.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <system_error>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include "core/error.h"
#include "core/validate.h"
#include "core/periodic_clock.h"
#include "core/timer_resolution.h"

namespace frusta {

namespace {

// a rotation whose columns are further than this from orthonormal was not meant as one
constexpr double kOrthonormalTolerance = 1e-6;
// a dynamic object faster than this has been flung by a bug or absurd input: capped,
// so that it stays a finite pose the solver can meet
constexpr double kMaxLinearSpeed = 100.0;   // m/s
constexpr double kMaxAngularSpeed = 1000.0; // rad/s
// the share of a period the hands' solves may take on the own thread; the rest is for
// the forces, the objects and the snapshot
constexpr double kStepBudget = 0.7;

vec3 clamp_length(const vec3& v, double limit) {
  // scaled by the largest component first: a length past 1e154 squares to infinity,
  // and limit / infinity would zero a finite vector (or turn an infinite one into NaN)
  const double largest = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  if (!(largest > limit / 2.0)) return v;  // also 0 and NaN, which stay as they are
  const vec3 unit = v / largest;
  const double length = largest * glm::length(unit);
  return length > limit ? unit * (limit / glm::length(unit)) : v;
}

}  // namespace

frusta_result check_rigid_pose(const RigidPose& pose, const char* name) {
  char field[96];
  std::snprintf(field, sizeof field, "%s.position", name);
  if (frusta_result r = check_bounded(glm::value_ptr(pose.position), 3, kMaxCoordinate, field))
    return r;
  std::snprintf(field, sizeof field, "%s.rotation", name);
  if (frusta_result r = check_finite(glm::value_ptr(pose.rotation), 9, field)) return r;
  const glm::dmat3 gram = glm::transpose(pose.rotation) * pose.rotation;
  double worst = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) worst = std::max(worst, std::fabs(gram[i][j] - (i == j ? 1.0 : 0.0)));
  if (worst > kOrthonormalTolerance || glm::determinant(pose.rotation) < 0.0)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                "%s is not a rotation (R^T R differs from I by %g, det %g)", field, worst,
                glm::determinant(pose.rotation));
  return FRUSTA_OK;
}

frusta_result check_object_def(const ObjectDef& def) {
  if (frusta_result r = check_rigid_pose(def.pose, "object pose")) return r;
  if (frusta_result r = check_force_material(def.material, "object material")) return r;
  if (frusta_result r = check_range(def.mass, kMinMass, kMaxMass, false, "object mass")) return r;
  for (int k = 0; k < 3; ++k)
    if (frusta_result r = check_range_named(def.inertia[k], kMinInertia, kMaxInertia, false,
                                            "object inertia[%d]", k))
      return r;
  // principal moments of a real body: each at most the sum of the other two
  for (int k = 0; k < 3; ++k) {
    const double others = def.inertia[(k + 1) % 3] + def.inertia[(k + 2) % 3];
    if (def.inertia[k] > others * (1.0 + 1e-9))
      return fail(FRUSTA_ERROR_OUT_OF_RANGE,
                  "object inertia[%d] is %g kg m^2, more than the other two together (%g): no "
                  "body has such principal moments", k, def.inertia[k], others);
  }
  if (frusta_result r = check_bounded(glm::value_ptr(def.linear_velocity), 3, kMaxLinearSpeed,
                                      "object linear_velocity"))
    return r;
  if (frusta_result r = check_bounded(glm::value_ptr(def.angular_velocity), 3, kMaxAngularSpeed,
                                      "object angular_velocity"))
    return r;
  if (frusta_result r = check_range(def.linear_damping, 0.0, 1e3, false, "object linear_damping"))
    return r;
  return check_range(def.angular_damping, 0.0, 1e3, false, "object angular_damping");
}

frusta_result check_world_def(const WorldDef& def) {
  if (frusta_result r = check_range(def.rate_hz, 1.0, 100000.0, false, "rate_hz")) return r;
  // the solver's knobs a world exposes; the hand-dependent rules are checked when a
  // hand is added. The margin lies above the solver's penetration tolerance (1e-6 m).
  if (frusta_result r = check_range(def.solver.prediction_margin, 1e-5, 0.1, false,
                                    "prediction_margin"))
    return r;
  if (frusta_result r = check_range(def.solver.node_radius, 0.0, 1.0, false, "node_radius"))
    return r;
  if (def.solver.max_iterations < 1 || def.solver.max_iterations > 100)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "max_iterations is %d, must be 1..100",
                def.solver.max_iterations);
  if (def.solver.max_substeps < 1 || def.solver.max_substeps > 1024)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "max_substeps is %d, must be 1..1024",
                def.solver.max_substeps);
  if (frusta_result r = check_range(def.spin_us, 0.0, 1e6 / def.rate_hz, false, "spin_us"))
    return r;
  if (frusta_result r = check_bounded(glm::value_ptr(def.gravity), 3, 1e3, "gravity")) return r;
  if (def.max_objects < 1 || def.max_objects > 65535)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "max_objects is %d, must be 1..65535", def.max_objects);
  if (def.max_contacts_per_hand < 0 || def.max_contacts_per_hand > 65536)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "max_contacts_per_hand is %d, must be 0..65536",
                def.max_contacts_per_hand);
  if (def.command_capacity < 1 || def.command_capacity > 1 << 20)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "command_capacity is %d, must be 1..2^20",
                def.command_capacity);
  return check_device_limits(def.device_limits);
}

World::World(const WorldDef& def)
    : def_(def),
      object_ids_(def.max_objects),
      host_trees_(static_cast<size_t>(def.max_objects)),
      commands_(static_cast<size_t>(def.command_capacity)),
      slots_(static_cast<size_t>(def.max_objects)) {
  active_.reserve(static_cast<size_t>(def.max_objects));
  active_slot_.reserve(static_cast<size_t>(def.max_objects));
  active_material_.reserve(static_cast<size_t>(def.max_objects));
  hand_reactions_.resize(static_cast<size_t>(def.max_objects));
  placed_.assign(static_cast<size_t>(def.max_objects), 0);
  WorldSnapshot prototype;
  prototype.objects.resize(static_cast<size_t>(def.max_objects));
  output_.reset(prototype);
}

frusta_result World::add_hand(const HandModel& model, int32_t* out_hand) {
  if (running() || step_ > 0)
    return fail(FRUSTA_ERROR_WRONG_STATE, "hands are added before the world's first step");
  if (frusta_result r = HandSolver::check_params(def_.solver, model)) return r;
  hands_.push_back(std::make_unique<HandSlot>(model, def_.solver, def_.max_contacts_per_hand,
                                              hand_count(), def_.rate_hz));
  HandSlot& added = *hands_.back();
  added.ignored.assign(static_cast<size_t>(def_.max_objects), 0);
  added.objects.reserve(static_cast<size_t>(def_.max_objects));
  added.object_slot.reserve(static_cast<size_t>(def_.max_objects));
  added.materials.reserve(static_cast<size_t>(def_.max_objects));
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
  if (object.generation > 0xFFFF ||
      !object_ids_.is_live(object.slot, static_cast<uint16_t>(object.generation)))
    return fail(FRUSTA_ERROR_STALE_ID, "object {slot=%d, generation=%u} names no object in this world",
                object.slot, object.generation);
  return FRUSTA_OK;
}

frusta_result World::add_object(std::shared_ptr<const TreeFile> tree, const ObjectDef& def,
                                ObjectHandle* out) {
  release_retired();
  if (!tree) return fail(FRUSTA_ERROR_NULL_POINTER, "tree is null");
  if (frusta_result r = check_object_def(def)) return r;
  int32_t slot = 0;
  uint16_t generation = 0;
  if (!object_ids_.acquire(&slot, &generation))
    return fail(FRUSTA_ERROR_CAPACITY, "the world holds max_objects (%d) objects", def_.max_objects);
  Command c;
  c.kind = CommandKind::kAdd;
  c.slot = slot;
  c.generation = generation;
  c.def = def;
  c.tree = tree.get();
  if (frusta_result r = queue(c)) {
    object_ids_.release(slot);  // never named to anyone: its next generation is as good
    return r;
  }
  host_trees_[static_cast<size_t>(slot)] = std::move(tree);
  *out = {slot, c.generation};
  return FRUSTA_OK;
}

frusta_result World::add_object(std::shared_ptr<const TreeFile> tree, const RigidPose& pose,
                                ObjectHandle* out) {
  ObjectDef def;
  def.pose = pose;
  return add_object(std::move(tree), def, out);
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
  object_ids_.release(object.slot);
  return FRUSTA_OK;
}

frusta_result World::set_object_pose(ObjectHandle object, const RigidPose& pose) {
  if (frusta_result r = check_handle(object)) return r;
  if (frusta_result r = check_rigid_pose(pose, "pose")) return r;
  Command c;
  c.kind = CommandKind::kPose;
  c.slot = object.slot;
  c.def.pose = pose;
  return queue(c);
}

frusta_result World::set_object_dynamic(ObjectHandle object, bool dynamic) {
  if (frusta_result r = check_handle(object)) return r;
  Command c;
  c.kind = CommandKind::kDynamic;
  c.slot = object.slot;
  c.def.dynamic = dynamic;
  return queue(c);
}

frusta_result World::set_haptic(int32_t hand, const HandState& haptic) {
  if (hand < 0 || hand >= hand_count())
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "hand is %d, the world has %d", hand, hand_count());
  return hands_[static_cast<size_t>(hand)]->port.set_input(haptic, HandPort::Driver::kHost);
}

void World::apply_commands() {
  Command c;
  bool changed = false;
  uint64_t applied = 0;
  while (commands_.pop(c)) {
    ObjectSlot& slot = slots_[static_cast<size_t>(c.slot)];
    switch (c.kind) {
      case CommandKind::kAdd:
        placed_[static_cast<size_t>(c.slot)] = 1;
        slot.tree = c.tree;
        slot.generation = c.generation;
        slot.def = c.def;
        break;
      case CommandKind::kRemove:
        slot.tree = nullptr;
        for (auto& hand : hands_) {  // a removed object is nobody's to ignore any more
          hand->ignored_count -= hand->ignored[static_cast<size_t>(c.slot)];
          hand->ignored[static_cast<size_t>(c.slot)] = 0;
        }
        break;
      case CommandKind::kPose:
        placed_[static_cast<size_t>(c.slot)] = 1;
        slot.def.pose = c.def.pose;
        slot.def.linear_velocity = slot.def.angular_velocity = vec3(0.0);
        break;
      case CommandKind::kDynamic:
        slot.def.dynamic = c.def.dynamic;
        slot.def.linear_velocity = slot.def.angular_velocity = vec3(0.0);
        break;
    }
    changed = true;
    ++applied;
  }
  if (!changed) return;
  rebuild_active();
  applied_.fetch_add(applied, std::memory_order_release);
}

void World::rebuild_active() {
  objects_moved_ = true;
  active_.clear();  // within the capacity reserved up front: no allocation
  active_slot_.clear();
  active_material_.clear();
  for (size_t s = 0; s < slots_.size(); ++s)
    if (slots_[s].tree) {
      active_.push_back({&slots_[s].tree->tree, slots_[s].def.pose});
      active_slot_.push_back(static_cast<int32_t>(s));
      active_material_.push_back(slots_[s].def.material);
    }
}

World::~World() { stop(); }

frusta_result World::step() {
  if (running())
    return fail(FRUSTA_ERROR_WRONG_STATE, "the world's own thread is stepping it: stop() it first");
  step_once(1.0 / def_.rate_hz, false, 0);
  return FRUSTA_OK;
}

frusta_result World::start() { return start(def_.rate_hz, def_.spin_us); }

frusta_result World::start(double rate_hz, double spin_us) {
  if (!(rate_hz >= 1.0 && rate_hz <= 100000.0))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "rate is %g Hz, must be 1..100000", rate_hz);
  if (!(spin_us >= 0.0 && spin_us <= 1e6 / rate_hz))
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "spin is %g us, must be 0..one period", spin_us);
  if (running()) return fail(FRUSTA_ERROR_WRONG_STATE, "the world's thread is already running");
  running_.store(true, std::memory_order_release);
  try {
    thread_ = std::thread([this, rate_hz, spin_us] { run(rate_hz, spin_us); });
  } catch (const std::system_error& e) {
    running_.store(false, std::memory_order_release);
    return fail(FRUSTA_ERROR_INTERNAL, "the world's thread could not start: %s", e.what());
  }
  return FRUSTA_OK;
}

void World::stop() {
  running_.store(false, std::memory_order_release);
  if (thread_.joinable()) thread_.join();
}

void World::run(double rate_hz, double spin_us) {
  using namespace std::chrono;
  const FineTimerResolution fine_sleeps;
  PeriodicClock clock(duration_cast<PeriodicClock::Clock::duration>(duration<double>(1.0 / rate_hz)),
                      duration_cast<PeriodicClock::Clock::duration>(duration<double, std::micro>(spin_us)));
  clock.start();
  const auto started = steady_clock::now();
  int64_t steps = 0;
  while (running_.load(std::memory_order_acquire)) {
    lateness_.record(duration<double, std::micro>(clock.wait()).count());
    overruns_ = clock.missed();
    const int64_t tick_ns = duration_cast<nanoseconds>(clock.tick().time_since_epoch()).count();
    ++steps;
    achieved_rate_hz_ = static_cast<double>(steps) / duration<double>(steady_clock::now() - started).count();
    step_once(1.0 / rate_hz, true, tick_ns);
  }
}

void World::step_hand(HandSlot& hand, HandSnapshot& snap, double dt, bool paced, int64_t tick_ns,
                      HandSolver::Clock::time_point deadline) {
  if (hand.port.input_fresh()) {
    hand.previous = hand.has_input ? hand.newest : hand.port.take_input();
    hand.newest = hand.port.take_input();
    hand.has_input = true;
  }
  if (!hand.has_input) return;  // nothing to solve before the first input
  HandState haptic = hand.newest.state;
  const int64_t span = hand.newest.set_ns - hand.previous.set_ns;
  if (paced && span > 0) {
    // where the glove was one period before this tick, between the two inputs around
    // that time (a tick caught up after a stall asks for its own time, not now's)
    const double late = static_cast<double>(tick_ns - hand.previous.set_ns) - dt * 1e9;
    const double t = std::clamp(late / static_cast<double>(span), 0.0, 1.0);
    haptic = interpolate(hand.previous.state, hand.newest.state, t);
  }
  update_ignored(hand);
  const bool own_list = hand.ignored_count > 0;
  const SolverObject* objects = own_list ? hand.objects.data() : active_.data();
  const int32_t* object_slot = own_list ? hand.object_slot.data() : active_slot_.data();
  const ForceMaterial* materials = own_list ? hand.materials.data() : active_material_.data();
  const int32_t object_count =
      static_cast<int32_t>(own_list ? hand.objects.size() : active_.size());
  StepStats stats;
  if (hand.solver.step(haptic, objects, object_count, &stats, deadline) == FRUSTA_OK) {
    hand.accepted = haptic;
  } else {
    ++rejected_;  // the graphic hand stays as it was, the forces follow the last good input
  }
  snap.haptic = hand.accepted;
  snap.graphic = hand.solver.graphic();
  snap.stats = stats;
  snap.solved = hand.solver.started();
  const std::vector<SolverContact>& contacts = hand.solver.contacts();
  snap.contact_count = static_cast<int32_t>(contacts.size());
  snap.device = DeviceOutputs{};
  snap.force_stats = ContactForceStats{};
  if (!snap.solved) return;

  // forces on the contacts the snapshot keeps; the table holds as many. The solver's
  // last step succeeded (a hand that failed one is not solved), so its target is the
  // accepted input's
  hand.forces.set_time_step(dt);  // in range: the rate was checked
  const int32_t kept = std::min(snap.contact_count, def_.max_contacts_per_hand);
  const HandPose& haptic_pose = hand.solver.target_pose();
  hand.forces.update(hand.solver.graphic_pose(), haptic_pose, contacts.data(), kept, objects,
                     object_count, materials, &snap.force_stats);
  compute_device_outputs(haptic_pose, hand.forces.forces().data(), kept, objects, object_count,
                         def_.device_limits, &snap.device, hand_reactions_.data());
  snap.force_stats.dropped = snap.contact_count - kept;
  for (int32_t i = 0; i < kept; ++i) {
    const size_t k = static_cast<size_t>(i);
    const int32_t slot = object_slot[contacts[k].object];
    snap.contacts[k] = contacts[k];
    snap.contacts[k].object = slot;
    snap.forces[k] = hand.forces.forces()[k];
    snap.forces[k].object = slot;
  }
  for (int32_t a = 0; a < object_count; ++a) {
    ObjectWrench& total = slots_[static_cast<size_t>(object_slot[a])].reaction;
    total.force += hand_reactions_[static_cast<size_t>(a)].force;
    total.torque += hand_reactions_[static_cast<size_t>(a)].torque;
  }
}

void World::update_ignored(HandSlot& hand) {
  bool changed = false;
  for (size_t a = 0; a < active_.size(); ++a) {
    const size_t slot = static_cast<size_t>(active_slot_[a]);
    uint8_t& ignored = hand.ignored[slot];
    if (!placed_[slot] && !ignored) continue;  // the common case: nothing to look at
    const uint8_t now = hand.solver.overlaps(active_[a]) ? 1 : 0;
    if (now == ignored) continue;
    hand.ignored_count += now ? 1 : -1;
    ignored = now;
    changed = true;
  }
  if (hand.ignored_count == 0 || (!changed && !objects_moved_)) return;
  hand.objects.clear();  // within the capacity reserved at add_hand
  hand.object_slot.clear();
  hand.materials.clear();
  for (size_t a = 0; a < active_.size(); ++a) {
    if (hand.ignored[static_cast<size_t>(active_slot_[a])]) continue;
    hand.objects.push_back(active_[a]);
    hand.object_slot.push_back(active_slot_[a]);
    hand.materials.push_back(active_material_[a]);
  }
}

void World::move_dynamic_objects(double dt) {
  bool moved = false;
  for (ObjectSlot& slot : slots_) {
    if (!slot.tree || !slot.def.dynamic) continue;
    ObjectDef& o = slot.def;
    // semi-implicit Euler: velocities first, then the pose with the new velocities,
    // stable for the contact springs at the world's rate (stiffness / mass << rate^2)
    const vec3 force = slot.reaction.force + o.mass * def_.gravity;
    o.linear_velocity += dt / o.mass * force;
    // Euler's equations in the body frame, where the inertia is the diagonal it was
    // given: the world-frame tensor of moments 1e-13 and 1e4 turned off the axes is
    // singular in doubles, and its inverse turned the spin into NaN
    const glm::dmat3& r = o.pose.rotation;
    const vec3 body_spin = glm::transpose(r) * o.angular_velocity;
    const vec3 body_torque =
        glm::transpose(r) * slot.reaction.torque - glm::cross(body_spin, o.inertia * body_spin);
    o.angular_velocity += dt * (r * (body_torque / o.inertia));
    o.linear_velocity = clamp_length(o.linear_velocity * std::max(0.0, 1.0 - o.linear_damping * dt),
                                     kMaxLinearSpeed);
    o.angular_velocity = clamp_length(
        o.angular_velocity * std::max(0.0, 1.0 - o.angular_damping * dt), kMaxAngularSpeed);

    vec3 position = o.pose.position + dt * o.linear_velocity;
    if (glm::any(glm::greaterThan(glm::abs(position), vec3(kMaxCoordinate)))) {
      // the world's edge: an object dropped with nothing below stops there
      position = glm::clamp(position, vec3(-kMaxCoordinate), vec3(kMaxCoordinate));
      o.linear_velocity = vec3(0.0);
    }
    o.pose.position = position;
    const glm::dquat q = glm::quat_cast(r);
    const glm::dquat turn(0.0, o.angular_velocity * (0.5 * dt));
    o.pose.rotation = glm::mat3_cast(glm::normalize(q + turn * q));
    moved = true;
  }
  if (moved) rebuild_active();
}

void World::step_once(double dt, bool paced, int64_t tick_ns) {
  const auto start = std::chrono::steady_clock::now();
  apply_commands();
  for (ObjectSlot& slot : slots_) slot.reaction = ObjectWrench{};
  WorldSnapshot& out = output_.write_slot();
  for (size_t h = 0; h < hands_.size(); ++h) {
    // on the own thread each hand may take its share of most of a period, so a hand
    // caught in a tangle of contacts lags for a step instead of stalling the thread
    const auto deadline =
        paced ? start + std::chrono::duration_cast<HandSolver::Clock::duration>(std::chrono::duration<double>(
                            kStepBudget * dt * static_cast<double>(h + 1) / static_cast<double>(hands_.size())))
              : HandSolver::Clock::time_point::max();
    step_hand(*hands_[h], out.hands[h], dt, paced, tick_ns, deadline);
    publish_device_feed(*hands_[h], out.hands[h]);
  }
  std::fill(placed_.begin(), placed_.end(), 0);
  objects_moved_ = false;
  for (size_t s = 0; s < slots_.size(); ++s) {
    const ObjectSlot& slot = slots_[s];
    ObjectSnapshot& o = out.objects[s];
    o.present = slot.tree != nullptr;
    o.dynamic = slot.def.dynamic;
    o.generation = slot.generation;
    o.pose = slot.def.pose;  // where the hands met it this step
    o.linear_velocity = slot.def.linear_velocity;
    o.angular_velocity = slot.def.angular_velocity;
    o.reaction = slot.reaction;
  }
  move_dynamic_objects(dt);
  out.step = ++step_;
  out.time = time_ += dt;
  out.rejected_inputs = rejected_;
  out.step_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
  histogram_.record(out.step_us);
  out.step_us_p50 = histogram_.percentile(0.5);
  out.step_us_p99 = histogram_.percentile(0.99);
  out.step_us_max = histogram_.max();
  out.wake_late_us_p50 = lateness_.percentile(0.5);
  out.wake_late_us_p99 = lateness_.percentile(0.99);
  out.wake_late_us_max = lateness_.max();
  out.overruns = overruns_;
  out.achieved_rate_hz = achieved_rate_hz_;
  output_.publish();
}

void World::publish_device_feed(HandSlot& hand, const HandSnapshot& snap) {
  DeviceFeed feed;
  feed.step = step_ + 1;  // the step being taken
  feed.published_ns = steady_ns();
  feed.host_read_ns = host_read_ns_.load(std::memory_order_relaxed);
  feed.solved = snap.solved;
  feed.device = snap.device;
  feed.haptic_palm_rotation = hand.accepted.palm_rotation;
  hand.port.publish_feed(feed);
}

const WorldSnapshot& World::read() {
  host_read_ns_.store(steady_ns(), std::memory_order_relaxed);
  release_retired();
  return output_.read();
}

}  // namespace frusta
