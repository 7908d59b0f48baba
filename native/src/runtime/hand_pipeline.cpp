// SPDX-License-Identifier: MIT
#include "runtime/hand_pipeline.h"

#include <algorithm>

#include "core/periodic_clock.h"

namespace frusta {

HandPipeline::HandPipeline(const HandModel& model, const SolverParams& params,
                           int32_t max_contacts, int32_t max_objects, int32_t slot,
                           HandPort& port)
    : solver_(model, params),
      slot_(slot),
      port_(port),
      forces_(max_contacts),
      reactions_(static_cast<size_t>(max_objects)),
      grasp_entry_(static_cast<size_t>(max_objects), -1),
      ignored_(static_cast<size_t>(max_objects), 0) {
  objects_.reserve(static_cast<size_t>(max_objects));
  object_slot_.reserve(static_cast<size_t>(max_objects));
  materials_.reserve(static_cast<size_t>(max_objects));
  // a force names one object: as many objects as the table holds forces (fades included)
  grasp_object_.reserve(forces_.forces().capacity());
  grasp_pushes_.reserve(forces_.forces().capacity());
  for (HandSnapshot& snap : snapshots_) {
    snap.model = &solver_.model();
    snap.contacts.resize(static_cast<size_t>(max_contacts));
    snap.forces.resize(static_cast<size_t>(max_contacts));
  }
}

void HandPipeline::forget(int32_t slot) {
  ignored_count_ -= ignored_[static_cast<size_t>(slot)];
  ignored_[static_cast<size_t>(slot)] = 0;
}

bool HandPipeline::step(const HandStepContext& context, SceneObjects& scene, HandSnapshot& snap) {
  // every sample delivered since the last step, in order; the newest as well, in case a
  // burst overflowed the port's queue (the playback drops what it has already)
  TimedInput input;
  while (port_.pop_input(input)) playback_.push(input);
  if (port_.input_fresh()) playback_.push(port_.take_input());
  if (playback_.empty()) return true;  // nothing to solve before the first input
  HandState haptic;
  bool late = false;
  if ((!context.paced || playback_.newest().live) && !playback_.newest().timed) {
    // the host steps and sets untimed inputs: it paces both, and the newest is for now;
    // a glove's untimed samples come about one a period from its own thread, and every
    // period of delay is felt: the newest, as it is
    playback_.keep_newest();
    haptic = playback_.newest().state;
    if (playback_.newest().live) live_sample_ns_ = playback_.newest().set_ns;
  } else {
    // where the driver's samples say the hand was input_delay before this step (a step
    // caught up after a stall asks for its own time, not now's)
    haptic = playback_.play(context.play_ns, context.max_extrapolation_ns, &late);
  }
  // the list the solver had last step, unchanged: it may keep what it detected
  const bool objects_as_before = !update_ignored(scene) && !scene.moved();
  const bool own_list = ignored_count_ > 0;
  const SolverObject* objects = own_list ? objects_.data() : scene.active().data();
  const int32_t* object_slot = own_list ? object_slot_.data() : scene.active_slot().data();
  const ForceMaterial* materials =
      own_list ? materials_.data() : scene.active_material().data();
  const int32_t object_count =
      static_cast<int32_t>(own_list ? objects_.size() : scene.active().size());
  StepStats stats;
  bool placed = true;
  // the scene's broad phase finds the present objects near the hand; the hand's own list
  // (while it ignores some, rare) is looked at whole
  const ObjectFinder* finder = own_list ? nullptr : &scene;
  if (solver_.step(haptic, objects, object_count, &stats, context.deadline, finder, objects_as_before) ==
      FRUSTA_OK) {
    accepted_ = haptic;
  } else {
    placed = false;  // the graphic hand stays as it was, the forces follow the last good input
  }
  snap.haptic = accepted_;
  snap.graphic = solver_.graphic();
  snap.stats = stats;
  snap.ignored_objects = ignored_count_;
  snap.input_late = late;
  snap.solved = solver_.started();
  const std::vector<SolverContact>& contacts = solver_.contacts();
  snap.contact_count = static_cast<int32_t>(contacts.size());
  snap.device = DeviceOutputs{};
  snap.force_stats = ContactForceStats{};
  if (!snap.solved) return placed;

  // forces on the contacts the snapshot keeps; the table holds as many. The solver's
  // last step succeeded (a hand that failed one is not solved), so its target is the
  // accepted input's
  forces_.set_time_step(context.dt);  // in range: the rate was checked
  const int32_t kept = std::min(snap.contact_count, context.max_contacts);
  const HandPose& haptic_pose = solver_.target_pose();
  forces_.update(solver_.graphic_pose(), haptic_pose, contacts.data(), kept, objects,
                 object_count, materials, &snap.force_stats, stats.lagging);
  // the contacts' forces, and the pushes a lag fades out after them
  compute_device_outputs(haptic_pose, forces_.forces().data(),
                         static_cast<int32_t>(forces_.forces().size()), objects, object_count,
                         context.device_limits, &snap.device, reactions_.data());
  snap.force_stats.dropped = snap.contact_count - kept;
  for (int32_t i = 0; i < kept; ++i) {
    const size_t k = static_cast<size_t>(i);
    const int32_t slot = object_slot[contacts[k].object];
    snap.contacts[k] = contacts[k];
    snap.contacts[k].object = slot;
    snap.forces[k] = forces_.forces()[k];
    snap.forces[k].object = slot;
  }
  // only objects a force names have a reaction: each added once (and cleared, so a
  // second force on it adds nothing), not one per object in the scene
  for (const ContactForce& c : forces_.forces()) {
    ObjectWrench& reaction = reactions_[static_cast<size_t>(c.object)];
    scene.add_reaction(object_slot[c.object], reaction);
    reaction = ObjectWrench{};
  }
  offer_grasps(scene, object_slot, materials);
  return placed;
}

void HandPipeline::offer_grasps(SceneObjects& scene, const int32_t* object_slot,
                                const ForceMaterial* materials) {
  for (const ContactForce& c : forces_.forces()) {
    if (!scene.dynamic(object_slot[c.object])) continue;
    int32_t& entry = grasp_entry_[static_cast<size_t>(c.object)];
    if (entry < 0) {  // within the capacity: one entry per force at most
      entry = static_cast<int32_t>(grasp_object_.size());
      grasp_object_.push_back(c.object);
      grasp_pushes_.push_back(BodyPushes{});
    }
    grasp_pushes_[static_cast<size_t>(entry)][static_cast<size_t>(c.body)] += c.normal_force;
  }
  // the haptic palm: a held object moves with the user's hand, and the graphic hand,
  // kept out of it, with both (it cannot lead the graphic hand, which it blocks)
  const HandPose& haptic = solver_.target_pose();
  const RigidPose palm{haptic.palm_position, haptic.palm_rotation};
  for (size_t e = 0; e < grasp_object_.size(); ++e) {
    const int32_t object = grasp_object_[e];
    scene.offer_grasp(object_slot[object], slot_,
                      squeeze_load(grasp_pushes_[e], materials[object].friction), palm);
    grasp_entry_[static_cast<size_t>(object)] = -1;
  }
  grasp_object_.clear();
  grasp_pushes_.clear();
}

bool HandPipeline::update_ignored(SceneObjects& scene) {
  const std::vector<SolverObject>& active = scene.active();
  const std::vector<int32_t>& active_slot = scene.active_slot();
  bool changed = false;
  auto look_at = [&](size_t a) {
    const int32_t slot = active_slot[a];
    uint8_t& ignored = ignored_[static_cast<size_t>(slot)];
    if (!scene.placed(slot) && !ignored) return;  // the common case: nothing to look at
    const uint8_t now = solver_.overlaps(active[a]) ? 1 : 0;
    if (now == ignored) return;
    ignored_count_ += now ? 1 : -1;
    ignored = now;
    scene.set_ignored(slot, slot_, now != 0);
    changed = true;
  };
  if (ignored_count_ > 0) {
    for (size_t a = 0; a < active.size(); ++a) look_at(a);
  } else {
    // nothing ignored: only the objects placed since the last step can start to be (a
    // room's props cost nothing)
    for (int32_t slot : scene.placed_slots())
      if (scene.active_index(slot) >= 0) look_at(static_cast<size_t>(scene.active_index(slot)));
  }
  if (ignored_count_ == 0 || (!changed && !scene.moved())) return changed;
  objects_.clear();  // within the capacity reserved at construction
  object_slot_.clear();
  materials_.clear();
  for (size_t a = 0; a < active.size(); ++a) {
    if (ignored_[static_cast<size_t>(active_slot[a])]) continue;
    objects_.push_back(active[a]);
    object_slot_.push_back(active_slot[a]);
    materials_.push_back(scene.active_material()[a]);
  }
  return changed;
}

void HandPipeline::publish_feed(const HandSnapshot& snap, uint64_t step, int64_t host_read_ns) {
  DeviceFeed feed;
  feed.step = step;
  feed.published_ns = steady_ns();
  feed.host_read_ns = host_read_ns;
  feed.solved = snap.solved;
  feed.device = snap.device;
  feed.haptic_palm_rotation = accepted_.palm_rotation;
  if (!playback_.empty()) {
    feed.input_sequence = playback_.newest().sequence;
    feed.input_set_ns = playback_.newest().set_ns;
  }
  port_.publish_feed(feed);
}

}  // namespace frusta
