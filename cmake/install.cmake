# `cmake --install BUILD [--prefix DIR]`: the six tools, the libraries with their headers, a CMake
# package (find_package(GranularGas) -> GranularGas::ggstructure, ...) and a pkg-config file
# (granular-gas.pc). Headers keep the layout the sources include them by ("gg/trajectory.hpp",
# "cluster.hpp", "fit/haff.hpp", "ggsim/engine.hpp") under include/granular_gas.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(GG_INSTALL_INCLUDEDIR ${CMAKE_INSTALL_INCLUDEDIR}/granular_gas)
set(GG_LIBRARIES ggerrors ggcommon ggstructure ggfit ggsim ggexport)

# Each library's include directories are source (or build) paths: the installed package points at
# GG_INSTALL_INCLUDEDIR instead, and the headers found there are installed.
foreach(lib IN LISTS GG_LIBRARIES)
  get_target_property(dirs ${lib} INTERFACE_INCLUDE_DIRECTORIES)
  set(wrapped "")
  foreach(dir IN LISTS dirs)
    list(APPEND wrapped "$<BUILD_INTERFACE:${dir}>")
    install(DIRECTORY ${dir}/ DESTINATION ${GG_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp")
  endforeach()
  list(APPEND wrapped "$<INSTALL_INTERFACE:${GG_INSTALL_INCLUDEDIR}>")
  set_target_properties(${lib} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${wrapped}")
  target_compile_features(${lib} PUBLIC cxx_std_20)  # the headers use concepts
endforeach()

install(TARGETS gg-sim gg-cluster gg-correlate gg-domains gg-velocity gg-fit gg-export RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS ${GG_LIBRARIES} EXPORT GranularGasTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(EXPORT GranularGasTargets NAMESPACE GranularGas:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/GranularGas)
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/GranularGasConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/GranularGasConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/GranularGas)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/GranularGasConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/GranularGasConfig.cmake ${CMAKE_BINARY_DIR}/GranularGasConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/GranularGas)

# pkg-config: the libraries are static, so Libs names what they link (HDF5 by its full paths: Debian's
# HDF5 has no pkg-config file for its high-level library).
# The prefix relative to the .pc file, so that `cmake --install --prefix DIR` anywhere gives a working file.
file(RELATIVE_PATH GG_PC_TO_PREFIX /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
string(JOIN " " GG_HDF5_LIBS ${HDF5_HL_LIBRARIES} ${HDF5_C_LIBRARIES})
configure_file(${CMAKE_CURRENT_LIST_DIR}/granular-gas.pc.in ${CMAKE_BINARY_DIR}/granular-gas.pc @ONLY)
install(FILES ${CMAKE_BINARY_DIR}/granular-gas.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
