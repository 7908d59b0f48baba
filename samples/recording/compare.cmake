# SPDX-License-Identifier: MIT
# cmake -DGENERATOR=... -DBUNDLED=... -DOUT=... -DBUNDLED_GLOVE=... -DOUT_GLOVE=...
# -P compare.cmake: fails unless the generator writes exactly the bundled recordings.
execute_process(COMMAND ${GENERATOR} ${OUT} ${OUT_GLOVE} RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${GENERATOR} failed (${result})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT} ${BUNDLED} RESULT_VARIABLE differs)
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT_GLOVE} ${BUNDLED_GLOVE}
                RESULT_VARIABLE glove_differs)
if(differs OR glove_differs)
  message(FATAL_ERROR "${BUNDLED} or ${BUNDLED_GLOVE} is not what ${GENERATOR} writes: "
                      "regenerate them (frusta-make-recording ${BUNDLED} ${BUNDLED_GLOVE}) "
                      "and commit them")
endif()
