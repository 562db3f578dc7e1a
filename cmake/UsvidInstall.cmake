# cmake --install: the usvid binary, the libraries and their headers with a CMake package
# (find_package(usvid), docs/python.md#install), and the Python module where python3 finds it.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(usvid_libraries usvid_core usvid_plot usvid_importers usvid_maneuvers usvid_simulators
    usvid_effects usvid_sensors usvid_simulation usvid_preprocessing usvid_methods usvid_metrics
    usvid_diagnosis usvid_design usvid_harness)
# usvid::usvid: every library, for a program that wants the whole of usvid.
add_library(usvid_all INTERFACE)
target_link_libraries(usvid_all INTERFACE ${usvid_libraries})
set_target_properties(usvid_all PROPERTIES EXPORT_NAME usvid)

install(TARGETS usvid RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS ${usvid_libraries} usvid_all EXPORT usvidTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(folder core plot importers maneuvers simulators effects sensors simulation preprocessing
        methods metrics diagnosis design harness)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${folder} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/usvid
          FILES_MATCHING PATTERN "*.h")
endforeach()
install(EXPORT usvidTargets NAMESPACE usvid:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/usvid)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/usvidConfig.cmake.in
  ${PROJECT_BINARY_DIR}/usvidConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/usvid)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/usvidConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/usvidConfig.cmake ${PROJECT_BINARY_DIR}/usvidConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/usvid)

if(USVID_BUILD_PYTHON)
  # Where this python3 looks for packages (an absolute path: DESTDIR moves it, --prefix not).
  set(USVID_PYTHON_INSTALL_DIR ${Python3_SITEARCH} CACHE PATH "Where the usvid module goes")
  install(TARGETS usvid_python LIBRARY DESTINATION ${USVID_PYTHON_INSTALL_DIR}/usvid)
  install(FILES ${PROJECT_SOURCE_DIR}/python/usvid/__init__.py
          DESTINATION ${USVID_PYTHON_INSTALL_DIR}/usvid)
endif()
