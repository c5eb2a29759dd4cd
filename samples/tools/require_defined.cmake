# Shared by the samples' CTest driver scripts (run with cmake -P): stops the script with a
# message naming it and the first of the given variables its caller did not pass with -D.
function(pf_require_defined script)
  foreach(v ${ARGN})
    if(NOT DEFINED ${v})
      message(FATAL_ERROR "${script}: ${v} not set")
    endif()
  endforeach()
endfunction()
