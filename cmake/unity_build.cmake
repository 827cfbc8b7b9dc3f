# Unity builds: a target's sources compile in batches of eight files per translation unit, so a
# batch parses its headers and instantiates the Eigen, GoogleTest and pybind11 templates its
# files share once instead of eight times. Measured in Release on 2 cores: the library and its
# readers (animkit + animkit_io) 641 s of CPU one file at a time, 407 s in batches; the unit
# tests 769 s against 337 s. The cost is that a file's own names (in its anonymous namespace)
# must differ from those of the other files of its target: helpers several files need live
# once in a shared header (src/cloth/stacked_vectors.h, core/validation.h, tests/support).
# ANIMKIT_UNITY_BUILD=OFF compiles one file at a time, which rebuilds faster after an edit of
# one file. https://cmake.org/cmake/help/v3.25/prop_tgt/UNITY_BUILD.html
option(ANIMKIT_UNITY_BUILD "Compile the large targets in unity batches of eight files" ON)

function(animkit_unity_build target)
  if(ANIMKIT_UNITY_BUILD)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 8)
  endif()
endfunction()
