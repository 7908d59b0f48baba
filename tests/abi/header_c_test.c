/* SPDX-License-Identifier: MIT */
/*
 * header_c_test: the public header compiled as C11 and every entry point of the
 * shared library called from C, as a C host (or a P/Invoke binding) calls it.
 *
 * Each check prints one line, "ok   ..." or "FAIL ...", and the last line is
 * "N passed, M failed"; the exit status is non-zero when anything failed.
 * Error paths check three things: the result code, a thread-local message that
 * names the field (and, where it is a number, the value) at fault, and that the
 * state the call would have changed is byte-for-byte unchanged.
 *
 * Only frusta/frusta.h and the C standard library (plus pthreads for the
 * thread-local error check) are used here; nothing from native/src. The sphere-tree
 * section bakes a 5 cm cube and writes two small files into the working directory,
 * removing them afterwards.
 */
#define _POSIX_C_SOURCE 200809L /* pthreads under -std=c11 */

#include <math.h>
#include <pthread.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "c_check.h"
#include "frusta/frusta.h"

/* The C compiler must lay the structs out as the C++ library does; the full
 * offset table lives in abi_layout_test.cpp, these are its sizes. */
_Static_assert(sizeof(frusta_hand_id) == 8, "frusta_hand_id layout changed");
_Static_assert(sizeof(frusta_pose) == 56, "frusta_pose layout changed");
_Static_assert(sizeof(frusta_sphere) == 32, "frusta_sphere layout changed");
_Static_assert(sizeof(frusta_segment) == 64, "frusta_segment layout changed");
_Static_assert(sizeof(frusta_hand_def) == 896, "frusta_hand_def layout changed");
_Static_assert(offsetof(frusta_hand_def, internal_value) == 888, "frusta_hand_def layout changed");
_Static_assert(sizeof(frusta_contact_query) == 104, "frusta_contact_query layout changed");
_Static_assert(sizeof(frusta_constraint) == 88, "frusta_constraint layout changed");
_Static_assert(sizeof(frusta_tree_id) == 8, "frusta_tree_id layout changed");
_Static_assert(sizeof(frusta_bake_def) == 56, "frusta_bake_def layout changed");
_Static_assert(sizeof(frusta_sphere_tree_info) == 120, "frusta_sphere_tree_info layout changed");
_Static_assert(sizeof(frusta_tree_hit) == 40, "frusta_tree_hit layout changed");
_Static_assert(sizeof(frusta_result) == 4, "frusta_result must be 32-bit");


/* ------------------------------------------------------------------ hand state */

#define MAX_PALM_SPHERES 1024

/* Everything a hand call could change, read through the ABI. */
typedef struct snapshot {
  double angles[FRUSTA_HAND_JOINT_COUNT];
  frusta_segment segments[FRUSTA_HAND_SEGMENT_COUNT];
  frusta_sphere palm[MAX_PALM_SPHERES];
  int32_t palm_count;
  double jacobian[FRUSTA_POINT_JACOBIAN_LENGTH];
} snapshot;

static snapshot g_before, g_after; /* static: they are large */

static int take_snapshot(frusta_hand_id hand, snapshot* s) {
  static const double kLocal[3] = {0.01, 0.002, -0.003};
  int32_t count = 0, other = 0;
  memset(s, 0, sizeof *s);
  if (frusta_hand_get_joint_angles(hand, s->angles, FRUSTA_HAND_JOINT_COUNT, &other) != FRUSTA_OK)
    return 0;
  if (frusta_hand_get_segments(hand, s->segments, FRUSTA_HAND_SEGMENT_COUNT, &count) != FRUSTA_OK)
    return 0;
  if (frusta_hand_get_palm_spheres(hand, s->palm, MAX_PALM_SPHERES, &s->palm_count) != FRUSTA_OK)
    return 0;
  if (frusta_hand_point_jacobian(hand, FRUSTA_FINGER_INDEX, 2, kLocal, NULL, s->jacobian,
                                 FRUSTA_POINT_JACOBIAN_LENGTH, &other) != FRUSTA_OK)
    return 0;
  return count == FRUSTA_HAND_SEGMENT_COUNT;
}

/* Snapshot the hand, so that expect_unchanged() can compare after a failing call. */
static void remember(frusta_hand_id hand) {
  if (!take_snapshot(hand, &g_before)) check(0, "snapshot before: %s", frusta_last_error());
}

static void expect_unchanged(frusta_hand_id hand, const char* what) {
  /* reading the state must not touch the message under test: read it after */
  const int read = take_snapshot(hand, &g_after);
  check(read && memcmp(&g_before, &g_after, sizeof g_before) == 0,
        "%s: hand state (angles, segments, palm, Jacobian) unchanged", what);
}

/* ------------------------------------------------------------------ sections */

static void test_version_and_abi(void) {
  check(frusta_version() == FRUSTA_VERSION, "frusta_version() %d == FRUSTA_VERSION %d",
        frusta_version(), FRUSTA_VERSION);
  check(FRUSTA_VERSION ==
            FRUSTA_VERSION_MAJOR * 1000000 + FRUSTA_VERSION_MINOR * 1000 + FRUSTA_VERSION_PATCH,
        "FRUSTA_VERSION is major*1000000 + minor*1000 + patch");
  check(frusta_abi_version() == FRUSTA_ABI_VERSION, "frusta_abi_version() %d == %d",
        frusta_abi_version(), FRUSTA_ABI_VERSION);
  expect_ok("FRUSTA_CHECK_ABI()", FRUSTA_CHECK_ABI());

  char header[32], library[32];
  snprintf(header, sizeof header, "ABI %d", FRUSTA_ABI_VERSION + 1);
  snprintf(library, sizeof library, "ABI %d", FRUSTA_ABI_VERSION);
  const frusta_result r = frusta_check_abi(FRUSTA_ABI_VERSION + 1);
  expect_error("frusta_check_abi(FRUSTA_ABI_VERSION + 1)", r, FRUSTA_ERROR_ABI_MISMATCH, header,
               library);
  expect_error("frusta_check_abi(0)", frusta_check_abi(0), FRUSTA_ERROR_ABI_MISMATCH, "ABI 0",
               library);
}

static void test_result_names(void) {
  static const char* const kNames[] = {"FRUSTA_OK",
                                       "FRUSTA_ERROR_NULL_POINTER",
                                       "FRUSTA_ERROR_STRUCT_SIZE",
                                       "FRUSTA_ERROR_DEF_NOT_DEFAULTED",
                                       "FRUSTA_ERROR_NULL_ID",
                                       "FRUSTA_ERROR_STALE_ID",
                                       "FRUSTA_ERROR_NOT_FINITE",
                                       "FRUSTA_ERROR_OUT_OF_RANGE",
                                       "FRUSTA_ERROR_CAPACITY",
                                       "FRUSTA_ERROR_ABI_MISMATCH",
                                       "FRUSTA_ERROR_OUT_OF_MEMORY",
                                       "FRUSTA_ERROR_INTERNAL",
                                       "FRUSTA_ERROR_IO",
                                       "FRUSTA_ERROR_FILE_FORMAT",
                                       "FRUSTA_ERROR_CORRUPT_FILE",
                                       "FRUSTA_ERROR_WRONG_STATE",
                                       "FRUSTA_ERROR_UNAVAILABLE",
                                       "FRUSTA_ERROR_CANCELLED"};
  const int count = (int)(sizeof kNames / sizeof kNames[0]);
  check(FRUSTA_ERROR_CANCELLED == count - 1, "result codes are 0..%d", count - 1);
  for (int32_t code = 0; code < count; ++code) {
    const char* name = frusta_result_name(code);
    check(name && strcmp(name, kNames[code]) == 0, "frusta_result_name(%d) = %s", code,
          name ? name : "(null)");
  }
  const int32_t unknown[] = {-1, count, 1000};
  for (int i = 0; i < 3; ++i) {
    const char* name = frusta_result_name(unknown[i]);
    int known = 0;
    for (int k = 0; k < count && name; ++k) known |= strcmp(name, kNames[k]) == 0;
    check(name && name[0] && !known, "frusta_result_name(%d) = %s (not a known code's name)",
          unknown[i], name ? name : "(null)");
  }
}

static void test_default_def(void) {
  const frusta_hand_def def = frusta_default_hand_def();
  check(def.struct_size == (int32_t)sizeof(frusta_hand_def), "default def struct_size %d",
        def.struct_size);
  check(def.side == FRUSTA_HAND_RIGHT, "default def is a right hand");
  check(def.hand_length == 0.19 && def.hand_breadth == 0.085,
        "default def is 0.19 m long and 0.085 m broad (%g, %g)", def.hand_length, def.hand_breadth);
  check(def.internal_value != 0, "default def carries its cookie");
  int positive = def.palm_length > 0 && def.palm_breadth > 0 && def.palm_thickness > 0;
  int ordered = 1;
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s) positive &= def.segment_length[f][s] > 0;
    for (int j = 0; j < 4; ++j) positive &= def.joint_radius[f][j] > 0;
    for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) {
      ordered &= def.joint_min[f][j] < def.joint_max[f][j];
      ordered &= def.joint_min[f][j] <= 0.0 && def.joint_max[f][j] >= 0.0; /* 0 is a pose */
    }
  }
  check(positive, "default def: every length and radius > 0");
  check(ordered, "default def: joint_min < joint_max and 0 within every range");
  const frusta_hand_def again = frusta_default_hand_def();
  check(memcmp(&def, &again, sizeof def) == 0, "frusta_default_hand_def() is deterministic");
}

/* A field of the def to corrupt, with the text the message must contain. */
typedef struct def_field {
  const char* name;
  size_t offset;
  int positive; /* must be > 0 (lengths, radii): 0 and negatives are refused too */
  double too_big;
} def_field;

static double* field_of(frusta_hand_def* def, const def_field* field) {
  return (double*)((char*)def + field->offset);
}

static void test_create_destroy(void) {
  frusta_hand_def def = frusta_default_hand_def();
  frusta_hand_id hand = {0, 0, 0};
  expect_ok("frusta_create_hand(default)", frusta_create_hand(&def, &hand));
  check(!FRUSTA_IS_NULL(hand), "created id is not null (index1 %d)", hand.index1);
  check(hand.generation != 0, "created id has a non-zero generation");
  check(frusta_hand_is_valid(hand) == 1, "frusta_hand_is_valid(new hand) == 1");

  double angles[FRUSTA_HAND_JOINT_COUNT];
  memset(angles, 0xff, sizeof angles);
  int32_t angle_count = -1;
  expect_ok("get_joint_angles(new hand)",
            frusta_hand_get_joint_angles(hand, angles, FRUSTA_HAND_JOINT_COUNT, &angle_count));
  check(angle_count == FRUSTA_HAND_JOINT_COUNT, "joint angle count %d", angle_count);
  int zero = 1;
  for (int i = 0; i < FRUSTA_HAND_JOINT_COUNT; ++i) zero &= angles[i] == 0.0;
  check(zero, "a new hand has every joint angle 0 (inside the default limits)");

  frusta_segment seg[FRUSTA_HAND_SEGMENT_COUNT + 1];
  int32_t count = -1;
  memset(seg, 0, sizeof seg);
  expect_ok("get_segments(new hand, capacity 16)",
            frusta_hand_get_segments(hand, seg, FRUSTA_HAND_SEGMENT_COUNT + 1, &count));
  check(count == FRUSTA_HAND_SEGMENT_COUNT, "segment count %d", count);
  /* a straight default middle finger ends, tip hemisphere included, at hand_length */
  const frusta_segment* tip = &seg[FRUSTA_FINGER_MIDDLE * FRUSTA_SEGMENTS_PER_FINGER + 2];
  check(near(tip->distal[0] + tip->distal_radius, def.hand_length, 1e-12),
        "middle fingertip surface at x = %.15g (hand_length %g)",
        tip->distal[0] + tip->distal_radius, def.hand_length);
  int chained = 1;
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    for (int s = 0; s + 1 < FRUSTA_SEGMENTS_PER_FINGER; ++s) {
      const frusta_segment* a = &seg[f * FRUSTA_SEGMENTS_PER_FINGER + s];
      const frusta_segment* b = a + 1;
      chained &= memcmp(a->distal, b->proximal, sizeof a->distal) == 0 &&
                 a->distal_radius == b->proximal_radius;
    }
  check(chained, "each segment starts where the previous one of its finger ends");
  check(seg[FRUSTA_HAND_SEGMENT_COUNT].proximal_radius == 0.0,
        "get_segments writes only FRUSTA_HAND_SEGMENT_COUNT entries");
  expect_error("get_segments(out_count null)",
               frusta_hand_get_segments(hand, seg, FRUSTA_HAND_SEGMENT_COUNT, NULL),
               FRUSTA_ERROR_NULL_POINTER, "out_count", NULL);

  int32_t palm_count = -1;
  expect_ok("get_palm_spheres(null, 0) size query",
            frusta_hand_get_palm_spheres(hand, NULL, 0, &palm_count));
  check(palm_count > 0 && palm_count <= MAX_PALM_SPHERES, "palm sphere count %d", palm_count);

  expect_ok("frusta_destroy_hand", frusta_destroy_hand(hand));
  check(frusta_hand_is_valid(hand) == 0, "destroyed hand is not valid");
}

