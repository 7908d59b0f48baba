/* SPDX-License-Identifier: MIT */
/*
 * hostile_abi_test: every function frusta.h declares, called as a careless or hostile
 * host would call it, from C, on the public header alone.
 *
 * A table names each function with the routine that attacks it; the test first checks
 * the table against the header itself (FRUSTA_HEADER_PATH), so a new function without
 * hostile cases fails here. Each routine calls its function with null, garbage, stale
 * (destroyed), foreign-world and mangled ids; null pointers; struct sizes 0, size - 1,
 * size + 8 and worse; defs not from frusta_default_*_def(); every double of every def
 * and argument as NaN, +-inf, +-1e300, 1e-300, -0.0, DBL_MIN, a denormal, +-DBL_MAX and
 * either side of its documented limits; integers INT32_MIN, -1, 0, INT32_MAX. Then:
 *  - a refused call returned the code its range calls for, frusta_last_error() names
 *    the field or argument (once, after the code's name), and nothing changed: out
 *    parameters keep a sentinel byte pattern, and what the call would have changed
 *    (a def, a hand, a world's inputs and objects) reads back as before;
 *  - an accepted call was used: a haptic input is the one the next step reports, an
 *    object added, moved, made dynamic or removed is so in the next step's snapshot,
 *    a def at its limits builds a hand or world that steps; and whatever is read back
 *    (world state, hands, contacts, objects, device status, tree info) is finite,
 *    unit where it should be, within the device limits and within capacity.
 * A second table presses hands into objects at the ends of every physical range
 * (masses, inertias, stiffness 1e9, friction 100, damping 1e9, rate 1 and 100000 Hz,
 * gravity 1e3, hands of 1 cm and 5 m), fills a world to its 65535 objects and tries
 * 10^5, and lays two hands on a tree of 10^6 leaves for a few hundred steps.
 *
 * Only failures print (with the call that failed), then one line per table entry
 * and the tally "N passed, M failed"; the exit status is non-zero when anything
 * failed. Deterministic: no sleeps and no timing; the one glove is a recording
 * replayed on its own thread, and nothing here depends on how far it got.
 */
#define _POSIX_C_SOURCE 200809L /* mkfifo, unlink */

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#if defined(__unix__)
#include <sys/stat.h>
#include <unistd.h>
#endif

#include "c_check.h"
#include "frusta/frusta.h"

#ifndef FRUSTA_HEADER_PATH
#error "CMake passes FRUSTA_HEADER_PATH, FRUSTA_TEST_OBJECTS_DIR and FRUSTA_RECORDING_PATH"
#endif

/* ------------------------------------------------------------------ reporting */

static const char* g_function = "";  /* the table entry running */
static int g_calls;                  /* hostile calls it made */
static int g_entry_failed;           /* its failed checks */
static char g_what[600];             /* the call being checked, for a failure line */

/* Names the call the next checks are about. */
static void what(const char* format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
static void what(const char* format, ...) {
  va_list args;
  va_start(args, format);
  vsnprintf(g_what, sizeof g_what, format, args);
  va_end(args);
}

/* One check: silent when it holds; a FAIL line with the call when it does not. */
static int verify(int ok, const char* format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
static int verify(int ok, const char* format, ...) {
  if (ok) {
    ++g_passed;
    return 1;
  }
  ++g_failed;
  ++g_entry_failed;
  printf("FAIL %s: %s: ", g_function, g_what);
  va_list args;
  va_start(args, format);
  vprintf(format, args);
  va_end(args);
  putchar('\n');
  return 0;
}

/* A refused call: the code wanted, and a message that starts with the code's name,
 * names it once and names `field`. */
static int refusal_ok(frusta_result got, frusta_result want, const char* field) {
  const char* m = frusta_last_error();
  const char* code = frusta_result_name(want);
  const size_t n = strlen(code);
  return got == want && m && strncmp(m, code, n) == 0 && !strstr(m + n, code) && contains(m, field);
}

static int refused(frusta_result got, frusta_result want, const char* field) {
  ++g_calls;
  const char* m = frusta_last_error();
  return verify(refusal_ok(got, want, field), "-> %s, want %s naming '%s': \"%s\"", frusta_result_name(got),
                frusta_result_name(want), field, m ? m : "(null)");
}

static int accepted(frusta_result got) {
  ++g_calls;
  return verify(got == FRUSTA_OK, "-> %s, want FRUSTA_OK: \"%s\"", frusta_result_name(got),
                got == FRUSTA_OK ? "" : frusta_last_error());
}

/* ------------------------------------------------------------------ values */

#define SENTINEL 0xA5

static void fill(void* p, size_t n) { memset(p, SENTINEL, n); }

static int is_sentinel(const void* p, size_t n) {
  const unsigned char* bytes = (const unsigned char*)p;
  for (size_t i = 0; i < n; ++i)
    if (bytes[i] != SENTINEL) return 0;
  return 1;
}

static int all_finite(const double* v, size_t n) {
  for (size_t i = 0; i < n; ++i)
    if (!isfinite(v[i])) return 0;
  return 1;
}

static double norm_n(const double* v, int n) {
  double s = 0.0;
  for (int i = 0; i < n; ++i) s += v[i] * v[i];
  return sqrt(s);
}

static int unit_quaternion(const double q[4]) { return fabs(norm_n(q, 4) - 1.0) <= 1e-9; }

/* v rotated by the unit quaternion q (x, y, z, w): v + 2w (u x v) + 2 u x (u x v). */
static void rotate(const double q[4], const double v[3], double out[3]) {
  const double t[3] = {2.0 * (q[1] * v[2] - q[2] * v[1]), 2.0 * (q[2] * v[0] - q[0] * v[2]),
                       2.0 * (q[0] * v[1] - q[1] * v[0])};
  out[0] = v[0] + q[3] * t[0] + (q[1] * t[2] - q[2] * t[1]);
  out[1] = v[1] + q[3] * t[1] + (q[2] * t[0] - q[0] * t[2]);
  out[2] = v[2] + q[3] * t[2] + (q[0] * t[1] - q[1] * t[0]);
}

/* The doubles every def field and argument meets, besides its own limits. */
static const double kHostile[] = {NAN, -NAN, INFINITY, -INFINITY, 1e300, -1e300, DBL_MAX,
                                  -DBL_MAX, 1e-300, -0.0, DBL_MIN, DBL_TRUE_MIN, -DBL_TRUE_MIN};
#define HOSTILE_COUNT ((int)(sizeof kHostile / sizeof kHostile[0]))
static const int32_t kHostileInts[] = {INT32_MIN, -1, 0, INT32_MAX};
#define HOSTILE_INT_COUNT 4

/* What a value in [lo, hi] (finite bounds) calls for. */
static frusta_result want_for(double v, double lo, double hi) {
  if (!isfinite(v)) return FRUSTA_ERROR_NOT_FINITE;
  return v >= lo && v <= hi ? FRUSTA_OK : FRUSTA_ERROR_OUT_OF_RANGE;
}

/* The values a field is tried with: the hostile ones, its limits and just beyond. */
static int field_values(double lo, double hi, double out[HOSTILE_COUNT + 4]) {
  int n = 0;
  for (int i = 0; i < HOSTILE_COUNT; ++i) out[n++] = kHostile[i];
  out[n++] = lo;
  out[n++] = hi;
  out[n++] = nextafter(lo, -INFINITY);
  out[n++] = nextafter(hi, INFINITY);
  return n;
}

/* ------------------------------------------------------------------ def fields */

/* How a message names an element: "name", "name[k]", "name[i][j]", or just "name"
 * for arrays a message numbers its own way. */
enum { NAME_SCALAR, NAME_1D, NAME_2D, NAME_ONLY };

/* A double field of a def (or of an argument struct) and its documented range.
 * cross: a value in range may still be refused (OUT_OF_RANGE) by a rule across fields,
 * e.g. joint_max >= joint_min; such a refusal must name some field. */
typedef struct Field {
  const char* name;
  size_t offset;
  int count;    /* doubles in the field */
  int columns;  /* of a 2-D array */
  int naming;
  double lo, hi;
  int cross;
} Field;

static void element_name(const Field* f, int e, char* out, size_t size) {
  if (f->naming == NAME_1D)
    snprintf(out, size, "%s[%d]", f->name, e);
  else if (f->naming == NAME_2D)
    snprintf(out, size, "%s[%d][%d]", f->name, e / f->columns, e % f->columns);
  else
    snprintf(out, size, "%s", f->name);
}

/* Tries a def (or argument) with one element changed: returns the call's result; an
 * accepted one it checks further itself (used, finite). *untouched: 1 if what the
 * call must not change on failure is as it was. */
typedef frusta_result (*DefCall)(const void* def, int* untouched, void* context);

#define MAX_DEF_BYTES 2048

/* Every element of every field, each value of field_values: the result must be the
 * one its range calls for; a refused call changes nothing. */
static void sweep_fields(const char* label, const void* base, size_t size, const Field* fields,
                         int field_count, DefCall call, void* context) {
  unsigned char def[MAX_DEF_BYTES];
  if (!verify(size <= sizeof def, "def of %zu bytes", size)) return;
  for (int fi = 0; fi < field_count; ++fi) {
    const Field* f = &fields[fi];
    double values[HOSTILE_COUNT + 4];
    const int n = field_values(f->lo, f->hi, values);
    for (int e = 0; e < f->count; ++e) {
      char name[96];
      element_name(f, e, name, sizeof name);
      for (int i = 0; i < n; ++i) {
        memcpy(def, base, size);
        memcpy(def + f->offset + (size_t)e * sizeof(double), &values[i], sizeof(double));
        what("%s: %s = %g", label, name, values[i]);
        int untouched = 1;
        const frusta_result got = call(def, &untouched, context);
        const frusta_result want = want_for(values[i], f->lo, f->hi);
        if (want == FRUSTA_OK && f->cross && got == FRUSTA_ERROR_OUT_OF_RANGE) {
          refused(got, FRUSTA_ERROR_OUT_OF_RANGE, "");  /* a rule across fields: named */
        } else if (want == FRUSTA_OK) {
          accepted(got);
        } else {
          refused(got, want, name);
        }
        if (got != FRUSTA_OK) verify(untouched, "a refused call changed something");
      }
    }
  }
}

/* ------------------------------------------------------------------ ids */

/* Every id type is {int32 index1; uint16 world0; uint16 generation}. */
typedef struct RawId {
  int32_t index1;
  uint16_t world0;
  uint16_t generation;
} RawId;

#define TO_RAW(id) ((RawId){(id).index1, (id).world0, (id).generation})
static frusta_hand_id hand_of_raw(RawId r) { return (frusta_hand_id){r.index1, r.world0, r.generation}; }
static frusta_tree_id tree_of_raw(RawId r) { return (frusta_tree_id){r.index1, r.world0, r.generation}; }
static frusta_world_id world_of_raw(RawId r) { return (frusta_world_id){r.index1, r.world0, r.generation}; }
static frusta_object_id object_of_raw(RawId r) {
  return (frusta_object_id){r.index1, r.world0, r.generation};
}
static frusta_device_id device_of_raw(RawId r) {
  return (frusta_device_id){r.index1, r.world0, r.generation};
}

typedef struct BadId {
  RawId id;
  frusta_result want;
  char label[64];
} BadId;

#define MAX_BAD_IDS 24

/* The ids a call must refuse, made from a live one and a destroyed one: null ones,
 * garbage indices, mangled generations and world0 (which must be 0 for standalone
 * ids), and the destroyed id itself. */
static int bad_ids(RawId live, RawId destroyed, int world0_is_zero, BadId out[MAX_BAD_IDS]) {
  int n = 0;
#define BAD(i1, w0, g, code, ...)                                      \
  do {                                                                 \
    out[n].id = (RawId){(i1), (uint16_t)(w0), (uint16_t)(g)};          \
    out[n].want = (code);                                              \
    snprintf(out[n].label, sizeof out[n].label, __VA_ARGS__);          \
    ++n;                                                               \
  } while (0)
  BAD(0, 0, 0, FRUSTA_ERROR_NULL_ID, "a zero id");
  BAD(0, live.world0, live.generation, FRUSTA_ERROR_NULL_ID, "index1 0, the rest live");
  const int32_t indices[] = {INT32_MIN, -1, INT32_MAX, live.index1 + 1000, live.index1 + 65536};
  for (int i = 0; i < 5; ++i)
    BAD(indices[i], live.world0, live.generation, FRUSTA_ERROR_STALE_ID, "index1 %d", indices[i]);
  const uint16_t generations[] = {(uint16_t)(live.generation + 1), (uint16_t)(live.generation - 1),
                                  0, 0xFFFF, (uint16_t)(live.generation ^ 0x100)};
  for (int i = 0; i < 5; ++i)
    if (generations[i] != live.generation)
      BAD(live.index1, live.world0, generations[i], FRUSTA_ERROR_STALE_ID, "generation %u",
          generations[i]);
  const uint16_t worlds[] = {world0_is_zero ? 1 : (uint16_t)(live.world0 ^ 0x100),
                             world0_is_zero ? 0x100 : (uint16_t)(live.world0 ^ 0x1), 0, 0xFFFF,
                             (uint16_t)(live.world0 + 0x80)};
  for (int i = 0; i < 5; ++i)
    if (worlds[i] != live.world0)
      BAD(live.index1, worlds[i], live.generation, FRUSTA_ERROR_STALE_ID, "world0 %u", worlds[i]);
  BAD(destroyed.index1, destroyed.world0, destroyed.generation, FRUSTA_ERROR_STALE_ID,
      "a destroyed id");
#undef BAD
  return n;
}

/* A call with every argument valid but the id; *untouched as for DefCall. */
typedef frusta_result (*IdCall)(RawId id, int* untouched);

/* Each bad id refused with its code, naming `kind` ("world", "object", ...). */
static void sweep_ids(const char* label, const char* kind, RawId live, RawId destroyed,
                      int world0_is_zero, IdCall call) {
  BadId bad[MAX_BAD_IDS];
  const int n = bad_ids(live, destroyed, world0_is_zero, bad);
  for (int i = 0; i < n; ++i) {
    what("%s with %s {%d, %u, %u}", label, bad[i].label, bad[i].id.index1, bad[i].id.world0,
         bad[i].id.generation);
    int untouched = 1;
    const frusta_result got = call(bad[i].id, &untouched);
    refused(got, bad[i].want, kind);
    verify(untouched, "a refused call changed something");
  }
}

/* is_valid: 0 for each bad id, 1 for the live one. */
static void sweep_valid(const char* label, RawId live, RawId destroyed, int world0_is_zero,
                        int32_t (*valid)(RawId)) {
  BadId bad[MAX_BAD_IDS];
  const int n = bad_ids(live, destroyed, world0_is_zero, bad);
  for (int i = 0; i < n; ++i) {
    what("%s with %s {%d, %u, %u}", label, bad[i].label, bad[i].id.index1, bad[i].id.world0,
         bad[i].id.generation);
    ++g_calls;
    verify(valid(bad[i].id) == 0, "says valid");
  }
  what("%s with the live id", label);
  ++g_calls;
  verify(valid(live) == 1, "says invalid");
}

/* ------------------------------------------------------------------ fixtures */

static frusta_tree_id g_box;        /* press_box: a 3 cm cube, baked at build time */
static frusta_tree_id g_plate;      /* million_leaves: 10^6 leaves on a 1 x 1 m plate */
static frusta_tree_id g_dead_tree;  /* loaded, then destroyed */
static frusta_hand_id g_hand;       /* a standalone default (right) hand */
static frusta_hand_id g_dead_hand;
static frusta_segment g_tip;        /* its open index fingertip segment, hand frame */
static frusta_world_id g_dead_world;
static frusta_hand_id g_dead_world_hand; /* a hand of g_dead_world */

static void object_path(const char* name, char* out, size_t size) {
  snprintf(out, size, "%s/%s.frtree", FRUSTA_TEST_OBJECTS_DIR, name);
}

static frusta_result load_object(const char* name, frusta_tree_id* out) {
  char path[1024];
  object_path(name, path, sizeof path);
  return frusta_create_sphere_tree_from_file(path, out);
}

static const frusta_pose kIdentity = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0, 1.0}};

/* A world, its def (for its limits), its hands and the objects it should hold. Hand 0
 * is a right hand at y = 0, hand 1 (if any) a left hand at y = kLeftY, each with a
 * box under its index fingertip (objects 0 and 1). */
#define RIG_OBJECTS 8
#define LEFT_Y 0.5
typedef struct Rig {
  frusta_world_id world;
  frusta_world_def def;
  int32_t hands;
  frusta_hand_id hand[16]; /* the world's hands, in creation order */
  frusta_object_id object[RIG_OBJECTS];
  int objects;
  frusta_pose palm[2];  /* the last haptic input set, per hand */
  double angles[2][FRUSTA_HAND_JOINT_COUNT];
} Rig;

static Rig g_a, g_b;                   /* two live worlds: each one's ids are foreign to the other */
static frusta_object_id g_dead_object; /* an object of g_a, removed */

/* A box's object def: its top `gap` metres below hand `hand`'s open index fingertip. */
static frusta_object_def box_under_tip(int hand, double gap) {
  frusta_object_def def = frusta_default_object_def();
  const double y = hand == 0 ? g_tip.distal[1] : LEFT_Y - g_tip.distal[1];
  def.pose.position[0] = g_tip.distal[0] - 0.01;
  def.pose.position[1] = y;
  def.pose.position[2] = g_tip.distal[2] - g_tip.distal_radius - 0.015 - gap;
  return def;
}

/* The pressing input of hand `hand` at step i of n: from 5 mm above down to `depth`
 * into the box over the first half, then a 1 cm slide along x and back, the fingers
 * curling to `curl` radians (beyond their limits: clamped). */
static void press_input(int hand, int i, int n, double depth, double curl, frusta_pose* palm,
                        double angles[FRUSTA_HAND_JOINT_COUNT]) {
  const double half = 0.5 * n;
  const double down = i < half ? i / half : 1.0;
  *palm = kIdentity;
  palm->position[1] = hand == 0 ? 0.0 : LEFT_Y;
  palm->position[2] = 0.005 - (0.005 + depth) * down;
  if (i >= half) palm->position[0] = 0.01 * sin(3.14159265358979 * (i - half) / half);
  for (int j = 0; j < FRUSTA_HAND_JOINT_COUNT; ++j)
    angles[j] = j % FRUSTA_JOINTS_PER_FINGER == 0 ? 0.0 : curl * i / n;
}

static frusta_world_state read_state(frusta_world_id world, frusta_result* result) {
  frusta_world_state s;
  memset(&s, 0, sizeof s);
  s.struct_size = (int32_t)sizeof s;
  *result = frusta_world_read(world, &s);
  return s;
}

static frusta_result get_hand(frusta_world_id world, frusta_hand_id hand, frusta_world_hand* out) {
  memset(out, 0, sizeof *out);
  out->struct_size = (int32_t)sizeof *out;
  return frusta_world_get_hand(world, hand, out);
}

static frusta_result get_object(frusta_world_id world, frusta_object_id object,
                                frusta_object_state* out) {
  memset(out, 0, sizeof *out);
  out->struct_size = (int32_t)sizeof *out;
  return frusta_world_get_object(world, object, out);
}

static int object_finite(const frusta_object_state* o) {
  return all_finite(o->pose.position, 3) && all_finite(o->pose.rotation, 4) &&
         unit_quaternion(o->pose.rotation) && all_finite(o->linear_velocity, 3) &&
         all_finite(o->angular_velocity, 3) && all_finite(o->reaction_force, 3) &&
         all_finite(o->reaction_torque, 3) && (o->dynamic == 0 || o->dynamic == 1);
}

/* |v| <= limit, allowing for rounding in the scaling that put it there. */
static int within(double value, double limit) { return fabs(value) <= limit * (1.0 + 1e-9) + 1e-12; }

#define MAX_CHECKED_CONTACTS 4096
static frusta_world_contact g_contacts[MAX_CHECKED_CONTACTS];

/* Latches the newest step and checks all it reports: finite, unit quaternions, counts
 * within capacity, device outputs within the world's limits, every contact's object
 * present, and the rig's objects present and finite. */
static int check_world(const Rig* rig) {
  const int failed_before = g_entry_failed;
  frusta_result r;
  const frusta_world_state s = read_state(rig->world, &r);
  if (!verify(r == FRUSTA_OK, "frusta_world_read -> %s: %s", frusta_result_name(r), frusta_last_error()))
    return 0;
  verify(s.hand_count == rig->hands, "hand_count %d, want %d", s.hand_count, rig->hands);
  verify(isfinite(s.time) && s.time >= 0.0 && isfinite(s.step_us) && s.step_us >= 0.0 &&
             isfinite(s.step_us_p50) && isfinite(s.step_us_p99) && isfinite(s.step_us_max) &&
             isfinite(s.wake_late_us_p50) && isfinite(s.wake_late_us_p99) &&
             isfinite(s.wake_late_us_max) && isfinite(s.achieved_rate_hz) && s.overruns >= 0 &&
             s.rejected_inputs >= 0,
         "world state not finite: time %g, step_us %g, rate %g", s.time, s.step_us,
         s.achieved_rate_hz);
  verify(s.object_count >= 0 && s.object_count <= rig->def.max_objects, "object_count %d of %d",
         s.object_count, rig->def.max_objects);
  const frusta_world_def* d = &rig->def;
  for (int32_t h = 0; h < s.hand_count; ++h) {
    frusta_world_hand wh;
    r = get_hand(rig->world, rig->hand[h], &wh);
    if (!verify(r == FRUSTA_OK, "get_hand(%d) -> %s", h, frusta_result_name(r))) continue;
    if (!wh.solved) continue;
    int finite = all_finite(wh.graphic_palm.position, 3) && all_finite(wh.graphic_palm.rotation, 4) &&
                 all_finite(wh.graphic_angles, FRUSTA_HAND_JOINT_COUNT) &&
                 all_finite(wh.haptic_palm.position, 3) && all_finite(wh.haptic_palm.rotation, 4) &&
                 all_finite(wh.haptic_angles, FRUSTA_HAND_JOINT_COUNT) &&
                 all_finite(&wh.fingertip_force[0][0], 15) && all_finite(wh.finger_resistance, 5) &&
                 all_finite(wh.joint_torque, FRUSTA_HAND_JOINT_COUNT) &&
                 all_finite(wh.palm_force, 3) && all_finite(wh.palm_torque, 3);
    if (!verify(finite, "hand %d reports a non-finite value", h)) continue;
    verify(unit_quaternion(wh.graphic_palm.rotation) && unit_quaternion(wh.haptic_palm.rotation),
           "hand %d: palm quaternions not unit", h);
    verify(wh.contact_count >= 0 && wh.pressing >= 0 && wh.pressing <= wh.contact_count &&
               wh.slipping >= 0 && wh.slipping <= wh.pressing && wh.substeps >= 0 &&
               wh.substeps <= d->max_substeps && (wh.lagging | wh.infeasible) <= 1 &&
               wh.lagging >= 0 && wh.infeasible >= 0,
           "hand %d counts: contacts %d, pressing %d, slipping %d, substeps %d", h,
           wh.contact_count, wh.pressing, wh.slipping, wh.substeps);
    int limited = 1;
    for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
      limited &= within(norm_n(wh.fingertip_force[f], 3), d->max_fingertip_force);
      limited &= wh.finger_resistance[f] >= 0.0 && within(wh.finger_resistance[f], d->max_finger_resistance);
    }
    for (int j = 0; j < FRUSTA_HAND_JOINT_COUNT; ++j) limited &= within(wh.joint_torque[j], d->max_joint_torque);
    limited &= within(norm_n(wh.palm_force, 3), d->max_palm_force) &&
               within(norm_n(wh.palm_torque, 3), d->max_palm_torque);
    verify(limited, "hand %d: a device output beyond the world's limits (palm force %g of %g)", h,
           norm_n(wh.palm_force, 3), d->max_palm_force);

    int32_t count = -1;
    r = frusta_world_get_contacts(rig->world, rig->hand[h], NULL, 0, &count);
    if (!verify(r == FRUSTA_OK, "get_contacts size query -> %s", frusta_result_name(r))) continue;
    verify(count >= 0 && count <= d->max_contacts_per_hand && count <= wh.contact_count,
           "hand %d: %d contacts kept of %d, max %d", h, count, wh.contact_count,
           d->max_contacts_per_hand);
    if (count > MAX_CHECKED_CONTACTS) count = MAX_CHECKED_CONTACTS;
    int32_t got = -1;
    r = frusta_world_get_contacts(rig->world, rig->hand[h], g_contacts, MAX_CHECKED_CONTACTS, &got);
    if (!verify(r == FRUSTA_OK, "get_contacts -> %s", frusta_result_name(r))) continue;
    for (int32_t c = 0; c < got && c < MAX_CHECKED_CONTACTS; ++c) {
      const frusta_world_contact* k = &g_contacts[c];
      const int ok = k->body >= 0 && k->body <= 15 && k->leaf >= -1 &&
                     (k->slipping == 0 || k->slipping == 1) && isfinite(k->distance) &&
                     all_finite(k->graphic_point, 3) && all_finite(k->haptic_point, 3) &&
                     all_finite(k->normal, 3) && fabs(norm_n(k->normal, 3) - 1.0) <= 1e-6 &&
                     all_finite(k->normal_force, 3) && all_finite(k->friction, 3);
      if (!verify(ok, "hand %d contact %d: body %d leaf %d distance %g |normal| %g", h, c,
                  k->body, k->leaf, k->distance, norm_n(k->normal, 3)))
        break;
      frusta_object_state o;
      r = get_object(rig->world, k->object, &o);
      if (!verify(r == FRUSTA_OK, "contact %d's object -> %s: %s", c, frusta_result_name(r),
                  frusta_last_error()))
        break;
    }
  }
  for (int i = 0; i < rig->objects; ++i) {
    frusta_object_state o;
    r = get_object(rig->world, rig->object[i], &o);
    if (verify(r == FRUSTA_OK, "object %d -> %s: %s (step %llu, %d objects)", i, frusta_result_name(r),
               frusta_last_error(), (unsigned long long)s.step, s.object_count))
      verify(object_finite(&o),
             "object %d not finite: position (%g, %g, %g), rotation (%g, %g, %g, %g), velocity (%g, %g, "
             "%g), spin (%g, %g, %g), reaction (%g, %g, %g), torque (%g, %g, %g)",
             i, o.pose.position[0], o.pose.position[1], o.pose.position[2], o.pose.rotation[0],
             o.pose.rotation[1], o.pose.rotation[2], o.pose.rotation[3], o.linear_velocity[0],
             o.linear_velocity[1], o.linear_velocity[2], o.angular_velocity[0], o.angular_velocity[1],
             o.angular_velocity[2], o.reaction_force[0], o.reaction_force[1], o.reaction_force[2],
             o.reaction_torque[0], o.reaction_torque[1], o.reaction_torque[2]);
  }
  return g_entry_failed == failed_before;
}

/* Sets hand `hand`'s haptic input and remembers it. */
static frusta_result set_input(Rig* rig, int hand, const frusta_pose* palm, const double* angles) {
  const frusta_result r =
      frusta_world_set_haptic(rig->world, rig->hand[hand], palm, angles, FRUSTA_HAND_JOINT_COUNT);
  if (r == FRUSTA_OK) {
    rig->palm[hand] = *palm;
    memcpy(rig->angles[hand], angles, sizeof rig->angles[hand]);
  }
  return r;
}

/* The latched step used each hand's last input: the palm as given (normalised) and the
 * angles as given. */
static int inputs_used(const Rig* rig) {
  int ok = 1;
  for (int h = 0; h < rig->hands; ++h) {
    frusta_world_hand wh;
    if (get_hand(rig->world, rig->hand[h], &wh) != FRUSTA_OK)
      return verify(0, "get_hand -> %s", frusta_last_error());
    const double n = norm_n(rig->palm[h].rotation, 4);
    for (int k = 0; k < 3; ++k) ok &= wh.haptic_palm.position[k] == rig->palm[h].position[k];
    for (int k = 0; k < 4; ++k) ok &= fabs(wh.haptic_palm.rotation[k] - rig->palm[h].rotation[k] / n) <= 1e-12;
    for (int j = 0; j < FRUSTA_HAND_JOINT_COUNT; ++j) ok &= wh.haptic_angles[j] == rig->angles[h][j];
    ok &= wh.solved == 1;
    if (!verify(ok, "hand %d: the step did not use the input accepted (solved %d, palm z %g, want %g)",
                h, wh.solved, wh.haptic_palm.position[2], rig->palm[h].position[2]))
      return 0;
  }
  return ok;
}

/* Steps the rig n times with both hands pressing its boxes `depth` deep, fingers curling
 * to `curl`; checks every `every` steps (and the last) that the inputs were used and
 * all is finite. */
static int press(Rig* rig, int n, double depth, double curl, int every) {
  for (int i = 0; i <= n; ++i) {
    for (int h = 0; h < rig->hands; ++h) {
      frusta_pose palm;
      double angles[FRUSTA_HAND_JOINT_COUNT];
      press_input(h, i, n, depth, curl, &palm, angles);
      const frusta_result r = set_input(rig, h, &palm, angles);
      if (!verify(r == FRUSTA_OK, "set_haptic at step %d -> %s", i, frusta_last_error())) return 0;
    }
    const frusta_result r = frusta_world_step(rig->world);
    g_calls += rig->hands + 1;
    if (!verify(r == FRUSTA_OK, "step %d -> %s", i, frusta_last_error())) return 0;
    if (i % every == 0 || i == n) {
      if (!check_world(rig) || !inputs_used(rig)) return 0;
    }
  }
  return 1;
}

/* A rig: world from def, a right hand (and a left one when hands == 2), each with a
 * box (object def from make_box, or the default box) under its index tip. */
static int make_rig(Rig* rig, const frusta_world_def* def, int hands) {
  memset(rig, 0, sizeof *rig);
  rig->def = *def;
  frusta_result r = frusta_create_world(def, &rig->world);
  if (!verify(r == FRUSTA_OK, "create_world -> %s", frusta_last_error())) return 0;
  for (int h = 0; h < hands; ++h) {
    frusta_hand_def hd = frusta_default_hand_def();
    hd.side = h == 0 ? FRUSTA_HAND_RIGHT : FRUSTA_HAND_LEFT;
    r = frusta_create_world_hand(rig->world, &hd, &rig->hand[h]);
    if (!verify(r == FRUSTA_OK && rig->hand[h].index1 == h + 1, "create_world_hand -> %s",
                frusta_last_error()))
      return 0;
    rig->palm[h] = kIdentity;
  }
  rig->hands = hands;
  return 1;
}

static int add_rig_object(Rig* rig, frusta_tree_id tree, const frusta_object_def* def) {
  const frusta_result r = frusta_create_object(rig->world, tree, def, &rig->object[rig->objects]);
  if (!verify(r == FRUSTA_OK, "add_object -> %s", frusta_last_error())) return 0;
  ++rig->objects;
  return 1;
}

static int make_press_rig(Rig* rig, const frusta_world_def* def, int hands,
                          const frusta_object_def* box) {
  if (!make_rig(rig, def, hands)) return 0;
  for (int h = 0; h < hands; ++h) {
    frusta_object_def o = box ? *box : frusta_default_object_def();
    const frusta_object_def placed = box_under_tip(h, 0.0);
    memcpy(o.pose.position, placed.pose.position, sizeof o.pose.position);
    if (!add_rig_object(rig, g_box, &o)) return 0;
  }
  return 1;
}

static void destroy_rig(Rig* rig) {
  if (frusta_world_is_valid(rig->world)) frusta_destroy_world(rig->world);
  memset(rig, 0, sizeof *rig);
}

static int setup(void) {
  g_function = "setup";
  what("fixtures");
  if (!verify(load_object("press_box", &g_box) == FRUSTA_OK, "load press_box: %s", frusta_last_error()))
    return 0;
  if (!verify(load_object("million_leaves", &g_plate) == FRUSTA_OK, "load million_leaves: %s",
              frusta_last_error()))
    return 0;
  if (!verify(load_object("press_box", &g_dead_tree) == FRUSTA_OK &&
                  frusta_destroy_sphere_tree(g_dead_tree) == FRUSTA_OK,
              "load and destroy a tree: %s", frusta_last_error()))
    return 0;
  const frusta_hand_def hd = frusta_default_hand_def();
  if (!verify(frusta_create_hand(&hd, &g_hand) == FRUSTA_OK &&
                  frusta_create_hand(&hd, &g_dead_hand) == FRUSTA_OK &&
                  frusta_destroy_hand(g_dead_hand) == FRUSTA_OK,
              "hands: %s", frusta_last_error()))
    return 0;
  frusta_segment segments[FRUSTA_HAND_SEGMENT_COUNT];
  int32_t count = 0;
  if (!verify(frusta_hand_get_segments(g_hand, segments, FRUSTA_HAND_SEGMENT_COUNT, &count) == FRUSTA_OK,
              "segments: %s", frusta_last_error()))
    return 0;
  g_tip = segments[FRUSTA_FINGER_INDEX * FRUSTA_SEGMENTS_PER_FINGER + 2];
  const frusta_world_def wd = frusta_default_world_def();
  if (!verify(frusta_create_world(&wd, &g_dead_world) == FRUSTA_OK &&
                  frusta_create_world_hand(g_dead_world, &hd, &g_dead_world_hand) == FRUSTA_OK &&
                  frusta_destroy_world(g_dead_world) == FRUSTA_OK,
              "a destroyed world with a hand: %s", frusta_last_error()))
    return 0;
  if (!make_press_rig(&g_a, &wd, 2, NULL) || !make_press_rig(&g_b, &wd, 1, NULL)) return 0;
  /* one more object in g_a, removed: a stale object id */
  frusta_object_def far = frusta_default_object_def();
  far.pose.position[2] = -1.0;
  if (!verify(frusta_create_object(g_a.world, g_box, &far, &g_dead_object) == FRUSTA_OK &&
                  frusta_world_step(g_a.world) == FRUSTA_OK &&
                  frusta_destroy_object(g_dead_object) == FRUSTA_OK,
              "a removed object: %s", frusta_last_error()))
    return 0;
  return press(&g_a, 10, 0.002, 0.2, 5) && press(&g_b, 10, 0.002, 0.2, 5);
}

/* ------------------------------------------------------------------ pose arguments */

#define PI 3.14159265358979323846

/* Every element of a pose argument: positions within 1e6 m; a quaternion of any finite
 * components whose norm lies in [0.5, 2], refused naming "rotation" otherwise. */
