# `make check-m1` must rebuild demo_m1 and playground_m1 (and the viewer, when VIEWER is given),
# so that the lesson's commands after it show the student's current code. Makes their sources
# newer than the programs, runs the check target (its verdicts do not matter here) and requires
# every program to be newer again. The demo and the viewer are built from the student's
# milestone files (the demo's own source is in checkpoints/demo/), so for them the student's
# lines.cpp is the source touched.
set(pairs "")
if(DEMO)
  list(APPEND pairs "${DEMO}|milestone1_lines/lines.cpp" "${PLAYGROUND}|milestone1_lines/playground.cpp")
endif()
if(VIEWER)
  list(APPEND pairs "${VIEWER}|milestone1_lines/lines.cpp")
endif()
foreach(pair ${pairs})
  string(REPLACE "|" ";" pair "${pair}")
  list(GET pair 1 source)
  execute_process(COMMAND ${CMAKE_COMMAND} -E touch ${SRC}/${source})
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 1)
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD} --target check-m1
                OUTPUT_QUIET ERROR_QUIET RESULT_VARIABLE ignored)
foreach(pair ${pairs})
  string(REPLACE "|" ";" pair "${pair}")
  list(GET pair 0 program)
  list(GET pair 1 source)
  if(NOT EXISTS ${program})
    message(FATAL_ERROR "make check-m1 did not build ${program}")
  endif()
  if(${SRC}/${source} IS_NEWER_THAN ${program})
    message(FATAL_ERROR "make check-m1 left ${program} older than ${source}: the lesson's command would show stale code")
  endif()
endforeach()
message(STATUS "make check-m1 rebuilt ${pairs}")
