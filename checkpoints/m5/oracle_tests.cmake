# The milestone-5 reference against independent oracles (project tests only): brute-force wrap
# tables and tent sums, block-average mipmaps, finite differences and a GLM ray cast of the uv,
# the 2x2 tangent system, a ray cast to the light, hand-worked values and the extreme inputs.
# include() this file from checkpoints/CMakeLists.txt once the target m5_reference exists.
add_executable(m5_oracle_tests EXCLUDE_FROM_ALL ${CMAKE_CURRENT_LIST_DIR}/oracle_tests.cpp)
target_link_libraries(m5_oracle_tests PRIVATE m5_reference glm::glm catch_main)
if(TARGET project-tests)
  add_dependencies(project-tests m5_oracle_tests)
else()  # included before project-tests is made: it collects this list
  set_property(GLOBAL APPEND PROPERTY RASTER_PROJECT_TEST_TARGETS m5_oracle_tests)
endif()
catch_discover_tests(m5_oracle_tests TEST_PREFIX "m5 oracle: " PROPERTIES LABELS project TIMEOUT 60)
