# shellcheck shell=bash
# Sourced after gpu-env.sh by gpu-mpi.sh, the GPU bench script that runs voxray-mpi:
# Debian's Open MPI packed by gpu-mpi-pack.sh into build-gpu/mpi, relocated there, every
# program through the carried loader. Sets M, the mpirun command line up to the program.
R=$PWD/build-gpu/mpi
export OPAL_PREFIX=$R PMIX_INSTALL_PREFIX=$R/pmix2
export PMIX_MCA_mca_base_component_path=$R/pmix2/lib/pmix
export OMPI_MCA_mca_base_component_show_load_errors=0
export OMPI_MCA_btl=self,vader OMPI_MCA_btl_vader_single_copy_mechanism=none OMPI_MCA_pml=ob1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_plm_rsh_agent=false
LOADER="$PWD/build-gpu/lib/ld-linux-x86-64.so.2 --library-path $PWD/build-gpu/lib"
# Each rank through the loader too (orterun starts the program it is given as it is).
cat >"$R/voxray-mpi" <<WRAP
#!/bin/sh
exec $LOADER $PWD/build-gpu/bin/voxray-mpi "\$@"
WRAP
chmod +x "$R/voxray-mpi"
# shellcheck disable=SC2034  # used by the script that sources this
M="$LOADER $R/bin/orterun --oversubscribe"
