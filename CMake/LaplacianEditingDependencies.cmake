# The numerical core's dependencies: Eigen 3, and CHOLMOD (SuiteSparse) when it is found. Included
# by the standalone and ParaView builds, and by the module's own code inside a VTK tree.
find_package(Eigen3 3.3 REQUIRED NO_MODULE)

option(LAPLACIAN_EDITING_USE_CHOLMOD "Use CHOLMOD (SuiteSparse) when it is found" ON)
if (LAPLACIAN_EDITING_USE_CHOLMOD)
  find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
  find_library(CHOLMOD_LIBRARY cholmod)
  find_library(SUITESPARSECONFIG_LIBRARY suitesparseconfig)
  if (CHOLMOD_INCLUDE_DIR AND CHOLMOD_LIBRARY AND SUITESPARSECONFIG_LIBRARY)
    set(LAPLACIAN_EDITING_CHOLMOD_INCLUDE_DIRS "${CHOLMOD_INCLUDE_DIR}")
    set(LAPLACIAN_EDITING_CHOLMOD_LIBRARIES "${CHOLMOD_LIBRARY}" "${SUITESPARSECONFIG_LIBRARY}")
    message(STATUS "CHOLMOD: ${CHOLMOD_LIBRARY}")
  else ()
    message(STATUS "CHOLMOD not found: only Eigen's SimplicialLDLT is available")
  endif ()
endif ()
