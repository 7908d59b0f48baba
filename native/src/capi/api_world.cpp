// SPDX-License-Identifier: MIT
// C ABI: worlds. Each function checks every input before it changes anything; the
// calls a device thread makes (frusta_world_set_haptic) take no lock and allocate
// nothing.
#include <algorithm>
#include <bitset>
#include <cmath>
#include <cstring>
#include <glm/gtc/quaternion.hpp>

#include "capi/convert.h"
#include "capi/tree_registry.h"
#include "capi/world_registry.h"
#include "core/error.h"
#include "core/periodic_clock.h"
#include "core/validate.h"
#include "frusta/frusta.h"
#include "hand/hand_model.h"

using namespace frusta;

namespace {

constexpr double kMaxInputTime = 1e9;  // seconds

vec3 vec3_of(const double v[3]) { return vec3(v[0], v[1], v[2]); }

frusta_result read_world_def(const frusta_world_def& in, WorldDef* out) {
  WorldDef def;
  def.max_objects = in.max_objects;
  def.max_hands = in.max_hands;
  def.rate_hz = in.rate_hz;
  def.spin_us = in.spin_us;
  if (in.realtime_priority != 0 && in.realtime_priority != 1)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "realtime_priority is %d, must be 0 or 1", in.realtime_priority);
  def.realtime_priority = in.realtime_priority == 1;
  def.gravity = vec3_of(in.gravity);
  def.max_contacts_per_hand = in.max_contacts_per_hand;
  def.solver.candidate_capacity = in.max_candidates_per_hand;
  def.command_capacity = in.command_capacity;
  def.solver.prediction_margin = in.prediction_margin;
  def.solver.lod_error = in.lod_error;
  def.solver.max_iterations = in.max_iterations;
  def.solver.max_substeps = in.max_substeps;
  def.device_limits = {in.max_fingertip_force, in.max_finger_resistance, in.max_joint_torque,
                       in.max_palm_force, in.max_palm_torque};
  def.input_delay = in.input_delay;
  def.max_extrapolation = in.max_extrapolation;
  if (frusta_result r = check_world_def(def)) return r;
  *out = def;
  return FRUSTA_OK;
}

frusta_result read_object_def(const frusta_object_def& in, ObjectDef* out) {
  if (in.dynamic != 0 && in.dynamic != 1)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "dynamic is %d, must be 0 or 1", in.dynamic);
  Pose pose;
  if (frusta_result r = read_pose(&in.pose, "pose", &pose)) return r;
  ObjectDef def;
  def.pose = {pose.position, glm::mat3_cast(pose.rotation)};
  def.dynamic = in.dynamic == 1;
  def.material.normal_stiffness = vec3_of(in.stiffness);
  def.material.friction = in.friction;
  def.material.tangential_stiffness = in.tangential_stiffness;
  def.material.normal_damping = in.normal_damping;
  def.material.tangential_damping = in.tangential_damping;
  def.mass = in.mass;
  def.inertia = vec3_of(in.inertia);
  def.linear_velocity = vec3_of(in.linear_velocity);
  def.angular_velocity = vec3_of(in.angular_velocity);
  def.linear_damping = in.linear_damping;
  def.angular_damping = in.angular_damping;
  if (frusta_result r = check_object_def(def)) return r;
  *out = def;
  return FRUSTA_OK;
}

// What an id names in the latched step (`shown`, null when it is not there), or why not:
// no step latched yet (for an id of something there now: `live`), or a stale id.
template <class Shown>
frusta_result from_latched(const WorldObject* w, const Shown* shown, bool live, const char* kind,
                           int32_t index1, uint16_t generation, const Shown** out) {
  if (!w->latched && live)
    return fail(FRUSTA_ERROR_WRONG_STATE, "no step latched yet: call frusta_world_read first");
  if (!shown)
    return fail(FRUSTA_ERROR_STALE_ID,
                "%s id {index1=%d, generation=%u} names no %s of this world in the latched step: "
                "destroyed, or created after it (step, then frusta_world_read)",
                kind, index1, generation, kind);
  *out = shown;
  return FRUSTA_OK;
}