static void sweep_pose(const char* label, const char* name, DefCall call, void* context) {
  frusta_pose pose;
  char field[96];
  for (int k = 0; k < 7; ++k) {
    double values[HOSTILE_COUNT + 4];
    const int n = k < 3 ? field_values(-1e6, 1e6, values) : field_values(0.5, 2.0, values);
    for (int i = 0; i < n; ++i) {
      pose = kIdentity;
      if (k < 3) pose.position[k] = values[i];
      else pose.rotation[k - 3] = values[i];
      frusta_result want;
      if (k < 3) {
        snprintf(field, sizeof field, "%s.position[%d]", name, k);
        want = want_for(values[i], -1e6, 1e6);
      } else {
        snprintf(field, sizeof field, "%s.rotation", name);
        const double norm = norm_n(pose.rotation, 4);
        want = !isfinite(values[i]) ? FRUSTA_ERROR_NOT_FINITE
               : norm >= 0.5 && norm <= 2.0 ? FRUSTA_OK : FRUSTA_ERROR_OUT_OF_RANGE;
      }
      what("%s: %s[%d] = %g", label, k < 3 ? "position" : "rotation", k < 3 ? k : k - 3, values[i]);
      int untouched = 1;
      const frusta_result got = call(&pose, &untouched, context);
      if (want == FRUSTA_OK) accepted(got);
      else refused(got, want, field);
      if (got != FRUSTA_OK) verify(untouched, "a refused call changed something");
    }
  }
  /* whole quaternions: tiny, huge (finite components, overflowing norm), at the limits */
  static const double quaternions[][4] = {
      {0, 0, 0, 0}, {1e-300, 0, 0, 0}, {DBL_MIN, DBL_MIN, DBL_MIN, DBL_MIN},
      {1e300, 1e300, 0, 0}, {1e154, 1e154, 1e154, 1e154}, {0.3, 0.3, 0.3, 0.3},
      {0.25, 0.25, 0.25, 0.25}, {1, 1, 1, 1}, {-1, -1, -1, -1}, {0, 0, 0, -1}};
  for (size_t q = 0; q < sizeof quaternions / sizeof quaternions[0]; ++q) {
    pose = kIdentity;
    memcpy(pose.rotation, quaternions[q], sizeof pose.rotation);
    const double norm = norm_n(pose.rotation, 4);
    what("%s: rotation (%g, %g, %g, %g)", label, pose.rotation[0], pose.rotation[1],
         pose.rotation[2], pose.rotation[3]);
    snprintf(field, sizeof field, "%s.rotation", name);
    int untouched = 1;
    const frusta_result got = call(&pose, &untouched, context);
    if (norm >= 0.5 && norm <= 2.0) accepted(got);
    else refused(got, FRUSTA_ERROR_OUT_OF_RANGE, field);
    if (got != FRUSTA_OK) verify(untouched, "a refused call changed something");
  }
}

/* ------------------------------------------------------------------ core */

static void t_version(void) {
  what("frusta_version()");
  ++g_calls;
  verify(frusta_version() == FRUSTA_VERSION && frusta_version() == frusta_version(), "%d",
         frusta_version());
}

static void t_abi_version(void) {
  what("frusta_abi_version()");
  ++g_calls;
  verify(frusta_abi_version() == FRUSTA_ABI_VERSION, "%d", frusta_abi_version());
}

static void t_last_error(void) {
  /* a failure sets it, a success leaves it (errno-like), and it stays bounded and
   * terminated after an argument of 10 KB */
  what("frusta_last_error after a refused frusta_check_abi");
  frusta_check_abi(-1);
  char before[1024];
  snprintf(before, sizeof before, "%s", frusta_last_error());
  ++g_calls;
  verify(strncmp(before, "FRUSTA_ERROR_ABI_MISMATCH", 25) == 0, "\"%s\"", before);
  what("frusta_last_error after successful calls");
  frusta_check_abi(FRUSTA_ABI_VERSION);
  frusta_hand_def def = frusta_default_hand_def();
  frusta_hand_def_set_size(&def, 0.2, 0.09);
  ++g_calls;
  verify(strcmp(before, frusta_last_error()) == 0, "changed to \"%s\"", frusta_last_error());
  static char path[10240];
  memset(path, 'x', sizeof path - 1);
  path[sizeof path - 1] = '\0';
  frusta_tree_id tree;
  what("frusta_last_error after a 10 KB path");
  frusta_create_sphere_tree_from_file(path, &tree);
  const char* m = frusta_last_error();
  ++g_calls;
  verify(m && strlen(m) < 4096 && strncmp(m, "FRUSTA_ERROR_", 13) == 0, "%zu bytes",
         m ? strlen(m) : 0);
}

static void t_result_name(void) {
  const int32_t codes[] = {INT32_MIN, -1, FRUSTA_ERROR_CANCELLED + 1, 1000, INT32_MAX};
  for (size_t i = 0; i < sizeof codes / sizeof codes[0]; ++i) {
    what("frusta_result_name(%d)", codes[i]);
    ++g_calls;
    const char* name = frusta_result_name(codes[i]);
    verify(name && strcmp(name, "FRUSTA_ERROR_UNKNOWN") == 0, "\"%s\"", name ? name : "(null)");
  }
  for (int32_t c = 0; c <= FRUSTA_ERROR_CANCELLED; ++c) {
    what("frusta_result_name(%d)", c);
    ++g_calls;
    const char* name = frusta_result_name(c);
    verify(name && strncmp(name, "FRUSTA_", 7) == 0 && strcmp(name, "FRUSTA_ERROR_UNKNOWN") != 0,
           "\"%s\"", name ? name : "(null)");
  }
}

static void t_check_abi(void) {
  const int32_t versions[] = {INT32_MIN, -1, 0, FRUSTA_ABI_VERSION - 1, FRUSTA_ABI_VERSION + 1,
                              INT32_MAX};
  for (size_t i = 0; i < sizeof versions / sizeof versions[0]; ++i) {
    char text[32];
    snprintf(text, sizeof text, "%d", versions[i]);
    what("frusta_check_abi(%d)", versions[i]);
    refused(frusta_check_abi(versions[i]), FRUSTA_ERROR_ABI_MISMATCH, text);
  }
  what("frusta_check_abi(FRUSTA_ABI_VERSION)");
  accepted(frusta_check_abi(FRUSTA_ABI_VERSION));
}

