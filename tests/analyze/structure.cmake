# tests of gg-cluster, gg-correlate, gg-domains (issue 3) and of the shared density grid
gg_add_test(NAME test_structure LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_density_grid.cpp
          ${CMAKE_CURRENT_LIST_DIR}/test_cluster.cpp
          ${CMAKE_CURRENT_LIST_DIR}/test_correlation.cpp
          ${CMAKE_CURRENT_LIST_DIR}/test_domains.cpp
  LIBS ggstructure)

# The tools end to end (library run_* calls, and the executables through files and pipes).
gg_add_test(NAME test_structure_tools LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_structure_tools.cpp
  LIBS ggstructure_tools)
target_compile_definitions(test_structure_tools PRIVATE
  GG_CLUSTER_EXE="$<TARGET_FILE:gg-cluster>"
  GG_CORRELATE_EXE="$<TARGET_FILE:gg-correlate>"
  GG_DOMAINS_EXE="$<TARGET_FILE:gg-domains>")
add_dependencies(test_structure_tools gg-cluster gg-correlate gg-domains)
