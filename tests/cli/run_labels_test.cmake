# render --labels-raw (issue 34) on the 64^3 head phantom: a label map (label 1: a sphere of
# radius 12 voxels in the middle) written here with the venv's Python, then
#   - hide:2 with segment-blend 0 (label 2 is nowhere, so nothing changes): exactly the
#     pixels without labels (tolerance 0: the labelled kernel mixes by 0 and scales by 1);
#   - show:2 (a label nobody holds): nothing shown, exactly the pixels of a fully
#     transparent table (the background);
#   - show:1: an image that differs from both.
set(common --phantom-size 64 --size 96x72 --mode dvr --preset CT-Bone --azimuth 30)
include(${CMAKE_CURRENT_LIST_DIR}/sphere_labels_64.cmake)  # sets labels
function(render out)
  execute_process(COMMAND ${CLI} render ${common} ${ARGN} -o ${WORK}/${out} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "voxray-cli render ${ARGN} failed (${rc})")
  endif()
endfunction()
function(compare a b expect)
  execute_process(COMMAND ${COMPARE} ${WORK}/${a} ${WORK}/${b} 0 0 0 RESULT_VARIABLE rc)
  if(expect STREQUAL "same" AND NOT rc EQUAL 0)
    message(FATAL_ERROR "${b} differs from ${a}")
  elseif(expect STREQUAL "different" AND rc EQUAL 0)
    message(FATAL_ERROR "${b} is the same as ${a}")
  endif()
endfunction()
render(plain.png)
render(hide_absent.png --labels-raw ${labels} --segment-mask hide:2 --segment-blend 0)
compare(plain.png hide_absent.png same)
render(transparent.png --tf -2000:0:0:0:0,4000:0:0:0:0)
render(show_absent.png --labels-raw ${labels} --segment-mask show:2)
compare(transparent.png show_absent.png same)
render(show_sphere.png --labels-raw ${labels} --segment-mask show:1)
compare(transparent.png show_sphere.png different)
compare(plain.png show_sphere.png different)
