# Issue 34's operations on label maps: threshold, seeded region, islands, holes, margins,
# smoothing, paint/erase with undo patches, statistics, the recipe the CLI and the editor share,
# and the output dispatch. ITK's filters (islands, median, closing/opening) sit in their own
# object library: ITK 5.2's headers build with GCC only, so other compilers get stubs that throw.
target_sources(voxray_segment PRIVATE
  src/segment_mask.cpp
  src/segment_ops.cpp
  src/segment_margin.cpp
  src/segment_edit.cpp
  src/segment_stats.cpp
  src/segment_recipe.cpp
  src/segment_output.cpp)
# ITKConfig loads every installed module, and its HDF5 one runs a C test compile.
enable_language(C)
find_package(ITK QUIET COMPONENTS ITKCommon ITKConnectedComponents ITKLabelVoting ITKLabelMap
  ITKMathematicalMorphology ITKBinaryMathematicalMorphology)
if(ITK_FOUND AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  add_library(voxray_segment_itk OBJECT src/segment_itk.cpp)
  target_include_directories(voxray_segment_itk SYSTEM PRIVATE ${ITK_INCLUDE_DIRS})
  target_link_libraries(voxray_segment_itk PRIVATE glm::glm voxray_core)
  set_target_properties(voxray_segment_itk PROPERTIES POSITION_INDEPENDENT_CODE ON)
  # ITK 5.2's neighbourhood iterators (ConnectedComponent's line offsets) offset a null pointer
  # of an empty helper image inside ITK's own headers: UBSan stops there before our code runs.
  # ASan stays on for this file; UBSan stays on everywhere else.
  if(VOXRAY_SANITIZE)
    target_compile_options(voxray_segment_itk PRIVATE -fno-sanitize=pointer-overflow)
  endif()
  target_sources(voxray_segment PRIVATE $<TARGET_OBJECTS:voxray_segment_itk>)
  target_link_libraries(voxray_segment PRIVATE ${ITK_LIBRARIES})
  set_property(TARGET voxray_segment PROPERTY VOXRAY_WITH_ITK ON)
else()
  target_sources(voxray_segment PRIVATE src/segment_itk_unavailable.cpp)
endif()
target_link_libraries(voxray_segment PRIVATE nlohmann_json::nlohmann_json)
