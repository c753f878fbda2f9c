# The milestone-5 reference against independent oracles: brute-force tables and sums, finite
# differences, a GLM ray cast, hand-worked values (project tests only). Included by
# checkpoints/CMakeLists.txt once the target m5_reference exists.
add_executable(m5_oracle_tests EXCLUDE_FROM_ALL ${CMAKE_CURRENT_LIST_DIR}/oracle_tests.cpp)
target_link_libraries(m5_oracle_tests PRIVATE m5_reference glm::glm catch_main)
add_dependencies(project-tests m5_oracle_tests)
catch_discover_tests(m5_oracle_tests TEST_PREFIX "m5 oracle, " PROPERTIES LABELS project)
