/* SPDX-License-Identifier: MIT */
/* hello_grasp OBJECTS_DIR: a hand closes on a baked 8 cm ball and prints the force. */
#include <stdio.h>

#include "frusta/frusta.h"

int main(int argc, char** argv) {
  char path[4096];
  snprintf(path, sizeof path, "%s/ball.frtree", argc > 1 ? argv[1] : ".");
  const frusta_world_def world_def = frusta_default_world_def(); /* 1 kHz, no gravity */
  const frusta_hand_def hand_def = frusta_default_hand_def();    /* a right hand */
  frusta_object_def ball_def = frusta_default_object_def();      /* kinematic */
  ball_def.pose.position[0] = 0.10;   /* metres, under the fingers (+x) */
  ball_def.pose.position[2] = -0.058; /* and 3 mm below the palm (-z) */
  frusta_world_id world;
  frusta_hand_id hand;
  frusta_tree_id ball;
  frusta_object_id object;
  if (FRUSTA_CHECK_ABI() || frusta_create_world(&world_def, &world) ||
      frusta_create_world_hand(world, &hand_def, &hand) ||
      frusta_create_sphere_tree_from_file(path, &ball) ||
      frusta_create_object(world, ball, &ball_def, &object)) {
    fprintf(stderr, "hello_grasp: %s\n", frusta_last_error());
    return 1;
  }
  /* the haptic hand (a glove would send it): palm still, fingers curling over 0.25 s */
  const frusta_pose palm = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0, 1.0}};
  double angles[FRUSTA_HAND_JOINT_COUNT] = {0};
  for (int step = 1; step <= 300; ++step) {
    for (int j = 0; j < FRUSTA_HAND_JOINT_COUNT; ++j) /* flexions; abductions stay 0 */
      angles[j] = j % FRUSTA_JOINTS_PER_FINGER ? 1.6 * (step < 250 ? step / 250.0 : 1.0) : 0.0;
    frusta_world_set_haptic(world, hand, &palm, angles, FRUSTA_HAND_JOINT_COUNT);
    frusta_world_step(world);
  }
  frusta_world_state state = {.struct_size = sizeof state};
  frusta_world_hand out = {.struct_size = sizeof out};
  frusta_world_read(world, &state);
  frusta_world_get_hand(world, hand, &out);
  const double* f = out.fingertip_force[FRUSTA_FINGER_INDEX];
  printf("after %.3f s: %d contacts, index fingertip force (%.3f, %.3f, %.3f) N\n", state.time,
         out.contact_count, f[0], f[1], f[2]);
  frusta_destroy_world(world);
  frusta_destroy_sphere_tree(ball);
  return out.finger_resistance[FRUSTA_FINGER_INDEX] > 0.0 ? 0 : 1;
}
