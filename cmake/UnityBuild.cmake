# Unity builds (-DCMAKE_UNITY_BUILD=ON, as scripts/test builds; CONTRIBUTING.md, Build time):
# CMake compiles each target's .cpp files CMAKE_UNITY_BUILD_BATCH_SIZE at a time (8) as one
# translation unit, unity_N_cxx.cxx, which includes them. A file that must stay out of the
# batches gets SKIP_UNITY_BUILD_INCLUSION beside its target, with the reason.
if(NOT CMAKE_UNITY_BUILD)
  return()
endif()
# GCC's -Wsubobject-linkage flags a class holding a member of an anonymous-namespace type
# when the class is defined outside the main file. In a batch every .cpp is an included file,
# so it fires on sound code (an Impl holding its file's own types) that a build file by file
# never warns about.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  add_compile_options(-Wno-subobject-linkage)
endif()
