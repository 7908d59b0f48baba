/* SPDX-License-Identifier: MIT */
/*
 * frusta_demo RECORDING.csv OBJECTS_DIR [--trace TRACE.csv] [--host-steps] [--untimed] [--check]
 *
 * Plays a scripted glove recording (samples/data/demo_glove.csv, written by
 * frusta-make-recording) through a world, through the public C ABI only, as a host
 * application would: the world runs on its own 1 kHz thread, this thread feeds the
 * glove's input every millisecond, applies the recording's events (the host lets go of
 * the marble once it is pinched, drops it once it has fallen), and reads the newest
 * step. At the end it prints a table: achieved rate, step time, wake-up jitter,
 * overruns, the deepest penetration, peak and mean force per finger, force continuity
 * (the largest step-to-step change of a finger's force, p99 and max), how far the
 * marble was carried. --trace writes one CSV row per host tick.
 *
 * Each sample is stamped with its time in the recording (frusta_world_set_haptic_at,
 * on the world's clock: frusta_now() at the start plus the recording's time), so a
 * host thread that stalls on a busy machine and then catches up still moves the hand
 * as the glove did; the world plays the samples input_delay behind. The table reports
 * how late this thread delivered them (the world's default input_delay is the p99 of
 * that on a busy machine) and how many steps had to extrapolate. --untimed sets them
 * with frusta_world_set_haptic instead, stamped when set (as before timed input).
 *
 * --host-steps steps the world from this thread instead, one step per millisecond of
 * recording time, as fast as it goes: deterministic, for tests (the samples are then
 * stamped on the world's step clock).
 * --check exits non-zero unless the hand never sank more than 0.1 mm into an object,
 * the marble was carried at least 10 cm up and then fell onto the table and came to rest
 * there, and the fingertip slide and the pinches made forces.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "frusta/frusta.h"

#define MAX_OBJECTS 16
/* a marble resting on the recording's table lies 1.2 cm under where it lay on its stand
 * (3 cm under is through the table); one slower than kAtRest (m/s) has come to rest */
static const double kTableBelowMarble = 0.03, kAtRest = 0.01;
#define MAX_EVENTS 64
#define MAX_FRAMES 100000
#define MAX_CONTACTS 256

typedef struct object_row {
  char name[32], sample[32];
  frusta_object_def def;
  frusta_object_id id;
  frusta_tree_id tree;
} object_row;

typedef struct event_row {
  double time;
  char kind[16], name[32];
  int value;
  int done;
} event_row;

typedef struct frame {
  double time;
  frusta_pose palm;
  double angles[FRUSTA_HAND_JOINT_COUNT];
} frame;

typedef struct recording {
  object_row objects[MAX_OBJECTS];
  int object_count;
  event_row events[MAX_EVENTS];
  int event_count;
  frame* frames;
  int frame_count;
} recording;

/* what the run saw, for the table and --check */
typedef struct tally {
  double deepest;  /* metres */
  double peak[FRUSTA_FINGER_COUNT], sum[FRUSTA_FINGER_COUNT];
  long touching[FRUSTA_FINGER_COUNT];
  double peak_palm;
  double marble_start_z, marble_top_z, marble_end_z, marble_end_speed;
  long marble_held; /* steps a hand's grasp held it */
  long ticks;
  long late_steps; /* latched steps whose input was extrapolated or held */
  /* force continuity: the largest change of a finger's force from one step to the next
     (latched steps one apart only), per latched step; newtons */
  double* jumps;
  long jump_count, jump_capacity;
  double last_force[FRUSTA_FINGER_COUNT];
  unsigned long long last_step;
} tally;

static const char* const kFingerNames[FRUSTA_FINGER_COUNT] = {"thumb", "index", "middle",
                                                              "ring", "little"};

static int check(frusta_result result, const char* what) {
  if (result == FRUSTA_OK) return 1;
  fprintf(stderr, "frusta_demo: %s failed: %s\n", what, frusta_last_error());
  return 0;
}

/* split a CSV line in place; returns the field count */
static int split(char* line, char** fields, int capacity) {
  int n = 0;
  line[strcspn(line, "\r\n")] = '\0';
  for (char* f = strtok(line, ","); f && n < capacity; f = strtok(NULL, ",")) fields[n++] = f;
  return n;
}

