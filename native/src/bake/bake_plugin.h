/* SPDX-License-Identifier: MIT
 * The baker as a plugin of the runtime library. Baking needs Embree, which exists
 * only on some platforms (Linux x86_64 here), while the runtime must run everywhere a
 * Unity player does. So the runtime's frusta_create_sphere_tree_from_mesh loads the
 * baker library (libfrusta_bake.so, frusta_bake.dll) from beside itself when first
 * called, and hands it the mesh; the baker answers with the tree in the .frtree
 * format, which the runtime decodes as it would a file. Where the baker is absent the
 * call fails with FRUSTA_ERROR_UNAVAILABLE, and trees come from frusta-bake's files
 * instead.
 * This interface is private to the two libraries; its version guards against a
 * baker from another build. */
#ifndef FRUSTA_BAKE_PLUGIN_H
#define FRUSTA_BAKE_PLUGIN_H

#include "core/base.h"

#if defined(FRUSTA_BAKE_PLUGIN_BUILD)
#  if defined(_WIN32)
#    define FRUSTA_BAKE_PLUGIN_EXPORT __declspec(dllexport)
#  else
#    define FRUSTA_BAKE_PLUGIN_EXPORT __attribute__((visibility("default")))
#  endif
#else
#  define FRUSTA_BAKE_PLUGIN_EXPORT
#endif
#ifdef __cplusplus
#  define FRUSTA_BAKE_PLUGIN_API extern "C" FRUSTA_BAKE_PLUGIN_EXPORT
#else
#  define FRUSTA_BAKE_PLUGIN_API FRUSTA_BAKE_PLUGIN_EXPORT
#endif

/* bumped with any change below (2: error messages come without the code's name;
 * 3: the plugin's own parameter struct instead of frusta_bake_def; 4: progress) */
#define FRUSTA_BAKE_PLUGIN_VERSION 4

/** Called now and then from the baking thread with how far the bake has come (0..1);
 *  return 0 to go on, anything else to cancel (the bake then fails with
 *  FRUSTA_ERROR_CANCELLED). */
typedef int32_t (*frusta_bake_plugin_progress)(double fraction, void* context);

/** What to bake: frusta_bake_def's values (the runtime checked them). */
typedef struct frusta_bake_plugin_params {
  double target_error;   /* metres */
  int64_t max_leaves;
  int64_t branching;
  int64_t max_depth;
  int64_t error_samples;
  uint64_t seed;
} frusta_bake_plugin_params;

/** FRUSTA_BAKE_PLUGIN_VERSION of the baker's build. */
FRUSTA_BAKE_PLUGIN_API int32_t frusta_bake_plugin_version(void);

/** Bake as frusta_create_sphere_tree_from_mesh documents (params already checked by the
 *  runtime). On success *out_tree_file holds the tree as a .frtree file of *out_size
 *  bytes, to release with frusta_bake_plugin_free, and *out_target_met is 1 when both
 *  error figures met the target. On failure, the message is written to error (at most
 *  error_capacity bytes with the terminating NUL) without the code's name, which
 *  the caller reports with the result. progress (may be null) is called with context.
 *  Thread: any. */
FRUSTA_BAKE_PLUGIN_API frusta_result frusta_bake_plugin_bake(
    const float* vertices, int32_t vertex_count, const int32_t* indices, int32_t index_count,
    const frusta_bake_plugin_params* params, frusta_bake_plugin_progress progress,
    void* context, uint8_t** out_tree_file, int64_t* out_size, int32_t* out_target_met,
    char* error, int32_t error_capacity);

/** Release what frusta_bake_plugin_bake returned (null is ignored). Thread: any. */
FRUSTA_BAKE_PLUGIN_API void frusta_bake_plugin_free(uint8_t* tree_file);

#endif
