# The modules voxray-cli loads on first use (libvoxray_oiio.so for images, libvoxray_mp4.so
# for MP4 movies, libvoxray_mesh.so for surface meshes (VTK), libvoxray_itk.so for ITK's
# operations; io/src/module/program_module.h): a program copied alone into WORK/alone finds none, and each command that needs one fails (exit 1) with the message that names
# the file, where it was looked for and what to do, leaving no file behind. With the modules
# copied beside it (BIN: the build tree's bin/) the same commands write their files: the
# module is looked for beside the program, not found by chance elsewhere.
set(alone ${WORK}/alone)
file(REMOVE_RECURSE ${alone})
file(MAKE_DIRECTORY ${alone}/out)
file(COPY ${CLI} DESTINATION ${alone})
get_filename_component(name ${CLI} NAME)
set(cli ${alone}/${name})
function(expect_missing module target out)
  execute_process(COMMAND ${cli} ${ARGN} -o ${alone}/out/${out} RESULT_VARIABLE rc
    ERROR_VARIABLE err OUTPUT_QUIET)
  if(NOT rc EQUAL 1)
    message(FATAL_ERROR "${ARGN} without ${module}: exit ${rc}, not 1 (${err})")
  endif()
  foreach(part "'s module ${module} is not beside the program nor in ../lib/voxray ("
      "${alone}/${module}: cannot open shared object file"
      "): reinstall Voxray or rebuild it (target ${target})")
    string(FIND "${err}" "${part}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "${ARGN} without ${module}: the message lacks \"${part}\": ${err}")
    endif()
  endforeach()
  file(GLOB left ${alone}/out/*)
  if(left)
    message(FATAL_ERROR "${ARGN} without ${module} left files: ${left}")
  endif()
endfunction()
set(slice slice --phantom-size 32)
set(movie movie --phantom-size 32 --cine axial --frames 4)
set(mesh segment --phantom-size 32 --threshold 0,3000)
expect_missing(libvoxray_oiio.so voxray_oiio slice.png ${slice})
expect_missing(libvoxray_mp4.so voxray_mp4 cine.mp4 ${movie})
expect_missing(libvoxray_mesh.so voxray_mesh head.stl ${mesh})
set(islands ${mesh} --keep-largest)
expect_missing(libvoxray_itk.so voxray_itk largest.labels.raw ${islands})
# Without the modules the commands that need none work: the head's label map (.labels.raw).
execute_process(COMMAND ${cli} ${mesh} -o ${alone}/out/head.labels.raw RESULT_VARIABLE rc
  ERROR_VARIABLE err OUTPUT_QUIET)
file(SIZE ${alone}/out/head.labels.raw size)
if(NOT rc EQUAL 0 OR NOT size EQUAL 32768)
  message(FATAL_ERROR "segment -o .labels.raw without the modules: exit ${rc}, ${size} bytes, "
                      "not the 32^3 labels (${err})")
endif()
file(REMOVE ${alone}/out/head.labels.raw)
# The control: beside the program, all four load.
file(COPY ${BIN}/libvoxray_oiio.so ${BIN}/libvoxray_mp4.so ${BIN}/libvoxray_mesh.so
  ${BIN}/libvoxray_itk.so DESTINATION ${alone})
foreach(run "slice.png;${slice}" "cine.mp4;${movie}" "head.stl;${mesh}"
    "largest.labels.raw;${islands}")
  list(POP_FRONT run out)
  execute_process(COMMAND ${cli} ${run} -o ${alone}/out/${out} RESULT_VARIABLE rc
    ERROR_VARIABLE err OUTPUT_QUIET)
  file(SIZE ${alone}/out/${out} size)
  if(NOT rc EQUAL 0 OR size LESS 100)
    message(FATAL_ERROR "${run} with the modules beside it: exit ${rc}, ${size} bytes (${err})")
  endif()
endforeach()
# A binary STL of N triangles is 84 + 50 N bytes: the closed surface of the head's 6,184
# voxels (a 32^3 phantom) has thousands (4,920 when this was written).
file(SIZE ${alone}/out/head.stl size)
math(EXPR triangles "(${size} - 84) / 50")
math(EXPR rest "(${size} - 84) % 50")
if(NOT rest EQUAL 0 OR triangles LESS 1000)
  message(FATAL_ERROR "head.stl with the mesh module: ${size} bytes is not a binary STL of the "
                      "head's surface (${triangles} triangles, ${rest} bytes over)")
endif()
message(STATUS "the four modules: missing is refused by name, beside the program they load")
