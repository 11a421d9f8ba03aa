# The house's arrows point down (docs/architecture.md): fails if a file in a room includes a
# header of a room it may not use, e.g. anything below io/ including io/ or app/, or the generic
# libraries continuation/ and fitting/ including src/. Also fails for a file in src/ over
# MAX_LINES lines (one concept per file).
#   cmake -DSOURCE_DIR=<repo> -P cmake/CheckLayering.cmake
#   cmake -DSELF_TEST=ON -DWORK_DIR=<dir> -P cmake/CheckLayering.cmake   (must report a violation)
cmake_minimum_required(VERSION 3.20)

# Rooms a room may include, besides itself. Order: lowest first.
set(allowed_core "")
set(allowed_solvers "core")
set(allowed_material "core")
set(allowed_section "core;material")
set(allowed_shell "core;material;section")
set(allowed_model "core;solvers;material;section;shell")
set(allowed_contact "core;material;section;shell;model")
set(allowed_damage "core;material;section;shell;model")
set(allowed_indentation "core;solvers;material;section;shell;model;contact;damage;continuation")
set(allowed_analysis
    "core;solvers;material;section;shell;model;contact;damage;indentation;continuation;fitting")
set(allowed_io core solvers material section shell model contact damage indentation analysis
    continuation fitting)
set(allowed_app core solvers material section shell model contact damage indentation analysis io
    continuation fitting)
set(allowed_continuation "")
set(allowed_fitting "")
set(rooms core solvers material section shell model contact damage indentation analysis io app
          continuation fitting)
if(NOT MAX_LINES)
  set(MAX_LINES 500)
endif()

if(SELF_TEST)
  # A tree with one arrow pointing up and one generic library reaching into src/.
  set(SOURCE_DIR ${WORK_DIR}/layering_self_test)
  file(REMOVE_RECURSE ${SOURCE_DIR})
  file(WRITE ${SOURCE_DIR}/src/model/ok.hpp "#include \"core/error.hpp\"\n")
  file(WRITE ${SOURCE_DIR}/src/model/bad.cpp "#include <vector>\n#include \"io/case_file.hpp\"\n")
  file(WRITE ${SOURCE_DIR}/continuation/bad.hpp "#include \"model/mesh.hpp\"\n")
endif()

set(violations "")
foreach(room IN LISTS rooms)
  if(room STREQUAL "continuation" OR room STREQUAL "fitting")
    set(dir ${SOURCE_DIR}/${room})
  else()
    set(dir ${SOURCE_DIR}/src/${room})
  endif()
  file(GLOB_RECURSE files ${dir}/*.cpp ${dir}/*.hpp)
  foreach(f IN LISTS files)
    file(STRINGS ${f} includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"[^\"/]+/")
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"/]+)/.*" "\\1" target "${line}")
      if(target STREQUAL room OR NOT target IN_LIST rooms)
        continue()  # itself, or a path relative to the file ("../x/y.hpp" is not in src/)
      endif()
      if(NOT target IN_LIST allowed_${room})
        file(RELATIVE_PATH rel ${SOURCE_DIR} ${f})
        string(APPEND violations "  ${rel}: ${room}/ may not include ${target}/ (${line})\n")
      endif()
    endforeach()
    if(NOT room STREQUAL "continuation" AND NOT room STREQUAL "fitting")
      file(READ ${f} content)
      string(REGEX MATCHALL "\n" newlines "${content}")
      list(LENGTH newlines n)
      if(n GREATER MAX_LINES)
        file(RELATIVE_PATH rel ${SOURCE_DIR} ${f})
        string(APPEND violations "  ${rel}: ${n} lines, more than ${MAX_LINES}\n")
      endif()
    endif()
  endforeach()
endforeach()

if(SELF_TEST)
  if(NOT violations MATCHES "src/model/bad.cpp: model/ may not include io/" OR
     NOT violations MATCHES "continuation/bad.hpp: continuation/ may not include model/" OR
     violations MATCHES "ok.hpp")
    message(FATAL_ERROR "layering self-test: the check did not report what it must:\n${violations}")
  endif()
  file(REMOVE_RECURSE ${SOURCE_DIR})
  message(STATUS "layering self-test passed")
  return()
endif()
if(violations)
  message(FATAL_ERROR "layering check failed (docs/architecture.md):\n${violations}")
endif()
