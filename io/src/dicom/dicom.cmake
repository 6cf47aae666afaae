# DICOM import (issue 3): DCMTK parses and decodes, OpenJPEG decodes JPEG 2000 (DCMTK has
# no free JPEG 2000 codec). Both stay PRIVATE: public headers expose std and GLM only. The
# Secondary Capture writer is here too: it writes a DICOM file (dcmdata), no network.
find_package(DCMTK REQUIRED CONFIG)
pkg_check_modules(OPENJPEG REQUIRED IMPORTED_TARGET libopenjp2)
target_sources(voxray_io PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/arrived_files.cpp
  ${CMAKE_CURRENT_LIST_DIR}/bounded_load.cpp
  ${CMAKE_CURRENT_LIST_DIR}/codec_registry.cpp
  ${CMAKE_CURRENT_LIST_DIR}/dicom_import.cpp
  ${CMAKE_CURRENT_LIST_DIR}/dicom_write.cpp
  ${CMAKE_CURRENT_LIST_DIR}/file_scan.cpp
  ${CMAKE_CURRENT_LIST_DIR}/frame_header.cpp
  ${CMAKE_CURRENT_LIST_DIR}/j2k_decode.cpp
  ${CMAKE_CURRENT_LIST_DIR}/not_dicom.cpp
  ${CMAKE_CURRENT_LIST_DIR}/pixel_decode.cpp
  ${CMAKE_CURRENT_LIST_DIR}/resample.cpp
  ${CMAKE_CURRENT_LIST_DIR}/secondary_capture.cpp
  ${CMAKE_CURRENT_LIST_DIR}/series_grouping.cpp
  ${CMAKE_CURRENT_LIST_DIR}/siemens_mosaic.cpp
  ${CMAKE_CURRENT_LIST_DIR}/slice_permute.cpp
  ${CMAKE_CURRENT_LIST_DIR}/phantom_series.cpp
  ${CMAKE_CURRENT_LIST_DIR}/private_tags.cpp
  ${CMAKE_CURRENT_LIST_DIR}/stack_geometry.cpp
  ${CMAKE_CURRENT_LIST_DIR}/suv.cpp
  ${CMAKE_CURRENT_LIST_DIR}/text_decode.cpp
  ${CMAKE_CURRENT_LIST_DIR}/value_mapping.cpp)
target_link_libraries(voxray_io PRIVATE
  DCMTK::dcmdata DCMTK::dcmjpeg DCMTK::dcmjpls PkgConfig::OPENJPEG Threads::Threads)
target_compile_definitions(voxray_io PUBLIC VOXRAY_HAS_DICOM)