frusta_result latched_hand(frusta_world_id world, WorldObject* w, frusta_hand_id id,
                           const HandSnapshot** out) {
  HandHandle handle;
  if (frusta_result r = hand_handle(world, id, &handle)) return r;
  return from_latched(w, w->latched ? w->latched->hand(handle) : nullptr,
                      w->world.hand_is_live(handle), "hand", id.index1, id.generation, out);
}

frusta_result latched_object(frusta_world_id world, WorldObject* w, frusta_object_id id,
                             const ObjectSnapshot** out) {
  ObjectHandle handle;
  if (frusta_result r = object_handle(world, id, &handle)) return r;
  return from_latched(w, w->latched ? w->latched->object(handle) : nullptr,
                      w->world.object_is_live(handle), "object", id.index1, id.generation, out);
}

// The pose of one of a latched hand's two hands (which: frusta_hand_kind).
frusta_result latched_hand_pose(frusta_world_id world, WorldObject* w, frusta_hand_id id,
                                int32_t which, const HandSnapshot** hand, HandPose* pose) {
  if (which != FRUSTA_HAND_KIND_GRAPHIC && which != FRUSTA_HAND_KIND_HAPTIC)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "which is %d, must be 0 (graphic) or 1 (haptic)", which);
  if (frusta_result r = latched_hand(world, w, id, hand)) return r;
  if (!(*hand)->solved)
    return fail(FRUSTA_ERROR_WRONG_STATE,
                "hand id {index1=%d} has had no input yet: it has no pose (solved 0)", id.index1);
  if (which == FRUSTA_HAND_KIND_GRAPHIC)
    forward_kinematics(*(*hand)->model, (*hand)->graphic, *pose);
  else
    haptic_hand_pose(*(*hand)->model, (*hand)->haptic, *pose);
  return FRUSTA_OK;
}

// A latched hand's geometry (which: frusta_hand_kind) by the output-array rule; `copy` is
// the standalone hand's conversion (copy_segments, copy_palm_spheres).
template <class Out>
frusta_result copy_latched_geometry(frusta_world_id world, frusta_hand_id hand, int32_t which,
                                    Out* out, int32_t capacity, int32_t* out_count,
                                    frusta_result (*copy)(const HandModel&, const HandPose&, Out*,
                                                          int32_t, int32_t*)) {
  WorldObject* w = nullptr;
  if (frusta_result r = world_registry().find(world, &w)) return r;
  HandHandle handle;
  if (frusta_result r = hand_handle(world, hand, &handle)) return r;
  if (frusta_result r = check_output_array(out, "out", capacity, out_count)) return r;
  const HandSnapshot* h = nullptr;
  HandPose pose;
  if (frusta_result r = latched_hand_pose(world, w, hand, which, &h, &pose)) return r;
  return copy(*h->model, pose, out, capacity, out_count);
}

void store_state(const HandState& state, frusta_pose* palm, double* angles) {
  store(Pose{state.palm_position, state.palm_rotation}, palm);
  std::memcpy(angles, state.angles.data(), sizeof(double) * FRUSTA_HAND_JOINT_COUNT);
}

}  // namespace

FRUSTA_API frusta_world_def frusta_default_world_def(void) {
  const WorldDef d;
  frusta_world_def def = blank_def<frusta_world_def>();
  def.max_objects = d.max_objects;
  def.max_hands = d.max_hands;
  def.rate_hz = d.rate_hz;
  def.spin_us = d.spin_us;
  def.realtime_priority = d.realtime_priority ? 1 : 0;
  store(d.gravity, def.gravity);
  def.prediction_margin = d.solver.prediction_margin;
  def.lod_error = d.solver.lod_error;
  def.max_iterations = d.solver.max_iterations;
  def.max_substeps = d.solver.max_substeps;
  def.max_contacts_per_hand = d.max_contacts_per_hand;
  def.max_candidates_per_hand = d.solver.candidate_capacity;
  def.command_capacity = d.command_capacity;
  def.max_fingertip_force = d.device_limits.max_fingertip_force;
  def.max_finger_resistance = d.device_limits.max_finger_resistance;
  def.max_joint_torque = d.device_limits.max_joint_torque;
  def.max_palm_force = d.device_limits.max_palm_force;
  def.max_palm_torque = d.device_limits.max_palm_torque;
  def.input_delay = d.input_delay;
  def.max_extrapolation = d.max_extrapolation;
  return def;
}