static void test_def_errors(void) {
  const frusta_hand_def good = frusta_default_hand_def();
  frusta_hand_def def;
  const frusta_hand_id sentinel = {12345, 7, 99};
  frusta_hand_id out;
  frusta_result r;

  r = frusta_create_hand(NULL, &out);
  expect_error("create_hand(def null)", r, FRUSTA_ERROR_NULL_POINTER, "def", NULL);
  def = good;
  r = frusta_create_hand(&def, NULL);
  expect_error("create_hand(out_hand null)", r, FRUSTA_ERROR_NULL_POINTER, "out_hand", NULL);

  const int32_t sizes[] = {0, (int32_t)sizeof(frusta_hand_def) - 8,
                           (int32_t)sizeof(frusta_hand_def) + 8, -1};
  for (int i = 0; i < 4; ++i) {
    char what[96];
    def = good;
    def.struct_size = sizes[i];
    out = sentinel;
    snprintf(what, sizeof what, "create_hand(struct_size %d)", sizes[i]);
    expect_error(what, frusta_create_hand(&def, &out), FRUSTA_ERROR_STRUCT_SIZE, "frusta_hand_def",
                 NULL);
    check(memcmp(&out, &sentinel, sizeof out) == 0, "%s leaves out_hand unchanged", what);
  }

  /* built by hand: memset + struct_size, no cookie */
  memset(&def, 0, sizeof def);
  def.struct_size = (int32_t)sizeof def;
  out = sentinel;
  expect_error("create_hand(memset def)", frusta_create_hand(&def, &out),
               FRUSTA_ERROR_DEF_NOT_DEFAULTED, "frusta_default_hand_def", NULL);
  check(memcmp(&out, &sentinel, sizeof out) == 0, "memset def leaves out_hand unchanged");
  /* a defaulted def whose cookie was overwritten, e.g. a drifted C# mirror */
  def = good;
  def.internal_value = 0;
  expect_error("create_hand(def.internal_value 0)", frusta_create_hand(&def, &out),
               FRUSTA_ERROR_DEF_NOT_DEFAULTED, "internal_value", NULL);

  for (int side = -1; side <= 7; side += 8) {
    char what[64];
    def = good;
    def.side = side;
    out = sentinel;
    snprintf(what, sizeof what, "create_hand(side %d)", side);
    expect_error(what, frusta_create_hand(&def, &out), FRUSTA_ERROR_OUT_OF_RANGE, "side",
                 side == 7 ? "7" : "-1");
    check(memcmp(&out, &sentinel, sizeof out) == 0, "%s leaves out_hand unchanged", what);
  }

  /* every numeric field class */
  const def_field fields[] = {
      {"hand_length", offsetof(frusta_hand_def, hand_length), 1, 1e300},
      {"hand_breadth", offsetof(frusta_hand_def, hand_breadth), 1, 1e300},
      {"segment_length[1][2]", offsetof(frusta_hand_def, segment_length[1][2]), 1, 1e300},
      {"segment_length[0][0]", offsetof(frusta_hand_def, segment_length[0][0]), 1, 1e300},
      {"joint_radius[3][1]", offsetof(frusta_hand_def, joint_radius[3][1]), 1, 1e300},
      {"joint_radius[4][3]", offsetof(frusta_hand_def, joint_radius[4][3]), 1, 1e300},
      {"base_position[2][1]", offsetof(frusta_hand_def, base_position[2][1]), 0, 1e300},
      {"base_rotation[0][2]", offsetof(frusta_hand_def, base_rotation[0][2]), 0, 1e300},
      {"joint_min[4][3]", offsetof(frusta_hand_def, joint_min[4][3]), 0, -1e300},
      {"joint_max[1][1]", offsetof(frusta_hand_def, joint_max[1][1]), 0, 1e300},
      {"palm_length", offsetof(frusta_hand_def, palm_length), 1, 1e300},
      {"palm_breadth", offsetof(frusta_hand_def, palm_breadth), 1, 1e300},
      {"palm_thickness", offsetof(frusta_hand_def, palm_thickness), 1, 1e300},
  };
  const int field_count = (int)(sizeof fields / sizeof fields[0]);
  for (int i = 0; i < field_count; ++i) {
    const def_field* field = &fields[i];
    struct {
      double value;
      frusta_result want;
      const char* text;
    } bad[7] = {
        {NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
        {INFINITY, FRUSTA_ERROR_NOT_FINITE, "inf"},
        {-INFINITY, FRUSTA_ERROR_NOT_FINITE, "-inf"},
        {field->too_big, FRUSTA_ERROR_OUT_OF_RANGE, field->too_big > 0 ? "1e+300" : "-1e+300"},
        {-0.01, FRUSTA_ERROR_OUT_OF_RANGE, "-0.01"},
        {0.0, FRUSTA_ERROR_OUT_OF_RANGE, NULL},
        /* a hand (or a part) 1e-300 m long was once accepted */
        {1e-300, FRUSTA_ERROR_OUT_OF_RANGE, "1e-300"}};
    const int cases = field->positive ? 7 : 4;
    for (int k = 0; k < cases; ++k) {
      char what[96];
      def = good;
      *field_of(&def, field) = bad[k].value;
      out = sentinel;
      snprintf(what, sizeof what, "create_hand(%s = %g)", field->name, bad[k].value);
      expect_error(what, frusta_create_hand(&def, &out), bad[k].want, field->name, bad[k].text);
      check(memcmp(&out, &sentinel, sizeof out) == 0, "%s leaves out_hand unchanged", what);
    }
  }

  /* a palm too thin for its size would be a grid of 10^10 spheres (an int overflow
     and a 45 GB allocation once): refused, naming the thickness */
  def = good;
  def.palm_length = def.palm_breadth = 5.0;
  def.palm_thickness = 1e-4;
  out = sentinel;
  expect_error("create_hand(5 m palm, 0.1 mm thick)", frusta_create_hand(&def, &out),
               FRUSTA_ERROR_OUT_OF_RANGE, "palm_thickness", "4096");
  check(memcmp(&out, &sentinel, sizeof out) == 0, "the thin palm leaves out_hand unchanged");

  /* limits: outside [-pi, pi], and min > max */
  def = good;
  def.joint_min[2][1] = -4.0;
  expect_error("create_hand(joint_min[2][1] = -4)", frusta_create_hand(&def, &out),
               FRUSTA_ERROR_OUT_OF_RANGE, "joint_min[2][1]", "-4");
  def = good;
  def.joint_max[2][1] = 4.0;
  expect_error("create_hand(joint_max[2][1] = 4)", frusta_create_hand(&def, &out),
               FRUSTA_ERROR_OUT_OF_RANGE, "joint_max[2][1]", "4");
  def = good;
  def.joint_min[2][1] = 1.0;
  def.joint_max[2][1] = 0.5;
  out = sentinel;
  r = frusta_create_hand(&def, &out);
  check(r == FRUSTA_ERROR_OUT_OF_RANGE && (contains(frusta_last_error(), "joint_max[2][1]") ||
                                           contains(frusta_last_error(), "joint_min[2][1]")),
        "create_hand(joint_min[2][1] 1 > joint_max 0.5) -> %s: \"%s\"", frusta_result_name(r),
        frusta_last_error());
  check(memcmp(&out, &sentinel, sizeof out) == 0, "min > max leaves out_hand unchanged");
  /* equal limits are a locked joint, not an error */
  def = good;
  def.joint_min[2][1] = def.joint_max[2][1] = 0.25;
  r = frusta_create_hand(&def, &out);
  expect_ok("create_hand(joint_min == joint_max: locked joint)", r);
  if (r == FRUSTA_OK) {
    double angles[FRUSTA_HAND_JOINT_COUNT];
    int32_t count = 0;
    frusta_hand_get_joint_angles(out, angles, FRUSTA_HAND_JOINT_COUNT, &count);
    check(angles[2 * FRUSTA_JOINTS_PER_FINGER + 1] == 0.25,
          "a locked joint starts at its only value (%g)", angles[2 * FRUSTA_JOINTS_PER_FINGER + 1]);
    frusta_destroy_hand(out);
  }
}

static void test_set_size(void) {
  const frusta_hand_def good = frusta_default_hand_def();
  frusta_hand_def def = good, before;
  frusta_result r;

  r = frusta_hand_def_set_size(NULL, 0.2, 0.09);
  expect_error("hand_def_set_size(null)", r, FRUSTA_ERROR_NULL_POINTER, "def", NULL);

  def.side = FRUSTA_HAND_LEFT;
  def.joint_max[1][2] = 1.5;
  expect_ok("hand_def_set_size(0.2, 0.09)", frusta_hand_def_set_size(&def, 0.2, 0.09));
  check(def.hand_length == 0.2 && def.hand_breadth == 0.09, "set_size stores length and breadth");
  check(def.side == FRUSTA_HAND_LEFT && def.joint_max[1][2] == 1.5 &&
            def.joint_min[0][0] == good.joint_min[0][0],
        "set_size keeps side and joint limits");
  check(def.internal_value == good.internal_value && def.struct_size == good.struct_size,
        "set_size keeps struct_size and the cookie");
  check(near(def.segment_length[2][0] / good.segment_length[2][0], 0.2 / 0.19, 1e-12) &&
            near(def.joint_radius[2][0] / good.joint_radius[2][0], 0.09 / 0.085, 1e-12),
        "set_size scales lengths with hand_length and radii with hand_breadth");
  /* resizing back to the default size reproduces the default geometry */
  frusta_hand_def back = def;
  frusta_hand_def_set_size(&back, 0.19, 0.085);
  back.side = good.side;
  back.joint_max[1][2] = good.joint_max[1][2];
  check(memcmp(&back, &good, sizeof back) == 0, "set_size(0.19, 0.085) gives the default def");

  const struct {
    double length, breadth;
    frusta_result want;
    const char *field, *value;
  } bad[] = {
      {NAN, 0.09, FRUSTA_ERROR_NOT_FINITE, "hand_length", "nan"},
      {INFINITY, 0.09, FRUSTA_ERROR_NOT_FINITE, "hand_length", "inf"},
      {-INFINITY, 0.09, FRUSTA_ERROR_NOT_FINITE, "hand_length", "-inf"},
      {1e300, 0.09, FRUSTA_ERROR_OUT_OF_RANGE, "hand_length", "1e+300"},
      {0.0, 0.09, FRUSTA_ERROR_OUT_OF_RANGE, "hand_length", NULL},
      {1e-300, 0.09, FRUSTA_ERROR_OUT_OF_RANGE, "hand_length", "1e-300"},
      {-0.19, 0.09, FRUSTA_ERROR_OUT_OF_RANGE, "hand_length", "-0.19"},
      {0.19, NAN, FRUSTA_ERROR_NOT_FINITE, "hand_breadth", "nan"},
      {0.19, INFINITY, FRUSTA_ERROR_NOT_FINITE, "hand_breadth", "inf"},
      {0.19, -INFINITY, FRUSTA_ERROR_NOT_FINITE, "hand_breadth", "-inf"},
      {0.19, 1e300, FRUSTA_ERROR_OUT_OF_RANGE, "hand_breadth", "1e+300"},
      {0.19, 0.0, FRUSTA_ERROR_OUT_OF_RANGE, "hand_breadth", NULL},
      {0.19, -0.085, FRUSTA_ERROR_OUT_OF_RANGE, "hand_breadth", "-0.085"},
  };
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
    char what[96];
    before = def;
    snprintf(what, sizeof what, "hand_def_set_size(%g, %g)", bad[i].length, bad[i].breadth);
    r = frusta_hand_def_set_size(&def, bad[i].length, bad[i].breadth);
    expect_error(what, r, bad[i].want, bad[i].field, bad[i].value);
    check(memcmp(&def, &before, sizeof def) == 0, "%s leaves the def unchanged", what);
  }

  /* valid arguments whose proportions give an invalid def: refused, def unchanged */
  before = def;
  r = frusta_hand_def_set_size(&def, 0.05, 0.2);
  check(r == FRUSTA_ERROR_OUT_OF_RANGE && frusta_last_error()[0] != '\0',
        "hand_def_set_size(0.05, 0.2): a breadth 4x the length -> %s: \"%s\"",
        frusta_result_name(r), frusta_last_error());
  check(memcmp(&def, &before, sizeof def) == 0,
        "hand_def_set_size(0.05, 0.2) leaves the def unchanged");

  /* the def itself is refused before anything is written */
  frusta_hand_def wrong = good;
  wrong.struct_size = 8;
  before = wrong;
  expect_error("hand_def_set_size(struct_size 8)", frusta_hand_def_set_size(&wrong, 0.2, 0.09),
               FRUSTA_ERROR_STRUCT_SIZE, "frusta_hand_def", NULL);
  check(memcmp(&wrong, &before, sizeof wrong) == 0, "wrong struct_size: def unchanged");
  memset(&wrong, 0, sizeof wrong);
  wrong.struct_size = (int32_t)sizeof wrong;
  before = wrong;
  expect_error("hand_def_set_size(memset def)", frusta_hand_def_set_size(&wrong, 0.2, 0.09),
               FRUSTA_ERROR_DEF_NOT_DEFAULTED, "frusta_default_hand_def", NULL);
  check(memcmp(&wrong, &before, sizeof wrong) == 0, "memset def: def unchanged");
  /* set_size keeps joint limits, so bad limits make the resized def invalid */
  wrong = good;
  wrong.joint_min[3][2] = 1.0;
  wrong.joint_max[3][2] = 0.0;
  before = wrong;
  r = frusta_hand_def_set_size(&wrong, 0.2, 0.09);
  check(r == FRUSTA_ERROR_OUT_OF_RANGE && (contains(frusta_last_error(), "joint_max[3][2]") ||
                                           contains(frusta_last_error(), "joint_min[3][2]")),
        "hand_def_set_size(def with joint_min > joint_max) -> %s: \"%s\"", frusta_result_name(r),
        frusta_last_error());
  check(memcmp(&wrong, &before, sizeof wrong) == 0, "bad limits: def unchanged");
  wrong = good;
  wrong.side = 7;
  before = wrong;
  expect_error("hand_def_set_size(def.side 7)", frusta_hand_def_set_size(&wrong, 0.2, 0.09),
               FRUSTA_ERROR_OUT_OF_RANGE, "side", "7");
  check(memcmp(&wrong, &before, sizeof wrong) == 0, "side 7: def unchanged");
}

