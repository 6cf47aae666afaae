# render --segment-tf (issue 35) on the 64^3 head phantom with run_labels_test's label map
# (label 1: a sphere of radius 12 voxels in the middle), the volume's table transparent and
# unshaded, so that only a segment's own table can show anything:
#   - without --segment-tf: every pixel the background (black);
#   - --segment-tf 1:POINTS, red and opaque at every HU: the sphere's disc exactly red, the rest
#     black (segment_tf_check.py counts them);
#   - --segment-tf 1:CT-Bone (a preset by name): an image that differs from the black one.
set(common --phantom-size 64 --size 96x72 --mode dvr --azimuth 30 --shading off
           --tf -2000:1:1:1:0,4000:1:1:1:0)
set(labels ${WORK}/labels_64.raw)
execute_process(COMMAND ${PYTHON} -c "
import sys
n = 64
out = bytearray(n * n * n)
for z in range(n):
    for y in range(n):
        for x in range(n):
            if (x - 31.5) ** 2 + (y - 31.5) ** 2 + (z - 31.5) ** 2 <= 144:
                out[(z * n + y) * n + x] = 1
open(sys.argv[1], 'wb').write(out)
" ${labels} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "could not write the label map with ${PYTHON}: run scripts/bootstrap")
endif()
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