FRUSTA_API frusta_object_def frusta_default_object_def(void) {
  const ObjectDef d;
  frusta_object_def def = blank_def<frusta_object_def>();
  def.dynamic = d.dynamic ? 1 : 0;
  store(to_pose(d.pose.position, d.pose.rotation), &def.pose);
  store(d.material.normal_stiffness, def.stiffness);
  def.friction = d.material.friction;
  def.tangential_stiffness = d.material.tangential_stiffness;
  def.normal_damping = d.material.normal_damping;
  def.tangential_damping = d.material.tangential_damping;
  def.mass = d.mass;
  store(d.inertia, def.inertia);
  store(d.linear_velocity, def.linear_velocity);
  store(d.angular_velocity, def.angular_velocity);
  def.linear_damping = d.linear_damping;
  def.angular_damping = d.angular_damping;
  return def;
}

FRUSTA_API frusta_result frusta_create_world(const frusta_world_def* def, frusta_world_id* out_world) {
  if (frusta_result r = check_def_input(def, "frusta_world_def")) return r;
  if (frusta_result r = check_pointer(out_world, "out_world")) return r;
  WorldDef d;
  if (frusta_result r = read_world_def(*def, &d)) return r;
  return guarded("frusta_create_world", [&] { return world_registry().create(d, out_world); });
}

FRUSTA_API frusta_result frusta_destroy_world(frusta_world_id world) {
  return guarded("frusta_destroy_world", [&] { return world_registry().destroy(world); });
}

FRUSTA_API int32_t frusta_world_is_valid(frusta_world_id world) {
  return world_registry().is_valid(world) ? 1 : 0;
}

FRUSTA_API frusta_result frusta_create_world_hand(frusta_world_id world, const frusta_hand_def* def,
                                                  frusta_hand_id* out_hand) {
  WorldObject* w = nullptr;
  if (frusta_result r = world_registry().find(world, &w)) return r;
  if (frusta_result r = check_def_input(def, "frusta_hand_def")) return r;
  if (frusta_result r = check_pointer(out_hand, "out_hand")) return r;
  const HandDef d = read_hand_def(*def);
  if (frusta_result r = check_hand_def(d)) return r;
  return guarded("frusta_create_world_hand", [&] {
    HandHandle hand;
    if (frusta_result r = w->world.add_hand(make_hand_model(d), &hand)) return r;
    *out_hand = hand_id(world, hand);
    return FRUSTA_OK;
  });
}

FRUSTA_API frusta_result frusta_destroy_world_hand(frusta_hand_id hand) {
  if (hand.index1 == 0) return fail(FRUSTA_ERROR_NULL_ID, "hand id is null (zero-initialised)");
  if (hand.world0 == 0)
    return fail(FRUSTA_ERROR_STALE_ID,
                "hand id {index1=%d, world0=0} names a standalone hand: frusta_destroy_hand "
                "destroys it",
                hand.index1);
  WorldObject* w = nullptr;
  frusta_world_id world;
  if (frusta_result r = world_registry().find_by_tag(hand.world0, "hand", &w, &world)) return r;
  HandHandle handle;
  if (frusta_result r = hand_handle(world, hand, &handle)) return r;
  // refused while a glove drives it: the glove holds the hand's port
  return guarded("frusta_destroy_world_hand", [&] { return w->world.remove_hand(handle); });
}

FRUSTA_API frusta_result frusta_world_set_haptic(frusta_world_id world, frusta_hand_id hand_id,
                                                 const frusta_pose* palm, const double* angles,
                                                 int32_t count) {
  WorldObject* w = nullptr;
  if (frusta_result r = world_registry().find(world, &w)) return r;
  HandHandle hand;
  if (frusta_result r = hand_handle(world, hand_id, &hand)) return r;
  Pose pose;
  if (frusta_result r = read_pose(palm, "palm", &pose)) return r;
  HandState state;
  if (frusta_result r = read_joint_angles(angles, count, "angles", &state.angles)) return r;
  state.palm_position = pose.position;
  state.palm_rotation = pose.rotation;
  // the hand's port refuses it once the hand is destroyed, and while a glove drives it
  return w->world.set_haptic(hand, state);
}

