// SPDX-License-Identifier: MIT
// The frozen layout of every public struct, the values of every public enum and
// constant, and the signature of every entry point. This table is what the C#
// binding mirrors (Marshal.SizeOf / Marshal.OffsetOf); change it only together with
// FRUSTA_ABI_VERSION, the binding and the changelog.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <type_traits>

#include "frusta/frusta.h"

// ---------------------------------------------------------------- the table
// X(struct, member, offset, size in bytes). Members are listed in declaration order.
#define FRUSTA_ABI_MEMBERS(X)                         \
  X(frusta_hand_id, index1, 0, 4)                     \
  X(frusta_hand_id, world0, 4, 2)                     \
  X(frusta_hand_id, generation, 6, 2)                 \
  X(frusta_pose, position, 0, 24)                     \
  X(frusta_pose, rotation, 24, 32)                    \
  X(frusta_sphere, center, 0, 24)                     \
  X(frusta_sphere, radius, 24, 8)                     \
  X(frusta_segment, proximal, 0, 24)                  \
  X(frusta_segment, distal, 24, 24)                   \
  X(frusta_segment, proximal_radius, 48, 8)           \
  X(frusta_segment, distal_radius, 56, 8)             \
  X(frusta_hand_def, struct_size, 0, 4)               \
  X(frusta_hand_def, side, 4, 4)                      \
  X(frusta_hand_def, hand_length, 8, 8)               \
  X(frusta_hand_def, hand_breadth, 16, 8)             \
  X(frusta_hand_def, segment_length, 24, 120)         \
  X(frusta_hand_def, joint_radius, 144, 160)          \
  X(frusta_hand_def, base_position, 304, 120)         \
  X(frusta_hand_def, base_rotation, 424, 120)         \
  X(frusta_hand_def, joint_min, 544, 160)             \
  X(frusta_hand_def, joint_max, 704, 160)             \
  X(frusta_hand_def, palm_length, 864, 8)             \
  X(frusta_hand_def, palm_breadth, 872, 8)            \
  X(frusta_hand_def, palm_thickness, 880, 8)          \
  X(frusta_hand_def, internal_value, 888, 4)          \
  X(frusta_hand_def, reserved0, 892, 4)               \
  X(frusta_tracked_joint, position, 0, 24)            \
  X(frusta_tracked_joint, rotation, 24, 32)           \
  X(frusta_tracked_joint, radius, 56, 8)              \
  X(frusta_tracked_joint, flags, 64, 4)               \
  X(frusta_tracked_joint, reserved0, 68, 4)           \
  X(frusta_hand_fitter_id, index1, 0, 4)              \
  X(frusta_hand_fitter_id, world0, 4, 2)              \
  X(frusta_hand_fitter_id, generation, 6, 2)          \
  X(frusta_hand_fit_def, struct_size, 0, 4)           \
  X(frusta_hand_fit_def, layout, 4, 4)                \
  X(frusta_hand_fit_def, require_tracked, 8, 4)       \
  X(frusta_hand_fit_def, max_iterations, 12, 4)       \
  X(frusta_hand_fit_def, orientation_weight, 16, 8)   \
  X(frusta_hand_fit_def, filter_min_cutoff, 24, 8)    \
  X(frusta_hand_fit_def, filter_beta, 32, 8)          \
  X(frusta_hand_fit_def, filter_d_cutoff, 40, 8)      \
  X(frusta_hand_fit_def, internal_value, 48, 4)       \
  X(frusta_hand_fit_def, reserved0, 52, 4)            \
  X(frusta_hand_fit, struct_size, 0, 4)               \
  X(frusta_hand_fit, palm_flags, 4, 4)                \
  X(frusta_hand_fit, palm, 8, 56)                     \
  X(frusta_hand_fit, angles, 64, 160)                 \
  X(frusta_hand_fit, palm_residual, 224, 8)           \
  X(frusta_hand_fit, finger_residual, 232, 40)        \
  X(frusta_hand_fit, finger_flags, 272, 20)           \
  X(frusta_hand_fit, reserved0, 292, 4)               \
  X(frusta_contact_query, struct_size, 0, 4)          \
  X(frusta_contact_query, feature, 4, 4)              \
  X(frusta_contact_query, patent_contact, 8, 4)       \
  X(frusta_contact_query, contact, 12, 4)             \
  X(frusta_contact_query, distance, 16, 8)            \
  X(frusta_contact_query, hand_point, 24, 24)         \
  X(frusta_contact_query, object_point, 48, 24)       \
  X(frusta_contact_query, normal, 72, 24)             \
  X(frusta_contact_query, axial, 96, 8)               \
  X(frusta_constraint, struct_size, 0, 4)             \
  X(frusta_constraint, feature, 4, 4)                 \
  X(frusta_constraint, value, 8, 8)                   \
  X(frusta_constraint, grad_proximal, 16, 24)         \
  X(frusta_constraint, grad_distal, 40, 24)           \
  X(frusta_constraint, grad_center, 64, 24)           \
  X(frusta_tree_id, index1, 0, 4)                     \
  X(frusta_tree_id, world0, 4, 2)                     \
  X(frusta_tree_id, generation, 6, 2)                 \
  X(frusta_bake_job_id, index1, 0, 4)                 \
  X(frusta_bake_job_id, world0, 4, 2)                 \
  X(frusta_bake_job_id, generation, 6, 2)             \
  X(frusta_bake_def, struct_size, 0, 4)               \
  X(frusta_bake_def, branching, 4, 4)                 \
  X(frusta_bake_def, target_error, 8, 8)              \
  X(frusta_bake_def, max_leaves, 16, 8)               \
  X(frusta_bake_def, max_depth, 24, 4)                \
  X(frusta_bake_def, reserved0, 28, 4)                \
  X(frusta_bake_def, error_samples, 32, 8)            \
  X(frusta_bake_def, seed, 40, 8)                     \
  X(frusta_bake_def, internal_value, 48, 4)           \
  X(frusta_bake_def, reserved1, 52, 4)                \
  X(frusta_sphere_tree_info, struct_size, 0, 4)       \
  X(frusta_sphere_tree_info, branching, 4, 4)         \
  X(frusta_sphere_tree_info, depth, 8, 4)             \
  X(frusta_sphere_tree_info, leaf_count, 12, 4)       \
  X(frusta_sphere_tree_info, node_count, 16, 4)       \
  X(frusta_sphere_tree_info, triangle_count, 20, 4)   \
  X(frusta_sphere_tree_info, bounds_min, 24, 24)      \
  X(frusta_sphere_tree_info, bounds_max, 48, 24)      \
  X(frusta_sphere_tree_info, target_error, 72, 8)     \
  X(frusta_sphere_tree_info, uncovered_error, 80, 8)  \
  X(frusta_sphere_tree_info, protruding_error, 88, 8) \
  X(frusta_sphere_tree_info, bake_seconds, 96, 8)     \
  X(frusta_sphere_tree_info, error_samples, 104, 8)   \
  X(frusta_sphere_tree_info, target_met, 112, 4)      \
  X(frusta_sphere_tree_info, reserved0, 116, 4)       \
  X(frusta_tree_hit, node, 0, 4)                      \
  X(frusta_tree_hit, leaf, 4, 4)                      \
  X(frusta_tree_hit, sphere, 8, 32)                   \
  X(frusta_world_id, index1, 0, 4)                    \
  X(frusta_world_id, world0, 4, 2)                    \
  X(frusta_world_id, generation, 6, 2)                \
  X(frusta_object_id, index1, 0, 4)                   \
  X(frusta_object_id, world0, 4, 2)                   \
  X(frusta_object_id, generation, 6, 2)               \
  X(frusta_world_def, struct_size, 0, 4)              \
  X(frusta_world_def, max_objects, 4, 4)              \
  X(frusta_world_def, rate_hz, 8, 8)                  \
  X(frusta_world_def, spin_us, 16, 8)                 \
  X(frusta_world_def, gravity, 24, 24)                \
  X(frusta_world_def, prediction_margin, 48, 8)       \
  X(frusta_world_def, lod_error, 56, 8)             \
  X(frusta_world_def, max_iterations, 64, 4)          \
  X(frusta_world_def, max_substeps, 68, 4)            \
  X(frusta_world_def, max_contacts_per_hand, 72, 4)   \
  X(frusta_world_def, command_capacity, 76, 4)        \
  X(frusta_world_def, max_hands, 80, 4)               \
  X(frusta_world_def, realtime_priority, 84, 4)       \
  X(frusta_world_def, max_fingertip_force, 88, 8)     \
  X(frusta_world_def, max_finger_resistance, 96, 8)   \
  X(frusta_world_def, max_joint_torque, 104, 8)       \
  X(frusta_world_def, max_palm_force, 112, 8)         \
  X(frusta_world_def, max_palm_torque, 120, 8)        \
  X(frusta_world_def, input_delay, 128, 8)            \
  X(frusta_world_def, max_extrapolation, 136, 8)      \
  X(frusta_world_def, max_candidates_per_hand, 144, 4) \
  X(frusta_world_def, internal_value, 148, 4)         \
  X(frusta_object_def, struct_size, 0, 4)             \
  X(frusta_object_def, dynamic, 4, 4)                 \
  X(frusta_object_def, pose, 8, 56)                   \
  X(frusta_object_def, stiffness, 64, 24)             \
  X(frusta_object_def, friction, 88, 8)               \
  X(frusta_object_def, tangential_stiffness, 96, 8)   \
  X(frusta_object_def, normal_damping, 104, 8)        \
  X(frusta_object_def, tangential_damping, 112, 8)    \
  X(frusta_object_def, mass, 120, 8)                  \
  X(frusta_object_def, inertia, 128, 24)              \
  X(frusta_object_def, linear_velocity, 152, 24)      \
  X(frusta_object_def, angular_velocity, 176, 24)     \
  X(frusta_object_def, linear_damping, 200, 8)        \
  X(frusta_object_def, angular_damping, 208, 8)       \
  X(frusta_object_def, internal_value, 216, 4)        \
  X(frusta_object_def, reserved0, 220, 4)             \
  X(frusta_world_state, struct_size, 0, 4)            \
  X(frusta_world_state, hand_count, 4, 4)             \
  X(frusta_world_state, step, 8, 8)                   \
  X(frusta_world_state, time, 16, 8)                  \
  X(frusta_world_state, step_us, 24, 8)               \
  X(frusta_world_state, step_us_p50, 32, 8)           \
  X(frusta_world_state, step_us_p99, 40, 8)           \
  X(frusta_world_state, step_us_max, 48, 8)           \
  X(frusta_world_state, wake_late_us_p50, 56, 8)      \
  X(frusta_world_state, wake_late_us_p99, 64, 8)      \
  X(frusta_world_state, wake_late_us_max, 72, 8)      \
  X(frusta_world_state, achieved_rate_hz, 80, 8)      \
  X(frusta_world_state, overruns, 88, 8)              \
  X(frusta_world_state, rejected_inputs, 96, 8)       \
  X(frusta_world_state, object_count, 104, 4)         \
  X(frusta_world_state, realtime, 108, 4)             \
  X(frusta_world_hand, struct_size, 0, 4)             \
  X(frusta_world_hand, solved, 4, 4)                  \
  X(frusta_world_hand, graphic_palm, 8, 56)           \
  X(frusta_world_hand, graphic_angles, 64, 160)       \
  X(frusta_world_hand, haptic_palm, 224, 56)          \
  X(frusta_world_hand, haptic_angles, 280, 160)       \
  X(frusta_world_hand, contact_count, 440, 4)         \
  X(frusta_world_hand, pressing, 444, 4)              \
  X(frusta_world_hand, slipping, 448, 4)              \
  X(frusta_world_hand, substeps, 452, 4)              \
  X(frusta_world_hand, lagging, 456, 4)               \
  X(frusta_world_hand, infeasible, 460, 4)            \
  X(frusta_world_hand, ignored_objects, 464, 4)       \
  X(frusta_world_hand, input_late, 468, 4)            \
  X(frusta_world_hand, fingertip_force, 472, 120)     \
  X(frusta_world_hand, finger_resistance, 592, 40)    \
  X(frusta_world_hand, joint_torque, 632, 160)        \
  X(frusta_world_hand, palm_force, 792, 24)           \
  X(frusta_world_hand, palm_torque, 816, 24)          \
  X(frusta_world_contact, object, 0, 8)               \
  X(frusta_world_contact, body, 8, 4)                 \
  X(frusta_world_contact, leaf, 12, 4)                \
  X(frusta_world_contact, slipping, 16, 4)            \
  X(frusta_world_contact, reserved0, 20, 4)           \
  X(frusta_world_contact, distance, 24, 8)            \
  X(frusta_world_contact, graphic_point, 32, 24)      \
  X(frusta_world_contact, haptic_point, 56, 24)       \
  X(frusta_world_contact, normal, 80, 24)             \
  X(frusta_world_contact, normal_force, 104, 24)      \
  X(frusta_world_contact, friction, 128, 24)          \
  X(frusta_object_state, struct_size, 0, 4)           \
  X(frusta_object_state, dynamic, 4, 4)               \
  X(frusta_object_state, pose, 8, 56)                 \
  X(frusta_object_state, linear_velocity, 64, 24)     \
  X(frusta_object_state, angular_velocity, 88, 24)    \
  X(frusta_object_state, reaction_force, 112, 24)     \
  X(frusta_object_state, reaction_torque, 136, 24) \
  X(frusta_object_state, ignoring_hands, 160, 4) \
  X(frusta_object_state, held, 164, 4) \
  X(frusta_device_id, index1, 0, 4) \
  X(frusta_device_id, world0, 4, 2) \
  X(frusta_device_id, generation, 6, 2) \
  X(frusta_device_def, struct_size, 0, 4) \
  X(frusta_device_def, hand, 4, 8) \
  X(frusta_device_def, reserved1, 12, 4) \
  X(frusta_device_def, output_rate_hz, 16, 8) \
  X(frusta_device_def, watchdog_s, 24, 8) \
  X(frusta_device_def, engine_timeout_s, 32, 8) \
  X(frusta_device_def, host_timeout_s, 40, 8) \
  X(frusta_device_def, reconnect_interval_s, 48, 8) \
  X(frusta_device_def, max_force_rate, 56, 8) \
  X(frusta_device_def, max_torque_rate, 64, 8) \
  X(frusta_device_def, max_finger_resistance, 72, 8) \
  X(frusta_device_def, max_fingertip_force, 80, 8) \
  X(frusta_device_def, max_joint_torque, 88, 8) \
  X(frusta_device_def, curl_open, 96, 120) \
  X(frusta_device_def, curl_closed, 216, 120) \
  X(frusta_device_def, flexion_open, 336, 120) \
  X(frusta_device_def, flexion_closed, 456, 120) \
  X(frusta_device_def, splay_center, 576, 40) \
  X(frusta_device_def, splay_span, 616, 40) \
  X(frusta_device_def, abduction_range, 656, 40) \
  X(frusta_device_def, brake_full_scale, 696, 8) \
  X(frusta_device_def, brake_units, 704, 8) \
  X(frusta_device_def, analog_max, 712, 8) \
  X(frusta_device_def, internal_value, 720, 4) \
  X(frusta_device_def, reserved0, 724, 4) \
  X(frusta_device_status, struct_size, 0, 4) \
  X(frusta_device_status, state, 4, 4) \
  X(frusta_device_status, watchdog, 8, 4) \
  X(frusta_device_status, outputs, 12, 4) \
  X(frusta_device_status, fingers, 16, 4) \
  X(frusta_device_status, has_palm_pose, 20, 4) \
  X(frusta_device_status, protocol_version, 24, 4) \
  X(frusta_device_status, recording_failed, 28, 4) \
  X(frusta_device_status, frames_ok, 32, 8) \
  X(frusta_device_status, frames_corrupt, 40, 8) \
  X(frusta_device_status, frames_truncated, 48, 8) \
  X(frusta_device_status, frames_out_of_range, 56, 8) \
  X(frusta_device_status, samples_rejected, 64, 8) \
  X(frusta_device_status, commands_sent, 72, 8) \
  X(frusta_device_status, commands_dropped, 80, 8) \
  X(frusta_device_status, reconnects, 88, 8) \
  X(frusta_device_status, disconnects, 96, 8) \
  X(frusta_device_status, watchdog_trips, 104, 8) \
  X(frusta_device_status, input_rate_hz, 112, 8) \
  X(frusta_device_status, output_rate_hz, 120, 8) \
  X(frusta_device_status, last_sample_age_s, 128, 8) \
  X(frusta_device_status, max_finger_resistance, 136, 8) \
  X(frusta_device_status, max_fingertip_force, 144, 8) \
  X(frusta_device_status, max_joint_torque, 152, 8) \
  X(frusta_device_status, finger_resistance, 160, 40) \
  X(frusta_device_status, fingertip_force, 200, 120) \
  X(frusta_device_info, kind, 0, 4) \
  X(frusta_device_info, vendor_id, 4, 4) \
  X(frusta_device_info, product_id, 8, 4) \
  X(frusta_device_info, uri, 12, 256)

