# tests of gg-cluster, gg-correlate, gg-domains (issue 3) and of the shared density grid
gg_add_test(NAME test_structure LABEL unit
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/test_density_grid.cpp
          ${CMAKE_CURRENT_LIST_DIR}/test_cluster.cpp
          ${CMAKE_CURRENT_LIST_DIR}/test_correlation.cpp
          ${CMAKE_CURRENT_LIST_DIR}/test_domains.cpp
  LIBS ggstructure)
