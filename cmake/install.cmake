# Installation and packaging (included at the end of the top CMakeLists):
#   - the CMake package halfslip (find_package(halfslip [COMPONENTS C Fortran]))
#     with the targets halfslip::halfslip (shared), halfslip::halfslip_static and
#     halfslip::fortran, and a version file;
#   - pkg-config files halfslip.pc and halfslip-fortran.pc;
#   - the Fortran module file and the Python package;
#   - tests that install into a temporary prefix and build consumers against it.
# The install rules of the C libraries and headers themselves are in the top
# CMakeLists (export set halfslipTargets).
include(CMakePackageConfigHelpers)

set(HALFSLIP_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/halfslip"
  CACHE STRING "Where the CMake package files go (relative to the prefix)")
set(HALFSLIP_INSTALL_PKGCONFIGDIR "${CMAKE_INSTALL_LIBDIR}/pkgconfig"
  CACHE STRING "Where the pkg-config files go (relative to the prefix)")
set(HALFSLIP_INSTALL_FORTRAN_MODDIR "${CMAKE_INSTALL_INCLUDEDIR}/halfslip/fortran"
  CACHE STRING "Where the Fortran module file halfslip.mod goes (relative to the prefix)")
set(HALFSLIP_INSTALL_PYTHONDIR "${CMAKE_INSTALL_LIBDIR}/python3/dist-packages"
  CACHE STRING "Where the Python package halfslip goes (relative to the prefix)")
foreach(d CMAKEDIR PKGCONFIGDIR FORTRAN_MODDIR PYTHONDIR)
  if(IS_ABSOLUTE "${HALFSLIP_INSTALL_${d}}")
    message(FATAL_ERROR "HALFSLIP_INSTALL_${d} must be relative to the install prefix")
  endif()
endforeach()

# Libraries a C or Fortran program needs on top of libhalfslip.a: MPFR, GMP
# and the C++ runtime (the C++ compiler's implicit libraries that the C
# compiler does not add by itself: stdc++ and m with GCC).
set(HS_CXX_RUNTIME_LIBS "")
foreach(l IN LISTS CMAKE_CXX_IMPLICIT_LINK_LIBRARIES)
  if(NOT l IN_LIST CMAKE_C_IMPLICIT_LINK_LIBRARIES AND NOT l IN_LIST HS_CXX_RUNTIME_LIBS)
    list(APPEND HS_CXX_RUNTIME_LIBS ${l})
  endif()
endforeach()
set(HS_STATIC_DEPS mpfr gmp pthread ${HS_CXX_RUNTIME_LIBS})  # pthread: hs_solve_batch

# The static library's link interface: MPFR and GMP as the imported target
# PkgConfig::HS_MP (re-created by halfslipConfig.cmake), halfslip_reference for
# the build tree only (top CMakeLists), and for installed consumers the C++
# runtime, which a C program's link line lacks.
foreach(l IN LISTS HS_CXX_RUNTIME_LIBS)
  target_link_libraries(halfslip_static INTERFACE "$<INSTALL_INTERFACE:$<LINK_ONLY:${l}>>")
endforeach()

# ---- CMake package --------------------------------------------------------------
install(EXPORT halfslipTargets NAMESPACE halfslip:: DESTINATION ${HALFSLIP_INSTALL_CMAKEDIR})
if(TARGET halfslip_fortran)
  get_target_property(hs_fortran_moddir halfslip_fortran Fortran_MODULE_DIRECTORY)
  target_include_directories(halfslip_fortran PUBLIC
    $<INSTALL_INTERFACE:${HALFSLIP_INSTALL_FORTRAN_MODDIR}>)
  install(TARGETS halfslip_fortran EXPORT halfslipFortranTargets
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(FILES ${hs_fortran_moddir}/halfslip.mod DESTINATION ${HALFSLIP_INSTALL_FORTRAN_MODDIR})
  install(EXPORT halfslipFortranTargets NAMESPACE halfslip:: DESTINATION ${HALFSLIP_INSTALL_CMAKEDIR})
endif()

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/halfslipConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/halfslipConfig.cmake
  INSTALL_DESTINATION ${HALFSLIP_INSTALL_CMAKEDIR})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/halfslipConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/halfslipConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/halfslipConfigVersion.cmake
  DESTINATION ${HALFSLIP_INSTALL_CMAKEDIR})

# ---- pkg-config -----------------------------------------------------------------------
# Relocatable: prefix is found from the .pc file's own directory.
file(RELATIVE_PATH HS_PC_TO_PREFIX "/prefix/${HALFSLIP_INSTALL_PKGCONFIGDIR}" "/prefix")
string(REGEX REPLACE "/$" "" HS_PC_TO_PREFIX "${HS_PC_TO_PREFIX}")
set(HS_PC_LIBS_PRIVATE "")
foreach(l IN LISTS HS_STATIC_DEPS)
  string(APPEND HS_PC_LIBS_PRIVATE " -l${l}")
endforeach()
string(STRIP "${HS_PC_LIBS_PRIVATE}" HS_PC_LIBS_PRIVATE)
# halfslip.pc gives a run path (-Wl,-rpath,${libdir}); with --static it links
# libhalfslip.a (the shared library's -lhalfslip is in halfslip-shlib.pc, which
# pkg-config emits after Libs.private, inside --as-needed).
foreach(pc halfslip halfslip-shlib)
  configure_file(${CMAKE_CURRENT_LIST_DIR}/${pc}.pc.in ${CMAKE_CURRENT_BINARY_DIR}/${pc}.pc @ONLY)
  install(FILES ${CMAKE_CURRENT_BINARY_DIR}/${pc}.pc DESTINATION ${HALFSLIP_INSTALL_PKGCONFIGDIR})
endforeach()
if(TARGET halfslip_fortran)
  configure_file(${CMAKE_CURRENT_LIST_DIR}/halfslip-fortran.pc.in ${CMAKE_CURRENT_BINARY_DIR}/halfslip-fortran.pc
    @ONLY)
  install(FILES ${CMAKE_CURRENT_BINARY_DIR}/halfslip-fortran.pc DESTINATION ${HALFSLIP_INSTALL_PKGCONFIGDIR})
endif()

# ---- Python package ---------------------------------------------------------------------
if(HALFSLIP_BUILD_PYTHON)
  # _install.py tells the installed package where the library is, relative to itself.
  file(RELATIVE_PATH HS_PY_TO_LIBDIR "/prefix/${HALFSLIP_INSTALL_PYTHONDIR}/halfslip"
    "/prefix/${CMAKE_INSTALL_LIBDIR}")
  file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/python/_install.py
    "# Installed by cmake --install: the library directory, relative to this package.\nLIBDIR = \"${HS_PY_TO_LIBDIR}\"\n")
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/bindings/python/halfslip DESTINATION ${HALFSLIP_INSTALL_PYTHONDIR}
    FILES_MATCHING PATTERN "*.py" PATTERN "__pycache__" EXCLUDE)
  install(FILES ${CMAKE_CURRENT_BINARY_DIR}/python/_install.py
    DESTINATION ${HALFSLIP_INSTALL_PYTHONDIR}/halfslip)
endif()

# ---- tests of the installed tree ----------------------------------------------------------
if(HALFSLIP_BUILD_TESTS)
  add_subdirectory(${PROJECT_SOURCE_DIR}/tests/consumer ${CMAKE_BINARY_DIR}/tests/consumer)
endif()
