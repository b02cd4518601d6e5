# ctest's python_install: cmake --install into a fresh prefix, then import the package contactbench from <prefix>/MODULE_DIR.
set(prefix "${BUILD_DIR}/python-install-check")
file(REMOVE_RECURSE "${prefix}")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}" --component python
                RESULT_VARIABLE status OUTPUT_QUIET)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${status})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env "PYTHONPATH=${prefix}/${MODULE_DIR}" ${PYTHON} -c
                        "import contactbench, sys; assert contactbench.__file__.startswith(sys.argv[1]), contactbench.__file__; print(contactbench.__file__)"
                        "${prefix}/${MODULE_DIR}"
                WORKING_DIRECTORY "${prefix}" RESULT_VARIABLE status)
file(REMOVE_RECURSE "${prefix}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the installed module does not import from ${prefix}/${MODULE_DIR}")
endif()
