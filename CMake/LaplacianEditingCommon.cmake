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

# VTK's vtk_module_build adds each module's folder as a subdirectory named after its path below
# the top-level source folder: the repository's root, the top-level vtk.module's folder, cannot be
# a subdirectory of a project rooted there, and the ParaView project (ParaView/) is not above the
# modules. The standalone and ParaView builds therefore scan staged copies inside the build
# folder: each module's vtk.module, and a CMakeLists.txt that includes the module's own code.
function (laplacian_editing_stage_modules module_files_variable)
  get_filename_component(root "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/.." ABSOLUTE)
  set(module_files)
  foreach (module IN ITEMS "Filters:vtk.module:Filters/CMakeLists.txt"
      "FiltersParallel:Filters/Parallel/vtk.module:Filters/Parallel/CMakeLists.txt"
      "Widgets:Widgets/vtk.module:Widgets/CMakeLists.txt" "IO:IO/vtk.module:IO/CMakeLists.txt")
    string(REPLACE ":" ";" parts "${module}")
    list(GET parts 0 name)
    list(GET parts 1 module_file)
    list(GET parts 2 code)
    set(stage "${CMAKE_BINARY_DIR}/LaplacianEditingModules/${name}")
    configure_file("${root}/${module_file}" "${stage}/vtk.module" COPYONLY)
    file(WRITE "${stage}/CMakeLists.txt.in"
      "# Generated: the module's code lives in the source tree.\n"
      "include(\"${root}/${code}\")\n")
    configure_file("${stage}/CMakeLists.txt.in" "${stage}/CMakeLists.txt" COPYONLY)
    list(APPEND module_files "${stage}/vtk.module")
  endforeach ()
  set("${module_files_variable}" "${module_files}" PARENT_SCOPE)
endfunction ()
