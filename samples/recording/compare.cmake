# SPDX-License-Identifier: MIT
# cmake -DGENERATOR=... -DBUNDLED=... -DOUT=... -DBUNDLED_GLOVE=... -DOUT_GLOVE=...
# -DBUNDLED_TRACKED=... -DOUT_TRACKED=... -P compare.cmake: fails unless the generator
# writes exactly the bundled recordings, byte for byte.
execute_process(COMMAND ${GENERATOR} ${OUT} ${OUT_GLOVE} ${OUT_TRACKED} RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${GENERATOR} failed (${result})")
endif()
set(stale "")
foreach(pair "${OUT};${BUNDLED}" "${OUT_GLOVE};${BUNDLED_GLOVE}" "${OUT_TRACKED};${BUNDLED_TRACKED}")
  list(GET pair 0 written)
  list(GET pair 1 bundled)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${written} ${bundled} RESULT_VARIABLE differs)
  if(differs)
    string(APPEND stale " ${bundled}")
  endif()
endforeach()
if(stale)
  message(FATAL_ERROR "not what ${GENERATOR} writes:${stale}: regenerate them "
                      "(frusta-make-recording ${BUNDLED} ${BUNDLED_GLOVE} ${BUNDLED_TRACKED}) "
                      "and commit them")
endif()
