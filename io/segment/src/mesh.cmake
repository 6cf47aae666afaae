# Surface meshes of segments (issue 34): VTK's flying edges, windowed-sinc smoothing,
# DecimatePro and STL/PLY writers, meshoptimizer's simplifier. VTK lives in a module,
# libvoxray_mesh.so (src/mesh/mesh_module.h), loaded on the first surface made or mesh file
# written, not linked into the programs: its libraries were a third of every voxray-cli
# start (issue 39 item 8). Beside the programs in the build tree; installed in lib/voxray.
find_package(VTK REQUIRED COMPONENTS CommonCore CommonDataModel FiltersCore IOGeometry IOPLY)
find_package(meshoptimizer REQUIRED)
set(_mesh ${CMAKE_CURRENT_LIST_DIR}/mesh)
add_library(voxray_mesh MODULE ${_mesh}/mesh_module.cpp ${_mesh}/segment_surface.cpp
  ${_mesh}/mesh_file.cpp ${_mesh}/mesh_plain.cpp
  # What the two files use of voxray_core and voxray_segment, compiled in (both are static
  # libraries without position-independent code).
  ${CMAKE_CURRENT_LIST_DIR}/segmentation_check.cpp
  ${PROJECT_SOURCE_DIR}/io/core/src/parallel.cpp)
target_include_directories(voxray_mesh PRIVATE ${CMAKE_CURRENT_LIST_DIR}/../include
  $<TARGET_PROPERTY:voxray_core,INTERFACE_INCLUDE_DIRECTORIES>)
target_link_libraries(voxray_mesh PRIVATE glm::glm Threads::Threads ${VTK_LIBRARIES}
  meshoptimizer::meshoptimizer)
# Hidden: the module's own functions bind inside it, never to a program's of the same name
# (mesh_loader.cpp defines makeSurface and writeMeshFile in the programs).
set_target_properties(voxray_mesh PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bin
  CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
install(TARGETS voxray_mesh LIBRARY DESTINATION lib/voxray)
# The programs: the VTK-free parts and the loader.
target_sources(voxray_segment PRIVATE ${_mesh}/mesh_plain.cpp ${_mesh}/mesh_loader.cpp)
target_link_libraries(voxray_segment PRIVATE ${CMAKE_DL_LIBS})
add_dependencies(voxray_segment voxray_mesh)  # every program that may mesh gets it built
