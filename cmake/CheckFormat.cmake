# Fails if any C++ source under src/, continuation/, fitting/, tests/, bench/ or python/ is not
# formatted according to .clang-format. Run `cmake -P cmake/CheckFormat.cmake -DFIX=ON ...` to fix in place.
file(GLOB_RECURSE files
     ${SOURCE_DIR}/src/*.cpp ${SOURCE_DIR}/src/*.hpp
     ${SOURCE_DIR}/continuation/*.cpp ${SOURCE_DIR}/continuation/*.hpp
     ${SOURCE_DIR}/fitting/*.cpp ${SOURCE_DIR}/fitting/*.hpp
     ${SOURCE_DIR}/tests/*.cpp ${SOURCE_DIR}/tests/*.hpp
     ${SOURCE_DIR}/bench/*.cpp
     ${SOURCE_DIR}/python/*.cpp ${SOURCE_DIR}/python/*.hpp)
if(FIX)
  execute_process(COMMAND ${CLANG_FORMAT} -i ${files})
  return()
endif()
execute_process(COMMAND ${CLANG_FORMAT} --dry-run -Werror ${files}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "clang-format check failed; fix with scripts/format.sh\n${err}")
endif()
