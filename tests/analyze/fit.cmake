# tests of gg-fit (issue 4): the library on synthetic data, and the executable end to end.
gg_add_test(NAME fit_test LABEL unit SOURCES ${CMAKE_CURRENT_LIST_DIR}/fit_test.cpp LIBS ggfit)
gg_add_test(NAME fit_cli_test LABEL unit SOURCES ${CMAKE_CURRENT_LIST_DIR}/fit_cli_test.cpp LIBS ggfit ggcommon)
target_compile_definitions(fit_cli_test PRIVATE GG_FIT_EXE="$<TARGET_FILE:gg-fit>")
add_dependencies(fit_cli_test gg-fit)
