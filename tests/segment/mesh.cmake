# Surface meshes of segments (issue 34): the sphere against its formulas, the files read back
# by trimesh from the venv (VOXRAY_PYTHON).
target_sources(voxray_segment_tests PRIVATE mesh_sphere_test.cpp mesh_file_test.cpp)
target_link_libraries(voxray_segment_tests PRIVATE nlohmann_json::nlohmann_json)
target_compile_definitions(voxray_segment_tests PRIVATE
  VOXRAY_PYTHON="${VOXRAY_PYTHON}" VOXRAY_MESH_READBACK="${CMAKE_CURRENT_SOURCE_DIR}/mesh_readback.py")
if(VOXRAY_BUILD_BENCH)
  # Bone of a 512x512x400 CT to STL; a timed program printing where the time goes.
  add_executable(voxray_mesh_bench bench/mesh_bench.cpp)
  target_link_libraries(voxray_mesh_bench PRIVATE voxray_segment voxray_io)
  target_compile_definitions(voxray_mesh_bench PRIVATE VOXRAY_DATA_DIR="${VOXRAY_DATA_DIR}")
  # The same without the DICOM reader (and its libraries): reads a label map --save-mask wrote.
  add_executable(voxray_mesh_bench_mask bench/mesh_bench.cpp)
  target_link_libraries(voxray_mesh_bench_mask PRIVATE voxray_segment)
  target_compile_definitions(voxray_mesh_bench_mask PRIVATE VOXRAY_MESH_BENCH_MASK_ONLY)
  target_link_options(voxray_mesh_bench_mask PRIVATE -Wl,--as-needed)
endif()
