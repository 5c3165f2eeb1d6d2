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

# The three tools: thin mains over ggstructure_tools (reading, the frame loop, writing).
add_library(ggstructure_tools STATIC ${CMAKE_CURRENT_LIST_DIR}/structure_tools.cpp)
target_link_libraries(ggstructure_tools PUBLIC ggstructure ggcommon)
foreach(tool cluster correlate domains)
  add_executable(gg-${tool} ${CMAKE_CURRENT_LIST_DIR}/gg_${tool}_main.cpp)
  target_link_libraries(gg-${tool} PRIVATE ggstructure_tools)
endforeach()
