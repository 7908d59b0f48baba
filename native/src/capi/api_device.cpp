// SPDX-License-Identifier: MIT
// C ABI: force-feedback gloves, each driving one hand of a world on a thread of its own.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "capi/convert.h"
#include "capi/world_registry.h"
#include "core/error.h"
#include "core/validate.h"
#include "devices/device_enumeration.h"
#include "devices/device_factory.h"
#include "devices/device_uri.h"
#include "frusta/frusta.h"

using namespace frusta;

namespace {

constexpr int32_t kFlexions = 3;

// The calibration's fields, between frusta_device_def and GloveCalibration (either
// way: they share names, the one as C arrays, the other as std::arrays).
template <class From, class To>
void copy_calibration(const From& from, To& to) {
  for (int32_t f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    for (int32_t j = 0; j < kFlexions; ++j) {
      to.curl_open[f][j] = from.curl_open[f][j];
      to.curl_closed[f][j] = from.curl_closed[f][j];
      to.flexion_open[f][j] = from.flexion_open[f][j];
      to.flexion_closed[f][j] = from.flexion_closed[f][j];
    }
    to.splay_center[f] = from.splay_center[f];
    to.splay_span[f] = from.splay_span[f];
    to.abduction_range[f] = from.abduction_range[f];
  }
  to.brake_full_scale = from.brake_full_scale;
  to.brake_units = from.brake_units;
  to.analog_max = from.analog_max;
}

// The link's fields as (frusta_device_def's, DeviceLinkDef's) pairs, `each` copying
// either way. The rate limits sit apart in DeviceLinkDef::rates, so unlike the
// calibration's fields these cannot be copied by name; one list of pairs serves both
// read_device_def and frusta_default_device_def.
template <class Def, class Link, class Each>
void pair_link_fields(Def& def, Link& link, Each each) {
  each(def.output_rate_hz, link.output_rate_hz);
  each(def.watchdog_s, link.watchdog_s);
  each(def.engine_timeout_s, link.engine_timeout_s);
  each(def.host_timeout_s, link.host_timeout_s);
  each(def.reconnect_interval_s, link.reconnect_interval_s);
  each(def.max_force_rate, link.rates.max_force_rate);
  each(def.max_torque_rate, link.rates.max_torque_rate);
  each(def.max_finger_resistance, link.max_finger_resistance);
  each(def.max_fingertip_force, link.max_fingertip_force);
  each(def.max_joint_torque, link.max_joint_torque);
}

frusta_result in_range(double value, double low, double high, const char* field) {
  if (!std::isfinite(value))
    return fail(FRUSTA_ERROR_NOT_FINITE, "frusta_device_def.%s is %g", field, value);
  if (value < low || value > high)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "frusta_device_def.%s is %g, not in [%g, %g]", field,
                value, low, high);
  return FRUSTA_OK;
}

// Every double of the def, named as the header names it: NaN or infinity anywhere is
// FRUSTA_ERROR_NOT_FINITE before any range is looked at (the calibration's own checks
// would call a NaN out of range).
frusta_result check_def_finite(const frusta_device_def& in) {
  struct Doubles {
    const char* name;
    const double* values;
    int count;
  };
  const Doubles fields[] = {
      {"output_rate_hz", &in.output_rate_hz, 1},
      {"watchdog_s", &in.watchdog_s, 1},
      {"engine_timeout_s", &in.engine_timeout_s, 1},
      {"host_timeout_s", &in.host_timeout_s, 1},
      {"reconnect_interval_s", &in.reconnect_interval_s, 1},
      {"max_force_rate", &in.max_force_rate, 1},
      {"max_torque_rate", &in.max_torque_rate, 1},
      {"max_finger_resistance", &in.max_finger_resistance, 1},
      {"max_fingertip_force", &in.max_fingertip_force, 1},
      {"max_joint_torque", &in.max_joint_torque, 1},
      {"curl_open", &in.curl_open[0][0], FRUSTA_FINGER_COUNT * kFlexions},
      {"curl_closed", &in.curl_closed[0][0], FRUSTA_FINGER_COUNT * kFlexions},
      {"flexion_open", &in.flexion_open[0][0], FRUSTA_FINGER_COUNT * kFlexions},
      {"flexion_closed", &in.flexion_closed[0][0], FRUSTA_FINGER_COUNT * kFlexions},
      {"splay_center", in.splay_center, FRUSTA_FINGER_COUNT},
      {"splay_span", in.splay_span, FRUSTA_FINGER_COUNT},
      {"abduction_range", in.abduction_range, FRUSTA_FINGER_COUNT},
      {"brake_full_scale", &in.brake_full_scale, 1},
      {"brake_units", &in.brake_units, 1},
      {"analog_max", &in.analog_max, 1},
  };
  for (const Doubles& f : fields) {
    for (int i = 0; i < f.count; ++i) {
      if (std::isfinite(f.values[i])) continue;
      if (f.count == 1)
        return fail(FRUSTA_ERROR_NOT_FINITE, "frusta_device_def.%s is %g", f.name, f.values[i]);
      if (f.count == FRUSTA_FINGER_COUNT)
        return fail(FRUSTA_ERROR_NOT_FINITE, "frusta_device_def.%s[%d] is %g", f.name, i, f.values[i]);
      return fail(FRUSTA_ERROR_NOT_FINITE, "frusta_device_def.%s[%d][%d] is %g", f.name,
                  i / kFlexions, i % kFlexions, f.values[i]);
    }
  }
  return FRUSTA_OK;
}