static void t_struct_size(void) {
  static char long_name[10240];
  memset(long_name, 'a', sizeof long_name - 1);
  const char* names[] = {NULL, "", "frusta_world_def ", " frusta_world_def", "FRUSTA_WORLD_DEF",
                         "frusta_world_de", "frusta_world_def\n", "frusta_", long_name};
  for (size_t i = 0; i < sizeof names / sizeof names[0]; ++i) {
    what("frusta_struct_size(\"%.20s\")", names[i] ? names[i] : "(null)");
    ++g_calls;
    verify(frusta_struct_size(names[i]) == 0, "%d", frusta_struct_size(names[i]));
  }
#define SIZE_OF(type)                                                          \
  do {                                                                         \
    what("frusta_struct_size(\"" #type "\")");                                 \
    ++g_calls;                                                                 \
    verify(frusta_struct_size(#type) == (int32_t)sizeof(type), "%d", frusta_struct_size(#type)); \
  } while (0)
  SIZE_OF(frusta_hand_def);
  SIZE_OF(frusta_tracked_joint);
  SIZE_OF(frusta_hand_fitter_id);
  SIZE_OF(frusta_hand_fit_def);
  SIZE_OF(frusta_hand_fit);
  SIZE_OF(frusta_contact_query);
  SIZE_OF(frusta_constraint);
  SIZE_OF(frusta_bake_def);
  SIZE_OF(frusta_sphere_tree_info);
  SIZE_OF(frusta_world_def);
  SIZE_OF(frusta_object_def);
  SIZE_OF(frusta_world_state);
  SIZE_OF(frusta_world_hand);
  SIZE_OF(frusta_object_state);
  SIZE_OF(frusta_device_def);
  SIZE_OF(frusta_device_status);
  SIZE_OF(frusta_device_info);
#undef SIZE_OF
}

/* The struct_size values every struct must refuse. */
static int bad_sizes(int32_t size, int32_t out[8]) {
  const int32_t sizes[] = {0, size - 1, size + 8, -size, INT32_MIN, INT32_MAX, 1, size / 2};
  memcpy(out, sizes, sizeof sizes);
  return 8;
}

/* A def with struct_size and internal_value at the given offsets, tried with every bad
 * size and every wrong cookie: refused with STRUCT_SIZE or DEF_NOT_DEFAULTED naming
 * the struct. */
static void sweep_def_header(const char* label, const char* struct_name, const void* base,
                             size_t size, size_t cookie_offset, DefCall call, void* context) {
  unsigned char def[MAX_DEF_BYTES];
  int32_t sizes[8];
  const int n = bad_sizes((int32_t)size, sizes);
  for (int i = 0; i < n; ++i) {
    memcpy(def, base, size);
    memcpy(def, &sizes[i], sizeof(int32_t));
    what("%s: struct_size %d", label, sizes[i]);
    int untouched = 1;
    refused(call(def, &untouched, context), FRUSTA_ERROR_STRUCT_SIZE, struct_name);
    verify(untouched, "a refused call changed something");
  }
  int32_t cookie;
  memcpy(&cookie, (const unsigned char*)base + cookie_offset, sizeof cookie);
  const int32_t cookies[] = {0, cookie + 1, -cookie, INT32_MIN, INT32_MAX, -1};
  for (int i = 0; i < 6; ++i) {
    memcpy(def, base, size);
    memcpy(def + cookie_offset, &cookies[i], sizeof(int32_t));
    what("%s: internal_value %d", label, cookies[i]);
    int untouched = 1;
    refused(call(def, &untouched, context), FRUSTA_ERROR_DEF_NOT_DEFAULTED, struct_name);
    verify(untouched, "a refused call changed something");
  }
  /* a zeroed def with a right struct_size: what a C host gets from `= {sizeof def}` */
  memset(def, 0, size);
  const int32_t right = (int32_t)size;
  memcpy(def, &right, sizeof right);
  what("%s: a zeroed def", label);
  int untouched = 1;
  refused(call(def, &untouched, context), FRUSTA_ERROR_DEF_NOT_DEFAULTED, struct_name);
  verify(untouched, "a refused call changed something");
}

/* An output struct's size checks: every bad struct_size refused naming the struct, the
 * rest of the struct left as it was. */
typedef frusta_result (*OutCall)(void* out);
static void sweep_out_size(const char* label, const char* struct_name, size_t size, OutCall call) {
  unsigned char out[MAX_DEF_BYTES];
  int32_t sizes[8];
  const int n = bad_sizes((int32_t)size, sizes);
  for (int i = 0; i < n; ++i) {
    fill(out, size);
    memcpy(out, &sizes[i], sizeof(int32_t));
    what("%s: struct_size %d", label, sizes[i]);
    refused(call(out), FRUSTA_ERROR_STRUCT_SIZE, struct_name);
    verify(is_sentinel(out + 4, size - 4), "a refused call wrote into the struct");
  }
}

/* ------------------------------------------------------------------ hands */

#define HAND_FIELD(member) #member, offsetof(frusta_hand_def, member)
static const Field kHandFields[] = {
    {HAND_FIELD(hand_length), 1, 0, NAME_SCALAR, 0.01, 5.0, 0},
    {HAND_FIELD(hand_breadth), 1, 0, NAME_SCALAR, 0.01, 5.0, 0},
    {HAND_FIELD(segment_length), 15, 3, NAME_2D, 1e-4, 5.0, 0},
    {HAND_FIELD(joint_radius), 20, 4, NAME_2D, 1e-4, 5.0, 0},
    {HAND_FIELD(base_position), 15, 3, NAME_2D, -5.0, 5.0, 0},
    {HAND_FIELD(base_rotation), 15, 3, NAME_2D, -2.0 * PI, 2.0 * PI, 0},
    {HAND_FIELD(joint_min), 20, 4, NAME_2D, -PI, PI, 1},  /* joint_min <= joint_max */
    {HAND_FIELD(joint_max), 20, 4, NAME_2D, -PI, PI, 1},
    {HAND_FIELD(palm_length), 1, 0, NAME_SCALAR, 1e-4, 5.0, 1},  /* at most 4096 palm spheres */
    {HAND_FIELD(palm_breadth), 1, 0, NAME_SCALAR, 1e-4, 5.0, 1},
    {HAND_FIELD(palm_thickness), 1, 0, NAME_SCALAR, 1e-4, 5.0, 1},
};
#define HAND_FIELD_COUNT ((int)(sizeof kHandFields / sizeof kHandFields[0]))

/* Everything a standalone hand reports is finite: segments, palm spheres, a Jacobian. */
static int hand_finite(frusta_hand_id hand) {
  frusta_segment segments[FRUSTA_HAND_SEGMENT_COUNT];
  int32_t count = 0;
  if (!verify(frusta_hand_get_segments(hand, segments, FRUSTA_HAND_SEGMENT_COUNT, &count) == FRUSTA_OK,
              "get_segments: %s", frusta_last_error()))
    return 0;
  for (int s = 0; s < count; ++s)
    if (!verify(all_finite(segments[s].proximal, 3) && all_finite(segments[s].distal, 3) &&
                    isfinite(segments[s].proximal_radius) && segments[s].proximal_radius >= 0.0 &&
                    isfinite(segments[s].distal_radius) && segments[s].distal_radius >= 0.0,
                "segment %d not finite", s))
      return 0;
  static frusta_sphere spheres[4096];
  if (!verify(frusta_hand_get_palm_spheres(hand, spheres, 4096, &count) == FRUSTA_OK && count > 0 &&
                  count <= 4096,
              "palm spheres (%d): %s", count, frusta_last_error()))
    return 0;
  for (int s = 0; s < count; ++s)
    if (!verify(all_finite(spheres[s].center, 3) && isfinite(spheres[s].radius), "palm sphere %d", s))
      return 0;
  double point[3], jacobian[30];
  const double local[3] = {0.01, 0.0, 0.0};
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    if (!verify(frusta_hand_point_jacobian(hand, f, 2, local, point, jacobian, 30, &count) ==
                        FRUSTA_OK &&
                    count == 30 && all_finite(point, 3) && all_finite(jacobian, 30),
                "jacobian of finger %d: %s", f, frusta_last_error()))
      return 0;
  return 1;
}

static frusta_result call_create_hand(const void* def, int* untouched, void* context) {
  (void)context;
  frusta_hand_id hand;
  fill(&hand, sizeof hand);
  const frusta_result r = frusta_create_hand((const frusta_hand_def*)def, &hand);
  if (r != FRUSTA_OK) {
    *untouched = is_sentinel(&hand, sizeof hand);
    return r;
  }
  verify(frusta_hand_is_valid(hand) == 1, "the hand created is not valid");
  hand_finite(hand);
  frusta_destroy_hand(hand);
  return r;
}

static void t_default_hand_def(void) {
  const frusta_hand_def a = frusta_default_hand_def(), b = frusta_default_hand_def();
  what("frusta_default_hand_def()");
  g_calls += 2;
  verify(memcmp(&a, &b, sizeof a) == 0 && a.struct_size == (int32_t)sizeof a && a.internal_value != 0 &&
             a.side == FRUSTA_HAND_RIGHT,
         "not a deterministic def of this size with its cookie");
  verify(all_finite(&a.hand_length, (offsetof(frusta_hand_def, internal_value) -
                                     offsetof(frusta_hand_def, hand_length)) / sizeof(double)),
         "a non-finite default");
  int untouched = 1;
  accepted(call_create_hand(&a, &untouched, NULL));
}

static frusta_result call_set_size(const void* sizes, int* untouched, void* context) {
  frusta_hand_def* def = (frusta_hand_def*)context;
  const double* s = (const double*)sizes;
  const frusta_hand_def before = *def;
  const frusta_result r = frusta_hand_def_set_size(def, s[0], s[1]);
  if (r != FRUSTA_OK) {
    *untouched = memcmp(&before, def, sizeof before) == 0;
    return r;
  }
  /* what set_size accepts, create_hand must too */
  int ignored = 1;
  verify(call_create_hand(def, &ignored, NULL) == FRUSTA_OK, "a sized def is refused by create_hand: %s",
         frusta_last_error());
  *def = frusta_default_hand_def();
  return r;
}

static frusta_result call_set_size_def(const void* def, int* untouched, void* context) {
  (void)context;
  frusta_hand_def copy;
  memcpy(&copy, def, sizeof copy);
  const frusta_result r = frusta_hand_def_set_size(&copy, 0.2, 0.09);
  *untouched = memcmp(&copy, def, sizeof copy) == 0;
  return r;
}

static void t_hand_def_set_size(void) {
  frusta_hand_def def = frusta_default_hand_def();
  what("frusta_hand_def_set_size(NULL, ...)");
  refused(frusta_hand_def_set_size(NULL, 0.2, 0.09), FRUSTA_ERROR_NULL_POINTER, "def");
  sweep_def_header("frusta_hand_def_set_size", "frusta_hand_def", &def, sizeof def,
                   offsetof(frusta_hand_def, internal_value), call_set_size_def, NULL);
  const double base[2] = {0.19, 0.085};
  /* each size alone in its range, and every corner of the two: hands of 1 cm to 5 m;
   * a palm too thin for its size may be refused (at most 4096 palm spheres), by name */
  const Field fields[] = {{"hand_length", 0, 1, 0, NAME_SCALAR, 0.01, 5.0, 1},
                          {"hand_breadth", sizeof(double), 1, 0, NAME_SCALAR, 0.01, 5.0, 1}};
  sweep_fields("frusta_hand_def_set_size", base, sizeof base, fields, 2, call_set_size, &def);
  const double corners[4][2] = {{0.01, 0.01}, {5.0, 5.0}, {0.01, 5.0}, {5.0, 0.01}};
  for (int c = 0; c < 4; ++c) {
    what("frusta_hand_def_set_size(%g, %g)", corners[c][0], corners[c][1]);
    int untouched = 1;
    const frusta_result r = call_set_size(corners[c], &untouched, &def);
    if (r == FRUSTA_OK) {
      accepted(r);
    } else {
      /* sizes in range whose proportions give no valid hand: refused, naming both */
      refused(r, FRUSTA_ERROR_OUT_OF_RANGE, "hand_length");
      refused(r, FRUSTA_ERROR_OUT_OF_RANGE, "hand_breadth");
    }
    verify(untouched, "a refused call changed the def");
  }
}

/* A hand with every part at its smallest (1e-4 m; joints locked at pi) or its largest
 * (5 m; joints free over [-pi, pi]), bases at the ends of their ranges. */
static frusta_hand_def extreme_hand_def(int big) {
  frusta_hand_def d = frusta_default_hand_def();
  const double part = big ? 5.0 : 1e-4;
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    for (int s = 0; s < 3; ++s) d.segment_length[f][s] = part;
    for (int j = 0; j < 4; ++j) d.joint_radius[f][j] = part;
    for (int k = 0; k < 3; ++k) d.base_position[f][k] = big ? 5.0 : -5.0;
    for (int k = 0; k < 3; ++k) d.base_rotation[f][k] = big ? 2.0 * PI : -2.0 * PI;
    for (int j = 0; j < 4; ++j) {
      d.joint_min[f][j] = big ? -PI : PI;
      d.joint_max[f][j] = PI;
    }
  }
  d.hand_length = d.hand_breadth = big ? 5.0 : 0.01;
  d.palm_length = d.palm_breadth = d.palm_thickness = big ? 5.0 : 0.01;
  return d;
}

static void t_create_hand(void) {
  const frusta_hand_def def = frusta_default_hand_def();
  frusta_hand_id hand;
  fill(&hand, sizeof hand);
  what("frusta_create_hand(NULL, &hand)");
  refused(frusta_create_hand(NULL, &hand), FRUSTA_ERROR_NULL_POINTER, "def");
  verify(is_sentinel(&hand, sizeof hand), "out_hand written");
  what("frusta_create_hand(&def, NULL)");
  refused(frusta_create_hand(&def, NULL), FRUSTA_ERROR_NULL_POINTER, "out_hand");
  sweep_def_header("frusta_create_hand", "frusta_hand_def", &def, sizeof def,
                   offsetof(frusta_hand_def, internal_value), call_create_hand, NULL);
  sweep_fields("frusta_create_hand", &def, sizeof def, kHandFields, HAND_FIELD_COUNT,
               call_create_hand, NULL);
  const int32_t sides[] = {INT32_MIN, -1, 2, INT32_MAX};
  for (int i = 0; i < 4; ++i) {
    frusta_hand_def d = def;
    d.side = sides[i];
    what("frusta_create_hand: side %d", sides[i]);
    int untouched = 1;
    refused(call_create_hand(&d, &untouched, NULL), FRUSTA_ERROR_OUT_OF_RANGE, "side");
    verify(untouched, "out_hand written");
  }
  /* every part at its smallest, and at its largest, at once */
  for (int big = 0; big < 2; ++big) {
    const frusta_hand_def d = extreme_hand_def(big);
    const double part = big ? 5.0 : 1e-4;
    what("frusta_create_hand: every part %g", part);
    int untouched = 1;
    accepted(call_create_hand(&d, &untouched, NULL));
  }
}

static frusta_result call_destroy_hand(RawId id, int* untouched) {
  const frusta_result r = frusta_destroy_hand(hand_of_raw(id));
  *untouched = frusta_hand_is_valid(g_hand) == 1;
  return r;
}

static int32_t valid_hand(RawId id) { return frusta_hand_is_valid(hand_of_raw(id)); }

static void t_destroy_hand(void) {
  sweep_ids("frusta_destroy_hand", "hand", TO_RAW(g_hand), TO_RAW(g_dead_hand), 1, call_destroy_hand);
  const frusta_hand_def def = frusta_default_hand_def();
  frusta_hand_id hand;
  what("frusta_destroy_hand twice");
  accepted(frusta_create_hand(&def, &hand));
  accepted(frusta_destroy_hand(hand));
  refused(frusta_destroy_hand(hand), FRUSTA_ERROR_STALE_ID, "hand");
}

static void t_hand_is_valid(void) {
  sweep_valid("frusta_hand_is_valid", TO_RAW(g_hand), TO_RAW(g_dead_hand), 1, valid_hand);
}

/* A standalone hand's whole state, to compare before and after a refused call. */
typedef struct HandSnapshot {
  double angles[FRUSTA_HAND_JOINT_COUNT];
  frusta_segment segments[FRUSTA_HAND_SEGMENT_COUNT];
} HandSnapshot;

static HandSnapshot hand_snapshot(frusta_hand_id hand) {
  HandSnapshot s;
  memset(&s, 0, sizeof s);
  int32_t count;
  frusta_hand_get_joint_angles(hand, s.angles, FRUSTA_HAND_JOINT_COUNT, &count);
  frusta_hand_get_segments(hand, s.segments, FRUSTA_HAND_SEGMENT_COUNT, &count);
  return s;
}

static int same_hand(frusta_hand_id hand, const HandSnapshot* before) {
  const HandSnapshot now = hand_snapshot(hand);
  return memcmp(&now, before, sizeof now) == 0;
}

static frusta_result call_set_palm_pose_id(RawId id, int* untouched) {
  const HandSnapshot before = hand_snapshot(g_hand);
  const frusta_pose pose = {{0.1, 0.0, 0.0}, {0.0, 0.0, 0.0, 1.0}};
  const frusta_result r = frusta_hand_set_palm_pose(hand_of_raw(id), &pose);
  *untouched = same_hand(g_hand, &before);
  return r;
}

static frusta_result call_set_palm_pose(const void* pose, int* untouched, void* context) {
  (void)context;
  const HandSnapshot before = hand_snapshot(g_hand);
  const frusta_pose* p = (const frusta_pose*)pose;
  const frusta_result r = frusta_hand_set_palm_pose(g_hand, p);
  if (r != FRUSTA_OK) {
    *untouched = same_hand(g_hand, &before);
    return r;
  }
  /* used: every segment moved rigidly with the palm (the hand was at the identity) */
  if (hand_finite(g_hand)) {
    const HandSnapshot now = hand_snapshot(g_hand);
    double q[4];
    const double n = norm_n(p->rotation, 4);
    for (int k = 0; k < 4; ++k) q[k] = p->rotation[k] / n;
    double worst = 0.0;
    for (int s = 0; s < FRUSTA_HAND_SEGMENT_COUNT; ++s) {
      double moved[3];
      rotate(q, before.segments[s].distal, moved);
      for (int k = 0; k < 3; ++k)
        worst = fmax(worst, fabs(now.segments[s].distal[k] - moved[k] - p->position[k]));
    }
    verify(worst <= 1e-9 * (1.0 + norm_n(p->position, 3)), "the hand did not follow the palm (off by %g m)",
           worst);
  }
  frusta_hand_set_palm_pose(g_hand, &kIdentity);
  return r;
}

static void t_hand_set_palm_pose(void) {
  sweep_ids("frusta_hand_set_palm_pose", "hand", TO_RAW(g_hand), TO_RAW(g_dead_hand), 1,
            call_set_palm_pose_id);
  what("frusta_hand_set_palm_pose(hand, NULL)");
  const HandSnapshot before = hand_snapshot(g_hand);
  refused(frusta_hand_set_palm_pose(g_hand, NULL), FRUSTA_ERROR_NULL_POINTER, "pose");
  verify(same_hand(g_hand, &before), "the hand changed");
  sweep_pose("frusta_hand_set_palm_pose", "pose", call_set_palm_pose, NULL);
}

static frusta_result call_set_angles_id(RawId id, int* untouched) {
  const HandSnapshot before = hand_snapshot(g_hand);
  double angles[FRUSTA_HAND_JOINT_COUNT] = {0.1};
  const frusta_result r = frusta_hand_set_joint_angles(hand_of_raw(id), angles, FRUSTA_HAND_JOINT_COUNT);
  *untouched = same_hand(g_hand, &before);
  return r;
}

static double clamp(double v, double lo, double hi) { return v < lo ? lo : v > hi ? hi : v; }

static frusta_result call_set_angles(const void* angles, int* untouched, void* context) {
  (void)context;
  const HandSnapshot before = hand_snapshot(g_hand);
  const double* a = (const double*)angles;
  const frusta_result r = frusta_hand_set_joint_angles(g_hand, a, FRUSTA_HAND_JOINT_COUNT);
  if (r != FRUSTA_OK) {
    *untouched = same_hand(g_hand, &before);
    return r;
  }
  /* used: the angles read back are the input clamped into the default limits */
  const frusta_hand_def def = frusta_default_hand_def();
  double got[FRUSTA_HAND_JOINT_COUNT];
  int32_t count;
  frusta_hand_get_joint_angles(g_hand, got, FRUSTA_HAND_JOINT_COUNT, &count);
  int same = 1;
  for (int j = 0; j < FRUSTA_HAND_JOINT_COUNT; ++j)
    same &= got[j] == clamp(a[j], def.joint_min[j / 4][j % 4], def.joint_max[j / 4][j % 4]);
  verify(same, "the angles read back are not the input clamped");
  hand_finite(g_hand);
  const double zero[FRUSTA_HAND_JOINT_COUNT] = {0};
  frusta_hand_set_joint_angles(g_hand, zero, FRUSTA_HAND_JOINT_COUNT);
  return r;
}

static void t_hand_set_joint_angles(void) {
  sweep_ids("frusta_hand_set_joint_angles", "hand", TO_RAW(g_hand), TO_RAW(g_dead_hand), 1,
            call_set_angles_id);
  const double zero[FRUSTA_HAND_JOINT_COUNT] = {0};
  const HandSnapshot before = hand_snapshot(g_hand);
  what("frusta_hand_set_joint_angles(hand, NULL, 20)");
  refused(frusta_hand_set_joint_angles(g_hand, NULL, FRUSTA_HAND_JOINT_COUNT),
          FRUSTA_ERROR_NULL_POINTER, "angles");
  const int32_t counts[] = {INT32_MIN, -1, 0, FRUSTA_HAND_JOINT_COUNT - 1,
                            FRUSTA_HAND_JOINT_COUNT + 1, INT32_MAX};
  for (int i = 0; i < 6; ++i) {
    what("frusta_hand_set_joint_angles: count %d", counts[i]);
    refused(frusta_hand_set_joint_angles(g_hand, zero, counts[i]), FRUSTA_ERROR_OUT_OF_RANGE, "count");
  }
  verify(same_hand(g_hand, &before), "the hand changed");
  const Field angles = {"angles", 0, FRUSTA_HAND_JOINT_COUNT, 0, NAME_1D, -FRUSTA_MAX_JOINT_ANGLE,
                        FRUSTA_MAX_JOINT_ANGLE, 0};
  sweep_fields("frusta_hand_set_joint_angles", zero, sizeof zero, &angles, 1, call_set_angles, NULL);
}

/* The output-array rule on one call: out_count required, out null only with capacity 0,
 * a negative capacity out of range (nothing written by any of them); then every
 * capacity from 0 past the count writes min(capacity, count) elements of `size` bytes
 * into a buffer of `room`, and counts them all. */
typedef frusta_result (*ArrayCall)(void* out, int32_t capacity, int32_t* out_count);

static void sweep_output_array(const char* label, ArrayCall call, void* out, size_t size,
                               int32_t room, int32_t want_count, const char* out_name) {
  int32_t count;
  fill(out, size * (size_t)room);
  fill(&count, sizeof count);
  what("%s(out, capacity, NULL)", label);
  refused(call(out, room, NULL), FRUSTA_ERROR_NULL_POINTER, "out_count");
  const int32_t given[] = {1, 5, INT32_MAX};
  for (int i = 0; i < 3; ++i) {
    what("%s(NULL, capacity %d, &count)", label, given[i]);
    refused(call(NULL, given[i], &count), FRUSTA_ERROR_NULL_POINTER, out_name);
  }
  const int32_t negative[] = {INT32_MIN, -1};
  for (int i = 0; i < 2; ++i) {
    what("%s: capacity %d", label, negative[i]);
    refused(call(out, negative[i], &count), FRUSTA_ERROR_OUT_OF_RANGE, "capacity");
    what("%s(NULL, capacity %d)", label, negative[i]);
    refused(call(NULL, negative[i], &count), FRUSTA_ERROR_OUT_OF_RANGE, "capacity");
  }
  verify(is_sentinel(out, size * (size_t)room) && is_sentinel(&count, sizeof count),
         "a refused call wrote out or out_count");
  what("%s(NULL, 0, &count): the count alone", label);
  accepted(call(NULL, 0, &count));
  verify(count == want_count, "count %d, want %d", count, want_count);
  const int32_t capacities[] = {0, 1, want_count - 1, want_count, want_count + 1, room};
  for (int i = 0; i < 6; ++i) {
    const int32_t capacity = capacities[i] < 0 ? 0 : capacities[i] > room ? room : capacities[i];
    const int32_t written = capacity < want_count ? capacity : want_count;
    fill(out, size * (size_t)room);
    fill(&count, sizeof count);
    what("%s: capacity %d of %d", label, capacity, want_count);
    accepted(call(out, capacity, &count));
    verify(count == want_count, "count %d, want %d", count, want_count);
    const unsigned char* bytes = (const unsigned char*)out;
    int all_written = 1;
    for (int32_t e = 0; e < written; ++e)
      all_written &= !is_sentinel(bytes + size * (size_t)e, size);
    verify(
        all_written && is_sentinel(bytes + size * (size_t)written, size * (size_t)(room - written)),
        "wrote other than the first %d elements", written);
  }
}

static frusta_result joint_angles_call(void* out, int32_t capacity, int32_t* count) {
  return frusta_hand_get_joint_angles(g_hand, (double*)out, capacity, count);
}
static frusta_result segments_call(void* out, int32_t capacity, int32_t* count) {
  return frusta_hand_get_segments(g_hand, (frusta_segment*)out, capacity, count);
}
static frusta_result palm_spheres_call(void* out, int32_t capacity, int32_t* count) {
  return frusta_hand_get_palm_spheres(g_hand, (frusta_sphere*)out, capacity, count);
}
static frusta_result jacobian_call(void* out, int32_t capacity, int32_t* count) {
  const double local[3] = {0.01, 0.0, 0.0};
  return frusta_hand_point_jacobian(g_hand, 1, 2, local, NULL, (double*)out, capacity, count);
}

static void t_hand_get_joint_angles(void) {
  double out[FRUSTA_HAND_JOINT_COUNT + 4];
  int32_t count;
  BadId bad[MAX_BAD_IDS];
  const int n = bad_ids(TO_RAW(g_hand), TO_RAW(g_dead_hand), 1, bad);
  for (int b = 0; b < n; ++b) {
    fill(out, sizeof out);
    fill(&count, sizeof count);
    what("frusta_hand_get_joint_angles with %s", bad[b].label);
    refused(
        frusta_hand_get_joint_angles(hand_of_raw(bad[b].id), out, FRUSTA_HAND_JOINT_COUNT, &count),
        bad[b].want, "hand");
    verify(is_sentinel(out, sizeof out) && is_sentinel(&count, sizeof count), "out written");
  }
  sweep_output_array("frusta_hand_get_joint_angles", joint_angles_call, out, sizeof out[0],
                     FRUSTA_HAND_JOINT_COUNT + 4, FRUSTA_HAND_JOINT_COUNT, "out");
  what("frusta_hand_get_joint_angles: capacity INT32_MAX (the buffer holds 24)");
  fill(out, sizeof out);
  accepted(frusta_hand_get_joint_angles(g_hand, out, INT32_MAX, &count));
  verify(count == FRUSTA_HAND_JOINT_COUNT && all_finite(out, FRUSTA_HAND_JOINT_COUNT) &&
             is_sentinel(out + FRUSTA_HAND_JOINT_COUNT, 4 * sizeof(double)),
         "wrote beyond 20 angles, or a non-finite one");
}

static void t_hand_get_segments(void) {
  frusta_segment out[FRUSTA_HAND_SEGMENT_COUNT + 2];
  int32_t count;
  BadId bad[MAX_BAD_IDS];
  const int n = bad_ids(TO_RAW(g_hand), TO_RAW(g_dead_hand), 1, bad);
  for (int b = 0; b < n; ++b) {
    fill(out, sizeof out);
    fill(&count, sizeof count);
    what("frusta_hand_get_segments with %s", bad[b].label);
    refused(frusta_hand_get_segments(hand_of_raw(bad[b].id), out, FRUSTA_HAND_SEGMENT_COUNT, &count),
            bad[b].want, "hand");
    verify(is_sentinel(out, sizeof out) && is_sentinel(&count, sizeof count), "out written");
  }
  sweep_output_array("frusta_hand_get_segments", segments_call, out, sizeof out[0],
                     FRUSTA_HAND_SEGMENT_COUNT + 2, FRUSTA_HAND_SEGMENT_COUNT, "out");
  what("frusta_hand_get_segments: capacity INT32_MAX (the buffer holds 17)");
  fill(out, sizeof out);
  accepted(frusta_hand_get_segments(g_hand, out, INT32_MAX, &count));
  verify(count == FRUSTA_HAND_SEGMENT_COUNT && is_sentinel(out + FRUSTA_HAND_SEGMENT_COUNT, 2 * sizeof out[0]),
         "count %d, or wrote beyond", count);
}

static void t_hand_get_palm_spheres(void) {
  static frusta_sphere out[4096];
  int32_t count, total = 0;
  what("frusta_hand_get_palm_spheres size query");
  accepted(frusta_hand_get_palm_spheres(g_hand, NULL, 0, &total));
  verify(total > 0 && total + 2 <= 4096, "%d spheres", total);
  BadId bad[MAX_BAD_IDS];
  const int n = bad_ids(TO_RAW(g_hand), TO_RAW(g_dead_hand), 1, bad);
  for (int b = 0; b < n; ++b) {
    fill(out, sizeof out[0] * 4);
    fill(&count, sizeof count);
    what("frusta_hand_get_palm_spheres with %s", bad[b].label);
    refused(frusta_hand_get_palm_spheres(hand_of_raw(bad[b].id), out, 4096, &count), bad[b].want, "hand");
    verify(is_sentinel(out, sizeof out[0] * 4) && is_sentinel(&count, sizeof count), "out written");
  }
  sweep_output_array("frusta_hand_get_palm_spheres", palm_spheres_call, out, sizeof out[0],
                     total + 2, total, "out");
}

static void t_hand_point_jacobian(void) {
  double point[3 + 1], jacobian[30 + 2];
  int32_t count;
  const double local[3] = {0.01, 0.0, 0.0};
#define JACOBIAN_REFUSED(call, want, field)                                              \
  do {                                                                                   \
    fill(point, sizeof point);                                                           \
    fill(jacobian, sizeof jacobian);                                                     \
    fill(&count, sizeof count);                                                          \
    refused((call), (want), (field));                                                    \
    verify(is_sentinel(point, sizeof point) && is_sentinel(jacobian, sizeof jacobian) && \
               is_sentinel(&count, sizeof count),                                        \
           "out written");                                                               \
  } while (0)
  BadId bad[MAX_BAD_IDS];
  const int n = bad_ids(TO_RAW(g_hand), TO_RAW(g_dead_hand), 1, bad);
  for (int b = 0; b < n; ++b) {
    what("frusta_hand_point_jacobian with %s", bad[b].label);
    JACOBIAN_REFUSED(frusta_hand_point_jacobian(hand_of_raw(bad[b].id), 1, 2, local, point,
                                                jacobian, 30, &count),
                     bad[b].want, "hand");
  }
  const int32_t fingers[] = {INT32_MIN, -1, FRUSTA_FINGER_COUNT, INT32_MAX};
  for (int i = 0; i < 4; ++i) {
    what("frusta_hand_point_jacobian: finger %d", fingers[i]);
    JACOBIAN_REFUSED(
        frusta_hand_point_jacobian(g_hand, fingers[i], 2, local, point, jacobian, 30, &count),
        FRUSTA_ERROR_OUT_OF_RANGE, "finger");
    what("frusta_hand_point_jacobian: segment %d", fingers[i] == FRUSTA_FINGER_COUNT ? 3 : fingers[i]);
    JACOBIAN_REFUSED(
        frusta_hand_point_jacobian(g_hand, 1, fingers[i] == FRUSTA_FINGER_COUNT ? 3 : fingers[i],
                                   local, point, jacobian, 30, &count),
        FRUSTA_ERROR_OUT_OF_RANGE, "segment");
  }
  what("frusta_hand_point_jacobian: local_point NULL");
  JACOBIAN_REFUSED(frusta_hand_point_jacobian(g_hand, 1, 2, NULL, point, jacobian, 30, &count),
                   FRUSTA_ERROR_NULL_POINTER, "local_point");
  what("frusta_hand_point_jacobian: out_jacobian NULL, capacity 30");
  JACOBIAN_REFUSED(frusta_hand_point_jacobian(g_hand, 1, 2, local, point, NULL, 30, &count),
                   FRUSTA_ERROR_NULL_POINTER, "out_jacobian");
  const int32_t capacities[] = {INT32_MIN, -1};
  for (int i = 0; i < 2; ++i) {
    what("frusta_hand_point_jacobian: capacity %d", capacities[i]);
    JACOBIAN_REFUSED(
        frusta_hand_point_jacobian(g_hand, 1, 2, local, point, jacobian, capacities[i], &count),
        FRUSTA_ERROR_OUT_OF_RANGE, "capacity");
  }
  sweep_output_array("frusta_hand_point_jacobian", jacobian_call, jacobian, sizeof jacobian[0], 32,
                     FRUSTA_POINT_JACOBIAN_LENGTH, "out_jacobian");
  for (int k = 0; k < 3; ++k) {
    double values[HOSTILE_COUNT + 4];
    const int nvalues = field_values(-1e6, 1e6, values);
    for (int i = 0; i < nvalues; ++i) {
      double p[3] = {0.01, 0.0, 0.0};
      p[k] = values[i];
      what("frusta_hand_point_jacobian: local_point[%d] = %g", k, values[i]);
      fill(point, sizeof point);
      fill(jacobian, sizeof jacobian);
      fill(&count, sizeof count);
      const frusta_result r =
          frusta_hand_point_jacobian(g_hand, 4, 0, p, point, jacobian, 30, &count);
      const frusta_result want = want_for(values[i], -1e6, 1e6);
      char field[32];
      snprintf(field, sizeof field, "local_point[%d]", k);
      if (want == FRUSTA_OK) {
        accepted(r);
        verify(count == 30 && all_finite(point, 3) && all_finite(jacobian, 30) &&
                   is_sentinel(&point[3], sizeof point[3]) &&
                   is_sentinel(&jacobian[30], 2 * sizeof jacobian[0]),
               "a non-finite point or Jacobian, or writes beyond");
      } else {
        refused(r, want, field);
        verify(is_sentinel(point, sizeof point) && is_sentinel(jacobian, sizeof jacobian) &&
                   is_sentinel(&count, sizeof count),
               "out written");
      }
    }
  }
  what("frusta_hand_point_jacobian: out_point NULL (allowed), capacity INT32_MAX");
  fill(jacobian, sizeof jacobian);
  accepted(frusta_hand_point_jacobian(g_hand, 0, 0, local, NULL, jacobian, INT32_MAX, &count));
  verify(all_finite(jacobian, 30) && is_sentinel(&jacobian[30], 2 * sizeof jacobian[0]), "bad Jacobian");
#undef JACOBIAN_REFUSED
}

/* ------------------------------------------------------------------ geometry */

typedef struct QueryInput {
  frusta_segment segment;
  frusta_sphere sphere;
} QueryInput;

#define QUERY_FIELD(member) offsetof(QueryInput, member)
static const Field kQueryFields[] = {
    {"segment.proximal", QUERY_FIELD(segment.proximal), 3, 0, NAME_1D, -1e6, 1e6, 0},
    {"segment.distal", QUERY_FIELD(segment.distal), 3, 0, NAME_1D, -1e6, 1e6, 0},
    {"segment.proximal_radius", QUERY_FIELD(segment.proximal_radius), 1, 0, NAME_SCALAR, 0.0, 1e6, 0},
    {"segment.distal_radius", QUERY_FIELD(segment.distal_radius), 1, 0, NAME_SCALAR, 0.0, 1e6, 0},
    {"sphere.center", QUERY_FIELD(sphere.center), 3, 0, NAME_1D, -1e6, 1e6, 0},
    {"sphere.radius", QUERY_FIELD(sphere.radius), 1, 0, NAME_SCALAR, 0.0, 1e6, 0},
};

static const QueryInput kQuery = {{{0.0, 0.0, 0.0}, {0.04, 0.0, 0.0}, 0.009, 0.008},
                                  {{0.02, 0.015, 0.0}, 0.01}};

/* Degenerate and extreme inputs within the documented ranges: every output finite. */
static const QueryInput kExtremeQueries[] = {
    {{{0, 0, 0}, {0, 0, 0}, 0.01, 0.005}, {{0.02, 0, 0}, 0.01}},        /* zero length */
    {{{0, 0, 0}, {0, 0, 0}, 0.0, 0.0}, {{0, 0, 0}, 0.0}},               /* all at one point */
    {{{0, 0, 0}, {0.04, 0, 0}, 0.0, 0.0}, {{0.02, 0, 0}, 0.0}},         /* a line through a point */
    {{{0, 0, 0}, {0.04, 0, 0}, 0.01, 0.01}, {{0, 0, 0}, 0.0}},          /* centre at D */
    {{{0, 0, 0}, {0.04, 0, 0}, 0.01, 0.01}, {{0.04, 0, 0}, 0.0}},       /* centre at E */
    {{{0, 0, 0}, {0.04, 0, 0}, 0.01, 0.01}, {{0.02, 0, 0}, 0.0}},       /* on the axis */
    {{{0, 0, 0}, {0.04, 0, 0}, 1e6, 0.0}, {{0.02, 1e-300, 0}, 1e6}},    /* huge radii */
    {{{-1e6, -1e6, -1e6}, {1e6, 1e6, 1e6}, 1e6, 1e6}, {{1e6, -1e6, 1e6}, 1e6}},
    {{{0, 0, 0}, {1e-300, 0, 0}, 0.01, 0.01}, {{0.02, 0.0, 0.0}, 0.01}}, /* denormal length */
    {{{0, 0, 0}, {DBL_TRUE_MIN, DBL_TRUE_MIN, 0}, 0.0, 1e-300}, {{DBL_MIN, 0, 0}, DBL_TRUE_MIN}},
    {{{1e6, 1e6, 1e6}, {1e6, 1e6, 1e6 - 1e-9}, 1e-9, 0.0}, {{1e6, 1e6, 1e6}, 1e-9}},
    {{{0, 0, 0}, {0.04, 0, 0}, 0.01, 1e6}, {{0.02, 0.0, 0.0}, 0.005}},   /* E's ball swallows all */
};

static int contact_finite(const frusta_contact_query* q) {
  return q->feature >= 0 && q->feature <= 2 && (q->contact | q->patent_contact) <= 1 &&
         isfinite(q->distance) && all_finite(q->hand_point, 3) && all_finite(q->object_point, 3) &&
         all_finite(q->normal, 3) && fabs(norm_n(q->normal, 3) - 1.0) <= 1e-6 && isfinite(q->axial);
}

static frusta_result call_query_contact(const void* input, int* untouched, void* context) {
  (void)context;
  const QueryInput* in = (const QueryInput*)input;
  frusta_contact_query out;
  fill(&out, sizeof out);
  out.struct_size = (int32_t)sizeof out;
  const frusta_result r = frusta_query_contact(&in->segment, &in->sphere, &out);
  if (r != FRUSTA_OK) {
    *untouched = is_sentinel((const char*)&out + 4, sizeof out - 4);
    return r;
  }
  verify(contact_finite(&out), "feature %d distance %g axial %g normal (%g, %g, %g)", out.feature,
         out.distance, out.axial, out.normal[0], out.normal[1], out.normal[2]);
  return r;
}

static frusta_result query_contact_out(void* out) {
  return frusta_query_contact(&kQuery.segment, &kQuery.sphere, (frusta_contact_query*)out);
}

static void t_query_contact(void) {
  frusta_contact_query out;
  fill(&out, sizeof out);
  out.struct_size = (int32_t)sizeof out;
  what("frusta_query_contact(NULL, ...)");
  refused(frusta_query_contact(NULL, &kQuery.sphere, &out), FRUSTA_ERROR_NULL_POINTER, "segment");
  what("frusta_query_contact(.., NULL, ..)");
  refused(frusta_query_contact(&kQuery.segment, NULL, &out), FRUSTA_ERROR_NULL_POINTER, "sphere");
  what("frusta_query_contact(.., .., NULL)");
  refused(frusta_query_contact(&kQuery.segment, &kQuery.sphere, NULL), FRUSTA_ERROR_NULL_POINTER, "out");
  verify(is_sentinel((char*)&out + 4, sizeof out - 4), "out written");
  sweep_out_size("frusta_query_contact", "frusta_contact_query", sizeof out, query_contact_out);
  sweep_fields("frusta_query_contact", &kQuery, sizeof kQuery, kQueryFields, 6, call_query_contact, NULL);
  for (size_t i = 0; i < sizeof kExtremeQueries / sizeof kExtremeQueries[0]; ++i) {
    what("frusta_query_contact: extreme input %zu", i);
    int untouched = 1;
    accepted(call_query_contact(&kExtremeQueries[i], &untouched, NULL));
  }
}

static int32_t g_form;
static frusta_result call_constraint(const void* input, int* untouched, void* context) {
  (void)context;
  const QueryInput* in = (const QueryInput*)input;
  frusta_constraint out;
  fill(&out, sizeof out);
  out.struct_size = (int32_t)sizeof out;
  const frusta_result r = frusta_constraint_eval(&in->segment, &in->sphere, g_form, &out);
  if (r != FRUSTA_OK) {
    *untouched = is_sentinel((const char*)&out + 4, sizeof out - 4);
    return r;
  }
  verify(out.feature >= 0 && out.feature <= 2 && isfinite(out.value) && all_finite(out.grad_proximal, 3) &&
             all_finite(out.grad_distal, 3) && all_finite(out.grad_center, 3),
         "feature %d value %g gradient (%g, %g, %g)", out.feature, out.value, out.grad_center[0],
         out.grad_center[1], out.grad_center[2]);
  return r;
}

static frusta_result constraint_out(void* out) {
  return frusta_constraint_eval(&kQuery.segment, &kQuery.sphere, FRUSTA_CONSTRAINT_DISTANCE,
                                (frusta_constraint*)out);
}

static void t_constraint_eval(void) {
  frusta_constraint out;
  fill(&out, sizeof out);
  out.struct_size = (int32_t)sizeof out;
  what("frusta_constraint_eval(NULL, ...)");
  refused(frusta_constraint_eval(NULL, &kQuery.sphere, 0, &out), FRUSTA_ERROR_NULL_POINTER, "segment");
  what("frusta_constraint_eval(.., NULL, ..)");
  refused(frusta_constraint_eval(&kQuery.segment, NULL, 0, &out), FRUSTA_ERROR_NULL_POINTER, "sphere");
  what("frusta_constraint_eval(.., .., .., NULL)");
  refused(frusta_constraint_eval(&kQuery.segment, &kQuery.sphere, 0, NULL), FRUSTA_ERROR_NULL_POINTER, "out");
  const int32_t forms[] = {INT32_MIN, -1, 2, INT32_MAX};
  for (int i = 0; i < 4; ++i) {
    what("frusta_constraint_eval: form %d", forms[i]);
    refused(frusta_constraint_eval(&kQuery.segment, &kQuery.sphere, forms[i], &out),
            FRUSTA_ERROR_OUT_OF_RANGE, "form");
  }
  verify(is_sentinel((char*)&out + 4, sizeof out - 4), "out written");
  sweep_out_size("frusta_constraint_eval", "frusta_constraint", sizeof out, constraint_out);
  for (g_form = 0; g_form <= 1; ++g_form) {
    sweep_fields(g_form ? "frusta_constraint_eval (distance)" : "frusta_constraint_eval (squared)",
                 &kQuery, sizeof kQuery, kQueryFields, 6, call_constraint, NULL);
    for (size_t i = 0; i < sizeof kExtremeQueries / sizeof kExtremeQueries[0]; ++i) {
      what("frusta_constraint_eval: form %d, extreme input %zu", g_form, i);
      int untouched = 1;
      accepted(call_constraint(&kExtremeQueries[i], &untouched, NULL));
    }
  }
}

/* ------------------------------------------------------------------ trees */

/* A 2 cm cube: 8 corners, 12 triangles counter-clockwise seen from outside. */
static const float kCube[24] = {-0.01f, -0.01f, -0.01f, 0.01f, -0.01f, -0.01f, 0.01f, 0.01f, -0.01f,
                                -0.01f, 0.01f,  -0.01f, -0.01f, -0.01f, 0.01f, 0.01f, -0.01f, 0.01f,
                                0.01f,  0.01f,  0.01f,  -0.01f, 0.01f,  0.01f};
static const int32_t kCubeTriangles[36] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                           1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};

/* A tree's info and leaves are finite and consistent. */
static int tree_finite(frusta_tree_id tree) {
  frusta_sphere_tree_info info;
  memset(&info, 0, sizeof info);
  info.struct_size = (int32_t)sizeof info;
  if (!verify(frusta_sphere_tree_get_info(tree, &info) == FRUSTA_OK, "get_info: %s", frusta_last_error()))
    return 0;
  if (!verify(info.leaf_count > 0 && info.node_count > 0 && info.depth >= 0 && info.branching >= 2 &&
                  all_finite(info.bounds_min, 3) && all_finite(info.bounds_max, 3) &&
                  isfinite(info.target_error) && isfinite(info.uncovered_error) &&
                  isfinite(info.protruding_error) && isfinite(info.bake_seconds) &&
                  (info.target_met == 0 || info.target_met == 1),
              "info: %d leaves, %d nodes, depth %d, errors %g %g", info.leaf_count, info.node_count,
              info.depth, info.uncovered_error, info.protruding_error))
    return 0;
  int32_t count = -1;
  if (!verify(frusta_sphere_tree_get_leaves(tree, NULL, 0, &count) == FRUSTA_OK && count == info.leaf_count,
              "leaf count %d, info says %d", count, info.leaf_count))
    return 0;
  frusta_sphere* leaves = (frusta_sphere*)malloc(sizeof *leaves * (size_t)count);
  if (!leaves) return verify(0, "out of memory");
  int ok = verify(frusta_sphere_tree_get_leaves(tree, leaves, count, &count) == FRUSTA_OK, "get_leaves: %s",
                  frusta_last_error());
  for (int32_t i = 0; ok && i < count; ++i)
    ok = verify(all_finite(leaves[i].center, 3) && isfinite(leaves[i].radius) && leaves[i].radius >= 0.0,
                "leaf %d", i);
  free(leaves);
  return ok;
}

static void bake_result(frusta_result got, frusta_result want, const char* field) {
  if (want == FRUSTA_OK)
    accepted(got);
  else
    refused(got, want, field);
}

typedef struct BakeInput {
  const float* vertices;
  int32_t vertex_count;
  const int32_t* indices;
  int32_t index_count;
} BakeInput;

/* A bake that is quick whatever the target: few leaves and samples. */
static frusta_bake_def quick_bake_def(void) {
  frusta_bake_def def = frusta_default_bake_def();
  def.max_leaves = 64;
  def.error_samples = 1000;
  def.target_error = 0.002;
  return def;
}

static frusta_result bake(const BakeInput* in, const frusta_bake_def* def, int* untouched) {
  frusta_tree_id tree;
  fill(&tree, sizeof tree);
  const clock_t start = clock();
  const frusta_result r = frusta_create_sphere_tree_from_mesh(
      in->vertices, in->vertex_count, in->indices, in->index_count, def, &tree);
  if (getenv("HOSTILE_ABI_TIMES") && clock() - start > CLOCKS_PER_SEC / 20)
    printf("     bake %.2f s: %s\n", (double)(clock() - start) / CLOCKS_PER_SEC, g_what);
  if (r != FRUSTA_OK) {
    *untouched = is_sentinel(&tree, sizeof tree);
    return r;
  }
  tree_finite(tree);
  frusta_destroy_sphere_tree(tree);
  return r;
}

static const BakeInput kCubeInput = {kCube, 8, kCubeTriangles, 36};

static frusta_result call_bake_def(const void* def, int* untouched, void* context) {
  (void)context;
  return bake(&kCubeInput, (const frusta_bake_def*)def, untouched);
}

static void t_default_bake_def(void) {
  const frusta_bake_def a = frusta_default_bake_def(), b = frusta_default_bake_def();
  what("frusta_default_bake_def()");
  ++g_calls;
  verify(memcmp(&a, &b, sizeof a) == 0 && a.struct_size == (int32_t)sizeof a && a.internal_value != 0 &&
             isfinite(a.target_error),
         "not a deterministic def of this size with its cookie");
  int untouched = 1;
  what("frusta_create_sphere_tree_from_mesh with the default def");
  bake_result(bake(&kCubeInput, &a, &untouched), FRUSTA_OK, "");
}

static void t_bake_sphere_tree(void) {
  const frusta_bake_def def = quick_bake_def();
  frusta_tree_id tree;
  fill(&tree, sizeof tree);
  int untouched = 1;
  what("frusta_create_sphere_tree_from_mesh: vertices NULL");
  bake_result(frusta_create_sphere_tree_from_mesh(NULL, 8, kCubeTriangles, 36, &def, &tree),
              FRUSTA_ERROR_NULL_POINTER, "vertices");
  what("frusta_create_sphere_tree_from_mesh: indices NULL");
  bake_result(frusta_create_sphere_tree_from_mesh(kCube, 8, NULL, 36, &def, &tree),
              FRUSTA_ERROR_NULL_POINTER, "indices");
  what("frusta_create_sphere_tree_from_mesh: def NULL");
  bake_result(frusta_create_sphere_tree_from_mesh(kCube, 8, kCubeTriangles, 36, NULL, &tree),
              FRUSTA_ERROR_NULL_POINTER, "def");
  what("frusta_create_sphere_tree_from_mesh: out_tree NULL");
  bake_result(frusta_create_sphere_tree_from_mesh(kCube, 8, kCubeTriangles, 36, &def, NULL),
              FRUSTA_ERROR_NULL_POINTER, "out_tree");
  verify(is_sentinel(&tree, sizeof tree), "out_tree written");
  sweep_def_header("frusta_create_sphere_tree_from_mesh", "frusta_bake_def", &def, sizeof def,
                   offsetof(frusta_bake_def, internal_value), call_bake_def, NULL);
  /* target_error: 1e-5..1 m; the accepted ones bake quickly (64 leaves, 1000 samples) */
  double values[HOSTILE_COUNT + 4];
  const int n = field_values(1e-5, 1.0, values);
  /* at 10 um the cover samples the surface that finely whatever the leaf budget (3.7 s
   * for the 2 cm cube here, a minute under ASan): the smallest target bakes a 0.2 mm cube */
  float tiny[24];
  for (int k = 0; k < 24; ++k) tiny[k] = kCube[k] * 0.01f;
  const BakeInput tiny_cube = {tiny, 8, kCubeTriangles, 36};
  for (int i = 0; i < n; ++i) {
    frusta_bake_def d = def;
    d.target_error = values[i];
    what("frusta_create_sphere_tree_from_mesh: target_error = %g", values[i]);
    bake_result(bake(values[i] < 1e-4 ? &tiny_cube : &kCubeInput, &d, &untouched),
                want_for(values[i], 1e-5, 1.0), "target_error");
  }
  const struct {
    const char* field;
    int64_t value;
    int ok;  /* 1: accepted, 0: refused, 2: either */
  } ints[] = {{"branching", INT32_MIN, 0}, {"branching", -1, 0}, {"branching", 0, 0}, {"branching", 1, 0},
              {"branching", 2, 1},         {"branching", 16, 1}, {"branching", 17, 0},
              {"branching", INT32_MAX, 0}, {"max_depth", INT32_MIN, 0}, {"max_depth", -1, 0},
              {"max_depth", 0, 0},         {"max_depth", 1, 2},  {"max_depth", 40, 1},
              {"max_depth", 41, 0},        {"max_depth", INT32_MAX, 0}, {"max_leaves", INT64_MIN, 0},
              {"max_leaves", -1, 0},       {"max_leaves", 0, 0}, {"max_leaves", 1, 1},
              {"max_leaves", (1 << 24) + 1, 0}, {"max_leaves", INT64_MAX, 0},
              {"error_samples", INT64_MIN, 0}, {"error_samples", -1, 0}, {"error_samples", 0, 0},
              {"error_samples", 999, 0},   {"error_samples", 1000, 1}, {"error_samples", 10000001, 0},
              {"error_samples", INT64_MAX, 0}};
  for (size_t i = 0; i < sizeof ints / sizeof ints[0]; ++i) {
    frusta_bake_def d = def;
    if (strcmp(ints[i].field, "branching") == 0) d.branching = (int32_t)ints[i].value;
    if (strcmp(ints[i].field, "max_depth") == 0) d.max_depth = (int32_t)ints[i].value;
    if (strcmp(ints[i].field, "max_leaves") == 0) d.max_leaves = ints[i].value;
    if (strcmp(ints[i].field, "error_samples") == 0) d.error_samples = ints[i].value;
    what("frusta_create_sphere_tree_from_mesh: %s = %lld", ints[i].field, (long long)ints[i].value);
    untouched = 1;
    /* ok 2: the def is valid, but the tree it asks for may be refused ("a deeper tree is
     * refused": 64 leaves need depth 3 at branching 4) */
    const frusta_result r = bake(&kCubeInput, &d, &untouched);
    bake_result(r, ints[i].ok == 1 || (ints[i].ok == 2 && r == FRUSTA_OK) ? FRUSTA_OK : FRUSTA_ERROR_OUT_OF_RANGE,
                ints[i].field);
    verify(untouched, "out_tree written by a refused call");
  }
  const uint64_t seeds[] = {0, UINT64_MAX};
  for (int i = 0; i < 2; ++i) {
    frusta_bake_def d = def;
    d.seed = seeds[i];
    what("frusta_create_sphere_tree_from_mesh: seed %llu", (unsigned long long)seeds[i]);
    bake_result(bake(&kCubeInput, &d, &untouched), FRUSTA_OK, "");
  }
  /* counts and indices */
  const struct {
    BakeInput in;
    const char* field;
  } meshes[] = {
      {{kCube, INT32_MIN, kCubeTriangles, 36}, "vertex_count"},
      {{kCube, -1, kCubeTriangles, 36}, "vertex_count"},
      {{kCube, 0, kCubeTriangles, 36}, "vertex_count"},
      {{kCube, 8, kCubeTriangles, INT32_MIN}, "index_count"},
      {{kCube, 8, kCubeTriangles, -1}, "index_count"},
      {{kCube, 8, kCubeTriangles, 0}, "index_count"},
      {{kCube, 8, kCubeTriangles, 35}, "index_count"},
      {{kCube, 7, kCubeTriangles, 36}, "ind"},  /* index 7 is now out of range */
  };
  for (size_t i = 0; i < sizeof meshes / sizeof meshes[0]; ++i) {
    what("frusta_create_sphere_tree_from_mesh: vertex_count %d, index_count %d",
         meshes[i].in.vertex_count, meshes[i].in.index_count);
    untouched = 1;
    bake_result(bake(&meshes[i].in, &def, &untouched), FRUSTA_ERROR_OUT_OF_RANGE, meshes[i].field);
    verify(untouched, "out_tree written by a refused call");
  }
  const int32_t bad_indices[] = {INT32_MIN, -1, 8, INT32_MAX};
  for (int i = 0; i < 4; ++i) {
    int32_t indices[36];
    memcpy(indices, kCubeTriangles, sizeof indices);
    indices[17] = bad_indices[i];
    const BakeInput in = {kCube, 8, indices, 36};
    what("frusta_create_sphere_tree_from_mesh: index %d", bad_indices[i]);
    untouched = 1;
    bake_result(bake(&in, &def, &untouched), FRUSTA_ERROR_OUT_OF_RANGE, "ind");
    verify(untouched, "out_tree written by a refused call");
  }
  /* vertex values: not finite is refused; finite ones bake or are refused by name */
  const float floats[] = {NAN, INFINITY, -INFINITY, FLT_MAX, -FLT_MAX, 1e30f, FLT_TRUE_MIN, -0.0f};
  for (int i = 0; i < 8; ++i) {
    float vertices[24];
    memcpy(vertices, kCube, sizeof vertices);
    vertices[13] = floats[i];
    const BakeInput in = {vertices, 8, kCubeTriangles, 36};
    what("frusta_create_sphere_tree_from_mesh: vertices[13] = %g", floats[i]);
    untouched = 1;
    const frusta_result r = bake(&in, &def, &untouched);
    if (!isfinite(floats[i])) bake_result(r, FRUSTA_ERROR_NOT_FINITE, "vert");
    else if (r != FRUSTA_OK) bake_result(r, FRUSTA_ERROR_OUT_OF_RANGE, "vert");
    else bake_result(r, FRUSTA_OK, "");
  }
  /* degenerate meshes: every vertex at one point, or on one line */
  float point[24] = {0}, line[24] = {0};
  for (int v = 0; v < 8; ++v) line[3 * v] = 0.001f * (float)v;
  const BakeInput degenerate[] = {{point, 8, kCubeTriangles, 36}, {line, 8, kCubeTriangles, 36}};
  for (int i = 0; i < 2; ++i) {
    what("frusta_create_sphere_tree_from_mesh: every vertex on a %s", i ? "line" : "point");
    untouched = 1;
    const frusta_result r = bake(&degenerate[i], &def, &untouched);
    if (r != FRUSTA_OK) bake_result(r, FRUSTA_ERROR_OUT_OF_RANGE, "");
    else bake_result(r, FRUSTA_OK, "");
  }
}

static frusta_tree_id g_saved_tree;
static const char kSavedPath[] = "hostile_abi_test.frtree";

/* bytes of a file, malloc'd; NULL if unreadable */
static unsigned char* read_file(const char* path, long* size) {
  FILE* f = fopen(path, "rb");
  if (!f) return NULL;
  fseek(f, 0, SEEK_END);
  *size = ftell(f);
  fseek(f, 0, SEEK_SET);
  unsigned char* bytes = (unsigned char*)malloc((size_t)*size + 1);
  if (bytes && fread(bytes, 1, (size_t)*size, f) != (size_t)*size) {
    free(bytes);
    bytes = NULL;
  }
  fclose(f);
  return bytes;
}

static int write_file(const char* path, const unsigned char* bytes, long size) {
  FILE* f = fopen(path, "wb");
  if (!f) return 0;
  const int ok = fwrite(bytes, 1, (size_t)size, f) == (size_t)size;
  return fclose(f) == 0 && ok;
}

/* ------------------------------------------------------------------ bake jobs */

static frusta_bake_job_id job_of_raw(RawId r) { return (frusta_bake_job_id){r.index1, r.world0, r.generation}; }

static frusta_bake_job_id g_dead_job; /* started, then finished */

/* A quick job on the cube, finished: 1 when its tree was finite. */
static int run_quick_job(const frusta_bake_def* def) {
  frusta_bake_job_id job;
  if (!accepted(frusta_start_bake(kCube, 8, kCubeTriangles, 36, def, &job))) return 0;
  frusta_tree_id tree;
  if (!accepted(frusta_finish_bake_job(job, &tree))) return 0;
  const int ok = tree_finite(tree);
  frusta_destroy_sphere_tree(tree);
  g_dead_job = job;
  return ok;
}

static frusta_result call_start_def(const void* def, int* untouched, void* context) {
  (void)context;
  frusta_bake_job_id job;
  fill(&job, sizeof job);
  const frusta_result r = frusta_start_bake(kCube, 8, kCubeTriangles, 36, (const frusta_bake_def*)def, &job);
  if (r != FRUSTA_OK) {
    *untouched = is_sentinel(&job, sizeof job);
    return r;
  }
  frusta_tree_id tree;
  const frusta_result finished = frusta_finish_bake_job(job, &tree);
  if (finished == FRUSTA_OK) frusta_destroy_sphere_tree(tree);
  return finished;
}

static void t_start_bake(void) {
  const frusta_bake_def def = quick_bake_def();
  frusta_bake_job_id job;
  fill(&job, sizeof job);
  what("frusta_start_bake: vertices NULL");
  refused(frusta_start_bake(NULL, 8, kCubeTriangles, 36, &def, &job), FRUSTA_ERROR_NULL_POINTER, "vertices");
  what("frusta_start_bake: indices NULL");
  refused(frusta_start_bake(kCube, 8, NULL, 36, &def, &job), FRUSTA_ERROR_NULL_POINTER, "indices");
  what("frusta_start_bake: def NULL");
  refused(frusta_start_bake(kCube, 8, kCubeTriangles, 36, NULL, &job), FRUSTA_ERROR_NULL_POINTER, "def");
  what("frusta_start_bake: out_job NULL");
  refused(frusta_start_bake(kCube, 8, kCubeTriangles, 36, &def, NULL), FRUSTA_ERROR_NULL_POINTER, "out_job");
  const int32_t counts[] = {INT32_MIN, -1};
  for (int i = 0; i < 2; ++i) {
    what("frusta_start_bake: vertex_count %d", counts[i]);
    refused(frusta_start_bake(kCube, counts[i], kCubeTriangles, 36, &def, &job), FRUSTA_ERROR_OUT_OF_RANGE,
            "vertex_count");
    what("frusta_start_bake: index_count %d", counts[i]);
    refused(frusta_start_bake(kCube, 8, kCubeTriangles, counts[i], &def, &job), FRUSTA_ERROR_OUT_OF_RANGE,
            "index_count");
  }
  verify(is_sentinel(&job, sizeof job), "out_job written by a refused call");
  sweep_def_header("frusta_start_bake", "frusta_bake_def", &def, sizeof def,
                   offsetof(frusta_bake_def, internal_value), call_start_def, NULL);
  /* a mesh the bake refuses: the job starts, and finishing it says why */
  const int32_t bad[] = {0, 1, 9};
  what("frusta_start_bake: index 9 of 8 vertices, refused at the finish");
  if (accepted(frusta_start_bake(kCube, 8, bad, 3, &def, &job))) {
    frusta_tree_id tree;
    fill(&tree, sizeof tree);
    refused(frusta_finish_bake_job(job, &tree), FRUSTA_ERROR_OUT_OF_RANGE, "indices[2]");
    verify(is_sentinel(&tree, sizeof tree), "out_tree written by a failed job");
  }
  what("frusta_start_bake: the cube, finished");
  verify(run_quick_job(&def), "the job's tree");
}

static frusta_result call_progress_id(RawId id, int* untouched) {
  double fraction;
  int32_t done;
  fill(&fraction, sizeof fraction);
  fill(&done, sizeof done);
  const frusta_result r = frusta_bake_job_progress(job_of_raw(id), &fraction, &done);
  *untouched = is_sentinel(&fraction, sizeof fraction) && is_sentinel(&done, sizeof done);
  return r;
}

static frusta_result call_cancel_id(RawId id, int* untouched) {
  *untouched = 1;
  return frusta_cancel_bake_job(job_of_raw(id));
}

static frusta_result call_finish_id(RawId id, int* untouched) {
  frusta_tree_id tree;
  fill(&tree, sizeof tree);
  const frusta_result r = frusta_finish_bake_job(job_of_raw(id), &tree);
  *untouched = is_sentinel(&tree, sizeof tree);
  return r;
}

/* A live job for the id sweeps: a bake of the cube, which the sweeps never touch. */
static frusta_bake_job_id live_job(void) {
  const frusta_bake_def def = quick_bake_def();
  frusta_bake_job_id job = {0, 0, 0};
  accepted(frusta_start_bake(kCube, 8, kCubeTriangles, 36, &def, &job));
  return job;
}

static void end_job(frusta_bake_job_id job) {
  frusta_tree_id tree;
  if (frusta_finish_bake_job(job, &tree) == FRUSTA_OK) frusta_destroy_sphere_tree(tree);
}

static void t_bake_job_progress(void) {
  if (g_dead_job.index1 == 0) {
    const frusta_bake_def def = quick_bake_def();
    run_quick_job(&def);
  }
  const frusta_bake_job_id job = live_job();
  sweep_ids("frusta_bake_job_progress", "bake job", TO_RAW(job), TO_RAW(g_dead_job), 1, call_progress_id);
  double fraction;
  int32_t done;
  what("frusta_bake_job_progress(job, NULL, &done)");
  refused(frusta_bake_job_progress(job, NULL, &done), FRUSTA_ERROR_NULL_POINTER, "out_fraction");
  what("frusta_bake_job_progress(job, &fraction, NULL)");
  refused(frusta_bake_job_progress(job, &fraction, NULL), FRUSTA_ERROR_NULL_POINTER, "out_done");
  what("frusta_bake_job_progress(job)");
  if (accepted(frusta_bake_job_progress(job, &fraction, &done)))
    verify(fraction >= 0.0 && fraction <= 1.0 && (done == 0 || done == 1), "%g, done %d", fraction, done);
  end_job(job);
}

static void t_cancel_bake_job(void) {
  const frusta_bake_job_id job = live_job();
  sweep_ids("frusta_cancel_bake_job", "bake job", TO_RAW(job), TO_RAW(g_dead_job), 1, call_cancel_id);
  what("frusta_cancel_bake_job(job), then its finish");
  accepted(frusta_cancel_bake_job(job));
  accepted(frusta_cancel_bake_job(job)); /* twice is once */
  frusta_tree_id tree;
  fill(&tree, sizeof tree);
  refused(frusta_finish_bake_job(job, &tree), FRUSTA_ERROR_CANCELLED, "cancelled");
  verify(is_sentinel(&tree, sizeof tree), "out_tree written by a cancelled job");
}

static void t_finish_bake_job(void) {
  const frusta_bake_job_id job = live_job();
  sweep_ids("frusta_finish_bake_job", "bake job", TO_RAW(job), TO_RAW(g_dead_job), 1, call_finish_id);
  what("frusta_finish_bake_job(job, NULL)");
  refused(frusta_finish_bake_job(job, NULL), FRUSTA_ERROR_NULL_POINTER, "out_tree");
  what("frusta_finish_bake_job(job) twice");
  frusta_tree_id tree;
  if (accepted(frusta_finish_bake_job(job, &tree))) frusta_destroy_sphere_tree(tree);
  refused(frusta_finish_bake_job(job, &tree), FRUSTA_ERROR_STALE_ID, "bake job");
}

/* ------------------------------------------------------------------ trees in memory */

static frusta_result call_memory(const unsigned char* bytes, int64_t size) {
  frusta_tree_id tree;
  fill(&tree, sizeof tree);
  const frusta_result r = frusta_create_sphere_tree_from_memory(bytes, size, &tree);
  if (r == FRUSTA_OK) {
    tree_finite(tree);
    frusta_destroy_sphere_tree(tree);
  } else {
    verify(is_sentinel(&tree, sizeof tree), "out_tree written by a refused call");
  }
  return r;
}

static void t_create_sphere_tree_from_memory(void) {
  char path[1024];
  object_path("press_box", path, sizeof path);
  long size = 0;
  unsigned char* bytes = read_file(path, &size);
  if (!verify(bytes != NULL, "cannot read %s", path)) return;
  frusta_tree_id tree;
  what("frusta_create_sphere_tree_from_memory(NULL, size, &tree)");
  refused(frusta_create_sphere_tree_from_memory(NULL, size, &tree), FRUSTA_ERROR_NULL_POINTER, "data");
  what("frusta_create_sphere_tree_from_memory(bytes, size, NULL)");
  refused(frusta_create_sphere_tree_from_memory(bytes, size, NULL), FRUSTA_ERROR_NULL_POINTER, "out_tree");
  const int64_t sizes[] = {INT64_MIN, -1, (int64_t)1 << 40, INT64_MAX};
  for (int i = 0; i < 4; ++i) {
    what("frusta_create_sphere_tree_from_memory: size %lld", (long long)sizes[i]);
    refused(call_memory(bytes, sizes[i]), FRUSTA_ERROR_OUT_OF_RANGE, "size");
  }
  what("frusta_create_sphere_tree_from_memory: the whole file");
  accepted(call_memory(bytes, size));
  /* every shorter piece is refused by the format's checks, naming the input */
  const long cuts[] = {0, 1, 8, 159, 160, 161, size / 2, size - 1};
  for (int i = 0; i < 8; ++i) {
    if (cuts[i] >= size) continue;
    what("frusta_create_sphere_tree_from_memory: the first %ld of %ld bytes", cuts[i], size);
    const frusta_result r = call_memory(bytes, cuts[i]);
    refused(r, r == FRUSTA_ERROR_FILE_FORMAT ? FRUSTA_ERROR_FILE_FORMAT : FRUSTA_ERROR_CORRUPT_FILE, "data");
  }
  /* a flipped byte in the payload: the checksum */
  bytes[size - 3] ^= 0x5a;
  what("frusta_create_sphere_tree_from_memory: a flipped byte");
  refused(call_memory(bytes, size), FRUSTA_ERROR_CORRUPT_FILE, "data");
  free(bytes);
}

static void load_refused(const char* label, const char* path, frusta_result want1, frusta_result want2,
                         const char* field) {
  frusta_tree_id tree;
  fill(&tree, sizeof tree);
  what("frusta_create_sphere_tree_from_file(%s)", label);
  const frusta_result r = frusta_create_sphere_tree_from_file(path, &tree);
  refused(r, r == want2 ? want2 : want1, field);
  verify(is_sentinel(&tree, sizeof tree), "out_tree written");
}

static void t_load_sphere_tree(void) {
  frusta_tree_id tree;
  fill(&tree, sizeof tree);
  char path[1024];
  object_path("press_box", path, sizeof path);
  what("frusta_create_sphere_tree_from_file(NULL, &tree)");
  refused(frusta_create_sphere_tree_from_file(NULL, &tree), FRUSTA_ERROR_NULL_POINTER, "path");
  what("frusta_create_sphere_tree_from_file(path, NULL)");
  refused(frusta_create_sphere_tree_from_file(path, NULL), FRUSTA_ERROR_NULL_POINTER, "out_tree");
  verify(is_sentinel(&tree, sizeof tree), "out_tree written");
  load_refused("\"\"", "", FRUSTA_ERROR_IO, FRUSTA_ERROR_IO, "");
  load_refused("a missing file", "no/such/dir/x.frtree", FRUSTA_ERROR_IO, FRUSTA_ERROR_IO, "no/such/dir");
  load_refused("a directory", ".", FRUSTA_ERROR_IO, FRUSTA_ERROR_FILE_FORMAT, "");
  load_refused("control characters", "\x01\x02\n\t\x7f", FRUSTA_ERROR_IO, FRUSTA_ERROR_IO, "");
  static char long_path[10240];
  memset(long_path, 'y', sizeof long_path - 1);
  load_refused("a 10 KB path", long_path, FRUSTA_ERROR_IO, FRUSTA_ERROR_IO, "yyyy");
#if defined(__unix__)
  load_refused("/dev/null", "/dev/null", FRUSTA_ERROR_IO, FRUSTA_ERROR_FILE_FORMAT, "/dev/null");
  load_refused("/dev/zero", "/dev/zero", FRUSTA_ERROR_IO, FRUSTA_ERROR_FILE_FORMAT, "/dev/zero");
  /* a FIFO nobody writes: opening it for reading would block forever */
  unlink("hostile_abi_test.fifo");
  if (verify(mkfifo("hostile_abi_test.fifo", 0600) == 0, "mkfifo"))
    load_refused("a FIFO", "hostile_abi_test.fifo", FRUSTA_ERROR_IO, FRUSTA_ERROR_FILE_FORMAT,
                 "hostile_abi_test.fifo");
  unlink("hostile_abi_test.fifo");
#endif
  /* damaged copies of a good file */
  long size = 0;
  unsigned char* bytes = read_file(path, &size);
  if (!verify(bytes != NULL && size > 200, "read %s", path)) return;
  const long cuts[] = {0, 1, 159, 160, size / 2, size - 1};
  for (int i = 0; i < 6; ++i) {
    write_file("hostile_abi_test_cut.frtree", bytes, cuts[i]);
    char label[64];
    snprintf(label, sizeof label, "cut to %ld bytes", cuts[i]);
    load_refused(label, "hostile_abi_test_cut.frtree", FRUSTA_ERROR_FILE_FORMAT, FRUSTA_ERROR_CORRUPT_FILE,
                 "hostile_abi_test_cut.frtree");
  }
  const long flips[] = {8, 24, 40, 160, size / 2, size - 1};
  for (int i = 0; i < 6; ++i) {
    bytes[flips[i]] ^= 0x40;
    write_file("hostile_abi_test_cut.frtree", bytes, size);
    bytes[flips[i]] ^= 0x40;
    char label[64];
    snprintf(label, sizeof label, "a bit flipped at byte %ld", flips[i]);
    load_refused(label, "hostile_abi_test_cut.frtree", FRUSTA_ERROR_CORRUPT_FILE, FRUSTA_ERROR_FILE_FORMAT,
                 "hostile_abi_test_cut.frtree");
  }
  memset(bytes, 'x', (size_t)size);
  write_file("hostile_abi_test_cut.frtree", bytes, size);
  load_refused("garbage", "hostile_abi_test_cut.frtree", FRUSTA_ERROR_FILE_FORMAT, FRUSTA_ERROR_FILE_FORMAT,
               "hostile_abi_test_cut.frtree");
  free(bytes);
  remove("hostile_abi_test_cut.frtree");
  what("frusta_create_sphere_tree_from_file(press_box)");
  if (accepted(frusta_create_sphere_tree_from_file(path, &tree))) {
    tree_finite(tree);
    frusta_destroy_sphere_tree(tree);
  }
}

static frusta_result call_save_id(RawId id, int* untouched) {
  remove(kSavedPath);
  const frusta_result r = frusta_sphere_tree_save(tree_of_raw(id), kSavedPath);
  FILE* f = fopen(kSavedPath, "rb");
  *untouched = f == NULL;
  if (f) fclose(f);
  return r;
}

static void t_save_sphere_tree(void) {
  sweep_ids("frusta_sphere_tree_save", "tree", TO_RAW(g_box), TO_RAW(g_dead_tree), 1, call_save_id);
  what("frusta_sphere_tree_save(tree, NULL)");
  refused(frusta_sphere_tree_save(g_box, NULL), FRUSTA_ERROR_NULL_POINTER, "path");
  static char long_path[10240];
  memset(long_path, 'z', sizeof long_path - 1);
  const char* paths[] = {"", ".", "no/such/dir/x.frtree", long_path, "/"};
  for (int i = 0; i < 5; ++i) {
    what("frusta_sphere_tree_save(tree, \"%.16s\")", paths[i]);
    refused(frusta_sphere_tree_save(g_box, paths[i]), FRUSTA_ERROR_IO, "");
  }
  what("frusta_sphere_tree_save(press_box) and load it back");
  if (accepted(frusta_sphere_tree_save(g_box, kSavedPath)) &&
      accepted(frusta_create_sphere_tree_from_file(kSavedPath, &g_saved_tree))) {
    int32_t a = 0, b = 0;
    frusta_sphere_tree_get_leaves(g_box, NULL, 0, &a);
    frusta_sphere_tree_get_leaves(g_saved_tree, NULL, 0, &b);
    verify(a == b && a > 0 && tree_finite(g_saved_tree), "%d leaves saved, %d loaded", a, b);
  }
  remove(kSavedPath);
}

static frusta_result call_destroy_tree(RawId id, int* untouched) {
  const frusta_result r = frusta_destroy_sphere_tree(tree_of_raw(id));
  *untouched = frusta_sphere_tree_is_valid(g_box) == 1;
  return r;
}

static void t_destroy_sphere_tree(void) {
  sweep_ids("frusta_destroy_sphere_tree", "tree", TO_RAW(g_box), TO_RAW(g_dead_tree), 1, call_destroy_tree);
  /* a tree destroyed while a world uses it: the world keeps it */
  frusta_tree_id tree;
  what("frusta_destroy_sphere_tree of a tree world A uses");
  if (!accepted(load_object("press_box", &tree))) return;
  frusta_object_def def = frusta_default_object_def();
  def.pose.position[2] = -2.0;
  frusta_object_id object;
  accepted(frusta_create_object(g_a.world, tree, &def, &object));
  accepted(frusta_destroy_sphere_tree(tree));
  refused(frusta_destroy_sphere_tree(tree), FRUSTA_ERROR_STALE_ID, "tree");
  g_a.object[g_a.objects++] = object;
  verify(press(&g_a, 4, 0.002, 0.2, 1), "the world stepped badly with a destroyed tree's object");
  accepted(frusta_destroy_object(object));
  --g_a.objects;
  accepted(frusta_world_step(g_a.world));
}

static int32_t valid_tree(RawId id) { return frusta_sphere_tree_is_valid(tree_of_raw(id)); }

static void t_sphere_tree_is_valid(void) {
  sweep_valid("frusta_sphere_tree_is_valid", TO_RAW(g_box), TO_RAW(g_dead_tree), 1, valid_tree);
}

static frusta_result call_info_id(RawId id, int* untouched) {
  frusta_sphere_tree_info info;
  fill(&info, sizeof info);
  info.struct_size = (int32_t)sizeof info;
  const frusta_result r = frusta_sphere_tree_get_info(tree_of_raw(id), &info);
  *untouched = is_sentinel((char*)&info + 4, sizeof info - 4);
  return r;
}

static frusta_result info_out(void* out) {
  return frusta_sphere_tree_get_info(g_box, (frusta_sphere_tree_info*)out);
}

static void t_sphere_tree_get_info(void) {
  sweep_ids("frusta_sphere_tree_get_info", "tree", TO_RAW(g_box), TO_RAW(g_dead_tree), 1, call_info_id);
  what("frusta_sphere_tree_get_info(tree, NULL)");
  refused(frusta_sphere_tree_get_info(g_box, NULL), FRUSTA_ERROR_NULL_POINTER, "info");
  sweep_out_size("frusta_sphere_tree_get_info", "frusta_sphere_tree_info", sizeof(frusta_sphere_tree_info),
                 info_out);
  what("frusta_sphere_tree_get_info: the box and the 10^6-leaf plate");
  tree_finite(g_box);
  frusta_sphere_tree_info info;
  memset(&info, 0, sizeof info);
  info.struct_size = (int32_t)sizeof info;
  if (accepted(frusta_sphere_tree_get_info(g_plate, &info)))
    verify(info.leaf_count == 1000000 && info.node_count > 0, "%d leaves, %d nodes", info.leaf_count,
           info.node_count);
}

static frusta_result leaves_call(void* out, int32_t capacity, int32_t* count) {
  return frusta_sphere_tree_get_leaves(g_box, (frusta_sphere*)out, capacity, count);
}

static void t_sphere_tree_get_leaves(void) {
  int32_t count;
  BadId bad[MAX_BAD_IDS];
  const int n = bad_ids(TO_RAW(g_box), TO_RAW(g_dead_tree), 1, bad);
  for (int b = 0; b < n; ++b) {
    fill(&count, sizeof count);
    what("frusta_sphere_tree_get_leaves with %s", bad[b].label);
    refused(frusta_sphere_tree_get_leaves(tree_of_raw(bad[b].id), NULL, 0, &count), bad[b].want, "tree");
    verify(is_sentinel(&count, sizeof count), "out_count written");
  }
  what("frusta_sphere_tree_get_leaves(tree, NULL, 0, NULL)");
  refused(frusta_sphere_tree_get_leaves(g_box, NULL, 0, NULL), FRUSTA_ERROR_NULL_POINTER, "out_count");
  what("frusta_sphere_tree_get_leaves(tree, NULL, 4, &count)");
  fill(&count, sizeof count);
  refused(frusta_sphere_tree_get_leaves(g_box, NULL, 4, &count), FRUSTA_ERROR_NULL_POINTER, "out");
  verify(is_sentinel(&count, sizeof count), "out_count written by refused calls");
  int32_t total = 0;
  frusta_sphere_tree_get_leaves(g_box, NULL, 0, &total);
  frusta_sphere* leaves = (frusta_sphere*)malloc(sizeof(frusta_sphere) * (size_t)(total + 2));
  if (verify(total > 0 && leaves != NULL, "%d leaves", total))
    sweep_output_array("frusta_sphere_tree_get_leaves", leaves_call, leaves, sizeof leaves[0],
                       total + 2, total, "out");
  free(leaves);
  what("frusta_sphere_tree_get_leaves: every leaf of the 10^6-leaf plate");
  verify(tree_finite(g_plate), "the plate's leaves");
}

/* query_segment's inputs besides the tree */
typedef struct SegmentQuery {
  frusta_pose pose;
  QueryInput input;  /* its segment; the sphere is unused */
  double margin;
} SegmentQuery;

static const SegmentQuery kSegmentQuery = {{{0, 0, 0}, {0, 0, 0, 1}},
                                           {{{-0.02, 0, 0.005}, {0.02, 0, 0.005}, 0.005, 0.004}, {{0, 0, 0}, 0}},
                                           0.001};

#define HITS 64
static frusta_result query_tree(frusta_tree_id tree, const frusta_pose* pose, const frusta_segment* segment,
                                double margin, int32_t level, frusta_tree_hit* out, int32_t capacity,
                                int32_t* count, int* untouched) {
  frusta_tree_hit hits[HITS + 1];
  int32_t found;
  fill(hits, sizeof hits);
  fill(&found, sizeof found);
  const frusta_result r = frusta_sphere_tree_query_segment(tree, pose, segment, margin, level,
                                                           out ? hits : NULL, capacity, &found);
  if (r != FRUSTA_OK) {
    *untouched = is_sentinel(hits, sizeof hits) && is_sentinel(&found, sizeof found);
    return r;
  }
  const int32_t written = found < capacity ? found : capacity;
  int ok = found >= 0 && is_sentinel(&hits[written], sizeof hits - sizeof hits[0] * (size_t)written);
  for (int32_t i = 0; ok && i < written; ++i)
    ok = hits[i].node >= 0 && hits[i].leaf >= -1 && all_finite(hits[i].sphere.center, 3) &&
         isfinite(hits[i].sphere.radius) && hits[i].sphere.radius >= 0.0;
  verify(ok, "%d hits, capacity %d: a bad hit, or writes beyond", found, capacity);
  if (out) memcpy(out, hits, sizeof hits[0] * (size_t)written);
  *count = found;
  return r;
}

static frusta_result call_query_segment(const void* input, int* untouched, void* context) {
  const SegmentQuery* q = (const SegmentQuery*)input;
  frusta_tree_hit hits[HITS];
  int32_t count;
  return query_tree(*(const frusta_tree_id*)context, &q->pose, &q->input.segment, q->margin, -1, hits, HITS,
                    &count, untouched);
}

static frusta_result call_query_segment_pose(const void* pose, int* untouched, void* context) {
  frusta_tree_hit hits[HITS];
  int32_t count;
  return query_tree(*(const frusta_tree_id*)context, (const frusta_pose*)pose, &kSegmentQuery.input.segment,
                    0.001, -1, hits, HITS, &count, untouched);
}

static frusta_result call_query_segment_id(RawId id, int* untouched) {
  frusta_tree_hit hits[HITS];
  int32_t count;
  return query_tree(tree_of_raw(id), NULL, &kSegmentQuery.input.segment, 0.001, -1, hits, HITS, &count,
                    untouched);
}

static void t_sphere_tree_query_segment(void) {
  sweep_ids("frusta_sphere_tree_query_segment", "tree", TO_RAW(g_box), TO_RAW(g_dead_tree), 1,
            call_query_segment_id);
  frusta_tree_hit hits[HITS];
  int32_t count;
  int untouched = 1;
  const frusta_segment* segment = &kSegmentQuery.input.segment;
  what("frusta_sphere_tree_query_segment: segment NULL");
  refused(query_tree(g_box, NULL, NULL, 0.001, -1, hits, HITS, &count, &untouched), FRUSTA_ERROR_NULL_POINTER,
          "segment");
  what("frusta_sphere_tree_query_segment: out NULL with capacity 4");
  refused(query_tree(g_box, NULL, segment, 0.001, -1, NULL, 4, &count, &untouched), FRUSTA_ERROR_NULL_POINTER,
          "out");
  what("frusta_sphere_tree_query_segment: out_count NULL");
  refused(frusta_sphere_tree_query_segment(g_box, NULL, segment, 0.001, -1, hits, HITS, NULL),
          FRUSTA_ERROR_NULL_POINTER, "out_count");
  const int32_t levels[] = {INT32_MIN, -2, 41, INT32_MAX};
  for (int i = 0; i < 4; ++i) {
    what("frusta_sphere_tree_query_segment: max_level %d", levels[i]);
    refused(query_tree(g_box, NULL, segment, 0.001, levels[i], hits, HITS, &count, &untouched),
            FRUSTA_ERROR_OUT_OF_RANGE, "max_level");
  }
  const int32_t good_levels[] = {-1, 0, 1, 40};
  for (int i = 0; i < 4; ++i) {
    what("frusta_sphere_tree_query_segment: max_level %d", good_levels[i]);
    accepted(query_tree(g_box, NULL, segment, 0.001, good_levels[i], hits, HITS, &count, &untouched));
  }
  const int32_t capacities[] = {INT32_MIN, -1};
  for (int i = 0; i < 2; ++i) {
    what("frusta_sphere_tree_query_segment: capacity %d", capacities[i]);
    refused(query_tree(g_box, NULL, segment, 0.001, -1, hits, capacities[i], &count, &untouched),
            FRUSTA_ERROR_OUT_OF_RANGE, "capacity");
  }
  verify(untouched, "a refused call wrote hits or a count");
  what("frusta_sphere_tree_query_segment: capacity 0, out NULL");
  accepted(query_tree(g_box, NULL, segment, 0.001, -1, NULL, 0, &count, &untouched));
  sweep_pose("frusta_sphere_tree_query_segment", "pose", call_query_segment_pose, &g_box);
  const Field fields[] = {
      {"segment.proximal", offsetof(SegmentQuery, input.segment.proximal), 3, 0, NAME_1D, -1e6, 1e6, 0},
      {"segment.distal", offsetof(SegmentQuery, input.segment.distal), 3, 0, NAME_1D, -1e6, 1e6, 0},
      {"segment.proximal_radius", offsetof(SegmentQuery, input.segment.proximal_radius), 1, 0, NAME_SCALAR,
       0.0, 1e6, 0},
      {"segment.distal_radius", offsetof(SegmentQuery, input.segment.distal_radius), 1, 0, NAME_SCALAR, 0.0,
       1e6, 0},
      {"margin", offsetof(SegmentQuery, margin), 1, 0, NAME_SCALAR, 0.0, 1e6, 0},
  };
  sweep_fields("frusta_sphere_tree_query_segment", &kSegmentQuery, sizeof kSegmentQuery, fields, 5,
               call_query_segment, &g_box);
  /* the plate: everything within 1e6 m is all 10^6 leaves, of which 64 are written */
  what("frusta_sphere_tree_query_segment: the 10^6-leaf plate, margin 1e6");
  if (accepted(query_tree(g_plate, NULL, segment, 1e6, -1, hits, HITS, &count, &untouched)))
    verify(count == 1000000, "%d hits", count);
  what("frusta_sphere_tree_query_segment: the plate, a segment 1e6 m long through it");
  const frusta_segment across = {{-1e6, 0, 0}, {1e6, 0, 0}, 1e6, 0.0};
  accepted(query_tree(g_plate, NULL, &across, 0.0, -1, hits, HITS, &count, &untouched));
  what("frusta_sphere_tree_query_segment: the plate, levels 0..40");
  for (int32_t level = 0; level <= 40; level += 8)
    accepted(query_tree(g_plate, NULL, segment, 0.01, level, hits, HITS, &count, &untouched));
}

/* ------------------------------------------------------------------ worlds */

static frusta_result add_object_to(frusta_world_id world, frusta_tree_id tree, const frusta_object_def* def,
                                   int* untouched);

#define WORLD_FIELD(member) #member, offsetof(frusta_world_def, member)
static const Field kWorldFields[] = {
    {WORLD_FIELD(rate_hz), 1, 0, NAME_SCALAR, 1.0, 100000.0, 1},  /* spin_us <= one period */
    {WORLD_FIELD(spin_us), 1, 0, NAME_SCALAR, 0.0, 1000.0, 0},    /* one period at 1 kHz */
    {WORLD_FIELD(gravity), 3, 0, NAME_1D, -1e3, 1e3, 0},
    {WORLD_FIELD(prediction_margin), 1, 0, NAME_SCALAR, 1e-5, 0.1, 0},
    {WORLD_FIELD(lod_error), 1, 0, NAME_SCALAR, 0.0, 1.0, 0},
    {WORLD_FIELD(max_fingertip_force), 1, 0, NAME_SCALAR, 0.0, 1e9, 0},
    {WORLD_FIELD(max_finger_resistance), 1, 0, NAME_SCALAR, 0.0, 1e9, 0},
    {WORLD_FIELD(max_joint_torque), 1, 0, NAME_SCALAR, 0.0, 1e9, 0},
    {WORLD_FIELD(max_palm_force), 1, 0, NAME_SCALAR, 0.0, 1e9, 0},
    {WORLD_FIELD(max_palm_torque), 1, 0, NAME_SCALAR, 0.0, 1e9, 0},
};

typedef struct IntField {
  const char* name;
  size_t offset;
  int32_t lo, hi;
} IntField;

static const IntField kWorldInts[] = {
    {WORLD_FIELD(max_objects), 1, 65535},
    {WORLD_FIELD(max_iterations), 1, 100},
    {WORLD_FIELD(max_substeps), 1, 1024},
    {WORLD_FIELD(max_contacts_per_hand), 0, 65536},
    {WORLD_FIELD(max_candidates_per_hand), 1, 1 << 18},
    {WORLD_FIELD(command_capacity), 1, 1 << 20},
    {WORLD_FIELD(max_hands), 1, 64},
    {WORLD_FIELD(realtime_priority), 0, 1},
};

#define OBJECT_FIELD(member) #member, offsetof(frusta_object_def, member)
static const Field kObjectFields[] = {
    {OBJECT_FIELD(stiffness), 3, 0, NAME_1D, 0.0, 1e9, 0},
    {OBJECT_FIELD(friction), 1, 0, NAME_SCALAR, 0.0, 100.0, 0},
    {OBJECT_FIELD(tangential_stiffness), 1, 0, NAME_SCALAR, 0.0, 1e9, 0},
    {OBJECT_FIELD(normal_damping), 1, 0, NAME_SCALAR, 0.0, 1e9, 0},
    {OBJECT_FIELD(tangential_damping), 1, 0, NAME_SCALAR, 0.0, 1e9, 0},
    {OBJECT_FIELD(mass), 1, 0, NAME_SCALAR, 1e-6, 1e4, 0},
    {OBJECT_FIELD(inertia), 3, 0, NAME_1D, 1e-13, 1e4, 1},  /* each <= the sum of the others */
    {OBJECT_FIELD(linear_velocity), 3, 0, NAME_1D, -100.0, 100.0, 0},
    {OBJECT_FIELD(angular_velocity), 3, 0, NAME_1D, -1000.0, 1000.0, 0},
    {OBJECT_FIELD(linear_damping), 1, 0, NAME_SCALAR, 0.0, 1000.0, 0},
    {OBJECT_FIELD(angular_damping), 1, 0, NAME_SCALAR, 0.0, 1000.0, 0},
};
#define OBJECT_FIELD_COUNT ((int)(sizeof kObjectFields / sizeof kObjectFields[0]))

/* Integer fields: INT32_MIN, -1, 0, INT32_MAX and either side of each limit, in a def
 * copied from base; `call` as for sweep_fields. */
static void sweep_ints(const char* label, const void* base, size_t size, const IntField* fields, int count,
                       DefCall call, void* context) {
  unsigned char def[MAX_DEF_BYTES];
  for (int fi = 0; fi < count; ++fi) {
    const IntField* f = &fields[fi];
    const int64_t values[] = {INT32_MIN, -1, 0, INT32_MAX, (int64_t)f->lo - 1, f->lo, f->hi, (int64_t)f->hi + 1};
    for (int i = 0; i < 8; ++i) {
      if (values[i] < INT32_MIN || values[i] > INT32_MAX) continue;
      const int32_t v = (int32_t)values[i];
      memcpy(def, base, size);
      memcpy(def + f->offset, &v, sizeof v);
      what("%s: %s = %d", label, f->name, v);
      int untouched = 1;
      const frusta_result got = call(def, &untouched, context);
      if (v >= f->lo && v <= f->hi) accepted(got);
      else refused(got, FRUSTA_ERROR_OUT_OF_RANGE, f->name);
      if (got != FRUSTA_OK) verify(untouched, "a refused call changed something");
    }
  }
}

/* A world from an accepted def is usable: a hand (unless the def's prediction margin is
 * too wide for it: refused by name), a box under its fingertip and a dynamic box in
 * the air, pressed for a few steps, everything finite. */
static void use_world(frusta_world_id world, const frusta_world_def* def) {
  Rig rig;
  memset(&rig, 0, sizeof rig);
  rig.world = world;
  rig.def = *def;
  frusta_hand_def hd = frusta_default_hand_def();
  const frusta_result r = frusta_create_world_hand(world, &hd, &rig.hand[0]);
  if (r != FRUSTA_OK) {
    refused(r, FRUSTA_ERROR_OUT_OF_RANGE, "prediction_margin");
    return;
  }
  rig.hands = 1;
  /* the hand's command first: a queue of one takes one command a step */
  if (!verify(frusta_world_step(world) == FRUSTA_OK, "step")) return;
  frusta_object_def box = box_under_tip(0, 0.0);
  if (!add_rig_object(&rig, g_box, &box) || !verify(frusta_world_step(world) == FRUSTA_OK, "step")) return;
  if (def->max_objects > 1) {
    frusta_object_def falling = frusta_default_object_def();
    falling.dynamic = 1;
    falling.pose.position[1] = 0.3;
    if (!add_rig_object(&rig, g_box, &falling)) return;
  }
  press(&rig, 6, 0.003, 0.5, 3);
}

static frusta_result call_create_world(const void* def, int* untouched, void* context) {
  (void)context;
  frusta_world_id world;
  fill(&world, sizeof world);
  const frusta_result r = frusta_create_world((const frusta_world_def*)def, &world);
  if (r != FRUSTA_OK) {
    *untouched = is_sentinel(&world, sizeof world);
    return r;
  }
  use_world(world, (const frusta_world_def*)def);
  verify(frusta_destroy_world(world) == FRUSTA_OK, "destroy: %s", frusta_last_error());
  return r;
}

static void t_default_world_def(void) {
  const frusta_world_def a = frusta_default_world_def(), b = frusta_default_world_def();
  what("frusta_default_world_def()");
  ++g_calls;
  verify(memcmp(&a, &b, sizeof a) == 0 && a.struct_size == (int32_t)sizeof a && a.internal_value != 0 &&
             isfinite(a.rate_hz) && isfinite(a.spin_us) && all_finite(a.gravity, 3) &&
             isfinite(a.prediction_margin) && isfinite(a.max_palm_torque),
         "not a deterministic, finite def of this size with its cookie");
  int untouched = 1;
  accepted(call_create_world(&a, &untouched, NULL));
}

static void t_default_object_def(void) {
  const frusta_object_def a = frusta_default_object_def(), b = frusta_default_object_def();
  what("frusta_default_object_def()");
  ++g_calls;
  verify(memcmp(&a, &b, sizeof a) == 0 && a.struct_size == (int32_t)sizeof a && a.internal_value != 0 &&
             all_finite(a.pose.position, 3) && unit_quaternion(a.pose.rotation) &&
             all_finite(a.stiffness, (offsetof(frusta_object_def, internal_value) -
                                      offsetof(frusta_object_def, stiffness)) / sizeof(double)),
         "not a deterministic, finite def of this size with its cookie");
  int untouched = 1;
  accepted(add_object_to(g_b.world, g_box, &a, &untouched));
}

static void t_create_world(void) {
  const frusta_world_def def = frusta_default_world_def();
  frusta_world_id world;
  fill(&world, sizeof world);
  what("frusta_create_world(NULL, &world)");
  refused(frusta_create_world(NULL, &world), FRUSTA_ERROR_NULL_POINTER, "def");
  what("frusta_create_world(&def, NULL)");
  refused(frusta_create_world(&def, NULL), FRUSTA_ERROR_NULL_POINTER, "out_world");
  verify(is_sentinel(&world, sizeof world), "out_world written");
  sweep_def_header("frusta_create_world", "frusta_world_def", &def, sizeof def,
                   offsetof(frusta_world_def, internal_value), call_create_world, NULL);
  sweep_fields("frusta_create_world", &def, sizeof def, kWorldFields,
               (int)(sizeof kWorldFields / sizeof kWorldFields[0]), call_create_world, NULL);
  sweep_ints("frusta_create_world", &def, sizeof def, kWorldInts,
             (int)(sizeof kWorldInts / sizeof kWorldInts[0]), call_create_world, NULL);
  /* the fastest world spins not at all; the slowest spins a whole second */
  frusta_world_def d = def;
  d.rate_hz = 100000.0;
  d.spin_us = 10.0;
  what("frusta_create_world: rate 100000 Hz, spin 10 us");
  int untouched = 1;
  accepted(call_create_world(&d, &untouched, NULL));
  d.spin_us = nextafter(10.0, INFINITY);
  what("frusta_create_world: rate 100000 Hz, spin just over one period");
  refused(call_create_world(&d, &untouched, NULL), FRUSTA_ERROR_OUT_OF_RANGE, "spin_us");
  d.rate_hz = 1.0;
  d.spin_us = 1e6;
  what("frusta_create_world: rate 1 Hz, spin 1 s");
  accepted(call_create_world(&d, &untouched, NULL));
}

static frusta_result call_destroy_world(RawId id, int* untouched) {
  const frusta_result r = frusta_destroy_world(world_of_raw(id));
  *untouched = frusta_world_is_valid(g_a.world) == 1;
  return r;
}

static int32_t valid_world(RawId id) { return frusta_world_is_valid(world_of_raw(id)); }

static void t_destroy_world(void) {
  sweep_ids("frusta_destroy_world", "world", TO_RAW(g_a.world), TO_RAW(g_dead_world), 1, call_destroy_world);
  /* destroyed twice; destroyed while its thread runs; with hands and objects */
  Rig rig;
  const frusta_world_def def = frusta_default_world_def();
  what("frusta_destroy_world of a running world with hands and objects, then again");
  if (make_press_rig(&rig, &def, 2, NULL) && press(&rig, 4, 0.002, 0.2, 4)) {
    accepted(frusta_world_start(rig.world));
    accepted(frusta_destroy_world(rig.world));
    refused(frusta_destroy_world(rig.world), FRUSTA_ERROR_STALE_ID, "world");
    ++g_calls;
    verify(frusta_world_is_valid(rig.world) == 0, "still valid");
    frusta_object_state o;
    refused(get_object(rig.world, rig.object[0], &o), FRUSTA_ERROR_STALE_ID, "world");
  }
}

static void t_world_is_valid(void) {
  sweep_valid("frusta_world_is_valid", TO_RAW(g_a.world), TO_RAW(g_dead_world), 1, valid_world);
}

/* add_hand's sweep: hands go into a world of their own, a new one every 16 hands, each
 * world stepped once with every hand given an input before it goes (the step adds them
 * all). */
static Rig g_hands_rig;
static void flush_hands_rig(void) {
  if (!frusta_world_is_valid(g_hands_rig.world)) return;
  for (int h = 0; h < g_hands_rig.hands; ++h)
    verify(frusta_world_set_haptic(g_hands_rig.world, g_hands_rig.hand[h], &kIdentity,
                                   g_hands_rig.angles[0], FRUSTA_HAND_JOINT_COUNT) == FRUSTA_OK,
           "set_haptic on hand %d: %s", h, frusta_last_error());
  verify(frusta_world_step(g_hands_rig.world) == FRUSTA_OK, "step");
  check_world(&g_hands_rig);
  destroy_rig(&g_hands_rig);
}

static frusta_result call_add_hand(const void* def, int* untouched, void* context) {
  (void)context;
  if (g_hands_rig.hands == 16) flush_hands_rig();
  if (!frusta_world_is_valid(g_hands_rig.world)) {
    frusta_world_def wd = frusta_default_world_def();
    wd.max_contacts_per_hand = 1;
    wd.max_objects = 1;
    wd.prediction_margin = 1e-5;  /* below the smallest finger radius a def may have */
    wd.max_hands = 16;
    make_rig(&g_hands_rig, &wd, 0);
  }
  frusta_hand_id hand;
  fill(&hand, sizeof hand);
  const frusta_result r =
      frusta_create_world_hand(g_hands_rig.world, (const frusta_hand_def*)def, &hand);
  if (r != FRUSTA_OK) {
    *untouched = is_sentinel(&hand, sizeof hand);
    return r;
  }
  verify(hand.index1 == g_hands_rig.hands + 1 && frusta_hand_is_valid(hand) == 1,
         "hand index1 %d, want %d", hand.index1, g_hands_rig.hands + 1);
  g_hands_rig.hand[g_hands_rig.hands++] = hand;
  return r;
}

static frusta_result call_add_hand_id(RawId id, int* untouched) {
  const frusta_hand_def def = frusta_default_hand_def();
  frusta_hand_id hand;
  fill(&hand, sizeof hand);
  const frusta_result r = frusta_create_world_hand(world_of_raw(id), &def, &hand);
  *untouched = is_sentinel(&hand, sizeof hand);
  return r;
}

static void t_world_add_hand(void) {
  sweep_ids("frusta_create_world_hand", "world", TO_RAW(g_a.world), TO_RAW(g_dead_world), 1,
            call_add_hand_id);
  const frusta_hand_def def = frusta_default_hand_def();
  frusta_hand_id hand;
  fill(&hand, sizeof hand);
  what("frusta_create_world_hand(world, NULL, &hand)");
  refused(frusta_create_world_hand(g_a.world, NULL, &hand), FRUSTA_ERROR_NULL_POINTER, "def");
  /* after the first step, as before it: present from the next step on, and gone again */
  what("frusta_create_world_hand after the first step, then frusta_destroy_world_hand");
  if (accepted(frusta_create_world_hand(g_a.world, &def, &hand))) {
    frusta_world_hand h;
    refused(get_hand(g_a.world, hand, &h), FRUSTA_ERROR_STALE_ID, "latched step");
    accepted(frusta_world_step(g_a.world));
    frusta_result r;
    verify(read_state(g_a.world, &r).hand_count == 3 && get_hand(g_a.world, hand, &h) == FRUSTA_OK &&
               h.solved == 0,
           "the hand added is not in the next step");
    accepted(frusta_destroy_world_hand(hand));
    accepted(frusta_world_step(g_a.world));
    check_world(&g_a);
  }
  memset(&g_hands_rig, 0, sizeof g_hands_rig);
  what("frusta_create_world_hand(world, &def, NULL)");
  int untouched = 1;
  call_add_hand(&def, &untouched, NULL);  /* makes the world */
  refused(frusta_create_world_hand(g_hands_rig.world, &def, NULL), FRUSTA_ERROR_NULL_POINTER,
          "out_hand");
  sweep_def_header("frusta_create_world_hand", "frusta_hand_def", &def, sizeof def,
                   offsetof(frusta_hand_def, internal_value), call_add_hand, NULL);
  sweep_fields("frusta_create_world_hand", &def, sizeof def, kHandFields, HAND_FIELD_COUNT,
               call_add_hand, NULL);
  flush_hands_rig();
  /* a margin wider than the smallest finger radius is refused by name */
  frusta_world_def wd = frusta_default_world_def();
  wd.prediction_margin = 0.1;
  Rig rig;
  if (make_rig(&rig, &wd, 0)) {
    what("frusta_create_world_hand: prediction_margin 0.1 m");
    refused(frusta_create_world_hand(rig.world, &def, &hand), FRUSTA_ERROR_OUT_OF_RANGE,
            "prediction_margin");
    accepted(frusta_world_start(rig.world));
    what("frusta_create_world_hand while the world runs: its settings are checked as ever");
    refused(frusta_create_world_hand(rig.world, &def, &hand), FRUSTA_ERROR_OUT_OF_RANGE,
            "prediction_margin");
    accepted(frusta_world_stop(rig.world));
    destroy_rig(&rig);
  }
}

/* A world call given every bad hand id: null, mangled indices, generations and world0
 * (world0 0 is a standalone hand's), a hand of a destroyed world, a hand of another
 * live world (g_b) and a live standalone hand: refused naming the hand, nothing changed. */
static void sweep_world_hand_ids(const char* label, frusta_hand_id live, IdCall call) {
  sweep_ids(label, "hand", TO_RAW(live), TO_RAW(g_dead_world_hand), 0, call);
  const struct {
    frusta_hand_id id;
    const char* what;
    const char* field;
  } foreign[] = {{g_b.hand[0], "g_b's hand", "another world"},
                 {g_hand, "a standalone hand", "standalone"}};
  for (int i = 0; i < 2; ++i) {
    what("%s with %s", label, foreign[i].what);
    int untouched = 1;
    refused(call(TO_RAW(foreign[i].id), &untouched), FRUSTA_ERROR_STALE_ID, foreign[i].field);
    verify(untouched, "a refused call changed something");
  }
}

/* g_a's inputs are as they were: the next step uses the inputs last accepted. */
static int a_inputs_kept(void) {
  return frusta_world_step(g_a.world) == FRUSTA_OK && check_world(&g_a) && inputs_used(&g_a);
}

static frusta_result call_set_haptic_id(RawId id, int* untouched) {
  frusta_pose palm = g_a.palm[0];
  palm.position[2] += 0.001;
  const frusta_result r = frusta_world_set_haptic(world_of_raw(id), g_a.hand[0], &palm,
                                                  g_a.angles[0], FRUSTA_HAND_JOINT_COUNT);
  *untouched = a_inputs_kept();
  return r;
}

static frusta_result call_set_haptic_palm(const void* palm, int* untouched, void* context) {
  (void)context;
  const frusta_pose before = g_a.palm[0];
  const frusta_result r = set_input(&g_a, 0, (const frusta_pose*)palm, g_a.angles[0]);
  *untouched = a_inputs_kept();  /* refused: the old input; accepted: the new one */
  if (r == FRUSTA_OK) {
    set_input(&g_a, 0, &before, g_a.angles[0]);
    a_inputs_kept();
  }
  return r;
}

static frusta_result call_set_haptic_angles(const void* angles, int* untouched, void* context) {
  (void)context;
  double before[FRUSTA_HAND_JOINT_COUNT];
  memcpy(before, g_a.angles[1], sizeof before);
  const frusta_result r = set_input(&g_a, 1, &g_a.palm[1], (const double*)angles);
  *untouched = a_inputs_kept();
  if (r == FRUSTA_OK) {
    set_input(&g_a, 1, &g_a.palm[1], before);
    a_inputs_kept();
  }
  return r;
}

static frusta_result call_set_haptic_hand(RawId id, int* untouched) {
  frusta_pose palm = g_a.palm[0];
  palm.position[2] += 0.001;
  const frusta_result r = frusta_world_set_haptic(g_a.world, hand_of_raw(id), &palm, g_a.angles[0],
                                                  FRUSTA_HAND_JOINT_COUNT);
  *untouched = a_inputs_kept();
  return r;
}

static void t_world_set_haptic(void) {
  sweep_ids("frusta_world_set_haptic", "world", TO_RAW(g_a.world), TO_RAW(g_dead_world), 1, call_set_haptic_id);
  sweep_world_hand_ids("frusta_world_set_haptic", g_a.hand[0], call_set_haptic_hand);
  what("frusta_world_set_haptic: palm NULL");
  refused(
      frusta_world_set_haptic(g_a.world, g_a.hand[0], NULL, g_a.angles[0], FRUSTA_HAND_JOINT_COUNT),
      FRUSTA_ERROR_NULL_POINTER, "palm");
  what("frusta_world_set_haptic: angles NULL");
  refused(
      frusta_world_set_haptic(g_a.world, g_a.hand[0], &g_a.palm[0], NULL, FRUSTA_HAND_JOINT_COUNT),
      FRUSTA_ERROR_NULL_POINTER, "angles");
  const int32_t counts[] = {INT32_MIN, -1, 0, FRUSTA_HAND_JOINT_COUNT - 1, FRUSTA_HAND_JOINT_COUNT + 1, INT32_MAX};
  for (int i = 0; i < 6; ++i) {
    what("frusta_world_set_haptic: count %d", counts[i]);
    refused(frusta_world_set_haptic(g_a.world, g_a.hand[0], &g_a.palm[0], g_a.angles[0], counts[i]),
            FRUSTA_ERROR_OUT_OF_RANGE, "count");
  }
  what("frusta_world_set_haptic: after the refused calls");
  verify(a_inputs_kept(), "the refused calls changed the inputs");
  sweep_pose("frusta_world_set_haptic", "palm", call_set_haptic_palm, NULL);
  const Field angles = {"angles", 0, FRUSTA_HAND_JOINT_COUNT, 0, NAME_1D, -FRUSTA_MAX_JOINT_ANGLE,
                        FRUSTA_MAX_JOINT_ANGLE, 0};
  sweep_fields("frusta_world_set_haptic", g_a.angles[1], sizeof g_a.angles[1], &angles, 1,
               call_set_haptic_angles, NULL);
}

/* frusta_world_set_haptic_at: g_a's hand 0 takes timed samples at g_time, which every
 * accepted call moves on (a hand's samples must come in time order) */
static double g_time = 1.0;

static frusta_result set_timed(frusta_world_id world, frusta_hand_id hand, double time,
                               const frusta_pose* palm, const double* angles, int32_t count) {
  return frusta_world_set_haptic_at(world, hand, time, palm, angles, count);
}

static frusta_result call_set_haptic_at_id(RawId id, int* untouched) {
  frusta_pose palm = g_a.palm[0];
  palm.position[2] += 0.001;
  const frusta_result r = set_timed(world_of_raw(id), g_a.hand[0], g_time += 0.001, &palm,
                                    g_a.angles[0], FRUSTA_HAND_JOINT_COUNT);
  *untouched = a_inputs_kept();
  return r;
}

static frusta_result call_set_haptic_at_hand(RawId id, int* untouched) {
  frusta_pose palm = g_a.palm[0];
  palm.position[2] += 0.001;
  const frusta_result r = set_timed(g_a.world, hand_of_raw(id), g_time += 0.001, &palm,
                                    g_a.angles[0], FRUSTA_HAND_JOINT_COUNT);
  *untouched = a_inputs_kept();
  return r;
}

/* a timed sample accepted is what the next step plays (the only one it has: held);
 * g_a's hand 0 is given its untimed input back afterwards */
static int timed_sample_played(double time) {
  frusta_pose palm = g_a.palm[0];
  palm.position[2] += 0.002;
  if (!accepted(set_timed(g_a.world, g_a.hand[0], time, &palm, g_a.angles[0],
                          FRUSTA_HAND_JOINT_COUNT)))
    return 0;
  frusta_world_hand wh;
  int ok = frusta_world_step(g_a.world) == FRUSTA_OK && check_world(&g_a) &&
           get_hand(g_a.world, g_a.hand[0], &wh) == FRUSTA_OK;
  ok = verify(ok && wh.haptic_palm.position[2] == palm.position[2],
              "the step did not play the timed sample at %g s (palm z %g, want %g)", time,
              wh.haptic_palm.position[2], palm.position[2]);
  set_input(&g_a, 0, &g_a.palm[0], g_a.angles[0]);
  return ok && a_inputs_kept();
}

static void t_world_set_haptic_at(void) {
  sweep_ids("frusta_world_set_haptic_at", "world", TO_RAW(g_a.world), TO_RAW(g_dead_world), 1,
            call_set_haptic_at_id);
  sweep_world_hand_ids("frusta_world_set_haptic_at", g_a.hand[0], call_set_haptic_at_hand);
  what("frusta_world_set_haptic_at: palm NULL");
  refused(set_timed(g_a.world, g_a.hand[0], g_time += 0.001, NULL, g_a.angles[0],
                    FRUSTA_HAND_JOINT_COUNT),
          FRUSTA_ERROR_NULL_POINTER, "palm");
  what("frusta_world_set_haptic_at: angles NULL");
  refused(set_timed(g_a.world, g_a.hand[0], g_time += 0.001, &g_a.palm[0], NULL,
                    FRUSTA_HAND_JOINT_COUNT),
          FRUSTA_ERROR_NULL_POINTER, "angles");
  const int32_t counts[] = {INT32_MIN, -1, 0, FRUSTA_HAND_JOINT_COUNT - 1, FRUSTA_HAND_JOINT_COUNT + 1, INT32_MAX};
  for (int i = 0; i < 6; ++i) {
    what("frusta_world_set_haptic_at: count %d", counts[i]);
    refused(set_timed(g_a.world, g_a.hand[0], g_time += 0.001, &g_a.palm[0], g_a.angles[0], counts[i]),
            FRUSTA_ERROR_OUT_OF_RANGE, "count");
  }
  const struct {
    double time;
    frusta_result want;
  } times[] = {{NAN, FRUSTA_ERROR_NOT_FINITE},       {INFINITY, FRUSTA_ERROR_NOT_FINITE},
               {-INFINITY, FRUSTA_ERROR_NOT_FINITE}, {-1.0, FRUSTA_ERROR_OUT_OF_RANGE},
               {-DBL_MIN, FRUSTA_ERROR_OUT_OF_RANGE}, {-DBL_MAX, FRUSTA_ERROR_OUT_OF_RANGE},
               {1.000001e9, FRUSTA_ERROR_OUT_OF_RANGE}, {DBL_MAX, FRUSTA_ERROR_OUT_OF_RANGE}};
  for (int i = 0; i < (int)(sizeof times / sizeof times[0]); ++i) {
    what("frusta_world_set_haptic_at: time %g", times[i].time);
    refused(set_timed(g_a.world, g_a.hand[0], times[i].time, &g_a.palm[0], g_a.angles[0],
                      FRUSTA_HAND_JOINT_COUNT),
            times[i].want, "time");
  }
  what("frusta_world_set_haptic_at: after the refused calls");
  verify(a_inputs_kept(), "the refused calls changed the inputs");
  /* in time order only: the same time again, or an earlier one, is refused */
  what("frusta_world_set_haptic_at: a sample, played");
  const double t = g_time += 0.001;
  verify(timed_sample_played(t), "the timed sample was not played");
  what("frusta_world_set_haptic_at: the same time again");
  refused(set_timed(g_a.world, g_a.hand[0], t, &g_a.palm[0], g_a.angles[0], FRUSTA_HAND_JOINT_COUNT),
          FRUSTA_ERROR_OUT_OF_RANGE, "previous");
  what("frusta_world_set_haptic_at: an earlier time");
  refused(set_timed(g_a.world, g_a.hand[0], t - 0.5, &g_a.palm[0], g_a.angles[0],
                    FRUSTA_HAND_JOINT_COUNT),
          FRUSTA_ERROR_OUT_OF_RANGE, "previous");
  verify(a_inputs_kept(), "the refused calls changed the inputs");
  /* the largest time there is: nothing can follow it on this hand, so it comes last */
  what("frusta_world_set_haptic_at: time 1e9");
  verify(timed_sample_played(1e9), "the timed sample at 1e9 s was not played");
  what("frusta_world_set_haptic_at: after 1e9");
  refused(set_timed(g_a.world, g_a.hand[0], 1e9, &g_a.palm[0], g_a.angles[0], FRUSTA_HAND_JOINT_COUNT),
          FRUSTA_ERROR_OUT_OF_RANGE, "previous");
  /* palm and angles as frusta_world_set_haptic's: the same one rule */
  what("frusta_world_set_haptic_at: a palm rotation of norm 3");
  frusta_pose bad = g_a.palm[0];
  bad.rotation[3] = 3.0;
  refused(set_timed(g_a.world, g_a.hand[1], 5.0, &bad, g_a.angles[1], FRUSTA_HAND_JOINT_COUNT),
          FRUSTA_ERROR_OUT_OF_RANGE, "palm");
  what("frusta_world_set_haptic_at: a NaN angle");
  double angles[FRUSTA_HAND_JOINT_COUNT];
  memcpy(angles, g_a.angles[1], sizeof angles);
  angles[7] = NAN;
  refused(set_timed(g_a.world, g_a.hand[1], 5.0, &g_a.palm[1], angles, FRUSTA_HAND_JOINT_COUNT),
          FRUSTA_ERROR_NOT_FINITE, "angles");
  verify(a_inputs_kept(), "the refused calls changed the inputs");
}

static void t_now(void) {
  what("frusta_now()");
  g_calls += 2;
  const double a = frusta_now(), b = frusta_now();
  verify(isfinite(a) && a >= 0.0 && b >= a, "frusta_now() gave %g then %g", a, b);
}

static int32_t objects_after_step(frusta_world_id world) {
  frusta_result r;
  if (frusta_world_step(world) != FRUSTA_OK) return -1;
  const frusta_world_state s = read_state(world, &r);
  return r == FRUSTA_OK ? s.object_count : -1;
}

static frusta_result add_object_to(frusta_world_id world, frusta_tree_id tree, const frusta_object_def* def,
                                   int* untouched) {
  const int32_t before = objects_after_step(world);
  frusta_object_id object;
  fill(&object, sizeof object);
  const frusta_result r = frusta_create_object(world, tree, def, &object);
  const int32_t after = objects_after_step(world);
  if (r != FRUSTA_OK) {
    *untouched = is_sentinel(&object, sizeof object) && after == before;
    return r;
  }
  /* used: present at the next step as defined */
  frusta_object_state o;
  const frusta_result got = get_object(world, object, &o);
  if (verify(got == FRUSTA_OK && after == before + 1, "the object added is not there (%s, %d objects, %d "
             "before)", frusta_result_name(got), after, before)) {
    const double n = norm_n(def->pose.rotation, 4);
    double worst = 0.0;
    for (int k = 0; k < 3; ++k) worst = fmax(worst, fabs(o.pose.position[k] - def->pose.position[k]));
    double dot = 0.0;
    for (int k = 0; k < 4; ++k) dot += o.pose.rotation[k] * def->pose.rotation[k] / n;
    verify(object_finite(&o) && worst == 0.0 && fabs(fabs(dot) - 1.0) <= 1e-9 && o.dynamic == def->dynamic,
           "the object is not as added: position off by %g, rotation dot %g, dynamic %d", worst, dot, o.dynamic);
    int same_velocity = 1;
    for (int k = 0; k < 3; ++k)
      same_velocity &= o.linear_velocity[k] == def->linear_velocity[k] &&
                       o.angular_velocity[k] == def->angular_velocity[k];
    verify(same_velocity, "the velocities are not the def's");
  }
  verify(frusta_destroy_object(object) == FRUSTA_OK && objects_after_step(world) == before,
         "remove: %s", frusta_last_error());
  return r;
}

static frusta_result call_add_object_def(const void* def, int* untouched, void* context) {
  (void)context;
  return add_object_to(g_b.world, g_box, (const frusta_object_def*)def, untouched);
}

static frusta_result call_add_object_pose(const void* pose, int* untouched, void* context) {
  frusta_object_def def = *(const frusta_object_def*)context;
  def.pose = *(const frusta_pose*)pose;
  if (fabs(def.pose.position[2]) < 1.0) def.pose.position[2] = -1.0;  /* away from the hand */
  return add_object_to(g_b.world, g_box, &def, untouched);
}

static frusta_result call_add_object_world(RawId id, int* untouched) {
  frusta_object_def def = frusta_default_object_def();
  frusta_object_id object;
  fill(&object, sizeof object);
  const frusta_result r = frusta_create_object(world_of_raw(id), g_box, &def, &object);
  *untouched = is_sentinel(&object, sizeof object);
  return r;
}

static frusta_result call_add_object_tree(RawId id, int* untouched) {
  frusta_object_def def = frusta_default_object_def();
  def.pose.position[2] = -1.0;
  return add_object_to(g_b.world, tree_of_raw(id), &def, untouched);
}

static void t_world_add_object(void) {
  sweep_ids("frusta_create_object", "world", TO_RAW(g_a.world), TO_RAW(g_dead_world), 1,
            call_add_object_world);
  sweep_ids("frusta_create_object", "tree", TO_RAW(g_box), TO_RAW(g_dead_tree), 1,
            call_add_object_tree);
  frusta_object_def def = frusta_default_object_def();
  def.pose.position[2] = -1.0;
  frusta_object_id object;
  fill(&object, sizeof object);
  what("frusta_create_object(world, tree, NULL, &object)");
  refused(frusta_create_object(g_b.world, g_box, NULL, &object), FRUSTA_ERROR_NULL_POINTER, "def");
  what("frusta_create_object(world, tree, &def, NULL)");
  refused(frusta_create_object(g_b.world, g_box, &def, NULL), FRUSTA_ERROR_NULL_POINTER,
          "out_object");
  verify(is_sentinel(&object, sizeof object), "out_object written");
  sweep_def_header("frusta_create_object", "frusta_object_def", &def, sizeof def,
                   offsetof(frusta_object_def, internal_value), call_add_object_def, NULL);
  sweep_fields("frusta_create_object", &def, sizeof def, kObjectFields, OBJECT_FIELD_COUNT,
               call_add_object_def, NULL);
  frusta_object_def dynamic = def;
  dynamic.dynamic = 1;
  sweep_fields("frusta_create_object (dynamic)", &dynamic, sizeof dynamic, kObjectFields,
               OBJECT_FIELD_COUNT, call_add_object_def, NULL);
  sweep_pose("frusta_create_object", "pose", call_add_object_pose, &def);
  for (int i = 0; i < HOSTILE_INT_COUNT; ++i) {
    frusta_object_def d = def;
    d.dynamic = kHostileInts[i] == 0 ? 2 : kHostileInts[i];
    what("frusta_create_object: dynamic %d", d.dynamic);
    int untouched = 1;
    refused(add_object_to(g_b.world, g_box, &d, &untouched), FRUSTA_ERROR_OUT_OF_RANGE, "dynamic");
    verify(untouched, "a refused call changed something");
  }
  /* a full command queue refuses, and the next step makes room */
  frusta_world_def wd = frusta_default_world_def();
  wd.command_capacity = 1;
  Rig rig;
  if (make_rig(&rig, &wd, 1)) {
    what("frusta_create_object with the command queue full");
    /* a hand's and an object's commands share the queue */
    fill(&object, sizeof object);
    refused(frusta_create_object(rig.world, g_box, &def, &object), FRUSTA_ERROR_CAPACITY, "queue");
    verify(is_sentinel(&object, sizeof object), "out_object written");
    accepted(frusta_world_step(rig.world));
    accepted(frusta_create_object(rig.world, g_box, &def, &object));
    fill(&object, sizeof object);
    refused(frusta_create_object(rig.world, g_box, &def, &object), FRUSTA_ERROR_CAPACITY, "queue");
    verify(is_sentinel(&object, sizeof object), "out_object written");
    verify(objects_after_step(rig.world) == 1, "not one object");
    accepted(frusta_create_object(rig.world, g_box, &def, &object));
    verify(objects_after_step(rig.world) == 2, "not two objects");
    destroy_rig(&rig);
  }
}

/* An object of g_a far below the hands, for the calls that move or remove it. */
static frusta_object_id add_far_object(void) {
  frusta_object_def def = frusta_default_object_def();
  def.pose.position[2] = -1.0;
  frusta_object_id object = {0, 0, 0};
  verify(frusta_create_object(g_a.world, g_box, &def, &object) == FRUSTA_OK, "add: %s",
         frusta_last_error());
  frusta_world_step(g_a.world);
  return object;
}

static frusta_object_id g_far;  /* the object the id sweeps aim at */

/* A world-and-object call with one of them bad: g_far must still be as it was. */
static int far_unchanged(void) {
  frusta_object_state o;
  if (frusta_world_step(g_a.world) != FRUSTA_OK || !check_world(&g_a)) return 0;
  frusta_result r;
  read_state(g_a.world, &r);
  return get_object(g_a.world, g_far, &o) == FRUSTA_OK && o.pose.position[2] == -1.0 && o.dynamic == 0 &&
         o.pose.position[0] == 0.0;
}

static frusta_result call_destroy_object(RawId id, int* untouched) {
  const frusta_result r = frusta_destroy_object(object_of_raw(id));
  *untouched = far_unchanged();
  return r;
}

/* Every way an object id can be wrong for g_a: the sweep, then another world's object,
 * and an object of a destroyed world. */
static void sweep_object_ids(const char* label, IdCall call) {
  sweep_ids(label, "object", TO_RAW(g_far), TO_RAW(g_dead_object), 0, call);
  what("%s with world B's object", label);
  int untouched = 1;
  refused(call(TO_RAW(g_b.object[0]), &untouched), FRUSTA_ERROR_STALE_ID, "object");
  verify(untouched, "a refused call changed something");
  Rig rig;
  const frusta_world_def def = frusta_default_world_def();
  if (make_press_rig(&rig, &def, 1, NULL)) {
    const frusta_object_id dead = rig.object[0];
    destroy_rig(&rig);
    what("%s with a destroyed world's object", label);
    refused(call(TO_RAW(dead), &untouched), FRUSTA_ERROR_STALE_ID, "object");
    verify(untouched, "a refused call changed something");
  }
}

static void t_destroy_object(void) {
  g_far = add_far_object();
  /* the id alone names the world: every bad id and an object of a destroyed world are
     refused (an object of another live world is that world's, and goes) */
  sweep_ids("frusta_destroy_object", "object", TO_RAW(g_far), TO_RAW(g_dead_object), 0,
            call_destroy_object);
  Rig rig;
  const frusta_world_def def = frusta_default_world_def();
  if (make_press_rig(&rig, &def, 1, NULL)) {
    const frusta_object_id dead = rig.object[0];
    destroy_rig(&rig);
    what("frusta_destroy_object with a destroyed world's object");
    int untouched = 1;
    refused(call_destroy_object(TO_RAW(dead), &untouched), FRUSTA_ERROR_STALE_ID, "object");
    verify(untouched, "a refused call changed something");
  }
  frusta_result r;
  const int32_t before = read_state(g_a.world, &r).object_count;
  what("frusta_destroy_object, then again");
  accepted(frusta_destroy_object(g_far));
  refused(frusta_destroy_object(g_far), FRUSTA_ERROR_STALE_ID, "object");
  verify(objects_after_step(g_a.world) == before - 1, "the object removed is still there");
  frusta_object_state o;
  refused(get_object(g_a.world, g_far, &o), FRUSTA_ERROR_STALE_ID, "object");
}

static frusta_result call_pose_world(RawId id, int* untouched) {
  const frusta_pose pose = {{0.5, 0.0, -1.0}, {0, 0, 0, 1}};
  const frusta_result r = frusta_world_set_object_pose(world_of_raw(id), g_far, &pose);
  *untouched = far_unchanged();
  return r;
}
static frusta_result call_pose_object(RawId id, int* untouched) {
  const frusta_pose pose = {{0.5, 0.0, -1.0}, {0, 0, 0, 1}};
  const frusta_result r = frusta_world_set_object_pose(g_a.world, object_of_raw(id), &pose);
  *untouched = far_unchanged();
  return r;
}

static frusta_result call_pose(const void* pose, int* untouched, void* context) {
  (void)context;
  frusta_pose p = *(const frusta_pose*)pose;
  if (fabs(p.position[2]) < 1.0) p.position[2] = -1.0;  /* never into the hands */
  const frusta_result r = frusta_world_set_object_pose(g_a.world, g_far, &p);
  if (r != FRUSTA_OK) {
    *untouched = far_unchanged();
    return r;
  }
  /* used: there at the next step, at rest */
  frusta_object_state o;
  if (verify(frusta_world_step(g_a.world) == FRUSTA_OK && check_world(&g_a) &&
                 get_object(g_a.world, g_far, &o) == FRUSTA_OK,
             "step and read: %s", frusta_last_error())) {
    const double n = norm_n(p.rotation, 4);
    double dot = 0.0;
    for (int k = 0; k < 4; ++k) dot += o.pose.rotation[k] * p.rotation[k] / n;
    verify(memcmp(o.pose.position, p.position, sizeof p.position) == 0 && fabs(fabs(dot) - 1.0) <= 1e-9 &&
               norm_n(o.linear_velocity, 3) == 0.0 && norm_n(o.angular_velocity, 3) == 0.0,
           "the object is at (%g, %g, %g), not where it was put", o.pose.position[0], o.pose.position[1],
           o.pose.position[2]);
  }
  const frusta_pose back = {{0.0, 0.0, -1.0}, {0, 0, 0, 1}};
  frusta_world_set_object_pose(g_a.world, g_far, &back);
  frusta_world_step(g_a.world);
  return r;
}

static void t_world_set_object_pose(void) {
  g_far = add_far_object();
  sweep_ids("frusta_world_set_object_pose", "world", TO_RAW(g_a.world), TO_RAW(g_dead_world), 1, call_pose_world);
  sweep_object_ids("frusta_world_set_object_pose", call_pose_object);
  what("frusta_world_set_object_pose(world, object, NULL)");
  refused(frusta_world_set_object_pose(g_a.world, g_far, NULL), FRUSTA_ERROR_NULL_POINTER, "pose");
  verify(far_unchanged(), "the object moved");
  sweep_pose("frusta_world_set_object_pose", "pose", call_pose, NULL);
  frusta_destroy_object(g_far);
  frusta_world_step(g_a.world);
}

static frusta_result call_dynamic_world(RawId id, int* untouched) {
  const frusta_result r = frusta_world_set_object_dynamic(world_of_raw(id), g_far, 1);
  *untouched = far_unchanged();
  return r;
}
static frusta_result call_dynamic_object(RawId id, int* untouched) {
  const frusta_result r = frusta_world_set_object_dynamic(g_a.world, object_of_raw(id), 1);
  *untouched = far_unchanged();
  return r;
}

static void t_world_set_object_dynamic(void) {
  g_far = add_far_object();
  sweep_ids("frusta_world_set_object_dynamic", "world", TO_RAW(g_a.world), TO_RAW(g_dead_world), 1,
            call_dynamic_world);
  sweep_object_ids("frusta_world_set_object_dynamic", call_dynamic_object);
  const int32_t values[] = {INT32_MIN, -1, 2, INT32_MAX};
  for (int i = 0; i < 4; ++i) {
    what("frusta_world_set_object_dynamic: %d", values[i]);
    refused(frusta_world_set_object_dynamic(g_a.world, g_far, values[i]), FRUSTA_ERROR_OUT_OF_RANGE, "dynamic");
    verify(far_unchanged(), "the object changed");
  }
  for (int32_t d = 1; d >= 0; --d) {
    what("frusta_world_set_object_dynamic: %d", d);
    accepted(frusta_world_set_object_dynamic(g_a.world, g_far, d));
    frusta_object_state o;
    verify(frusta_world_step(g_a.world) == FRUSTA_OK && check_world(&g_a) &&
               get_object(g_a.world, g_far, &o) == FRUSTA_OK && o.dynamic == d,
           "the next step has dynamic %d", o.dynamic);
  }
  frusta_destroy_object(g_far);
  frusta_world_step(g_a.world);
}

static frusta_result call_step_id(RawId id, int* untouched) {
  frusta_result r;
  const uint64_t before = read_state(g_a.world, &r).step;
  const frusta_result got = frusta_world_step(world_of_raw(id));
  *untouched = read_state(g_a.world, &r).step == before;
  return got;
}

static void t_world_step(void) {
  sweep_ids("frusta_world_step", "world", TO_RAW(g_a.world), TO_RAW(g_dead_world), 1, call_step_id);
  what("frusta_world_step while its thread runs");
  if (accepted(frusta_world_start(g_b.world))) {
    refused(frusta_world_step(g_b.world), FRUSTA_ERROR_WRONG_STATE, "");
    accepted(frusta_world_stop(g_b.world));
  }
  accepted(frusta_world_step(g_b.world));
}

static frusta_result call_start_id(RawId id, int* untouched) {
  const frusta_result r = frusta_world_start(world_of_raw(id));
  *untouched = frusta_world_step(g_a.world) == FRUSTA_OK;  /* not started: the host may step */
  return r;
}

static void t_world_start(void) {
  sweep_ids("frusta_world_start", "world", TO_RAW(g_a.world), TO_RAW(g_dead_world), 1, call_start_id);
  what("frusta_world_start twice");
  if (accepted(frusta_world_start(g_b.world))) {
    refused(frusta_world_start(g_b.world), FRUSTA_ERROR_WRONG_STATE, "running");
    accepted(frusta_world_stop(g_b.world));
  }
  check_world(&g_b);
}

static frusta_result call_stop_id(RawId id, int* untouched) {
  *untouched = 1;
  return frusta_world_stop(world_of_raw(id));
}

static void t_world_stop(void) {
  sweep_ids("frusta_world_stop", "world", TO_RAW(g_a.world), TO_RAW(g_dead_world), 1, call_stop_id);
  what("frusta_world_stop of a world not running, twice");
  accepted(frusta_world_stop(g_b.world));
  accepted(frusta_world_stop(g_b.world));
}

static frusta_result call_read_id(RawId id, int* untouched) {
  frusta_world_state s;
  fill(&s, sizeof s);
  s.struct_size = (int32_t)sizeof s;
  const frusta_result r = frusta_world_read(world_of_raw(id), &s);
  *untouched = is_sentinel((char*)&s + 4, sizeof s - 4);
  return r;
}

static frusta_result read_out(void* out) { return frusta_world_read(g_a.world, (frusta_world_state*)out); }

static void t_world_read(void) {
  sweep_ids("frusta_world_read", "world", TO_RAW(g_a.world), TO_RAW(g_dead_world), 1, call_read_id);
  what("frusta_world_read(world, NULL)");
  refused(frusta_world_read(g_a.world, NULL), FRUSTA_ERROR_NULL_POINTER, "state");
  sweep_out_size("frusta_world_read", "frusta_world_state", sizeof(frusta_world_state), read_out);
  what("frusta_world_read");
  check_world(&g_a);
}

/* A new world with a hand and no step latched: the get calls must say so. */
static void unlatched(const char* label, int which) {
  Rig rig;
  const frusta_world_def def = frusta_default_world_def();
  if (!make_press_rig(&rig, &def, 1, NULL)) return;
  frusta_world_hand h;
  frusta_object_state o;
  int32_t count;
  fill(&count, sizeof count);
  what("%s before any frusta_world_read", label);
  if (which == 0)
    refused(get_hand(rig.world, rig.hand[0], &h), FRUSTA_ERROR_WRONG_STATE, "frusta_world_read");
  if (which == 1)
    refused(frusta_world_get_contacts(rig.world, rig.hand[0], NULL, 0, &count),
            FRUSTA_ERROR_WRONG_STATE, "frusta_world_read");
  if (which == 2) refused(get_object(rig.world, rig.object[0], &o), FRUSTA_ERROR_WRONG_STATE, "frusta_world_read");
  if (which == 3)
    refused(frusta_world_get_object_ignored_by(rig.world, rig.object[0], rig.hand[0], &count),
            FRUSTA_ERROR_WRONG_STATE, "frusta_world_read");
  if (which == 4)
    refused(frusta_world_get_hand_segments(rig.world, rig.hand[0], 0, NULL, 0, &count),
            FRUSTA_ERROR_WRONG_STATE, "frusta_world_read");
  if (which == 5)
    refused(frusta_world_get_hand_palm_spheres(rig.world, rig.hand[0], 1, NULL, 0, &count),
            FRUSTA_ERROR_WRONG_STATE, "frusta_world_read");
  verify(is_sentinel(&count, sizeof count), "out_count written");
  destroy_rig(&rig);
}

static frusta_result call_get_hand_id(RawId id, int* untouched) {
  frusta_world_hand h;
  fill(&h, sizeof h);
  h.struct_size = (int32_t)sizeof h;
  const frusta_result r = frusta_world_get_hand(world_of_raw(id), g_a.hand[0], &h);
  *untouched = is_sentinel((char*)&h + 4, sizeof h - 4);
  return r;
}

static frusta_result call_get_hand_hand(RawId id, int* untouched) {
  frusta_world_hand h;
  fill(&h, sizeof h);
  h.struct_size = (int32_t)sizeof h;
  const frusta_result r = frusta_world_get_hand(g_a.world, hand_of_raw(id), &h);
  *untouched = is_sentinel((char*)&h + 4, sizeof h - 4);
  return r;
}

static frusta_result get_hand_out(void* out) {
  return frusta_world_get_hand(g_a.world, g_a.hand[0], (frusta_world_hand*)out);
}

static void t_world_get_hand(void) {
  sweep_ids("frusta_world_get_hand", "world", TO_RAW(g_a.world), TO_RAW(g_dead_world), 1, call_get_hand_id);
  check_world(&g_a);
  sweep_world_hand_ids("frusta_world_get_hand", g_a.hand[0], call_get_hand_hand);
  what("frusta_world_get_hand(world, hand, NULL)");
  refused(frusta_world_get_hand(g_a.world, g_a.hand[0], NULL), FRUSTA_ERROR_NULL_POINTER, "out");
  sweep_out_size("frusta_world_get_hand", "frusta_world_hand", sizeof(frusta_world_hand), get_hand_out);
  unlatched("frusta_world_get_hand", 0);
}

static frusta_result call_contacts_id(RawId id, int* untouched) {
  int32_t count;
  fill(&count, sizeof count);
  fill(g_contacts, sizeof g_contacts[0] * 4);
  const frusta_result r =
      frusta_world_get_contacts(world_of_raw(id), g_a.hand[0], g_contacts, 4, &count);
  *untouched = is_sentinel(&count, sizeof count) && is_sentinel(g_contacts, sizeof g_contacts[0] * 4);
  return r;
}

static frusta_result call_contacts_hand(RawId id, int* untouched) {
  int32_t count;
  fill(&count, sizeof count);
  fill(g_contacts, sizeof g_contacts[0] * 4);
  const frusta_result r =
      frusta_world_get_contacts(g_a.world, hand_of_raw(id), g_contacts, 4, &count);
  *untouched =
      is_sentinel(&count, sizeof count) && is_sentinel(g_contacts, sizeof g_contacts[0] * 4);
  return r;
}

static frusta_result contacts_call(void* out, int32_t capacity, int32_t* count) {
  return frusta_world_get_contacts(g_a.world, g_a.hand[0], (frusta_world_contact*)out, capacity,
                                   count);
}

static void t_world_get_contacts(void) {
  sweep_ids("frusta_world_get_contacts", "world", TO_RAW(g_a.world), TO_RAW(g_dead_world), 1, call_contacts_id);
  press(&g_a, 6, 0.004, 0.3, 6);  /* pressing: contacts to count */
  int32_t kept = -1, count;
  what("frusta_world_get_contacts size query");
  accepted(frusta_world_get_contacts(g_a.world, g_a.hand[0], NULL, 0, &kept));
  verify(kept > 0 && kept + 4 <= MAX_CHECKED_CONTACTS, "no contacts while pressing (%d)", kept);
  sweep_world_hand_ids("frusta_world_get_contacts", g_a.hand[0], call_contacts_hand);
  sweep_output_array("frusta_world_get_contacts", contacts_call, g_contacts, sizeof g_contacts[0],
                     kept + 4, kept, "out");
  what("frusta_world_get_contacts: capacity INT32_MAX");
  fill(g_contacts, sizeof g_contacts);
  accepted(frusta_world_get_contacts(g_a.world, g_a.hand[0], g_contacts, INT32_MAX, &count));
  verify(count == kept && is_sentinel(&g_contacts[kept],
                                      sizeof g_contacts[0] * (size_t)(MAX_CHECKED_CONTACTS - kept)),
         "%d contacts, or writes beyond them", count);
  unlatched("frusta_world_get_contacts", 1);
}

static frusta_result call_get_object_world(RawId id, int* untouched) {
  frusta_object_state o;
  fill(&o, sizeof o);
  o.struct_size = (int32_t)sizeof o;
  const frusta_result r = frusta_world_get_object(world_of_raw(id), g_far, &o);
  *untouched = is_sentinel((char*)&o + 4, sizeof o - 4);
  return r;
}
static frusta_result call_get_object_id(RawId id, int* untouched) {
  frusta_object_state o;
  fill(&o, sizeof o);
  o.struct_size = (int32_t)sizeof o;
  const frusta_result r = frusta_world_get_object(g_a.world, object_of_raw(id), &o);
  *untouched = is_sentinel((char*)&o + 4, sizeof o - 4);
  return r;
}
static frusta_result get_object_out(void* out) {
  return frusta_world_get_object(g_a.world, g_far, (frusta_object_state*)out);
}

static void t_world_get_object(void) {
  g_far = add_far_object();
  check_world(&g_a);
  sweep_ids("frusta_world_get_object", "world", TO_RAW(g_a.world), TO_RAW(g_dead_world), 1, call_get_object_world);
  sweep_object_ids("frusta_world_get_object", call_get_object_id);
  what("frusta_world_get_object(world, object, NULL)");
  refused(frusta_world_get_object(g_a.world, g_far, NULL), FRUSTA_ERROR_NULL_POINTER, "out");
  sweep_out_size("frusta_world_get_object", "frusta_object_state", sizeof(frusta_object_state), get_object_out);
  unlatched("frusta_world_get_object", 2);
  frusta_destroy_object(g_far);
  frusta_world_step(g_a.world);
}

/* frusta_destroy_world_hand: the id alone names the world. Every bad id is refused and
 * g_a keeps its hands; a hand of another live world is that world's, and goes. Then a
 * hand destroyed for good, a full world, and a hand a glove drives. */
static int a_hands_kept(void) {
  return frusta_hand_is_valid(g_a.hand[0]) == 1 && frusta_hand_is_valid(g_a.hand[1]) == 1 &&
         frusta_world_step(g_a.world) == FRUSTA_OK && check_world(&g_a);
}

static frusta_result call_destroy_world_hand(RawId id, int* untouched) {
  const frusta_result r = frusta_destroy_world_hand(hand_of_raw(id));
  *untouched = a_hands_kept();
  return r;
}

static void t_destroy_world_hand(void) {
  sweep_ids("frusta_destroy_world_hand", "hand", TO_RAW(g_a.hand[0]), TO_RAW(g_dead_world_hand), 0,
            call_destroy_world_hand);
  what("frusta_destroy_world_hand with a standalone hand");
  int untouched = 1;
  refused(call_destroy_world_hand(TO_RAW(g_hand), &untouched), FRUSTA_ERROR_STALE_ID, "standalone");
  verify(untouched && frusta_hand_is_valid(g_hand) == 1, "a refused call changed something");

  /* destroyed: stale at once, shown until a step applied it, then gone */
  Rig rig;
  frusta_world_def wd = frusta_default_world_def();
  wd.max_hands = 1;
  if (!make_press_rig(&rig, &wd, 1, NULL)) return;
  press(&rig, 4, 0.002, 0.2, 4);
  const frusta_hand_id hand = rig.hand[0];
  frusta_hand_id again;
  const frusta_hand_def hd = frusta_default_hand_def();
  what("frusta_destroy_world_hand, then every call on the hand");
  accepted(frusta_destroy_world_hand(hand));
  refused(frusta_destroy_world_hand(hand), FRUSTA_ERROR_STALE_ID, "hand");
  refused(frusta_world_set_haptic(rig.world, hand, &kIdentity, rig.angles[0], FRUSTA_HAND_JOINT_COUNT),
          FRUSTA_ERROR_STALE_ID, "hand");
  ++g_calls;
  verify(frusta_hand_is_valid(hand) == 0, "still valid");
  frusta_world_hand h;
  accepted(get_hand(rig.world, hand, &h));  /* the latched step shows it still */
  fill(&again, sizeof again);
  refused(frusta_create_world_hand(rig.world, &hd, &again), FRUSTA_ERROR_CAPACITY, "max_hands");
  accepted(frusta_world_step(rig.world));
  refused(frusta_create_world_hand(rig.world, &hd, &again), FRUSTA_ERROR_CAPACITY, "removed");
  verify(is_sentinel(&again, sizeof again), "out_hand written");
  frusta_result r;
  verify(read_state(rig.world, &r).hand_count == 0, "the hand is still in the step");
  refused(get_hand(rig.world, hand, &h), FRUSTA_ERROR_STALE_ID, "hand");
  if (accepted(frusta_create_world_hand(rig.world, &hd, &again))) {
    ++g_calls;
    verify(again.index1 == hand.index1 && again.generation != hand.generation,
           "the new hand is not in the slot of the one destroyed");
    refused(frusta_destroy_world_hand(hand), FRUSTA_ERROR_STALE_ID, "hand");
    ++g_calls;
    verify(frusta_hand_is_valid(again) == 1, "the old id destroyed the new hand");
    /* a glove holds it until it is closed */
    frusta_device_def dd = frusta_default_device_def();
    dd.hand = again;
    frusta_device_id glove;
    if (accepted(frusta_create_device(rig.world, "replay:" FRUSTA_RECORDING_PATH "?speed=1&loop=1", &dd,
                                      &glove))) {
      refused(frusta_destroy_world_hand(again), FRUSTA_ERROR_WRONG_STATE, "glove");
      accepted(frusta_destroy_device(glove));
      accepted(frusta_destroy_world_hand(again));
    }
  }
  destroy_rig(&rig);
}

/* A latched hand's geometry calls, `which` 0 (graphic) or 1 (haptic). */
static int32_t g_which;
static frusta_result hand_segments_call(void* out, int32_t capacity, int32_t* count) {
  return frusta_world_get_hand_segments(g_a.world, g_a.hand[0], g_which, (frusta_segment*)out, capacity,
                                        count);
}
static frusta_result hand_palm_spheres_call(void* out, int32_t capacity, int32_t* count) {
  return frusta_world_get_hand_palm_spheres(g_a.world, g_a.hand[0], g_which, (frusta_sphere*)out,
                                            capacity, count);
}

typedef frusta_result (*HandGeometryCall)(frusta_world_id world, frusta_hand_id hand, int32_t which,
                                          void* out, int32_t capacity, int32_t* count);
static frusta_result segments_of(frusta_world_id world, frusta_hand_id hand, int32_t which, void* out,
                                 int32_t capacity, int32_t* count) {
  return frusta_world_get_hand_segments(world, hand, which, (frusta_segment*)out, capacity, count);
}
static frusta_result palm_spheres_of(frusta_world_id world, frusta_hand_id hand, int32_t which,
                                     void* out, int32_t capacity, int32_t* count) {
  return frusta_world_get_hand_palm_spheres(world, hand, which, (frusta_sphere*)out, capacity, count);
}

static HandGeometryCall g_geometry;
static frusta_result call_geometry_world(RawId id, int* untouched) {
  static frusta_sphere out[4];  /* room for 2 segments */
  int32_t count;
  fill(out, sizeof out);
  fill(&count, sizeof count);
  const frusta_result r = g_geometry(world_of_raw(id), g_a.hand[0], 0, out, 2, &count);
  *untouched = is_sentinel(out, sizeof out) && is_sentinel(&count, sizeof count);
  return r;
}
static frusta_result call_geometry_hand(RawId id, int* untouched) {
  static frusta_sphere out[4];
  int32_t count;
  fill(out, sizeof out);
  fill(&count, sizeof count);
  const frusta_result r = g_geometry(g_a.world, hand_of_raw(id), 1, out, 2, &count);
  *untouched = is_sentinel(out, sizeof out) && is_sentinel(&count, sizeof count);
  return r;
}

/* Every bad world, hand and `which`, the output-array rule for both hands, the calls
 * before a read and on a hand with no input yet; what is copied is finite. */
static void sweep_hand_geometry(const char* label, HandGeometryCall call, ArrayCall array,
                                size_t size, int32_t want_count, int unlatched_case) {
  g_geometry = call;
  sweep_ids(label, "world", TO_RAW(g_a.world), TO_RAW(g_dead_world), 1, call_geometry_world);
  press(&g_a, 4, 0.004, 0.3, 4);
  sweep_world_hand_ids(label, g_a.hand[0], call_geometry_hand);
  int32_t count;
  static frusta_sphere out[4096 + 2];
  for (int i = 0; i < HOSTILE_INT_COUNT + 2; ++i) {
    const int32_t which = i < HOSTILE_INT_COUNT ? kHostileInts[i] : i == HOSTILE_INT_COUNT ? 2 : -2;
    if (which == 0) continue;
    fill(out, sizeof out[0] * 4);
    fill(&count, sizeof count);
    what("%s: which %d", label, which);
    refused(call(g_a.world, g_a.hand[0], which, out, 2, &count), FRUSTA_ERROR_OUT_OF_RANGE, "which");
    verify(is_sentinel(out, sizeof out[0] * 4) && is_sentinel(&count, sizeof count), "out written");
  }
  for (g_which = 0; g_which < 2; ++g_which)
    sweep_output_array(label, array, out, size, want_count + 2, want_count, "out");
  what("%s: what is copied", label);
  for (int32_t which = 0; which < 2; ++which) {
    accepted(call(g_a.world, g_a.hand[1], which, out, want_count, &count));
    verify(count == want_count && all_finite((const double*)out, (size_t)count * size / sizeof(double)),
           "%d elements, or not finite", count);
  }
  unlatched(label, unlatched_case);
  /* a hand with no input has no pose */
  Rig rig;
  const frusta_world_def wd = frusta_default_world_def();
  if (make_rig(&rig, &wd, 1)) {
    frusta_result r;
    frusta_world_step(rig.world);
    read_state(rig.world, &r);
    fill(&count, sizeof count);
    what("%s on a hand with no input", label);
    refused(call(rig.world, rig.hand[0], 0, NULL, 0, &count), FRUSTA_ERROR_WRONG_STATE, "solved");
    verify(is_sentinel(&count, sizeof count), "out_count written");
    destroy_rig(&rig);
  }
}

static void t_world_get_hand_segments(void) {
  sweep_hand_geometry("frusta_world_get_hand_segments", segments_of, hand_segments_call,
                      sizeof(frusta_segment), FRUSTA_HAND_SEGMENT_COUNT, 4);
}

static void t_world_get_hand_palm_spheres(void) {
  int32_t spheres = 0;
  frusta_hand_get_palm_spheres(g_hand, NULL, 0, &spheres);
  sweep_hand_geometry("frusta_world_get_hand_palm_spheres", palm_spheres_of, hand_palm_spheres_call,
                      sizeof(frusta_sphere), spheres, 5);
}

/* frusta_world_get_object_ignored_by: bad worlds, objects and hands, a null out, the
 * calls before a read; g_a's boxes are under its hands, not put inside them: 0. */
static frusta_result call_ignored_world(RawId id, int* untouched) {
  int32_t out;
  fill(&out, sizeof out);
  const frusta_result r = frusta_world_get_object_ignored_by(world_of_raw(id), g_far, g_a.hand[0], &out);
  *untouched = is_sentinel(&out, sizeof out);
  return r;
}
static frusta_result call_ignored_object(RawId id, int* untouched) {
  int32_t out;
  fill(&out, sizeof out);
  const frusta_result r =
      frusta_world_get_object_ignored_by(g_a.world, object_of_raw(id), g_a.hand[0], &out);
  *untouched = is_sentinel(&out, sizeof out);
  return r;
}
static frusta_result call_ignored_hand(RawId id, int* untouched) {
  int32_t out;
  fill(&out, sizeof out);
  const frusta_result r = frusta_world_get_object_ignored_by(g_a.world, g_far, hand_of_raw(id), &out);
  *untouched = is_sentinel(&out, sizeof out);
  return r;
}

static void t_world_get_object_ignored_by(void) {
  g_far = add_far_object();
  check_world(&g_a);
  sweep_ids("frusta_world_get_object_ignored_by", "world", TO_RAW(g_a.world), TO_RAW(g_dead_world), 1,
            call_ignored_world);
  sweep_object_ids("frusta_world_get_object_ignored_by", call_ignored_object);
  sweep_world_hand_ids("frusta_world_get_object_ignored_by", g_a.hand[0], call_ignored_hand);
  what("frusta_world_get_object_ignored_by(world, object, hand, NULL)");
  refused(frusta_world_get_object_ignored_by(g_a.world, g_far, g_a.hand[0], NULL),
          FRUSTA_ERROR_NULL_POINTER, "out_ignored");
  what("frusta_world_get_object_ignored_by: every object and hand of g_a");
  for (int o = 0; o < g_a.objects; ++o)
    for (int h = 0; h < g_a.hands; ++h) {
      int32_t ignored = -1;
      accepted(frusta_world_get_object_ignored_by(g_a.world, g_a.object[o], g_a.hand[h], &ignored));
      verify(ignored == 0, "object %d ignored by hand %d (%d)", o, h, ignored);
    }
  unlatched("frusta_world_get_object_ignored_by", 3);
  frusta_destroy_object(g_far);
  frusta_world_step(g_a.world);
}

/* ------------------------------------------------------------------ devices */

static Rig g_dev;  /* the world the gloves drive: two hands */
static const char kReplayUri[] = "replay:" FRUSTA_RECORDING_PATH "?speed=1&loop=1";
static frusta_device_id g_dead_device;

#define DEVICE_FIELD(member) #member, offsetof(frusta_device_def, member)
static const Field kDeviceFields[] = {
    {DEVICE_FIELD(watchdog_s), 1, 0, NAME_SCALAR, 0.001, 10.0, 0},
    {DEVICE_FIELD(engine_timeout_s), 1, 0, NAME_SCALAR, 0.001, 10.0, 0},
    {DEVICE_FIELD(reconnect_interval_s), 1, 0, NAME_SCALAR, 0.001, 60.0, 0},
    {DEVICE_FIELD(max_force_rate), 1, 0, NAME_SCALAR, 0.0, 1e9, 0},
    {DEVICE_FIELD(max_torque_rate), 1, 0, NAME_SCALAR, 0.0, 1e9, 0},
    {DEVICE_FIELD(max_finger_resistance), 1, 0, NAME_SCALAR, 0.0, 1e9, 0},
    {DEVICE_FIELD(max_fingertip_force), 1, 0, NAME_SCALAR, 0.0, 1e9, 0},
    {DEVICE_FIELD(max_joint_torque), 1, 0, NAME_SCALAR, 0.0, 1e9, 0},
    /* calibration; curl_open and curl_closed must differ, and stay within analog_max */
    {DEVICE_FIELD(curl_open), 15, 3, NAME_ONLY, 0.0, 4095.0, 1},
    {DEVICE_FIELD(curl_closed), 15, 3, NAME_ONLY, 0.0, 4095.0, 1},
    {DEVICE_FIELD(flexion_open), 15, 3, NAME_ONLY, -PI, PI, 0},
    {DEVICE_FIELD(flexion_closed), 15, 3, NAME_ONLY, -PI, PI, 0},
    {DEVICE_FIELD(splay_center), 5, 0, NAME_1D, 0.0, 4095.0, 0},
    {DEVICE_FIELD(splay_span), 5, 0, NAME_1D, 1.0, 4095.0, 0},
    {DEVICE_FIELD(abduction_range), 5, 0, NAME_1D, 0.0, PI / 2, 0},
    {DEVICE_FIELD(brake_full_scale), 1, 0, NAME_SCALAR, DBL_TRUE_MIN, 1e6, 0},  /* > 0 */
    {DEVICE_FIELD(brake_units), 1, 0, NAME_SCALAR, 1.0, 65535.0, 0},
    {DEVICE_FIELD(analog_max), 1, 0, NAME_SCALAR, 1.0, 1e9, 1},
};

static int status_finite(const frusta_device_status* s) {
  int ok = s->state >= 1 && s->state <= 3 && s->watchdog >= 0 && s->watchdog <= 4 && s->outputs >= 0 &&
           s->outputs <= 7 && s->fingers >= 0 && s->fingers <= 5 && (s->has_palm_pose | 1) == 1 &&
           (s->recording_failed | 1) == 1 && s->frames_ok >= 0 && s->frames_corrupt >= 0 &&
           s->frames_truncated >= 0 && s->frames_out_of_range >= 0 && s->samples_rejected >= 0 &&
           s->commands_sent >= 0 && s->commands_dropped >= 0 && s->reconnects >= 0 && s->disconnects >= 0 &&
           s->watchdog_trips >= 0 && isfinite(s->input_rate_hz) && s->input_rate_hz >= 0.0 &&
           isfinite(s->output_rate_hz) && s->output_rate_hz >= 0.0 && isfinite(s->last_sample_age_s) &&
           s->last_sample_age_s >= -1.0 && isfinite(s->max_finger_resistance) &&
           isfinite(s->max_fingertip_force) && isfinite(s->max_joint_torque) &&
           all_finite(s->finger_resistance, 5) && all_finite(&s->fingertip_force[0][0], 15);
  for (int f = 0; ok && f < FRUSTA_FINGER_COUNT; ++f)
    ok = s->finger_resistance[f] >= 0.0 && within(s->finger_resistance[f], s->max_finger_resistance) &&
         within(norm_n(s->fingertip_force[f], 3), s->max_fingertip_force);
  return ok;
}

static int device_status_ok(frusta_device_id device) {
  frusta_device_status s;
  memset(&s, 0, sizeof s);
  s.struct_size = (int32_t)sizeof s;
  if (!verify(frusta_device_get_status(device, &s) == FRUSTA_OK, "get_status: %s", frusta_last_error())) return 0;
  return verify(status_finite(&s), "status: state %d, watchdog %d, rates %g %g, age %g", s.state, s.watchdog,
                s.input_rate_hz, s.output_rate_hz, s.last_sample_age_s);
}

/* An open on g_dev; refused: out_device untouched and the hand still the host's. */
static frusta_result open_device(const char* uri, const frusta_device_def* def, int* untouched) {
  frusta_device_id device;
  fill(&device, sizeof device);
  const frusta_result r = frusta_create_device(g_dev.world, uri, def, &device);
  if (r != FRUSTA_OK) {
    /* the hand asked for (or hand 0 for a bad one) is still the host's: a call that, for
       a good id, succeeds and leaves the refusal's message alone */
    const frusta_hand_id hand =
        def && frusta_hand_is_valid(def->hand) && def->hand.world0 == g_dev.hand[0].world0
            ? def->hand
            : g_dev.hand[0];
    *untouched = is_sentinel(&device, sizeof device) &&
                 frusta_world_set_haptic(g_dev.world, hand, &kIdentity, g_dev.angles[0],
                                         FRUSTA_HAND_JOINT_COUNT) == FRUSTA_OK;
    return r;
  }
  /* used: the glove drives the hand (the host's input is refused) and reports sanely */
  const frusta_hand_id hand = def->hand;
  verify(frusta_device_is_valid(device) == 1, "the device opened is not valid");
  refused(frusta_world_set_haptic(g_dev.world, hand, &kIdentity, g_dev.angles[0], FRUSTA_HAND_JOINT_COUNT),
          FRUSTA_ERROR_WRONG_STATE, "glove");
  frusta_world_step(g_dev.world);
  frusta_result rr;
  read_state(g_dev.world, &rr);
  device_status_ok(device);
  verify(frusta_destroy_device(device) == FRUSTA_OK, "close: %s", frusta_last_error());
  verify(frusta_world_set_haptic(g_dev.world, hand, &kIdentity, g_dev.angles[0], FRUSTA_HAND_JOINT_COUNT) ==
             FRUSTA_OK,
         "the hand is not the host's again after close: %s", frusta_last_error());
  return r;
}

static frusta_result call_open_def(const void* def, int* untouched, void* context) {
  (void)context;
  return open_device(kReplayUri, (const frusta_device_def*)def, untouched);
}

/* A device def for g_dev's hand `hand`. */
static frusta_device_def dev_def(int hand) {
  frusta_device_def def = frusta_default_device_def();
  def.hand = g_dev.hand[hand];
  return def;
}

static frusta_result call_open_hand(RawId id, int* untouched) {
  frusta_device_def def = dev_def(0);
  def.hand = hand_of_raw(id);
  return open_device(kReplayUri, &def, untouched);
}

static frusta_result call_open_world(RawId id, int* untouched) {
  const frusta_device_def def = dev_def(0);
  frusta_device_id device;
  fill(&device, sizeof device);
  const frusta_result r = frusta_create_device(world_of_raw(id), kReplayUri, &def, &device);
  *untouched = is_sentinel(&device, sizeof device);
  return r;
}

static void t_default_device_def(void) {
  const frusta_device_def a = frusta_default_device_def(), b = frusta_default_device_def();
  what("frusta_default_device_def()");
  ++g_calls;
  verify(memcmp(&a, &b, sizeof a) == 0 && a.struct_size == (int32_t)sizeof a && a.internal_value != 0 &&
             all_finite(&a.output_rate_hz, (offsetof(frusta_device_def, internal_value) -
                                            offsetof(frusta_device_def, output_rate_hz)) / sizeof(double)),
         "not a deterministic, finite def of this size with its cookie");
  verify(FRUSTA_IS_NULL(a.hand) && a.reserved1 == 0, "the default def names a hand");
  int untouched = 1;
  what("frusta_create_device with the default def: no hand");
  refused(open_device(kReplayUri, &a, &untouched), FRUSTA_ERROR_NULL_ID, "frusta_device_def.hand");
  verify(untouched, "a refused call changed something");
  frusta_device_def with_hand = a;
  with_hand.hand = g_dev.hand[0];
  what("frusta_create_device with the default def and a hand");
  accepted(open_device(kReplayUri, &with_hand, &untouched));
}

static void t_enumerate_devices(void) {
  frusta_device_info out[4];
  int32_t count;
  fill(&count, sizeof count);
  what("frusta_enumerate_devices(out, 4, NULL)");
  refused(frusta_enumerate_devices(out, 4, NULL), FRUSTA_ERROR_NULL_POINTER, "out_count");
  what("frusta_enumerate_devices(NULL, 4, &count)");
  refused(frusta_enumerate_devices(NULL, 4, &count), FRUSTA_ERROR_NULL_POINTER, "out");
  const int32_t capacities[] = {INT32_MIN, -1};
  for (int i = 0; i < 2; ++i) {
    what("frusta_enumerate_devices: capacity %d", capacities[i]);
    refused(frusta_enumerate_devices(out, capacities[i], &count), FRUSTA_ERROR_OUT_OF_RANGE, "capacity");
    refused(frusta_enumerate_devices(NULL, capacities[i], &count), FRUSTA_ERROR_OUT_OF_RANGE, "capacity");
  }
  verify(is_sentinel(&count, sizeof count), "out_count written by a refused call");
  what("frusta_enumerate_devices size query, then 4");
  int32_t total = -1;
  accepted(frusta_enumerate_devices(NULL, 0, &total));
  fill(out, sizeof out);
  if (accepted(frusta_enumerate_devices(out, 4, &count))) {
    /* how many there are, which may exceed 4; the first min(4, count) written */
    verify(count >= 0 && total >= 0, "%d devices", count);
    for (int k = 0; k < count && k < 4; ++k)
      verify(out[k].kind >= 1 && out[k].kind <= 3 && memchr(out[k].uri, 0, sizeof out[k].uri) != NULL,
             "device %d: kind %d, an unterminated URI", k, out[k].kind);
    for (int k = count; k < 4; ++k)
      verify(is_sentinel(&out[k], sizeof out[k]), "entry %d written beyond the count", k);
  }
}

/* A device def field that is 0 or within [lo, hi]: between 0 and lo is refused. */
static void sweep_zero_or(const frusta_device_def* def, const char* name, size_t offset, double lo, double hi) {
  double values[HOSTILE_COUNT + 5];
  int n = field_values(lo, hi, values);
  values[n++] = 0.0;
  for (int i = 0; i < n; ++i) {
    frusta_device_def d = *def;
    const double v = values[i];
    memcpy((unsigned char*)&d + offset, &v, sizeof v);
    const frusta_result want = !isfinite(v) ? FRUSTA_ERROR_NOT_FINITE
                               : v == 0.0 || (v >= lo && v <= hi) ? FRUSTA_OK : FRUSTA_ERROR_OUT_OF_RANGE;
    what("frusta_create_device: %s = %g", name, v);
    int untouched = 1;
    const frusta_result r = open_device(kReplayUri, &d, &untouched);
    if (want == FRUSTA_OK) accepted(r);
    else refused(r, want, name);
    verify(untouched, "a refused call changed something");
  }
}

static void t_world_open_device(void) {
  sweep_ids("frusta_create_device", "world", TO_RAW(g_dev.world), TO_RAW(g_dead_world), 1,
            call_open_world);
  const frusta_device_def def = dev_def(0);
  frusta_device_id device;
  fill(&device, sizeof device);
  what("frusta_create_device: uri NULL");
  refused(frusta_create_device(g_dev.world, NULL, &def, &device), FRUSTA_ERROR_NULL_POINTER, "uri");
  what("frusta_create_device: def NULL");
  refused(frusta_create_device(g_dev.world, kReplayUri, NULL, &device), FRUSTA_ERROR_NULL_POINTER,
          "def");
  what("frusta_create_device: out_device NULL");
  refused(frusta_create_device(g_dev.world, kReplayUri, &def, NULL), FRUSTA_ERROR_NULL_POINTER,
          "out_device");
  verify(is_sentinel(&device, sizeof device), "out_device written");
  sweep_def_header("frusta_create_device", "frusta_device_def", &def, sizeof def,
                   offsetof(frusta_device_def, internal_value), call_open_def, NULL);
  sweep_fields("frusta_create_device", &def, sizeof def, kDeviceFields,
               (int)(sizeof kDeviceFields / sizeof kDeviceFields[0]), call_open_def, NULL);
  /* 0 (the world's rate; not watched) or within a range */
  sweep_zero_or(&def, "output_rate_hz", offsetof(frusta_device_def, output_rate_hz), 1.0, 100000.0);
  sweep_zero_or(&def, "host_timeout_s", offsetof(frusta_device_def, host_timeout_s), 0.001, 60.0);
  sweep_world_hand_ids("frusta_create_device: def.hand", g_dev.hand[0], call_open_hand);
  /* URIs that fail at once: malformed, absent, not a glove */
  static char long_uri[10240], long_scheme[10240];
  snprintf(long_uri, sizeof long_uri, "serial:/");
  memset(long_uri + 8, 'u', sizeof long_uri - 9);
  memset(long_scheme, 's', sizeof long_scheme - 1);
  const struct {
    const char* uri;
    frusta_result want, or_want;
    const char* field;
  } uris[] = {
      {"", FRUSTA_ERROR_OUT_OF_RANGE, 0, "URI"},
      {"serial", FRUSTA_ERROR_OUT_OF_RANGE, 0, "scheme"},
      {"bogus:/dev/null", FRUSTA_ERROR_OUT_OF_RANGE, 0, "scheme"},
      {"SERIAL:/dev/null", FRUSTA_ERROR_OUT_OF_RANGE, 0, "scheme"},
      {"serial:", FRUSTA_ERROR_OUT_OF_RANGE, 0, "path"},
      {"serial:?baud=9600", FRUSTA_ERROR_OUT_OF_RANGE, 0, "path"},
      {"serial:/no/such/tty", FRUSTA_ERROR_IO, 0, "/no/such/tty"},
      {"opengloves:/no/such/tty?baud=115200", FRUSTA_ERROR_IO, 0, "/no/such/tty"},
      {"serial:/dev/null", FRUSTA_ERROR_IO, 0, "/dev/null"},
      {"serial:/x?baud=", FRUSTA_ERROR_OUT_OF_RANGE, 0, "baud"},
      {"serial:/x?baud=abc", FRUSTA_ERROR_OUT_OF_RANGE, 0, "baud"},
      {"serial:/x?baud=-1", FRUSTA_ERROR_OUT_OF_RANGE, 0, "baud"},
      {"serial:/x?baud=0", FRUSTA_ERROR_OUT_OF_RANGE, 0, "baud"},
      {"serial:/x?baud=1e6", FRUSTA_ERROR_OUT_OF_RANGE, 0, "baud"},
      {"serial:/x?baud=99999999999999999999999", FRUSTA_ERROR_OUT_OF_RANGE, 0, "baud"},
      {"serial:/x?baud=4294967296", FRUSTA_ERROR_OUT_OF_RANGE, 0, "baud"},
      {"serial:/x?baud=4295082496", FRUSTA_ERROR_OUT_OF_RANGE, 0, "baud"},  /* 2^32 + 115200 */
      {"serial:/x?bogus=1", FRUSTA_ERROR_OUT_OF_RANGE, 0, "parameter"},
      {"serial:/x?=", FRUSTA_ERROR_OUT_OF_RANGE, 0, "parameter"},
      {"serial:/x?&&", FRUSTA_ERROR_OUT_OF_RANGE, 0, "parameter"},
      {"serial:/x?baud", FRUSTA_ERROR_OUT_OF_RANGE, 0, "parameter"},
      {"serial:/x?speed=max", FRUSTA_ERROR_OUT_OF_RANGE, 0, "parameter"},
      {"replay:/x?speed=2", FRUSTA_ERROR_OUT_OF_RANGE, 0, "parameter"},
      {"replay:/x?loop=yes", FRUSTA_ERROR_OUT_OF_RANGE, 0, "parameter"},
      {"replay:/x?baud=9600", FRUSTA_ERROR_OUT_OF_RANGE, 0, "parameter"},
      {"hid:", FRUSTA_ERROR_OUT_OF_RANGE, 0, "path"},
      {"hid:1209", FRUSTA_ERROR_OUT_OF_RANGE, 0, "hid:VID:PID"},
      {"hid::", FRUSTA_ERROR_OUT_OF_RANGE, 0, "hid:VID:PID"},
      {"hid:zzzz:1", FRUSTA_ERROR_OUT_OF_RANGE, 0, "hid:VID:PID"},
      {"hid:12345:1", FRUSTA_ERROR_OUT_OF_RANGE, 0, "hid:VID:PID"},
      {"hid:-1:-1", FRUSTA_ERROR_OUT_OF_RANGE, 0, "hid:VID:PID"},
      {"hid:ffff:fffe", FRUSTA_ERROR_IO, FRUSTA_ERROR_UNAVAILABLE, "hid"},
      {"hid:ffff:fffe:\x01\x02", FRUSTA_ERROR_IO, FRUSTA_ERROR_UNAVAILABLE, "hid"},
      {"replay:/no/such/recording", FRUSTA_ERROR_IO, 0, "/no/such/recording"},
      {"replay:/dev/zero", FRUSTA_ERROR_IO, FRUSTA_ERROR_FILE_FORMAT, "/dev/zero"},
      {"replay:.", FRUSTA_ERROR_IO, FRUSTA_ERROR_FILE_FORMAT, "."},
      {"replay:" FRUSTA_HEADER_PATH, FRUSTA_ERROR_FILE_FORMAT, FRUSTA_ERROR_IO, "frusta.h"},
      {"replay:" FRUSTA_RECORDING_PATH "?record=/no/such/dir/rec", FRUSTA_ERROR_IO, 0, "/no/such/dir/rec"},
      {"serial:/dev/\x01\x02\n", FRUSTA_ERROR_IO, 0, "serial"},
      {"replay:\t\n", FRUSTA_ERROR_IO, 0, "recording"},
      {long_uri, FRUSTA_ERROR_IO, 0, "uuuu"},
      {long_scheme, FRUSTA_ERROR_OUT_OF_RANGE, 0, "URI"},
  };
  for (size_t i = 0; i < sizeof uris / sizeof uris[0]; ++i) {
    what("frusta_create_device(\"%.40s\")", uris[i].uri);
    int untouched = 1;
    const frusta_result r = open_device(uris[i].uri, &def, &untouched);
    refused(r, uris[i].or_want && r == uris[i].or_want ? uris[i].or_want : uris[i].want, uris[i].field);
    verify(untouched, "out_device written, or the hand left to a glove");
  }
  /* a 10 KB URI with a bad parameter at its end: the reason survives the long quote */
  static char long_query[10240];
  memset(long_query, 'u', sizeof long_query - 1);
  memcpy(long_query, "serial:/", 8);
  memcpy(long_query + sizeof long_query - 9, "?bogus=1", 8);
  what("frusta_create_device(10 KB URI ending in ?bogus=1)");
  {
    int untouched = 1;
    refused(open_device(long_query, &def, &untouched), FRUSTA_ERROR_OUT_OF_RANGE, "unknown parameter");
    verify(untouched, "out_device written, or the hand left to a glove");
  }
  /* a recording of its own input: refused, and the input survives it */
  long size = 0, after = 0;
  unsigned char* recording = read_file(FRUSTA_RECORDING_PATH, &size);
  if (verify(recording && write_file("hostile_abi_test.frrec", recording, size), "copy the recording")) {
    what("frusta_create_device(\"replay:R?record=R\")");
    int untouched = 1;
    const frusta_result r = open_device("replay:hostile_abi_test.frrec?speed=max&record=hostile_abi_test.frrec",
                                        &def, &untouched);
    refused(r, FRUSTA_ERROR_OUT_OF_RANGE, "record=hostile_abi_test.frrec");
    free(read_file("hostile_abi_test.frrec", &after));
    verify(after == size && untouched, "the recording replayed went from %ld to %ld bytes", size, after);
    remove("hostile_abi_test.frrec");
  }
  free(recording);
  /* one glove per hand */
  what("frusta_create_device twice on hand 0");
  frusta_device_id first;
  if (accepted(frusta_create_device(g_dev.world, kReplayUri, &def, &first))) {
    fill(&device, sizeof device);
    refused(frusta_create_device(g_dev.world, kReplayUri, &def, &device), FRUSTA_ERROR_WRONG_STATE,
            "hand 0");
    verify(is_sentinel(&device, sizeof device) && frusta_device_is_valid(first) == 1, "the first glove is gone");
    accepted(frusta_destroy_device(first));
  }
}

static frusta_device_id g_glove;  /* open on g_dev's hand 1 during the device id sweeps */

static frusta_result call_close_id(RawId id, int* untouched) {
  const frusta_result r = frusta_destroy_device(device_of_raw(id));
  *untouched = frusta_device_is_valid(g_glove) == 1;
  return r;
}

static int32_t valid_device(RawId id) { return frusta_device_is_valid(device_of_raw(id)); }

static frusta_result call_status_id(RawId id, int* untouched) {
  frusta_device_status s;
  fill(&s, sizeof s);
  s.struct_size = (int32_t)sizeof s;
  const frusta_result r = frusta_device_get_status(device_of_raw(id), &s);
  *untouched = is_sentinel((char*)&s + 4, sizeof s - 4);
  return r;
}

static frusta_result status_out(void* out) {
  return frusta_device_get_status(g_glove, (frusta_device_status*)out);
}

static frusta_result call_palm_id(RawId id, int* untouched) {
  *untouched = 1;
  return frusta_device_set_palm_pose(device_of_raw(id), &kIdentity);
}

static frusta_result call_palm(const void* pose, int* untouched, void* context) {
  (void)context;
  *untouched = 1;
  const frusta_result r = frusta_device_set_palm_pose(g_glove, (const frusta_pose*)pose);
  if (r == FRUSTA_OK) {
    frusta_world_step(g_dev.world);
    check_world(&g_dev);
  }
  return r;
}

static int open_glove(void) {
  const frusta_device_def def = dev_def(1);
  return verify(frusta_create_device(g_dev.world, kReplayUri, &def, &g_glove) == FRUSTA_OK,
                "open the glove: %s", frusta_last_error());
}

static void t_device_close(void) {
  if (!open_glove()) return;
  sweep_ids("frusta_destroy_device", "device", TO_RAW(g_glove), TO_RAW(g_dead_device), 0,
            call_close_id);
  what("frusta_destroy_device, then again");
  accepted(frusta_destroy_device(g_glove));
  refused(frusta_destroy_device(g_glove), FRUSTA_ERROR_STALE_ID, "device");
}

static void t_device_is_valid(void) {
  if (!open_glove()) return;
  sweep_valid("frusta_device_is_valid", TO_RAW(g_glove), TO_RAW(g_dead_device), 0, valid_device);
  frusta_destroy_device(g_glove);
}

static void t_device_get_status(void) {
  if (!open_glove()) return;
  sweep_ids("frusta_device_get_status", "device", TO_RAW(g_glove), TO_RAW(g_dead_device), 0, call_status_id);
  what("frusta_device_get_status(device, NULL)");
  refused(frusta_device_get_status(g_glove, NULL), FRUSTA_ERROR_NULL_POINTER, "out");
  sweep_out_size("frusta_device_get_status", "frusta_device_status", sizeof(frusta_device_status), status_out);
  what("frusta_device_get_status while the world steps");
  for (int i = 0; i < 20; ++i) {
    frusta_world_step(g_dev.world);
    check_world(&g_dev);
    device_status_ok(g_glove);
  }
  frusta_destroy_device(g_glove);
}

static void t_device_set_palm_pose(void) {
  if (!open_glove()) return;
  sweep_ids("frusta_device_set_palm_pose", "device", TO_RAW(g_glove), TO_RAW(g_dead_device), 0, call_palm_id);
  what("frusta_device_set_palm_pose(device, NULL)");
  refused(frusta_device_set_palm_pose(g_glove, NULL), FRUSTA_ERROR_NULL_POINTER, "palm");
  sweep_pose("frusta_device_set_palm_pose", "palm", call_palm, NULL);
  frusta_destroy_device(g_glove);
}

static int device_setup(void) {
  const frusta_world_def def = frusta_default_world_def();
  if (!make_press_rig(&g_dev, &def, 2, NULL)) return 0;
  const frusta_device_def dd = dev_def(0);
  return verify(frusta_create_device(g_dev.world, kReplayUri, &dd, &g_dead_device) == FRUSTA_OK &&
                    frusta_destroy_device(g_dead_device) == FRUSTA_OK,
                "open and close a glove: %s", frusta_last_error());
}

/* ------------------------------------------------------------------ extremes */

/* Presses both hands into boxes of `def` in a world of `wd`, n steps, and checks. */
static void press_boxes(const char* label, const frusta_world_def* wd, const frusta_object_def* def, int n) {
  Rig rig;
  what("%s", label);
  if (make_press_rig(&rig, wd, 2, def)) press(&rig, n, 0.004, FRUSTA_MAX_JOINT_ANGLE, 5);
  destroy_rig(&rig);
}

static void s_extreme_objects(void) {
  const frusta_world_def wd = frusta_default_world_def();
  const frusta_object_def base = frusta_default_object_def();
  char label[160];
  for (int fi = 0; fi < OBJECT_FIELD_COUNT; ++fi) {
    const Field* f = &kObjectFields[fi];
    for (int end = 0; end < 2; ++end) {
      for (int dynamic = 0; dynamic < 2; ++dynamic) {
        frusta_object_def def = base;
        def.dynamic = dynamic;
        const double v = end ? f->hi : f->lo;
        /* inertia: all three at once (each at most the sum of the others); the rest
         * element 0 alone */
        const int count = f->cross ? f->count : 1;
        for (int e = 0; e < count; ++e)
          memcpy((unsigned char*)&def + f->offset + (size_t)e * sizeof(double), &v, sizeof v);
        snprintf(label, sizeof label, "hands pressing %s boxes, %s = %g", dynamic ? "dynamic" : "kinematic",
                 f->name, v);
        press_boxes(label, &wd, &def, 16);
      }
    }
  }
  /* every extreme at once */
  frusta_object_def light = base;
  light.dynamic = 1;
  light.mass = 1e-6;
  light.inertia[0] = light.inertia[1] = light.inertia[2] = 1e-13;
  light.stiffness[0] = light.stiffness[1] = light.stiffness[2] = 1e9;
  light.tangential_stiffness = light.normal_damping = light.tangential_damping = 1e9;
  light.friction = 100.0;
  frusta_world_def heavy_gravity = wd;
  heavy_gravity.gravity[2] = -1e3;
  press_boxes("the lightest, stiffest, most damped dynamic boxes, gravity 1e3", &heavy_gravity, &light, 40);
  light.dynamic = 0;
  press_boxes("the same boxes kinematic", &wd, &light, 40);
  light.dynamic = 1;
  frusta_world_def slow = heavy_gravity;
  slow.rate_hz = 1.0;
  slow.spin_us = 0.0;
  press_boxes("the lightest, stiffest boxes at 1 Hz", &slow, &light, 40);
  frusta_world_def fast = heavy_gravity;
  fast.rate_hz = 100000.0;
  fast.spin_us = 0.0;
  press_boxes("the lightest, stiffest boxes at 100 kHz", &fast, &light, 40);
  frusta_object_def heavy = base;
  heavy.dynamic = 1;
  heavy.mass = 1e4;
  heavy.inertia[0] = heavy.inertia[1] = heavy.inertia[2] = 1e4;
  heavy.stiffness[0] = heavy.stiffness[1] = heavy.stiffness[2] = 0.0;
  heavy.friction = heavy.tangential_stiffness = 0.0;
  press_boxes("the heaviest, softest dynamic boxes", &heavy_gravity, &heavy, 40);
  /* a needle: one principal moment 1e17 times the others, turned off the axes */
  frusta_object_def needle = light;
  needle.inertia[0] = 1e-13;
  needle.inertia[1] = needle.inertia[2] = 1e4;
  needle.pose.rotation[0] = needle.pose.rotation[1] = needle.pose.rotation[2] = 0.5;
  needle.pose.rotation[3] = 0.5;
  needle.angular_velocity[0] = 1000.0;
  needle.angular_velocity[1] = -1000.0;
  press_boxes("needle-like dynamic boxes (inertia 1e-13, 1e4, 1e4), turned and spinning", &wd, &needle, 40);
  press_boxes("needle-like boxes at 1 Hz", &slow, &needle, 40);
  frusta_object_def flung = base;
  flung.dynamic = 1;
  flung.linear_velocity[0] = flung.linear_velocity[2] = 100.0;
  flung.linear_velocity[1] = -100.0;
  flung.angular_velocity[0] = flung.angular_velocity[2] = 1000.0;
  flung.angular_velocity[1] = -1000.0;
  press_boxes("dynamic boxes flung at 100 m/s and 1000 rad/s", &heavy_gravity, &flung, 40);
  flung.linear_damping = flung.angular_damping = 1000.0;
  press_boxes("flung boxes damped at 1000/s, at 1 Hz", &slow, &flung, 40);
}

/* Hands of every size the def allows, pressing a box with fingers curled past 4 pi. */
static void s_extreme_hands(void) {
  /* sized hands from small to large, and every part at its limits at once */
  const double sizes[][2] = {{0.04, 0.02}, {0.05, 0.05}, {5.0, 5.0}, {5.0, 0.5}, {0.5, 0.5}};
  for (int i = 0; i < 7; ++i) {
    frusta_hand_def hd = frusta_default_hand_def();
    if (i < 5) {
      what("a hand %g x %g m pressing a box", sizes[i][0], sizes[i][1]);
      if (!accepted(frusta_hand_def_set_size(&hd, sizes[i][0], sizes[i][1]))) continue;
    } else {
      hd = extreme_hand_def(i == 6);
      what("a hand with every part %s pressing a box", i == 6 ? "5 m" : "1e-4 m");
    }
    frusta_hand_id hand;
    frusta_segment segments[FRUSTA_HAND_SEGMENT_COUNT];
    int32_t count;
    if (!accepted(frusta_create_hand(&hd, &hand))) continue;
    frusta_hand_get_segments(hand, segments, FRUSTA_HAND_SEGMENT_COUNT, &count);
    frusta_destroy_hand(hand);
    const frusta_segment tip = segments[FRUSTA_FINGER_INDEX * FRUSTA_SEGMENTS_PER_FINGER + 2];
    frusta_world_def wd = frusta_default_world_def();
    wd.prediction_margin = 1e-5;  /* below the smallest finger radius of any def */
    Rig rig;
    if (!make_rig(&rig, &wd, 0)) continue;
    if (accepted(frusta_create_world_hand(rig.world, &hd, &rig.hand[0]))) {
      rig.hands = 1;
      rig.palm[0] = kIdentity;
      frusta_object_def box = frusta_default_object_def();
      box.pose.position[0] = tip.distal[0] - 0.01;
      box.pose.position[1] = tip.distal[1];
      box.pose.position[2] = tip.distal[2] - tip.distal_radius - 0.015;
      if (add_rig_object(&rig, g_box, &box)) press(&rig, 30, 0.004, FRUSTA_MAX_JOINT_ANGLE, 5);
    }
    destroy_rig(&rig);
  }
}

/* A world filled to its 65535 objects; 10^5 adds in all, the rest refused cleanly. */
static void s_capacity(void) {
  frusta_world_def wd = frusta_default_world_def();
  wd.max_objects = 65535;
  wd.command_capacity = 1 << 17;
  Rig rig;
  what("a world of 65535 objects");
  if (!make_press_rig(&rig, &wd, 2, NULL)) return;
  frusta_object_def def = frusta_default_object_def();
  static frusta_object_id objects[65535];
  int added = 0, refused_ok = 1, refused_count = 0;
  for (int i = 0; i < 100000 - 2; ++i) {
    def.pose.position[0] = 2.0 + 0.05 * (i % 256);
    def.pose.position[1] = 0.05 * (i / 256);
    def.pose.position[2] = -1.0;
    frusta_object_id object;
    fill(&object, sizeof object);
    const frusta_result r = frusta_create_object(rig.world, g_box, &def, &object);
    if (added < 65535 - 2) {
      if (!accepted(r)) break;
      objects[added++] = object;
    } else {
      ++g_calls;
      ++refused_count;
      refused_ok &= r == FRUSTA_ERROR_CAPACITY && contains(frusta_last_error(), "max_objects") &&
                    is_sentinel(&object, sizeof object);
    }
  }
  verify(added == 65535 - 2 && refused_ok && refused_count == 100000 - 65535,
         "%d added, %d refused (cleanly: %d)", added, refused_count, refused_ok);
  what("the full world stepped with both hands pressing");
  press(&rig, 4, 0.004, 0.5, 2);
  frusta_result r;
  const frusta_world_state s = read_state(rig.world, &r);
  verify(r == FRUSTA_OK && s.object_count == 65535, "%d objects present", s.object_count);
  int placed = 1;
  for (int i = 0; i < added; ++i) {
    frusta_object_state o;
    placed &= get_object(rig.world, objects[i], &o) == FRUSTA_OK && o.pose.position[0] == 2.0 + 0.05 * (i % 256) &&
              o.pose.position[1] == 0.05 * (i / 256) && o.pose.position[2] == -1.0;
  }
  verify(placed, "an object is missing or misplaced");
  what("every object removed, then one added");
  int removed = 1;
  for (int i = 0; i < added; ++i) removed &= frusta_destroy_object(objects[i]) == FRUSTA_OK;
  verify(removed && objects_after_step(rig.world) == 2, "not two objects left");
  accepted(frusta_create_object(rig.world, g_box, &def, &objects[0]));
  verify(objects_after_step(rig.world) == 3, "not three objects");
  destroy_rig(&rig);
}

/* Both hands lie on a 1 x 1 m plate of 10^6 leaves, press and slide for 300 steps; then
 * the plate is handed to the dynamics. */
static void s_million_leaves(void) {
  const frusta_world_def wd = frusta_default_world_def();
  Rig rig;
  what("two hands on a plate of 10^6 leaves");
  if (!make_rig(&rig, &wd, 2)) return;
  frusta_object_def plate = frusta_default_object_def();
  plate.pose.position[0] = 0.1;
  plate.pose.position[1] = 0.5 * LEFT_Y;
  plate.pose.position[2] = g_tip.distal[2] - g_tip.distal_radius - 0.001;
  if (!add_rig_object(&rig, g_plate, &plate)) return;
  press(&rig, 300, 0.004, 0.4, 25);
  what("the plate made dynamic under the hands");
  accepted(frusta_world_set_object_dynamic(rig.world, rig.object[0], 1));
  press(&rig, 20, 0.004, 0.4, 5);
  destroy_rig(&rig);
}

/* Ids outlive their world by 256 generations of its slot: a world destroyed and its slot
 * reused until the new world's generation has the old one's low byte (all an object's
 * or a glove's world0 holds). The old world's object and glove ids must stay stale. */
static void s_reused_slot(void) {
  const frusta_world_def wd = frusta_default_world_def();
  Rig old;
  what("ids of a world whose slot was reused 256 times");
  if (!make_press_rig(&old, &wd, 1, NULL)) return;
  frusta_device_def dd = frusta_default_device_def();
  dd.hand = old.hand[0];
  frusta_device_id old_glove;
  if (!accepted(frusta_create_device(old.world, kReplayUri, &dd, &old_glove))) return;
  const frusta_world_id old_world = old.world;
  const frusta_object_id old_object = old.object[0];
  const frusta_hand_id old_hand = old.hand[0];
  destroy_rig(&old);
  frusta_world_id world = {0, 0, 0};
  for (int i = 0; i < 1000; ++i) {
    if (frusta_create_world(&wd, &world) != FRUSTA_OK) break;
    if (world.index1 == old_world.index1 && (world.generation & 0xff) == (old_world.generation & 0xff) &&
        world.generation != old_world.generation)
      break;
    frusta_destroy_world(world);
    world.index1 = 0;
  }
  if (!verify(world.index1 == old_world.index1, "the slot was not reused")) return;
  Rig rig;
  memset(&rig, 0, sizeof rig);
  rig.world = world;
  rig.def = wd;
  frusta_hand_def hd = frusta_default_hand_def();
  frusta_object_def box = box_under_tip(0, 0.0);
  frusta_device_id glove;
  if (accepted(frusta_create_world_hand(world, &hd, &rig.hand[0])) &&
      add_rig_object(&rig, g_box, &box) && (dd.hand = rig.hand[0], 1) &&
      accepted(frusta_create_device(world, kReplayUri, &dd, &glove))) {
    rig.hands = 1;
    /* the old world's hand: same index and world0, an older generation */
    ++g_calls;
    verify(old_hand.index1 == rig.hand[0].index1 && old_hand.world0 == rig.hand[0].world0 &&
               frusta_hand_is_valid(old_hand) == 0,
           "the old world's hand id names the new world's hand");
    frusta_world_hand wh;
    refused(get_hand(world, old_hand, &wh), FRUSTA_ERROR_STALE_ID, "hand");
    refused(frusta_world_set_haptic(world, old_hand, &kIdentity, rig.angles[0],
                                    FRUSTA_HAND_JOINT_COUNT),
            FRUSTA_ERROR_STALE_ID, "hand");
    frusta_world_step(world);
    frusta_result r;
    read_state(world, &r);
    frusta_object_state o;
    refused(get_object(world, old_object, &o), FRUSTA_ERROR_STALE_ID, "object");
    refused(frusta_world_set_object_pose(world, old_object, &kIdentity), FRUSTA_ERROR_STALE_ID, "object");
    refused(frusta_destroy_object(old_object), FRUSTA_ERROR_STALE_ID, "object");
    accepted(get_object(world, rig.object[0], &o));
    ++g_calls;
    verify(frusta_device_is_valid(old_glove) == 0, "the old glove's id names the new glove");
    frusta_device_status s;
    memset(&s, 0, sizeof s);
    s.struct_size = (int32_t)sizeof s;
    refused(frusta_device_get_status(old_glove, &s), FRUSTA_ERROR_STALE_ID, "device");
    refused(frusta_device_set_palm_pose(old_glove, &kIdentity), FRUSTA_ERROR_STALE_ID, "device");
    refused(frusta_destroy_device(old_glove), FRUSTA_ERROR_STALE_ID, "device");
    verify(frusta_device_is_valid(glove) == 1, "the new glove was closed through the old id");
    frusta_destroy_device(glove);
  }
  destroy_rig(&rig);
}

/* A world on its own thread at 100 kHz while the host feeds it good and bad input,
 * adds and removes objects and reads it; stopped, it steps from the last good input. */
static void s_running(void) {
  frusta_world_def wd = frusta_default_world_def();
  wd.rate_hz = 100000.0;
  wd.spin_us = 0.0;
  Rig rig;
  what("a world running at 100 kHz under hostile calls");
  /* a step first: the hands are in from it on */
  if (!make_press_rig(&rig, &wd, 2, NULL) || !accepted(frusta_world_step(rig.world)) ||
      !accepted(frusta_world_start(rig.world))) {
    destroy_rig(&rig);
    return;
  }
  frusta_object_def far = frusta_default_object_def();
  far.pose.position[2] = -1.0;
  frusta_object_id extra = {0, 0, 0};
  const double bad[FRUSTA_HAND_JOINT_COUNT] = {NAN};
  for (int i = 0; i <= 400; ++i) {
    for (int h = 0; h < 2; ++h) {
      frusta_pose palm;
      double angles[FRUSTA_HAND_JOINT_COUNT];
      press_input(h, i, 400, 0.004, 0.5, &palm, angles);
      if (!accepted(set_input(&rig, h, &palm, angles))) break;
      refused(frusta_world_set_haptic(rig.world, rig.hand[h], &palm, bad, FRUSTA_HAND_JOINT_COUNT),
              FRUSTA_ERROR_NOT_FINITE, "angles[0]");
    }
    refused(frusta_world_step(rig.world), FRUSTA_ERROR_WRONG_STATE, "");
    if (i % 50 == 0) {
      if (extra.index1 != 0) accepted(frusta_destroy_object(extra));
      extra.index1 = 0;
      if (accepted(frusta_create_object(rig.world, g_box, &far, &extra)) == 0) extra.index1 = 0;
      frusta_result r;
      read_state(rig.world, &r);
      accepted(r);
    }
    if (i % 20 == 0) {
      /* the objects are there once the thread has stepped, which it may not have yet */
      Rig running = rig;
      running.objects = 0;
      check_world(&running);
    }
  }
  accepted(frusta_world_stop(rig.world));
  accepted(frusta_world_step(rig.world));
  check_world(&rig);
  inputs_used(&rig);
  destroy_rig(&rig);
}

/* ------------------------------------------------------------------ tracked hands */

static frusta_hand_fitter_id g_fitter;      /* a fitter of the default hand, XR layout */
static frusta_hand_fitter_id g_dead_fitter; /* created, then destroyed */
static frusta_tracked_joint g_joints[FRUSTA_XR_JOINT_COUNT]; /* the default hand, posed */
static frusta_hand_fit g_fit;               /* g_fitter's fit of g_joints */
#define CALIBRATION_FRAMES 3
static frusta_tracked_joint g_frames[CALIBRATION_FRAMES * FRUSTA_XR_JOINT_COUNT];

static frusta_hand_fitter_id fitter_of_raw(RawId r) {
  return (frusta_hand_fitter_id){r.index1, r.world0, r.generation};
}

/* The default hand's joints of a layout at a pose: the palm turned and moved, fingers
 * bent by `bend` (clamped into the limits). */
static frusta_result posed_joints(int32_t layout, double bend, frusta_tracked_joint* out) {
  const frusta_hand_def def = frusta_default_hand_def();
  frusta_pose palm = {{0.1, -0.2, 0.3}, {0.1, 0.2, 0.3, 0.9}};
  const double n = norm_n(palm.rotation, 4);
  for (int k = 0; k < 4; ++k) palm.rotation[k] /= n;
  double angles[FRUSTA_HAND_JOINT_COUNT];
  for (int j = 0; j < FRUSTA_HAND_JOINT_COUNT; ++j) angles[j] = j % 4 == 0 ? 0.1 * bend : bend;
  int32_t count = 0;
  return frusta_hand_joints_from_pose(&def, layout, &palm, angles, FRUSTA_HAND_JOINT_COUNT, out,
                                      FRUSTA_XR_JOINT_COUNT, &count);
}

static int tracking_setup(void) {
  what("tracked-hand fixtures");
  const frusta_hand_def hd = frusta_default_hand_def();
  const frusta_hand_fit_def fd = frusta_default_hand_fit_def();
  memset(&g_fit, 0, sizeof g_fit);
  g_fit.struct_size = (int32_t)sizeof g_fit;
  int ok = frusta_create_hand_fitter(&hd, &fd, &g_fitter) == FRUSTA_OK &&
           frusta_create_hand_fitter(&hd, &fd, &g_dead_fitter) == FRUSTA_OK &&
           frusta_destroy_hand_fitter(g_dead_fitter) == FRUSTA_OK &&
           posed_joints(FRUSTA_JOINT_LAYOUT_XR, 0.4, g_joints) == FRUSTA_OK &&
           frusta_hand_fitter_fit(g_fitter, g_joints, FRUSTA_XR_JOINT_COUNT, NULL, &g_fit) == FRUSTA_OK;
  for (int f = 0; ok && f < CALIBRATION_FRAMES; ++f)
    ok = posed_joints(FRUSTA_JOINT_LAYOUT_XR, 0.3 * f, g_frames + f * FRUSTA_XR_JOINT_COUNT) == FRUSTA_OK;
  return verify(ok, "fitters and joints: %s", frusta_last_error());
}

/* What a fit reports is finite, its palm a unit quaternion, its angles within the
 * default hand's limits and its flags frusta_fit_flag's. */
static int fit_sane(const frusta_hand_fit* fit) {
  const frusta_hand_def def = frusta_default_hand_def();
  int ok = all_finite(fit->palm.position, 3) && unit_quaternion(fit->palm.rotation) &&
           isfinite(fit->palm_residual) && fit->palm_residual >= 0.0 && fit->palm_flags >= 0 &&
           fit->palm_flags < 32;
  for (int j = 0; j < FRUSTA_HAND_JOINT_COUNT; ++j)
    ok &= fit->angles[j] >= def.joint_min[j / 4][j % 4] && fit->angles[j] <= def.joint_max[j / 4][j % 4];
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    ok &= isfinite(fit->finger_residual[f]) && fit->finger_residual[f] >= 0.0 &&
          fit->finger_flags[f] >= 0 && fit->finger_flags[f] < 32;
  return verify(ok, "an accepted fit is not finite, unit and within the limits");
}

/* g_fitter's last good fit is g_fit's again (a fit of g_joints restores it). */
static void restore_fitter(void) {
  frusta_hand_fit fit = g_fit;
  frusta_hand_fitter_fit(g_fitter, g_joints, FRUSTA_XR_JOINT_COUNT, NULL, &fit);
}

/* g_fitter's history is g_fit: a sample with every joint missing gives it back, held. */
static int fitter_history_kept(void) {
  frusta_tracked_joint none[FRUSTA_XR_JOINT_COUNT];
  memset(none, 0, sizeof none);
  frusta_hand_fit held;
  memset(&held, 0, sizeof held);
  held.struct_size = (int32_t)sizeof held;
  return frusta_hand_fitter_fit(g_fitter, none, FRUSTA_XR_JOINT_COUNT, NULL, &held) == FRUSTA_OK &&
         held.palm_flags == FRUSTA_FIT_HELD &&
         memcmp(&held.palm, &g_fit.palm, sizeof held.palm) == 0 &&
         memcmp(held.angles, g_fit.angles, sizeof held.angles) == 0;
}

/* Every field of joint `index` of a sample (its flags all set) at the hostile values and
 * its limits; fields a flag does not declare valid, and the flags, too. */
typedef frusta_result (*JointsCall)(const frusta_tracked_joint* joints, int* untouched, void* context);
#define MAX_JOINTS (CALIBRATION_FRAMES * FRUSTA_XR_JOINT_COUNT)

static void sweep_joint(const char* label, const char* array, const frusta_tracked_joint* base,
                        int count, int index, JointsCall call, void* context) {
  static frusta_tracked_joint joints[MAX_JOINTS];
  char field[96];
  if (!verify(count <= MAX_JOINTS, "%d joints", count)) return;
  for (int part = 0; part < 8; ++part) {
    double values[HOSTILE_COUNT + 4];
    /* position (within 1e6 m), rotation (norm in [0.5, 2]), radius (0..5 m) */
    const int n = part < 3 ? field_values(-1e6, 1e6, values)
                  : part < 7 ? field_values(0.5, 2.0, values)
                             : field_values(0.0, 5.0, values);
    for (int i = 0; i < n; ++i) {
      memcpy(joints, base, sizeof joints[0] * (size_t)count);
      frusta_tracked_joint* j = &joints[index];
      j->flags = 15;
      frusta_result want;
      if (part < 3) {
        j->position[part] = values[i];
        snprintf(field, sizeof field, "%s[%d].position", array, index);
        want = want_for(values[i], -1e6, 1e6);
      } else if (part < 7) {
        const double identity[4] = {0.0, 0.0, 0.0, 1.0};
        memcpy(j->rotation, identity, sizeof identity);
        j->rotation[part - 3] = values[i];
        snprintf(field, sizeof field, "%s[%d].rotation", array, index);
        const double norm = norm_n(j->rotation, 4);
        want = !isfinite(values[i]) ? FRUSTA_ERROR_NOT_FINITE
               : norm >= 0.5 && norm <= 2.0 ? FRUSTA_OK : FRUSTA_ERROR_OUT_OF_RANGE;
      } else {
        j->radius = values[i];
        snprintf(field, sizeof field, "%s[%d].radius", array, index);
        want = want_for(values[i], 0.0, 5.0);
      }
      what("%s: %s = %g", label, field, values[i]);
      int untouched = 1;
      const frusta_result got = call(joints, &untouched, context);
      if (want == FRUSTA_OK) accepted(got);
      else refused(got, want, field);
      if (got != FRUSTA_OK) verify(untouched, "a refused call changed something");
      /* the same value where no flag declares the field valid: not read */
      j->flags = part < 3 || part == 7 ? FRUSTA_JOINT_ORIENTATION_VALID : FRUSTA_JOINT_POSITION_VALID;
      if (part < 7) j->radius = 0.0;
      if (part == 7) j->flags = 0;
      what("%s: %s = %g, not declared valid", label, field, values[i]);
      untouched = 1;
      accepted(call(joints, &untouched, context));
    }
  }
  const int32_t flags[] = {16, 0x20, -1, INT32_MIN, INT32_MAX, 15 | 0x100};
  for (int i = 0; i < 6; ++i) {
    memcpy(joints, base, sizeof joints[0] * (size_t)count);
    joints[index].flags = flags[i];
    snprintf(field, sizeof field, "%s[%d].flags", array, index);
    what("%s: %s = %d", label, field, flags[i]);
    int untouched = 1;
    refused(call(joints, &untouched, context), FRUSTA_ERROR_OUT_OF_RANGE, field);
    verify(untouched, "a refused call changed something");
  }
}

/* ---- defaults and creation */

static frusta_result call_create_fitter(const frusta_hand_def* hd, const frusta_hand_fit_def* fd,
                                        int* untouched) {
  frusta_hand_fitter_id fitter;
  fill(&fitter, sizeof fitter);
  const frusta_result r = frusta_create_hand_fitter(hd, fd, &fitter);
  if (r != FRUSTA_OK) {
    *untouched = is_sentinel(&fitter, sizeof fitter);
    return r;
  }
  /* used: it fits the hand's own joints in its layout */
  verify(frusta_hand_fitter_is_valid(fitter) == 1, "the fitter created is not valid");
  frusta_tracked_joint joints[FRUSTA_XR_JOINT_COUNT];
  int32_t count = 0;
  const double zero[FRUSTA_HAND_JOINT_COUNT] = {0};
  frusta_hand_fit fit;
  memset(&fit, 0, sizeof fit);
  fit.struct_size = (int32_t)sizeof fit;
  if (verify(frusta_hand_joints_from_pose(hd, fd->layout, &kIdentity, zero, FRUSTA_HAND_JOINT_COUNT,
                                          joints, FRUSTA_XR_JOINT_COUNT, &count) == FRUSTA_OK &&
                 frusta_hand_fitter_fit(fitter, joints, count, NULL, &fit) == FRUSTA_OK,
             "a created fitter does not fit its hand's joints: %s", frusta_last_error()))
    verify(all_finite(fit.palm.position, 3) && unit_quaternion(fit.palm.rotation) &&
               all_finite(fit.angles, FRUSTA_HAND_JOINT_COUNT) && !(fit.palm_flags & FRUSTA_FIT_HELD),
           "its fit is not finite, or held");
  frusta_destroy_hand_fitter(fitter);
  return r;
}

static frusta_result call_create_fitter_hand(const void* def, int* untouched, void* context) {
  (void)context;
  const frusta_hand_fit_def fd = frusta_default_hand_fit_def();
  return call_create_fitter((const frusta_hand_def*)def, &fd, untouched);
}

static frusta_result call_create_fitter_fit(const void* def, int* untouched, void* context) {
  (void)context;
  const frusta_hand_def hd = frusta_default_hand_def();
  return call_create_fitter(&hd, (const frusta_hand_fit_def*)def, untouched);
}

static void t_default_hand_fit_def(void) {
  const frusta_hand_fit_def a = frusta_default_hand_fit_def(), b = frusta_default_hand_fit_def();
  what("frusta_default_hand_fit_def()");
  g_calls += 2;
  verify(memcmp(&a, &b, sizeof a) == 0 && a.struct_size == (int32_t)sizeof a && a.internal_value != 0 &&
             a.layout == FRUSTA_JOINT_LAYOUT_XR && a.require_tracked == 0 && a.max_iterations == 10 &&
             a.orientation_weight == 0.0 && a.filter_min_cutoff == 1.0 && a.filter_beta == 2.0 &&
             a.filter_d_cutoff == 1.0,
         "not the documented deterministic def of this size with its cookie");
  int untouched = 1;
  accepted(call_create_fitter_fit(&a, &untouched, NULL));
}

#define FIT_FIELD(member) #member, offsetof(frusta_hand_fit_def, member)
static const IntField kFitInts[] = {
    {FIT_FIELD(layout), 0, 1},
    {FIT_FIELD(require_tracked), 0, 1},
    {FIT_FIELD(max_iterations), 1, 100},
};

static void t_create_hand_fitter(void) {
  const frusta_hand_def hd = frusta_default_hand_def();
  const frusta_hand_fit_def fd = frusta_default_hand_fit_def();
  frusta_hand_fitter_id fitter;
  fill(&fitter, sizeof fitter);
  what("frusta_create_hand_fitter(NULL, &fit_def, &fitter)");
  refused(frusta_create_hand_fitter(NULL, &fd, &fitter), FRUSTA_ERROR_NULL_POINTER, "def");
  what("frusta_create_hand_fitter(&def, NULL, &fitter)");
  refused(frusta_create_hand_fitter(&hd, NULL, &fitter), FRUSTA_ERROR_NULL_POINTER, "fit_def");
  verify(is_sentinel(&fitter, sizeof fitter), "out_fitter written");
  what("frusta_create_hand_fitter(&def, &fit_def, NULL)");
  refused(frusta_create_hand_fitter(&hd, &fd, NULL), FRUSTA_ERROR_NULL_POINTER, "out_fitter");
  sweep_def_header("frusta_create_hand_fitter", "frusta_hand_def", &hd, sizeof hd,
                   offsetof(frusta_hand_def, internal_value), call_create_fitter_hand, NULL);
  sweep_def_header("frusta_create_hand_fitter", "frusta_hand_fit_def", &fd, sizeof fd,
                   offsetof(frusta_hand_fit_def, internal_value), call_create_fitter_fit, NULL);
  sweep_fields("frusta_create_hand_fitter", &hd, sizeof hd, kHandFields, HAND_FIELD_COUNT,
               call_create_fitter_hand, NULL);
  const Field weight = {FIT_FIELD(orientation_weight), 1, 0, NAME_SCALAR, 0.0, 1.0, 0};
  sweep_fields("frusta_create_hand_fitter", &fd, sizeof fd, &weight, 1, call_create_fitter_fit, NULL);
  const Field filter[] = {{FIT_FIELD(filter_min_cutoff), 1, 0, NAME_SCALAR, 0.0, 1000.0, 0},
                          {FIT_FIELD(filter_beta), 1, 0, NAME_SCALAR, 0.0, 1000.0, 0},
                          {FIT_FIELD(filter_d_cutoff), 1, 0, NAME_SCALAR, 1e-3, 1000.0, 0}};
  sweep_fields("frusta_create_hand_fitter", &fd, sizeof fd, filter, 3, call_create_fitter_fit, NULL);
  sweep_ints("frusta_create_hand_fitter", &fd, sizeof fd, kFitInts, 3, call_create_fitter_fit, NULL);
  /* hands at the ends of their ranges fit their own joints */
  for (int big = 0; big < 2; ++big) {
    const frusta_hand_def d = extreme_hand_def(big);
    what("frusta_create_hand_fitter: every part %g", big ? 5.0 : 1e-4);
    int untouched = 1;
    accepted(call_create_fitter(&d, &fd, &untouched));
  }
}

static frusta_result call_destroy_fitter(RawId id, int* untouched) {
  const frusta_result r = frusta_destroy_hand_fitter(fitter_of_raw(id));
  *untouched = frusta_hand_fitter_is_valid(g_fitter) == 1;
  return r;
}

static int32_t valid_fitter(RawId id) { return frusta_hand_fitter_is_valid(fitter_of_raw(id)); }

static void t_destroy_hand_fitter(void) {
  sweep_ids("frusta_destroy_hand_fitter", "hand fitter", TO_RAW(g_fitter), TO_RAW(g_dead_fitter), 1,
            call_destroy_fitter);
  const frusta_hand_def hd = frusta_default_hand_def();
  const frusta_hand_fit_def fd = frusta_default_hand_fit_def();
  frusta_hand_fitter_id fitter;
  what("frusta_destroy_hand_fitter twice");
  accepted(frusta_create_hand_fitter(&hd, &fd, &fitter));
  accepted(frusta_destroy_hand_fitter(fitter));
  refused(frusta_destroy_hand_fitter(fitter), FRUSTA_ERROR_STALE_ID, "hand fitter");
}

static void t_hand_fitter_is_valid(void) {
  sweep_valid("frusta_hand_fitter_is_valid", TO_RAW(g_fitter), TO_RAW(g_dead_fitter), 1, valid_fitter);
}

/* ---- fitting */

/* 1 while frusta_hand_fitter_fit_at is attacked: each fit below is a timed one, at 1 s
 * after an untimed fit of g_joints (which restarts the filter, so any time is next) */
static int g_timed = 0;

static frusta_result fit_call(frusta_hand_fitter_id fitter, const frusta_tracked_joint* joints,
                              int32_t count, const frusta_pose* frame, frusta_hand_fit* out) {
  if (!g_timed) return frusta_hand_fitter_fit(fitter, joints, count, frame, out);
  return frusta_hand_fitter_fit_at(fitter, 1.0, joints, count, frame, out);
}

/* g_fitter on joints (and frame): a refused call leaves out and the fitter's history as
 * they were; an accepted fit is sane. */
static frusta_result fit_with(const frusta_tracked_joint* joints, int32_t count,
                              const frusta_pose* frame, int* untouched) {
  restore_fitter();
  frusta_hand_fit out;
  fill(&out, sizeof out);
  out.struct_size = (int32_t)sizeof out;
  const frusta_result r = fit_call(g_fitter, joints, count, frame, &out);
  if (r != FRUSTA_OK) {
    *untouched = is_sentinel((unsigned char*)&out + 4, sizeof out - 4) && fitter_history_kept();
    return r;
  }
  fit_sane(&out);
  return r;
}

static frusta_result call_fit_id(RawId id, int* untouched) {
  restore_fitter();
  frusta_hand_fit out;
  fill(&out, sizeof out);
  out.struct_size = (int32_t)sizeof out;
  const frusta_result r =
      fit_call(fitter_of_raw(id), g_joints, FRUSTA_XR_JOINT_COUNT, NULL, &out);
  *untouched = is_sentinel((unsigned char*)&out + 4, sizeof out - 4) && fitter_history_kept();
  return r;
}

static frusta_result call_fit_joints(const frusta_tracked_joint* joints, int* untouched, void* context) {
  (void)context;
  return fit_with(joints, FRUSTA_XR_JOINT_COUNT, NULL, untouched);
}

static frusta_result call_fit_frame(const void* frame, int* untouched, void* context) {
  (void)context;
  const frusta_result r = fit_with(g_joints, FRUSTA_XR_JOINT_COUNT, (const frusta_pose*)frame, untouched);
  return r;
}

static frusta_result fit_out(void* out) {
  restore_fitter();
  return fit_call(g_fitter, g_joints, FRUSTA_XR_JOINT_COUNT, NULL, (frusta_hand_fit*)out);
}

static void fit_sweeps(void) {
  sweep_ids("frusta_hand_fitter_fit", "hand fitter", TO_RAW(g_fitter), TO_RAW(g_dead_fitter), 1,
            call_fit_id);
  int untouched = 1;
  what("frusta_hand_fitter_fit(fitter, NULL, 26, NULL, &out)");
  refused(fit_with(NULL, FRUSTA_XR_JOINT_COUNT, NULL, &untouched), FRUSTA_ERROR_NULL_POINTER, "joints");
  verify(untouched, "a refused call changed something");
  what("frusta_hand_fitter_fit(fitter, joints, 26, NULL, NULL)");
  refused(fit_call(g_fitter, g_joints, FRUSTA_XR_JOINT_COUNT, NULL, NULL),
          FRUSTA_ERROR_NULL_POINTER, "out");
  sweep_out_size("frusta_hand_fitter_fit", "frusta_hand_fit", sizeof(frusta_hand_fit), fit_out);
  /* a count other than the layout's: refused before a joint is read (the buffer holds 26) */
  const int32_t counts[] = {INT32_MIN, -1, 0, FRUSTA_KEYPOINT_COUNT, FRUSTA_XR_JOINT_COUNT - 1,
                            FRUSTA_XR_JOINT_COUNT + 1, INT32_MAX};
  for (int i = 0; i < 7; ++i) {
    what("frusta_hand_fitter_fit: count %d", counts[i]);
    untouched = 1;
    refused(fit_with(g_joints, counts[i], NULL, &untouched), FRUSTA_ERROR_OUT_OF_RANGE, "count");
    verify(untouched, "a refused call changed something");
  }
  sweep_pose("frusta_hand_fitter_fit", "frame", call_fit_frame, NULL);
  /* a palm-rigid joint and a moving one */
  sweep_joint("frusta_hand_fitter_fit", "joints", g_joints, FRUSTA_XR_JOINT_COUNT, 1, call_fit_joints, NULL);
  sweep_joint("frusta_hand_fitter_fit", "joints", g_joints, FRUSTA_XR_JOINT_COUNT, 9, call_fit_joints, NULL);
  /* every joint missing, every joint at 1e6 m, every joint at one point: taken, held or fit */
  frusta_tracked_joint joints[FRUSTA_XR_JOINT_COUNT];
  const double places[] = {0.0, 1e6, -1e6};
  for (int p = 0; p < 3; ++p) {
    memcpy(joints, g_joints, sizeof joints);
    for (int i = 0; i < FRUSTA_XR_JOINT_COUNT; ++i)
      for (int k = 0; k < 3; ++k) joints[i].position[k] = places[p];
    what("frusta_hand_fitter_fit: every joint at %g", places[p]);
    untouched = 1;
    accepted(fit_with(joints, FRUSTA_XR_JOINT_COUNT, NULL, &untouched));
  }
  memset(joints, 0, sizeof joints);
  what("frusta_hand_fitter_fit: every joint missing");
  untouched = 1;
  accepted(fit_with(joints, FRUSTA_XR_JOINT_COUNT, NULL, &untouched));
  ++g_calls;
  verify(fitter_history_kept(), "a sample of missing joints did not give the last fit back, held");
  restore_fitter();
}

static void t_hand_fitter_fit(void) { fit_sweeps(); }

/* a timed fit at t (after an untimed one at `after` >= 0 s, else after none) */
static frusta_result fit_at_after(double after, double t, int* untouched) {
  restore_fitter();
  frusta_hand_fit out;
  if (after >= 0.0) {
    memset(&out, 0, sizeof out);
    out.struct_size = (int32_t)sizeof out;
    if (!verify(frusta_hand_fitter_fit_at(g_fitter, after, g_joints, FRUSTA_XR_JOINT_COUNT, NULL,
                                          &out) == FRUSTA_OK, "a timed fit at %g s", after))
      return FRUSTA_OK;
  }
  fill(&out, sizeof out);
  out.struct_size = (int32_t)sizeof out;
  const frusta_result r = frusta_hand_fitter_fit_at(g_fitter, t, g_joints, FRUSTA_XR_JOINT_COUNT, NULL, &out);
  if (r != FRUSTA_OK) *untouched = is_sentinel((unsigned char*)&out + 4, sizeof out - 4);
  else fit_sane(&out);
  return r;
}

static void t_hand_fitter_fit_at(void) {
  /* everything frusta_hand_fitter_fit is attacked with, timed */
  g_timed = 1;
  fit_sweeps();
  g_timed = 0;
  /* the time: finite, strictly after the previous timed sample's */
  for (int i = 0; i < HOSTILE_COUNT; ++i) {
    const double t = kHostile[i];
    what("frusta_hand_fitter_fit_at: time %g, the first", t);
    int untouched = 1;
    if (isfinite(t)) accepted(fit_at_after(-1.0, t, &untouched));
    else refused(fit_at_after(-1.0, t, &untouched), FRUSTA_ERROR_NOT_FINITE, "time");
    verify(untouched, "a refused call changed something");
  }
  const double previous[] = {0.0, 5.0, -5.0, 1e300};
  for (int p = 0; p < 4; ++p) {
    const double t0 = previous[p];
    const double times[] = {t0, nextafter(t0, -INFINITY), t0 - 1.0, -DBL_MAX, NAN, INFINITY,
                            nextafter(t0, INFINITY), t0 + 1.0, DBL_MAX};
    for (int i = 0; i < 9; ++i) {
      what("frusta_hand_fitter_fit_at: time %.17g after %.17g", times[i], t0);
      int untouched = 1;
      const frusta_result r = fit_at_after(t0 >= 0.0 ? t0 : -1.0, times[i], &untouched);
      if (t0 < 0.0) {  /* after an untimed fit: any finite time */
        if (isfinite(times[i])) accepted(r);
        else refused(r, FRUSTA_ERROR_NOT_FINITE, "time");
      } else if (!isfinite(times[i])) {
        refused(r, FRUSTA_ERROR_NOT_FINITE, "time");
      } else if (times[i] > t0) {
        accepted(r);
      } else {
        refused(r, FRUSTA_ERROR_OUT_OF_RANGE, "time");
      }
      if (r != FRUSTA_OK) verify(untouched, "a refused call changed something");
    }
  }
  /* a refused time leaves the previous one: the next after it is taken */
  what("frusta_hand_fitter_fit_at: after a refused time");
  int untouched = 1;
  frusta_hand_fit out;
  memset(&out, 0, sizeof out);
  out.struct_size = (int32_t)sizeof out;
  refused(fit_at_after(2.0, 1.0, &untouched), FRUSTA_ERROR_OUT_OF_RANGE, "time");
  accepted(frusta_hand_fitter_fit_at(g_fitter, nextafter(2.0, 3.0), g_joints, FRUSTA_XR_JOINT_COUNT,
                                     NULL, &out));
  /* a fit at a held palm is taken (and restarts the filter) */
  frusta_tracked_joint none[FRUSTA_XR_JOINT_COUNT];
  memset(none, 0, sizeof none);
  what("frusta_hand_fitter_fit_at: every joint missing");
  accepted(frusta_hand_fitter_fit_at(g_fitter, 3.0, none, FRUSTA_XR_JOINT_COUNT, NULL, &out));
  verify(out.palm_flags == FRUSTA_FIT_HELD, "a palm with no joint was not held");
  restore_fitter();
}

/* ---- joints from a pose */

static frusta_result joints_from(const frusta_hand_def* def, int32_t layout, const frusta_pose* palm,
                                 const double* angles, int32_t angle_count, int* untouched) {
  frusta_tracked_joint out[FRUSTA_XR_JOINT_COUNT + 2];
  int32_t count;
  fill(out, sizeof out);
  fill(&count, sizeof count);
  const frusta_result r = frusta_hand_joints_from_pose(def, layout, palm, angles, angle_count, out,
                                                       FRUSTA_XR_JOINT_COUNT + 2, &count);
  if (r != FRUSTA_OK) {
    *untouched = is_sentinel(out, sizeof out) && is_sentinel(&count, sizeof count);
    return r;
  }
  const int32_t want = layout == FRUSTA_JOINT_LAYOUT_XR ? FRUSTA_XR_JOINT_COUNT : FRUSTA_KEYPOINT_COUNT;
  int ok = count == want && is_sentinel(out + want, sizeof out[0] * (size_t)(FRUSTA_XR_JOINT_COUNT + 2 - want));
  for (int i = 0; i < want; ++i)
    ok &= all_finite(out[i].position, 3) && isfinite(out[i].radius) && out[i].radius >= 0.0 &&
          (layout != FRUSTA_JOINT_LAYOUT_XR || (unit_quaternion(out[i].rotation) && out[i].flags == 15));
  verify(ok, "%d joints, or not finite, unit and valid", count);
  return r;
}

static const double kZeroAngles[FRUSTA_HAND_JOINT_COUNT] = {0};

static frusta_result call_joints_def(const void* def, int* untouched, void* context) {
  (void)context;
  return joints_from((const frusta_hand_def*)def, FRUSTA_JOINT_LAYOUT_XR, &kIdentity, kZeroAngles,
                     FRUSTA_HAND_JOINT_COUNT, untouched);
}

static frusta_result call_joints_palm(const void* palm, int* untouched, void* context) {
  (void)context;
  const frusta_hand_def def = frusta_default_hand_def();
  return joints_from(&def, FRUSTA_JOINT_LAYOUT_XR, (const frusta_pose*)palm, kZeroAngles,
                     FRUSTA_HAND_JOINT_COUNT, untouched);
}

static frusta_result call_joints_angles(const void* angles, int* untouched, void* context) {
  (void)context;
  const frusta_hand_def def = frusta_default_hand_def();
  return joints_from(&def, FRUSTA_JOINT_LAYOUT_KEYPOINTS, &kIdentity, (const double*)angles,
                     FRUSTA_HAND_JOINT_COUNT, untouched);
}

static int32_t g_array_layout;
static frusta_result joints_array_call(void* out, int32_t capacity, int32_t* count) {
  const frusta_hand_def def = frusta_default_hand_def();
  return frusta_hand_joints_from_pose(&def, g_array_layout, &kIdentity, kZeroAngles,
                                      FRUSTA_HAND_JOINT_COUNT, (frusta_tracked_joint*)out, capacity,
                                      count);
}

static void t_hand_joints_from_pose(void) {
  const frusta_hand_def def = frusta_default_hand_def();
  int untouched = 1;
  what("frusta_hand_joints_from_pose(NULL, ...)");
  refused(joints_from(NULL, 0, &kIdentity, kZeroAngles, FRUSTA_HAND_JOINT_COUNT, &untouched),
          FRUSTA_ERROR_NULL_POINTER, "def");
  what("frusta_hand_joints_from_pose(def, 0, NULL, ...)");
  refused(joints_from(&def, 0, NULL, kZeroAngles, FRUSTA_HAND_JOINT_COUNT, &untouched),
          FRUSTA_ERROR_NULL_POINTER, "palm");
  what("frusta_hand_joints_from_pose(def, 0, palm, NULL, 20, ...)");
  refused(joints_from(&def, 0, &kIdentity, NULL, FRUSTA_HAND_JOINT_COUNT, &untouched),
          FRUSTA_ERROR_NULL_POINTER, "angles");
  verify(untouched, "a refused call wrote out");
  const int32_t layouts[] = {INT32_MIN, -1, 2, INT32_MAX};
  for (int i = 0; i < 4; ++i) {
    what("frusta_hand_joints_from_pose: layout %d", layouts[i]);
    refused(joints_from(&def, layouts[i], &kIdentity, kZeroAngles, FRUSTA_HAND_JOINT_COUNT, &untouched),
            FRUSTA_ERROR_OUT_OF_RANGE, "layout");
  }
  const int32_t counts[] = {INT32_MIN, -1, 0, FRUSTA_HAND_JOINT_COUNT - 1, FRUSTA_HAND_JOINT_COUNT + 1,
                            INT32_MAX};
  for (int i = 0; i < 6; ++i) {
    what("frusta_hand_joints_from_pose: angle_count %d", counts[i]);
    refused(joints_from(&def, 0, &kIdentity, kZeroAngles, counts[i], &untouched),
            FRUSTA_ERROR_OUT_OF_RANGE, "count");
  }
  verify(untouched, "a refused call wrote out");
  sweep_def_header("frusta_hand_joints_from_pose", "frusta_hand_def", &def, sizeof def,
                   offsetof(frusta_hand_def, internal_value), call_joints_def, NULL);
  sweep_fields("frusta_hand_joints_from_pose", &def, sizeof def, kHandFields, HAND_FIELD_COUNT,
               call_joints_def, NULL);
  sweep_pose("frusta_hand_joints_from_pose", "palm", call_joints_palm, NULL);
  const Field angles = {"angles", 0, FRUSTA_HAND_JOINT_COUNT, 0, NAME_1D, -FRUSTA_MAX_JOINT_ANGLE,
                        FRUSTA_MAX_JOINT_ANGLE, 0};
  sweep_fields("frusta_hand_joints_from_pose", kZeroAngles, sizeof kZeroAngles, &angles, 1,
               call_joints_angles, NULL);
  frusta_tracked_joint out[FRUSTA_XR_JOINT_COUNT + 2];
  g_array_layout = FRUSTA_JOINT_LAYOUT_XR;
  sweep_output_array("frusta_hand_joints_from_pose", joints_array_call, out, sizeof out[0],
                     FRUSTA_XR_JOINT_COUNT + 2, FRUSTA_XR_JOINT_COUNT, "out");
  g_array_layout = FRUSTA_JOINT_LAYOUT_KEYPOINTS;
  sweep_output_array("frusta_hand_joints_from_pose (keypoints)", joints_array_call, out, sizeof out[0],
                     FRUSTA_XR_JOINT_COUNT + 2, FRUSTA_KEYPOINT_COUNT, "out");
  for (int big = 0; big < 2; ++big) {
    const frusta_hand_def d = extreme_hand_def(big);
    what("frusta_hand_joints_from_pose: every part %g", big ? 5.0 : 1e-4);
    untouched = 1;
    accepted(joints_from(&d, FRUSTA_JOINT_LAYOUT_XR, &kIdentity, kZeroAngles, FRUSTA_HAND_JOINT_COUNT,
                         &untouched));
  }
}

/* ---- calibration */

static frusta_result calibrate(const frusta_tracked_joint* frames, int32_t frame_count, int32_t layout,
                               const frusta_hand_def* def, int* untouched) {
  frusta_hand_def copy = *def;
  const frusta_result r = frusta_calibrate_hand_def(frames, frame_count, layout, &copy);
  if (r != FRUSTA_OK) {
    *untouched = memcmp(&copy, def, sizeof copy) == 0;
    return r;
  }
  /* used: the frames are the default hand's; a hand of the def sized is made */
  int ignored = 1;
  verify(fabs(copy.hand_length - 0.19) < 0.01 && fabs(copy.hand_breadth - 0.085) < 0.01 &&
             call_create_hand(&copy, &ignored, NULL) == FRUSTA_OK,
         "calibrated to %g x %g m, or refused by create_hand: %s", copy.hand_length,
         copy.hand_breadth, frusta_last_error());
  return r;
}

static frusta_result call_calibrate_def(const void* def, int* untouched, void* context) {
  (void)context;
  return calibrate(g_frames, CALIBRATION_FRAMES, FRUSTA_JOINT_LAYOUT_XR, (const frusta_hand_def*)def,
                   untouched);
}

static frusta_result call_calibrate_frames(const frusta_tracked_joint* frames, int* untouched,
                                           void* context) {
  (void)context;
  const frusta_hand_def def = frusta_default_hand_def();
  return calibrate(frames, CALIBRATION_FRAMES, FRUSTA_JOINT_LAYOUT_XR, &def, untouched);
}

static void t_calibrate_hand_def(void) {
  const frusta_hand_def def = frusta_default_hand_def();
  int untouched = 1;
  what("frusta_calibrate_hand_def(NULL, 3, 0, &def)");
  refused(calibrate(NULL, CALIBRATION_FRAMES, 0, &def, &untouched), FRUSTA_ERROR_NULL_POINTER, "frames");
  verify(untouched, "a refused call changed the def");
  what("frusta_calibrate_hand_def(frames, 3, 0, NULL)");
  refused(frusta_calibrate_hand_def(g_frames, CALIBRATION_FRAMES, 0, NULL), FRUSTA_ERROR_NULL_POINTER, "def");
  const int32_t counts[] = {INT32_MIN, -1, 0, 65537, INT32_MAX};
  for (int i = 0; i < 5; ++i) {
    what("frusta_calibrate_hand_def: frame_count %d", counts[i]);
    refused(calibrate(g_frames, counts[i], 0, &def, &untouched), FRUSTA_ERROR_OUT_OF_RANGE, "frame_count");
    verify(untouched, "a refused call changed the def");
  }
  const int32_t layouts[] = {INT32_MIN, -1, 2, INT32_MAX};
  for (int i = 0; i < 4; ++i) {
    what("frusta_calibrate_hand_def: layout %d", layouts[i]);
    refused(calibrate(g_frames, CALIBRATION_FRAMES, layouts[i], &def, &untouched),
            FRUSTA_ERROR_OUT_OF_RANGE, "layout");
    verify(untouched, "a refused call changed the def");
  }
  sweep_def_header("frusta_calibrate_hand_def", "frusta_hand_def", &def, sizeof def,
                   offsetof(frusta_hand_def, internal_value), call_calibrate_def, NULL);
  sweep_fields("frusta_calibrate_hand_def", &def, sizeof def, kHandFields, HAND_FIELD_COUNT,
               call_calibrate_def, NULL);
  /* a joint of the last frame: frames are one array, named by its index */
  sweep_joint("frusta_calibrate_hand_def", "frames", g_frames, CALIBRATION_FRAMES * FRUSTA_XR_JOINT_COUNT,
              2 * FRUSTA_XR_JOINT_COUNT + 13, call_calibrate_frames, NULL);
  /* nothing tracked: nothing to size by */
  frusta_tracked_joint frames[CALIBRATION_FRAMES * FRUSTA_XR_JOINT_COUNT];
  memcpy(frames, g_frames, sizeof frames);
  for (int i = 0; i < CALIBRATION_FRAMES * FRUSTA_XR_JOINT_COUNT; ++i) frames[i].flags &= ~8;
  what("frusta_calibrate_hand_def: positions valid but none tracked");
  refused(calibrate(frames, CALIBRATION_FRAMES, 0, &def, &untouched), FRUSTA_ERROR_OUT_OF_RANGE, "frames");
  verify(untouched, "a refused call changed the def");
  /* every frame's joints at one point: a hand of no size */
  memcpy(frames, g_frames, sizeof frames);
  for (int i = 0; i < CALIBRATION_FRAMES * FRUSTA_XR_JOINT_COUNT; ++i)
    memset(frames[i].position, 0, sizeof frames[i].position);
  what("frusta_calibrate_hand_def: every joint at the origin");
  refused(calibrate(frames, CALIBRATION_FRAMES, 0, &def, &untouched), FRUSTA_ERROR_OUT_OF_RANGE, "frames");
  verify(untouched, "a refused call changed the def");
  /* one frame, and keypoints */
  what("frusta_calibrate_hand_def: one frame");
  accepted(calibrate(g_frames, 1, 0, &def, &untouched));
  frusta_tracked_joint keypoints[FRUSTA_XR_JOINT_COUNT];
  what("frusta_calibrate_hand_def: keypoints");
  if (accepted(posed_joints(FRUSTA_JOINT_LAYOUT_KEYPOINTS, 0.5, keypoints)))
    accepted(calibrate(keypoints, 1, FRUSTA_JOINT_LAYOUT_KEYPOINTS, &def, &untouched));
}

/* ------------------------------------------------------------------ the tables */

typedef struct Entry {
  const char* name;
  void (*run)(void);
} Entry;

/* Every function frusta.h declares, with what attacks it (the order is the header's;
 * later entries use what earlier ones left, e.g. the worlds). */
static const Entry kFunctions[] = {
    {"frusta_version", t_version},
    {"frusta_abi_version", t_abi_version},
    {"frusta_last_error", t_last_error},
    {"frusta_result_name", t_result_name},
    {"frusta_check_abi", t_check_abi},
    {"frusta_struct_size", t_struct_size},
    {"frusta_default_hand_def", t_default_hand_def},
    {"frusta_hand_def_set_size", t_hand_def_set_size},
    {"frusta_create_hand", t_create_hand},
    {"frusta_destroy_hand", t_destroy_hand},
    {"frusta_hand_is_valid", t_hand_is_valid},
    {"frusta_hand_set_palm_pose", t_hand_set_palm_pose},
    {"frusta_hand_set_joint_angles", t_hand_set_joint_angles},
    {"frusta_hand_get_joint_angles", t_hand_get_joint_angles},
    {"frusta_hand_get_segments", t_hand_get_segments},
    {"frusta_hand_get_palm_spheres", t_hand_get_palm_spheres},
    {"frusta_hand_point_jacobian", t_hand_point_jacobian},
    {"frusta_default_hand_fit_def", t_default_hand_fit_def},
    {"frusta_create_hand_fitter", t_create_hand_fitter},
    {"frusta_destroy_hand_fitter", t_destroy_hand_fitter},
    {"frusta_hand_fitter_is_valid", t_hand_fitter_is_valid},
    {"frusta_hand_fitter_fit", t_hand_fitter_fit},
    {"frusta_hand_fitter_fit_at", t_hand_fitter_fit_at},
    {"frusta_hand_joints_from_pose", t_hand_joints_from_pose},
    {"frusta_calibrate_hand_def", t_calibrate_hand_def},
    {"frusta_query_contact", t_query_contact},
    {"frusta_constraint_eval", t_constraint_eval},
    {"frusta_default_bake_def", t_default_bake_def},
    {"frusta_create_sphere_tree_from_mesh", t_bake_sphere_tree},
    {"frusta_create_sphere_tree_from_memory", t_create_sphere_tree_from_memory},
    {"frusta_start_bake", t_start_bake},
    {"frusta_bake_job_progress", t_bake_job_progress},
    {"frusta_cancel_bake_job", t_cancel_bake_job},
    {"frusta_finish_bake_job", t_finish_bake_job},
    {"frusta_create_sphere_tree_from_file", t_load_sphere_tree},
    {"frusta_sphere_tree_save", t_save_sphere_tree},
    {"frusta_destroy_sphere_tree", t_destroy_sphere_tree},
    {"frusta_sphere_tree_is_valid", t_sphere_tree_is_valid},
    {"frusta_sphere_tree_get_info", t_sphere_tree_get_info},
    {"frusta_sphere_tree_get_leaves", t_sphere_tree_get_leaves},
    {"frusta_sphere_tree_query_segment", t_sphere_tree_query_segment},
    {"frusta_default_world_def", t_default_world_def},
    {"frusta_default_object_def", t_default_object_def},
    {"frusta_create_world", t_create_world},
    {"frusta_destroy_world", t_destroy_world},
    {"frusta_world_is_valid", t_world_is_valid},
    {"frusta_create_world_hand", t_world_add_hand},
    {"frusta_destroy_world_hand", t_destroy_world_hand},
    {"frusta_world_set_haptic", t_world_set_haptic},
    {"frusta_world_set_haptic_at", t_world_set_haptic_at},
    {"frusta_now", t_now},
    {"frusta_create_object", t_world_add_object},
    {"frusta_destroy_object", t_destroy_object},
    {"frusta_world_set_object_pose", t_world_set_object_pose},
    {"frusta_world_set_object_dynamic", t_world_set_object_dynamic},
    {"frusta_world_step", t_world_step},
    {"frusta_world_start", t_world_start},
    {"frusta_world_stop", t_world_stop},
    {"frusta_world_read", t_world_read},
    {"frusta_world_get_hand", t_world_get_hand},
    {"frusta_world_get_contacts", t_world_get_contacts},
    {"frusta_world_get_object", t_world_get_object},
    {"frusta_world_get_object_ignored_by", t_world_get_object_ignored_by},
    {"frusta_world_get_hand_segments", t_world_get_hand_segments},
    {"frusta_world_get_hand_palm_spheres", t_world_get_hand_palm_spheres},
    {"frusta_default_device_def", t_default_device_def},
    {"frusta_enumerate_devices", t_enumerate_devices},
    {"frusta_create_device", t_world_open_device},
    {"frusta_destroy_device", t_device_close},
    {"frusta_device_is_valid", t_device_is_valid},
    {"frusta_device_get_status", t_device_get_status},
    {"frusta_device_set_palm_pose", t_device_set_palm_pose},
};
#define FUNCTION_COUNT ((int)(sizeof kFunctions / sizeof kFunctions[0]))

static const Entry kScenarios[] = {
    {"extreme objects pressed", s_extreme_objects},
    {"extreme hands pressing", s_extreme_hands},
    {"65535 objects, 10^5 adds", s_capacity},
    {"10^6 leaves under two hands", s_million_leaves},
    {"ids of a reused world slot", s_reused_slot},
    {"a running world", s_running},
};

/* The function names the header declares (FRUSTA_API ... frusta_name(), as the exports
 * test reads them): every one must have an entry, and every entry a function. */
static void check_table_covers_header(void) {
  g_function = "the table";
  what("%s", FRUSTA_HEADER_PATH);
  long size = 0;
  unsigned char* text = read_file(FRUSTA_HEADER_PATH, &size);
  if (!verify(text != NULL, "cannot read the header")) return;
  text[size] = '\0';
  int found = 0, seen[FUNCTION_COUNT] = {0};
  for (char* p = strstr((char*)text, "FRUSTA_API"); p; p = strstr(p + 10, "FRUSTA_API")) {
    char* end = p + 10;
    while (*end && *end != '(' && *end != ';') ++end;
    if (*end != '(') continue;
    char* name_end = end;
    while (name_end > p && name_end[-1] == ' ') --name_end;
    char* name = name_end;
    while (name > p && (name[-1] == '_' || (name[-1] >= 'a' && name[-1] <= 'z') || (name[-1] >= '0' && name[-1] <= '9')))
      --name;
    if (name_end - name < 8 || strncmp(name, "frusta_", 7) != 0) continue;
    ++found;
    int entry = -1;
    for (int i = 0; i < FUNCTION_COUNT; ++i)
      if (strlen(kFunctions[i].name) == (size_t)(name_end - name) &&
          strncmp(kFunctions[i].name, name, (size_t)(name_end - name)) == 0)
        entry = i;
    ++g_calls;
    if (verify(entry >= 0, "%.*s has no hostile cases in kFunctions", (int)(name_end - name), name))
      ++seen[entry];
  }
  for (int i = 0; i < FUNCTION_COUNT; ++i)
    verify(seen[i] == 1, "%s is in the table %s", kFunctions[i].name, seen[i] ? "twice" : "but not in the header");
  verify(found == FUNCTION_COUNT && found >= 50, "%d functions in the header, %d in the table", found, FUNCTION_COUNT);
  free(text);
  printf("%s  the table: %d functions of %s\n", g_entry_failed ? "FAIL" : "ok  ", found, FRUSTA_HEADER_PATH);
}

static void run_entry(const Entry* e) {
  g_function = e->name;
  g_calls = 0;
  g_entry_failed = 0;
  const clock_t start = clock();
  struct timespec wall_start, wall_end;
  clock_gettime(CLOCK_MONOTONIC, &wall_start);
  e->run();
  clock_gettime(CLOCK_MONOTONIC, &wall_end);
  /* the time each entry takes, on request (HOSTILE_ABI_TIMES=1): what to trim when the
   * test grows slow */
  if (getenv("HOSTILE_ABI_TIMES"))
    printf("     %.2f s processor, %.2f s wall\n", (double)(clock() - start) / CLOCKS_PER_SEC,
           (double)(wall_end.tv_sec - wall_start.tv_sec) + 1e-9 * (double)(wall_end.tv_nsec - wall_start.tv_nsec));
  printf("%s %s: %d calls\n", g_entry_failed ? "FAIL" : "ok  ", e->name, g_calls);
}

int main(void) {
  setvbuf(stdout, NULL, _IOLBF, 0);
  check_table_covers_header();
  if (!setup() || !tracking_setup() || !device_setup()) {
    printf("FAIL setup: the fixtures could not be made\n%d passed, %d failed\n", g_passed, g_failed);
    return 1;
  }
  int total = 0;
  for (int i = 0; i < FUNCTION_COUNT; ++i) {
    run_entry(&kFunctions[i]);
    total += g_calls;
  }
  for (size_t i = 0; i < sizeof kScenarios / sizeof kScenarios[0]; ++i) {
    run_entry(&kScenarios[i]);
    total += g_calls;
  }
  destroy_rig(&g_a);
  destroy_rig(&g_b);
  destroy_rig(&g_dev);
  frusta_destroy_hand(g_hand);
  frusta_destroy_hand_fitter(g_fitter);
  frusta_destroy_sphere_tree(g_box);
  frusta_destroy_sphere_tree(g_plate);
  if (frusta_sphere_tree_is_valid(g_saved_tree)) frusta_destroy_sphere_tree(g_saved_tree);
  printf("%d functions, %d hostile calls\n", FUNCTION_COUNT, total);
  printf("%d passed, %d failed\n", g_passed, g_failed);
  return g_failed == 0 ? 0 : 1;
}
