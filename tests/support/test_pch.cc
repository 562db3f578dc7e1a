// The translation unit that compiles the tests' precompiled header (tests/CMakeLists.txt,
// usvid_test_pch). It holds no test: the executable is GoogleTest's main alone.
