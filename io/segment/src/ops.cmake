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
  # ITK in a module, libvoxray_itk.so (src/itk_module.h), loaded on the first ITK operation,
  # not linked into the programs (issue 39 item 8: every voxray-cli start loaded its
  # libraries). Beside the programs in the build tree; installed in lib/voxray.
  add_library(voxray_itk MODULE src/segment_itk.cpp src/itk_module.cpp)
  target_include_directories(voxray_itk SYSTEM PRIVATE ${ITK_INCLUDE_DIRS})
  target_link_libraries(voxray_itk PRIVATE glm::glm ${ITK_LIBRARIES})
  # Hidden: the module's own functions bind inside it, never to a program's of the same name
  # (itk_loader.cpp defines itk_ops' functions in the programs).
  set_target_properties(voxray_itk PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bin
    CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
  install(TARGETS voxray_itk LIBRARY DESTINATION lib/voxray)
  # ITK 5.2's neighbourhood iterators (ConnectedComponent's line offsets) offset a null pointer
  # of an empty helper image inside ITK's own headers: UBSan stops there before our code runs.
  # ASan stays on for this file; UBSan stays on everywhere else.
  if(VOXRAY_SANITIZE)
    target_compile_options(voxray_itk PRIVATE -fno-sanitize=pointer-overflow)
  endif()
  target_sources(voxray_segment PRIVATE src/itk_loader.cpp)
  target_link_libraries(voxray_segment PRIVATE ${CMAKE_DL_LIBS})
  add_dependencies(voxray_segment voxray_itk)  # every program that may use it gets it built
  set_property(TARGET voxray_segment PROPERTY VOXRAY_WITH_ITK ON)
else()
  target_sources(voxray_segment PRIVATE src/segment_itk_unavailable.cpp)
endif()
target_link_libraries(voxray_segment PRIVATE nlohmann_json::nlohmann_json)
