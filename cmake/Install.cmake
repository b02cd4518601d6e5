# `cmake --install`: the libraries contactbench::core, ::bem and ::theories (and ::mpi when built with
# CB_WITH_MPI) with their headers under
# <prefix>/include/contactbench/, the contactbench program, and a CMake package so that another project can
#   find_package(contactbench 0.1 REQUIRED)
#   target_link_libraries(my_program PRIVATE contactbench::bem)
# (examples/consumer does exactly that; the test command builds it against a temporary install).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(CB_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/contactbench")

set(cb_installed_libraries contactbench_core contactbench_bem contactbench_theories)
if(CB_WITH_MPI)
  list(APPEND cb_installed_libraries contactbench_mpi)
endif()
install(TARGETS ${cb_installed_libraries}
        EXPORT contactbenchTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT contactbenchTargets NAMESPACE contactbench:: DESTINATION ${CB_INSTALL_CMAKEDIR}
        COMPONENT development)

configure_package_config_file(cmake/contactbenchConfig.cmake.in
                              "${PROJECT_BINARY_DIR}/package/contactbenchConfig.cmake"
                              INSTALL_DESTINATION ${CB_INSTALL_CMAKEDIR})
write_basic_package_version_file("${PROJECT_BINARY_DIR}/package/contactbenchConfigVersion.cmake"
                                 COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/package/contactbenchConfig.cmake"
              "${PROJECT_BINARY_DIR}/package/contactbenchConfigVersion.cmake"
              cmake/FFTWTargets.cmake cmake/FFTWMpiTargets.cmake
        DESTINATION ${CB_INSTALL_CMAKEDIR} COMPONENT development)
install(FILES README.md DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)
