// The source of the targets that compile the tests' precompiled headers (tests/CMakeLists.txt):
// CMake builds a header only for a target with a source; this one adds no code.
