# The label-map files of a segmentation (issue 34): NIfTI through the NIfTI C library, 3D
# Slicer's .seg.nrrd through Teem, binary DICOM SEG through DCMTK's dcmseg. All PRIVATE:
# segment_files.h exposes std and GLM only. The NIfTI and Teem targets are io's
# (formats.cmake); without them (VOXRAY_WITH_FORMATS/DICOM off) the files are left out.
if(TARGET voxray_nifti2 AND TARGET voxray_teem AND VOXRAY_WITH_DICOM)
  target_sources(voxray_segment PRIVATE
    ${CMAKE_CURRENT_LIST_DIR}/segment_files.cpp
    ${CMAKE_CURRENT_LIST_DIR}/files/whole_file.cpp
    ${CMAKE_CURRENT_LIST_DIR}/files/label_grid.cpp
    ${CMAKE_CURRENT_LIST_DIR}/files/nifti_labels.cpp
    ${CMAKE_CURRENT_LIST_DIR}/files/seg_nrrd.cpp
    ${CMAKE_CURRENT_LIST_DIR}/files/dicom_seg_write.cpp
    ${CMAKE_CURRENT_LIST_DIR}/files/dicom_seg_read.cpp)
  target_link_libraries(voxray_segment PRIVATE voxray_nifti2 voxray_teem DCMTK::dcmseg
    DCMTK::dcmfg DCMTK::dcmiod DCMTK::dcmdata)
  target_compile_definitions(voxray_segment PUBLIC VOXRAY_HAS_SEGMENT_FILES)
endif()
