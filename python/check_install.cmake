# Installs the python component into a scratch prefix and imports the package from there with
# nothing of the build tree on the path: it reads the built-in case and computes its section.
#   cmake -DBUILD_DIR=.. -DPREFIX=.. -DPACKAGE_DIR=.. -DPYTHON=.. -P check_install.cmake
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX}
                        --component python
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed")
endif()
if(IS_ABSOLUTE ${PACKAGE_DIR})
  set(path ${PACKAGE_DIR})
else()
  set(path ${PREFIX}/${PACKAGE_DIR})
endif()
execute_process(
  COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${path} ${PYTHON} -c
          "import shellindent as s; assert s.__file__.startswith('${path}'), s.__file__; \
print(s.__file__, s.section(s.default_case())['vam']['A_R'][0, 0])"
  WORKING_DIRECTORY ${PREFIX}  # not the build tree's python/, which holds a package too
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the installed package does not import or run from ${path}")
endif()
