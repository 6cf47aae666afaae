# Included by the label tests' scripts (run_labels_test, run_segment_tf_test): writes a label
# map for the 64^3 head phantom (label 1: a sphere of radius 12 voxels in the middle) with the
# venv's Python to ${WORK}/labels_64.raw, and sets labels to its path.
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
