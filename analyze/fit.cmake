# gg-fit (issue 4): the fitting library `ggfit` (plain vectors + GSL, no HDF5), the command-line
# layer `ggfit_tool` (CLI11 subcommands, reading and writing through ggcommon) and the thin `gg-fit`.
# In `ggfit_tool`, tool.cpp wires CLI11, each cmd_*.cpp runs one subcommand (or a pair) and
# subcommand_support.cpp holds what they share.
add_library(ggfit
  fit/series.cpp
  fit/least_squares.cpp
  fit/power_law.cpp
  fit/ensemble.cpp
  fit/onset.cpp
  fit/haff.cpp
  fit/collapse.cpp
  fit/extrapolate.cpp
)
# Only the header-only error types of common/ (gg/errors.hpp) are used, so the library does not
# link ggcommon and its tests build without HDF5.
target_include_directories(ggfit PUBLIC ${CMAKE_CURRENT_LIST_DIR} ${PROJECT_SOURCE_DIR}/common/include)
target_link_libraries(ggfit PUBLIC GSL::gsl)

add_library(ggfit_tool
  fit/tool.cpp
  fit/subcommand_support.cpp
  fit/cmd_average.cpp
  fit/cmd_power_law.cpp
  fit/cmd_onset.cpp
  fit/cmd_haff.cpp
  fit/cmd_collapse.cpp
  fit/cmd_extrapolate.cpp
  fit/cmd_table.cpp
)
target_link_libraries(ggfit_tool PUBLIC ggfit ggcommon)

add_executable(gg-fit gg_fit_main.cpp)
target_link_libraries(gg-fit PRIVATE ggfit_tool)
