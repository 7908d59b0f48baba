// SPDX-License-Identifier: MIT
// C ABI: baking a sphere tree from triangles, by the baker library where it exists
// (bake/bake_plugin.h): the runtime itself needs no Embree. A bake blocks its caller
// (frusta_create_sphere_tree_from_mesh) or runs as a job on a thread of its own, which
// reports progress and can be cancelled (an editor's progress bar).
#include <algorithm>
#include <atomic>
#include <string>
#include <thread>
#include <vector>

#include "bake/bake_params.h"
#include "capi/bake_plugin_loader.h"
#include "capi/convert.h"
#include "capi/registry.h"
#include "capi/tree_registry.h"
#include "core/error.h"
#include "core/validate.h"
#include "frusta/frusta.h"

using namespace frusta;

namespace {

// The def's one check, before the baker is loaded (bake/bake_params.h).
frusta_result read_def(const frusta_bake_def* def, frusta_bake_plugin_params* out) {
  if (frusta_result r = check_def_input(def, "frusta_bake_def")) return r;
  BakeParams params;
  copy_bake_params(*def, params);
  if (frusta_result r = check_bake_params(params)) return r;
  copy_bake_params(params, *out);
  return FRUSTA_OK;
}

// Bake through the plugin into a new tree (the mesh is checked there).
frusta_result bake(const float* vertices, int32_t vertex_count, const int32_t* indices,
                   int32_t index_count, const frusta_bake_plugin_params& params,
                   frusta_bake_plugin_progress progress, void* context,
                   std::unique_ptr<TreeObject>* out) {
  std::string why;
  const BakePlugin* plugin = bake_plugin(&why);
  if (plugin == nullptr) return fail(FRUSTA_ERROR_UNAVAILABLE, "cannot bake: %s", why.c_str());
  uint8_t* bytes = nullptr;
  int64_t size = 0;
  int32_t target_met = 0;
  char error[1024] = "";
  const frusta_result r = plugin->bake(vertices, vertex_count, indices, index_count, &params,
                                       progress, context, &bytes, &size, &target_met, error,
                                       sizeof error);
  if (r != FRUSTA_OK) return fail(r, "%s", error);  // the baker's message, without its code
  auto tree = std::make_unique<TreeObject>();
  const frusta_result decoded =
      decode_tree_file(bytes, static_cast<size_t>(size), "the baked tree", &tree->file);
  plugin->free(bytes);
  if (decoded != FRUSTA_OK) return decoded;  // the two libraries disagree: named by decode
  tree->target_met = target_met != 0;
  *out = std::move(tree);
  return FRUSTA_OK;
}

// A bake on its own thread. The thread only writes the atomics and, before `done`,
// the result; the caller reads the result after joining.
struct BakeJob {
  std::vector<float> vertices;
  std::vector<int32_t> indices;
  frusta_bake_plugin_params params{};
  std::atomic<double> fraction{0.0};
  std::atomic<bool> cancel{false};
  std::atomic<bool> done{false};
  frusta_result result = FRUSTA_OK;
  std::string message;  // the error's, without its code
  std::unique_ptr<TreeObject> tree;
  std::thread thread;

  ~BakeJob() {
    // a job never finished (the process exiting) still ends its thread
    cancel = true;
    if (thread.joinable()) thread.join();
  }

  static int32_t report(double f, void* context) {
    auto* job = static_cast<BakeJob*>(context);
    // never backwards: the bake's phases each count from their own start
    double seen = job->fraction.load(std::memory_order_relaxed);
    while (f > seen && !job->fraction.compare_exchange_weak(seen, f, std::memory_order_relaxed)) {
    }
    return job->cancel.load(std::memory_order_relaxed) ? 1 : 0;
  }

  void run() {
    result = guarded("frusta_start_bake", [&] {
      return bake(vertices.data(), static_cast<int32_t>(vertices.size() / 3), indices.data(),
                  static_cast<int32_t>(indices.size()), params, &BakeJob::report, this, &tree);
    });
    if (result != FRUSTA_OK) message = last_error_detail(result);
    if (result == FRUSTA_OK) fraction = 1.0;
    done.store(true, std::memory_order_release);
  }
};

using BakeJobRegistry = Registry<BakeJob, frusta_bake_job_id>;
BakeJobRegistry& bake_job_registry() {
  static BakeJobRegistry registry("bake job");
  return registry;
}

}  // namespace

