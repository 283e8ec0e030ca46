# cmake -DEXE=program -P check_not_needed.cmake: fails if EXE needs libhalfslip.so.
file(GET_RUNTIME_DEPENDENCIES EXECUTABLES "${EXE}" RESOLVED_DEPENDENCIES_VAR deps
  UNRESOLVED_DEPENDENCIES_VAR unresolved)
foreach(d IN LISTS deps unresolved)
  if(d MATCHES "libhalfslip")
    message(FATAL_ERROR "${EXE} needs ${d} at run time")
  endif()
endforeach()
message(STATUS "${EXE}: no libhalfslip run-time dependency")
