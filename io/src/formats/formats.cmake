# NIfTI, NRRD and MetaImage import (issue 13), each through the library made for it:
# NIfTI through the NIfTI C library (libnifti2: NIfTI-1 and NIfTI-2, the sform/qform fields as
# the header has them), NRRD through Teem (ITK 5.2's NRRD reader gets left-anterior-superior
# wrong), MetaImage through MetaIO (ITK's MetaIO library on its own: Debian's ITK headers
# refuse any compiler but GCC, which would break clang-tidy and the clang fuzz build). An
# object library of its own: ITK's include folder carries its own openjpeg.h and nifti1_io.h,
# which must not shadow the system ones for the rest of io. Nothing leaks out of io.
find_package(ZLIB REQUIRED)
# Debian 12's NIFTIConfig.cmake names /usr/lib/libznz.so.3.0.0, which the package installs
# under the multiarch folder: find the library and its headers directly instead.
find_path(NIFTI2_INCLUDE_DIR nifti2_io.h PATH_SUFFIXES nifti REQUIRED)
find_library(NIFTI2_LIBRARY nifti2 REQUIRED)
find_library(ZNZ_LIBRARY znz REQUIRED)
if(NOT TARGET voxray_nifti2)
  add_library(voxray_nifti2 INTERFACE)
  target_include_directories(voxray_nifti2 SYSTEM INTERFACE ${NIFTI2_INCLUDE_DIR})
  target_link_libraries(voxray_nifti2 INTERFACE ${NIFTI2_LIBRARY} ${ZNZ_LIBRARY} ZLIB::ZLIB m)
endif()
find_path(METAIO_INCLUDE_DIR metaImage.h PATH_SUFFIXES ITK-5.2 REQUIRED)
find_library(METAIO_LIBRARY NAMES ITKMetaIO-5.2 REQUIRED)
# Teem's CMake config (TeemUse.cmake) sets global flags; the library and headers suffice.
find_path(TEEM_INCLUDE_DIR teem/nrrd.h REQUIRED)
find_library(TEEM_LIBRARY teem REQUIRED)
# Teem with the handles and error text io's NRRD reader and segment's .seg.nrrd files share
# (io/src/teem/teem_handles.h, header-only).
if(NOT TARGET voxray_teem)
  add_library(voxray_teem INTERFACE)
  target_include_directories(voxray_teem INTERFACE ${CMAKE_CURRENT_LIST_DIR}/../teem)
  target_include_directories(voxray_teem SYSTEM INTERFACE ${TEEM_INCLUDE_DIR})
  target_link_libraries(voxray_teem INTERFACE ${TEEM_LIBRARY})
endif()

add_library(voxray_io_formats OBJECT
  ${CMAKE_CURRENT_LIST_DIR}/metaimage_read.cpp
  ${CMAKE_CURRENT_LIST_DIR}/nifti_header_check.cpp
  ${CMAKE_CURRENT_LIST_DIR}/nifti_hints.cpp
  ${CMAKE_CURRENT_LIST_DIR}/nifti_read.cpp
  ${CMAKE_CURRENT_LIST_DIR}/nrrd_header_check.cpp
  ${CMAKE_CURRENT_LIST_DIR}/nrrd_read.cpp
  ${CMAKE_CURRENT_LIST_DIR}/volume_file.cpp)
target_include_directories(voxray_io_formats PRIVATE include)
# SYSTEM: the libraries' headers are not ours to keep warning-free.
target_include_directories(voxray_io_formats SYSTEM PRIVATE ${METAIO_INCLUDE_DIR})
target_link_libraries(voxray_io_formats PRIVATE voxray_core glm::glm voxray_nifti2 ${METAIO_LIBRARY}
  voxray_teem)
target_link_libraries(voxray_io PRIVATE voxray_io_formats voxray_nifti2 ${METAIO_LIBRARY}
  voxray_teem)
target_compile_definitions(voxray_io PUBLIC VOXRAY_HAS_FORMATS)