// 0 (`zero_means`) or within [low, high]: a value between 0 and low is no setting
// (a command period of 1e300 s overflowed the glove thread's clock)
frusta_result zero_or_in_range(double value, double low, double high, const char* field,
                               const char* zero_means) {
  if (value == 0.0 || (value >= low && value <= high)) return FRUSTA_OK;
  return fail(FRUSTA_ERROR_OUT_OF_RANGE, "frusta_device_def.%s is %g, must be 0 (%s) or in [%g, %g]",
              field, value, zero_means, low, high);
}

frusta_result read_device_def(const frusta_device_def& in, DeviceLinkDef* link,
                              GloveCalibration* calibration) {
  if (frusta_result r = check_def_finite(in)) return r;
  DeviceLinkDef d;
  pair_link_fields(in, d, [](const double& from, double& to) { to = from; });
  if (frusta_result r = zero_or_in_range(d.output_rate_hz, 1.0, 100000.0, "output_rate_hz",
                                         "the world's rate"))
    return r;
  if (frusta_result r = in_range(d.watchdog_s, 0.001, 10.0, "watchdog_s")) return r;
  if (frusta_result r = in_range(d.engine_timeout_s, 0.001, 10.0, "engine_timeout_s")) return r;
  if (frusta_result r = zero_or_in_range(d.host_timeout_s, 0.001, 60.0, "host_timeout_s",
                                         "not watched"))
    return r;
  if (frusta_result r = in_range(d.reconnect_interval_s, 0.001, 60.0, "reconnect_interval_s")) return r;
  if (frusta_result r = in_range(d.rates.max_force_rate, 0.0, 1e9, "max_force_rate")) return r;
  if (frusta_result r = in_range(d.rates.max_torque_rate, 0.0, 1e9, "max_torque_rate")) return r;
  if (frusta_result r = in_range(d.max_finger_resistance, 0.0, 1e9, "max_finger_resistance")) return r;
  if (frusta_result r = in_range(d.max_fingertip_force, 0.0, 1e9, "max_fingertip_force")) return r;
  if (frusta_result r = in_range(d.max_joint_torque, 0.0, 1e9, "max_joint_torque")) return r;

  GloveCalibration c;
  copy_calibration(in, c);
  if (frusta_result r = check_glove_calibration(c)) return r;
  *link = d;
  *calibration = c;
  return FRUSTA_OK;
}

// The world and glove of a device id, or why not.
frusta_result find_device(frusta_device_id id, WorldObject** world, DeviceLink** link,
                          int32_t* hand) {
  if (id.index1 == 0) return fail(FRUSTA_ERROR_NULL_ID, "device id is null (zero-initialised)");
  frusta_world_id world_id;
  if (frusta_result r = world_registry().find_by_tag(id.world0, "device", world, &world_id)) return r;
  // index1 is checked before 1 is taken off it: INT32_MIN - 1 overflows
  const int32_t slots = static_cast<int32_t>((*world)->gloves.size());
  const int32_t h = id.index1 >= 1 && id.index1 <= slots ? id.index1 - 1 : -1;
  if (h < 0 || !(*world)->gloves[static_cast<size_t>(h)] ||
      (*world)->glove_generation[static_cast<size_t>(h)] != id.generation)
    return fail(FRUSTA_ERROR_STALE_ID,
                "device id {index1=%d, generation=%u} names no open glove: it was closed",
                id.index1, id.generation);
  *link = (*world)->gloves[static_cast<size_t>(h)].get();
  *hand = h;
  return FRUSTA_OK;
}

