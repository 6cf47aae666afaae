# The label-map files (NIfTI, .seg.nrrd, DICOM SEG): round trips, the independent readers of
# the venv (nibabel, pynrrd, highdicom), dciodvfy, the real pelvis series, bad inputs.
if(TARGET voxray_segment AND VOXRAY_WITH_DICOM AND VOXRAY_WITH_FORMATS)
  add_executable(voxray_segment_files_tests segment_files_test.cpp)
  target_link_libraries(voxray_segment_files_tests PRIVATE voxray_segment voxray_io
    nlohmann_json::nlohmann_json GTest::gtest_main voxray_test_support)
  target_compile_definitions(voxray_segment_files_tests PRIVATE
    VOXRAY_PYTHON="${VOXRAY_PYTHON}"
    VOXRAY_SEGMENT_CHECKER="${CMAKE_CURRENT_SOURCE_DIR}/check_segment_files.py"
    VOXRAY_DATA_DIR="${VOXRAY_DATA_DIR}")
  gtest_discover_tests(voxray_segment_files_tests DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT 600)
endif()