FRUSTA_API frusta_result frusta_world_set_haptic_at(frusta_world_id world, frusta_hand_id hand_id,
                                                    double time, const frusta_pose* palm,
                                                    const double* angles, int32_t count) {
  WorldObject* w = nullptr;
  if (frusta_result r = world_registry().find(world, &w)) return r;
  HandHandle hand;
  if (frusta_result r = hand_handle(world, hand_id, &hand)) return r;
  // within int64 nanoseconds with room to spare: 1e9 s is 31 years of uptime
  if (frusta_result r = check_range(time, 0.0, kMaxInputTime, false, "time")) return r;
  Pose pose;
  if (frusta_result r = read_pose(palm, "palm", &pose)) return r;
  HandState state;
  if (frusta_result r = read_joint_angles(angles, count, "angles", &state.angles)) return r;
  state.palm_position = pose.position;
  state.palm_rotation = pose.rotation;
  const int64_t time_ns = static_cast<int64_t>(std::llround(time * 1e9));
  // the port refuses a sample out of time order, and as frusta_world_set_haptic
  return w->world.set_haptic_at(hand, state, time_ns);
}

FRUSTA_API double frusta_now(void) { return static_cast<double>(steady_ns()) * 1e-9; }

FRUSTA_API frusta_result frusta_create_object(frusta_world_id world, frusta_tree_id tree,
                                              const frusta_object_def* def,
                                              frusta_object_id* out_object) {
  WorldObject* w = nullptr;
  if (frusta_result r = world_registry().find(world, &w)) return r;
  std::shared_ptr<TreeObject> shape;
  if (frusta_result r = tree_registry().find_shared(tree, &shape)) return r;
  if (frusta_result r = check_def_input(def, "frusta_object_def")) return r;
  if (frusta_result r = check_pointer(out_object, "out_object")) return r;
  ObjectDef d;
  if (frusta_result r = read_object_def(*def, &d)) return r;
  return guarded("frusta_create_object", [&] {
    // the world shares the tree object, and sees only its file
    std::shared_ptr<const TreeFile> file(shape, &shape->file);
    ObjectHandle handle;
    if (frusta_result r = w->world.add_object(std::move(file), d, &handle)) return r;
    *out_object = object_id(world, handle);
    return FRUSTA_OK;
  });
}

FRUSTA_API frusta_result frusta_destroy_object(frusta_object_id object) {
  if (object.index1 == 0) return fail(FRUSTA_ERROR_NULL_ID, "object id is null (zero-initialised)");
  WorldObject* w = nullptr;
  frusta_world_id world;
  if (frusta_result r = world_registry().find_by_tag(object.world0, "object", &w, &world)) return r;
  ObjectHandle handle;
  if (frusta_result r = object_handle(world, object, &handle)) return r;
  return guarded("frusta_destroy_object", [&] { return w->world.remove_object(handle); });
}

FRUSTA_API frusta_result frusta_world_set_object_pose(frusta_world_id world,
                                                      frusta_object_id object,
                                                      const frusta_pose* pose) {
  WorldObject* w = nullptr;
  if (frusta_result r = world_registry().find(world, &w)) return r;
  ObjectHandle handle;
  if (frusta_result r = object_handle(world, object, &handle)) return r;
  Pose p;
  if (frusta_result r = read_pose(pose, "pose", &p)) return r;
  return w->world.set_object_pose(handle, {p.position, glm::mat3_cast(p.rotation)});
}

FRUSTA_API frusta_result frusta_world_set_object_dynamic(frusta_world_id world,
                                                         frusta_object_id object, int32_t dynamic) {
  WorldObject* w = nullptr;
  if (frusta_result r = world_registry().find(world, &w)) return r;
  ObjectHandle handle;
  if (frusta_result r = object_handle(world, object, &handle)) return r;
  if (dynamic != 0 && dynamic != 1)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "dynamic is %d, must be 0 or 1", dynamic);
  return w->world.set_object_dynamic(handle, dynamic == 1);
}

