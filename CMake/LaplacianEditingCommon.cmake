# What the VTK build (../CMakeLists.txt) and the ParaView plugin build
# (../ParaView/CMakeLists.txt) share, since they compile the same module sources: compiler
# settings, output folders, the core's dependencies, and the staged module folder.
set(CMAKE_CXX_STANDARD 17)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
if (NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type" FORCE)
endif ()

include(GNUInstallDirs)
set(CMAKE_RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_BINDIR}")
set(CMAKE_LIBRARY_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}")
set(CMAKE_ARCHIVE_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}")

include("${CMAKE_CURRENT_LIST_DIR}/LaplacianEditingDependencies.cmake")

# VTK's vtk_module_build adds each module's folder as a subdirectory of the top-level project,
# so the top-level vtk.module cannot be the module folder of a project rooted at the same place.
# The standalone and ParaView builds therefore scan a staged copy: the same vtk.module, and a
# CMakeLists.txt that includes the module's code (LaplacianEditingModule.cmake).
function (laplacian_editing_stage_module module_file_variable)
  set(stage "${CMAKE_BINARY_DIR}/LaplacianEditingModule")
  get_filename_component(root "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/.." ABSOLUTE)
  configure_file("${root}/vtk.module" "${stage}/vtk.module" COPYONLY)
  file(WRITE "${stage}/CMakeLists.txt.in"
    "# Generated: the module's code lives in the source tree.\n"
    "include(\"${root}/CMake/LaplacianEditingModule.cmake\")\n")
  configure_file("${stage}/CMakeLists.txt.in" "${stage}/CMakeLists.txt" COPYONLY)
  set("${module_file_variable}" "${stage}/vtk.module" PARENT_SCOPE)
endfunction ()
