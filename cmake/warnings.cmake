# Compiler warnings, in one place, for every target the project builds:
#   halfslip_warnings(target ...)       the given targets
#   halfslip_warnings_directory()       every compiled target of the calling directory
# C and C++: -Wall -Wextra (-Wall includes -Wunused); Fortran: -Wall (gfortran's
# -Wextra flags the exact REAL comparisons the tests make on purpose). Targets
# that are stricter add their own flags on top (test_capi and the consumer
# tests: -pedantic -Werror; the Fortran module: -Wextra -std=f2008 -pedantic -Werror).
set(HALFSLIP_WARNING_FLAGS -Wall -Wextra)
set(HALFSLIP_WARNING_FLAGS_Fortran -Wall)
function(halfslip_warnings)
  string(REPLACE ";" "$<SEMICOLON>" flags "${HALFSLIP_WARNING_FLAGS}")
  string(REPLACE ";" "$<SEMICOLON>" fflags "${HALFSLIP_WARNING_FLAGS_Fortran}")
  foreach(t IN LISTS ARGN)
    get_target_property(type ${t} TYPE)
    if(NOT type STREQUAL "INTERFACE_LIBRARY" AND NOT type STREQUAL "UTILITY")
      target_compile_options(${t} PRIVATE "$<$<COMPILE_LANGUAGE:C,CXX>:${flags}>"
        "$<$<COMPILE_LANGUAGE:Fortran>:${fflags}>")
    endif()
  endforeach()
endfunction()
function(halfslip_warnings_directory)
  get_property(targets DIRECTORY PROPERTY BUILDSYSTEM_TARGETS)
  halfslip_warnings(${targets})
endfunction()
