# MPI (Open MPI, libopenmpi-dev) and IceT as Debian ships it inside ParaView (paraview-dev:
# vtkicet headers, libvtkIceTCore/MPI-pv5.11). IceT has no CMake config of its own there and
# ParaView's pulls in all of ParaView, so its header and two libraries are found directly.
# Sets VOXRAY_MPI_FOUND and the imported target Voxray::IceT.
set(VOXRAY_MPI_FOUND OFF)
find_package(MPI COMPONENTS CXX QUIET)
file(GLOB _voxray_icet_hints /usr/include/paraview-*/vtkicet/src/include)
find_path(VOXRAY_ICET_INCLUDE_DIR IceTMPI.h HINTS ${_voxray_icet_hints})
find_library(VOXRAY_ICET_CORE NAMES IceTCore vtkIceTCore-pv5.11 vtkIceTCore-pv5.12 vtkIceTCore-pv5.10)
find_library(VOXRAY_ICET_MPI NAMES IceTMPI vtkIceTMPI-pv5.11 vtkIceTMPI-pv5.12 vtkIceTMPI-pv5.10)
if(NOT MPI_CXX_FOUND)
  message(STATUS "voxray-mpi: not built, no MPI found (apt-get install libopenmpi-dev openmpi-bin, "
                 "or scripts/bootstrap)")
elseif(NOT VOXRAY_ICET_INCLUDE_DIR OR NOT VOXRAY_ICET_CORE OR NOT VOXRAY_ICET_MPI)
  message(STATUS "voxray-mpi: not built, no IceT found (apt-get install paraview-dev, or "
                 "scripts/bootstrap; looked for IceTMPI.h and libvtkIceTCore/MPI-pv5.x)")
else()
  # IceT.h, IceTConfig.h and IceTMPI.h lie in one folder.
  add_library(Voxray::IceT INTERFACE IMPORTED)
  target_include_directories(Voxray::IceT SYSTEM INTERFACE ${VOXRAY_ICET_INCLUDE_DIR})
  target_link_libraries(Voxray::IceT INTERFACE ${VOXRAY_ICET_MPI} ${VOXRAY_ICET_CORE} MPI::MPI_CXX)
  # FindMPI's mpiexec (/usr/bin/mpiexec): Open MPI takes its prefix from the path it was
  # started by, and /bin/mpiexec (merged /usr) gives "/", which it refuses.
  set(VOXRAY_MPIEXEC ${MPIEXEC_EXECUTABLE} CACHE INTERNAL "mpiexec for the voxray-mpi tests")
  set(VOXRAY_MPI_FOUND ON)
  message(STATUS "voxray-mpi: MPI ${MPI_CXX_VERSION}, IceT ${VOXRAY_ICET_CORE}, ${VOXRAY_MPIEXEC}")
endif()