static int parse_object(char** f, int n, object_row* o) {
  if (n != 15) return 0;
  snprintf(o->name, sizeof o->name, "%s", f[1]);
  snprintf(o->sample, sizeof o->sample, "%s", f[2]);
  o->def = frusta_default_object_def();
  for (int k = 0; k < 3; ++k) o->def.pose.position[k] = atof(f[3 + k]);
  for (int k = 0; k < 4; ++k) o->def.pose.rotation[k] = atof(f[6 + k]);
  o->def.dynamic = atoi(f[10]);
  o->def.mass = atof(f[11]);
  o->def.friction = atof(f[12]);
  o->def.normal_damping = atof(f[13]);
  o->def.tangential_damping = atof(f[14]);
  /* a solid of its mass about 2 cm across: enough for the world's rotation */
  for (int k = 0; k < 3; ++k) o->def.inertia[k] = 0.4 * o->def.mass * 0.01 * 0.01;
  o->def.linear_damping = o->def.angular_damping = 0.5;
  return 1;
}

static int load_recording(const char* path, recording* rec) {
  FILE* file = fopen(path, "r");
  if (!file) {
    fprintf(stderr, "frusta_demo: cannot open %s\n", path);
    return 0;
  }
  rec->frames = malloc(sizeof(frame) * MAX_FRAMES);
  char line[4096];
  int number = 0, ok = rec->frames != NULL;
  while (ok && fgets(line, sizeof line, file)) {
    ++number;
    if (line[0] == '#' || line[0] == '\n') continue;
    char* f[40];
    const int n = split(line, f, 40);
    if (n > 0 && strcmp(f[0], "object") == 0 && rec->object_count < MAX_OBJECTS) {
      ok = parse_object(f, n, &rec->objects[rec->object_count++]);
    } else if (n == 5 && strcmp(f[0], "event") == 0 && rec->event_count < MAX_EVENTS) {
      event_row* e = &rec->events[rec->event_count++];
      e->time = atof(f[1]);
      snprintf(e->kind, sizeof e->kind, "%s", f[2]);
      snprintf(e->name, sizeof e->name, "%s", f[3]);
      e->value = atoi(f[4]);
      e->done = 0;
    } else if (n == 9 + FRUSTA_HAND_JOINT_COUNT && strcmp(f[0], "frame") == 0 &&
               rec->frame_count < MAX_FRAMES) {
      frame* fr = &rec->frames[rec->frame_count++];
      fr->time = atof(f[1]);
      for (int k = 0; k < 3; ++k) fr->palm.position[k] = atof(f[2 + k]);
      for (int k = 0; k < 4; ++k) fr->palm.rotation[k] = atof(f[5 + k]);
      for (int j = 0; j < FRUSTA_HAND_JOINT_COUNT; ++j) fr->angles[j] = atof(f[9 + j]);
    } else {
      ok = 0;
    }
    if (!ok) fprintf(stderr, "frusta_demo: %s:%d: not an object, event or frame row\n", path, number);
  }
  fclose(file);
  if (ok && rec->frame_count < 2) {
    fprintf(stderr, "frusta_demo: %s has fewer than two frames\n", path);
    ok = 0;
  }
  return ok;
}

/* the glove at time t: frames interpolated (the quaternion normalised by the world) */
static void glove_at(const recording* rec, double t, frame* out) {
  int i = 0;
  while (i + 2 < rec->frame_count && rec->frames[i + 1].time <= t) ++i;
  const frame* a = &rec->frames[i];
  const frame* b = &rec->frames[i + 1];
  double u = (t - a->time) / (b->time - a->time);
  u = u < 0.0 ? 0.0 : u > 1.0 ? 1.0 : u;
  const double sign = a->palm.rotation[0] * b->palm.rotation[0] + a->palm.rotation[1] * b->palm.rotation[1] +
                      a->palm.rotation[2] * b->palm.rotation[2] + a->palm.rotation[3] * b->palm.rotation[3] < 0.0 ? -1.0 : 1.0;
  for (int k = 0; k < 3; ++k)
    out->palm.position[k] = a->palm.position[k] + u * (b->palm.position[k] - a->palm.position[k]);
  for (int k = 0; k < 4; ++k)
    out->palm.rotation[k] = a->palm.rotation[k] + u * (sign * b->palm.rotation[k] - a->palm.rotation[k]);
  for (int j = 0; j < FRUSTA_HAND_JOINT_COUNT; ++j)
    out->angles[j] = a->angles[j] + u * (b->angles[j] - a->angles[j]);
}