// X(struct, sizeof, alignof)
#define FRUSTA_ABI_STRUCTS(X)        \
  X(frusta_hand_id, 8, 4)            \
  X(frusta_pose, 56, 8)              \
  X(frusta_sphere, 32, 8)            \
  X(frusta_segment, 64, 8)           \
  X(frusta_hand_def, 896, 8)         \
  X(frusta_tracked_joint, 72, 8)     \
  X(frusta_hand_fitter_id, 8, 4)     \
  X(frusta_hand_fit_def, 56, 8)      \
  X(frusta_hand_fit, 296, 8)         \
  X(frusta_contact_query, 104, 8)    \
  X(frusta_constraint, 88, 8)        \
  X(frusta_tree_id, 8, 4)            \
  X(frusta_bake_def, 56, 8)          \
  X(frusta_bake_job_id, 8, 4)        \
  X(frusta_sphere_tree_info, 120, 8) \
  X(frusta_tree_hit, 40, 8)          \
  X(frusta_world_id, 8, 4)           \
  X(frusta_object_id, 8, 4)          \
  X(frusta_world_def, 152, 8)        \
  X(frusta_object_def, 224, 8)       \
  X(frusta_world_state, 112, 8)      \
  X(frusta_world_hand, 840, 8)       \
  X(frusta_world_contact, 152, 8)    \
  X(frusta_object_state, 168, 8) \
  X(frusta_device_id, 8, 4) \
  X(frusta_device_def, 728, 8) \
  X(frusta_device_status, 320, 8) \
  X(frusta_device_info, 268, 4)

