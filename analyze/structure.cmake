# gg-cluster, gg-correlate, gg-domains (issue 3)
# ggstructure: the analyses as plain functions of a DensityGrid (no I/O); tests call it directly.
add_library(ggstructure STATIC
  ${CMAKE_CURRENT_LIST_DIR}/cluster.cpp
  ${CMAKE_CURRENT_LIST_DIR}/correlation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/domains.cpp
)
target_include_directories(ggstructure PUBLIC ${CMAKE_CURRENT_LIST_DIR})
target_link_libraries(ggstructure PUBLIC ggcommon PRIVATE PkgConfig::FFTW3)

# Timing of the analyses on one N = 96993, L = 512 configuration (make -f Makefile.study bench).
add_executable(gg-bench-structure ${CMAKE_CURRENT_LIST_DIR}/bench_structure.cpp)
target_link_libraries(gg-bench-structure PRIVATE ggstructure)
