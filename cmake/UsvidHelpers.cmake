# usvid_add_test(NAME source.cc LIBS lib...): one GoogleTest executable, registered with CTest.
function(usvid_add_test name source)
  cmake_parse_arguments(ARG "" "" "LIBS" ${ARGN})
  add_executable(${name} ${source})
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} GTest::gtest GTest::gmock GTest::gtest_main)
  target_compile_definitions(${name} PRIVATE
    USVID_SHARED_DATA_DIR="${PROJECT_SOURCE_DIR}/../shared/data"
    USVID_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60)
endfunction()