FRUSTA_API frusta_bake_def frusta_default_bake_def(void) {
  frusta_bake_def def = blank_def<frusta_bake_def>();
  copy_bake_params(BakeParams(), def);
  return def;
}

FRUSTA_API frusta_result frusta_create_sphere_tree_from_mesh(
    const float* vertices, int32_t vertex_count, const int32_t* indices, int32_t index_count,
    const frusta_bake_def* def, frusta_tree_id* out_tree) {
  frusta_bake_plugin_params params;
  if (frusta_result r = read_def(def, &params)) return r;
  if (frusta_result r = check_pointer(out_tree, "out_tree")) return r;
  return guarded("frusta_create_sphere_tree_from_mesh", [&] {
    std::unique_ptr<TreeObject> tree;
    if (frusta_result r = bake(vertices, vertex_count, indices, index_count, params, nullptr,
                               nullptr, &tree))
      return r;
    return tree_registry().add(std::move(tree), out_tree);
  });
}

FRUSTA_API frusta_result frusta_start_bake(const float* vertices, int32_t vertex_count,
                                           const int32_t* indices, int32_t index_count,
                                           const frusta_bake_def* def,
                                           frusta_bake_job_id* out_job) {
  frusta_bake_plugin_params params;
  if (frusta_result r = read_def(def, &params)) return r;
  if (frusta_result r = check_pointer(vertices, "vertices")) return r;
  if (frusta_result r = check_pointer(indices, "indices")) return r;
  if (frusta_result r = check_pointer(out_job, "out_job")) return r;
  // the copy's size only: the bake checks the mesh itself, as a blocking bake does
  if (vertex_count < 0 || index_count < 0)
    return fail(FRUSTA_ERROR_OUT_OF_RANGE, "vertex_count is %d and index_count %d, must be >= 0",
                vertex_count, index_count);
  return guarded("frusta_start_bake", [&] {
    auto job = std::make_unique<BakeJob>();
    job->vertices.assign(vertices, vertices + 3 * static_cast<size_t>(vertex_count));
    job->indices.assign(indices, indices + static_cast<size_t>(index_count));
    job->params = params;
    // started before it is registered, so that no other caller sees the thread member
    // change; a job the registry refuses is cancelled and joined by its destructor
    BakeJob* running = job.get();
    job->thread = std::thread([running] { running->run(); });
    return bake_job_registry().add(std::move(job), out_job);
  });
}

// Progress and cancel hold the job shared: a finish on another thread cannot free it
// under them.
FRUSTA_API frusta_result frusta_bake_job_progress(frusta_bake_job_id job, double* out_fraction,
                                                  int32_t* out_done) {
  std::shared_ptr<BakeJob> j;
  if (frusta_result r = bake_job_registry().find_shared(job, &j)) return r;
  if (frusta_result r = check_pointer(out_fraction, "out_fraction")) return r;
  if (frusta_result r = check_pointer(out_done, "out_done")) return r;
  *out_done = j->done.load(std::memory_order_acquire) ? 1 : 0;
  *out_fraction = j->fraction.load(std::memory_order_relaxed);
  return FRUSTA_OK;
}

FRUSTA_API frusta_result frusta_cancel_bake_job(frusta_bake_job_id job) {
  std::shared_ptr<BakeJob> j;
  if (frusta_result r = bake_job_registry().find_shared(job, &j)) return r;
  j->cancel = true;
  return FRUSTA_OK;
}

FRUSTA_API frusta_result frusta_finish_bake_job(frusta_bake_job_id job, frusta_tree_id* out_tree) {
  std::shared_ptr<BakeJob> j;
  if (frusta_result r = bake_job_registry().find_shared(job, &j)) return r;
  if (frusta_result r = check_pointer(out_tree, "out_tree")) return r;
  // the id goes first: a second finish (or a racing one) finds it stale
  if (frusta_result r = bake_job_registry().destroy(job)) return r;
  return guarded("frusta_finish_bake_job", [&] {
    if (j->thread.joinable()) j->thread.join();
    // cancelled is cancelled, however far the bake had come: a caller that asked to stop
    // gets no tree (and a test of it no race)
    if (j->cancel) return fail(FRUSTA_ERROR_CANCELLED, "the bake job was cancelled");
    if (j->result != FRUSTA_OK) return fail(j->result, "%s", j->message.c_str());
    return tree_registry().add(std::move(j->tree), out_tree);
  });
}
