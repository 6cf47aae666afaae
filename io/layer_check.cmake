# The io layer's floors, checked once every target exists (a wrong dependency fails the
# configure, as ui/study's Qt check does): core links nothing beyond GLM and threads; the
# readers and writers link no network library; the layers below the front ends (core, io,
# engine, lab) never link the PACS client. Its headers are on no include path but
# voxray_pacs's users', so including them elsewhere fails to compile as well.
function(voxray_check_io_layers)
  get_target_property(_links voxray_core LINK_LIBRARIES)
  foreach(_lib IN LISTS _links)
    if(NOT _lib MATCHES "^(glm::glm|Threads::Threads)$")
      message(FATAL_ERROR "voxray_core must link only GLM and threads (found ${_lib})")
    endif()
  endforeach()
  foreach(_target voxray_core voxray_io voxray_io_formats voxray_engine voxray_lab)
    if(NOT TARGET ${_target})
      continue()
    endif()
    get_target_property(_links ${_target} LINK_LIBRARIES)
    foreach(_lib IN LISTS _links)
      if(_lib MATCHES "voxray_pacs|dcmnet|CURL")
        message(FATAL_ERROR "${_target} must not link ${_lib}: network code belongs to "
          "voxray_pacs (io/pacs/), which only the front ends and their tests link")
      endif()
    endforeach()
  endforeach()
endfunction()
cmake_language(DEFER DIRECTORY ${CMAKE_SOURCE_DIR} CALL voxray_check_io_layers)
