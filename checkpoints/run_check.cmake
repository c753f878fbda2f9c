# `make check` / `make check-mN`: run the student's checkpoints, then print the summary table
# (verdict, image error and render time for your code and the reference) and write it as JSON.
# Invoked by the check targets with BUILD_DIR, LABEL and SUMMARY set.
file(GLOB dirs LIST_DIRECTORIES true ${BUILD_DIR}/checkpoints/run/m*_student)
foreach(d ${dirs})  # forget the previous run: its records and failure pictures
  file(REMOVE_RECURSE ${d}/checkpoint_results ${d}/checkpoint_output)
endforeach()
execute_process(
  COMMAND ${CMAKE_CTEST_COMMAND} --test-dir ${BUILD_DIR} -L "${LABEL}" --output-on-failure
  RESULT_VARIABLE ctest_result)

set(results ${BUILD_DIR}/checkpoints/run/student_results)
file(REMOVE_RECURSE ${results})
file(MAKE_DIRECTORY ${results})
foreach(d ${dirs})
  file(GLOB records ${d}/checkpoint_results/*.txt)
  if(records)
    file(COPY ${records} DESTINATION ${results})
  endif()
endforeach()
execute_process(COMMAND ${SUMMARY} ${results} ${BUILD_DIR}/check_results.json)
if(NOT ctest_result EQUAL 0)
  message(FATAL_ERROR "Some checkpoints failed: read their messages above and open the pictures they list.")
endif()
