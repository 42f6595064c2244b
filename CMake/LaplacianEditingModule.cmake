# The LaplacianEditing module: its sources are Filters/ (the public filters), Filters/Stages/
# (the stages of their RequestData, adapters between vtkPolyData and the numerical core),
# Filters/Parallel/ (the MPI filter and what it sends between ranks) and Widgets/ (the handle
# widget). VTK builds it as a Remote module
# through the top-level CMakeLists.txt; the standalone and ParaView builds through the staged
# module directory of laplacian_editing_stage_module (LaplacianEditingCommon.cmake).
get_filename_component(_le_root "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)

# The numerical core first: the module links it privately.
include("${_le_root}/CMake/LaplacianEditingDependencies.cmake")
add_subdirectory("${_le_root}/Filters/Numerics" "${CMAKE_CURRENT_BINARY_DIR}/Numerics")

set(classes
  Filters/vtkBumpyPlaneSource
  Filters/vtkLaplacianDeformationFilter
  Filters/vtkLaplacianLandmarkWarp
  Filters/Parallel/vtkPLaplacianDeformationFilter
  Widgets/vtkDeformationHandleRepresentation
  Widgets/vtkDeformationHandleWidget)
list(TRANSFORM classes PREPEND "${_le_root}/")
# The filters' stages and the parallel filter's helpers, not part of the module's API.
set(private_classes
  Filters/Stages/vtkLaplacianDragPreview
  Filters/Stages/vtkLaplacianEditSolver
  Filters/Stages/vtkLaplacianHandleMaps
  Filters/Stages/vtkLaplacianLandmarkBinder
  Filters/Stages/vtkLaplacianNormalRefresher
  Filters/Stages/vtkLaplacianOutputArray
  Filters/Stages/vtkLaplacianOutputWriter
  Filters/Stages/vtkLaplacianRegionSelector
  Filters/Stages/vtkLaplacianRestShape
  Filters/Stages/vtkLaplacianSurfaceAdapter
  Filters/Parallel/vtkLaplacianPieceEdit
  Widgets/vtkDeformationHandlePreview)
list(TRANSFORM private_classes PREPEND "${_le_root}/")
set(private_sources ${private_classes})
set(private_headers ${private_classes})
list(TRANSFORM private_sources APPEND ".cxx")
list(TRANSFORM private_headers APPEND ".h")

# MUMPS factors a region across the MPI processes in the parallel filter, where VTK has MPI
# (ParaView's VTK; Debian's libmumps-dev, which the ParaView stage installs).
option(LAPLACIAN_EDITING_USE_MUMPS "Use MUMPS across MPI processes when it is found" ON)
set(_le_mumps OFF)
if (LAPLACIAN_EDITING_USE_MUMPS AND TARGET VTK::ParallelMPI)
  find_path(MUMPS_INCLUDE_DIR dmumps_c.h)
  find_library(DMUMPS_LIBRARY dmumps)
  find_library(MUMPS_COMMON_LIBRARY mumps_common)
  if (MUMPS_INCLUDE_DIR AND DMUMPS_LIBRARY AND MUMPS_COMMON_LIBRARY)
    set(_le_mumps ON)
    list(APPEND private_sources "${_le_root}/Filters/Parallel/vtkLaplacianMumpsSolver.cxx")
    list(APPEND private_headers "${_le_root}/Filters/Parallel/vtkLaplacianMumpsSolver.h")
    message(STATUS "MUMPS: ${DMUMPS_LIBRARY}")
  else ()
    message(STATUS "MUMPS not found: regions are factored on one MPI process")
  endif ()
endif ()

# In the ParaView plugin the module is linked into the plugin library itself.
set(force_static)
if (LAPLACIAN_EDITING_PARAVIEW_PLUGIN)
  set(force_static FORCE_STATIC)
endif ()
vtk_module_add_module(LaplacianEditing::Deformation ${force_static}
  CLASSES ${classes}
  SOURCES ${private_sources}
  PRIVATE_HEADERS ${private_headers})
vtk_module_include(LaplacianEditing::Deformation
  PUBLIC "$<BUILD_INTERFACE:${_le_root}/Filters>" "$<BUILD_INTERFACE:${_le_root}/Filters/Parallel>"
    "$<BUILD_INTERFACE:${_le_root}/Widgets>"
  PRIVATE "${_le_root}/Filters/Stages")
vtk_module_link(LaplacianEditing::Deformation PRIVATE LaplacianEditing::Numerics)
if (_le_mumps)
  vtk_module_link(LaplacianEditing::Deformation PRIVATE
    VTK::ParallelMPI "${DMUMPS_LIBRARY}" "${MUMPS_COMMON_LIBRARY}")
  vtk_module_include(LaplacianEditing::Deformation PRIVATE "${MUMPS_INCLUDE_DIR}")
  vtk_module_definitions(LaplacianEditing::Deformation PRIVATE LAPLACIAN_EDITING_HAS_MUMPS)
endif ()
if (COMMAND paraview_add_server_manager_xmls)
  paraview_add_server_manager_xmls(XMLS "${_le_root}/ParaView/Plugin/LaplacianDeformation.xml")
endif ()
