// SPDX-License-Identifier: MIT
// Bake jobs (a bake on a thread of its own, with progress and cancel) and trees from
// memory, through the C ABI: a job makes the tree a blocking bake makes, its progress
// only grows and ends at 1, a cancelled job gives no tree whenever it was cancelled,
// the mesh is the job's own copy, and a file's bytes make the tree the file makes.
// No timing: the tests wait for the state they check.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <thread>
#include <vector>

#include "frusta/frusta.h"
#include "scenes/cube_mesh.h"

namespace {

using frusta_test::kCubeIndices;
using frusta_test::kCubeVertices;

frusta_bake_def cube_def() {
  frusta_bake_def def = frusta_default_bake_def();
  def.error_samples = 20000;
  return def;
}

std::vector<frusta_sphere> leaves(frusta_tree_id tree) {
  int32_t count = 0;
  EXPECT_EQ(frusta_sphere_tree_get_leaves(tree, nullptr, 0, &count), FRUSTA_OK);
  std::vector<frusta_sphere> out(static_cast<size_t>(count));
  EXPECT_EQ(frusta_sphere_tree_get_leaves(tree, out.data(), count, &count), FRUSTA_OK);
  return out;
}

void expect_same_leaves(frusta_tree_id a, frusta_tree_id b) {
  const std::vector<frusta_sphere> la = leaves(a), lb = leaves(b);
  ASSERT_EQ(la.size(), lb.size());
  for (size_t i = 0; i < la.size(); ++i) {
    EXPECT_EQ(la[i].radius, lb[i].radius) << i;
    for (int k = 0; k < 3; ++k) EXPECT_EQ(la[i].center[k], lb[i].center[k]) << i;
  }
}

// polls until the job has ended, checking that its progress never goes back
double wait_for(frusta_bake_job_id job) {
  double last = 0.0;
  for (;;) {
    double fraction = -1.0;
    int32_t done = 0;
    EXPECT_EQ(frusta_bake_job_progress(job, &fraction, &done), FRUSTA_OK);
    EXPECT_GE(fraction, last);
    EXPECT_LE(fraction, 1.0);
    last = fraction;
    if (done) return fraction;
    std::this_thread::yield();
  }
}

TEST(capiBakeJob, AJobBakesTheTreeABlockingBakeBakesAndReportsProgressToTheEnd) {
  const frusta_bake_def def = cube_def();
  frusta_tree_id blocking{};
  ASSERT_EQ(frusta_create_sphere_tree_from_mesh(kCubeVertices, 8, kCubeIndices, 36, &def, &blocking), FRUSTA_OK)
      << frusta_last_error();
  frusta_bake_job_id job{};
  ASSERT_EQ(frusta_start_bake(kCubeVertices, 8, kCubeIndices, 36, &def, &job), FRUSTA_OK) << frusta_last_error();
  EXPECT_EQ(wait_for(job), 1.0);
  frusta_tree_id tree{};
  ASSERT_EQ(frusta_finish_bake_job(job, &tree), FRUSTA_OK) << frusta_last_error();
  expect_same_leaves(blocking, tree);
  // the job is gone with its finish
  double fraction = 0.0;
  int32_t done = 0;
  EXPECT_EQ(frusta_bake_job_progress(job, &fraction, &done), FRUSTA_ERROR_STALE_ID);
  EXPECT_EQ(frusta_finish_bake_job(job, &tree), FRUSTA_ERROR_STALE_ID);
  frusta_destroy_sphere_tree(tree);
  frusta_destroy_sphere_tree(blocking);
}

TEST(capiBakeJob, ACancelledJobGivesNoTreeWheneverItWasCancelled) {
  // a slow bake, cancelled at once: it stops at its next progress check
  frusta_bake_def slow = cube_def();
  slow.target_error = 1e-4;
  slow.error_samples = 10000000;
  frusta_bake_job_id job{};
  ASSERT_EQ(frusta_start_bake(kCubeVertices, 8, kCubeIndices, 36, &slow, &job), FRUSTA_OK);
  ASSERT_EQ(frusta_cancel_bake_job(job), FRUSTA_OK);
  wait_for(job);
  frusta_tree_id tree{};
  EXPECT_EQ(frusta_finish_bake_job(job, &tree), FRUSTA_ERROR_CANCELLED);
  EXPECT_EQ(tree.index1, 0) << "no tree";
  // a job cancelled after it ended gives none either
  const frusta_bake_def def = cube_def();
  ASSERT_EQ(frusta_start_bake(kCubeVertices, 8, kCubeIndices, 36, &def, &job), FRUSTA_OK);
  EXPECT_EQ(wait_for(job), 1.0);
  ASSERT_EQ(frusta_cancel_bake_job(job), FRUSTA_OK);
  EXPECT_EQ(frusta_finish_bake_job(job, &tree), FRUSTA_ERROR_CANCELLED);
  EXPECT_NE(std::string(frusta_last_error()).find("cancelled"), std::string::npos) << frusta_last_error();
}

TEST(capiBakeJob, TheJobBakesItsOwnCopyOfTheMeshAndReportsTheMeshsErrorsAtTheFinish) {
  const frusta_bake_def def = cube_def();
  std::vector<float> vertices(std::begin(kCubeVertices), std::end(kCubeVertices));
  std::vector<int32_t> indices(std::begin(kCubeIndices), std::end(kCubeIndices));
  frusta_bake_job_id job{};
  ASSERT_EQ(frusta_start_bake(vertices.data(), 8, indices.data(), 36, &def, &job), FRUSTA_OK);
  // the caller's arrays change and go at once
  std::fill(vertices.begin(), vertices.end(), 1e30f);
  vertices.clear();
  vertices.shrink_to_fit();
  indices.clear();
  indices.shrink_to_fit();
  frusta_tree_id tree{}, blocking{};
  ASSERT_EQ(frusta_finish_bake_job(job, &tree), FRUSTA_OK) << frusta_last_error();
  ASSERT_EQ(frusta_create_sphere_tree_from_mesh(kCubeVertices, 8, kCubeIndices, 36, &def, &blocking), FRUSTA_OK);
  expect_same_leaves(blocking, tree);
  frusta_destroy_sphere_tree(tree);
  frusta_destroy_sphere_tree(blocking);

  const int32_t bad[] = {0, 1, 9};
  ASSERT_EQ(frusta_start_bake(kCubeVertices, 8, bad, 3, &def, &job), FRUSTA_OK);
  EXPECT_EQ(frusta_finish_bake_job(job, &tree), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_NE(std::string(frusta_last_error()).find("indices[2] is 9"), std::string::npos) << frusta_last_error();
}

TEST(capiBakeJob, JobsRunSideBySide) {
  const frusta_bake_def def = cube_def();
  frusta_bake_job_id jobs[4]{};
  for (frusta_bake_job_id& job : jobs)
    ASSERT_EQ(frusta_start_bake(kCubeVertices, 8, kCubeIndices, 36, &def, &job), FRUSTA_OK);
  frusta_tree_id first{};
  for (int i = 0; i < 4; ++i) {
    frusta_tree_id tree{};
    ASSERT_EQ(frusta_finish_bake_job(jobs[i], &tree), FRUSTA_OK) << frusta_last_error();
    if (i == 0) first = tree;
    else {
      expect_same_leaves(first, tree);
      frusta_destroy_sphere_tree(tree);
    }
  }
  frusta_destroy_sphere_tree(first);
}

TEST(capiTreeMemory, AFilesBytesMakeTheTreeTheFileMakes) {
  const frusta_bake_def def = cube_def();
  frusta_tree_id baked{};
  ASSERT_EQ(frusta_create_sphere_tree_from_mesh(kCubeVertices, 8, kCubeIndices, 36, &def, &baked), FRUSTA_OK);
  const char* path = "api_bake_job_test.frtree";
  ASSERT_EQ(frusta_sphere_tree_save(baked, path), FRUSTA_OK);
  std::ifstream in(path, std::ios::binary);
  const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::remove(path);
  frusta_tree_id tree{};
  ASSERT_EQ(frusta_create_sphere_tree_from_memory(bytes.data(), static_cast<int64_t>(bytes.size()), &tree),
            FRUSTA_OK)
      << frusta_last_error();
  expect_same_leaves(baked, tree);
  frusta_sphere_tree_info a{}, b{};
  a.struct_size = b.struct_size = sizeof a;
  ASSERT_EQ(frusta_sphere_tree_get_info(baked, &a), FRUSTA_OK);
  ASSERT_EQ(frusta_sphere_tree_get_info(tree, &b), FRUSTA_OK);
  EXPECT_EQ(a.uncovered_error, b.uncovered_error);
  EXPECT_EQ(a.target_met, b.target_met);
  // a piece of it is refused, naming the input
  EXPECT_EQ(frusta_create_sphere_tree_from_memory(bytes.data(), static_cast<int64_t>(bytes.size() / 2), &tree),
            FRUSTA_ERROR_CORRUPT_FILE);
  EXPECT_NE(std::string(frusta_last_error()).find("data"), std::string::npos) << frusta_last_error();
  frusta_destroy_sphere_tree(tree);
  frusta_destroy_sphere_tree(baked);
}

}  // namespace
