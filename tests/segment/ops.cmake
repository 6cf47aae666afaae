# Issue 34's operations: threshold, seeded region, islands, holes, margins, paint/erase with
# undo, statistics, the recipe and the output dispatch.
add_executable(voxray_segment_ops_tests
  ops_mask_test.cpp ops_margin_test.cpp ops_edit_test.cpp ops_stats_test.cpp ops_recipe_test.cpp)
target_link_libraries(voxray_segment_ops_tests PRIVATE voxray_segment nlohmann_json::nlohmann_json
  GTest::gtest_main)
gtest_discover_tests(voxray_segment_ops_tests DISCOVERY_TIMEOUT 60)

if(VOXRAY_BUILD_BENCH)
  find_package(benchmark REQUIRED)
  add_executable(voxray_segment_bench segment_bench.cpp)
  target_link_libraries(voxray_segment_bench PRIVATE voxray_segment benchmark::benchmark)
endif()
