# The render half and the judge half run as separate processes, as a grader runs them:
# artifacts rendered by one program are judged by another, which runs no code under test.
# 1. the reference renders, the reference program judges: PASS.
# 2. the skeleton renders, the REFERENCE program judges: FAIL. The verdict follows the
#    artifacts, not whichever implementation happens to be linked into the judging process.
set(id m1.octant_3)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
function(run mode exe dir expect)
  execute_process(
    COMMAND ${CMAKE_COMMAND} -E env RASTER_CHECKPOINT_MODE=${mode} RASTER_ARTIFACTS_DIR=${WORK}/${dir}
            RASTER_RESULTS_DIR=${WORK}/results RASTER_OUTPUT_DIR=${WORK}/output ${exe} ${id}
    OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT out MATCHES "${expect}")
    message(FATAL_ERROR "${mode} with ${exe}: expected '${expect}', got:\n${out}\n${err}")
  endif()
endfunction()
run(render ${EXE} ref "")
if(NOT EXISTS ${WORK}/ref/${id}/main.png)
  message(FATAL_ERROR "render mode wrote no artifacts")
endif()
run(judge ${EXE} ref "VERDICT ${id} PASS")
run(render ${SKELETON} skel "")
run(judge ${EXE} skel "VERDICT ${id} FAIL")
message(STATUS "render/judge split works")