// A glove id's generation, from one counter for every world: world0 keeps only the
// low byte of its world's generation, so with a count per world, a glove id of a world
// destroyed 256 generations of its slot ago named the new world's glove on that hand
// (and frusta_destroy_device through it closed that glove). Never 0.
uint16_t next_glove_generation() {
  static std::atomic<uint32_t> count{0};
  uint16_t generation;
  do {
    generation = static_cast<uint16_t>(count.fetch_add(1, std::memory_order_relaxed) + 1);
  } while (generation == 0);
  return generation;
}

void store_uri(const std::string& uri, uint8_t* out, size_t capacity) {
  const size_t n = std::min(uri.size(), capacity - 1);
  std::memcpy(out, uri.data(), n);
  out[n] = 0;
}

}  // namespace

FRUSTA_API frusta_device_def frusta_default_device_def(void) {
  const DeviceLinkDef d;
  const GloveCalibration c = default_glove_calibration();
  frusta_device_def def = blank_def<frusta_device_def>();  // hand stays null: the caller names one
  pair_link_fields(def, d, [](double& to, const double& from) { to = from; });
  copy_calibration(c, def);
  return def;
}

FRUSTA_API frusta_result frusta_enumerate_devices(frusta_device_info* out, int32_t capacity,
                                                  int32_t* out_count) {
  if (frusta_result r = check_output_array(out, "out", capacity, out_count)) return r;
  return guarded("frusta_enumerate_devices", [&] {
    std::vector<DeviceInfo> found;
    enumerate_devices(&found);
    const int32_t count = static_cast<int32_t>(found.size());
    return fill_output_array(capacity, count, out_count, [&](int32_t i) {
      const DeviceInfo& d = found[static_cast<size_t>(i)];
      frusta_device_info& o = out[i];
      o.kind = d.kind;
      o.vendor_id = d.vendor_id;
      o.product_id = d.product_id;
      store_uri(d.uri, o.uri, sizeof o.uri);
    });
  });
}

FRUSTA_API frusta_result frusta_create_device(frusta_world_id world, const char* uri,
                                              const frusta_device_def* def,
                                              frusta_device_id* out_device) {
  WorldObject* w = nullptr;
  if (frusta_result r = world_registry().find(world, &w)) return r;
  if (frusta_result r = check_pointer(uri, "uri")) return r;
  if (frusta_result r = check_def_input(def, "frusta_device_def")) return r;
  if (frusta_result r = check_pointer(out_device, "out_device")) return r;
  DeviceLinkDef link_def;
  GloveCalibration calibration;
  if (frusta_result r = read_device_def(*def, &link_def, &calibration)) return r;
  HandHandle handle;
  frusta_result found = hand_handle(world, def->hand, &handle);
  if (found == FRUSTA_OK && !w->world.hand_is_live(handle))
    found = fail(FRUSTA_ERROR_STALE_ID,
                 "hand id {index1=%d, generation=%u} names no hand of this world: it was "
                 "destroyed, or never created",
                 def->hand.index1, def->hand.generation);
  if (found != FRUSTA_OK) {
    // the field, then why, without the code's name that opens the message
    const std::string why = last_error_message();
    const size_t colon = why.find(": ");
    return fail(found, "frusta_device_def.hand: %s",
                colon == std::string::npos ? why.c_str() : why.c_str() + colon + 2);
  }
  const int32_t hand = handle.slot;
  DeviceAddress address;
  if (frusta_result r = parse_device_uri(uri, &address)) return r;
  return guarded("frusta_create_device", [&] {
    Glove glove;
    if (frusta_result r = make_glove(address, calibration, &glove)) return r;
    link_def.record_path = address.record_path;
    link_def.protocol_name = glove.protocol_name;
    auto link = std::make_unique<DeviceLink>(w->world.port(hand), link_def,
                                             std::move(glove.stream), std::move(glove.protocol));
    if (frusta_result r = link->open()) return r;  // the port refuses a second glove
    uint16_t& generation = w->glove_generation[static_cast<size_t>(hand)];
    generation = next_glove_generation();
    w->gloves[static_cast<size_t>(hand)] = std::move(link);
    *out_device = frusta_device_id{hand + 1, world_tag(world), generation};
    return FRUSTA_OK;
  });
}

