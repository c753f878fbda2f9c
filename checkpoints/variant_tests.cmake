# Scene variants (grading): fairness and sharpness of the checkpoints on seeded variants of
# every scene (RASTER_SCENE_SEED, see "Scene variants (grading)" in README.md).
#
# Included at the end of checkpoints/CMakeLists.txt, it registers (label `project`), for each
# milestone with variants and each seed in RASTER_VARIANT_SEEDS:
#   - "variant seed S: <program> passes": the reference and every correct variant pass every
#     checkpoint of the milestone (one run of the whole program);
#   - "variant seed S: skeleton fails every checkpoint: <m>": every checkpoint prints a FAIL
#     verdict for the untouched skeleton;
#   - "variant seed S: bug <name> caught by <id>": each deliberate bug fails each checkpoint its
#     must_fail: line names, with its says: concept (as "bug <name> caught by <id>" does on the
#     public scenes);
# and "scene variants: seed 0 restores the public scenes" (variant_selftest.cpp).
#
# Run with `cmake -DPROGRAM=... -DSEED=... -DWORKDIR=... -P variant_tests.cmake`, this file
# is the skeleton test's script: it lists the program's checkpoints, runs them all on the seed
# and requires a "VERDICT <id> FAIL" line for each.

if(CMAKE_SCRIPT_MODE_FILE)
  execute_process(COMMAND ${PROGRAM} --list-test-names-only WORKING_DIRECTORY ${WORKDIR}
                  OUTPUT_VARIABLE listing RESULT_VARIABLE rc)
  string(REGEX MATCHALL "m[0-9]+\\.[a-z0-9_]+" ids "${listing}")
  if(NOT ids)
    message(FATAL_ERROR "${PROGRAM} lists no checkpoints (exit ${rc}): ${listing}")
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E env RASTER_SCENE_SEED=${SEED} RASTER_WATCHDOG_SECONDS=1 ${PROGRAM}
                  WORKING_DIRECTORY ${WORKDIR} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
  set(missing "")
  foreach(id ${ids})
    string(REPLACE "." "\\." id_re "${id}")
    if(NOT out MATCHES "VERDICT ${id_re} FAIL")
      list(APPEND missing ${id})
    endif()
  endforeach()
  if(missing)
    message(FATAL_ERROR "seed ${SEED}: the skeleton does not fail: ${missing}\n${out}\n${err}")
  endif()
  list(LENGTH ids n)
  message(STATUS "seed ${SEED}: the skeleton fails all ${n} checkpoints")
  return()
endif()

if(RASTER_HANDOUT)  # a student's handout has no reference source, bugs or correct variants
  return()
endif()

set(RASTER_VARIANT_SEEDS 1 2 3 CACHE STRING "Scene seeds the project's variant tests run")
set(raster_variant_milestones m1 m2 m3 m4 m5)

foreach(m ${raster_variant_milestones})
  file(GLOB variant_files CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${m}/variants/*.variant)
  set(passing reference)
  foreach(vf ${variant_files})
    get_filename_component(name ${vf} NAME_WE)
    list(APPEND passing variant_${name})
  endforeach()
  file(GLOB bug_files CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${m}/bugs/*.bug)

  foreach(seed ${RASTER_VARIANT_SEEDS})
    foreach(v ${passing})
      set(workdir ${CMAKE_CURRENT_BINARY_DIR}/run/${m}_${v}_seed${seed})
      file(MAKE_DIRECTORY ${workdir})
      set(test "variant seed ${seed}: checkpoints_${m}_${v} passes")
      add_test(NAME "${test}" COMMAND checkpoints_${m}_${v} WORKING_DIRECTORY ${workdir})
      set_tests_properties("${test}" PROPERTIES LABELS project TIMEOUT 60
        ENVIRONMENT "RASTER_SCENE_SEED=${seed};RASTER_WATCHDOG_SECONDS=${RASTER_WATCHDOG_SECONDS}")
    endforeach()

    set(workdir ${CMAKE_CURRENT_BINARY_DIR}/run/${m}_skeleton_seed${seed})
    file(MAKE_DIRECTORY ${workdir})
    set(test "variant seed ${seed}: skeleton fails every checkpoint: ${m}")
    add_test(NAME "${test}"
      COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:checkpoints_${m}_skeleton> -DSEED=${seed}
              -DWORKDIR=${workdir} -P ${CMAKE_CURRENT_LIST_FILE})
    set_tests_properties("${test}" PROPERTIES LABELS project TIMEOUT 120)

    foreach(bug ${bug_files})
      get_filename_component(name ${bug} NAME_WE)
      file(STRINGS ${bug} must_fail REGEX "^must_fail:")
      file(STRINGS ${bug} says REGEX "^says:")
      string(REGEX REPLACE "^must_fail:[ ]*" "" must_fail "${must_fail}")
      string(REGEX REPLACE "^says:[ ]*" "" says "${says}")
      separate_arguments(must_fail)
      set(workdir ${CMAKE_CURRENT_BINARY_DIR}/run/${m}_bug_${name}_seed${seed})
      file(MAKE_DIRECTORY ${workdir})
      foreach(id ${must_fail})
        string(REPLACE "." "\\." id_re "${id}")
        set(test "variant seed ${seed}: bug ${name} caught by ${id}")
        add_test(NAME "${test}" COMMAND checkpoints_${m}_bug_${name} ${id} WORKING_DIRECTORY ${workdir})
        set_tests_properties("${test}" PROPERTIES LABELS project TIMEOUT ${RASTER_CHECKPOINT_TIMEOUT}
          ENVIRONMENT "RASTER_SCENE_SEED=${seed};RASTER_WATCHDOG_SECONDS=1"
          PASS_REGULAR_EXPRESSION "VERDICT ${id_re} FAIL concepts=[a-z ,]*${says}")
      endforeach()
    endforeach()
  endforeach()
endforeach()

# use_variant(0) after a variant gives back the public scenes, exactly; a seed gives the same
# variants every time, and they differ from the public scenes.
add_executable(variant_selftest EXCLUDE_FROM_ALL variant_selftest.cpp)
target_link_libraries(variant_selftest PRIVATE m1_scenes m2_scenes m3_scenes m4_scenes m5_scenes)
add_dependencies(project-tests variant_selftest)
add_test(NAME "scene variants: seed 0 restores the public scenes" COMMAND variant_selftest)
set_tests_properties("scene variants: seed 0 restores the public scenes" PROPERTIES LABELS project)
