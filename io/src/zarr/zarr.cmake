# OME-Zarr (issue 38 part 3): NGFF 0.4 on Zarr v2 and 0.5 on Zarr v3, read and written. Debian 12
# packages no C or C++ Zarr library (only python3-zarr), so the array layout is read here, over
# the packaged codec libraries: Blosc (libblosc, its lz4/zstd/zlib inner codecs), zstd
# (libzstd), zlib and gzip (zlib); the metadata through nlohmann_json.
find_package(ZLIB REQUIRED)
pkg_check_modules(BLOSC REQUIRED IMPORTED_TARGET blosc)
pkg_check_modules(ZSTD REQUIRED IMPORTED_TARGET libzstd)
target_sources(voxray_io PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/zarr_codecs.cpp
  ${CMAKE_CURRENT_LIST_DIR}/zarr_array.cpp
  ${CMAKE_CURRENT_LIST_DIR}/zarr_folder_store.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ome_zarr_meta.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ome_zarr_read.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ome_zarr_slices.cpp
  ${CMAKE_CURRENT_LIST_DIR}/ome_zarr_write.cpp)
target_link_libraries(voxray_io PRIVATE PkgConfig::BLOSC PkgConfig::ZSTD ZLIB::ZLIB)
target_compile_definitions(voxray_io PUBLIC VOXRAY_HAS_ZARR)