static_assert(FRUSTA_ABI_VERSION == 9,
              "the layout table below is ABI 9: update it and the C# mirror with the ABI");

#define FRUSTA_CHECK_MEMBER(type, member, offset, size)                          \
  static_assert(offsetof(type, member) == (offset), #type "." #member " moved"); \
  static_assert(sizeof(type::member) == (size), #type "." #member " changed size");
FRUSTA_ABI_MEMBERS(FRUSTA_CHECK_MEMBER)
#undef FRUSTA_CHECK_MEMBER

#define FRUSTA_CHECK_STRUCT(type, size, align)                                         \
  static_assert(sizeof(type) == (size), "sizeof(" #type ") changed");                  \
  static_assert(alignof(type) == (align), "alignof(" #type ") changed");               \
  static_assert(std::is_standard_layout_v<type> && std::is_trivially_copyable_v<type>, \
                #type " must stay a plain C struct");
FRUSTA_ABI_STRUCTS(FRUSTA_CHECK_STRUCT)
#undef FRUSTA_CHECK_STRUCT

// enums travel as int32_t (in structs) and as the return value
static_assert(sizeof(frusta_result) == 4 && sizeof(frusta_hand_side) == 4 &&
                  sizeof(frusta_finger) == 4 && sizeof(frusta_feature) == 4 &&
                  sizeof(frusta_constraint_form) == 4 && sizeof(frusta_device_output) == 4 &&
                  sizeof(frusta_device_state) == 4 && sizeof(frusta_watchdog_reason) == 4 &&
                  sizeof(frusta_device_kind) == 4 && sizeof(frusta_joint_layout) == 4 &&
                  sizeof(frusta_joint_flag) == 4 && sizeof(frusta_fit_flag) == 4 &&
                  sizeof(frusta_hand_kind) == 4,
              "enums must be 32-bit");

// ---------------------------------------------------------------- values
static_assert(FRUSTA_OK == 0 && FRUSTA_ERROR_NULL_POINTER == 1 && FRUSTA_ERROR_STRUCT_SIZE == 2 &&
              FRUSTA_ERROR_DEF_NOT_DEFAULTED == 3 && FRUSTA_ERROR_NULL_ID == 4 &&
              FRUSTA_ERROR_STALE_ID == 5 && FRUSTA_ERROR_NOT_FINITE == 6 &&
              FRUSTA_ERROR_OUT_OF_RANGE == 7 && FRUSTA_ERROR_CAPACITY == 8 &&
              FRUSTA_ERROR_ABI_MISMATCH == 9 && FRUSTA_ERROR_OUT_OF_MEMORY == 10 &&
              FRUSTA_ERROR_INTERNAL == 11 && FRUSTA_ERROR_IO == 12 &&
              FRUSTA_ERROR_FILE_FORMAT == 13 && FRUSTA_ERROR_CORRUPT_FILE == 14 &&
              FRUSTA_ERROR_WRONG_STATE == 15 && FRUSTA_ERROR_UNAVAILABLE == 16 &&
              FRUSTA_ERROR_CANCELLED == 17);
static_assert(FRUSTA_HAND_RIGHT == 0 && FRUSTA_HAND_LEFT == 1);
static_assert(FRUSTA_FINGER_THUMB == 0 && FRUSTA_FINGER_INDEX == 1 && FRUSTA_FINGER_MIDDLE == 2 &&
              FRUSTA_FINGER_RING == 3 && FRUSTA_FINGER_LITTLE == 4);
static_assert(FRUSTA_DEVICE_OUTPUT_FINGER_RESISTANCE == 1 && FRUSTA_DEVICE_OUTPUT_FINGERTIP_FORCE == 2 &&
              FRUSTA_DEVICE_OUTPUT_JOINT_TORQUE == 4);
static_assert(FRUSTA_DEVICE_CONNECTED == 1 && FRUSTA_DEVICE_DISCONNECTED == 2 &&
              FRUSTA_DEVICE_CLOSED == 3);
static_assert(FRUSTA_WATCHDOG_NONE == 0 && FRUSTA_WATCHDOG_INPUT_STALLED == 1 &&
              FRUSTA_WATCHDOG_DISCONNECTED == 2 && FRUSTA_WATCHDOG_ENGINE_STALLED == 3 &&
              FRUSTA_WATCHDOG_HOST_STALLED == 4);
static_assert(FRUSTA_DEVICE_KIND_SERIAL == 1 && FRUSTA_DEVICE_KIND_HID == 2 &&
              FRUSTA_DEVICE_KIND_USB == 3);
static_assert(FRUSTA_JOINT_LAYOUT_XR == 0 && FRUSTA_JOINT_LAYOUT_KEYPOINTS == 1);
// OpenXR's XrSpaceLocationFlags bits, so that locationFlags pass as they are
static_assert(FRUSTA_JOINT_ORIENTATION_VALID == 1 && FRUSTA_JOINT_POSITION_VALID == 2 &&
              FRUSTA_JOINT_ORIENTATION_TRACKED == 4 && FRUSTA_JOINT_POSITION_TRACKED == 8);
static_assert(FRUSTA_FIT_HELD == 1 && FRUSTA_FIT_PARTIAL == 2 && FRUSTA_FIT_CLAMPED == 4 &&
              FRUSTA_FIT_NO_HISTORY == 8 && FRUSTA_FIT_ORIENTATION == 16);
static_assert(FRUSTA_XR_JOINT_COUNT == 26 && FRUSTA_KEYPOINT_COUNT == 21);
static_assert(FRUSTA_FEATURE_SIDE == 0 && FRUSTA_FEATURE_DISTAL == 1 &&
              FRUSTA_FEATURE_PROXIMAL == 2);
static_assert(FRUSTA_CONSTRAINT_SQUARED == 0 && FRUSTA_CONSTRAINT_DISTANCE == 1);
static_assert(FRUSTA_HAND_KIND_GRAPHIC == 0 && FRUSTA_HAND_KIND_HAPTIC == 1);
static_assert(FRUSTA_FINGER_COUNT == 5 && FRUSTA_SEGMENTS_PER_FINGER == 3 &&
              FRUSTA_JOINTS_PER_FINGER == 4 && FRUSTA_HAND_SEGMENT_COUNT == 15 &&
              FRUSTA_HAND_JOINT_COUNT == 20 && FRUSTA_PALM_DOF == 6 &&
              FRUSTA_POINT_JACOBIAN_LENGTH == 30);
static_assert(FRUSTA_VERSION ==
              FRUSTA_VERSION_MAJOR * 1000000 + FRUSTA_VERSION_MINOR * 1000 + FRUSTA_VERSION_PATCH);

// ---------------------------------------------------------------- signatures
#define FRUSTA_CHECK_SIGNATURE(function, type) \
  static_assert(std::is_same_v<decltype(&function), type>, #function " changed signature");
FRUSTA_CHECK_SIGNATURE(frusta_version, int32_t (*)())
FRUSTA_CHECK_SIGNATURE(frusta_abi_version, int32_t (*)())
FRUSTA_CHECK_SIGNATURE(frusta_last_error, const char* (*)())
FRUSTA_CHECK_SIGNATURE(frusta_result_name, const char* (*)(int32_t))
FRUSTA_CHECK_SIGNATURE(frusta_check_abi, frusta_result (*)(int32_t))
FRUSTA_CHECK_SIGNATURE(frusta_struct_size, int32_t (*)(const char*))
FRUSTA_CHECK_SIGNATURE(frusta_default_hand_def, frusta_hand_def (*)())
FRUSTA_CHECK_SIGNATURE(frusta_hand_def_set_size,
                       frusta_result (*)(frusta_hand_def*, double, double))
FRUSTA_CHECK_SIGNATURE(frusta_create_hand,
                       frusta_result (*)(const frusta_hand_def*, frusta_hand_id*))
FRUSTA_CHECK_SIGNATURE(frusta_destroy_hand, frusta_result (*)(frusta_hand_id))
FRUSTA_CHECK_SIGNATURE(frusta_hand_is_valid, int32_t (*)(frusta_hand_id))
FRUSTA_CHECK_SIGNATURE(frusta_hand_set_palm_pose,
                       frusta_result (*)(frusta_hand_id, const frusta_pose*))
FRUSTA_CHECK_SIGNATURE(frusta_hand_set_joint_angles,
                       frusta_result (*)(frusta_hand_id, const double*, int32_t))
FRUSTA_CHECK_SIGNATURE(frusta_hand_get_joint_angles,
                       frusta_result (*)(frusta_hand_id, double*, int32_t, int32_t*))
FRUSTA_CHECK_SIGNATURE(frusta_hand_get_segments,
                       frusta_result (*)(frusta_hand_id, frusta_segment*, int32_t, int32_t*))
FRUSTA_CHECK_SIGNATURE(frusta_hand_get_palm_spheres,
                       frusta_result (*)(frusta_hand_id, frusta_sphere*, int32_t, int32_t*))
FRUSTA_CHECK_SIGNATURE(frusta_hand_point_jacobian,
                       frusta_result (*)(frusta_hand_id, int32_t, int32_t, const double*, double*,
                                         double*, int32_t, int32_t*))
FRUSTA_CHECK_SIGNATURE(frusta_default_hand_fit_def, frusta_hand_fit_def (*)())
FRUSTA_CHECK_SIGNATURE(frusta_create_hand_fitter,
                       frusta_result (*)(const frusta_hand_def*, const frusta_hand_fit_def*,
                                         frusta_hand_fitter_id*))
FRUSTA_CHECK_SIGNATURE(frusta_destroy_hand_fitter, frusta_result (*)(frusta_hand_fitter_id))
FRUSTA_CHECK_SIGNATURE(frusta_hand_fitter_is_valid, int32_t (*)(frusta_hand_fitter_id))
FRUSTA_CHECK_SIGNATURE(frusta_hand_fitter_fit,
                       frusta_result (*)(frusta_hand_fitter_id, const frusta_tracked_joint*,
                                         int32_t, const frusta_pose*, frusta_hand_fit*))
FRUSTA_CHECK_SIGNATURE(frusta_hand_fitter_fit_at,
                       frusta_result (*)(frusta_hand_fitter_id, double, const frusta_tracked_joint*,
                                         int32_t, const frusta_pose*, frusta_hand_fit*))
FRUSTA_CHECK_SIGNATURE(frusta_hand_joints_from_pose,
                       frusta_result (*)(const frusta_hand_def*, int32_t, const frusta_pose*,
                                         const double*, int32_t, frusta_tracked_joint*, int32_t,
                                         int32_t*))
FRUSTA_CHECK_SIGNATURE(frusta_calibrate_hand_def,
                       frusta_result (*)(const frusta_tracked_joint*, int32_t, int32_t,
                                         frusta_hand_def*))
FRUSTA_CHECK_SIGNATURE(frusta_query_contact,
                       frusta_result (*)(const frusta_segment*, const frusta_sphere*,
                                         frusta_contact_query*))
FRUSTA_CHECK_SIGNATURE(frusta_constraint_eval,
                       frusta_result (*)(const frusta_segment*, const frusta_sphere*, int32_t,
                                         frusta_constraint*))
FRUSTA_CHECK_SIGNATURE(frusta_default_bake_def, frusta_bake_def (*)())
FRUSTA_CHECK_SIGNATURE(frusta_create_sphere_tree_from_mesh,
                       frusta_result (*)(const float*, int32_t, const int32_t*, int32_t,
                                         const frusta_bake_def*, frusta_tree_id*))
FRUSTA_CHECK_SIGNATURE(frusta_create_sphere_tree_from_file,
                       frusta_result (*)(const char*, frusta_tree_id*))
FRUSTA_CHECK_SIGNATURE(frusta_create_sphere_tree_from_memory,
                       frusta_result (*)(const void*, int64_t, frusta_tree_id*))
FRUSTA_CHECK_SIGNATURE(frusta_start_bake,
                       frusta_result (*)(const float*, int32_t, const int32_t*, int32_t,
                                         const frusta_bake_def*, frusta_bake_job_id*))
FRUSTA_CHECK_SIGNATURE(frusta_bake_job_progress,
                       frusta_result (*)(frusta_bake_job_id, double*, int32_t*))
FRUSTA_CHECK_SIGNATURE(frusta_cancel_bake_job, frusta_result (*)(frusta_bake_job_id))
FRUSTA_CHECK_SIGNATURE(frusta_finish_bake_job, frusta_result (*)(frusta_bake_job_id, frusta_tree_id*))
FRUSTA_CHECK_SIGNATURE(frusta_destroy_sphere_tree, frusta_result (*)(frusta_tree_id))
FRUSTA_CHECK_SIGNATURE(frusta_sphere_tree_save, frusta_result (*)(frusta_tree_id, const char*))
FRUSTA_CHECK_SIGNATURE(frusta_sphere_tree_is_valid, int32_t (*)(frusta_tree_id))
FRUSTA_CHECK_SIGNATURE(frusta_sphere_tree_get_info,
                       frusta_result (*)(frusta_tree_id, frusta_sphere_tree_info*))
FRUSTA_CHECK_SIGNATURE(frusta_sphere_tree_get_leaves,
                       frusta_result (*)(frusta_tree_id, frusta_sphere*, int32_t, int32_t*))
FRUSTA_CHECK_SIGNATURE(frusta_sphere_tree_query_segment,
                       frusta_result (*)(frusta_tree_id, const frusta_pose*, const frusta_segment*,
                                         double, int32_t, frusta_tree_hit*, int32_t, int32_t*))
FRUSTA_CHECK_SIGNATURE(frusta_default_world_def, frusta_world_def (*)())
FRUSTA_CHECK_SIGNATURE(frusta_default_object_def, frusta_object_def (*)())
FRUSTA_CHECK_SIGNATURE(frusta_create_world,
                       frusta_result (*)(const frusta_world_def*, frusta_world_id*))
FRUSTA_CHECK_SIGNATURE(frusta_destroy_world, frusta_result (*)(frusta_world_id))
FRUSTA_CHECK_SIGNATURE(frusta_world_is_valid, int32_t (*)(frusta_world_id))
FRUSTA_CHECK_SIGNATURE(frusta_create_world_hand,
                       frusta_result (*)(frusta_world_id, const frusta_hand_def*, frusta_hand_id*))
FRUSTA_CHECK_SIGNATURE(frusta_destroy_world_hand, frusta_result (*)(frusta_hand_id))
FRUSTA_CHECK_SIGNATURE(frusta_world_set_haptic,
                       frusta_result (*)(frusta_world_id, frusta_hand_id, const frusta_pose*,
                                         const double*, int32_t))
FRUSTA_CHECK_SIGNATURE(frusta_world_set_haptic_at,
                       frusta_result (*)(frusta_world_id, frusta_hand_id, double,
                                         const frusta_pose*, const double*, int32_t))
FRUSTA_CHECK_SIGNATURE(frusta_now, double (*)(void))
FRUSTA_CHECK_SIGNATURE(frusta_create_object,
                       frusta_result (*)(frusta_world_id, frusta_tree_id, const frusta_object_def*,
                                         frusta_object_id*))
FRUSTA_CHECK_SIGNATURE(frusta_destroy_object, frusta_result (*)(frusta_object_id))
FRUSTA_CHECK_SIGNATURE(frusta_world_set_object_pose,
                       frusta_result (*)(frusta_world_id, frusta_object_id, const frusta_pose*))
FRUSTA_CHECK_SIGNATURE(frusta_world_set_object_dynamic,
                       frusta_result (*)(frusta_world_id, frusta_object_id, int32_t))
FRUSTA_CHECK_SIGNATURE(frusta_world_step, frusta_result (*)(frusta_world_id))
FRUSTA_CHECK_SIGNATURE(frusta_world_start, frusta_result (*)(frusta_world_id))
FRUSTA_CHECK_SIGNATURE(frusta_world_stop, frusta_result (*)(frusta_world_id))
FRUSTA_CHECK_SIGNATURE(frusta_world_read,
                       frusta_result (*)(frusta_world_id, frusta_world_state*))
FRUSTA_CHECK_SIGNATURE(frusta_world_get_hand,
                       frusta_result (*)(frusta_world_id, frusta_hand_id, frusta_world_hand*))
FRUSTA_CHECK_SIGNATURE(frusta_world_get_contacts,
                       frusta_result (*)(frusta_world_id, frusta_hand_id, frusta_world_contact*,
                                         int32_t, int32_t*))
FRUSTA_CHECK_SIGNATURE(frusta_world_get_object,
                       frusta_result (*)(frusta_world_id, frusta_object_id, frusta_object_state*))
FRUSTA_CHECK_SIGNATURE(frusta_world_get_object_ignored_by,
                       frusta_result (*)(frusta_world_id, frusta_object_id, frusta_hand_id,
                                         int32_t*))
FRUSTA_CHECK_SIGNATURE(frusta_world_get_hand_segments,
                       frusta_result (*)(frusta_world_id, frusta_hand_id, int32_t, frusta_segment*,
                                         int32_t, int32_t*))
FRUSTA_CHECK_SIGNATURE(frusta_world_get_hand_palm_spheres,
                       frusta_result (*)(frusta_world_id, frusta_hand_id, int32_t, frusta_sphere*,
                                         int32_t, int32_t*))
FRUSTA_CHECK_SIGNATURE(frusta_default_device_def, frusta_device_def (*)())
FRUSTA_CHECK_SIGNATURE(frusta_enumerate_devices,
                       frusta_result (*)(frusta_device_info*, int32_t, int32_t*))
FRUSTA_CHECK_SIGNATURE(frusta_create_device,
                       frusta_result (*)(frusta_world_id, const char*, const frusta_device_def*,
                                         frusta_device_id*))
FRUSTA_CHECK_SIGNATURE(frusta_destroy_device, frusta_result (*)(frusta_device_id))
FRUSTA_CHECK_SIGNATURE(frusta_device_is_valid, int32_t (*)(frusta_device_id))
FRUSTA_CHECK_SIGNATURE(frusta_device_get_status,
                       frusta_result (*)(frusta_device_id, frusta_device_status*))
FRUSTA_CHECK_SIGNATURE(frusta_device_set_palm_pose,
                       frusta_result (*)(frusta_device_id, const frusta_pose*))
#undef FRUSTA_CHECK_SIGNATURE

namespace {

struct Member {
  const char* type;
  const char* name;
  size_t offset, size;
  size_t declared_offset, declared_size;  // what the compiler says
};
struct Struct {
  const char* type;
  size_t size, declared_size;
};

#define FRUSTA_MEMBER_ROW(type, member, offset, size) \
  Member{#type, #member, offset, size, offsetof(type, member), sizeof(type::member)},
constexpr Member kMembers[] = {FRUSTA_ABI_MEMBERS(FRUSTA_MEMBER_ROW)};
#undef FRUSTA_MEMBER_ROW
#define FRUSTA_STRUCT_ROW(type, size, align) Struct{#type, size, sizeof(type)},
constexpr Struct kStructs[] = {FRUSTA_ABI_STRUCTS(FRUSTA_STRUCT_ROW)};
#undef FRUSTA_STRUCT_ROW

TEST(abiLayout, VersionMacroMatchesTheLibrary) {
  EXPECT_EQ(FRUSTA_VERSION, frusta_version());
  EXPECT_EQ(FRUSTA_ABI_VERSION, frusta_abi_version());
  EXPECT_EQ(FRUSTA_CHECK_ABI(), FRUSTA_OK);
}

// Every struct is its members back to back: no implicit padding for a mirror to
// guess, and the table lists every member (a forgotten one shows up as a gap). The
// table is printed for whoever writes the binding's mirror.
TEST(abiLayout, StructsHaveNoImplicitPaddingAndTheTableIsComplete) {
  for (const Struct& s : kStructs) {
    std::printf("%-22s sizeof %3zu\n", s.type, s.declared_size);
    size_t end = 0;
    int members = 0;
    for (const Member& m : kMembers) {
      if (std::string(m.type) != s.type) continue;
      std::printf("  %-16s offset %3zu size %3zu\n", m.name, m.declared_offset, m.declared_size);
      EXPECT_EQ(m.offset, end) << s.type << "." << m.name << " does not follow the previous member";
      end = m.offset + m.size;
      ++members;
    }
    EXPECT_GT(members, 0) << s.type;
    EXPECT_EQ(end, s.size) << s.type << " has trailing padding or an unlisted member";
  }
}

// struct_size fields hold the library's sizeof, as every binding will send it.
TEST(abiLayout, DefaultDefCarriesItsSize) {
  EXPECT_EQ(frusta_default_hand_def().struct_size, 896);
  EXPECT_EQ(frusta_default_bake_def().struct_size, 56);
  EXPECT_EQ(frusta_default_world_def().struct_size, 152);
  EXPECT_EQ(frusta_default_object_def().struct_size, 224);
  EXPECT_EQ(frusta_default_device_def().struct_size, 728);
  EXPECT_EQ(frusta_default_hand_fit_def().struct_size, 56);
}

// Bindings learn the native sizes at load from frusta_struct_size; it must know every
// struct the header declares, with the size the table freezes.
TEST(abiLayout, StructSizeReportsEveryStructOfTheHeader) {
  std::ifstream header(FRUSTA_HEADER_PATH);
  ASSERT_TRUE(header) << FRUSTA_HEADER_PATH;
  const std::string text((std::istreambuf_iterator<char>(header)), {});
  const std::regex declaration(R"(\}\s*(frusta_[a-z_0-9]+)\s*;)");
  std::set<std::string> declared;
  for (std::sregex_iterator it(text.begin(), text.end(), declaration), end; it != end; ++it) {
    declared.insert((*it)[1]);
  }
  std::set<std::string> tabled;
  for (const Struct& s : kStructs) {
    tabled.insert(s.type);
    EXPECT_EQ(frusta_struct_size(s.type), static_cast<int32_t>(s.size)) << s.type;
  }
  for (const std::string& name : declared) {
    if (frusta_struct_size(name.c_str()) == 0) {
      // enums are the only other `} frusta_x;` declarations
      EXPECT_NE(text.find("typedef enum " + name), std::string::npos) << name << " is not reported";
    } else {
      EXPECT_TRUE(tabled.count(name)) << name << " is missing from the layout table";
    }
  }
  EXPECT_EQ(frusta_struct_size("frusta_no_such_struct"), 0);
  EXPECT_EQ(frusta_struct_size(""), 0);
  EXPECT_EQ(frusta_struct_size(nullptr), 0);
}

}  // namespace
