// SPDX-License-Identifier: MIT
// C ABI: hands. Each function checks every input before it changes anything.
#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "capi/convert.h"
#include "capi/hand_registry.h"
#include "capi/world_registry.h"
#include "core/error.h"
#include "core/validate.h"
#include "frusta/frusta.h"
#include "hand/anthropometry.h"

using namespace frusta;

namespace {

// The standalone hand of id. A live world's hand id is refused by name: its state lives
// in the world (frusta_world_get_hand), and the registry would only call it stale.
frusta_result find_hand(frusta_hand_id id, HandObject** out) {
  if (world_hand_is_valid(id))
    return fail(FRUSTA_ERROR_STALE_ID,
                "hand id {index1=%d, world0=%u, generation=%u} names a world's hand, not a "
                "standalone one: the frusta_world_* calls take it (frusta_destroy_world_hand "
                "destroys it)",
                id.index1, id.world0, id.generation);
  return hand_registry().find(id, out);
}

}  // namespace

FRUSTA_API frusta_hand_def frusta_default_hand_def(void) {
  frusta_hand_def def = blank_def<frusta_hand_def>();
  store_hand_def(default_hand_def(), &def);
  return def;
}

FRUSTA_API frusta_result frusta_hand_def_set_size(frusta_hand_def* def, double hand_length,
                                                  double hand_breadth) {
  if (frusta_result r = check_def_input(def, "frusta_hand_def")) return r;
  if (frusta_result r = check_range(hand_length, kMinHandSize, kMaxHandSize, false, "hand_length"))
    return r;
  if (frusta_result r = check_range(hand_breadth, kMinHandSize, kMaxHandSize, false, "hand_breadth"))
    return r;
  HandDef sized = read_hand_def(*def);
  fill_hand_geometry(sized, hand_length, hand_breadth);
  if (frusta_result r = check_hand_def(sized)) {
    // each size is in range, but together they make no hand (a 1 cm hand's fingertip
    // segment is 30 um; one 5 m broad and 1 cm long has negative ones): name the
    // arguments the caller gave, then the part at fault
    const std::string part = last_error_message();
    const size_t colon = part.find(": ");
    return fail(r, "hand_length %g m and hand_breadth %g m give no valid hand: %s", hand_length,
                hand_breadth, colon == std::string::npos ? part.c_str() : part.c_str() + colon + 2);
  }
  store_hand_def(sized, def);
  return FRUSTA_OK;
}

FRUSTA_API frusta_result frusta_create_hand(const frusta_hand_def* def, frusta_hand_id* out_hand) {
  if (frusta_result r = check_def_input(def, "frusta_hand_def")) return r;
  if (frusta_result r = check_pointer(out_hand, "out_hand")) return r;
  const HandDef d = read_hand_def(*def);
  if (frusta_result r = check_hand_def(d)) return r;
  return guarded("frusta_create_hand", [&] { return hand_registry().create(d, out_hand); });
}

FRUSTA_API frusta_result frusta_destroy_hand(frusta_hand_id hand) {
  HandObject* h = nullptr;
  if (frusta_result r = find_hand(hand, &h)) return r;
  return hand_registry().destroy(hand);
}

FRUSTA_API int32_t frusta_hand_is_valid(frusta_hand_id hand) {
  if (hand.world0 != 0) return world_hand_is_valid(hand) ? 1 : 0;
  return hand_registry().is_valid(hand) ? 1 : 0;
}

FRUSTA_API frusta_result frusta_hand_set_palm_pose(frusta_hand_id hand, const frusta_pose* pose) {
  HandObject* h = nullptr;
  if (frusta_result r = find_hand(hand, &h)) return r;
  Pose p;
  if (frusta_result r = read_pose(pose, "pose", &p)) return r;
  h->state.palm_position = p.position;
  h->state.palm_rotation = p.rotation;
  forward_kinematics(h->model, h->state, h->pose);
  return FRUSTA_OK;
}

FRUSTA_API frusta_result frusta_hand_set_joint_angles(frusta_hand_id hand, const double* angles,
                                                      int32_t count) {
  HandObject* h = nullptr;
  if (frusta_result r = find_hand(hand, &h)) return r;
  if (frusta_result r = read_joint_angles(angles, count, "angles", &h->state.angles)) return r;
  clamp_to_limits(h->model, h->state);
  forward_kinematics(h->model, h->state, h->pose);
  return FRUSTA_OK;
}

FRUSTA_API frusta_result frusta_hand_get_joint_angles(frusta_hand_id hand, double* out,
                                                      int32_t capacity, int32_t* out_count) {
  HandObject* h = nullptr;
  if (frusta_result r = find_hand(hand, &h)) return r;
  if (frusta_result r = check_output_array(out, "out", capacity, out_count)) return r;
  return fill_output_array(capacity, FRUSTA_HAND_JOINT_COUNT, out_count,
                           [&](int32_t i) { out[i] = h->state.angles[static_cast<size_t>(i)]; });
}

FRUSTA_API frusta_result frusta_hand_get_segments(frusta_hand_id hand, frusta_segment* out,
                                                  int32_t capacity, int32_t* out_count) {
  HandObject* h = nullptr;
  if (frusta_result r = find_hand(hand, &h)) return r;
  if (frusta_result r = check_output_array(out, "out", capacity, out_count)) return r;
  return copy_segments(h->model, h->pose, out, capacity, out_count);
}

FRUSTA_API frusta_result frusta_hand_get_palm_spheres(frusta_hand_id hand, frusta_sphere* out,
                                                      int32_t capacity, int32_t* out_count) {
  HandObject* h = nullptr;
  if (frusta_result r = find_hand(hand, &h)) return r;
  if (frusta_result r = check_output_array(out, "out", capacity, out_count)) return r;
  return copy_palm_spheres(h->model, h->pose, out, capacity, out_count);
}

FRUSTA_API frusta_result frusta_hand_point_jacobian(frusta_hand_id hand, int32_t finger,
                                                    int32_t segment, const double local_point[3],
                                                    double* out_point, double* out_jacobian,
                                                    int32_t capacity, int32_t* out_count) {
  HandObject* h = nullptr;
  if (frusta_result r = find_hand(hand, &h)) return r;
  if (finger < 0 || finger >= FRUSTA_FINGER_COUNT)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "finger is %d, must be 0..%d", finger,
                FRUSTA_FINGER_COUNT - 1);
  if (segment < 0 || segment >= FRUSTA_SEGMENTS_PER_FINGER)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "segment is %d, must be 0..%d", segment,
                FRUSTA_SEGMENTS_PER_FINGER - 1);
  if (frusta_result r = check_pointer(local_point, "local_point")) return r;
  if (frusta_result r = check_bounded(local_point, 3, kMaxCoordinate, "local_point")) return r;
  if (frusta_result r = check_output_array(out_jacobian, "out_jacobian", capacity, out_count))
    return r;
  static_assert(3 * kJacobianColumns == FRUSTA_POINT_JACOBIAN_LENGTH, "a 3 x 10 Jacobian");
  const vec3 world = segment_point(h->pose, finger, segment,
                                   vec3(local_point[0], local_point[1], local_point[2]));
  // computed whole, copied as far as the caller's buffer reaches
  double jacobian[FRUSTA_POINT_JACOBIAN_LENGTH];
  point_jacobian(h->pose, finger, segment, world, jacobian);
  if (out_point) store(world, out_point);
  return fill_output_array(capacity, FRUSTA_POINT_JACOBIAN_LENGTH, out_count,
                           [&](int32_t i) { out_jacobian[i] = jacobian[i]; });
}
