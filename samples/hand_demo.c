/* SPDX-License-Identifier: MIT */
/*
 * frusta_demo RECORDING.csv [--check]
 *
 * Plays a recorded haptic hand (palm pose + 20 joint angles per frame) against a
 * scene of object spheres, through the public C ABI only. For every frame it
 * reports how deep each finger of the haptic hand goes into the objects, and
 * compares the seed's contact test (eq. 5) and the engine's test with the exact
 * distance. Until the solver lands, this is the haptic hand: it penetrates.
 * --check exits non-zero unless the engine's test missed no contact.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "frusta/frusta.h"

#define MAX_SPHERES 4096
#define MAX_FRAMES 100000

typedef struct frame {
  double time;
  frusta_pose pose;
  double angles[FRUSTA_HAND_JOINT_COUNT];
} frame;

typedef struct recording {
  frusta_sphere spheres[MAX_SPHERES];
  int sphere_count;
  frame* frames;
  int frame_count;
} recording;

typedef struct tally {
  long pairs, exact, patent, engine;
  long patent_false_positive, patent_false_negative, engine_false_negative;
} tally;

static const char* const kFingerNames[FRUSTA_FINGER_COUNT] = {"thumb", "index", "middle",
                                                              "ring", "little"};

static double now_seconds(void) {
  struct timespec t;
  timespec_get(&t, TIME_UTC);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Parse the CSV rows 'sphere,cx,cy,cz,r' and 'frame,t,px,py,pz,qx,qy,qz,qw,a0..a19'. */
static int load_recording(const char* path, recording* rec) {
  FILE* file = fopen(path, "r");
  if (!file) {
    fprintf(stderr, "frusta_demo: cannot open %s\n", path);
    return 0;
  }
  char line[4096];
  int number = 0;
  rec->frames = malloc(sizeof(frame) * MAX_FRAMES);
  if (!rec->frames) {
    fclose(file);
    return 0;
  }
  while (fgets(line, sizeof line, file)) {
    ++number;
    if (line[0] == '#' || line[0] == '\n') continue;
    double v[3 + 4 + FRUSTA_HAND_JOINT_COUNT + 1];
    int n = 0;
    char* cursor = strchr(line, ',');
    while (cursor && n < (int)(sizeof v / sizeof v[0])) {
      v[n++] = strtod(cursor + 1, &cursor);
      cursor = strchr(cursor, ',');
    }
    if (strncmp(line, "sphere,", 7) == 0 && n == 4 && rec->sphere_count < MAX_SPHERES) {
      frusta_sphere* s = &rec->spheres[rec->sphere_count++];
      memcpy(s->center, v, sizeof s->center);
      s->radius = v[3];
    } else if (strncmp(line, "frame,", 6) == 0 && n == 8 + FRUSTA_HAND_JOINT_COUNT &&
               rec->frame_count < MAX_FRAMES) {
      frame* f = &rec->frames[rec->frame_count++];
      f->time = v[0];
      memcpy(f->pose.position, v + 1, sizeof f->pose.position);
      memcpy(f->pose.rotation, v + 4, sizeof f->pose.rotation);
      memcpy(f->angles, v + 8, sizeof f->angles);
    } else {
      fprintf(stderr, "frusta_demo: %s:%d: not a sphere or frame row\n", path, number);
      fclose(file);
      return 0;
    }
  }
  fclose(file);
  return 1;
}

static int check(frusta_result result, const char* what) {
  if (result == FRUSTA_OK) return 1;
  fprintf(stderr, "frusta_demo: %s failed: %s\n", what, frusta_last_error());
  return 0;
}

