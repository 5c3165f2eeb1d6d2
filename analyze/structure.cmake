# gg-cluster, gg-correlate, gg-domains (issue 3)
# ggstructure: the analyses as plain functions of a DensityGrid (no I/O); tests call it directly.
add_library(ggstructure STATIC
  ${CMAKE_CURRENT_LIST_DIR}/cluster.cpp
  ${CMAKE_CURRENT_LIST_DIR}/correlation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/domains.cpp
)
target_include_directories(ggstructure PUBLIC ${CMAKE_CURRENT_LIST_DIR})
target_link_libraries(ggstructure PUBLIC ggcommon PRIVATE PkgConfig::FFTW3)


# The three tools: thin mains over ggstructure_tools (reading, the frame loop, writing).
add_library(ggstructure_tools STATIC ${CMAKE_CURRENT_LIST_DIR}/structure_tools.cpp)
target_link_libraries(ggstructure_tools PUBLIC ggstructure ggcommon)
foreach(tool cluster correlate domains)
  add_executable(gg-${tool} ${CMAKE_CURRENT_LIST_DIR}/gg_${tool}_main.cpp)
  target_link_libraries(gg-${tool} PRIVATE ggstructure_tools)
endforeach()

# Timing of the analyses and of the whole tools on one N = 96993, L = 512 snapshot
# (make -f Makefile.study bench; issue 3: < 50 ms analysis, < 0.3 s per tool run).
add_executable(gg-bench-structure ${CMAKE_CURRENT_LIST_DIR}/bench_structure.cpp)
target_link_libraries(gg-bench-structure PRIVATE ggstructure)
target_compile_definitions(gg-bench-structure PRIVATE
  GG_CLUSTER_EXE="$<TARGET_FILE:gg-cluster>"
  GG_CORRELATE_EXE="$<TARGET_FILE:gg-correlate>"
  GG_DOMAINS_EXE="$<TARGET_FILE:gg-domains>")
add_dependencies(gg-bench-structure gg-cluster gg-correlate gg-domains)
gg_only_outside_sanitize_tree(gg-bench-structure)
