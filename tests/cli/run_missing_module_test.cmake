# The modules voxray-cli loads on first use (libvoxray_oiio.so for images, libvoxray_mp4.so
# for MP4 movies; io/src/module/program_module.h): a program copied alone into WORK/alone
# finds neither, and each command that needs one fails (exit 1) with the message that names
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
expect_missing(libvoxray_oiio.so voxray_oiio slice.png ${slice})
expect_missing(libvoxray_mp4.so voxray_mp4 cine.mp4 ${movie})
# The control: beside the program, both load.
file(COPY ${BIN}/libvoxray_oiio.so ${BIN}/libvoxray_mp4.so DESTINATION ${alone})
foreach(run "slice.png;${slice}" "cine.mp4;${movie}")
  list(POP_FRONT run out)
  execute_process(COMMAND ${cli} ${run} -o ${alone}/out/${out} RESULT_VARIABLE rc
    ERROR_VARIABLE err OUTPUT_QUIET)
  file(SIZE ${alone}/out/${out} size)
  if(NOT rc EQUAL 0 OR size LESS 100)
    message(FATAL_ERROR "${run} with the modules beside it: exit ${rc}, ${size} bytes (${err})")
  endif()
endforeach()
message(STATUS "both modules: missing is refused by name, beside the program they load")