FRUSTA_API frusta_result frusta_world_step(frusta_world_id world) {
  WorldObject* w = nullptr;
  if (frusta_result r = world_registry().find(world, &w)) return r;
  return w->world.step();
}

FRUSTA_API frusta_result frusta_world_start(frusta_world_id world) {
  WorldObject* w = nullptr;
  if (frusta_result r = world_registry().find(world, &w)) return r;
  return guarded("frusta_world_start", [&] { return w->world.start(); });
}

FRUSTA_API frusta_result frusta_world_stop(frusta_world_id world) {
  WorldObject* w = nullptr;
  if (frusta_result r = world_registry().find(world, &w)) return r;
  w->world.stop();
  return FRUSTA_OK;
}

FRUSTA_API frusta_result frusta_world_read(frusta_world_id world, frusta_world_state* state) {
  WorldObject* w = nullptr;
  if (frusta_result r = world_registry().find(world, &w)) return r;
  if (frusta_result r = check_out_struct(state, "state", "frusta_world_state")) return r;
  const WorldSnapshot& snap = w->world.read();
  w->latched = &snap;
  int32_t hands = 0;
  for (const HandSlot& h : snap.hands) hands += h.present ? 1 : 0;
  state->hand_count = hands;
  state->step = snap.step;
  state->time = snap.time;
  state->step_us = snap.step_us;
  state->step_us_p50 = snap.step_us_p50;
  state->step_us_p99 = snap.step_us_p99;
  state->step_us_max = snap.step_us_max;
  state->wake_late_us_p50 = snap.wake_late_us_p50;
  state->wake_late_us_p99 = snap.wake_late_us_p99;
  state->wake_late_us_max = snap.wake_late_us_max;
  state->achieved_rate_hz = snap.achieved_rate_hz;
  state->overruns = snap.overruns;
  state->rejected_inputs = snap.rejected_inputs;
  int32_t present = 0;
  for (const ObjectSnapshot& o : snap.objects) present += o.present ? 1 : 0;
  state->object_count = present;
  state->realtime = snap.realtime ? 1 : 0;
  return FRUSTA_OK;
}

FRUSTA_API frusta_result frusta_world_get_hand(frusta_world_id world, frusta_hand_id hand,
                                               frusta_world_hand* out) {
  WorldObject* w = nullptr;
  if (frusta_result r = world_registry().find(world, &w)) return r;
  if (frusta_result r = check_out_struct(out, "out", "frusta_world_hand")) return r;
  const HandSnapshot* h = nullptr;
  if (frusta_result r = latched_hand(world, w, hand, &h)) return r;
  out->solved = h->solved ? 1 : 0;
  store_state(h->graphic, &out->graphic_palm, out->graphic_angles);
  store_state(h->haptic, &out->haptic_palm, out->haptic_angles);
  out->contact_count = h->contact_count;
  out->pressing = h->force_stats.pressing;
  out->slipping = h->force_stats.slipping;
  out->substeps = h->stats.substeps;
  out->lagging = h->stats.lagging ? 1 : 0;
  out->infeasible = h->stats.infeasible ? 1 : 0;
  out->ignored_objects = h->ignored_objects;
  out->input_late = h->input_late ? 1 : 0;
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    store(h->device.fingertip_force[static_cast<size_t>(f)], out->fingertip_force[f]);
    out->finger_resistance[f] = h->device.finger_resistance[static_cast<size_t>(f)];
  }
  std::memcpy(out->joint_torque, h->device.joint_torque.data(), sizeof out->joint_torque);
  store(h->device.palm_force, out->palm_force);
  store(h->device.palm_torque, out->palm_torque);
  return FRUSTA_OK;
}

