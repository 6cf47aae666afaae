# Issue 34's operations: threshold, seeded region, islands, holes, margins, paint/erase with
# undo, statistics, the recipe and the output dispatch.
add_executable(voxray_segment_ops_tests
  ops_mask_test.cpp ops_margin_test.cpp ops_edit_test.cpp ops_stats_test.cpp ops_recipe_test.cpp)
target_link_libraries(voxray_segment_ops_tests PRIVATE voxray_segment nlohmann_json::nlohmann_json
  GTest::gtest_main)
gtest_discover_tests(voxray_segment_ops_tests DISCOVERY_TIMEOUT 60)
# The ITK operations' private header, to compare ITK's fill holes with the hand-written one.
target_include_directories(voxray_segment_ops_tests PRIVATE ${CMAKE_SOURCE_DIR}/io/segment/src)
get_target_property(_voxray_segment_itk voxray_segment VOXRAY_WITH_ITK)
if(_voxray_segment_itk)
  target_compile_definitions(voxray_segment_ops_tests PRIVATE VOXRAY_SEGMENT_WITH_ITK=1)
endif()

if(VOXRAY_BUILD_BENCH)
  find_package(benchmark REQUIRED)
  add_executable(voxray_segment_bench segment_bench.cpp)
  target_link_libraries(voxray_segment_bench PRIVATE voxray_segment benchmark::benchmark)
  target_include_directories(voxray_segment_bench PRIVATE ${CMAKE_SOURCE_DIR}/io/segment/src)
endif()
