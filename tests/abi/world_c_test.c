/* SPDX-License-Identifier: MIT */
/*
 * world_c_test: the world section of frusta.h compiled as C11 and called from C, as a
 * C host (or a P/Invoke binding) calls it.
 *
 * Each check prints one line, "ok   ..." or "FAIL ...", and the last line is
 * "N passed, M failed"; the exit status is non-zero when anything failed.
 * Error paths check three things: the result code, a thread-local message that
 * names the field (and, where it is a number, the value) at fault, and that nothing
 * changed: out parameters keep a sentinel byte pattern, and the world's hands,
 * objects and inputs read back as before.
 *
 * The happy path presses the default open hand's index fingertip into a 2 cm box
 * baked from 12 triangles, lets a box fall under gravity and runs a world on its own
 * thread for about 50 ms. Only frusta/frusta.h and the C standard library (plus
 * POSIX nanosleep) are used here; nothing from native/src.
 */
#define _POSIX_C_SOURCE 200809L /* nanosleep under -std=c11 */

#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "c_check.h"
#include "frusta/frusta.h"

/* The C compiler must lay the structs out as the C++ library does; the full
 * offset table lives in abi_layout_test.cpp, these are its sizes. */
_Static_assert(sizeof(frusta_world_id) == 8, "frusta_world_id layout changed");
_Static_assert(sizeof(frusta_object_id) == 8, "frusta_object_id layout changed");
_Static_assert(sizeof(frusta_world_def) == 152, "frusta_world_def layout changed");
_Static_assert(offsetof(frusta_world_def, internal_value) == 148, "frusta_world_def layout changed");
_Static_assert(sizeof(frusta_object_def) == 224, "frusta_object_def layout changed");
_Static_assert(offsetof(frusta_object_def, internal_value) == 216,
               "frusta_object_def layout changed");
_Static_assert(sizeof(frusta_world_state) == 112, "frusta_world_state layout changed");
_Static_assert(sizeof(frusta_world_hand) == 840, "frusta_world_hand layout changed");
_Static_assert(sizeof(frusta_world_contact) == 152, "frusta_world_contact layout changed");
_Static_assert(sizeof(frusta_object_state) == 168, "frusta_object_state layout changed");


