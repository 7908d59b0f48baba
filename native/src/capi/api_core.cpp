// SPDX-License-Identifier: MIT
// C ABI: version, ABI check and error reporting.
#include <cstring>

#include "core/error.h"
#include "frusta/frusta.h"

FRUSTA_API int32_t frusta_version(void) { return FRUSTA_VERSION; }

FRUSTA_API int32_t frusta_abi_version(void) { return FRUSTA_ABI_VERSION; }

FRUSTA_API const char* frusta_last_error(void) { return frusta::last_error_message(); }

FRUSTA_API const char* frusta_result_name(int32_t result) { return frusta::result_name(result); }


FRUSTA_API frusta_result frusta_check_abi(int32_t header_abi_version) {
  if (header_abi_version == FRUSTA_ABI_VERSION) return FRUSTA_OK;
  return frusta::fail(FRUSTA_ERROR_ABI_MISMATCH,
                      "the caller was built against ABI %d but this library (version %d) has "
                      "ABI %d: rebuild the caller with this library's frusta.h",
                      header_abi_version, FRUSTA_VERSION, FRUSTA_ABI_VERSION);
}

namespace {

struct NamedSize {
  const char* name;
  int32_t size;
};

// every struct of frusta.h; abi_layout_test checks this table covers the header
#define FRUSTA_NAMED_SIZE(type) NamedSize{#type, static_cast<int32_t>(sizeof(type))}
constexpr NamedSize kStructSizes[] = {
    FRUSTA_NAMED_SIZE(frusta_hand_id),       FRUSTA_NAMED_SIZE(frusta_pose),
    FRUSTA_NAMED_SIZE(frusta_sphere),        FRUSTA_NAMED_SIZE(frusta_segment),
    FRUSTA_NAMED_SIZE(frusta_hand_def),      FRUSTA_NAMED_SIZE(frusta_tracked_joint),
    FRUSTA_NAMED_SIZE(frusta_hand_fitter_id), FRUSTA_NAMED_SIZE(frusta_hand_fit_def),
    FRUSTA_NAMED_SIZE(frusta_hand_fit),      FRUSTA_NAMED_SIZE(frusta_contact_query),
    FRUSTA_NAMED_SIZE(frusta_constraint),    FRUSTA_NAMED_SIZE(frusta_tree_id),
    FRUSTA_NAMED_SIZE(frusta_bake_job_id),
    FRUSTA_NAMED_SIZE(frusta_bake_def),      FRUSTA_NAMED_SIZE(frusta_sphere_tree_info),
    FRUSTA_NAMED_SIZE(frusta_tree_hit),      FRUSTA_NAMED_SIZE(frusta_world_id),
    FRUSTA_NAMED_SIZE(frusta_object_id),     FRUSTA_NAMED_SIZE(frusta_world_def),
    FRUSTA_NAMED_SIZE(frusta_object_def),    FRUSTA_NAMED_SIZE(frusta_world_state),
    FRUSTA_NAMED_SIZE(frusta_world_hand),    FRUSTA_NAMED_SIZE(frusta_world_contact),
    FRUSTA_NAMED_SIZE(frusta_object_state),    FRUSTA_NAMED_SIZE(frusta_device_id),
    FRUSTA_NAMED_SIZE(frusta_device_def),      FRUSTA_NAMED_SIZE(frusta_device_status),
    FRUSTA_NAMED_SIZE(frusta_device_info),
};
#undef FRUSTA_NAMED_SIZE

}  // namespace

FRUSTA_API int32_t frusta_struct_size(const char* name) {
  if (name == nullptr) return 0;
  for (const NamedSize& entry : kStructSizes) {
    if (std::strcmp(entry.name, name) == 0) return entry.size;
  }
  return 0;
}
