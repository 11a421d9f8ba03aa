# Debian's SuiteSparse 5.12 ships neither a CMake config nor pkg-config files
# (../shared/docs/toolchain.md section 2), so the libraries are found by hand and
# exposed as imported targets SuiteSparse::<lib>. Headers live in include/suitesparse.
find_path(SuiteSparse_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
set(_si_suitesparse_libs umfpack cholmod klu btf amd camd colamd ccolamd suitesparseconfig)
set(_si_suitesparse_vars SuiteSparse_INCLUDE_DIR)
foreach(lib IN LISTS _si_suitesparse_libs)
  find_library(SuiteSparse_${lib}_LIBRARY ${lib})
  list(APPEND _si_suitesparse_vars SuiteSparse_${lib}_LIBRARY)
endforeach()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(SuiteSparseDeb REQUIRED_VARS ${_si_suitesparse_vars})
if(SuiteSparseDeb_FOUND)
  foreach(lib IN LISTS _si_suitesparse_libs)
    if(NOT TARGET SuiteSparse::${lib})
      add_library(SuiteSparse::${lib} UNKNOWN IMPORTED)
      set_target_properties(SuiteSparse::${lib} PROPERTIES
        IMPORTED_LOCATION "${SuiteSparse_${lib}_LIBRARY}"
        INTERFACE_INCLUDE_DIRECTORIES "${SuiteSparse_INCLUDE_DIR}")
    endif()
  endforeach()
endif()
