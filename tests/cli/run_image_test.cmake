# Renders with voxray-cli, then compares with the reference (see CMakeLists.txt for the
# tolerance). Fails on either step.
execute_process(COMMAND ${CLI} render ${ARGS} -o ${OUT} RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "voxray-cli render failed (${rc})")
endif()
execute_process(COMMAND ${COMPARE} ${REF} ${OUT} 0.5 0.005 8 RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "image differs from ${REF}")
endif()