FRUSTA_API frusta_result frusta_world_get_contacts(frusta_world_id world, frusta_hand_id hand,
                                                   frusta_world_contact* out, int32_t capacity,
                                                   int32_t* out_count) {
  WorldObject* w = nullptr;
  if (frusta_result r = world_registry().find(world, &w)) return r;
  HandHandle handle;
  if (frusta_result r = hand_handle(world, hand, &handle)) return r;
  if (frusta_result r = check_output_array(out, "out", capacity, out_count)) return r;
  const HandSnapshot* h = nullptr;
  if (frusta_result r = latched_hand(world, w, hand, &h)) return r;
  const WorldSnapshot& snap = *w->latched;
  const int32_t kept = std::min(h->contact_count, static_cast<int32_t>(h->contacts.size()));
  return fill_output_array(capacity, kept, out_count, [&](int32_t i) {
    const SolverContact& c = h->contacts[static_cast<size_t>(i)];
    const ContactForce& f = h->forces[static_cast<size_t>(i)];
    frusta_world_contact& o = out[i];
    const ObjectSnapshot& object = snap.objects[static_cast<size_t>(c.object)];
    o.object = object_id(world, {c.object, object.generation});
    o.body = c.body;
    o.leaf = c.leaf;
    o.slipping = f.slipping ? 1 : 0;
    o.reserved0 = 0;
    o.distance = c.distance;
    store(f.graphic_point, o.graphic_point);
    store(f.haptic_point, o.haptic_point);
    store(c.normal, o.normal);
    store(f.normal_force, o.normal_force);
    store(f.friction, o.friction);
  });
}

FRUSTA_API frusta_result frusta_world_get_object(frusta_world_id world, frusta_object_id object,
                                                 frusta_object_state* out) {
  WorldObject* w = nullptr;
  if (frusta_result r = world_registry().find(world, &w)) return r;
  ObjectHandle handle;
  if (frusta_result r = object_handle(world, object, &handle)) return r;
  if (frusta_result r = check_out_struct(out, "out", "frusta_object_state")) return r;
  const ObjectSnapshot* o = nullptr;
  if (frusta_result r = latched_object(world, w, object, &o)) return r;
  out->dynamic = o->dynamic ? 1 : 0;
  store(to_pose(o->pose.position, o->pose.rotation), &out->pose);
  store(o->linear_velocity, out->linear_velocity);
  store(o->angular_velocity, out->angular_velocity);
  store(o->reaction.force, out->reaction_force);
  store(o->reaction.torque, out->reaction_torque);
  out->ignoring_hands = static_cast<int32_t>(std::bitset<64>(o->ignored_by).count());
  out->held = o->held_by >= 0 ? 1 : 0;
  return FRUSTA_OK;
}

FRUSTA_API frusta_result frusta_world_get_object_ignored_by(frusta_world_id world,
                                                            frusta_object_id object,
                                                            frusta_hand_id hand,
                                                            int32_t* out_ignored) {
  WorldObject* w = nullptr;
  if (frusta_result r = world_registry().find(world, &w)) return r;
  ObjectHandle object_slot;
  if (frusta_result r = object_handle(world, object, &object_slot)) return r;
  HandHandle hand_slot;
  if (frusta_result r = hand_handle(world, hand, &hand_slot)) return r;
  if (frusta_result r = check_pointer(out_ignored, "out_ignored")) return r;
  const ObjectSnapshot* o = nullptr;
  if (frusta_result r = latched_object(world, w, object, &o)) return r;
  const HandSnapshot* h = nullptr;
  if (frusta_result r = latched_hand(world, w, hand, &h)) return r;
  *out_ignored = static_cast<int32_t>((o->ignored_by >> hand_slot.slot) & 1u);
  return FRUSTA_OK;
}

FRUSTA_API frusta_result frusta_world_get_hand_segments(frusta_world_id world,
                                                        frusta_hand_id hand, int32_t which,
                                                        frusta_segment* out, int32_t capacity,
                                                        int32_t* out_count) {
  return copy_latched_geometry(world, hand, which, out, capacity, out_count, copy_segments);
}

FRUSTA_API frusta_result frusta_world_get_hand_palm_spheres(frusta_world_id world,
                                                            frusta_hand_id hand, int32_t which,
                                                            frusta_sphere* out, int32_t capacity,
                                                            int32_t* out_count) {
  return copy_latched_geometry(world, hand, which, out, capacity, out_count, copy_palm_spheres);
}
