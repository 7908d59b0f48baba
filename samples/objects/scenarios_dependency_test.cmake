# SPDX-License-Identifier: MIT
# The hand scenarios' library waits for the baked sample objects it loads: ninja lists
# frusta_sample_objects among what building the library needs (a dependency made where
# the target did not exist yet was silently left out, and a build of the scenarios alone
# had no trees to load).
execute_process(COMMAND ${NINJA} -C ${BUILD} -t query tests/libfrusta_hand_scenarios.a
                OUTPUT_VARIABLE query RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "ninja -t query failed (${failed}):\n${query}")
endif()
if(NOT query MATCHES "samples/objects/frusta_sample_objects")
  message(FATAL_ERROR "tests/libfrusta_hand_scenarios.a does not wait for frusta_sample_objects:\n${query}")
endif()
