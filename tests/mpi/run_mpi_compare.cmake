# One voxray-mpi frame against voxray-cli render of the same scene on one device (see
# CMakeLists.txt for the bound). Fails on either run or when a pixel differs by more.
execute_process(COMMAND ${MPIEXEC} ${MPI_FLAGS} -n ${NP} ${MPI} ${ARGS} ${MPI_ARGS} -o ${OUT}-mpi.png
  RESULT_VARIABLE rc TIMEOUT 240)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "voxray-mpi on ${NP} ranks failed (${rc})")
endif()
execute_process(COMMAND ${CLI} render ${ARGS} -o ${OUT}-one.png RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "voxray-cli render failed (${rc})")
endif()
execute_process(COMMAND ${COMPARE} ${OUT}-one.png ${OUT}-mpi.png ${MEAN} 0 ${LEVELS}
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the ${NP}-rank image differs from the one-device render")
endif()
