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

# usvid_add_vessel_instances(TARGET TEMPLATE NAME): adds to TARGET one source generated from
# TEMPLATE (configure_file, @USVID_VESSEL_INDEX@ replaced) for each vessel type listed in
# simulators/vessel_types.h, as generated/NAME_<index>.cc: typed code instantiated once a
# vessel, in translation units that compile in parallel. The list is read from the header, so a
# new vessel needs no CMake edit.
function(usvid_add_vessel_instances target template name)
  set(list_header ${PROJECT_SOURCE_DIR}/simulators/vessel_types.h)
  file(STRINGS ${list_header} line REGEX "^#define USVID_VESSEL_TYPES")
  string(REGEX MATCHALL "X\\([A-Za-z0-9_]+\\)" entries "${line}")
  list(LENGTH entries count)
  if(count EQUAL 0)
    message(FATAL_ERROR "no vessel types found in ${list_header}")
  endif()
  math(EXPR last "${count} - 1")
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${list_header})
  foreach(USVID_VESSEL_INDEX RANGE 0 ${last})
    set(out ${CMAKE_CURRENT_BINARY_DIR}/generated/${name}_${USVID_VESSEL_INDEX}.cc)
    configure_file(${template} ${out} @ONLY)
    target_sources(${target} PRIVATE ${out})
  endforeach()
endfunction()
