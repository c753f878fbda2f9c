# `make check-m1` must rebuild demo_m1 and playground_m1, so that the lesson's commands after
# it show the student's current code. Makes their sources newer than the programs, runs the
# check target (its verdicts do not matter here) and requires both programs to be newer again.
foreach(source milestone1_lines/demo.cpp milestone1_lines/playground.cpp)
  execute_process(COMMAND ${CMAKE_COMMAND} -E touch ${SRC}/${source})
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 1)
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD} --target check-m1
                OUTPUT_QUIET ERROR_QUIET RESULT_VARIABLE ignored)
foreach(pair "${DEMO}|milestone1_lines/demo.cpp" "${PLAYGROUND}|milestone1_lines/playground.cpp")
  string(REPLACE "|" ";" pair "${pair}")
  list(GET pair 0 program)
  list(GET pair 1 source)
  if(NOT EXISTS ${program})
    message(FATAL_ERROR "make check-m1 did not build ${program}")
  endif()
  if(${SRC}/${source} IS_NEWER_THAN ${program})
    message(FATAL_ERROR "make check-m1 left ${program} older than ${source}: the lesson's demo would show stale code")
  endif()
endforeach()
message(STATUS "make check-m1 rebuilt the demo and the playground")
