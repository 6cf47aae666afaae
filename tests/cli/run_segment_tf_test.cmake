# render --segment-tf (issue 35) on the 64^3 head phantom with sphere_labels_64.cmake's label map
# (label 1: a sphere of radius 12 voxels in the middle), the volume's table transparent and
# unshaded, so that only a segment's own table can show anything:
#   - without --segment-tf: every pixel the background (black);
#   - --segment-tf 1:POINTS, red and opaque at every HU: the sphere's disc exactly red, the rest
#     black (segment_tf_check.py counts them);
#   - --segment-tf 1:CT-Bone (a preset by name): an image that differs from the black one.
set(common --phantom-size 64 --size 96x72 --mode dvr --azimuth 30 --shading off
           --tf -2000:1:1:1:0,4000:1:1:1:0)
include(${CMAKE_CURRENT_LIST_DIR}/sphere_labels_64.cmake)  # sets labels
function(render out)
  execute_process(COMMAND ${CLI} render ${common} --labels-raw ${labels} ${ARGN}
                  -o ${WORK}/${out} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "voxray-cli render ${ARGN} failed (${rc})")
  endif()
endfunction()
render(none.png)
render(red.png --segment-tf "1:-2000:1:0:0:1,4000:1:0:0:1")
render(bone.png --segment-tf 1:CT-Bone)
execute_process(COMMAND ${PYTHON} ${CHECK} ${WORK}/none.png ${WORK}/red.png ${WORK}/bone.png
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "segment_tf_check.py failed (${rc})")
endif()