static int apply_events(recording* rec, frusta_world_id world, double t) {
  for (int i = 0; i < rec->event_count; ++i) {
    event_row* e = &rec->events[i];
    if (e->done || e->time > t) continue;
    e->done = 1;
    for (int o = 0; o < rec->object_count; ++o) {
      object_row* obj = &rec->objects[o];
      if (strcmp(obj->name, e->name) != 0 || FRUSTA_IS_NULL(obj->id)) continue;
      if (strcmp(e->kind, "dynamic") == 0) {
        if (!check(frusta_world_set_object_dynamic(world, obj->id, e->value), "set_object_dynamic"))
          return 0;
      } else if (strcmp(e->kind, "remove") == 0) {
        if (!check(frusta_destroy_object(obj->id), "destroy_object")) return 0;
        memset(&obj->id, 0, sizeof obj->id);
      }
    }
  }
  return 1;
}

static double norm3(const double v[3]) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

/* one host tick: latch the newest step, tally it, trace it */
static int observe(frusta_world_id world, frusta_hand_id hand_id, const recording* rec, tally* t,
                   FILE* trace) {
  frusta_world_state state = {.struct_size = sizeof state};
  frusta_world_hand hand = {.struct_size = sizeof hand};
  static frusta_world_contact contacts[MAX_CONTACTS];
  int32_t count = 0;
  if (!check(frusta_world_read(world, &state), "frusta_world_read")) return 0;
  if (state.step == 0) return 1;
  if (!check(frusta_world_get_hand(world, hand_id, &hand), "frusta_world_get_hand")) return 0;
  if (!check(frusta_world_get_contacts(world, hand_id, contacts, MAX_CONTACTS, &count),
             "get_contacts"))
    return 0;
  if (count > MAX_CONTACTS) count = MAX_CONTACTS; /* the rest were not copied */
  double deepest = 0.0;
  for (int i = 0; i < count; ++i)
    if (-contacts[i].distance > deepest) deepest = -contacts[i].distance;
  if (deepest > t->deepest) t->deepest = deepest;
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    const double force = hand.finger_resistance[f];
    if (force > t->peak[f]) t->peak[f] = force;
    if (force > 0.0) {
      t->sum[f] += force;
      ++t->touching[f];
    }
  }
  if (t->last_step != 0 && state.step == t->last_step + 1 && t->jump_count < t->jump_capacity) {
    double jump = 0.0;
    for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
      const double d = fabs(hand.finger_resistance[f] - t->last_force[f]);
      if (d > jump) jump = d;
    }
    t->jumps[t->jump_count++] = jump;
  }
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) t->last_force[f] = hand.finger_resistance[f];
  t->last_step = state.step;
  const double palm = norm3(hand.palm_force);
  if (palm > t->peak_palm) t->peak_palm = palm;
  t->late_steps += hand.input_late ? 1 : 0;
  double marble_z = NAN;
  const object_row* marble = &rec->objects[0];
  frusta_object_state object = {.struct_size = sizeof object};
  if (!FRUSTA_IS_NULL(marble->id) && frusta_world_get_object(world, marble->id, &object) == FRUSTA_OK) {
    marble_z = object.pose.position[2];
    if (t->ticks == 0) t->marble_start_z = marble_z;
    if (marble_z > t->marble_top_z) t->marble_top_z = marble_z;
    t->marble_end_z = marble_z;
    t->marble_end_speed = norm3(object.linear_velocity);
    t->marble_held += object.held ? 1 : 0;
  }
  ++t->ticks;
  if (trace) {
    fprintf(trace, "%.4f,%llu,%.2f,%lld,%d,%.4f", state.time, (unsigned long long)state.step,
            state.step_us, (long long)state.overruns, count, 1e3 * deepest);
    for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) fprintf(trace, ",%.4f", hand.finger_resistance[f]);
    fprintf(trace, ",%.4f,%.5f\n", palm, marble_z);
  }
  return 1;
}

static int by_value(const void* a, const void* b) {
  const double x = *(const double*)a, y = *(const double*)b;
  return x < y ? -1 : x > y ? 1 : 0;
}

static void sleep_until(struct timespec* deadline, long step_ns) {
  deadline->tv_nsec += step_ns;
  while (deadline->tv_nsec >= 1000000000L) {
    deadline->tv_nsec -= 1000000000L;
    ++deadline->tv_sec;
  }
  clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, deadline, NULL);
}

