# Surface meshes of segments (issue 34): VTK's flying edges, windowed-sinc smoothing,
# DecimatePro and STL/PLY writers, meshoptimizer's simplifier. An object library of its own
# so that VTK's include directories and flags stay off every other target.
find_package(VTK REQUIRED COMPONENTS CommonCore CommonDataModel FiltersCore IOGeometry IOPLY)
find_package(meshoptimizer REQUIRED)
add_library(voxray_segment_mesh OBJECT src/mesh/segment_surface.cpp src/mesh/mesh_file.cpp)
target_include_directories(voxray_segment_mesh PUBLIC include)
target_link_libraries(voxray_segment_mesh PUBLIC voxray_core glm::glm
  PRIVATE ${VTK_LIBRARIES} meshoptimizer::meshoptimizer)
target_link_libraries(voxray_segment PRIVATE voxray_segment_mesh)
