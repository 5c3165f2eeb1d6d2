# tests of gg-fit (issue 4)
gg_add_test(NAME fit_test LABEL unit SOURCES ${CMAKE_CURRENT_LIST_DIR}/fit_test.cpp LIBS ggfit)
