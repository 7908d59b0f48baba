// SPDX-License-Identifier: MIT
// C ABI: version, ABI check and error reporting.
#include <cstring>

#include "core/error.h"
#include "frusta/frusta.h"

FRUSTA_API int32_t frusta_version(void) { return FRUSTA_VERSION; }

FRUSTA_API int32_t frusta_abi_version(void) { return FRUSTA_ABI_VERSION; }

FRUSTA_API const char* frusta_last_error(void) { return frusta::last_error_message(); }

FRUSTA_API const char* frusta_result_name(int32_t result) {
  switch (result) {
    case FRUSTA_OK: return "FRUSTA_OK";
    case FRUSTA_ERROR_NULL_POINTER: return "FRUSTA_ERROR_NULL_POINTER";
    case FRUSTA_ERROR_STRUCT_SIZE: return "FRUSTA_ERROR_STRUCT_SIZE";
    case FRUSTA_ERROR_DEF_NOT_DEFAULTED: return "FRUSTA_ERROR_DEF_NOT_DEFAULTED";
    case FRUSTA_ERROR_NULL_ID: return "FRUSTA_ERROR_NULL_ID";
    case FRUSTA_ERROR_STALE_ID: return "FRUSTA_ERROR_STALE_ID";
    case FRUSTA_ERROR_NOT_FINITE: return "FRUSTA_ERROR_NOT_FINITE";
    case FRUSTA_ERROR_OUT_OF_RANGE: return "FRUSTA_ERROR_OUT_OF_RANGE";
    case FRUSTA_ERROR_CAPACITY: return "FRUSTA_ERROR_CAPACITY";
    case FRUSTA_ERROR_ABI_MISMATCH: return "FRUSTA_ERROR_ABI_MISMATCH";
    case FRUSTA_ERROR_OUT_OF_MEMORY: return "FRUSTA_ERROR_OUT_OF_MEMORY";
    case FRUSTA_ERROR_INTERNAL: return "FRUSTA_ERROR_INTERNAL";
    case FRUSTA_ERROR_IO: return "FRUSTA_ERROR_IO";
    case FRUSTA_ERROR_FILE_FORMAT: return "FRUSTA_ERROR_FILE_FORMAT";
    case FRUSTA_ERROR_CORRUPT_FILE: return "FRUSTA_ERROR_CORRUPT_FILE";
    case FRUSTA_ERROR_WRONG_STATE: return "FRUSTA_ERROR_WRONG_STATE";
    case FRUSTA_ERROR_UNAVAILABLE: return "FRUSTA_ERROR_UNAVAILABLE";
    default: return "FRUSTA_ERROR_UNKNOWN";
  }
}

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
    FRUSTA_NAMED_SIZE(frusta_hand_def),      FRUSTA_NAMED_SIZE(frusta_contact_query),
    FRUSTA_NAMED_SIZE(frusta_constraint),    FRUSTA_NAMED_SIZE(frusta_tree_id),
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
