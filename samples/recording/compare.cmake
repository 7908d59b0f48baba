# SPDX-License-Identifier: MIT
# cmake -DGENERATOR=... -DBUNDLED=... -DOUT=... -P compare.cmake: fails unless the
# generator writes exactly the bundled recording.
execute_process(COMMAND ${GENERATOR} ${OUT} RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${GENERATOR} failed (${result})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT} ${BUNDLED} RESULT_VARIABLE differs)
if(differs)
  message(FATAL_ERROR "${BUNDLED} is not what ${GENERATOR} writes: regenerate it "
                      "(frusta-make-recording ${BUNDLED}) and commit it")
endif()
