# cb_public_headers(<target> <folder> [INSTALL]): makes <folder>'s headers reachable as
# "contactbench/<folder>/x.hpp", the same include path in the build tree and in an installed prefix.
#
# While building, a per-library folder of the build tree holds a link contactbench/<folder> -> the sources, and
# only that folder is on the include path: a library sees its own headers and those of the libraries it links,
# never the whole source tree (so core cannot even find bem's headers; scripts/check-layers.sh checks it too).
# Once installed, the headers are under <prefix>/include/contactbench/<folder>/.
include(GNUInstallDirs)

function(cb_public_headers target folder)
  cmake_parse_arguments(PARSE_ARGV 2 arg "INSTALL" "" "")
  set(root "${PROJECT_BINARY_DIR}/include/${folder}")
  file(MAKE_DIRECTORY "${root}/contactbench")
  if(NOT EXISTS "${root}/contactbench/${folder}")
    file(CREATE_LINK "${CMAKE_CURRENT_SOURCE_DIR}" "${root}/contactbench/${folder}" SYMBOLIC)
  endif()
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${root}>
                                              $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  if(arg_INSTALL)
    # Subfolders (core/formats/) keep their place: contactbench/core/formats/x.hpp.
    file(GLOB_RECURSE headers CONFIGURE_DEPENDS RELATIVE "${CMAKE_CURRENT_SOURCE_DIR}"
         "${CMAKE_CURRENT_SOURCE_DIR}/*.hpp")
    foreach(header IN LISTS headers)
      get_filename_component(subfolder "${header}" DIRECTORY)
      install(FILES "${CMAKE_CURRENT_SOURCE_DIR}/${header}"
              DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/contactbench/${folder}/${subfolder}"
              COMPONENT development)
    endforeach()
  endif()
endfunction()
