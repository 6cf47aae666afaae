# voxray_embed_files(TARGET NAMESPACE FILES...)
# Turns text files (OpenCL kernels, presets) into a static library holding a
# name -> contents table, regenerated whenever one of the files changes, so the
# binaries need no files on disk at run time.
set(VOXRAY_EMBED_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/EmbedFilesScript.cmake)

function(voxray_embed_files target function_name)
  set(files ${ARGN})
  set(out ${CMAKE_CURRENT_BINARY_DIR}/${target}_embedded.cpp)
  add_custom_command(
    OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DOUT=${out} -DFUNCTION=${function_name} "-DFILES=${files}"
            -P ${VOXRAY_EMBED_SCRIPT}
    DEPENDS ${files} ${VOXRAY_EMBED_SCRIPT}
    COMMENT "Embedding ${target}"
    VERBATIM)
  add_library(${target} STATIC ${out})
endfunction()