static double dot3(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static double norm3(const double a[3]) { return sqrt(dot3(a, a)); }

static int finite3(const double a[3]) {
  return isfinite(a[0]) && isfinite(a[1]) && isfinite(a[2]);
}

static void sleep_ms(long ms) {
  const struct timespec t = {ms / 1000, (ms % 1000) * 1000000L};
  nanosleep(&t, NULL);
}

/* ------------------------------------------------------------------ sentinels */

/* Out parameters are filled with this byte first; a failed call must leave it. */
#define SENTINEL 0xA5

static void fill(void* p, size_t n) { memset(p, SENTINEL, n); }

static int is_sentinel(const void* p, size_t n) {
  const unsigned char* bytes = (const unsigned char*)p;
  for (size_t i = 0; i < n; ++i)
    if (bytes[i] != SENTINEL) return 0;
  return 1;
}

/* Output structs: sentinel bytes everywhere but a correct struct_size. */
static frusta_world_state sentinel_state(void) {
  frusta_world_state s;
  fill(&s, sizeof s);
  s.struct_size = (int32_t)sizeof s;
  return s;
}

static frusta_world_hand sentinel_hand(void) {
  frusta_world_hand h;
  fill(&h, sizeof h);
  h.struct_size = (int32_t)sizeof h;
  return h;
}

static frusta_object_state sentinel_object(void) {
  frusta_object_state o;
  fill(&o, sizeof o);
  o.struct_size = (int32_t)sizeof o;
  return o;
}

/* ------------------------------------------------------------------ scene */

/* A 2 cm box around its centre: 8 corners, 12 triangles counter-clockwise seen
 * from outside. */
#define BOX_HALF 0.01
static const double kCorners[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                      {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
static const int32_t kBoxTriangles[36] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                          1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};

static frusta_tree_id g_box;  /* the box's sphere tree, default bake def */
static frusta_segment g_tip;  /* the open default hand's index distal segment, hand frame */

static const frusta_world_id kNullWorld = {0, 0, 0};
static const frusta_object_id kNullObject = {0, 0, 0};

static int bake_box(frusta_tree_id* out) {
  float vertices[8 * 3];
  for (int v = 0; v < 8; ++v)
    for (int k = 0; k < 3; ++k) vertices[3 * v + k] = (float)(BOX_HALF * kCorners[v][k]);
  const frusta_bake_def def = frusta_default_bake_def();
  return expect_ok("bake a 2 cm box (12 triangles, default bake def)",
                   frusta_create_sphere_tree_from_mesh(vertices, 8, kBoxTriangles, 36, &def, out));
}

/* The index fingertip of a standalone default hand at the identity pose, open. */
static int find_index_tip(void) {
  const frusta_hand_def def = frusta_default_hand_def();
  frusta_hand_id hand;
  frusta_segment segments[FRUSTA_HAND_SEGMENT_COUNT];
  int32_t count = 0;
  if (!expect_ok("create a standalone default hand", frusta_create_hand(&def, &hand))) return 0;
  const frusta_result r =
      frusta_hand_get_segments(hand, segments, FRUSTA_HAND_SEGMENT_COUNT, &count);
  frusta_destroy_hand(hand);
  if (!expect_ok("get its segments", r)) return 0;
  g_tip = segments[FRUSTA_FINGER_INDEX * FRUSTA_SEGMENTS_PER_FINGER + 2];
  return check(g_tip.distal[0] > 0.15 && g_tip.distal[0] < 0.2 && g_tip.distal_radius > 0.0,
               "index fingertip centre at (%g, %g, %g), radius %g", g_tip.distal[0],
               g_tip.distal[1], g_tip.distal[2], g_tip.distal_radius);
}

/* A box under the index fingertip, its top face touching the tip from below and its
 * centre 5 mm behind the tip's centre: under the distal segment only. */
static frusta_object_def box_under_tip(void) {
  frusta_object_def def = frusta_default_object_def();
  def.pose.position[0] = g_tip.distal[0] + BOX_HALF - 0.005;
  def.pose.position[1] = g_tip.distal[1];
  def.pose.position[2] = g_tip.distal[2] - (g_tip.distal_radius + BOX_HALF);
  return def;
}

/* The open hand, lowered `depth` metres (z is out of the back of the hand). */
static void open_hand(double depth, frusta_pose* palm, double angles[FRUSTA_HAND_JOINT_COUNT]) {
  const frusta_pose pose = {{0.0, 0.0, -depth}, {0.0, 0.0, 0.0, 1.0}};
  *palm = pose;
  for (int j = 0; j < FRUSTA_HAND_JOINT_COUNT; ++j) angles[j] = 0.0;
}

static int make_world(const frusta_world_def* def, frusta_world_id* out, const char* what) {
  char text[128];
  snprintf(text, sizeof text, "create world (%s)", what);
  return expect_ok(text, frusta_create_world(def, out));
}

static int add_default_hand(frusta_world_id world, frusta_hand_id* out) {
  const frusta_hand_def def = frusta_default_hand_def();
  return expect_ok("add the default hand", frusta_create_world_hand(world, &def, out));
}

/* Step n times and latch the newest step into *state. */
static int step_and_read(frusta_world_id world, int n, frusta_world_state* state) {
  for (int i = 0; i < n; ++i)
    if (frusta_world_step(world) != FRUSTA_OK) return 0;
  memset(state, 0, sizeof *state);
  state->struct_size = (int32_t)sizeof *state;
  return frusta_world_read(world, state) == FRUSTA_OK;
}

/* Objects present after one more step; -1 if stepping or reading failed. */
static int32_t objects_after_a_step(frusta_world_id world) {
  frusta_world_state state;
  return step_and_read(world, 1, &state) ? state.object_count : -1;
}

static int get_object(frusta_world_id world, frusta_object_id object, frusta_object_state* out) {
  memset(out, 0, sizeof *out);
  out->struct_size = (int32_t)sizeof *out;
  return frusta_world_get_object(world, object, out) == FRUSTA_OK;
}

static int get_hand(frusta_world_id world, frusta_hand_id hand, frusta_world_hand* out) {
  memset(out, 0, sizeof *out);
  out->struct_size = (int32_t)sizeof *out;
  return frusta_world_get_hand(world, hand, out) == FRUSTA_OK;
}

/* ------------------------------------------------------------------ defaults */

static void test_defaults(void) {
  const frusta_world_def w = frusta_default_world_def();
  check(w.struct_size == (int32_t)sizeof(frusta_world_def), "default world def struct_size %d",
        w.struct_size);
  check(w.internal_value != 0, "default world def carries its cookie");
  check(w.max_objects == 64 && w.rate_hz == 1000.0 && w.spin_us == 200.0,
        "world def: max_objects 64, rate_hz 1000, spin_us 200 (%d, %g, %g)", w.max_objects,
        w.rate_hz, w.spin_us);
  check(w.gravity[0] == 0.0 && w.gravity[1] == 0.0 && w.gravity[2] == 0.0,
        "world def: gravity off");
  check(w.prediction_margin == 0.002 && w.lod_error == 0.0 && w.max_iterations == 2 &&
            w.max_substeps == 64,
        "world def: prediction_margin 0.002, lod_error 0, max_iterations 2, max_substeps 64");
  check(w.max_contacts_per_hand == 256 && w.command_capacity == 256 && w.max_hands == 8 &&
            w.realtime_priority == 1,
        "world def: max_contacts_per_hand 256, command_capacity 256, max_hands 8, realtime");
  check(w.max_candidates_per_hand == 1024, "world def: max_candidates_per_hand 1024 (%d)",
        w.max_candidates_per_hand);
  check(w.max_fingertip_force == 10.0 && w.max_finger_resistance == 10.0 &&
            w.max_joint_torque == 0.5 && w.max_palm_force == 20.0 && w.max_palm_torque == 1.0,
        "world def: device limits 10 N, 10 N, 0.5 N m, 20 N, 1 N m");
  const frusta_world_def w2 = frusta_default_world_def();
  check(memcmp(&w, &w2, sizeof w) == 0, "frusta_default_world_def() is deterministic");

  const frusta_object_def o = frusta_default_object_def();
  check(o.struct_size == (int32_t)sizeof(frusta_object_def), "default object def struct_size %d",
        o.struct_size);
  check(o.internal_value != 0 && o.reserved0 == 0, "default object def carries its cookie");
  check(o.dynamic == 0, "object def: kinematic");
  check(o.pose.position[0] == 0.0 && o.pose.position[1] == 0.0 && o.pose.position[2] == 0.0 &&
            o.pose.rotation[0] == 0.0 && o.pose.rotation[1] == 0.0 &&
            o.pose.rotation[2] == 0.0 && o.pose.rotation[3] == 1.0,
        "object def: identity pose");
  check(o.stiffness[0] == 400.0 && o.stiffness[1] == 400.0 && o.stiffness[2] == 400.0 &&
            o.friction == 0.6 && o.tangential_stiffness == 1e4 && o.normal_damping == 0.0 &&
            o.tangential_damping == 0.0,
        "object def: stiffness 400, friction 0.6, tangential_stiffness 1e4, damping 0 (%g, %g, "
        "%g, %g, %g)",
        o.stiffness[0], o.friction, o.tangential_stiffness, o.normal_damping,
        o.tangential_damping);
  check(o.mass == 0.1 && o.inertia[0] == 4e-5 && o.inertia[1] == 4e-5 && o.inertia[2] == 4e-5,
        "object def: mass 0.1, inertia 4e-5");
  int at_rest = o.linear_damping == 0.0 && o.angular_damping == 0.0;
  for (int k = 0; k < 3; ++k) at_rest &= o.linear_velocity[k] == 0.0 && o.angular_velocity[k] == 0.0;
  check(at_rest, "object def: at rest, no damping");
  const frusta_object_def o2 = frusta_default_object_def();
  check(memcmp(&o, &o2, sizeof o) == 0, "frusta_default_object_def() is deterministic");
}

/* ------------------------------------------------------------------ create */

/* A double field of a def to corrupt, the result wanted and the text the message
 * must contain besides the field's name (null: the field's name only). */
typedef struct double_case {
  const char* field;
  size_t offset;
  double value;
  frusta_result want;
  const char* text;
} double_case;

typedef struct int_case {
  const char* field;
  size_t offset;
  int32_t value;
} int_case;

#define WORLD_FIELD(name) #name, offsetof(frusta_world_def, name)
#define OBJECT_FIELD(name) #name, offsetof(frusta_object_def, name)

static void test_create_errors(void) {
  const frusta_world_def good = frusta_default_world_def();
  frusta_world_def def;
  frusta_world_id out, sentinel;
  fill(&sentinel, sizeof sentinel);
  char what[128];

  out = sentinel;
  expect_error("create_world(def null)", frusta_create_world(NULL, &out),
               FRUSTA_ERROR_NULL_POINTER, "def", NULL);
  check(memcmp(&out, &sentinel, sizeof out) == 0, "def null leaves out_world unchanged");
  def = good;
  expect_error("create_world(out_world null)", frusta_create_world(&def, NULL),
               FRUSTA_ERROR_NULL_POINTER, "out_world", NULL);

  const int32_t sizes[] = {0, (int32_t)sizeof(frusta_world_def) - 8,
                           (int32_t)sizeof(frusta_world_def) + 8, -1};
  for (int i = 0; i < 4; ++i) {
    def = good;
    def.struct_size = sizes[i];
    out = sentinel;
    snprintf(what, sizeof what, "create_world(struct_size %d)", sizes[i]);
    expect_error(what, frusta_create_world(&def, &out), FRUSTA_ERROR_STRUCT_SIZE,
                 "frusta_world_def", NULL);
    check(memcmp(&out, &sentinel, sizeof out) == 0, "%s leaves out_world unchanged", what);
  }

  /* built by hand: memset + struct_size, no cookie */
  memset(&def, 0, sizeof def);
  def.struct_size = (int32_t)sizeof def;
  out = sentinel;
  expect_error("create_world(memset def)", frusta_create_world(&def, &out),
               FRUSTA_ERROR_DEF_NOT_DEFAULTED, "frusta_default_world_def", NULL);
  check(memcmp(&out, &sentinel, sizeof out) == 0, "memset def leaves out_world unchanged");
  /* a defaulted def whose cookie was overwritten, e.g. a drifted C# mirror */
  def = good;
  def.internal_value = 0;
  expect_error("create_world(def.internal_value 0)", frusta_create_world(&def, &out),
               FRUSTA_ERROR_DEF_NOT_DEFAULTED, "internal_value", NULL);
  check(memcmp(&out, &sentinel, sizeof out) == 0, "internal_value 0 leaves out_world unchanged");

  const double_case doubles[] = {
      {WORLD_FIELD(rate_hz), NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
      {WORLD_FIELD(rate_hz), INFINITY, FRUSTA_ERROR_NOT_FINITE, "inf"},
      {WORLD_FIELD(rate_hz), 0.0, FRUSTA_ERROR_OUT_OF_RANGE, NULL},
      {WORLD_FIELD(rate_hz), 0.5, FRUSTA_ERROR_OUT_OF_RANGE, "0.5"},
      {WORLD_FIELD(rate_hz), -1000.0, FRUSTA_ERROR_OUT_OF_RANGE, "-1000"},
      {WORLD_FIELD(rate_hz), 1e6, FRUSTA_ERROR_OUT_OF_RANGE, "1e+06"},
      {WORLD_FIELD(spin_us), NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
      {WORLD_FIELD(spin_us), -1.0, FRUSTA_ERROR_OUT_OF_RANGE, "-1"},
      {WORLD_FIELD(spin_us), 1500.0, FRUSTA_ERROR_OUT_OF_RANGE, "1500"}, /* > 1 ms period */
      {WORLD_FIELD(gravity[1]), NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
      {WORLD_FIELD(gravity[2]), -INFINITY, FRUSTA_ERROR_NOT_FINITE, "-inf"},
      {WORLD_FIELD(gravity[0]), 1e4, FRUSTA_ERROR_OUT_OF_RANGE, "10000"},
      {WORLD_FIELD(prediction_margin), NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
      {WORLD_FIELD(prediction_margin), 0.0, FRUSTA_ERROR_OUT_OF_RANGE, NULL},
      {WORLD_FIELD(prediction_margin), -0.001, FRUSTA_ERROR_OUT_OF_RANGE, "-0.001"},
      {WORLD_FIELD(prediction_margin), 0.2, FRUSTA_ERROR_OUT_OF_RANGE, "0.2"},
      {WORLD_FIELD(lod_error), INFINITY, FRUSTA_ERROR_NOT_FINITE, "inf"},
      {WORLD_FIELD(lod_error), -0.001, FRUSTA_ERROR_OUT_OF_RANGE, "-0.001"},
      {WORLD_FIELD(lod_error), 2.0, FRUSTA_ERROR_OUT_OF_RANGE, "2"},
      {WORLD_FIELD(input_delay), NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
      {WORLD_FIELD(input_delay), -0.001, FRUSTA_ERROR_OUT_OF_RANGE, "-0.001"},
      {WORLD_FIELD(input_delay), 0.2, FRUSTA_ERROR_OUT_OF_RANGE, "0.2"},
      {WORLD_FIELD(max_extrapolation), INFINITY, FRUSTA_ERROR_NOT_FINITE, "inf"},
      {WORLD_FIELD(max_extrapolation), -1.0, FRUSTA_ERROR_OUT_OF_RANGE, "-1"},
      {WORLD_FIELD(max_extrapolation), 1.0, FRUSTA_ERROR_OUT_OF_RANGE, "1"},
      {WORLD_FIELD(max_fingertip_force), NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
      {WORLD_FIELD(max_fingertip_force), INFINITY, FRUSTA_ERROR_NOT_FINITE, "inf"},
      {WORLD_FIELD(max_fingertip_force), -1.0, FRUSTA_ERROR_OUT_OF_RANGE, "-1"},
      {WORLD_FIELD(max_fingertip_force), 2e9, FRUSTA_ERROR_OUT_OF_RANGE, "2e+09"},
      {WORLD_FIELD(max_finger_resistance), NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
      {WORLD_FIELD(max_finger_resistance), -1.0, FRUSTA_ERROR_OUT_OF_RANGE, "-1"},
      {WORLD_FIELD(max_joint_torque), NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
      {WORLD_FIELD(max_joint_torque), -0.5, FRUSTA_ERROR_OUT_OF_RANGE, "-0.5"},
      {WORLD_FIELD(max_palm_force), -INFINITY, FRUSTA_ERROR_NOT_FINITE, "-inf"},
      {WORLD_FIELD(max_palm_force), -1.0, FRUSTA_ERROR_OUT_OF_RANGE, "-1"},
      {WORLD_FIELD(max_palm_torque), NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
      {WORLD_FIELD(max_palm_torque), -1.0, FRUSTA_ERROR_OUT_OF_RANGE, "-1"},
  };
  for (size_t i = 0; i < sizeof doubles / sizeof doubles[0]; ++i) {
    const double_case* c = &doubles[i];
    def = good;
    memcpy((char*)&def + c->offset, &c->value, sizeof c->value);
    out = sentinel;
    snprintf(what, sizeof what, "create_world(%s = %g)", c->field, c->value);
    /* gravity[1] is reported as gravity[1]; scalars by their name */
    expect_error(what, frusta_create_world(&def, &out), c->want, c->field, c->text);
    check(memcmp(&out, &sentinel, sizeof out) == 0, "%s leaves out_world unchanged", what);
  }

  const int_case ints[] = {
      {WORLD_FIELD(max_objects), 0},          {WORLD_FIELD(max_objects), -1},
      {WORLD_FIELD(max_objects), 65536},      {WORLD_FIELD(max_objects), 65537},
      {WORLD_FIELD(max_iterations), 0},       {WORLD_FIELD(max_iterations), 101},
      {WORLD_FIELD(max_substeps), 0},         {WORLD_FIELD(max_substeps), 1025},
      {WORLD_FIELD(max_contacts_per_hand), -1}, {WORLD_FIELD(max_contacts_per_hand), 65537},
      {WORLD_FIELD(max_candidates_per_hand), 0}, {WORLD_FIELD(max_candidates_per_hand), (1 << 18) + 1},
      {WORLD_FIELD(command_capacity), 0},     {WORLD_FIELD(command_capacity), -5},
      {WORLD_FIELD(command_capacity), (1 << 20) + 1},
      {WORLD_FIELD(max_hands), 0},            {WORLD_FIELD(max_hands), -1},
      {WORLD_FIELD(max_hands), 65},          {WORLD_FIELD(realtime_priority), 2},
      {WORLD_FIELD(realtime_priority), -1},
  };
  for (size_t i = 0; i < sizeof ints / sizeof ints[0]; ++i) {
    const int_case* c = &ints[i];
    char value[32];
    def = good;
    memcpy((char*)&def + c->offset, &c->value, sizeof c->value);
    out = sentinel;
    snprintf(what, sizeof what, "create_world(%s = %d)", c->field, c->value);
    snprintf(value, sizeof value, "%d", c->value);
    expect_error(what, frusta_create_world(&def, &out), FRUSTA_ERROR_OUT_OF_RANGE, c->field,
                 value);
    check(memcmp(&out, &sentinel, sizeof out) == 0, "%s leaves out_world unchanged", what);
  }

  /* the edges of every range are accepted */
  def = good;
  def.max_objects = 1;
  def.rate_hz = 100000.0;
  def.spin_us = 10.0; /* one period */
  def.gravity[2] = -1000.0;
  def.prediction_margin = 0.1;
  def.lod_error = 1.0;
  def.max_iterations = 100;
  def.max_substeps = 1024;
  def.max_contacts_per_hand = 0;
  def.max_candidates_per_hand = 1;
  def.command_capacity = 1;
  def.max_fingertip_force = 0.0;
  out = sentinel;
  if (expect_ok("create_world(every field at an edge of its range)",
                frusta_create_world(&def, &out))) {
    check(!FRUSTA_IS_NULL(out) && out.world0 == 0 && out.generation != 0 &&
              frusta_world_is_valid(out) == 1,
          "the new world id {%d, %u, %u} is valid", out.index1, out.world0, out.generation);
    expect_ok("destroy it", frusta_destroy_world(out));
  }
  def = good;
  def.rate_hz = 1.0;
  def.spin_us = 1e6;
  def.max_objects = 65535;
  if (expect_ok("create_world(rate_hz 1, spin_us 1e6, max_objects 65535)",
                frusta_create_world(&def, &out)))
    frusta_destroy_world(out);
}

/* ------------------------------------------------------------------ world ids */

/* Every entry point that takes a world id, called with `id`, must fail with `want`
 * naming the id's problem, and write nothing. */
static void expect_world_id_refused(frusta_world_id id, frusta_result want, const char* label) {
  char what[128];
  const char* needle = want == FRUSTA_ERROR_NULL_ID ? "null" : "no live world";
  const frusta_hand_def hand_def = frusta_default_hand_def();
  const frusta_object_def object_def = frusta_default_object_def();
  const frusta_pose pose = {{0.1, 0.2, 0.3}, {0, 0, 0, 1}};
  const frusta_object_id object = {1, (uint16_t)id.index1, 1};
  const frusta_hand_id a_hand = {1, (uint16_t)id.index1, id.generation};
  double angles[FRUSTA_HAND_JOINT_COUNT] = {0};
  frusta_hand_id out_hand;
  int32_t count;
  frusta_object_id out_object;
  frusta_world_contact contacts[2];
  frusta_segment segments[2];
  frusta_sphere spheres[2];
  int32_t ignored;
  fill(&out_hand, sizeof out_hand);
  fill(&count, sizeof count);
  fill(&out_object, sizeof out_object);
  fill(contacts, sizeof contacts);
  fill(segments, sizeof segments);
  fill(spheres, sizeof spheres);
  fill(&ignored, sizeof ignored);
  frusta_world_state state = sentinel_state();
  frusta_world_hand hand = sentinel_hand();
  frusta_object_state object_state = sentinel_object();
  const frusta_world_state state_before = state;
  const frusta_world_hand hand_before = hand;
  const frusta_object_state object_before = object_state;

#define REFUSED(call, name)                                   \
  snprintf(what, sizeof what, "%s(%s)", name, label);         \
  expect_error(what, call, want, needle, NULL)
  REFUSED(frusta_destroy_world(id), "destroy_world");
  REFUSED(frusta_create_world_hand(id, &hand_def, &out_hand), "create_world_hand");
  REFUSED(frusta_world_set_haptic(id, a_hand, &pose, angles, FRUSTA_HAND_JOINT_COUNT),
          "world_set_haptic");
  REFUSED(frusta_create_object(id, g_box, &object_def, &out_object), "create_object");
  REFUSED(frusta_world_set_object_pose(id, object, &pose), "world_set_object_pose");
  REFUSED(frusta_world_set_object_dynamic(id, object, 1), "world_set_object_dynamic");
  REFUSED(frusta_world_step(id), "world_step");
  REFUSED(frusta_world_start(id), "world_start");
  REFUSED(frusta_world_stop(id), "world_stop");
  REFUSED(frusta_world_read(id, &state), "world_read");
  REFUSED(frusta_world_get_hand(id, a_hand, &hand), "world_get_hand");
  REFUSED(frusta_world_get_contacts(id, a_hand, contacts, 2, &count), "world_get_contacts");
  REFUSED(frusta_world_get_object(id, object, &object_state), "world_get_object");
  REFUSED(frusta_world_get_object_ignored_by(id, object, a_hand, &ignored),
          "world_get_object_ignored_by");
  REFUSED(frusta_world_get_hand_segments(id, a_hand, FRUSTA_HAND_KIND_GRAPHIC, segments, 2, &count),
          "world_get_hand_segments");
  REFUSED(frusta_world_get_hand_palm_spheres(id, a_hand, FRUSTA_HAND_KIND_HAPTIC, spheres, 2, &count),
          "world_get_hand_palm_spheres");
#undef REFUSED
  check(is_sentinel(segments, sizeof segments) && is_sentinel(spheres, sizeof spheres) &&
            is_sentinel(&ignored, sizeof ignored),
        "the geometry and ignored_by calls with %s write nothing", label);
  check(is_sentinel(&out_hand, sizeof out_hand) && is_sentinel(&out_object, sizeof out_object) &&
            is_sentinel(&count, sizeof count) && is_sentinel(contacts, sizeof contacts) &&
            memcmp(&state, &state_before, sizeof state) == 0 &&
            memcmp(&hand, &hand_before, sizeof hand) == 0 &&
            memcmp(&object_state, &object_before, sizeof object_state) == 0,
        "calls with %s write no out parameter", label);
  check(frusta_world_is_valid(id) == 0, "frusta_world_is_valid(%s) == 0", label);
}

static void test_world_ids(void) {
  const frusta_world_def def = frusta_default_world_def();
  frusta_world_id witness, old_world, new_world;
  frusta_hand_id hand = {0};
  frusta_object_id object;
  const frusta_object_def object_def = frusta_default_object_def();
  if (!make_world(&def, &witness, "witness")) return;
  add_default_hand(witness, &hand);
  expect_ok("witness: add an object", frusta_create_object(witness, g_box, &object_def, &object));
  frusta_world_state before, after;
  step_and_read(witness, 3, &before);

  check(FRUSTA_IS_NULL(kNullWorld), "FRUSTA_IS_NULL(null world id)");
  expect_world_id_refused(kNullWorld, FRUSTA_ERROR_NULL_ID, "null id");
  const frusta_world_id null_with_generation = {0, 0, 3};
  expect_world_id_refused(null_with_generation, FRUSTA_ERROR_NULL_ID, "{0, 0, 3}");

  if (make_world(&def, &old_world, "A")) {
    expect_ok("destroy world A", frusta_destroy_world(old_world));
    expect_world_id_refused(old_world, FRUSTA_ERROR_STALE_ID, "destroyed world id");
    /* the slot is reused: A's id stays stale, B's is valid */
    if (make_world(&def, &new_world, "B")) {
      check(new_world.index1 == old_world.index1 && new_world.generation != old_world.generation,
            "B reuses A's slot with a new generation (A {%d,%u}, B {%d,%u})", old_world.index1,
            old_world.generation, new_world.index1, new_world.generation);
      expect_world_id_refused(old_world, FRUSTA_ERROR_STALE_ID, "A's id after reuse");
      check(frusta_world_is_valid(new_world) == 1, "B is valid after calls with A's id");
      frusta_world_id forged = new_world;
      forged.world0 = 1;
      expect_world_id_refused(forged, FRUSTA_ERROR_STALE_ID, "B's id with world0 1");
      forged = new_world;
      forged.generation = (uint16_t)(new_world.generation + 1);
      expect_world_id_refused(forged, FRUSTA_ERROR_STALE_ID, "B's id with the next generation");
      expect_ok("destroy world B", frusta_destroy_world(new_world));
      expect_error("destroy world B twice", frusta_destroy_world(new_world),
                   FRUSTA_ERROR_STALE_ID, "no live world", NULL);
    }
  }
  const frusta_world_id beyond = {257, 0, 1}, huge = {1000000, 0, 1}, negative = {-3, 0, 1},
                        lowest = {INT32_MIN, 0, 1};
  expect_world_id_refused(beyond, FRUSTA_ERROR_STALE_ID, "index1 257");
  expect_world_id_refused(huge, FRUSTA_ERROR_STALE_ID, "index1 1000000");
  expect_world_id_refused(negative, FRUSTA_ERROR_STALE_ID, "index1 -3");
  expect_world_id_refused(lowest, FRUSTA_ERROR_STALE_ID, "index1 INT32_MIN");

  /* the witness saw none of it */
  check(frusta_world_is_valid(witness) == 1, "the witness world is still valid");
  step_and_read(witness, 0, &after);
  check(after.step == before.step && after.hand_count == 1 && after.object_count == 1,
        "the witness world is unchanged (step %llu -> %llu, %d hand, %d object)",
        (unsigned long long)before.step, (unsigned long long)after.step, after.hand_count,
        after.object_count);
  expect_ok("destroy the witness", frusta_destroy_world(witness));
  expect_world_id_refused(witness, FRUSTA_ERROR_STALE_ID, "destroyed witness with a hand");
}

/* ------------------------------------------------------------------ hands */

/* Hands present after one more step (hands come at a step); -1 if it failed. */
static int32_t hand_count(frusta_world_id world) {
  frusta_world_state state;
  return step_and_read(world, 1, &state) ? state.hand_count : -1;
}

static void test_add_hand(void) {
  const frusta_world_def world_def = frusta_default_world_def();
  const frusta_hand_def good = frusta_default_hand_def();
  frusta_hand_def def;
  frusta_world_id world;
  frusta_hand_id out, first = {0};
  char what[128];
  if (!make_world(&world_def, &world, "for add_hand")) return;

  fill(&out, sizeof out);
  expect_error("create_world_hand(def null)", frusta_create_world_hand(world, NULL, &out),
               FRUSTA_ERROR_NULL_POINTER, "def", NULL);
  def = good;
  expect_error("create_world_hand(out_hand null)", frusta_create_world_hand(world, &def, NULL),
               FRUSTA_ERROR_NULL_POINTER, "out_hand", NULL);
  const int32_t sizes[] = {0, (int32_t)sizeof(frusta_hand_def) - 8,
                           (int32_t)sizeof(frusta_hand_def) + 8, -1};
  for (int i = 0; i < 4; ++i) {
    def = good;
    def.struct_size = sizes[i];
    snprintf(what, sizeof what, "create_world_hand(hand def struct_size %d)", sizes[i]);
    expect_error(what, frusta_create_world_hand(world, &def, &out), FRUSTA_ERROR_STRUCT_SIZE,
                 "frusta_hand_def", NULL);
  }
  memset(&def, 0, sizeof def);
  def.struct_size = (int32_t)sizeof def;
  expect_error("create_world_hand(memset hand def)", frusta_create_world_hand(world, &def, &out),
               FRUSTA_ERROR_DEF_NOT_DEFAULTED, "frusta_default_hand_def", NULL);
  def = good;
  def.internal_value = 0;
  expect_error("create_world_hand(hand def internal_value 0)",
               frusta_create_world_hand(world, &def, &out), FRUSTA_ERROR_DEF_NOT_DEFAULTED,
               "internal_value", NULL);
  def = good;
  def.hand_length = NAN;
  expect_error("create_world_hand(hand_length nan)", frusta_create_world_hand(world, &def, &out),
               FRUSTA_ERROR_NOT_FINITE, "hand_length", "nan");
  def = good;
  def.joint_radius[2][1] = -0.01;
  expect_error("create_world_hand(joint_radius[2][1] -0.01)",
               frusta_create_world_hand(world, &def, &out), FRUSTA_ERROR_OUT_OF_RANGE,
               "joint_radius[2][1]", "-0.01");
  def = good;
  def.side = 7;
  expect_error("create_world_hand(side 7)", frusta_create_world_hand(world, &def, &out),
               FRUSTA_ERROR_OUT_OF_RANGE, "side", "7");
  check(is_sentinel(&out, sizeof out), "failed add_hand calls leave out_hand unchanged");
  check(hand_count(world) == 0, "failed add_hand calls add no hand (hand_count %d)",
        hand_count(world));

  /* two hands, ids naming the world; a left hand is a hand like any other */
  def = good;
  if (expect_ok("create_world_hand(right)", frusta_create_world_hand(world, &def, &first)))
    check(first.index1 == 1 && first.world0 != 0 && frusta_hand_is_valid(first) == 1,
          "the first hand's id names the world: {%d, %u, %u}", first.index1, first.world0,
          first.generation);
  def.side = FRUSTA_HAND_LEFT;
  if (expect_ok("create_world_hand(left)", frusta_create_world_hand(world, &def, &out)))
    check(out.index1 == 2 && out.world0 == first.world0 && out.generation == first.generation,
          "the second hand is the world's second: {%d, %u, %u}", out.index1, out.world0,
          out.generation);
  check(hand_count(world) == 2, "hand_count 2 (%d)", hand_count(world));

  /* after steps, hands come as before, each at the next step: the latched step does
     not have it */
  def = good;
  expect_ok("create_world_hand after steps", frusta_create_world_hand(world, &def, &out));
  check(out.index1 == 3 && frusta_hand_is_valid(out) == 1, "the third hand {%d, %u, %u}",
        out.index1, out.world0, out.generation);
  frusta_world_hand h = sentinel_hand();
  const frusta_world_hand h_before = h;
  expect_error("get_hand before a step added it", frusta_world_get_hand(world, out, &h),
               FRUSTA_ERROR_STALE_ID, "latched step", NULL);
  check(memcmp(&h, &h_before, sizeof h) == 0, "the refused get_hand leaves out unchanged");
  check(hand_count(world) == 3, "3 hands (%d)", hand_count(world));
  expect_ok("and now get_hand", frusta_world_get_hand(world, out, &h));
  frusta_destroy_world(world);

  /* the world's prediction margin must stay below the hand's smallest radius */
  frusta_world_def wide = world_def;
  wide.prediction_margin = 0.05;
  if (make_world(&wide, &world, "prediction_margin 0.05")) {
    fill(&out, sizeof out);
    def = good;
    expect_error("create_world_hand(world prediction_margin 0.05 > finger radii)",
                 frusta_create_world_hand(world, &def, &out), FRUSTA_ERROR_OUT_OF_RANGE,
                 "prediction_margin", "0.05");
    check(is_sentinel(&out, sizeof out) && hand_count(world) == 0,
          "the refused hand leaves out_hand unchanged and the world without hands");
    frusta_destroy_world(world);
  }
}

/* A world's hand id names its world: every call on a world's hands refuses a null id,
 * a standalone hand's id, another world's hand, a forged index or generation, and the
 * standalone hand calls refuse a world's hand. Nothing is written on refusal. */
static void expect_world_hand_refused(frusta_world_id world, frusta_hand_id id, frusta_result want,
                                      const char* needle, const char* label) {
  char what[160];
  const frusta_pose palm = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0, 1.0}};
  double angles[FRUSTA_HAND_JOINT_COUNT] = {0};
  frusta_world_hand h = sentinel_hand();
  const frusta_world_hand h_before = h;
  frusta_world_contact contacts[2];
  int32_t count;
  fill(contacts, sizeof contacts);
  fill(&count, sizeof count);
  frusta_device_def device_def = frusta_default_device_def();
  device_def.hand = id;
  frusta_device_id device;
  fill(&device, sizeof device);
  snprintf(what, sizeof what, "set_haptic(%s)", label);
  expect_error(what, frusta_world_set_haptic(world, id, &palm, angles, FRUSTA_HAND_JOINT_COUNT),
               want, needle, NULL);
  snprintf(what, sizeof what, "get_hand(%s)", label);
  expect_error(what, frusta_world_get_hand(world, id, &h), want, needle, NULL);
  snprintf(what, sizeof what, "get_contacts(%s)", label);
  expect_error(what, frusta_world_get_contacts(world, id, contacts, 2, &count), want, needle, NULL);
  snprintf(what, sizeof what, "create_device(def.hand %s)", label);
  expect_error(what, frusta_create_device(world, "replay:no_such_file", &device_def, &device), want,
               "frusta_device_def.hand", needle);
  check(memcmp(&h, &h_before, sizeof h) == 0 && is_sentinel(contacts, sizeof contacts) &&
            is_sentinel(&count, sizeof count) && is_sentinel(&device, sizeof device),
        "calls with %s write no out parameter", label);
}

static void test_hand_ids(void) {
  const frusta_world_def world_def = frusta_default_world_def();
  const frusta_hand_def hand_def = frusta_default_hand_def();
  frusta_world_id world, other;
  frusta_hand_id hand = {0}, other_hand = {0}, standalone = {0};
  if (!make_world(&world_def, &world, "for hand ids")) return;
  if (!add_default_hand(world, &hand)) return;
  if (make_world(&world_def, &other, "another, for hand ids")) add_default_hand(other, &other_hand);
  expect_ok("a standalone hand", frusta_create_hand(&hand_def, &standalone));
  frusta_world_state state;
  step_and_read(world, 1, &state);
  check(frusta_hand_is_valid(hand) == 1 && frusta_hand_is_valid(other_hand) == 1,
        "world hands are valid hand ids");
  check(hand.world0 != 0 && hand.world0 != other_hand.world0 && standalone.world0 == 0,
        "a world hand's world0 names its world (%u, %u; standalone %u)", hand.world0,
        other_hand.world0, standalone.world0);

  const frusta_hand_id null_hand = {0, hand.world0, hand.generation};
  expect_world_hand_refused(world, null_hand, FRUSTA_ERROR_NULL_ID, "null", "null hand id");
  expect_world_hand_refused(world, standalone, FRUSTA_ERROR_STALE_ID, "standalone",
                            "a standalone hand's id");
  expect_world_hand_refused(world, other_hand, FRUSTA_ERROR_STALE_ID, "another world",
                            "another world's hand");
  frusta_hand_id forged = hand;
  forged.generation = (uint16_t)(hand.generation + 1);
  expect_world_hand_refused(world, forged, FRUSTA_ERROR_STALE_ID, "no hand of this world",
                            "the hand with the next generation");
  forged = hand;
  forged.world0 = (uint16_t)(hand.world0 + 0x100);
  expect_world_hand_refused(world, forged, FRUSTA_ERROR_STALE_ID, "another world",
                            "the hand with the next world generation");
  const int32_t indices[] = {2, -1, INT32_MIN};
  for (int i = 0; i < 3; ++i) {
    char label[64];
    forged = hand;
    forged.index1 = indices[i];
    snprintf(label, sizeof label, "the hand with index1 %d", indices[i]);
    expect_world_hand_refused(world, forged, FRUSTA_ERROR_STALE_ID, "no hand of this world", label);
  }

  /* the standalone hand calls take no world hand */
  frusta_segment segments[FRUSTA_HAND_SEGMENT_COUNT];
  int32_t count = -7;
  expect_error("hand_get_segments(a world's hand)",
               frusta_hand_get_segments(hand, segments, FRUSTA_HAND_SEGMENT_COUNT, &count),
               FRUSTA_ERROR_STALE_ID, "world's hand", NULL);
  expect_error("destroy_hand(a world's hand)", frusta_destroy_hand(hand), FRUSTA_ERROR_STALE_ID,
               "world's hand", NULL);
  check(count == -7 && frusta_hand_is_valid(hand) == 1,
        "a refused world hand is untouched and still valid");

  /* a world's hands go with it, and stay stale when its slot is reused */
  if (!FRUSTA_IS_NULL(other_hand)) {
    expect_ok("destroy the other world", frusta_destroy_world(other));
    check(frusta_hand_is_valid(other_hand) == 0, "its hand is no longer valid");
    frusta_world_id reused;
    frusta_hand_id reused_hand = {0};
    if (make_world(&world_def, &reused, "in the other's slot") &&
        add_default_hand(reused, &reused_hand)) {
      check(reused_hand.index1 == other_hand.index1 && reused_hand.world0 != other_hand.world0,
            "the new world's first hand has a new world0 (%u, was %u)", reused_hand.world0,
            other_hand.world0);
      check(frusta_hand_is_valid(other_hand) == 0 && frusta_hand_is_valid(reused_hand) == 1,
            "the old world's hand stays stale");
      expect_world_hand_refused(reused, other_hand, FRUSTA_ERROR_STALE_ID, "another world",
                                "the hand of the slot's previous world");
      frusta_destroy_world(reused);
    }
  }
  frusta_destroy_hand(standalone);
  frusta_destroy_world(world);
  check(frusta_hand_is_valid(hand) == 0, "a destroyed world's hand is not valid");
}

static void test_set_haptic(void) {
  const frusta_world_def world_def = frusta_default_world_def();
  frusta_world_id world;
  frusta_hand_id hand = {0};
  char what[128];
  if (!make_world(&world_def, &world, "for set_haptic")) return;
  if (!add_default_hand(world, &hand)) return;

  /* a non-trivial input, so that an accidental write shows */
  const frusta_pose start = {{0.01, -0.02, 0.03},
                             {0.0, 0.0, 0.38268343236508978, 0.92387953251128674}};
  double angles[FRUSTA_HAND_JOINT_COUNT];
  for (int j = 0; j < FRUSTA_HAND_JOINT_COUNT; ++j) angles[j] = 0.05 * (j % 4) + 0.01;
  expect_ok("set_haptic(start)",
            frusta_world_set_haptic(world, hand, &start, angles, FRUSTA_HAND_JOINT_COUNT));
  frusta_world_state state;
  frusta_world_hand before, after;
  step_and_read(world, 2, &state);
  get_hand(world, hand, &before);
  check(before.solved == 1, "the hand is solved after its first input");
  const int64_t rejected = state.rejected_inputs;

  expect_error("set_haptic(palm null)",
               frusta_world_set_haptic(world, hand, NULL, angles, FRUSTA_HAND_JOINT_COUNT),
               FRUSTA_ERROR_NULL_POINTER, "palm", NULL);
  expect_error("set_haptic(angles null)",
               frusta_world_set_haptic(world, hand, &start, NULL, FRUSTA_HAND_JOINT_COUNT),
               FRUSTA_ERROR_NULL_POINTER, "angles", NULL);
  const int32_t counts[] = {0, -1, FRUSTA_HAND_JOINT_COUNT - 1, FRUSTA_HAND_JOINT_COUNT + 1};
  for (int i = 0; i < 4; ++i) {
    char value[16];
    snprintf(what, sizeof what, "set_haptic(count %d)", counts[i]);
    snprintf(value, sizeof value, "%d", counts[i]);
    expect_error(what, frusta_world_set_haptic(world, hand, &start, angles, counts[i]),
                 FRUSTA_ERROR_OUT_OF_RANGE, "count", value);
  }
  const int32_t hands[] = {-1, 2, 1000, INT32_MIN};
  for (int i = 0; i < 4; ++i) {
    frusta_hand_id forged = hand;
    forged.index1 = hands[i];
    snprintf(what, sizeof what, "set_haptic(hand index1 %d of 1)", hands[i]);
    expect_error(what,
                 frusta_world_set_haptic(world, forged, &start, angles, FRUSTA_HAND_JOINT_COUNT),
                 FRUSTA_ERROR_STALE_ID, "no hand of this world", NULL);
  }

  /* the palm pose: positions within 1e6 m, finite quaternion of norm 0.5..2 */
  const struct {
    const char* label;
    int index; /* 0..2 position, 3..6 rotation */
    double value;
    frusta_result want;
    const char *field, *text;
  } poses[] = {
      {"position[0] nan", 0, NAN, FRUSTA_ERROR_NOT_FINITE, "palm.position", "nan"},
      {"position[1] inf", 1, INFINITY, FRUSTA_ERROR_NOT_FINITE, "palm.position", "inf"},
      {"position[2] -2e6", 2, -2e6, FRUSTA_ERROR_OUT_OF_RANGE, "palm.position", "-2e+06"},
      {"rotation[3] nan", 6, NAN, FRUSTA_ERROR_NOT_FINITE, "palm.rotation", "nan"},
      {"rotation[0] -inf", 3, -INFINITY, FRUSTA_ERROR_NOT_FINITE, "palm.rotation", "-inf"},
  };
  for (size_t i = 0; i < sizeof poses / sizeof poses[0]; ++i) {
    frusta_pose palm = start;
    if (poses[i].index < 3)
      palm.position[poses[i].index] = poses[i].value;
    else
      palm.rotation[poses[i].index - 3] = poses[i].value;
    snprintf(what, sizeof what, "set_haptic(palm.%s)", poses[i].label);
    expect_error(what,
                 frusta_world_set_haptic(world, hand, &palm, angles, FRUSTA_HAND_JOINT_COUNT),
                 poses[i].want, poses[i].field, poses[i].text);
  }
  const struct {
    double w;
    const char* text;
  } norms[] = {{0.0, "norm 0"}, {0.4, "norm 0.4"}, {2.5, "norm 2.5"}};
  for (int i = 0; i < 3; ++i) {
    frusta_pose palm = {{0, 0, 0}, {0, 0, 0, norms[i].w}};
    snprintf(what, sizeof what, "set_haptic(palm quaternion %s)", norms[i].text);
    expect_error(what,
                 frusta_world_set_haptic(world, hand, &palm, angles, FRUSTA_HAND_JOINT_COUNT),
                 FRUSTA_ERROR_OUT_OF_RANGE, "palm.rotation", norms[i].text);
  }
  const struct {
    double value;
    frusta_result want;
    const char* text;
  } bad_angles[] = {{NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
                    {-INFINITY, FRUSTA_ERROR_NOT_FINITE, "-inf"},
                    {12.6, FRUSTA_ERROR_OUT_OF_RANGE, "12.6"},
                    {-100.5, FRUSTA_ERROR_OUT_OF_RANGE, "-100.5"}};
  for (int i = 0; i < 4; ++i) {
    double bad[FRUSTA_HAND_JOINT_COUNT];
    memcpy(bad, angles, sizeof bad);
    bad[7] = bad_angles[i].value;
    snprintf(what, sizeof what, "set_haptic(angles[7] %g)", bad_angles[i].value);
    expect_error(what, frusta_world_set_haptic(world, hand, &start, bad, FRUSTA_HAND_JOINT_COUNT),
                 bad_angles[i].want, "angles[7]", bad_angles[i].text);
  }

  /* none of it reached the hand: the next step uses the last good input */
  step_and_read(world, 2, &state);
  get_hand(world, hand, &after);
  check(memcmp(&before.haptic_palm, &after.haptic_palm, sizeof before.haptic_palm) == 0 &&
            memcmp(before.haptic_angles, after.haptic_angles, sizeof before.haptic_angles) == 0,
        "refused inputs leave the hand's haptic input unchanged");
  check(state.rejected_inputs == rejected, "and count no rejected input (%lld -> %lld)",
        (long long)rejected, (long long)state.rejected_inputs);

  /* angles beyond the joint limits but within FRUSTA_MAX_JOINT_ANGLE are taken, and
     the next step uses them, clamped: accepted means used, never dropped later */
  angles[7] = FRUSTA_MAX_JOINT_ANGLE;
  expect_ok("set_haptic(angles[7] FRUSTA_MAX_JOINT_ANGLE: beyond the limit, clamped)",
            frusta_world_set_haptic(world, hand, &start, angles, FRUSTA_HAND_JOINT_COUNT));
  step_and_read(world, 1, &state);
  get_hand(world, hand, &after);
  const frusta_hand_def limits = frusta_default_hand_def();
  check(after.haptic_angles[7] == FRUSTA_MAX_JOINT_ANGLE &&
            after.graphic_angles[7] == limits.joint_max[1][3],
        "the step used it (%g), clamped to the limit (%g, limit %g)", after.haptic_angles[7],
        after.graphic_angles[7], limits.joint_max[1][3]);
  check(state.rejected_inputs == rejected, "and rejected none (%lld -> %lld)",
        (long long)rejected, (long long)state.rejected_inputs);
  frusta_destroy_world(world);
}

/* ------------------------------------------------------------------ objects */

/* Every call that takes an object id, called with `id`, must fail with `want`
 * naming `needle`, and change nothing. */
/* destroy_needle: what frusta_destroy_object, which finds the world by the id alone, says;
 * null for an id of another live world, which it would act on. */
static void expect_object_id_refused(frusta_world_id world, frusta_object_id id, frusta_result want,
                                     const char* needle, const char* destroy_needle,
                                     const char* label) {
  char what[160];
  const frusta_pose pose = {{0.3, 0.2, 0.1}, {0, 0, 0, 1}};
  frusta_object_state out = sentinel_object();
  const frusta_object_state out_before = out;
  if (destroy_needle) {
    snprintf(what, sizeof what, "destroy_object(%s)", label);
    expect_error(what, frusta_destroy_object(id), want, destroy_needle, NULL);
  }
  snprintf(what, sizeof what, "set_object_pose(%s)", label);
  expect_error(what, frusta_world_set_object_pose(world, id, &pose), want, needle, NULL);
  snprintf(what, sizeof what, "set_object_dynamic(%s)", label);
  expect_error(what, frusta_world_set_object_dynamic(world, id, 1), want, needle, NULL);
  snprintf(what, sizeof what, "get_object(%s)", label);
  expect_error(what, frusta_world_get_object(world, id, &out), want, needle, NULL);
  check(memcmp(&out, &out_before, sizeof out) == 0, "get_object(%s) leaves out unchanged", label);
}

static void test_add_object_errors(void) {
  const frusta_world_def world_def = frusta_default_world_def();
  const frusta_object_def good = frusta_default_object_def();
  frusta_object_def def;
  frusta_world_id world;
  frusta_object_id out, sentinel, first;
  fill(&sentinel, sizeof sentinel);
  char what[128];
  if (!make_world(&world_def, &world, "for add_object")) return;
  def = good;
  def.pose.position[0] = 1.0;
  expect_ok("add a first object", frusta_create_object(world, g_box, &def, &first));
  check(first.index1 > 0 && (first.world0 & 0xFF) == (uint16_t)world.index1 &&
            first.world0 >> 8 == (world.generation & 0xFF) && first.generation != 0,
        "its id {%d, %u, %u} names the world's slot + 1 (%d) and generation (%u)", first.index1,
        first.world0, first.generation, world.index1, world.generation);
  check(objects_after_a_step(world) == 1, "one object present after a step");

  /* the tree */
  out = sentinel;
  const frusta_tree_id null_tree = {0, 0, 0};
  expect_error("create_object(null tree id)", frusta_create_object(world, null_tree, &good, &out),
               FRUSTA_ERROR_NULL_ID, "sphere tree", NULL);
  frusta_tree_id stale_tree = g_box;
  stale_tree.generation = (uint16_t)(g_box.generation + 1);
  expect_error("create_object(tree id of the next generation)",
               frusta_create_object(world, stale_tree, &good, &out), FRUSTA_ERROR_STALE_ID,
               "sphere tree", NULL);
  /* the def and out */
  expect_error("create_object(def null)", frusta_create_object(world, g_box, NULL, &out),
               FRUSTA_ERROR_NULL_POINTER, "def", NULL);
  def = good;
  expect_error("create_object(out_object null)", frusta_create_object(world, g_box, &def, NULL),
               FRUSTA_ERROR_NULL_POINTER, "out_object", NULL);
  const int32_t sizes[] = {0, (int32_t)sizeof(frusta_object_def) - 8,
                           (int32_t)sizeof(frusta_object_def) + 8, -1};
  for (int i = 0; i < 4; ++i) {
    def = good;
    def.struct_size = sizes[i];
    snprintf(what, sizeof what, "create_object(struct_size %d)", sizes[i]);
    expect_error(what, frusta_create_object(world, g_box, &def, &out), FRUSTA_ERROR_STRUCT_SIZE,
                 "frusta_object_def", NULL);
  }
  memset(&def, 0, sizeof def);
  def.struct_size = (int32_t)sizeof def;
  expect_error("create_object(memset def)", frusta_create_object(world, g_box, &def, &out),
               FRUSTA_ERROR_DEF_NOT_DEFAULTED, "frusta_default_object_def", NULL);
  def = good;
  def.internal_value = 0;
  expect_error("create_object(def.internal_value 0)",
               frusta_create_object(world, g_box, &def, &out), FRUSTA_ERROR_DEF_NOT_DEFAULTED,
               "internal_value", NULL);
  const int32_t dynamics[] = {2, -1};
  for (int i = 0; i < 2; ++i) {
    char value[16];
    def = good;
    def.dynamic = dynamics[i];
    snprintf(what, sizeof what, "create_object(dynamic %d)", dynamics[i]);
    snprintf(value, sizeof value, "%d", dynamics[i]);
    expect_error(what, frusta_create_object(world, g_box, &def, &out), FRUSTA_ERROR_OUT_OF_RANGE,
                 "dynamic", value);
  }

  /* every number: non-finite, below and above its range. The messages name the
   * engine's field, which contains the def's (stiffness -> normal_stiffness[k]) */
  const double_case doubles[] = {
      {OBJECT_FIELD(pose.position[2]), NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
      {OBJECT_FIELD(pose.position[0]), INFINITY, FRUSTA_ERROR_NOT_FINITE, "inf"},
      {OBJECT_FIELD(pose.position[1]), 2e6, FRUSTA_ERROR_OUT_OF_RANGE, "2e+06"},
      {OBJECT_FIELD(pose.rotation[1]), NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
      {OBJECT_FIELD(pose.rotation[3]), -INFINITY, FRUSTA_ERROR_NOT_FINITE, "-inf"},
      {OBJECT_FIELD(stiffness[1]), NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
      {OBJECT_FIELD(stiffness[0]), -1.0, FRUSTA_ERROR_OUT_OF_RANGE, "-1"},
      {OBJECT_FIELD(stiffness[2]), 2e9, FRUSTA_ERROR_OUT_OF_RANGE, "2e+09"},
      {OBJECT_FIELD(friction), NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
      {OBJECT_FIELD(friction), -0.1, FRUSTA_ERROR_OUT_OF_RANGE, "-0.1"},
      {OBJECT_FIELD(friction), 101.0, FRUSTA_ERROR_OUT_OF_RANGE, "101"},
      {OBJECT_FIELD(tangential_stiffness), INFINITY, FRUSTA_ERROR_NOT_FINITE, "inf"},
      {OBJECT_FIELD(tangential_stiffness), -1.0, FRUSTA_ERROR_OUT_OF_RANGE, "-1"},
      {OBJECT_FIELD(tangential_stiffness), 2e9, FRUSTA_ERROR_OUT_OF_RANGE, "2e+09"},
      {OBJECT_FIELD(normal_damping), NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
      {OBJECT_FIELD(normal_damping), -1.0, FRUSTA_ERROR_OUT_OF_RANGE, "-1"},
      {OBJECT_FIELD(tangential_damping), NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
      {OBJECT_FIELD(tangential_damping), -1.0, FRUSTA_ERROR_OUT_OF_RANGE, "-1"},
      {OBJECT_FIELD(tangential_damping), 2e9, FRUSTA_ERROR_OUT_OF_RANGE, "2e+09"},
      {OBJECT_FIELD(mass), NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
      {OBJECT_FIELD(mass), INFINITY, FRUSTA_ERROR_NOT_FINITE, "inf"},
      {OBJECT_FIELD(mass), 0.0, FRUSTA_ERROR_OUT_OF_RANGE, NULL},
      {OBJECT_FIELD(mass), -1.0, FRUSTA_ERROR_OUT_OF_RANGE, "-1"},
      {OBJECT_FIELD(mass), 2e6, FRUSTA_ERROR_OUT_OF_RANGE, "2e+06"},
      /* accepted once, and a palm swinging through it overflowed the QP's active set */
      {OBJECT_FIELD(mass), 1e-300, FRUSTA_ERROR_OUT_OF_RANGE, "1e-300"},
      {OBJECT_FIELD(inertia[0]), 1e-300, FRUSTA_ERROR_OUT_OF_RANGE, "1e-300"},
      {OBJECT_FIELD(inertia[1]), 2e4, FRUSTA_ERROR_OUT_OF_RANGE, "20000"},
      /* principal moments no body has: one larger than the other two together */
      {OBJECT_FIELD(inertia[2]), 1e-3, FRUSTA_ERROR_OUT_OF_RANGE, "inertia[2]"},
      {OBJECT_FIELD(inertia[2]), NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
      {OBJECT_FIELD(inertia[1]), 0.0, FRUSTA_ERROR_OUT_OF_RANGE, NULL},
      {OBJECT_FIELD(inertia[0]), -4e-5, FRUSTA_ERROR_OUT_OF_RANGE, "-4e-05"},
      {OBJECT_FIELD(linear_velocity[0]), NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
      {OBJECT_FIELD(linear_velocity[1]), 101.0, FRUSTA_ERROR_OUT_OF_RANGE, "101"},
      {OBJECT_FIELD(linear_velocity[2]), -101.0, FRUSTA_ERROR_OUT_OF_RANGE, "-101"},
      {OBJECT_FIELD(angular_velocity[2]), INFINITY, FRUSTA_ERROR_NOT_FINITE, "inf"},
      {OBJECT_FIELD(angular_velocity[0]), 1001.0, FRUSTA_ERROR_OUT_OF_RANGE, "1001"},
      {OBJECT_FIELD(linear_damping), NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
      {OBJECT_FIELD(linear_damping), -1.0, FRUSTA_ERROR_OUT_OF_RANGE, "-1"},
      {OBJECT_FIELD(linear_damping), 1001.0, FRUSTA_ERROR_OUT_OF_RANGE, "1001"},
      {OBJECT_FIELD(angular_damping), NAN, FRUSTA_ERROR_NOT_FINITE, "nan"},
      {OBJECT_FIELD(angular_damping), -1.0, FRUSTA_ERROR_OUT_OF_RANGE, "-1"},
      {OBJECT_FIELD(angular_damping), 1001.0, FRUSTA_ERROR_OUT_OF_RANGE, "1001"},
  };
  for (size_t i = 0; i < sizeof doubles / sizeof doubles[0]; ++i) {
    const double_case* c = &doubles[i];
    char field[64];
    def = good;
    memcpy((char*)&def + c->offset, &c->value, sizeof c->value);
    snprintf(what, sizeof what, "create_object(%s = %g)", c->field, c->value);
    /* the message's field: pose.position[k] and pose.rotation (the quaternion as a
     * whole); the engine's own checks name inertia and velocities without an index */
    snprintf(field, sizeof field, "%s", c->field);
    if (!strncmp(field, "pose.rotation", 13) || !strncmp(field, "inertia", 7) ||
        !strncmp(field, "linear_velocity", 15) || !strncmp(field, "angular_velocity", 16))
      *strchr(field, '[') = '\0';
    expect_error(what, frusta_create_object(world, g_box, &def, &out), c->want, field, c->text);
  }
  const struct {
    double w;
    const char* text;
  } norms[] = {{0.0, "norm 0"}, {0.25, "norm 0.25"}, {3.0, "norm 3"}};
  for (int i = 0; i < 3; ++i) {
    def = good;
    def.pose.rotation[3] = norms[i].w;
    snprintf(what, sizeof what, "create_object(pose quaternion %s)", norms[i].text);
    expect_error(what, frusta_create_object(world, g_box, &def, &out), FRUSTA_ERROR_OUT_OF_RANGE,
                 "pose.rotation", norms[i].text);
  }
  check(memcmp(&out, &sentinel, sizeof out) == 0, "failed add_object calls leave out unchanged");
  check(objects_after_a_step(world) == 1, "and add no object (still 1 after a step)");

  /* a quaternion of norm 2 is normalised, as documented */
  def = good;
  def.pose.rotation[3] = 2.0;
  frusta_object_id scaled;
  frusta_object_state state;
  if (expect_ok("create_object(pose quaternion (0, 0, 0, 2))",
                frusta_create_object(world, g_box, &def, &scaled))) {
    objects_after_a_step(world);
    const int read = get_object(world, scaled, &state);
    check(read && state.pose.rotation[3] == 1.0,
          "is placed with the unit quaternion (w %g)", state.pose.rotation[3]);
  }
  frusta_destroy_world(world);
}

static void test_object_ids(void) {
  const frusta_world_def world_def = frusta_default_world_def();
  const frusta_object_def def = frusta_default_object_def();
  frusta_world_id world, other;
  frusta_object_id kept, removed, foreign;
  char what[128];
  if (!make_world(&world_def, &world, "for object ids")) return;
  if (!make_world(&world_def, &other, "another")) return;
  frusta_object_def kept_def = def;
  kept_def.pose.position[1] = 0.5;
  expect_ok("add the kept object", frusta_create_object(world, g_box, &kept_def, &kept));
  expect_ok("add an object to remove", frusta_create_object(world, g_box, &def, &removed));
  expect_ok("add an object to the other world", frusta_create_object(other, g_box, &def, &foreign));
  check(objects_after_a_step(world) == 2 && objects_after_a_step(other) == 1,
        "2 objects in the world, 1 in the other");
  frusta_object_state kept_before, kept_after;
  get_object(world, kept, &kept_before);

  /* removal: the id turns stale at once for the host's calls */
  expect_ok("destroy_object", frusta_destroy_object(removed));
  expect_error("destroy_object twice", frusta_destroy_object(removed), FRUSTA_ERROR_STALE_ID,
               "names no object", NULL);
  /* and for get_object once a step without it is latched */
  check(objects_after_a_step(world) == 1, "1 object after the removal's step");
  expect_object_id_refused(world, removed, FRUSTA_ERROR_STALE_ID, "names no object",
                           "names no object", "removed object");

  expect_object_id_refused(world, kNullObject, FRUSTA_ERROR_NULL_ID, "null", "null",
                           "null object id");
  const frusta_object_id null_with_world = {0, (uint16_t)world.index1, 1};
  expect_object_id_refused(world, null_with_world, FRUSTA_ERROR_NULL_ID, "null", "null",
                           "{0, world, 1}");
  expect_object_id_refused(world, foreign, FRUSTA_ERROR_STALE_ID, "another world", NULL,
                           "the other world's object");
  frusta_object_id forged = kept;
  forged.world0 = 0;
  expect_object_id_refused(world, forged, FRUSTA_ERROR_STALE_ID, "another world", "never existed",
                           "kept id with world0 0");
  forged = kept;
  forged.generation = (uint16_t)(kept.generation + 1);
  expect_object_id_refused(world, forged, FRUSTA_ERROR_STALE_ID, "names no object",
                           "names no object", "kept id with the next generation");
  const int32_t indices[] = {1000, 65, -3, INT32_MIN, INT32_MAX};
  for (int i = 0; i < 5; ++i) {
    forged = kept;
    forged.index1 = indices[i];
    snprintf(what, sizeof what, "object id with index1 %d", indices[i]);
    expect_object_id_refused(world, forged, FRUSTA_ERROR_STALE_ID, "names no object",
                             "names no object", what);
  }

  /* an object id of a destroyed world, whose slot a new, empty world took */
  frusta_world_id dead, reborn;
  frusta_object_id orphan;
  if (make_world(&world_def, &dead, "to destroy")) {
    expect_ok("add an object to it", frusta_create_object(dead, g_box, &def, &orphan));
    frusta_destroy_world(dead);
    if (make_world(&world_def, &reborn, "in the destroyed one's slot")) {
      check(reborn.index1 == dead.index1, "the new world took the slot");
      objects_after_a_step(reborn);
      expect_object_id_refused(reborn, orphan, FRUSTA_ERROR_STALE_ID, "destroyed", "destroyed",
                               "object of the destroyed world");
      /* and once the new world has an object in the same slot, with the same
         generation, the orphan still names nothing: ids carry their world's generation */
      frusta_object_id twin;
      expect_ok("add an object to the new world", frusta_create_object(reborn, g_box, &def, &twin));
      check(twin.index1 == orphan.index1 && twin.generation == orphan.generation,
            "the new object has the orphan's slot and generation");
      expect_object_id_refused(reborn, orphan, FRUSTA_ERROR_STALE_ID, "destroyed", "destroyed",
                               "object of the destroyed world beside its twin");
      check(objects_after_a_step(reborn) == 1, "the twin is untouched");
      frusta_destroy_world(reborn);
    }
  }

  /* nothing touched the kept object */
  check(objects_after_a_step(world) == 1, "still 1 object in the world");
  check(objects_after_a_step(other) == 1, "still 1 object in the other world");
  check(get_object(world, kept, &kept_after) &&
            memcmp(&kept_before, &kept_after, sizeof kept_before) == 0,
        "the kept object reads back unchanged");

  /* an object added after the latched step is not in it */
  frusta_object_id fresh;
  frusta_object_state out = sentinel_object();
  const frusta_object_state out_before = out;
  expect_ok("add an object without stepping", frusta_create_object(world, g_box, &def, &fresh));
  expect_error("get_object(added after the latched step)",
               frusta_world_get_object(world, fresh, &out), FRUSTA_ERROR_STALE_ID,
               "latched step", NULL);
  check(memcmp(&out, &out_before, sizeof out) == 0, "and leaves out unchanged");
  check(objects_after_a_step(world) == 2 && get_object(world, fresh, &out),
        "it is there after the next step and read");

  /* pose and dynamic flag: bad values change nothing */
  expect_error("set_object_pose(pose null)", frusta_world_set_object_pose(world, kept, NULL),
               FRUSTA_ERROR_NULL_POINTER, "pose", NULL);
  frusta_pose pose = kept_def.pose;
  pose.position[2] = NAN;
  expect_error("set_object_pose(position[2] nan)", frusta_world_set_object_pose(world, kept, &pose),
               FRUSTA_ERROR_NOT_FINITE, "pose.position", "nan");
  pose = kept_def.pose;
  pose.position[0] = 1e7;
  expect_error("set_object_pose(position[0] 1e7)", frusta_world_set_object_pose(world, kept, &pose),
               FRUSTA_ERROR_OUT_OF_RANGE, "pose.position", "1e+07");
  pose = kept_def.pose;
  pose.rotation[1] = INFINITY;
  expect_error("set_object_pose(rotation[1] inf)", frusta_world_set_object_pose(world, kept, &pose),
               FRUSTA_ERROR_NOT_FINITE, "pose.rotation", "inf");
  pose = kept_def.pose;
  pose.rotation[3] = 0.0;
  expect_error("set_object_pose(quaternion norm 0)",
               frusta_world_set_object_pose(world, kept, &pose), FRUSTA_ERROR_OUT_OF_RANGE,
               "pose.rotation", "norm 0");
  pose.rotation[3] = 2.5;
  expect_error("set_object_pose(quaternion norm 2.5)",
               frusta_world_set_object_pose(world, kept, &pose), FRUSTA_ERROR_OUT_OF_RANGE,
               "pose.rotation", "norm 2.5");
  expect_error("set_object_dynamic(2)", frusta_world_set_object_dynamic(world, kept, 2),
               FRUSTA_ERROR_OUT_OF_RANGE, "dynamic", "2");
  expect_error("set_object_dynamic(-1)", frusta_world_set_object_dynamic(world, kept, -1),
               FRUSTA_ERROR_OUT_OF_RANGE, "dynamic", "-1");
  objects_after_a_step(world);
  check(get_object(world, kept, &kept_after) &&
            memcmp(&kept_before, &kept_after, sizeof kept_before) == 0,
        "refused pose and dynamic calls leave the kept object unchanged");

  /* and good ones take effect at the next step */
  const frusta_pose moved = {{0.2, 0.5, -0.1}, {0.0, 0.0, 0.6, 0.8}};
  expect_ok("set_object_pose", frusta_world_set_object_pose(world, kept, &moved));
  check(get_object(world, kept, &kept_after) &&
            memcmp(&kept_before, &kept_after, sizeof kept_before) == 0,
        "queued: the latched step still has the old pose");
  objects_after_a_step(world);
  int same = get_object(world, kept, &kept_after);
  for (int k = 0; k < 3; ++k) same &= near(kept_after.pose.position[k], moved.position[k], 1e-15);
  for (int k = 0; k < 4; ++k) same &= near(kept_after.pose.rotation[k], moved.rotation[k], 1e-15);
  check(same && kept_after.dynamic == 0, "after a step it is at the new pose, still kinematic");
  frusta_destroy_world(other);
  frusta_destroy_world(world);
}

static void test_capacity(void) {
  frusta_world_def def = frusta_default_world_def();
  const frusta_object_def object_def = frusta_default_object_def();
  frusta_world_id world;
  frusta_object_id a, b, c, out, sentinel;
  fill(&sentinel, sizeof sentinel);

  def.max_objects = 2;
  if (make_world(&def, &world, "max_objects 2")) {
    expect_ok("add object a", frusta_create_object(world, g_box, &object_def, &a));
    expect_ok("add object b", frusta_create_object(world, g_box, &object_def, &b));
    out = sentinel;
    expect_error("add a third object to max_objects 2",
                 frusta_create_object(world, g_box, &object_def, &out), FRUSTA_ERROR_CAPACITY,
                 "max_objects", "2");
    check(memcmp(&out, &sentinel, sizeof out) == 0, "the refused add leaves out unchanged");
    check(objects_after_a_step(world) == 2, "2 objects present");
    /* a removal frees its slot at once, under a new generation */
    expect_ok("remove a", frusta_destroy_object(a));
    if (expect_ok("add c in a's place", frusta_create_object(world, g_box, &object_def, &c)))
      check(c.index1 == a.index1 && c.generation != a.generation,
            "c reuses a's slot with a new generation (a {%d,%u}, c {%d,%u})", a.index1,
            a.generation, c.index1, c.generation);
    check(objects_after_a_step(world) == 2, "2 objects present after the swap");
    frusta_object_state state;
    check(get_object(world, c, &state), "c reads back");
    expect_error("get_object(a, whose slot c took)", frusta_world_get_object(world, a, &state),
                 FRUSTA_ERROR_STALE_ID, "latched step", NULL);
    frusta_destroy_world(world);
  }

  /* the command queue holds command_capacity commands between steps */
  def = frusta_default_world_def();
  def.command_capacity = 2;
  if (make_world(&def, &world, "command_capacity 2")) {
    expect_ok("queue command 1", frusta_create_object(world, g_box, &object_def, &a));
    expect_ok("queue command 2", frusta_create_object(world, g_box, &object_def, &b));
    out = sentinel;
    expect_error("queue command 3", frusta_create_object(world, g_box, &object_def, &out),
                 FRUSTA_ERROR_CAPACITY, "command queue", NULL);
    check(memcmp(&out, &sentinel, sizeof out) == 0, "the refused add leaves out unchanged");
    const frusta_pose pose = {{0.0, 0.0, 1.0}, {0, 0, 0, 1}};
    expect_error("queue a pose command on a full queue",
                 frusta_world_set_object_pose(world, a, &pose), FRUSTA_ERROR_CAPACITY,
                 "command queue", NULL);
    expect_error("queue a removal on a full queue", frusta_destroy_object(b), FRUSTA_ERROR_CAPACITY,
                 "command queue", NULL);
    check(objects_after_a_step(world) == 2, "the step applied the two queued adds");
    frusta_object_state state;
    check(get_object(world, b, &state), "b was not removed");
    check(get_object(world, a, &state) && state.pose.position[2] == 0.0, "a was not moved");
    expect_ok("the queue has room again", frusta_create_object(world, g_box, &object_def, &c));
    check(objects_after_a_step(world) == 3, "3 objects present");
    frusta_destroy_world(world);
  }
}

/* ------------------------------------------------------------------ reads */

static void test_read_errors(void) {
  const frusta_world_def world_def = frusta_default_world_def();
  const frusta_object_def object_def = frusta_default_object_def();
  frusta_world_id world;
  frusta_hand_id hand = {0};
  frusta_object_id object;
  char what[128];
  if (!make_world(&world_def, &world, "for reads")) return;
  add_default_hand(world, &hand);
  expect_ok("add an object", frusta_create_object(world, g_box, &object_def, &object));
  expect_ok("step", frusta_world_step(world));

  frusta_world_hand h = sentinel_hand();
  frusta_object_state o = sentinel_object();
  frusta_world_contact contacts[4];
  int32_t count;
  fill(contacts, sizeof contacts);
  fill(&count, sizeof count);
  const frusta_world_hand h_before = h;
  const frusta_object_state o_before = o;

  /* nothing latched yet */
  expect_error("get_hand before any read", frusta_world_get_hand(world, hand, &h),
               FRUSTA_ERROR_WRONG_STATE, "frusta_world_read", NULL);
  expect_error("get_contacts before any read",
               frusta_world_get_contacts(world, hand, contacts, 4, &count),
               FRUSTA_ERROR_WRONG_STATE, "frusta_world_read", NULL);
  expect_error("get_contacts(size query) before any read",
               frusta_world_get_contacts(world, hand, NULL, 0, &count), FRUSTA_ERROR_WRONG_STATE,
               "frusta_world_read", NULL);
  expect_error("get_object before any read", frusta_world_get_object(world, object, &o),
               FRUSTA_ERROR_WRONG_STATE, "frusta_world_read", NULL);

  /* a failed read latches nothing */
  frusta_world_state state = sentinel_state();
  expect_error("read(state null)", frusta_world_read(world, NULL), FRUSTA_ERROR_NULL_POINTER,
               "state", NULL);
  const int32_t sizes[] = {0, (int32_t)sizeof(frusta_world_state) - 8,
                           (int32_t)sizeof(frusta_world_state) + 8, -1};
  for (int i = 0; i < 4; ++i) {
    frusta_world_state bad = sentinel_state();
    bad.struct_size = sizes[i];
    const frusta_world_state bad_before = bad;
    snprintf(what, sizeof what, "read(struct_size %d)", sizes[i]);
    expect_error(what, frusta_world_read(world, &bad), FRUSTA_ERROR_STRUCT_SIZE,
                 "frusta_world_state", NULL);
    check(memcmp(&bad, &bad_before, sizeof bad) == 0, "%s leaves state unchanged", what);
  }
  expect_error("get_hand after failed reads", frusta_world_get_hand(world, hand, &h),
               FRUSTA_ERROR_WRONG_STATE, "frusta_world_read", NULL);

  /* latched: the newest step */
  if (expect_ok("read", frusta_world_read(world, &state)))
    check(state.struct_size == (int32_t)sizeof state && state.step == 1 && state.hand_count == 1 &&
              state.object_count == 1 && near(state.time, 0.001, 1e-15) && state.realtime == 0,
          "state: step %llu, %d hand, %d object, time %g", (unsigned long long)state.step,
          state.hand_count, state.object_count, state.time);

  /* get_hand */
  expect_error("get_hand(out null)", frusta_world_get_hand(world, hand, NULL),
               FRUSTA_ERROR_NULL_POINTER, "out", NULL);
  const int32_t hand_sizes[] = {0, (int32_t)sizeof(frusta_world_hand) - 8,
                                (int32_t)sizeof(frusta_world_hand) + 8, -1};
  for (int i = 0; i < 4; ++i) {
    frusta_world_hand bad = sentinel_hand();
    bad.struct_size = hand_sizes[i];
    const frusta_world_hand bad_before = bad;
    snprintf(what, sizeof what, "get_hand(struct_size %d)", bad.struct_size);
    expect_error(what, frusta_world_get_hand(world, hand, &bad), FRUSTA_ERROR_STRUCT_SIZE,
                 "frusta_world_hand", NULL);
    check(memcmp(&bad, &bad_before, sizeof bad) == 0, "%s leaves out unchanged", what);
  }
  const int32_t hands[] = {-1, 2, 1000, INT32_MIN};
  for (int i = 0; i < 4; ++i) {
    frusta_hand_id forged = hand;
    forged.index1 = hands[i];
    snprintf(what, sizeof what, "get_hand(hand index1 %d of 1)", hands[i]);
    expect_error(what, frusta_world_get_hand(world, forged, &h), FRUSTA_ERROR_STALE_ID, "hand id",
                 NULL);
    snprintf(what, sizeof what, "get_contacts(hand index1 %d of 1)", hands[i]);
    expect_error(what, frusta_world_get_contacts(world, forged, contacts, 4, &count),
                 FRUSTA_ERROR_STALE_ID, "hand id", NULL);
  }
  check(memcmp(&h, &h_before, sizeof h) == 0, "refused get_hand calls leave out unchanged");

  /* get_contacts */
  expect_error("get_contacts(out_count null)",
               frusta_world_get_contacts(world, hand, contacts, 4, NULL),
               FRUSTA_ERROR_NULL_POINTER, "out_count", NULL);
  expect_error("get_contacts(out null, capacity 4)",
               frusta_world_get_contacts(world, hand, NULL, 4, &count), FRUSTA_ERROR_NULL_POINTER,
               "out", NULL);
  expect_error("get_contacts(out null, capacity -1)",
               frusta_world_get_contacts(world, hand, NULL, -1, &count), FRUSTA_ERROR_OUT_OF_RANGE,
               "capacity", "-1");
  check(is_sentinel(contacts, sizeof contacts) && is_sentinel(&count, sizeof count),
        "refused get_contacts calls write neither out nor out_count");

  /* get_object */
  expect_error("get_object(out null)", frusta_world_get_object(world, object, NULL),
               FRUSTA_ERROR_NULL_POINTER, "out", NULL);
  const int32_t object_sizes[] = {0, (int32_t)sizeof(frusta_object_state) - 8,
                                  (int32_t)sizeof(frusta_object_state) + 8, -1};
  for (int i = 0; i < 4; ++i) {
    frusta_object_state bad = sentinel_object();
    bad.struct_size = object_sizes[i];
    const frusta_object_state bad_before = bad;
    snprintf(what, sizeof what, "get_object(struct_size %d)", bad.struct_size);
    expect_error(what, frusta_world_get_object(world, object, &bad), FRUSTA_ERROR_STRUCT_SIZE,
                 "frusta_object_state", NULL);
    check(memcmp(&bad, &bad_before, sizeof bad) == 0, "%s leaves out unchanged", what);
  }
  check(memcmp(&o, &o_before, sizeof o) == 0, "refused get_object calls leave out unchanged");

  /* a hand with no input yet: not solved, no contacts */
  if (expect_ok("get_hand", frusta_world_get_hand(world, hand, &h)))
    check(h.struct_size == (int32_t)sizeof h && h.solved == 0 && h.contact_count == 0,
          "a hand without input: solved %d, %d contacts", h.solved, h.contact_count);
  count = -1;
  expect_ok("get_contacts(null, 0) size query",
            frusta_world_get_contacts(world, hand, NULL, 0, &count));
  check(count == 0, "no contacts (%d)", count);
  expect_ok("get_object", frusta_world_get_object(world, object, &o));
  check(o.struct_size == (int32_t)sizeof o && o.dynamic == 0 && o.pose.rotation[3] == 1.0,
        "the object reads back kinematic at the identity");
  frusta_destroy_world(world);
}

/* ------------------------------------------------------------------ pressing */

/* The open hand lowered 3 mm onto a box under its index fingertip. */
static void test_press(void) {
  const frusta_world_def world_def = frusta_default_world_def();
  frusta_world_id world;
  frusta_tree_id tree;
  frusta_hand_id hand = {0};
  frusta_object_id box;
  frusta_world_state state;
  frusta_world_hand h;
  frusta_object_state o;
  char what[128];
  if (!bake_box(&tree)) return;
  if (!make_world(&world_def, &world, "press")) return;
  if (!add_default_hand(world, &hand)) return;
  const frusta_object_def box_def = box_under_tip();
  if (!expect_ok("add the box under the index fingertip",
                 frusta_create_object(world, tree, &box_def, &box)))
    return;

  frusta_pose palm;
  double angles[FRUSTA_HAND_JOINT_COUNT];
  open_hand(0.003, &palm, angles);
  int stepped = 1;
  for (int t = 0; t < 50; ++t) {
    stepped &= frusta_world_set_haptic(world, hand, &palm, angles, FRUSTA_HAND_JOINT_COUNT) ==
               FRUSTA_OK;
    stepped &= frusta_world_step(world) == FRUSTA_OK;
  }
  check(stepped, "50 steps with the hand lowered 3 mm");
  if (!check(step_and_read(world, 0, &state), "read")) return;
  check(state.step == 50 && near(state.time, 0.05, 1e-12) && state.hand_count == 1 &&
            state.object_count == 1 && state.rejected_inputs == 0,
        "state: step %llu, time %g, %d hand, %d object, %lld rejected",
        (unsigned long long)state.step, state.time, state.hand_count, state.object_count,
        (long long)state.rejected_inputs);
  check(state.step_us > 0.0 && state.step_us_p50 > 0.0 && state.step_us_p99 >= state.step_us_p50 &&
            state.step_us_max >= state.step_us_p99 && state.achieved_rate_hz == 0.0,
        "timing: step %g us, p50 %g, p99 %g, max %g; no own thread (rate %g)", state.step_us,
        state.step_us_p50, state.step_us_p99, state.step_us_max, state.achieved_rate_hz);

  if (!check(get_hand(world, hand, &h), "get_hand")) return;
  check(h.solved == 1 && h.contact_count > 0 && h.pressing > 0,
        "the hand is solved and presses: %d contacts, %d pressing, %d slipping, %d substeps",
        h.contact_count, h.pressing, h.slipping, h.substeps);
  check(h.haptic_palm.position[2] == -0.003 && h.graphic_palm.position[2] > -0.003,
        "the graphic hand stays above the haptic one (z %g > %g)", h.graphic_palm.position[2],
        h.haptic_palm.position[2]);
  const double* tip_force = h.fingertip_force[FRUSTA_FINGER_INDEX];
  check(finite3(tip_force) && tip_force[2] > 0.0 && h.finger_resistance[FRUSTA_FINGER_INDEX] > 0.0,
        "the index fingertip is pushed up: (%g, %g, %g) N, resistance %g N", tip_force[0],
        tip_force[1], tip_force[2], h.finger_resistance[FRUSTA_FINGER_INDEX]);
  int others_free = 1;
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    if (f != FRUSTA_FINGER_INDEX) others_free &= h.finger_resistance[f] == 0.0;
  check(others_free, "no other finger feels anything");

  /* the graphic hand's geometry stays out of the box, by the exact distance; the
     haptic hand's sinks in as deep as it was lowered */
  static frusta_sphere leaves[4096];
  int32_t leaf_count = 0, segment_count = 0;
  frusta_segment graphic[FRUSTA_HAND_SEGMENT_COUNT], haptic[FRUSTA_HAND_SEGMENT_COUNT];
  frusta_sphere_tree_get_leaves(tree, leaves, 4096, &leaf_count);
  expect_ok("get_hand_segments(graphic)",
            frusta_world_get_hand_segments(world, hand, FRUSTA_HAND_KIND_GRAPHIC, graphic,
                                           FRUSTA_HAND_SEGMENT_COUNT, &segment_count));
  expect_ok("get_hand_segments(haptic)",
            frusta_world_get_hand_segments(world, hand, FRUSTA_HAND_KIND_HAPTIC, haptic,
                                           FRUSTA_HAND_SEGMENT_COUNT, &segment_count));
  double graphic_gap = INFINITY, haptic_gap = INFINITY;
  for (int32_t l = 0; l < leaf_count && l < 4096; ++l) {
    frusta_sphere sphere = leaves[l];
    for (int k = 0; k < 3; ++k) sphere.center[k] += box_def.pose.position[k];
    for (int i = 0; i < FRUSTA_HAND_SEGMENT_COUNT; ++i) {
      frusta_contact_query q;
      q.struct_size = (int32_t)sizeof q;
      if (frusta_query_contact(&graphic[i], &sphere, &q) == FRUSTA_OK)
        graphic_gap = fmin(graphic_gap, q.distance);
      if (frusta_query_contact(&haptic[i], &sphere, &q) == FRUSTA_OK)
        haptic_gap = fmin(haptic_gap, q.distance);
    }
  }
  check(leaf_count > 0 && leaf_count <= 4096 && graphic_gap >= -1e-6 && haptic_gap < -0.001,
        "of %d leaves, the graphic segments' nearest is %g m away (>= -1e-6), the haptic ones "
        "sink %g m in",
        leaf_count, graphic_gap, -haptic_gap);

  /* contacts: the size query, then the copy */
  int32_t count = -1;
  expect_ok("get_contacts(null, 0) size query",
            frusta_world_get_contacts(world, hand, NULL, 0, &count));
  check(count == h.contact_count, "count %d == contact_count %d", count, h.contact_count);
  enum { kMaxContacts = 256 };
  static frusta_world_contact contacts[kMaxContacts + 1];
  frusta_world_contact pattern;
  fill(contacts, sizeof contacts);
  fill(&pattern, sizeof pattern);
  if (count < 1 || count > kMaxContacts) return;

  /* a negative capacity: refused, nothing written */
  int32_t small_count;
  fill(&small_count, sizeof small_count);
  expect_error("get_contacts(capacity -1)",
               frusta_world_get_contacts(world, hand, contacts, -1, &small_count),
               FRUSTA_ERROR_OUT_OF_RANGE, "capacity", "-1");
  check(is_sentinel(contacts, sizeof contacts) && is_sentinel(&small_count, sizeof small_count),
        "a negative capacity writes neither out nor out_count");
  /* too small a buffer: what fits, and the count of all */
  snprintf(what, sizeof what, "get_contacts(capacity %d of %d)", count - 1, count);
  expect_ok(what, frusta_world_get_contacts(world, hand, contacts, count - 1, &small_count));
  check(small_count == count && memcmp(&contacts[count - 1], &pattern, sizeof pattern) == 0,
        "a short buffer gets %d contacts and the count %d (got %d)", count - 1, count, small_count);
  fill(contacts, sizeof contacts);

  int32_t got = -1;
  expect_ok("get_contacts", frusta_world_get_contacts(world, hand, contacts, kMaxContacts, &got));
  check(got == count, "%d contacts copied", got);
  check(memcmp(&contacts[got], &pattern, sizeof pattern) == 0,
        "nothing written past the last contact");
  double sum[3] = {0, 0, 0}, torque[3] = {0, 0, 0};
  int ids = 1, bodies = 1, finite = 1, unit = 1, away = 1, reserved = 1;
  int pushing = 0;
  for (int32_t i = 0; i < got; ++i) {
    const frusta_world_contact* c = &contacts[i];
    ids &= memcmp(&c->object, &box, sizeof box) == 0;
    bodies &= c->body == FRUSTA_FINGER_INDEX * FRUSTA_SEGMENTS_PER_FINGER + 2;
    finite &= isfinite(c->distance) && finite3(c->graphic_point) && finite3(c->haptic_point) &&
              finite3(c->normal) && finite3(c->normal_force) && finite3(c->friction);
    unit &= near(norm3(c->normal), 1.0, 1e-9);
    const double along = dot3(c->normal_force, c->normal);
    away &= along >= 0.0;
    pushing += along > 0.0;
    reserved &= c->reserved0 == 0 && (c->slipping == 0 || c->slipping == 1) && c->leaf >= -1;
    /* the reaction's torque about the object's position, from the graphic points */
    const double total[3] = {c->normal_force[0] + c->friction[0],
                             c->normal_force[1] + c->friction[1],
                             c->normal_force[2] + c->friction[2]};
    const double r[3] = {c->graphic_point[0] - box_def.pose.position[0],
                         c->graphic_point[1] - box_def.pose.position[1],
                         c->graphic_point[2] - box_def.pose.position[2]};
    for (int k = 0; k < 3; ++k) sum[k] += total[k];
    torque[0] += r[1] * total[2] - r[2] * total[1];
    torque[1] += r[2] * total[0] - r[0] * total[2];
    torque[2] += r[0] * total[1] - r[1] * total[0];
  }
  check(ids, "every contact names the box's id");
  check(bodies, "every contact is on the index distal segment (body 5)");
  check(finite && unit, "every contact is finite with a unit normal");
  check(away && pushing > 0,
        "every normal force points away from the box (normal_force . normal >= 0; %d > 0)",
        pushing);
  check(reserved, "reserved0 0, slipping 0 or 1, leaf >= -1");
  check(sum[2] > 0.0, "the contacts push the hand up (%g, %g, %g) N", sum[0], sum[1], sum[2]);

  /* what the box receives is what the hand feels, reversed */
  if (!check(get_object(world, box, &o), "get_object(box)")) return;
  double worst = 0.0, worst_torque = 0.0;
  for (int k = 0; k < 3; ++k) {
    worst = fmax(worst, fabs(o.reaction_force[k] + sum[k]));
    worst_torque = fmax(worst_torque, fabs(o.reaction_torque[k] + torque[k]));
  }
  check(worst <= 1e-9 * norm3(sum),
        "reaction_force (%g, %g, %g) == -(sum of normal_force + friction), off by %g N",
        o.reaction_force[0], o.reaction_force[1], o.reaction_force[2], worst);
  check(worst_torque <= 1e-9 * norm3(torque) + 1e-15,
        "reaction_torque == -(sum of (graphic_point - position) x force), off by %g N m",
        worst_torque);
  int placed = o.dynamic == 0;
  for (int k = 0; k < 3; ++k)
    placed &= near(o.pose.position[k], box_def.pose.position[k], 1e-15) &&
              o.linear_velocity[k] == 0.0 && o.angular_velocity[k] == 0.0;
  check(placed, "the kinematic box stays where it was put, at rest");

  /* the tree's id may go: the world shares the tree */
  expect_ok("destroy the box's sphere tree id", frusta_destroy_sphere_tree(tree));
  check(frusta_sphere_tree_is_valid(tree) == 0, "the tree id is stale");
  frusta_object_id again;
  expect_error("create_object(destroyed tree id)",
               frusta_create_object(world, tree, &box_def, &again), FRUSTA_ERROR_STALE_ID,
               "sphere tree", NULL);
  for (int t = 0; t < 10; ++t) {
    frusta_world_set_haptic(world, hand, &palm, angles, FRUSTA_HAND_JOINT_COUNT);
    frusta_world_step(world);
  }
  check(step_and_read(world, 0, &state) && get_hand(world, hand, &h) && get_object(world, box, &o),
        "the world still steps and reads");
  check(h.contact_count > 0 && h.pressing > 0 && o.reaction_force[2] < 0.0,
        "and the hand still presses the box (%d contacts, %d pressing, reaction z %g N)",
        h.contact_count, h.pressing, o.reaction_force[2]);

  /* removed: stale for the host at once, for get_object after the next step */
  expect_ok("remove the box", frusta_destroy_object(box));
  const frusta_pose pose = {{0, 0, 0}, {0, 0, 0, 1}};
  expect_error("set_object_pose(removed box)", frusta_world_set_object_pose(world, box, &pose),
               FRUSTA_ERROR_STALE_ID, "names no object", NULL);
  expect_ok("step", frusta_world_step(world));
  step_and_read(world, 0, &state);
  frusta_object_state out = sentinel_object();
  const frusta_object_state out_before = out;
  expect_error("get_object(removed box) after step and read",
               frusta_world_get_object(world, box, &out), FRUSTA_ERROR_STALE_ID, "latched step",
               NULL);
  check(memcmp(&out, &out_before, sizeof out) == 0, "and leaves out unchanged");
  check(state.object_count == 0, "no object left (%d)", state.object_count);
  frusta_world_set_haptic(world, hand, &palm, angles, FRUSTA_HAND_JOINT_COUNT);
  step_and_read(world, 5, &state);
  count = -1;
  frusta_world_get_contacts(world, hand, NULL, 0, &count);
  get_hand(world, hand, &h);
  check(count == 0 && h.pressing == 0 && h.finger_resistance[FRUSTA_FINGER_INDEX] == 0.0,
        "nothing to touch: %d contacts, %d pressing", count, h.pressing);
  expect_ok("destroy the world (the last user of the tree)", frusta_destroy_world(world));
}

/* ------------------------------------------------------------------ dynamics */

static void test_dynamics(void) {
  frusta_world_def def = frusta_default_world_def();
  def.gravity[2] = -9.81;
  frusta_world_id world;
  frusta_object_id falling, still;
  frusta_world_state state;
  frusta_object_state o;
  if (!make_world(&def, &world, "gravity -9.81 z")) return;
  frusta_object_def object_def = frusta_default_object_def();
  object_def.dynamic = 1;
  expect_ok("add a dynamic box", frusta_create_object(world, g_box, &object_def, &falling));
  object_def.dynamic = 0;
  object_def.pose.position[0] = 1.0;
  expect_ok("add a kinematic box", frusta_create_object(world, g_box, &object_def, &still));

  /* semi-implicit Euler at 1 kHz; a step publishes the state the hands met, so after
   * n steps the box has been integrated n - 1 times */
  const int n = 100;
  const double dt = 0.001, g = 9.81;
  step_and_read(world, n, &state);
  const double v = -g * dt * (n - 1), z = -g * dt * dt * (n - 1) * n / 2.0;
  if (check(get_object(world, falling, &o), "get_object(dynamic box)"))
    check(o.dynamic == 1 && near(o.linear_velocity[2], v, 1e-12) &&
              near(o.pose.position[2], z, 1e-12) && o.linear_velocity[0] == 0.0 &&
              o.reaction_force[2] == 0.0,
          "it falls: z %.15g m (want %.15g), vz %.15g m/s (want %.15g)", o.pose.position[2], z,
          o.linear_velocity[2], v);
  if (check(get_object(world, still, &o), "get_object(kinematic box)"))
    check(o.dynamic == 0 && o.pose.position[2] == 0.0 && o.linear_velocity[2] == 0.0,
          "the kinematic box stays (z %g)", o.pose.position[2]);

  /* hand the kinematic box to the dynamics, and take the falling one back */
  expect_ok("set_object_dynamic(still, 1)", frusta_world_set_object_dynamic(world, still, 1));
  expect_ok("set_object_dynamic(falling, 0)", frusta_world_set_object_dynamic(world, falling, 0));
  step_and_read(world, 10, &state);
  if (get_object(world, still, &o))
    check(o.dynamic == 1 && o.pose.position[2] < 0.0 && o.linear_velocity[2] < 0.0,
          "the former kinematic box now falls (z %g, vz %g)", o.pose.position[2],
          o.linear_velocity[2]);
  double held = 0.0;
  if (get_object(world, falling, &o)) {
    held = o.pose.position[2];
    check(o.dynamic == 0 && o.linear_velocity[2] == 0.0 && held < z,
          "the taken-back box is at rest (z %g, vz %g)", held, o.linear_velocity[2]);
  }
  step_and_read(world, 10, &state);
  check(get_object(world, falling, &o) && o.pose.position[2] == held,
        "and stays where it stopped");
  frusta_destroy_world(world);
}

/* ------------------------------------------------------------------ hands come and go */

static const frusta_hand_id kNullHand = {0, 0, 0};

/* frusta_destroy_world_hand's error paths, and a destroyed hand's id: stale at once for
 * the calls that change the world, shown by reads until a step applied the removal,
 * its slot taken again once a read latched that step. */
static void test_destroy_world_hand(void) {
  frusta_world_def world_def = frusta_default_world_def();
  world_def.max_hands = 2;
  const frusta_hand_def hand_def = frusta_default_hand_def();
  frusta_world_id world, other;
  frusta_hand_id a = {0}, b = {0}, c, standalone = {0}, other_hand = {0};
  frusta_world_state state;
  frusta_world_hand h;
  if (!make_world(&world_def, &world, "two hand slots")) return;
  if (!add_default_hand(world, &a) || !add_default_hand(world, &b)) return;
  fill(&c, sizeof c);
  expect_error("create_world_hand in a full world", frusta_create_world_hand(world, &hand_def, &c),
               FRUSTA_ERROR_CAPACITY, "max_hands", "2");
  check(is_sentinel(&c, sizeof c), "a full world's refusal leaves out_hand unchanged");

  expect_error("destroy_world_hand(null)", frusta_destroy_world_hand(kNullHand),
               FRUSTA_ERROR_NULL_ID, "null", NULL);
  expect_ok("a standalone hand", frusta_create_hand(&hand_def, &standalone));
  expect_error("destroy_world_hand(a standalone hand)", frusta_destroy_world_hand(standalone),
               FRUSTA_ERROR_STALE_ID, "standalone", NULL);
  check(frusta_hand_is_valid(standalone) == 1, "the standalone hand lives on");
  frusta_destroy_hand(standalone);
  frusta_hand_id forged = a;
  forged.generation = (uint16_t)(a.generation + 1);
  expect_error("destroy_world_hand(the next generation)", frusta_destroy_world_hand(forged),
               FRUSTA_ERROR_STALE_ID, "no hand of this world", NULL);
  const int32_t indices[] = {3, 1000, -1, INT32_MIN};
  for (int i = 0; i < 4; ++i) {
    char what[64];
    forged = a;
    forged.index1 = indices[i];
    snprintf(what, sizeof what, "destroy_world_hand(index1 %d)", indices[i]);
    expect_error(what, frusta_destroy_world_hand(forged), FRUSTA_ERROR_STALE_ID, "no hand", NULL);
  }
  check(frusta_hand_is_valid(a) == 1 && frusta_hand_is_valid(b) == 1, "both hands live on");

  /* a destroyed world's hand */
  if (make_world(&world_def, &other, "another") && add_default_hand(other, &other_hand)) {
    expect_ok("destroy the other world", frusta_destroy_world(other));
    expect_error("destroy_world_hand(a destroyed world's hand)",
                 frusta_destroy_world_hand(other_hand), FRUSTA_ERROR_STALE_ID, "destroyed", NULL);
  }

  /* destroyed: stale at once for every call that changes the world */
  frusta_pose palm;
  double angles[FRUSTA_HAND_JOINT_COUNT];
  open_hand(0.0, &palm, angles);
  expect_ok("set_haptic(a)", frusta_world_set_haptic(world, a, &palm, angles, FRUSTA_HAND_JOINT_COUNT));
  step_and_read(world, 1, &state);
  if (!expect_ok("destroy_world_hand(a)", frusta_destroy_world_hand(a))) return;
  check(frusta_hand_is_valid(a) == 0, "a's id is stale at once");
  expect_error("destroy_world_hand(a) twice", frusta_destroy_world_hand(a), FRUSTA_ERROR_STALE_ID,
               "no hand of this world", NULL);
  expect_error("set_haptic(a destroyed hand)",
               frusta_world_set_haptic(world, a, &palm, angles, FRUSTA_HAND_JOINT_COUNT),
               FRUSTA_ERROR_STALE_ID, "no hand of this world", NULL);
  frusta_device_def device_def = frusta_default_device_def();
  device_def.hand = a;
  frusta_device_id device;
  expect_error("create_device(def.hand a destroyed hand)",
               frusta_create_device(world, "replay:" FRUSTA_RECORDING_PATH, &device_def, &device),
               FRUSTA_ERROR_STALE_ID, "frusta_device_def.hand", "no hand of this world");
  check(get_hand(world, a, &h) && h.solved == 1,
        "the latched step still shows it (a step has not applied the removal)");

  /* its slot is taken again once a read latched a step that applied the removal */
  fill(&c, sizeof c);
  expect_error("create_world_hand while a's removal is under way",
               frusta_create_world_hand(world, &hand_def, &c), FRUSTA_ERROR_CAPACITY, "removed", NULL);
  expect_ok("step", frusta_world_step(world));
  expect_error("create_world_hand before a read latched that step",
               frusta_create_world_hand(world, &hand_def, &c), FRUSTA_ERROR_CAPACITY, "removed", NULL);
  check(is_sentinel(&c, sizeof c), "and out_hand is unchanged");
  step_and_read(world, 0, &state);
  check(state.hand_count == 1, "one hand left (%d)", state.hand_count);
  h = sentinel_hand();
  expect_error("get_hand(a) once the removal is latched", frusta_world_get_hand(world, a, &h),
               FRUSTA_ERROR_STALE_ID, "latched step", NULL);
  if (expect_ok("create_world_hand in a's slot", frusta_create_world_hand(world, &hand_def, &c)))
    check(c.index1 == a.index1 && c.world0 == a.world0 && c.generation != a.generation &&
              frusta_hand_is_valid(c) == 1 && frusta_hand_is_valid(a) == 0,
          "a new generation in a's slot ({%d, %u, %u}, a was {%d, %u, %u})", c.index1, c.world0,
          c.generation, a.index1, a.world0, a.generation);
  expect_error("set_haptic(a) reaches not the hand in its slot",
               frusta_world_set_haptic(world, a, &palm, angles, FRUSTA_HAND_JOINT_COUNT),
               FRUSTA_ERROR_STALE_ID, "no hand of this world", NULL);
  step_and_read(world, 1, &state);
  check(get_hand(world, c, &h) && h.solved == 0, "the new hand has had no input");

  /* a hand a glove drives stays until the glove is closed */
  device_def.hand = b;
  if (expect_ok("open a replayed glove on b",
                frusta_create_device(world, "replay:" FRUSTA_RECORDING_PATH "?loop=1", &device_def,
                                     &device))) {
    expect_error("destroy_world_hand(b, a glove drives it)", frusta_destroy_world_hand(b),
                 FRUSTA_ERROR_WRONG_STATE, "frusta_destroy_device", NULL);
    check(frusta_hand_is_valid(b) == 1 && frusta_device_is_valid(device) == 1,
          "the hand and the glove live on");
    expect_ok("destroy the glove", frusta_destroy_device(device));
    expect_ok("then destroy_world_hand(b)", frusta_destroy_world_hand(b));
  }
  frusta_destroy_world(world);
  check(frusta_hand_is_valid(c) == 0, "a destroyed world's hands are not valid");
}

static int same_segments(const frusta_segment* a, const frusta_segment* b, int n, double* worst) {
  *worst = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) {
      *worst = fmax(*worst, fabs(a[i].proximal[k] - b[i].proximal[k]));
      *worst = fmax(*worst, fabs(a[i].distal[k] - b[i].distal[k]));
    }
    *worst = fmax(*worst, fabs(a[i].proximal_radius - b[i].proximal_radius));
    *worst = fmax(*worst, fabs(a[i].distal_radius - b[i].distal_radius));
  }
  return *worst <= 1e-12;
}

/* A standalone hand put in a world hand's latched state: its geometry is the one the
 * world gives for that hand (frusta_hand_get_segments and _palm_spheres). */
static void expect_world_geometry(frusta_world_id world, frusta_hand_id hand, int32_t which,
                                  const frusta_pose* palm, const double* angles, const char* label) {
  const frusta_hand_def def = frusta_default_hand_def();
  frusta_hand_id alone;
  if (!expect_ok("a standalone hand", frusta_create_hand(&def, &alone))) return;
  frusta_hand_set_palm_pose(alone, palm);
  frusta_hand_set_joint_angles(alone, angles, FRUSTA_HAND_JOINT_COUNT);
  frusta_segment got[FRUSTA_HAND_SEGMENT_COUNT], want[FRUSTA_HAND_SEGMENT_COUNT];
  int32_t n = 0, m = 0;
  double worst = 0.0;
  expect_ok(label, frusta_world_get_hand_segments(world, hand, which, got, FRUSTA_HAND_SEGMENT_COUNT, &n));
  frusta_hand_get_segments(alone, want, FRUSTA_HAND_SEGMENT_COUNT, &m);
  check(n == FRUSTA_HAND_SEGMENT_COUNT && m == n && same_segments(got, want, n, &worst),
        "%s: %d segments, those of a standalone hand in its state (off by %g m)", label, n, worst);
  int32_t spheres = 0, spheres_alone = 0;
  frusta_hand_get_palm_spheres(alone, NULL, 0, &spheres_alone);
  expect_ok(label, frusta_world_get_hand_palm_spheres(world, hand, which, NULL, 0, &spheres));
  static frusta_sphere got_palm[4096], want_palm[4096];
  int32_t copied = 0;
  if (check(spheres == spheres_alone && spheres > 0 && spheres <= 4096, "%s: %d palm spheres",
            label, spheres)) {
    frusta_world_get_hand_palm_spheres(world, hand, which, got_palm, spheres, &copied);
    frusta_hand_get_palm_spheres(alone, want_palm, spheres, &m);
    worst = 0.0;
    for (int32_t i = 0; i < spheres; ++i) {
      for (int k = 0; k < 3; ++k)
        worst = fmax(worst, fabs(got_palm[i].center[k] - want_palm[i].center[k]));
      worst = fmax(worst, fabs(got_palm[i].radius - want_palm[i].radius));
    }
    check(copied == spheres && worst <= 1e-12, "%s: the palm spheres of the standalone hand (off by %g m)",
          label, worst);
  }
  frusta_destroy_hand(alone);
}

/* Every segment and palm sphere of a world's hand, graphic or haptic, as a standalone
 * hand in the same state has them; and the calls' error paths. */
static void test_hand_geometry(void) {
  const frusta_world_def world_def = frusta_default_world_def();
  frusta_world_id world;
  frusta_hand_id hand = {0}, late = {0};
  frusta_world_state state;
  frusta_world_hand h;
  frusta_segment segments[FRUSTA_HAND_SEGMENT_COUNT + 1];
  int32_t count;
  if (!make_world(&world_def, &world, "hand geometry")) return;
  if (!add_default_hand(world, &hand) || !add_default_hand(world, &late)) return;
  /* a turned, moved palm; flexed fingers, one of them past its limit */
  const frusta_pose palm = {{0.1, -0.2, 0.3}, {0.0, 0.0, 0.38268343236508978, 0.92387953251128674}};
  double angles[FRUSTA_HAND_JOINT_COUNT];
  for (int j = 0; j < FRUSTA_HAND_JOINT_COUNT; ++j) angles[j] = j % 4 == 0 ? 0.05 : 0.4;
  angles[FRUSTA_FINGER_MIDDLE * FRUSTA_JOINTS_PER_FINGER + 2] = 3.0;
  frusta_world_set_haptic(world, hand, &palm, angles, FRUSTA_HAND_JOINT_COUNT);
  step_and_read(world, 3, &state);
  if (!check(get_hand(world, hand, &h) && h.solved == 1, "the hand is solved")) return;
  expect_world_geometry(world, hand, FRUSTA_HAND_KIND_GRAPHIC, &h.graphic_palm, h.graphic_angles,
                        "get_hand_segments(graphic)");
  expect_world_geometry(world, hand, FRUSTA_HAND_KIND_HAPTIC, &h.haptic_palm, h.haptic_angles,
                        "get_hand_segments(haptic)");

  /* the output-array rule */
  fill(segments, sizeof segments);
  fill(&count, sizeof count);
  expect_ok("get_hand_segments(null, 0): the count",
            frusta_world_get_hand_segments(world, hand, 0, NULL, 0, &count));
  check(count == FRUSTA_HAND_SEGMENT_COUNT, "%d segments", count);
  expect_ok("get_hand_segments(capacity 4)",
            frusta_world_get_hand_segments(world, hand, 0, segments, 4, &count));
  check(count == FRUSTA_HAND_SEGMENT_COUNT && is_sentinel(&segments[4], sizeof segments[4]),
        "a short buffer gets 4 segments and the count of all");
  fill(segments, sizeof segments);
  fill(&count, sizeof count);
  const struct {
    const char* what;
    int32_t which, capacity;
    int null_out, null_count;
    frusta_result want;
    const char* field;
  } refused[] = {
      {"which 2", 2, 4, 0, 0, FRUSTA_ERROR_OUT_OF_RANGE, "which"},
      {"which -1", -1, 4, 0, 0, FRUSTA_ERROR_OUT_OF_RANGE, "which"},
      {"capacity -1", 0, -1, 0, 0, FRUSTA_ERROR_OUT_OF_RANGE, "capacity"},
      {"out null, capacity 4", 0, 4, 1, 0, FRUSTA_ERROR_NULL_POINTER, "out"},
      {"out_count null", 0, 4, 0, 1, FRUSTA_ERROR_NULL_POINTER, "out_count"},
  };
  for (size_t i = 0; i < sizeof refused / sizeof refused[0]; ++i) {
    char what[96];
    snprintf(what, sizeof what, "get_hand_segments(%s)", refused[i].what);
    expect_error(what,
                 frusta_world_get_hand_segments(world, hand, refused[i].which,
                                                refused[i].null_out ? NULL : segments,
                                                refused[i].capacity,
                                                refused[i].null_count ? NULL : &count),
                 refused[i].want, refused[i].field, NULL);
    snprintf(what, sizeof what, "get_hand_palm_spheres(%s)", refused[i].what);
    frusta_sphere spheres[2];
    fill(spheres, sizeof spheres);
    expect_error(what,
                 frusta_world_get_hand_palm_spheres(world, hand, refused[i].which,
                                                    refused[i].null_out ? NULL : spheres,
                                                    refused[i].capacity,
                                                    refused[i].null_count ? NULL : &count),
                 refused[i].want, refused[i].field, NULL);
    check(is_sentinel(spheres, sizeof spheres), "%s writes nothing", what);
  }
  expect_error("get_hand_segments(a hand with no input yet)",
               frusta_world_get_hand_segments(world, late, 0, segments, 4, &count),
               FRUSTA_ERROR_WRONG_STATE, "solved", NULL);
  check(is_sentinel(segments, sizeof segments) && is_sentinel(&count, sizeof count),
        "the refused calls write nothing");
  frusta_destroy_world(world);
}

/* An object created inside a hand: the hand ignores it until they part, and the
 * latched step says so for the object (a count), the hand (a count) and the pair. */
static void test_ignored_objects(void) {
  const frusta_world_def world_def = frusta_default_world_def();
  frusta_world_id world;
  frusta_hand_id hand = {0}, other = {0};
  frusta_object_id box, far_box;
  frusta_world_state state;
  frusta_world_hand h;
  frusta_object_state o;
  if (!make_world(&world_def, &world, "ignored objects")) return;
  if (!add_default_hand(world, &hand) || !add_default_hand(world, &other)) return;
  frusta_pose palm;
  double angles[FRUSTA_HAND_JOINT_COUNT];
  open_hand(0.0, &palm, angles);
  frusta_world_set_haptic(world, hand, &palm, angles, FRUSTA_HAND_JOINT_COUNT);
  frusta_pose away = palm;
  away.position[1] = 1.0;
  frusta_world_set_haptic(world, other, &away, angles, FRUSTA_HAND_JOINT_COUNT);
  step_and_read(world, 1, &state);
  /* the box around the index fingertip, and one far from both hands */
  frusta_object_def inside = frusta_default_object_def();
  for (int k = 0; k < 3; ++k) inside.pose.position[k] = g_tip.distal[k];
  frusta_object_def far = frusta_default_object_def();
  far.pose.position[2] = 1.0;
  expect_ok("create a box around the index fingertip",
            frusta_create_object(world, g_box, &inside, &box));
  expect_ok("and one far away", frusta_create_object(world, g_box, &far, &far_box));
  step_and_read(world, 5, &state);
  int32_t ignored = -1, other_ignored = -1, far_ignored = -1;
  expect_ok("get_object_ignored_by(box, hand)",
            frusta_world_get_object_ignored_by(world, box, hand, &ignored));
  expect_ok("get_object_ignored_by(box, other)",
            frusta_world_get_object_ignored_by(world, box, other, &other_ignored));
  expect_ok("get_object_ignored_by(far box, hand)",
            frusta_world_get_object_ignored_by(world, far_box, hand, &far_ignored));
  check(ignored == 1 && other_ignored == 0 && far_ignored == 0,
        "the hand it was put into ignores the box (%d), the other hand does not (%d), nor "
        "does anyone the far box (%d)",
        ignored, other_ignored, far_ignored);
  check(get_object(world, box, &o) && o.ignoring_hands == 1 && o.held == 0,
        "the box's state counts one hand ignoring it (%d)", o.ignoring_hands);
  check(get_hand(world, hand, &h) && h.ignored_objects == 1 && h.contact_count == 0 &&
            h.input_late == 0,
        "the hand passes through one object (%d), touching nothing (%d contacts)",
        h.ignored_objects, h.contact_count);
  check(get_object(world, far_box, &o) && o.ignoring_hands == 0, "the far box: none");

  /* once they part, the box is solid to the hand again */
  frusta_pose back = palm;
  back.position[0] = -0.2;
  for (int t = 0; t < 20; ++t) {
    frusta_world_set_haptic(world, hand, &back, angles, FRUSTA_HAND_JOINT_COUNT);
    frusta_world_step(world);
  }
  step_and_read(world, 0, &state);
  frusta_world_get_object_ignored_by(world, box, hand, &ignored);
  check(ignored == 0 && get_object(world, box, &o) && o.ignoring_hands == 0 &&
            get_hand(world, hand, &h) && h.ignored_objects == 0,
        "parted: nobody ignores the box");

  /* error paths: ids (object first, then hand), the pointer, the latched step */
  const frusta_object_id stale_object = {box.index1, box.world0, (uint16_t)(box.generation + 1)};
  frusta_hand_id stale_hand = hand;
  stale_hand.generation = (uint16_t)(hand.generation + 1);
  const struct {
    const char* what;
    frusta_object_id object;
    frusta_hand_id hand;
    int null_out;
    frusta_result want;
    const char* field;
  } refused[] = {
      {"null object", kNullObject, hand, 0, FRUSTA_ERROR_NULL_ID, "object"},
      {"null hand", box, kNullHand, 0, FRUSTA_ERROR_NULL_ID, "hand"},
      {"stale object", stale_object, hand, 0, FRUSTA_ERROR_STALE_ID, "object"},
      {"stale hand", box, stale_hand, 0, FRUSTA_ERROR_STALE_ID, "hand"},
      {"out_ignored null", box, hand, 1, FRUSTA_ERROR_NULL_POINTER, "out_ignored"},
  };
  fill(&ignored, sizeof ignored);
  for (size_t i = 0; i < sizeof refused / sizeof refused[0]; ++i) {
    char what[96];
    snprintf(what, sizeof what, "get_object_ignored_by(%s)", refused[i].what);
    expect_error(what,
                 frusta_world_get_object_ignored_by(world, refused[i].object, refused[i].hand,
                                                    refused[i].null_out ? NULL : &ignored),
                 refused[i].want, refused[i].field, NULL);
  }
  check(is_sentinel(&ignored, sizeof ignored), "the refused calls write nothing");
  frusta_destroy_world(world);
}

/* ------------------------------------------------------------------ own thread */

static void test_thread(void) {
  const frusta_world_def def = frusta_default_world_def();
  frusta_world_id world;
  frusta_hand_id hand = {0}, late_hand;
  frusta_object_id box;
  frusta_world_state state;
  if (!make_world(&def, &world, "own thread")) return;
  add_default_hand(world, &hand);
  const frusta_object_def box_def = box_under_tip();
  expect_ok("add the box", frusta_create_object(world, g_box, &box_def, &box));
  frusta_pose palm;
  double angles[FRUSTA_HAND_JOINT_COUNT];
  open_hand(0.002, &palm, angles);
  frusta_world_set_haptic(world, hand, &palm, angles, FRUSTA_HAND_JOINT_COUNT);

  expect_ok("stop before any start: nothing to stop", frusta_world_stop(world));
  if (!expect_ok("start", frusta_world_start(world))) return;
  expect_error("start while running", frusta_world_start(world), FRUSTA_ERROR_WRONG_STATE,
               "already running", NULL);
  expect_error("step while the own thread runs", frusta_world_step(world),
               FRUSTA_ERROR_WRONG_STATE, "own thread", NULL);
  const frusta_hand_def hand_def = frusta_default_hand_def();
  expect_ok("add a hand while the own thread runs",
            frusta_create_world_hand(world, &hand_def, &late_hand));

  /* host calls go on while it runs: inputs, commands, reads. The thread's first steps
     may take a while on a loaded machine (the sanitizer run): wait for them, up to 5 s */
  uint64_t first = 0;
  for (int waited = 0; first == 0 && waited < 5000; waited += 10) {
    sleep_ms(10);
    frusta_world_set_haptic(world, hand, &palm, angles, FRUSTA_HAND_JOINT_COUNT);
    step_and_read(world, 0, &state);
    first = state.step;
  }
  for (int waited = 0; state.step <= first + 5 && waited < 5000; waited += 10) {
    sleep_ms(10);
    frusta_world_set_haptic(world, hand, &palm, angles, FRUSTA_HAND_JOINT_COUNT);
    step_and_read(world, 0, &state);
  }
  const frusta_pose pose = box_def.pose;
  expect_ok("set_object_pose while running", frusta_world_set_object_pose(world, box, &pose));
  sleep_ms(5);
  expect_ok("stop", frusta_world_stop(world));
  step_and_read(world, 0, &state);
  const uint64_t stopped_at = state.step;
  check(state.step > first + 5 && first > 0,
        "the step count grew while it ran (%llu at the first read that saw a step, %llu at "
        "the stop)",
        (unsigned long long)first, (unsigned long long)state.step);
  check(state.achieved_rate_hz > 0.0 && state.hand_count == 2 && state.object_count == 1,
        "achieved_rate_hz %g > 0 (rate_hz %g); wake late p50 %g us, p99 %g us; %lld overruns",
        state.achieved_rate_hz, def.rate_hz, state.wake_late_us_p50, state.wake_late_us_p99,
        (long long)state.overruns);
  frusta_world_hand h;
  const int read = get_hand(world, hand, &h);
  check(read && h.solved == 1 && h.pressing > 0,
        "the own thread solved the pressing hand (%d pressing)", h.pressing);
  sleep_ms(10);
  step_and_read(world, 0, &state);
  check(state.step == stopped_at, "stopped: no step after stop (%llu)",
        (unsigned long long)state.step);
  expect_ok("stop again: no effect", frusta_world_stop(world));
  expect_ok("the host steps again after stop", frusta_world_step(world));
  step_and_read(world, 0, &state);
  check(state.step == stopped_at + 1, "one more step (%llu)", (unsigned long long)state.step);

  /* destroying a running world stops its thread first */
  expect_ok("start again", frusta_world_start(world));
  sleep_ms(5);
  expect_ok("destroy the running world", frusta_destroy_world(world));
  check(frusta_world_is_valid(world) == 0, "its id is stale");
}

/* ------------------------------------------------------------------ main */

int main(void) {
  if (!bake_box(&g_box) || !find_index_tip()) {
    printf("%d passed, %d failed (setup failed)\n", g_passed, g_failed);
    return 1;
  }
  test_defaults();
  test_create_errors();
  test_world_ids();
  test_add_hand();
  test_hand_ids();
  test_set_haptic();
  test_add_object_errors();
  test_object_ids();
  test_capacity();
  test_read_errors();
  test_press();
  test_dynamics();
  test_destroy_world_hand();
  test_hand_geometry();
  test_ignored_objects();
  test_thread();
  frusta_destroy_sphere_tree(g_box);
  printf("%d passed, %d failed\n", g_passed, g_failed);
  return g_failed == 0 ? 0 : 1;
}
