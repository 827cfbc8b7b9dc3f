# ctest's python.install: installs the build into a fresh prefix and imports animkit from there.
#   cmake -DBUILD_DIR=... -DPREFIX=... -DSITE=lib/python3.11/dist-packages -DPYTHON=... -P this
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX}
                RESULT_VARIABLE result OUTPUT_QUIET)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "cmake --install failed: ${result}")
endif()
foreach(file animkit/__init__.py animkit/__init__.pyi animkit/py.typed)
  if(NOT EXISTS ${PREFIX}/${SITE}/${file})
    message(FATAL_ERROR "the install has no ${SITE}/${file}")
  endif()
endforeach()
if(NOT EXISTS ${PREFIX}/bin/animkit)
  message(FATAL_ERROR "the install has no bin/animkit")
endif()
# -I: ignore PYTHONPATH and the user's site, so only the prefix can provide the package.
execute_process(
  COMMAND ${PYTHON} -I -c
          "import sys; sys.path.insert(0, '${PREFIX}/${SITE}'); import animkit; assert animkit.__file__.startswith('${PREFIX}'), animkit.__file__; print(animkit.__version__)"
  RESULT_VARIABLE result OUTPUT_VARIABLE version ERROR_VARIABLE error)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "import animkit from the install failed: ${error}")
endif()
message(STATUS "installed animkit ${version}")
