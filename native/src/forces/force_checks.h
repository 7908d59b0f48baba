// SPDX-License-Identifier: MIT
// The one check of each kind of input the forces take, each naming the field at fault in
// the thread's error. A material is checked where its object enters (check_object_def);
// poses, contacts and object poses are the solver's and the world's own output, which
// the forces assert in debug builds only.
#pragma once

#include <cstdint>

#include "core/base.h"
#include "forces/force_params.h"
#include "hand/kinematics.h"
#include "solver/hand_solver.h"

namespace frusta {

// Stiffnesses and dampings in [0, kMaxContactStiffness], friction in [0, 100]; the error
// names `name` and the field.
frusta_result check_force_material(const ForceMaterial& material, const char* name);

// Every position, frame and axis finite, the palm within kMaxCoordinate and the finger
// joints within kMaxPointCoordinate; the error names
// `which` and the field.
frusta_result check_hand_pose(const HandPose& pose, const char* which);

// what[index].object in [0, object_count) and .body a hand body.
frusta_result check_contact_ids(int32_t object, int32_t body, int32_t object_count,
                                const char* what, int32_t index);

// `count` (>= 0) contacts as a HandSolver reports them against `object_count` objects:
// ids in range, leaf >= -1, part >= 0, finite distance, points within kMaxPointCoordinate,
// unit normals.
frusta_result check_solver_contacts(const SolverContact* contacts, int32_t count,
                                    int32_t object_count);

// `count` (>= 0) objects' poses finite, positions within kMaxCoordinate, and each of
// `materials` (one per object; may be null) a valid material.
frusta_result check_force_objects(const SolverObject* objects, int32_t count,
                                  const ForceMaterial* materials);

}  // namespace frusta
