// SPDX-License-Identifier: MIT
// The baked objects the tests, the benchmarks and the samples' generators put in a
// world: the sample objects (samples/objects), boxes in the sizes the tests need, and
// boxes baked on the spot.
//
// The test boxes are baked once, at build time (frusta-make-test-objects), into
// FRUSTA_TEST_OBJECTS_DIR; a test loads the file, as a host loads a baked object,
// instead of baking in every test process (about a second in RelWithDebInfo, 25 s
// under ThreadSanitizer). Builds without a baker (arm64, Windows) and the sanitizer
// builds read their host build's files.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "runtime/world_def.h"
#include "spheretree/tree_file.h"

namespace frusta::scenes {

// The sample objects baked at build time (samples/objects): ball, marble, box, plate,
// tile, bowl, mug, octahedron. Loaded once per process; a missing file throws.
std::shared_ptr<const TreeFile> sample_tree(const std::string& name);
// A def for an unrotated object at `at`: static, or dynamic of `mass` kg with the
// inertia of a 3 cm cube (what a prop dropped on a table needs).
ObjectDef object_at(const vec3& at, double mass, bool dynamic);

struct TestBox {
  const char* name;
  vec3 size;            // edges, metres
  double target_error;  // metres, the bake's bound
};

// press_box: the 3 cm cube a glove's curling index presses (the device tests and bench)
// fingertip_box: a 2 cm cube a fingertip is pressed into, baked fine (0.2 mm)
// lifted_box: the 5 cm cube an open palm lifts and tips off
// pinch_plate: the 3 x 3 cm, 4 mm plate between the thumb and index pads
// room_box: 40 x 30 x 16 cm, coarse: a hand starts inside it
const std::vector<TestBox>& test_boxes();
// One of test_boxes() by name (an unknown name throws), and its tree from
// FRUSTA_TEST_OBJECTS_DIR, loaded once per process (a missing file throws).
const TestBox& test_box_spec(const std::string& name);
std::shared_ptr<const TreeFile> test_box(const std::string& name);

// A box baked now, by the baker (builds without one throw): for what sweeps the bake's
// own parameters, as the forces benchmark does, and for making the test boxes.
std::shared_ptr<const TreeFile> baked_box(const vec3& size, double target_error);

// Straight prisms whose side edges are the sharp edges a fingertip slides over
// (scenes/edge_slides.h), baked at build time like the test boxes.
struct TestPrism {
  const char* name;
  // a convex polygon (x, z), metres, extruded along y (meshes/meshes.h make_prism);
  // its vertex 0 is the edge the slides are about
  std::vector<std::pair<double, double>> section;
  double length;        // along y, metres
  double target_error;  // metres, the bake's bound
};

// hex_prism: a regular hexagon 2 cm to its corners, 6 cm long: 120-degree edges
// edge_box: a 3 x 3 cm square, 6 cm long: 90-degree edges
// wedge: a right triangle with a 30-degree corner, legs 4 and 2.3 cm, 6 cm long
const std::vector<TestPrism>& test_prisms();
const TestPrism& test_prism_spec(const std::string& name);
std::shared_ptr<const TreeFile> test_prism(const std::string& name);
// A prism baked now (builds without the baker throw): for making the test prisms.
std::shared_ptr<const TreeFile> baked_prism(const TestPrism& prism);

}  // namespace frusta::scenes