/* Every entry point that takes a hand id, called with `id`, must fail with `want`
 * and leave `witness` (another, live hand) unchanged. */
static void expect_id_refused(frusta_hand_id id, frusta_result want, const char* label,
                              frusta_hand_id witness) {
  char what[128];
  const char* needle = want == FRUSTA_ERROR_NULL_ID ? "null" : "destroyed";
  double angles[FRUSTA_HAND_JOINT_COUNT] = {0};
  double jacobian[30];
  const double local[3] = {0, 0, 0};
  frusta_segment segments[FRUSTA_HAND_SEGMENT_COUNT];
  frusta_sphere palm[4];
  int32_t count = -7;
  const frusta_pose pose = {{0.1, 0.2, 0.3}, {0, 0, 0, 1}};

  remember(witness);
  snprintf(what, sizeof what, "destroy_hand(%s)", label);
  expect_error(what, frusta_destroy_hand(id), want, needle, NULL);
  snprintf(what, sizeof what, "set_palm_pose(%s)", label);
  expect_error(what, frusta_hand_set_palm_pose(id, &pose), want, needle, NULL);
  snprintf(what, sizeof what, "set_joint_angles(%s)", label);
  expect_error(what, frusta_hand_set_joint_angles(id, angles, FRUSTA_HAND_JOINT_COUNT), want,
               needle, NULL);
  snprintf(what, sizeof what, "get_joint_angles(%s)", label);
  expect_error(what, frusta_hand_get_joint_angles(id, angles, FRUSTA_HAND_JOINT_COUNT, &count),
               want, needle, NULL);
  check(count == -7, "get_joint_angles(%s) leaves out_count unchanged", label);
  snprintf(what, sizeof what, "get_segments(%s)", label);
  expect_error(what, frusta_hand_get_segments(id, segments, FRUSTA_HAND_SEGMENT_COUNT, &count),
               want, needle, NULL);
  check(count == -7, "get_segments(%s) leaves out_count unchanged", label);
  snprintf(what, sizeof what, "get_palm_spheres(%s)", label);
  expect_error(what, frusta_hand_get_palm_spheres(id, palm, 4, &count), want, needle, NULL);
  check(count == -7, "get_palm_spheres(%s) leaves out_count unchanged", label);
  snprintf(what, sizeof what, "point_jacobian(%s)", label);
  expect_error(what, frusta_hand_point_jacobian(id, 1, 1, local, NULL, jacobian, 30, &count), want,
               needle, NULL);
  check(count == -7, "point_jacobian(%s) leaves out_count unchanged", label);
  check(frusta_hand_is_valid(id) == 0, "frusta_hand_is_valid(%s) == 0", label);
  snprintf(what, sizeof what, "calls on %s", label);
  expect_unchanged(witness, what);
}

static void test_ids(void) {
  frusta_hand_def def = frusta_default_hand_def();
  frusta_hand_id witness, old_hand, new_hand;
  expect_ok("create witness hand", frusta_create_hand(&def, &witness));
  const double angles[FRUSTA_HAND_JOINT_COUNT] = {0.1, 0.2, 0.3, 0.4, 0.1, 0.5, 0.6, 0.2};
  frusta_hand_set_joint_angles(witness, angles, FRUSTA_HAND_JOINT_COUNT);

  const frusta_hand_id null_id = {0, 0, 0};
  check(FRUSTA_IS_NULL(null_id), "FRUSTA_IS_NULL({0})");
  expect_id_refused(null_id, FRUSTA_ERROR_NULL_ID, "null id", witness);
  const frusta_hand_id null_with_generation = {0, 0, 3};
  expect_id_refused(null_with_generation, FRUSTA_ERROR_NULL_ID, "{0, 0, 3}", witness);

  expect_ok("create hand A", frusta_create_hand(&def, &old_hand));
  expect_ok("destroy hand A", frusta_destroy_hand(old_hand));
  expect_id_refused(old_hand, FRUSTA_ERROR_STALE_ID, "destroyed id", witness);

  /* the slot is reused: A's id stays stale, B's is valid */
  expect_ok("create hand B", frusta_create_hand(&def, &new_hand));
  check(new_hand.index1 == old_hand.index1 && new_hand.generation != old_hand.generation,
        "B reuses A's slot with a new generation (A {%d,%u}, B {%d,%u})", old_hand.index1,
        old_hand.generation, new_hand.index1, new_hand.generation);
  check(frusta_hand_is_valid(new_hand) == 1, "B is valid");
  expect_id_refused(old_hand, FRUSTA_ERROR_STALE_ID, "A's id after reuse", new_hand);
  check(frusta_hand_is_valid(new_hand) == 1, "B is still valid after calls with A's id");

  frusta_hand_id forged = new_hand;
  forged.world0 = 1;
  expect_id_refused(forged, FRUSTA_ERROR_STALE_ID, "B's id with world0 1", new_hand);
  forged = new_hand;
  forged.index1 = 1000000;
  expect_id_refused(forged, FRUSTA_ERROR_STALE_ID, "id with index1 1000000", new_hand);
  forged.index1 = -3;
  expect_id_refused(forged, FRUSTA_ERROR_STALE_ID, "id with index1 -3", new_hand);
  forged = new_hand;
  forged.generation = (uint16_t)(new_hand.generation + 1);
  expect_id_refused(forged, FRUSTA_ERROR_STALE_ID, "B's id with the next generation", new_hand);

  expect_ok("destroy hand B", frusta_destroy_hand(new_hand));
  expect_error("destroy hand B twice", frusta_destroy_hand(new_hand), FRUSTA_ERROR_STALE_ID,
               "destroyed", NULL);
  expect_ok("destroy witness", frusta_destroy_hand(witness));
}

