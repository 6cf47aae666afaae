# PACS client (issue 12): DIMSE through DCMTK dcmnet, DICOMweb through libcurl, the local
# cache of retrieved series. Both libraries stay PRIVATE.
find_package(CURL REQUIRED)
set(_voxray_pacs_sources pacs_node.cpp pacs_cache.cpp dimse_support.cpp dimse_client.cpp
  cancellable_transport.cpp pacs_messages.cpp sendable.cpp staged_series.cpp
  move_receiver.cpp http_session.cpp multipart.cpp dicom_json.cpp web_client.cpp
  secondary_capture.cpp)
list(TRANSFORM _voxray_pacs_sources PREPEND ${CMAKE_CURRENT_LIST_DIR}/)
target_sources(voxray_io PRIVATE ${_voxray_pacs_sources})
target_link_libraries(voxray_io PRIVATE DCMTK::dcmnet CURL::libcurl nlohmann_json::nlohmann_json)
