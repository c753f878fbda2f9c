# Test: CTest lists the student's checkpoints without running the student's program (which would
# run the student's static initializers). The program is moved away while CTest lists the tests;
# every checkpoint must still be listed.  -DBUILD=<build dir> -DEXE=<checkpoints_m1> -DIDS=<checkpoint_ids>
execute_process(COMMAND ${IDS} m1 OUTPUT_VARIABLE ids RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "checkpoint_ids m1 failed")
endif()
file(RENAME ${EXE} ${EXE}.away)
execute_process(COMMAND ${CMAKE_CTEST_COMMAND} --test-dir ${BUILD} -N -L student-m1
                OUTPUT_VARIABLE listed RESULT_VARIABLE rc)
file(RENAME ${EXE}.away ${EXE})
string(REPLACE "\n" ";" ids "${ids}")
foreach(id ${ids})
  if(NOT id STREQUAL "" AND NOT listed MATCHES "Test +#[0-9]+: ${id}\n")
    message(FATAL_ERROR "${id} is not listed without the student's program:\n${listed}")
  endif()
endforeach()
message(STATUS "every m1 checkpoint is listed without running the student's program")