static void test_hand_inputs(void) {
  frusta_hand_def def = frusta_default_hand_def();
  frusta_hand_id hand;
  if (!expect_ok("create hand for input checks", frusta_create_hand(&def, &hand))) return;
  /* a non-trivial state, so that an accidental write shows */
  const frusta_pose start = {{0.1, -0.2, 0.3},
                             {0.0, 0.0, 0.38268343236508978, 0.92387953251128674}};
  expect_ok("set_palm_pose(start)", frusta_hand_set_palm_pose(hand, &start));
  double angles[FRUSTA_HAND_JOINT_COUNT];
  for (int i = 0; i < FRUSTA_HAND_JOINT_COUNT; ++i) angles[i] = 0.05 * (i % 4) + 0.01;
  expect_ok("set_joint_angles(start)",
            frusta_hand_set_joint_angles(hand, angles, FRUSTA_HAND_JOINT_COUNT));
  char what[128];
  frusta_result r;

  /* palm pose */
  remember(hand);
  r = frusta_hand_set_palm_pose(hand, NULL);
  expect_error("set_palm_pose(pose null)", r, FRUSTA_ERROR_NULL_POINTER, "pose", NULL);
  expect_unchanged(hand, "set_palm_pose(null)");
  const struct {
    double value;
    frusta_result want;
    const char* text;
  } position_bad[] = {{NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
                      {INFINITY, FRUSTA_ERROR_NOT_FINITE, "inf"},
                      {-INFINITY, FRUSTA_ERROR_NOT_FINITE, "-inf"},
                      {1e300, FRUSTA_ERROR_OUT_OF_RANGE, "1e+300"},
                      {-2e6, FRUSTA_ERROR_OUT_OF_RANGE, "-2e+06"}};
  for (int k = 0; k < 3; ++k)
    for (size_t b = 0; b < sizeof position_bad / sizeof position_bad[0]; ++b) {
      frusta_pose pose = start;
      char field[32];
      pose.position[k] = position_bad[b].value;
      snprintf(field, sizeof field, "pose.position[%d]", k);
      snprintf(what, sizeof what, "set_palm_pose(%s = %g)", field, position_bad[b].value);
      expect_error(what, frusta_hand_set_palm_pose(hand, &pose), position_bad[b].want, field,
                   position_bad[b].text);
      expect_unchanged(hand, what);
    }
  for (int k = 0; k < 4; ++k)
    for (int b = 0; b < 3; ++b) {
      frusta_pose pose = start;
      char field[32];
      pose.rotation[k] = position_bad[b].value;
      snprintf(field, sizeof field, "pose.rotation[%d]", k);
      snprintf(what, sizeof what, "set_palm_pose(%s = %g)", field, position_bad[b].value);
      expect_error(what, frusta_hand_set_palm_pose(hand, &pose), FRUSTA_ERROR_NOT_FINITE, field,
                   position_bad[b].text);
      expect_unchanged(hand, what);
    }
  const struct {
    double q[4];
    const char* label;
  } rotation_bad[] = {{{0, 0, 0, 0}, "zero quaternion"},
                      {{0, 0, 0, 1e300}, "w = 1e300"},
                      {{1e-300, 0, 0, 0}, "x = 1e-300"},
                      {{0, 3.0, 0, 0}, "norm 3"},
                      {{0, 0, 0, 0.4}, "norm 0.4"}};
  for (size_t b = 0; b < sizeof rotation_bad / sizeof rotation_bad[0]; ++b) {
    frusta_pose pose = start;
    memcpy(pose.rotation, rotation_bad[b].q, sizeof pose.rotation);
    snprintf(what, sizeof what, "set_palm_pose(%s)", rotation_bad[b].label);
    expect_error(what, frusta_hand_set_palm_pose(hand, &pose), FRUSTA_ERROR_OUT_OF_RANGE,
                 "pose.rotation", NULL);
    expect_unchanged(hand, what);
  }

  /* joint angles */
  r = frusta_hand_set_joint_angles(hand, NULL, FRUSTA_HAND_JOINT_COUNT);
  expect_error("set_joint_angles(null)", r, FRUSTA_ERROR_NULL_POINTER, "angles", NULL);
  expect_unchanged(hand, "set_joint_angles(null)");
  const int32_t counts[] = {FRUSTA_HAND_JOINT_COUNT - 1, FRUSTA_HAND_JOINT_COUNT + 1, 0, -1};
  for (int i = 0; i < 4; ++i) {
    double many[FRUSTA_HAND_JOINT_COUNT + 1] = {0};
    snprintf(what, sizeof what, "set_joint_angles(count %d)", counts[i]);
    expect_error(what, frusta_hand_set_joint_angles(hand, many, counts[i]),
                 FRUSTA_ERROR_OUT_OF_RANGE, "count", NULL);
    expect_unchanged(hand, what);
  }
  const struct {
    int index;
    double value;
    frusta_result want;
    const char* text;
  } angle_bad[] = {{5, NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
                   {0, INFINITY, FRUSTA_ERROR_NOT_FINITE, "inf"},
                   {19, -INFINITY, FRUSTA_ERROR_NOT_FINITE, "-inf"},
                   {7, 1e300, FRUSTA_ERROR_OUT_OF_RANGE, "1e+300"},
                   {12, -12.6, FRUSTA_ERROR_OUT_OF_RANGE, "-12.6"}};
  for (size_t b = 0; b < sizeof angle_bad / sizeof angle_bad[0]; ++b) {
    double bad[FRUSTA_HAND_JOINT_COUNT];
    char field[32];
    memcpy(bad, angles, sizeof bad);
    for (int i = 0; i < FRUSTA_HAND_JOINT_COUNT; ++i) bad[i] += 0.02; /* a real change */
    bad[angle_bad[b].index] = angle_bad[b].value;
    snprintf(field, sizeof field, "angles[%d]", angle_bad[b].index);
    snprintf(what, sizeof what, "set_joint_angles(%s = %g)", field, angle_bad[b].value);
    expect_error(what, frusta_hand_set_joint_angles(hand, bad, FRUSTA_HAND_JOINT_COUNT),
                 angle_bad[b].want, field, angle_bad[b].text);
    expect_unchanged(hand, what);
  }

  /* outputs, by the output-array rule: the count, and min(capacity, count) elements */
  double out_angles[FRUSTA_HAND_JOINT_COUNT + 1];
  memset(out_angles, 0x5a, sizeof out_angles);
  double pattern[FRUSTA_HAND_JOINT_COUNT + 1];
  memset(pattern, 0x5a, sizeof pattern);
  int32_t count = -7;
  expect_error("get_joint_angles(out null, capacity 20)",
               frusta_hand_get_joint_angles(hand, NULL, FRUSTA_HAND_JOINT_COUNT, &count),
               FRUSTA_ERROR_NULL_POINTER, "out", NULL);
  expect_error("get_joint_angles(capacity -1)",
               frusta_hand_get_joint_angles(hand, out_angles, -1, &count),
               FRUSTA_ERROR_OUT_OF_RANGE, "capacity", NULL);
  expect_error("get_joint_angles(out_count null)",
               frusta_hand_get_joint_angles(hand, out_angles, FRUSTA_HAND_JOINT_COUNT, NULL),
               FRUSTA_ERROR_NULL_POINTER, "out_count", NULL);
  check(memcmp(out_angles, pattern, sizeof pattern) == 0 && count == -7,
        "failed get_joint_angles writes neither out nor out_count");
  expect_ok("get_joint_angles(out null, capacity 0): count only",
            frusta_hand_get_joint_angles(hand, NULL, 0, &count));
  check(count == FRUSTA_HAND_JOINT_COUNT, "get_joint_angles counts %d angles", count);
  count = -7;
  expect_ok("get_joint_angles(capacity 19)",
            frusta_hand_get_joint_angles(hand, out_angles, FRUSTA_HAND_JOINT_COUNT - 1, &count));
  check(count == FRUSTA_HAND_JOINT_COUNT &&
            memcmp(&out_angles[19], &pattern[19], 2 * sizeof out_angles[0]) == 0,
        "get_joint_angles(capacity 19) writes 19 angles and counts 20 (got %d)", count);

  frusta_segment segments[FRUSTA_HAND_SEGMENT_COUNT], segment_pattern[FRUSTA_HAND_SEGMENT_COUNT];
  memset(segments, 0x5a, sizeof segments);
  memset(segment_pattern, 0x5a, sizeof segment_pattern);
  count = -7;
  expect_error("get_segments(out null)",
               frusta_hand_get_segments(hand, NULL, FRUSTA_HAND_SEGMENT_COUNT, &count),
               FRUSTA_ERROR_NULL_POINTER, "out", NULL);
  /* a negative capacity is a wrong argument, as for every call with a capacity */
  expect_error("get_segments(capacity -1)", frusta_hand_get_segments(hand, segments, -1, &count),
               FRUSTA_ERROR_OUT_OF_RANGE, "capacity", NULL);
  check(memcmp(segments, segment_pattern, sizeof segments) == 0 && count == -7,
        "failed get_segments writes neither out nor out_count");
  expect_ok("get_segments(capacity 14)",
            frusta_hand_get_segments(hand, segments, FRUSTA_HAND_SEGMENT_COUNT - 1, &count));
  check(count == FRUSTA_HAND_SEGMENT_COUNT &&
            memcmp(&segments[14], &segment_pattern[14], sizeof segments[0]) == 0 &&
            memcmp(&segments[13], &segment_pattern[13], sizeof segments[0]) != 0,
        "get_segments(capacity 14) writes 14 segments and counts 15 (got %d)", count);

  int32_t palm_count = 0;
  frusta_hand_get_palm_spheres(hand, NULL, 0, &palm_count);
  frusta_sphere palm[MAX_PALM_SPHERES], palm_pattern[MAX_PALM_SPHERES];
  memset(palm, 0x5a, sizeof palm);
  memset(palm_pattern, 0x5a, sizeof palm_pattern);
  count = -7;
  expect_error("get_palm_spheres(out null, capacity 4)",
               frusta_hand_get_palm_spheres(hand, NULL, 4, &count), FRUSTA_ERROR_NULL_POINTER,
               "out", NULL);
  expect_error("get_palm_spheres(exact capacity, out_count null)",
               frusta_hand_get_palm_spheres(hand, palm, palm_count, NULL),
               FRUSTA_ERROR_NULL_POINTER, "out_count", NULL);
  check(memcmp(palm, palm_pattern, sizeof palm) == 0, "failed get_palm_spheres writes no sphere");
  /* "On failure ... nothing the call would have changed has changed" (frusta.h) */
  check(count == -7, "failed get_palm_spheres leaves out_count unchanged (got %d)", count);
  snprintf(what, sizeof what, "get_palm_spheres(capacity %d)", palm_count - 1);
  expect_ok(what, frusta_hand_get_palm_spheres(hand, palm, palm_count - 1, &count));
  check(count == palm_count &&
            memcmp(&palm[palm_count - 1], &palm_pattern[palm_count - 1], sizeof palm[0]) == 0,
        "a short get_palm_spheres writes what fits and counts them all (got %d)", count);
  expect_ok("get_palm_spheres(exact capacity)",
            frusta_hand_get_palm_spheres(hand, palm, palm_count, &count));
  check(memcmp(&palm[palm_count], &palm_pattern[palm_count], sizeof palm[0]) == 0,
        "get_palm_spheres writes only count spheres");

  /* point Jacobian */
  double jacobian[31], jacobian_pattern[31], point[3], point_pattern[3];
  const double local[3] = {0.01, 0.0, 0.0};
  memset(jacobian, 0x5a, sizeof jacobian);
  memset(jacobian_pattern, 0x5a, sizeof jacobian_pattern);
  memset(point, 0x5a, sizeof point);
  memset(point_pattern, 0x5a, sizeof point_pattern);
  count = -7;
  const struct {
    int finger, segment;
    const char* field;
  } index_bad[] = {{-1, 0, "finger"}, {5, 0, "finger"}, {0, -1, "segment"}, {0, 3, "segment"}};
  for (int i = 0; i < 4; ++i) {
    snprintf(what, sizeof what, "point_jacobian(finger %d, segment %d)", index_bad[i].finger,
             index_bad[i].segment);
    expect_error(what,
                 frusta_hand_point_jacobian(hand, index_bad[i].finger, index_bad[i].segment, local,
                                            point, jacobian, 30, &count),
                 FRUSTA_ERROR_OUT_OF_RANGE, index_bad[i].field, NULL);
  }
  expect_error("point_jacobian(local_point null)",
               frusta_hand_point_jacobian(hand, 1, 1, NULL, point, jacobian, 30, &count),
               FRUSTA_ERROR_NULL_POINTER, "local_point", NULL);
  expect_error("point_jacobian(out_jacobian null, capacity 30)",
               frusta_hand_point_jacobian(hand, 1, 1, local, point, NULL, 30, &count),
               FRUSTA_ERROR_NULL_POINTER, "out_jacobian", NULL);
  expect_error("point_jacobian(capacity -1)",
               frusta_hand_point_jacobian(hand, 1, 1, local, point, jacobian, -1, &count),
               FRUSTA_ERROR_OUT_OF_RANGE, "capacity", NULL);
  expect_error("point_jacobian(out_count null)",
               frusta_hand_point_jacobian(hand, 1, 1, local, point, jacobian, 30, NULL),
               FRUSTA_ERROR_NULL_POINTER, "out_count", NULL);
  for (int b = 0; b < 5; ++b) {
    double bad_local[3] = {0.01, 0.0, 0.0};
    bad_local[1] = position_bad[b].value;
    snprintf(what, sizeof what, "point_jacobian(local_point[1] = %g)", position_bad[b].value);
    expect_error(what,
                 frusta_hand_point_jacobian(hand, 1, 1, bad_local, point, jacobian, 30, &count),
                 position_bad[b].want, "local_point[1]", position_bad[b].text);
  }
  check(memcmp(jacobian, jacobian_pattern, sizeof jacobian) == 0 &&
            memcmp(point, point_pattern, sizeof point) == 0 && count == -7,
        "failed point_jacobian writes neither out_point, out_jacobian nor out_count");
  expect_ok("point_jacobian(capacity 29)",
            frusta_hand_point_jacobian(hand, 1, 1, local, point, jacobian, 29, &count));
  check(count == FRUSTA_POINT_JACOBIAN_LENGTH &&
            memcmp(&jacobian[29], &jacobian_pattern[29], 2 * sizeof jacobian[0]) == 0,
        "point_jacobian(capacity 29) writes 29 doubles and counts 30 (got %d)", count);
  expect_ok("point_jacobian(out_point null)",
            frusta_hand_point_jacobian(hand, 1, 1, local, NULL, jacobian, 30, &count));
  check(memcmp(&jacobian[30], &jacobian_pattern[30], sizeof jacobian[30]) == 0,
        "point_jacobian writes only 30 doubles");
  expect_ok("point_jacobian(finger 1, segment 2, origin)",
            frusta_hand_point_jacobian(hand, 1, 2, (const double[3]){0, 0, 0}, point, jacobian, 30,
                                       &count));
  frusta_hand_get_segments(hand, segments, FRUSTA_HAND_SEGMENT_COUNT, &count);
  check(memcmp(point, segments[1 * FRUSTA_SEGMENTS_PER_FINGER + 2].proximal, sizeof point) == 0,
        "the origin of segment (1, 2) is its proximal joint");
  expect_unchanged(hand, "all failing output calls");

  frusta_destroy_hand(hand);
}

static void test_palm_pose_and_clamping(void) {
  frusta_hand_def def = frusta_default_hand_def();
  frusta_hand_id hand;
  if (!expect_ok("create hand for poses", frusta_create_hand(&def, &hand))) return;
  frusta_segment at_rest[FRUSTA_HAND_SEGMENT_COUNT], moved[FRUSTA_HAND_SEGMENT_COUNT];
  int32_t count = 0;
  frusta_hand_get_segments(hand, at_rest, FRUSTA_HAND_SEGMENT_COUNT, &count);

  /* a quarter turn about z, given with norm 2: normalised, not refused */
  const double h = sqrt(0.5);
  const frusta_pose turned = {{1.0, 2.0, 3.0}, {0.0, 0.0, 2.0 * h, 2.0 * h}};
  expect_ok("set_palm_pose(quarter turn about z, norm 2)",
            frusta_hand_set_palm_pose(hand, &turned));
  frusta_hand_get_segments(hand, moved, FRUSTA_HAND_SEGMENT_COUNT, &count);
  double worst = 0.0;
  for (int i = 0; i < FRUSTA_HAND_SEGMENT_COUNT; ++i) {
    /* (x, y, z) -> (-y, x, z), then + (1, 2, 3) */
    const double* p = at_rest[i].distal;
    const double want[3] = {1.0 - p[1], 2.0 + p[0], 3.0 + p[2]};
    for (int k = 0; k < 3; ++k) worst = fmax(worst, fabs(moved[i].distal[k] - want[k]));
  }
  check(worst < 1e-12, "a norm-2 quarter turn is applied as the unit one (error %g)", worst);
  const frusta_pose identity = {{0, 0, 0}, {0, 0, 0, 0.5}};
  expect_ok("set_palm_pose(identity with norm 0.5)", frusta_hand_set_palm_pose(hand, &identity));
  frusta_hand_get_segments(hand, moved, FRUSTA_HAND_SEGMENT_COUNT, &count);
  check(memcmp(moved, at_rest, sizeof moved) == 0, "identity pose restores the rest geometry");

  /* angles beyond the limits, within FRUSTA_MAX_JOINT_ANGLE, are clamped, not refused */
  double wild[FRUSTA_HAND_JOINT_COUNT], got[FRUSTA_HAND_JOINT_COUNT];
  for (int i = 0; i < FRUSTA_HAND_JOINT_COUNT; ++i)
    wild[i] = i % 2 ? FRUSTA_MAX_JOINT_ANGLE : -FRUSTA_MAX_JOINT_ANGLE;
  expect_ok("set_joint_angles(+-FRUSTA_MAX_JOINT_ANGLE)",
            frusta_hand_set_joint_angles(hand, wild, FRUSTA_HAND_JOINT_COUNT));
  frusta_hand_get_joint_angles(hand, got, FRUSTA_HAND_JOINT_COUNT, &count);
  int clamped = 1;
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) {
      const int i = f * FRUSTA_JOINTS_PER_FINGER + j;
      clamped &= got[i] == (i % 2 ? def.joint_max[f][j] : def.joint_min[f][j]);
    }
  check(clamped, "angles beyond the limits read back as the def's limits");
  frusta_destroy_hand(hand);
}

/* ------------------------------------------------------------------ queries */

static const frusta_segment kCylinder = {{1.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, 0.1, 0.1};

static void test_queries(void) {
  frusta_contact_query q;
  frusta_constraint c;
  frusta_result r;
  char what[128];

  /* happy path: a sphere of radius 0.2 touching the cylinder's side from +y */
  const frusta_sphere touching = {{0.5, 0.3, 0.0}, 0.2};
  memset(&q, 0, sizeof q);
  q.struct_size = (int32_t)sizeof q;
  expect_ok("query_contact(touching side)", frusta_query_contact(&kCylinder, &touching, &q));
  check(near(q.distance, 0.0, 1e-12) && q.feature == FRUSTA_FEATURE_SIDE && q.contact == 1,
        "touching: distance %g, feature %d, contact %d", q.distance, q.feature, q.contact);
  check(near(q.normal[0], 0, 1e-12) && near(q.normal[1], -1, 1e-12) && near(q.normal[2], 0, 1e-12),
        "touching: normal (%g, %g, %g) points from the sphere to the hand", q.normal[0],
        q.normal[1], q.normal[2]);
  check(near(q.hand_point[1], 0.1, 1e-12) && near(q.object_point[1], 0.1, 1e-12) &&
            near(q.axial, 0.5, 1e-12),
        "touching: hand and object points at y = 0.1, axial 0.5");
  check(q.struct_size == (int32_t)sizeof q, "query leaves struct_size as set");
  memset(&c, 0, sizeof c);
  c.struct_size = (int32_t)sizeof c;
  expect_ok("constraint_eval(touching, distance)",
            frusta_constraint_eval(&kCylinder, &touching, FRUSTA_CONSTRAINT_DISTANCE, &c));
  check(near(c.value, 0.0, 1e-12) && c.feature == FRUSTA_FEATURE_SIDE,
        "distance constraint of a touching sphere is 0 (%g)", c.value);
  check(near(c.grad_center[1], 1.0, 1e-12), "distance constraint gradient in O is +y (%g)",
        c.grad_center[1]);
  expect_ok("constraint_eval(touching, squared)",
            frusta_constraint_eval(&kCylinder, &touching, FRUSTA_CONSTRAINT_SQUARED, &c));
  check(near(c.value, 0.0, 1e-12), "squared constraint of a touching sphere is 0 (%g)", c.value);
  /* beyond the distal ball */
  const frusta_sphere beyond = {{-0.5, 0.0, 0.0}, 0.1};
  frusta_query_contact(&kCylinder, &beyond, &q);
  check(q.feature == FRUSTA_FEATURE_DISTAL && near(q.distance, 0.3, 1e-12) && q.contact == 0,
        "beyond E: distal ball, distance %g, contact %d", q.distance, q.contact);
  /* zero radii and a zero-length segment are valid */
  const frusta_segment point = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, 0.0, 0.0};
  const frusta_sphere dot = {{0.0, 0.0, 2.0}, 0.0};
  r = frusta_query_contact(&point, &dot, &q);
  expect_ok("query_contact(point segment, point sphere)", r);
  check(near(q.distance, 2.0, 1e-15), "point to point distance %g", q.distance);

  /* null pointers */
  expect_error("query_contact(segment null)", frusta_query_contact(NULL, &touching, &q),
               FRUSTA_ERROR_NULL_POINTER, "segment", NULL);
  expect_error("query_contact(sphere null)", frusta_query_contact(&kCylinder, NULL, &q),
               FRUSTA_ERROR_NULL_POINTER, "sphere", NULL);
  expect_error("query_contact(out null)", frusta_query_contact(&kCylinder, &touching, NULL),
               FRUSTA_ERROR_NULL_POINTER, "out", NULL);
  expect_error("constraint_eval(segment null)",
               frusta_constraint_eval(NULL, &touching, FRUSTA_CONSTRAINT_DISTANCE, &c),
               FRUSTA_ERROR_NULL_POINTER, "segment", NULL);
  expect_error("constraint_eval(sphere null)",
               frusta_constraint_eval(&kCylinder, NULL, FRUSTA_CONSTRAINT_DISTANCE, &c),
               FRUSTA_ERROR_NULL_POINTER, "sphere", NULL);
  expect_error("constraint_eval(out null)",
               frusta_constraint_eval(&kCylinder, &touching, FRUSTA_CONSTRAINT_DISTANCE, NULL),
               FRUSTA_ERROR_NULL_POINTER, "out", NULL);

  /* struct sizes; a refused out struct is not written */
  frusta_contact_query q_pattern;
  frusta_constraint c_pattern;
  const int32_t sizes[] = {0, -1, 8, (int32_t)sizeof q - 8, (int32_t)sizeof q + 8};
  for (int i = 0; i < 5; ++i) {
    memset(&q, 0x5a, sizeof q);
    q.struct_size = sizes[i];
    q_pattern = q;
    snprintf(what, sizeof what, "query_contact(out.struct_size %d)", sizes[i]);
    expect_error(what, frusta_query_contact(&kCylinder, &touching, &q), FRUSTA_ERROR_STRUCT_SIZE,
                 "frusta_contact_query", NULL);
    check(memcmp(&q, &q_pattern, sizeof q) == 0, "%s writes nothing", what);
    memset(&c, 0x5a, sizeof c);
    c.struct_size = sizes[i] == (int32_t)sizeof q - 8 ? (int32_t)sizeof c - 8 : sizes[i];
    c_pattern = c;
    snprintf(what, sizeof what, "constraint_eval(out.struct_size %d)", c.struct_size);
    expect_error(what, frusta_constraint_eval(&kCylinder, &touching, 0, &c),
                 FRUSTA_ERROR_STRUCT_SIZE, "frusta_constraint", NULL);
    check(memcmp(&c, &c_pattern, sizeof c) == 0, "%s writes nothing", what);
  }
  /* the two out structs are not interchangeable */
  frusta_constraint big;
  memset(&big, 0, sizeof big);
  big.struct_size = (int32_t)sizeof(frusta_contact_query);
  expect_error("constraint_eval(struct_size = sizeof(frusta_contact_query))",
               frusta_constraint_eval(&kCylinder, &touching, 0, &big), FRUSTA_ERROR_STRUCT_SIZE,
               "frusta_constraint", NULL);

  /* forms */
  const int32_t forms[] = {5, -1, 2};
  for (int i = 0; i < 3; ++i) {
    memset(&c, 0x5a, sizeof c);
    c.struct_size = (int32_t)sizeof c;
    c_pattern = c;
    snprintf(what, sizeof what, "constraint_eval(form %d)", forms[i]);
    expect_error(what, frusta_constraint_eval(&kCylinder, &touching, forms[i], &c),
                 FRUSTA_ERROR_OUT_OF_RANGE, "form", NULL);
    check(memcmp(&c, &c_pattern, sizeof c) == 0, "%s writes nothing", what);
  }

  /* every numeric input */
  typedef struct {
    const char* field;
    double* target;
    int is_radius;
  } input;
  frusta_segment segment;
  frusta_sphere sphere;
  const input inputs[] = {
      {"segment.proximal[0]", &segment.proximal[0], 0},
      {"segment.proximal[2]", &segment.proximal[2], 0},
      {"segment.distal[1]", &segment.distal[1], 0},
      {"segment.proximal_radius", &segment.proximal_radius, 1},
      {"segment.distal_radius", &segment.distal_radius, 1},
      {"sphere.center[0]", &sphere.center[0], 0},
      {"sphere.center[2]", &sphere.center[2], 0},
      {"sphere.radius", &sphere.radius, 1},
  };
  const struct {
    double value;
    frusta_result want;
    const char* text;
    int radius_only;
  } bad[] = {{NAN, FRUSTA_ERROR_NOT_FINITE, "nan", 0},
             {INFINITY, FRUSTA_ERROR_NOT_FINITE, "inf", 0},
             {-INFINITY, FRUSTA_ERROR_NOT_FINITE, "-inf", 0},
             {1e300, FRUSTA_ERROR_OUT_OF_RANGE, "1e+300", 0},
             {-1e300, FRUSTA_ERROR_OUT_OF_RANGE, "-1e+300", 0},
             {2e6, FRUSTA_ERROR_OUT_OF_RANGE, "2e+06", 0},
             {-0.001, FRUSTA_ERROR_OUT_OF_RANGE, "-0.001", 1}};
  for (size_t i = 0; i < sizeof inputs / sizeof inputs[0]; ++i)
    for (size_t b = 0; b < sizeof bad / sizeof bad[0]; ++b) {
      if (bad[b].radius_only && !inputs[i].is_radius) continue;
      for (int form = -1; form <= 1; ++form) { /* -1: query_contact */
        segment = kCylinder;
        sphere = touching;
        *inputs[i].target = bad[b].value;
        if (form < 0) {
          memset(&q, 0x5a, sizeof q);
          q.struct_size = (int32_t)sizeof q;
          q_pattern = q;
          snprintf(what, sizeof what, "query_contact(%s = %g)", inputs[i].field, bad[b].value);
          expect_error(what, frusta_query_contact(&segment, &sphere, &q), bad[b].want,
                       inputs[i].field, bad[b].text);
          check(memcmp(&q, &q_pattern, sizeof q) == 0, "%s writes nothing", what);
        } else {
          memset(&c, 0x5a, sizeof c);
          c.struct_size = (int32_t)sizeof c;
          c_pattern = c;
          snprintf(what, sizeof what, "constraint_eval(form %d, %s = %g)", form, inputs[i].field,
                   bad[b].value);
          expect_error(what, frusta_constraint_eval(&segment, &sphere, form, &c), bad[b].want,
                       inputs[i].field, bad[b].text);
          check(memcmp(&c, &c_pattern, sizeof c) == 0, "%s writes nothing", what);
        }
      }
    }
}

/* ------------------------------------------------------------------ sphere trees */

/* A 5 cm cube, triangles counter-clockwise seen from outside. */
static const float kCube[8 * 3] = {0.0f, 0.0f,  0.0f,  0.05f, 0.0f,  0.0f, 0.05f, 0.05f,
                                   0.0f, 0.0f,  0.05f, 0.0f,  0.0f,  0.0f, 0.05f, 0.05f,
                                   0.0f, 0.05f, 0.05f, 0.05f, 0.05f, 0.0f, 0.05f, 0.05f};
static const int32_t kCubeTriangles[36] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                           1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
static const char kTreePath[] = "header_c_test.frtree";
#if !defined(FRUSTA_TEST_NO_BAKER)
static const char kTruncatedPath[] = "header_c_test_truncated.frtree";

#define MAX_LEAVES 20000
#define MAX_HITS 20000
static frusta_sphere g_leaves[MAX_LEAVES], g_leaves_again[MAX_LEAVES];
static frusta_tree_hit g_hits[MAX_HITS], g_hits_again[MAX_HITS], g_hit_pattern[MAX_HITS];
#endif

/* a fast bake: the cube needs a few hundred leaves at 3 mm */
static frusta_bake_def quick_bake_def(void) {
  frusta_bake_def def = frusta_default_bake_def();
  def.target_error = 0.003;
  def.error_samples = 1000;
  return def;
}

/* Every call that takes a tree id, with `id`, fails with `want` naming "sphere tree". */
static void expect_tree_id_refused(frusta_tree_id id, frusta_result want, const char* label) {
  char what[128];
  const frusta_segment segment = {{0.0, 0.0, 0.0}, {0.1, 0.0, 0.0}, 0.01, 0.01};
  frusta_sphere_tree_info info;
  frusta_sphere leaves[2];
  frusta_tree_hit hits[2];
  int32_t count = -7;
  memset(&info, 0, sizeof info);
  info.struct_size = (int32_t)sizeof info;
  snprintf(what, sizeof what, "destroy_sphere_tree(%s)", label);
  expect_error(what, frusta_destroy_sphere_tree(id), want, "sphere tree", NULL);
  snprintf(what, sizeof what, "sphere_tree_save(%s)", label);
  expect_error(what, frusta_sphere_tree_save(id, kTreePath), want, "sphere tree", NULL);
  snprintf(what, sizeof what, "sphere_tree_get_info(%s)", label);
  expect_error(what, frusta_sphere_tree_get_info(id, &info), want, "sphere tree", NULL);
  snprintf(what, sizeof what, "sphere_tree_get_leaves(%s)", label);
  expect_error(what, frusta_sphere_tree_get_leaves(id, leaves, 2, &count), want, "sphere tree",
               NULL);
  snprintf(what, sizeof what, "sphere_tree_query_segment(%s)", label);
  expect_error(what, frusta_sphere_tree_query_segment(id, NULL, &segment, 0.0, -1, hits, 2, &count),
               want, "sphere tree", NULL);
  check(count == -7, "calls on %s leave out_count unchanged", label);
  check(frusta_sphere_tree_is_valid(id) == 0, "frusta_sphere_tree_is_valid(%s) == 0", label);
}

#if !defined(FRUSTA_TEST_NO_BAKER)  /* the baked trees' section; the other is at its end */

/* 1 if v is neither NaN nor infinite: MinGW's isfinite macro passes a double through
 * a float function's argument on its way, which -Wconversion refuses */
static int finite_double(double v) { return v - v == 0.0; }

/* Hits of a query as a flag per leaf; -1 on a non-leaf hit. */
static int hits_to_flags(const frusta_tree_hit* hits, int32_t count, int32_t leaf_count,
                         unsigned char* flags) {
  memset(flags, 0, (size_t)leaf_count);
  for (int32_t i = 0; i < count; ++i) {
    if (hits[i].leaf < 0 || hits[i].leaf >= leaf_count) return -1;
    flags[hits[i].leaf] = 1;
  }
  return 0;
}

static void test_bake_errors(void) {
  const frusta_bake_def good = quick_bake_def();
  frusta_bake_def def;
  const frusta_tree_id sentinel = {4321, 3, 77};
  frusta_tree_id out;
  char what[128];

  const frusta_bake_def defaults = frusta_default_bake_def();
  check(defaults.struct_size == (int32_t)sizeof(frusta_bake_def) && defaults.branching == 4 &&
            defaults.target_error == 0.001 && defaults.max_leaves == 200000 &&
            defaults.max_depth == 40 && defaults.error_samples == 100000 && defaults.seed == 1 &&
            defaults.internal_value != 0,
        "frusta_default_bake_def() has the documented defaults");

  expect_error("bake(def null)",
               frusta_create_sphere_tree_from_mesh(kCube, 8, kCubeTriangles, 36, NULL, &out),
               FRUSTA_ERROR_NULL_POINTER, "def", NULL);
  def = good;
  expect_error("bake(out_tree null)",
               frusta_create_sphere_tree_from_mesh(kCube, 8, kCubeTriangles, 36, &def, NULL),
               FRUSTA_ERROR_NULL_POINTER, "out_tree", NULL);
  def.struct_size = 48;
  out = sentinel;
  expect_error("bake(def.struct_size 48)",
               frusta_create_sphere_tree_from_mesh(kCube, 8, kCubeTriangles, 36, &def, &out),
               FRUSTA_ERROR_STRUCT_SIZE, "frusta_bake_def", "48");
  check(memcmp(&out, &sentinel, sizeof out) == 0, "bake(struct_size 48) leaves out_tree unchanged");
  memset(&def, 0, sizeof def);
  def.struct_size = (int32_t)sizeof def;
  expect_error("bake(memset def)",
               frusta_create_sphere_tree_from_mesh(kCube, 8, kCubeTriangles, 36, &def, &out),
               FRUSTA_ERROR_DEF_NOT_DEFAULTED, "frusta_default_bake_def", NULL);

  /* the mesh */
  def = good;
  expect_error("bake(vertices null)",
               frusta_create_sphere_tree_from_mesh(NULL, 8, kCubeTriangles, 36, &def, &out),
               FRUSTA_ERROR_NULL_POINTER, "vertices", NULL);
  expect_error("bake(indices null)",
               frusta_create_sphere_tree_from_mesh(kCube, 8, NULL, 36, &def, &out),
               FRUSTA_ERROR_NULL_POINTER, "indices", NULL);
  const int32_t vertex_counts[] = {2, 0, -1};
  for (int i = 0; i < 3; ++i) {
    snprintf(what, sizeof what, "bake(vertex_count %d)", vertex_counts[i]);
    expect_error(what,
                 frusta_create_sphere_tree_from_mesh(kCube, vertex_counts[i], kCubeTriangles, 36,
                                                     &def, &out),
                 FRUSTA_ERROR_OUT_OF_RANGE, "vertex_count", NULL);
  }
  const int32_t index_counts[] = {35, 0, -3, 2};
  for (int i = 0; i < 4; ++i) {
    snprintf(what, sizeof what, "bake(index_count %d)", index_counts[i]);
    expect_error(
        what,
        frusta_create_sphere_tree_from_mesh(kCube, 8, kCubeTriangles, index_counts[i], &def, &out),
        FRUSTA_ERROR_OUT_OF_RANGE, "index_count", NULL);
  }
  int32_t bad_indices[36];
  memcpy(bad_indices, kCubeTriangles, sizeof bad_indices);
  bad_indices[5] = 8;
  expect_error("bake(indices[5] = 8 of 8 vertices)",
               frusta_create_sphere_tree_from_mesh(kCube, 8, bad_indices, 36, &def, &out),
               FRUSTA_ERROR_OUT_OF_RANGE, "indices[5]", NULL);
  bad_indices[5] = -1;
  expect_error("bake(indices[5] = -1)",
               frusta_create_sphere_tree_from_mesh(kCube, 8, bad_indices, 36, &def, &out),
               FRUSTA_ERROR_OUT_OF_RANGE, "indices[5]", "-1");
  float bad_vertices[8 * 3];
  const float float_bad[] = {NAN, INFINITY, -INFINITY, 2e6f};
  for (int b = 0; b < 4; ++b) {
    memcpy(bad_vertices, kCube, sizeof bad_vertices);
    bad_vertices[3 * 6 + 1] = float_bad[b]; /* vertex 6, y */
    out = sentinel;
    snprintf(what, sizeof what, "bake(vertex 6 y = %g)", (double)float_bad[b]);
    expect_error(
        what, frusta_create_sphere_tree_from_mesh(bad_vertices, 8, kCubeTriangles, 36, &def, &out),
        b < 3 ? FRUSTA_ERROR_NOT_FINITE : FRUSTA_ERROR_OUT_OF_RANGE, "vertex 6", NULL);
    check(memcmp(&out, &sentinel, sizeof out) == 0, "%s leaves out_tree unchanged", what);
  }
  const float flat[9] = {0, 0, 0, 1, 1, 1, 2, 2, 2}; /* collinear: no area */
  const int32_t one[3] = {0, 1, 2};
  expect_error("bake(a triangle without area)",
               frusta_create_sphere_tree_from_mesh(flat, 3, one, 3, &def, &out),
               FRUSTA_ERROR_OUT_OF_RANGE, "area", NULL);

  /* the parameters */
  const struct {
    const char* label;
    const char* needle;
    int field;
    double value;
  } params[] = {
      {"target_error NaN", "target", 0, NAN},     {"target_error inf", "target", 0, INFINITY},
      {"target_error 0", "target", 0, 0.0},       {"target_error -0.001", "target", 0, -0.001},
      {"max_leaves 0", "leaves", 1, 0.0},         {"max_leaves 2^24 + 1", "leaves", 1, 16777217.0},
      {"max_depth 0", "depth", 2, 0.0},           {"max_depth 41", "depth", 2, 41.0},
      {"error_samples 999", "samples", 3, 999.0}, {"error_samples 1e8 + 1", "samples", 3, 1e8 + 1},
      {"branching 1", "branching", 4, 1.0},       {"branching 17", "branching", 4, 17.0}};
  for (size_t i = 0; i < sizeof params / sizeof params[0]; ++i) {
    def = good;
    switch (params[i].field) {
      case 0:
        def.target_error = params[i].value;
        break;
      case 1:
        def.max_leaves = (int64_t)params[i].value;
        break;
      case 2:
        def.max_depth = (int32_t)params[i].value;
        break;
      case 3:
        def.error_samples = (int64_t)params[i].value;
        break;
      default:
        def.branching = (int32_t)params[i].value;
        break;
    }
    out = sentinel;
    snprintf(what, sizeof what, "bake(%s)", params[i].label);
    /* frusta.h: FRUSTA_ERROR_NOT_FINITE is "NaN or infinity in an input" */
    const frusta_result want =
        finite_double(params[i].value) ? FRUSTA_ERROR_OUT_OF_RANGE : FRUSTA_ERROR_NOT_FINITE;
    expect_error(what,
                 frusta_create_sphere_tree_from_mesh(kCube, 8, kCubeTriangles, 36, &def, &out),
                 want, params[i].needle, NULL);
    check(memcmp(&out, &sentinel, sizeof out) == 0, "%s leaves out_tree unchanged", what);
  }
  /* a tree deeper than max_depth allows */
  def = good;
  def.branching = 2;
  def.max_depth = 1;
  expect_error("bake(branching 2, max_depth 1)",
               frusta_create_sphere_tree_from_mesh(kCube, 8, kCubeTriangles, 36, &def, &out),
               FRUSTA_ERROR_OUT_OF_RANGE, "max_depth", NULL);
}

static void test_sphere_trees(void) {
  char what[160];
  frusta_result r;
  test_bake_errors();

  const frusta_tree_id null_tree = {0, 0, 0};
  expect_tree_id_refused(null_tree, FRUSTA_ERROR_NULL_ID, "null tree id");

  frusta_bake_def def = quick_bake_def();
  frusta_tree_id tree;
  if (!expect_ok("bake(5 cm cube)",
                 frusta_create_sphere_tree_from_mesh(kCube, 8, kCubeTriangles, 36, &def, &tree)))
    return;
  check(!FRUSTA_IS_NULL(tree) && frusta_sphere_tree_is_valid(tree) == 1, "baked tree is valid");

  /* info */
  frusta_sphere_tree_info info, info_pattern;
  memset(&info, 0x5a, sizeof info);
  info.struct_size = (int32_t)sizeof info - 8;
  info_pattern = info;
  expect_error("sphere_tree_get_info(struct_size - 8)", frusta_sphere_tree_get_info(tree, &info),
               FRUSTA_ERROR_STRUCT_SIZE, "frusta_sphere_tree_info", NULL);
  check(memcmp(&info, &info_pattern, sizeof info) == 0, "refused get_info writes nothing");
  expect_error("sphere_tree_get_info(info null)", frusta_sphere_tree_get_info(tree, NULL),
               FRUSTA_ERROR_NULL_POINTER, "info", NULL);
  memset(&info, 0, sizeof info);
  info.struct_size = (int32_t)sizeof info;
  expect_ok("sphere_tree_get_info", frusta_sphere_tree_get_info(tree, &info));
  check(info.triangle_count == 12 && info.branching == 4 && info.leaf_count > 0 &&
            info.node_count >= info.leaf_count && info.depth >= 1 && info.target_error == 0.003 &&
            info.error_samples > 0,
        "info: %d triangles, branching %d, %d leaves, %d nodes, depth %d", info.triangle_count,
        info.branching, info.leaf_count, info.node_count, info.depth);
  check(info.target_met == (info.uncovered_error <= info.target_error &&
                            info.protruding_error <= info.target_error),
        "info.target_met %d agrees with the errors (%g, %g <= %g)", info.target_met,
        info.uncovered_error, info.protruding_error, info.target_error);
  /* The error figures are sampled estimates, so the bounds are compared with the
   * target: leaves reach each face (within the uncovered figure) and stand out of it
   * by no more than a few targets. */
  double out_most = 0.0, in_most = 0.0;
  for (int k = 0; k < 3; ++k) {
    out_most = fmax(out_most, fmax(-info.bounds_min[k], info.bounds_max[k] - 0.05));
    in_most = fmax(in_most, fmax(info.bounds_min[k], 0.05 - info.bounds_max[k]));
  }
  check(out_most <= 2.0 * info.target_error && in_most <= info.uncovered_error + 1e-9,
        "info bounds match the cube: out by %g m at most (protruding %g), in by %g m (uncovered "
        "%g)",
        out_most, info.protruding_error, in_most, info.uncovered_error);
  if (info.leaf_count > MAX_LEAVES) {
    check(0, "test buffers hold %d leaves, the tree has %d", MAX_LEAVES, info.leaf_count);
    frusta_destroy_sphere_tree(tree);
    return;
  }

  /* leaves */
  int32_t count = -7;
  expect_ok("sphere_tree_get_leaves(null, 0) size query",
            frusta_sphere_tree_get_leaves(tree, NULL, 0, &count));
  check(count == info.leaf_count, "leaf count %d == info.leaf_count", count);
  const int32_t leaf_count = count;
  memset(g_leaves, 0x5a, sizeof g_leaves);
  memset(g_leaves_again, 0x5a, sizeof g_leaves_again);
  count = -7;
  expect_error("sphere_tree_get_leaves(out null, capacity 5)",
               frusta_sphere_tree_get_leaves(tree, NULL, 5, &count), FRUSTA_ERROR_NULL_POINTER,
               "out", NULL);
  expect_error("sphere_tree_get_leaves(capacity -1)",
               frusta_sphere_tree_get_leaves(tree, g_leaves, -1, &count), FRUSTA_ERROR_OUT_OF_RANGE,
               "capacity", NULL);
  expect_error("sphere_tree_get_leaves(out_count null)",
               frusta_sphere_tree_get_leaves(tree, g_leaves, leaf_count, NULL),
               FRUSTA_ERROR_NULL_POINTER, "out_count", NULL);
  check(memcmp(g_leaves, g_leaves_again, sizeof g_leaves) == 0,
        "refused get_leaves writes no leaf");
  check(count == -7, "refused get_leaves leaves out_count unchanged (got %d)", count);
  /* a short buffer is no error: what fits is written, and the count says there is more */
  expect_ok("sphere_tree_get_leaves(capacity count - 1)",
            frusta_sphere_tree_get_leaves(tree, g_leaves, leaf_count - 1, &count));
  check(count == leaf_count && memcmp(&g_leaves[leaf_count - 1], &g_leaves_again[leaf_count - 1],
                                      sizeof g_leaves[0]) == 0,
        "a short get_leaves writes count - 1 leaves and counts %d (got %d)", leaf_count, count);
  expect_ok("sphere_tree_get_leaves",
            frusta_sphere_tree_get_leaves(tree, g_leaves, leaf_count, &count));
  int inside = 1;
  for (int32_t i = 0; i < leaf_count; ++i)
    for (int k = 0; k < 3; ++k)
      inside &= g_leaves[i].radius > 0.0 &&
                g_leaves[i].center[k] - g_leaves[i].radius >= info.bounds_min[k] - 1e-12 &&
                g_leaves[i].center[k] + g_leaves[i].radius <= info.bounds_max[k] + 1e-12;
  check(inside, "every leaf lies within info's bounds");

  /* segment queries: the hits are exactly the leaves the contact test reports */
  const frusta_segment far_away = {{0.025, 0.025, 0.3}, {0.025, 0.025, 0.2}, 0.01, 0.008};
  const frusta_segment through = {{0.025, 0.025, 0.1}, {0.02, 0.03, 0.035}, 0.01, 0.008};
  memset(g_hits, 0x5a, sizeof g_hits);
  memcpy(g_hit_pattern, g_hits, sizeof g_hits);
  count = -7;
  expect_ok(
      "query_segment(far away)",
      frusta_sphere_tree_query_segment(tree, NULL, &far_away, 0.0, -1, g_hits, MAX_HITS, &count));
  check(count == 0 && memcmp(g_hits, g_hit_pattern, sizeof g_hits) == 0,
        "a segment 15 cm away hits nothing (%d hits)", count);
  count = -7;
  expect_ok(
      "query_segment(into the cube)",
      frusta_sphere_tree_query_segment(tree, NULL, &through, 0.0, -1, g_hits, MAX_HITS, &count));
  const int32_t hit_count = count;
  static unsigned char flags[MAX_LEAVES], want_flags[MAX_LEAVES];
  int exact = 1, leaves_match = 1;
  const int mapped = hits_to_flags(g_hits, hit_count, leaf_count, flags);
  for (int32_t i = 0; i < hit_count && mapped == 0; ++i)
    leaves_match &=
        memcmp(&g_hits[i].sphere, &g_leaves[g_hits[i].leaf], sizeof(frusta_sphere)) == 0;
  for (int32_t i = 0; i < leaf_count; ++i) {
    frusta_contact_query q;
    memset(&q, 0, sizeof q);
    q.struct_size = (int32_t)sizeof q;
    frusta_query_contact(&through, &g_leaves[i], &q);
    want_flags[i] = (unsigned char)q.contact;
  }
  exact = mapped == 0 && memcmp(flags, want_flags, (size_t)leaf_count) == 0;
  int want_count = 0;
  for (int32_t i = 0; i < leaf_count; ++i) want_count += want_flags[i];
  check(hit_count > 0 && hit_count == want_count && exact,
        "query hits %d leaves, exactly the %d that frusta_query_contact says touch", hit_count,
        want_count);
  check(leaves_match, "each hit carries its leaf's sphere (identity pose)");
  /* a short buffer: at most capacity written, out_count still the total */
  if (hit_count > 3) {
    memcpy(g_hits_again, g_hit_pattern, sizeof g_hits_again);
    count = -7;
    expect_ok(
        "query_segment(capacity 3)",
        frusta_sphere_tree_query_segment(tree, NULL, &through, 0.0, -1, g_hits_again, 3, &count));
    check(count == hit_count && memcmp(g_hits_again, g_hits, 3 * sizeof g_hits[0]) == 0 &&
              memcmp(&g_hits_again[3], &g_hit_pattern[3], sizeof g_hits[0]) == 0,
          "capacity 3: the first 3 hits written, out_count %d is the total", count);
    expect_ok("query_segment(out null, capacity 0): count only",
              frusta_sphere_tree_query_segment(tree, NULL, &through, 0.0, -1, NULL, 0, &count));
    check(count == hit_count, "count-only query finds %d hits", count);
  }
  /* a margin only adds hits */
  int32_t margin_count = -7;
  frusta_sphere_tree_query_segment(tree, NULL, &through, 0.005, -1, NULL, 0, &margin_count);
  check(margin_count >= hit_count, "a 5 mm margin finds at least as many (%d >= %d)", margin_count,
        hit_count);
  /* the object's pose moves the tree: move both by the same rigid motion */
  const double h = sqrt(0.5);
  const frusta_pose identity = {{0, 0, 0}, {0, 0, 0, 1}};
  const frusta_pose moved = {{1.0, 2.0, 3.0}, {0.0, 0.0, h, h}}; /* quarter turn about z */
  frusta_segment moved_segment = through;
  moved_segment.proximal[0] = 1.0 - through.proximal[1];
  moved_segment.proximal[1] = 2.0 + through.proximal[0];
  moved_segment.proximal[2] = 3.0 + through.proximal[2];
  moved_segment.distal[0] = 1.0 - through.distal[1];
  moved_segment.distal[1] = 2.0 + through.distal[0];
  moved_segment.distal[2] = 3.0 + through.distal[2];
  count = -7;
  expect_ok("query_segment(identity pose)",
            frusta_sphere_tree_query_segment(tree, &identity, &through, 0.0, -1, g_hits_again,
                                             MAX_HITS, &count));
  check(count == hit_count && memcmp(g_hits_again, g_hits, (size_t)count * sizeof g_hits[0]) == 0,
        "an identity pose gives the same hits as a null pose");
  count = -7;
  expect_ok("query_segment(moved pose, moved segment)",
            frusta_sphere_tree_query_segment(tree, &moved, &moved_segment, 0.0, -1, g_hits_again,
                                             MAX_HITS, &count));
  double worst = 0.0;
  int same_leaves = count == hit_count;
  for (int32_t i = 0; i < count && same_leaves; ++i) {
    const frusta_sphere* a = &g_leaves[g_hits_again[i].leaf];
    const double want[3] = {1.0 - a->center[1], 2.0 + a->center[0], 3.0 + a->center[2]};
    for (int k = 0; k < 3; ++k)
      worst = fmax(worst, fabs(g_hits_again[i].sphere.center[k] - want[k]));
    same_leaves &= g_hits_again[i].sphere.radius == a->radius;
  }
  check(same_leaves && worst < 1e-12,
        "moving tree and segment together: the same %d hits, in world coordinates (error %g)",
        count, worst);
  /* max_level 0: the root stands in for the whole tree */
  count = -7;
  expect_ok("query_segment(max_level 0)",
            frusta_sphere_tree_query_segment(tree, NULL, &through, 0.0, 0, g_hits_again, MAX_HITS,
                                             &count));
  check(count == 1 && g_hits_again[0].leaf == -1,
        "max_level 0 returns the root alone (%d hits, leaf %d)", count, g_hits_again[0].leaf);

  /* query errors: out and out_count untouched */
  memcpy(g_hits_again, g_hit_pattern, sizeof g_hits_again);
  frusta_pose bad_pose = identity;
  bad_pose.position[0] = NAN;
  count = -7;
  expect_error("query_segment(pose.position[0] NaN)",
               frusta_sphere_tree_query_segment(tree, &bad_pose, &through, 0.0, -1, g_hits_again,
                                                MAX_HITS, &count),
               FRUSTA_ERROR_NOT_FINITE, "pose.position[0]", "nan");
  bad_pose = identity;
  bad_pose.rotation[3] = 0.0;
  expect_error("query_segment(zero quaternion)",
               frusta_sphere_tree_query_segment(tree, &bad_pose, &through, 0.0, -1, g_hits_again,
                                                MAX_HITS, &count),
               FRUSTA_ERROR_OUT_OF_RANGE, "pose.rotation", NULL);
  expect_error(
      "query_segment(segment null)",
      frusta_sphere_tree_query_segment(tree, NULL, NULL, 0.0, -1, g_hits_again, MAX_HITS, &count),
      FRUSTA_ERROR_NULL_POINTER, "segment", NULL);
  frusta_segment bad_segment = through;
  bad_segment.distal_radius = -0.001;
  expect_error("query_segment(segment.distal_radius -0.001)",
               frusta_sphere_tree_query_segment(tree, NULL, &bad_segment, 0.0, -1, g_hits_again,
                                                MAX_HITS, &count),
               FRUSTA_ERROR_OUT_OF_RANGE, "segment.distal_radius", "-0.001");
  bad_segment = through;
  bad_segment.proximal[2] = INFINITY;
  expect_error("query_segment(segment.proximal[2] inf)",
               frusta_sphere_tree_query_segment(tree, NULL, &bad_segment, 0.0, -1, g_hits_again,
                                                MAX_HITS, &count),
               FRUSTA_ERROR_NOT_FINITE, "segment.proximal[2]", "inf");
  const double margins[] = {NAN, -0.001, 1e300};
  for (int i = 0; i < 3; ++i) {
    snprintf(what, sizeof what, "query_segment(margin %g)", margins[i]);
    expect_error(what,
                 frusta_sphere_tree_query_segment(tree, NULL, &through, margins[i], -1,
                                                  g_hits_again, MAX_HITS, &count),
                 i == 0 ? FRUSTA_ERROR_NOT_FINITE : FRUSTA_ERROR_OUT_OF_RANGE, "margin", NULL);
  }
  const int32_t levels[] = {-2, 41};
  for (int i = 0; i < 2; ++i) {
    snprintf(what, sizeof what, "query_segment(max_level %d)", levels[i]);
    expect_error(what,
                 frusta_sphere_tree_query_segment(tree, NULL, &through, 0.0, levels[i],
                                                  g_hits_again, MAX_HITS, &count),
                 FRUSTA_ERROR_OUT_OF_RANGE, "max_level", NULL);
  }
  expect_error(
      "query_segment(capacity -1)",
      frusta_sphere_tree_query_segment(tree, NULL, &through, 0.0, -1, g_hits_again, -1, &count),
      FRUSTA_ERROR_OUT_OF_RANGE, "capacity", NULL);
  expect_error("query_segment(out null, capacity 5)",
               frusta_sphere_tree_query_segment(tree, NULL, &through, 0.0, -1, NULL, 5, &count),
               FRUSTA_ERROR_NULL_POINTER, "out", NULL);
  check(count == -7 && memcmp(g_hits_again, g_hit_pattern, sizeof g_hits_again) == 0,
        "refused queries write neither hits nor out_count");
  expect_error(
      "query_segment(out_count null)",
      frusta_sphere_tree_query_segment(tree, NULL, &through, 0.0, -1, g_hits_again, MAX_HITS, NULL),
      FRUSTA_ERROR_NULL_POINTER, "out_count", NULL);

  /* save and load: the same tree back */
  expect_error("sphere_tree_save(path null)", frusta_sphere_tree_save(tree, NULL),
               FRUSTA_ERROR_NULL_POINTER, "path", NULL);
  expect_error("sphere_tree_save(into a missing folder)",
               frusta_sphere_tree_save(tree, "no/such/folder/tree.frtree"), FRUSTA_ERROR_IO,
               "no/such/folder", NULL);
  expect_ok("save_sphere_tree", frusta_sphere_tree_save(tree, kTreePath));
  frusta_tree_id loaded;
  r = frusta_create_sphere_tree_from_file(kTreePath, &loaded);
  if (expect_ok("create_sphere_tree_from_file(saved file)", r)) {
    frusta_sphere_tree_info loaded_info;
    memset(&loaded_info, 0, sizeof loaded_info);
    loaded_info.struct_size = (int32_t)sizeof loaded_info;
    frusta_sphere_tree_get_info(loaded, &loaded_info);
    check(memcmp(&loaded_info, &info, sizeof info) == 0,
          "the loaded tree's info is the saved one's");
    count = 0;
    frusta_sphere_tree_get_leaves(loaded, g_leaves_again, MAX_LEAVES, &count);
    check(count == leaf_count &&
              memcmp(g_leaves_again, g_leaves, (size_t)leaf_count * sizeof g_leaves[0]) == 0,
          "the loaded tree has the saved leaves, bit for bit");
    check(loaded.index1 != tree.index1 && frusta_sphere_tree_is_valid(tree) == 1,
          "loading makes a second, independent tree");
    frusta_destroy_sphere_tree(loaded);
  }
  const frusta_tree_id tree_sentinel = {4321, 3, 77};
  frusta_tree_id not_loaded = tree_sentinel;
  expect_error("create_sphere_tree_from_file(path null)",
               frusta_create_sphere_tree_from_file(NULL, &not_loaded), FRUSTA_ERROR_NULL_POINTER,
               "path", NULL);
  expect_error("create_sphere_tree_from_file(out_tree null)",
               frusta_create_sphere_tree_from_file(kTreePath, NULL), FRUSTA_ERROR_NULL_POINTER,
               "out_tree", NULL);
  expect_error("create_sphere_tree_from_file(missing file)",
               frusta_create_sphere_tree_from_file("no_such_file.frtree", &not_loaded),
               FRUSTA_ERROR_IO, "no_such_file.frtree", NULL);
  /* a file cut short, and a file that is not a tree at all */
  FILE* in = fopen(kTreePath, "rb");
  static unsigned char bytes[1 << 20];
  const size_t size = in ? fread(bytes, 1, sizeof bytes, in) : 0;
  if (in) fclose(in);
  check(size > 64 && size < sizeof bytes, "the saved file has %zu bytes", size);
  FILE* cut = fopen(kTruncatedPath, "wb");
  if (cut) {
    fwrite(bytes, 1, size - 17, cut);
    fclose(cut);
  }
  r = frusta_create_sphere_tree_from_file(kTruncatedPath, &not_loaded);
  check((r == FRUSTA_ERROR_CORRUPT_FILE || r == FRUSTA_ERROR_FILE_FORMAT) &&
            contains(frusta_last_error(), kTruncatedPath),
        "create_sphere_tree_from_file(file cut short) -> %s: \"%s\"", frusta_result_name(r),
        frusta_last_error());
  cut = fopen(kTruncatedPath, "wb");
  if (cut) {
    bytes[size / 2] ^= 0x40; /* one flipped bit in the middle */
    fwrite(bytes, 1, size, cut);
    fclose(cut);
  }
  expect_error("create_sphere_tree_from_file(one bit flipped)",
               frusta_create_sphere_tree_from_file(kTruncatedPath, &not_loaded),
               FRUSTA_ERROR_CORRUPT_FILE, kTruncatedPath, NULL);
  cut = fopen(kTruncatedPath, "wb");
  if (cut) {
    fputs("definitely not a sphere tree\n", cut);
    fclose(cut);
  }
  expect_error("create_sphere_tree_from_file(text file)",
               frusta_create_sphere_tree_from_file(kTruncatedPath, &not_loaded),
               FRUSTA_ERROR_FILE_FORMAT, kTruncatedPath, NULL);
  check(memcmp(&not_loaded, &tree_sentinel, sizeof not_loaded) == 0,
        "failed loads leave out_tree unchanged");
  remove(kTruncatedPath);
  remove(kTreePath);

  /* destroy: stale, also after the slot is reused */
  expect_ok("destroy_sphere_tree", frusta_destroy_sphere_tree(tree));
  expect_tree_id_refused(tree, FRUSTA_ERROR_STALE_ID, "destroyed tree id");
  frusta_tree_id again;
  if (expect_ok("bake again",
                frusta_create_sphere_tree_from_mesh(kCube, 8, kCubeTriangles, 36, &def, &again))) {
    check(again.index1 == tree.index1 && again.generation != tree.generation,
          "the new tree reuses the slot with a new generation");
    expect_tree_id_refused(tree, FRUSTA_ERROR_STALE_ID, "old tree id after reuse");
    check(frusta_sphere_tree_is_valid(again) == 1, "the new tree is still valid");
    const frusta_tree_id foreign = {again.index1, 1, again.generation};
    expect_tree_id_refused(foreign, FRUSTA_ERROR_STALE_ID, "tree id with world0 1");
    expect_ok("destroy the new tree", frusta_destroy_sphere_tree(again));
  }
}
#else
/* A build without the baker (Windows: no Embree here): a bake is refused as such, with
 * the reason, after the def's own checks; the trees' other calls need a baked tree, and
 * the builds with the baker test them. */
static void test_sphere_trees(void) {
  const frusta_tree_id sentinel = {4321, 3, 77};
  frusta_tree_id out = sentinel;
  const frusta_bake_def def = quick_bake_def();
  expect_error("bake(def null)", frusta_create_sphere_tree_from_mesh(kCube, 8, kCubeTriangles, 36, NULL, &out),
               FRUSTA_ERROR_NULL_POINTER, "def", NULL);
  expect_error("bake(5 cm cube) without a baker",
               frusta_create_sphere_tree_from_mesh(kCube, 8, kCubeTriangles, 36, &def, &out),
               FRUSTA_ERROR_UNAVAILABLE, "cannot bake", NULL);
  check(memcmp(&out, &sentinel, sizeof out) == 0, "a refused bake leaves out_tree unchanged");
  const frusta_tree_id null_tree = {0, 0, 0};
  expect_tree_id_refused(null_tree, FRUSTA_ERROR_NULL_ID, "null tree id");
}
#endif

/* ------------------------------------------------------------------ threads */

typedef struct thread_result {
  char initial[256];
  char after[256];
  int mismatches;
} thread_result;

/* Fails with its own error many times while another thread does the same with a
 * different error: each must always read back its own message. */
static void* fail_on_a_thread(void* arg) {
  thread_result* out = (thread_result*)arg;
  snprintf(out->initial, sizeof out->initial, "%s", frusta_last_error());
  for (int i = 0; i < 20000; ++i) {
    frusta_check_abi(-42);
    if (!contains(frusta_last_error(), "ABI -42")) ++out->mismatches;
  }
  snprintf(out->after, sizeof out->after, "%s", frusta_last_error());
  return NULL;
}

static void test_thread_local_error(void) {
  const frusta_hand_id null_id = {0, 0, 0};
  frusta_destroy_hand(null_id);
  char mine[256];
  snprintf(mine, sizeof mine, "%s", frusta_last_error());
  check(contains(mine, "null"), "main thread has its own error: \"%s\"", mine);

  thread_result result;
  memset(&result, 0, sizeof result);
  pthread_t thread;
  if (!check(pthread_create(&thread, NULL, fail_on_a_thread, &result) == 0, "pthread_create"))
    return;
  int main_mismatches = 0;
  for (int i = 0; i < 20000; ++i) {
    frusta_destroy_hand(null_id);
    if (strcmp(frusta_last_error(), mine) != 0) ++main_mismatches;
  }
  pthread_join(thread, NULL);
  check(result.initial[0] == '\0', "a new thread starts with \"\" (got \"%s\")", result.initial);
  check(result.mismatches == 0 && contains(result.after, "ABI -42"),
        "the other thread always read its own message (%d mismatches): \"%s\"", result.mismatches,
        result.after);
  check(main_mismatches == 0 && strcmp(frusta_last_error(), mine) == 0,
        "the main thread's message survived the other thread's failures (%d mismatches)",
        main_mismatches);
}

/* ------------------------------------------------------------------ main */

int main(void) {
  /* before any failure the message is empty */
  check(frusta_last_error() != NULL && frusta_last_error()[0] == '\0',
        "frusta_last_error() is \"\" before any failure");
  test_version_and_abi();
  test_result_names();
  test_default_def();
  test_create_destroy();
  test_def_errors();
  test_set_size();
  test_ids();
  test_hand_inputs();
  test_palm_pose_and_clamping();
  test_queries();
  test_sphere_trees();
  test_thread_local_error();
  printf("%d passed, %d failed\n", g_passed, g_failed);
  return g_failed == 0 ? 0 : 1;
}