FRUSTA_API frusta_result frusta_destroy_device(frusta_device_id device) {
  WorldObject* w = nullptr;
  DeviceLink* link = nullptr;
  int32_t hand = -1;
  if (frusta_result r = find_device(device, &w, &link, &hand)) return r;
  return guarded("frusta_destroy_device", [&] {
    // zeroes the glove, joins its thread, gives the hand back to the host
    w->gloves[static_cast<size_t>(hand)].reset();
    return FRUSTA_OK;
  });
}

FRUSTA_API int32_t frusta_device_is_valid(frusta_device_id device) {
  if (device.index1 == 0) return 0;
  WorldObject* w = nullptr;
  frusta_world_id world;
  if (world_registry().find_by_tag(device.world0, nullptr, &w, &world) != FRUSTA_OK) return 0;
  // index1 is checked before 1 is taken off it
  if (device.index1 < 1 || device.index1 > static_cast<int32_t>(w->gloves.size())) return 0;
  const int32_t h = device.index1 - 1;
  return w->gloves[static_cast<size_t>(h)] &&
                 w->glove_generation[static_cast<size_t>(h)] == device.generation
             ? 1
             : 0;
}

FRUSTA_API frusta_result frusta_device_get_status(frusta_device_id device,
                                                  frusta_device_status* out) {
  WorldObject* w = nullptr;
  DeviceLink* link = nullptr;
  int32_t hand = -1;
  if (frusta_result r = find_device(device, &w, &link, &hand)) return r;
  if (frusta_result r = check_out_struct(out, "out", "frusta_device_status")) return r;
  const DeviceLinkStatus& s = link->status();
  frusta_device_status o;
  std::memset(&o, 0, sizeof o);
  o.struct_size = sizeof o;
  o.state = static_cast<int32_t>(s.state);
  o.watchdog = static_cast<int32_t>(s.watchdog);
  o.outputs = static_cast<int32_t>(s.capabilities.outputs);
  o.fingers = s.capabilities.fingers;
  o.has_palm_pose = s.capabilities.has_palm_pose ? 1 : 0;
  o.protocol_version = static_cast<int32_t>(s.capabilities.protocol_version);
  o.recording_failed = s.recording_failed ? 1 : 0;
  o.frames_ok = s.frames_ok;
  o.frames_corrupt = s.frames_corrupt;
  o.frames_truncated = s.frames_truncated;
  o.frames_out_of_range = s.frames_out_of_range;
  o.samples_rejected = s.samples_rejected;
  o.commands_sent = s.commands_sent;
  o.commands_dropped = s.commands_dropped;
  o.reconnects = s.reconnects;
  o.disconnects = s.disconnects;
  o.watchdog_trips = s.watchdog_trips;
  o.input_rate_hz = s.input_rate_hz;
  o.output_rate_hz = s.output_rate_hz;
  o.last_sample_age_s = s.last_sample_age_s;
  o.max_finger_resistance = s.capabilities.max_finger_resistance;
  o.max_fingertip_force = s.capabilities.max_fingertip_force;
  o.max_joint_torque = s.capabilities.max_joint_torque;
  for (int32_t f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    o.finger_resistance[f] = s.last_command.finger_resistance[f];
    store(s.last_command.fingertip_force[f], o.fingertip_force[f]);
  }
  *out = o;
  return FRUSTA_OK;
}

FRUSTA_API frusta_result frusta_device_set_palm_pose(frusta_device_id device,
                                                     const frusta_pose* palm) {
  WorldObject* w = nullptr;
  DeviceLink* link = nullptr;
  int32_t hand = -1;
  if (frusta_result r = find_device(device, &w, &link, &hand)) return r;
  Pose pose;
  if (frusta_result r = read_pose(palm, "palm", &pose)) return r;
  link->set_palm_pose(pose.position, pose.rotation);
  return FRUSTA_OK;
}