int main(int argc, char** argv) {
  if (argc < 3) {
    fprintf(stderr, "usage: frusta_demo RECORDING.csv OBJECTS_DIR [--trace TRACE.csv] "
                    "[--host-steps] [--untimed] [--check]\n");
    return 2;
  }
  const char* trace_path = NULL;
  int check_mode = 0, host_steps = 0, untimed = 0;
  for (int i = 3; i < argc; ++i) {
    if (strcmp(argv[i], "--check") == 0) check_mode = 1;
    else if (strcmp(argv[i], "--host-steps") == 0) host_steps = 1;
    else if (strcmp(argv[i], "--untimed") == 0) untimed = 1;
    else if (strcmp(argv[i], "--trace") == 0 && i + 1 < argc) trace_path = argv[++i];
    else {
      fprintf(stderr, "frusta_demo: unknown argument %s\n", argv[i]);
      return 2;
    }
  }
  if (!check(FRUSTA_CHECK_ABI(), "the ABI check")) return 1;
  static recording rec;
  if (!load_recording(argv[1], &rec)) return 1;

  frusta_world_def def = frusta_default_world_def();
  def.gravity[2] = -9.81;
  frusta_world_id world;
  if (!check(frusta_create_world(&def, &world), "frusta_create_world")) return 1;
  frusta_hand_def hand_def = frusta_default_hand_def();
  frusta_hand_id hand;
  if (!check(frusta_create_world_hand(world, &hand_def, &hand), "frusta_create_world_hand"))
    return 1;
  for (int o = 0; o < rec.object_count; ++o) {
    object_row* obj = &rec.objects[o];
    char path[4096];
    snprintf(path, sizeof path, "%s/%s.frtree", argv[2], obj->sample);
    if (!check(frusta_create_sphere_tree_from_file(path, &obj->tree), path)) return 1;
    if (!check(frusta_create_object(world, obj->tree, &obj->def, &obj->id), obj->name)) return 1;
  }
  FILE* trace = NULL;
  if (trace_path) {
    trace = fopen(trace_path, "w");
    if (!trace) {
      fprintf(stderr, "frusta_demo: cannot write %s\n", trace_path);
      return 1;
    }
    fprintf(trace, "time_s,step,step_us,overruns,contacts,penetration_mm");
    for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) fprintf(trace, ",%s_N", kFingerNames[f]);
    fprintf(trace, ",palm_N,marble_z_m\n");
  }

  const double duration = rec.frames[rec.frame_count - 1].time;
  printf("Frusta %d.%d.%d demo: %d objects, %.1f s of a glove recording at %.0f Hz, %s\n",
         FRUSTA_VERSION_MAJOR, FRUSTA_VERSION_MINOR, FRUSTA_VERSION_PATCH, rec.object_count,
         duration, (rec.frame_count - 1) / duration,
         host_steps ? "stepped by the host" : "the world on its own thread");
  tally t;
  memset(&t, 0, sizeof t);
  t.marble_top_z = -1e9;
  const long tick_ns = (long)(1e9 / def.rate_hz);
  const long tick_count = (long)(duration * def.rate_hz) + 1;
  double* lateness = malloc(sizeof(double) * (size_t)tick_count);
  t.jumps = malloc(sizeof(double) * (size_t)tick_count);
  t.jump_capacity = tick_count;
  int ok = lateness != NULL && t.jumps != NULL;
  if (ok && !host_steps) ok = check(frusta_world_start(world), "frusta_world_start");
  struct timespec deadline;
  clock_gettime(CLOCK_MONOTONIC, &deadline);
  /* the recording's time 0 on the world's clock: frusta_now() for its own thread; its
   * step clock (the step after n steps is at (n + 1) / rate) when this thread steps it */
  const double origin = host_steps ? 1.0 / def.rate_hz : frusta_now();
  long ticks = 0;
  for (long tick = 0; ok && tick < tick_count; ++tick) {
    const double now = (double)tick * 1e-9 * (double)tick_ns;
    frame glove;
    glove_at(&rec, now, &glove);
    lateness[ticks++] = host_steps ? 0.0 : frusta_now() - (origin + now);
    if (untimed)
      ok = check(frusta_world_set_haptic(world, hand, &glove.palm, glove.angles,
                                         FRUSTA_HAND_JOINT_COUNT), "set_haptic");
    else
      ok = check(frusta_world_set_haptic_at(world, hand, origin + now, &glove.palm, glove.angles,
                                            FRUSTA_HAND_JOINT_COUNT), "set_haptic_at");
    /* the host's own actions (let go of the marble) follow the hand the world plays */
    ok = ok && apply_events(&rec, world, now - (untimed && host_steps ? 0.0 : def.input_delay));
    if (ok && host_steps) ok = check(frusta_world_step(world), "frusta_world_step");
    if (ok) ok = observe(world, hand, &rec, &t, trace);
    if (!host_steps) sleep_until(&deadline, tick_ns);
  }
  if (!host_steps) frusta_world_stop(world);
  frusta_world_state state = {.struct_size = sizeof state};
  if (ok) ok = check(frusta_world_read(world, &state), "frusta_world_read");
  if (trace) fclose(trace);
  if (!ok) return 1;

  printf("\n  steps %llu in %.2f s of world time", (unsigned long long)state.step, state.time);
  if (!host_steps) printf(", achieved %.1f Hz, %lld overruns", state.achieved_rate_hz, (long long)state.overruns);
  printf("\n  step time        p50 %7.1f us   p99 %7.1f us   max %7.1f us\n", state.step_us_p50,
         state.step_us_p99, state.step_us_max);
  if (!host_steps)
    printf("  wake-up late     p50 %7.1f us   p99 %7.1f us   max %7.1f us\n", state.wake_late_us_p50,
           state.wake_late_us_p99, state.wake_late_us_max);
  printf("  deepest penetration %.4f mm (exact, against the leaves); rejected inputs %lld\n",
         1e3 * t.deepest, (long long)state.rejected_inputs);
  if (!host_steps && ticks > 0) {
    qsort(lateness, (size_t)ticks, sizeof(double), by_value);
    printf("  samples set late  p50 %7.2f ms   p99 %7.2f ms   max %7.2f ms   (input delay %.1f ms%s)\n",
           1e3 * lateness[ticks / 2], 1e3 * lateness[ticks * 99 / 100], 1e3 * lateness[ticks - 1],
           1e3 * def.input_delay, untimed ? ", untimed" : "");
    printf("  steps past the newest sample (extrapolated or held): %ld of %ld latched\n", t.late_steps,
           t.ticks);
  }
  printf("\n  %-8s %10s %10s %12s\n", "finger", "peak N", "mean N", "touching s");
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    printf("  %-8s %10.3f %10.3f %12.2f\n", kFingerNames[f], t.peak[f],
           t.touching[f] ? t.sum[f] / (double)t.touching[f] : 0.0,
           (double)t.touching[f] * 1e-9 * (double)tick_ns);
  printf("  %-8s %10.3f\n", "palm", t.peak_palm);
  if (t.jump_count > 0) {
    qsort(t.jumps, (size_t)t.jump_count, sizeof(double), by_value);
    printf("  force continuity: a finger's force changed by p99 %.3f N, max %.3f N from one step "
           "to the next (%ld steps)\n",
           t.jumps[t.jump_count * 99 / 100], t.jumps[t.jump_count - 1], t.jump_count);
  }
  const double lifted = t.marble_top_z - t.marble_start_z;
  printf("\n  marble: carried %.1f cm up in the pinch (held %.2f s), then fell onto the table, "
         "%.1f cm below where it lay, %s (%.1f mm/s)\n",
         1e2 * lifted, (double)t.marble_held * 1e-9 * (double)tick_ns,
         1e2 * (t.marble_start_z - t.marble_end_z),
         t.marble_end_speed < kAtRest ? "at rest" : "still moving", 1e3 * t.marble_end_speed);
  if (trace_path) printf("  trace: %s\n", trace_path);

  for (int o = 0; o < rec.object_count; ++o) frusta_destroy_sphere_tree(rec.objects[o].tree);
  frusta_destroy_world(world);
  free(rec.frames);
  free(lateness);
  free(t.jumps);
  if (!check_mode) return 0;
  int failed = 0;
  if (t.deepest > 1e-4) failed = fprintf(stderr, "check: the hand sank %.3f mm\n", 1e3 * t.deepest);
  if (lifted < 0.10) failed = fprintf(stderr, "check: the marble rose %.1f cm, not 10\n", 1e2 * lifted);
  if (t.marble_end_z > t.marble_start_z) failed = fprintf(stderr, "check: the marble did not fall\n");
  if (t.marble_start_z - t.marble_end_z > kTableBelowMarble)
    failed = fprintf(stderr, "check: the marble fell %.1f cm, through the table\n",
                     1e2 * (t.marble_start_z - t.marble_end_z));
  if (t.marble_end_speed >= kAtRest) failed = fprintf(stderr, "check: the marble is not at rest\n");
  if (t.peak[0] <= 0.0 || t.peak[1] <= 0.0) failed = fprintf(stderr, "check: no pinch force\n");
  if (state.rejected_inputs != 0) failed = fprintf(stderr, "check: inputs were rejected\n");
  return failed ? 1 : 0;
}
