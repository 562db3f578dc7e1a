# usvid_test_settings(TARGET): what every test executable is compiled with: GoogleTest, OpenMP
# (so that the precompiled header below suits every test) and where the data are.
function(usvid_test_settings target)
  target_link_libraries(${target} PRIVATE GTest::gtest GTest::gmock GTest::gtest_main
                        OpenMP::OpenMP_CXX)
  target_compile_definitions(${target} PRIVATE
    USVID_SHARED_DATA_DIR="${PROJECT_SOURCE_DIR}/../shared/data"
    USVID_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
endfunction()

# usvid_add_test(NAME source.cc [JET] LIBS lib...): one GoogleTest executable, registered with
# CTest. It reuses the tests' precompiled header (usvid_test_pch, tests/CMakeLists.txt). JET: the
# source differentiates simulations with ceres::Jet, and is compiled as the library's Jet files.
function(usvid_add_test name source)
  cmake_parse_arguments(ARG "JET" "" "LIBS" ${ARGN})
  if(ARG_JET)
    add_executable(${name})
    usvid_jet_sources(${name} ${source})
  else()
    add_executable(${name} ${source})
  endif()
  target_link_libraries(${name} PRIVATE ${ARG_LIBS})
  usvid_test_settings(${name})
  target_precompile_headers(${name} REUSE_FROM usvid_test_pch)
  add_dependencies(usvid_tests ${name})
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60)
endfunction()

# Translation units that differentiate whole simulations with ceres::Jet (a fit's rollouts
# through the flattened RK4 step) are huge functions, and GCC's RTL global CSE passes grow faster
# than linearly with a function's size: on the kvlcc2 refit they took half of a 200 s compile.
# Without them the Jet steps run as many instructions or fewer (docs/performance.md#build-time).
set(USVID_JET_COMPILE_OPTIONS $<$<CXX_COMPILER_ID:GNU>:-fno-gcse;-fno-gcse-after-reload>)

# usvid_jet_sources(TARGET source.cc...): the sources of TARGET that hold such Jet code.
function(usvid_jet_sources target)
  target_sources(${target} PRIVATE ${ARGN})
  set_source_files_properties(${ARGN} TARGET_DIRECTORY ${target}
    PROPERTIES COMPILE_OPTIONS "${USVID_JET_COMPILE_OPTIONS}")
endfunction()

# usvid_per_vessel_sources(TARGET TEMPLATE): one translation unit per vessel type of
# simulators/vessel_types.h (USVID_VESSEL_TYPES), configured from TEMPLATE with @USVID_VESSEL@
# set to the type, added to TARGET as Jet sources. The typed code of every vessel then compiles
# in parallel, and a new vessel needs no new file here.
function(usvid_per_vessel_sources target template)
  set(list_file ${PROJECT_SOURCE_DIR}/simulators/vessel_types.h)
  file(STRINGS ${list_file} line REGEX "^#define USVID_VESSEL_TYPES\\(X\\)")
  string(REGEX MATCHALL "X\\([A-Za-z0-9_]+\\)" entries "${line}")
  if(NOT entries)
    message(FATAL_ERROR "no USVID_VESSEL_TYPES(X) list in ${list_file}")
  endif()
  get_filename_component(stem ${template} NAME_WE)
  set(sources "")
  foreach(entry IN LISTS entries)
    string(REGEX REPLACE "X\\(([A-Za-z0-9_]+)\\)" "\\1" USVID_VESSEL "${entry}")
    string(TOLOWER ${USVID_VESSEL} lower)
    set(out ${CMAKE_CURRENT_BINARY_DIR}/generated/${stem}_${lower}.cc)
    configure_file(${template} ${out} @ONLY)
    list(APPEND sources ${out})
  endforeach()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${list_file} ${template})
  usvid_jet_sources(${target} ${sources})
endfunction()

# usvid_precompile_headers(TARGET [CERES] [CLI] [FROM OTHER]): TARGET's files parse Eigen,
# nlohmann-json and the common standard headers once, from a precompiled header (with CERES also
# ceres.h, with CLI CLI11). Parsing them took 2-4 s per header and file, a third of a small
# file's compile. FROM: TARGET reuses OTHER's precompiled header instead of compiling its own
# (10-17 s each, docs/performance.md#build-time). GCC accepts it only where the two are compiled
# alike: both with OpenMP or both without (-fopenmp defines _OPENMP and _REENTRANT, which the
# standard headers read); otherwise it warns (-Winvalid-pch) and parses the headers anew.
function(usvid_precompile_headers target)
  cmake_parse_arguments(ARG "CERES;CLI" "FROM" "" ${ARGN})
  if(ARG_FROM)
    target_precompile_headers(${target} REUSE_FROM ${ARG_FROM})
    return()
  endif()
  set(headers <algorithm> <map> <memory> <optional> <string> <vector> <Eigen/Dense>
              <nlohmann/json.hpp>)
  if(ARG_CERES)
    list(APPEND headers <ceres/ceres.h>)
  endif()
  if(ARG_CLI)
    list(APPEND headers <CLI/CLI.hpp>)
  endif()
  target_precompile_headers(${target} PRIVATE ${headers})
endfunction()