int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: frusta_demo RECORDING.csv [--check]\n");
    return 2;
  }
  const int check_mode = argc > 2 && strcmp(argv[2], "--check") == 0;
  if (!check(FRUSTA_CHECK_ABI(), "the ABI check")) return 1;

  static recording rec;
  if (!load_recording(argv[1], &rec)) return 1;

  frusta_hand_def def = frusta_default_hand_def();
  frusta_hand_id hand;
  if (!check(frusta_create_hand(&def, &hand), "frusta_create_hand")) return 1;

  printf("Frusta %d.%d.%d demo: %d object spheres, %d frames of a right hand (%.0f x %.0f mm)\n",
         FRUSTA_VERSION_MAJOR, FRUSTA_VERSION_MINOR, FRUSTA_VERSION_PATCH, rec.sphere_count,
         rec.frame_count, def.hand_length * 1e3, def.hand_breadth * 1e3);
  printf("%7s  %-42s  %s\n", "time s", "deepest penetration per finger, mm",
         "contacts exact / seed eq.5 / engine");
  printf("%7s  %8s %8s %8s %8s %8s\n", "", kFingerNames[0], kFingerNames[1], kFingerNames[2],
         kFingerNames[3], kFingerNames[4]);

  tally total = {0};
  double query_seconds = 0.0;
  frusta_segment segments[FRUSTA_HAND_SEGMENT_COUNT];
  frusta_contact_query q;
  memset(&q, 0, sizeof q);
  q.struct_size = (int32_t)sizeof q;
  for (int i = 0; i < rec.frame_count; ++i) {
    const frame* f = &rec.frames[i];
    if (!check(frusta_hand_set_palm_pose(hand, &f->pose), "frusta_hand_set_palm_pose") ||
        !check(frusta_hand_set_joint_angles(hand, f->angles, FRUSTA_HAND_JOINT_COUNT),
               "frusta_hand_set_joint_angles") ||
        !check(frusta_hand_get_segments(hand, segments, FRUSTA_HAND_SEGMENT_COUNT, NULL),
               "frusta_hand_get_segments"))
      return 1;

    tally t = {0};
    double deepest[FRUSTA_FINGER_COUNT] = {0};
    const double start = now_seconds();
    for (int s = 0; s < FRUSTA_HAND_SEGMENT_COUNT; ++s) {
      for (int k = 0; k < rec.sphere_count; ++k) {
        if (!check(frusta_query_contact(&segments[s], &rec.spheres[k], &q), "frusta_query_contact"))
          return 1;
        const int exact = q.distance <= 0.0;
        ++t.pairs;
        t.exact += exact;
        t.patent += q.patent_contact;
        t.engine += q.contact;
        t.patent_false_positive += q.patent_contact && !exact;
        t.patent_false_negative += !q.patent_contact && exact;
        t.engine_false_negative += !q.contact && exact;
        const int finger = s / FRUSTA_SEGMENTS_PER_FINGER;
        if (-q.distance > deepest[finger]) deepest[finger] = -q.distance;
      }
    }
    query_seconds += now_seconds() - start;

    if (i % 6 == 0 || i + 1 == rec.frame_count) {
      printf("%7.3f  ", f->time);
      for (int finger = 0; finger < FRUSTA_FINGER_COUNT; ++finger)
        printf("%8.2f ", deepest[finger] * 1e3);
      printf("   %3ld / %3ld / %3ld\n", t.exact, t.patent, t.engine);
    }
    total.pairs += t.pairs;
    total.exact += t.exact;
    total.patent += t.patent;
    total.engine += t.engine;
    total.patent_false_positive += t.patent_false_positive;
    total.patent_false_negative += t.patent_false_negative;
    total.engine_false_negative += t.engine_false_negative;
  }
  frusta_destroy_hand(hand);

  printf("\n%ld segment/sphere pairs, %ld in contact (exact reference)\n", total.pairs, total.exact);
  printf("seed eq. 5: %ld false positives, %ld false negatives (missed fingertip contacts)\n",
         total.patent_false_positive, total.patent_false_negative);
  printf("engine test: %ld false negatives\n", total.engine_false_negative);
  printf("full query through the C ABI: %.1f ns per pair\n",
         1e9 * query_seconds / (double)(total.pairs ? total.pairs : 1));
  printf("The haptic hand penetrates the ball: the graphic hand that does not is the solver's job.\n");
  free(rec.frames);
  if (check_mode && (total.engine_false_negative != 0 || total.exact == 0)) {
    fprintf(stderr, "frusta_demo: check failed\n");
    return 1;
  }
  return 0;
}
