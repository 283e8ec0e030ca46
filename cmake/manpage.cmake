# cmake -DEXE=<halfslip> -DOUT=<halfslip.1> -DVERSION=<x.y.z> -P manpage.cmake
# Generates the man page halfslip(1) from `halfslip --help` (the single source
# of the option descriptions): the usage text verbatim, framed by NAME, FILES,
# SEE ALSO and citation sections.
execute_process(COMMAND "${EXE}" --help RESULT_VARIABLE rc OUTPUT_VARIABLE help ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${EXE} --help failed (${rc}): ${err}")
endif()
# troff escapes: backslashes, then lines starting with . or ' (control characters)
string(REPLACE "\\" "\\e" help "${help}")
string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" help "${help}")
string(REGEX REPLACE "\n$" "" help "${help}")
string(TIMESTAMP today "%Y-%m-%d" UTC)  # honours SOURCE_DATE_EPOCH (reproducible builds)
file(WRITE "${OUT}.tmp" ".\\\" Generated from `halfslip --help` by cmake/manpage.cmake; do not edit.
.TH HALFSLIP 1 \"${today}\" \"halfslip ${VERSION}\" \"User Commands\"
.SH NAME
halfslip \\- half-plane partial-slip contact with a constant normal load, shear force and bulk tension
.SH SYNOPSIS
.B halfslip solve
[\\fIoptions\\fR]
.br
.B halfslip table
\\fB\\-\\-Q\\-over\\-fP\\fR \\fILIST\\fR \\fB\\-\\-sigma\\-over\\-fp0\\fR \\fILIST\\fR [\\fIoptions\\fR]
.br
.B halfslip asymptotic\\-error
\\fB\\-\\-loading\\fR \\fBshear\\fR|\\fBbulk\\fR \\fB\\-\\-b\\-over\\-a\\fR \\fIX\\fR [\\fB\\-\\-json\\fR]
.br
.B halfslip \\-\\-version
.SH DESCRIPTION
Solves the plane-strain partial-slip contact of an elastic body on a half-plane under a constant
normal load P, a shear force Q and a differential bulk tension sigma (M.R. Moore, R. Ramesh, D.A. Hills,
J.R. Barber, J. Mech. Phys. Solids, 2018): the stick and slip zones, slip, dislocation density, work
density and dissipated energy, in double precision or to a requested number of certified digits.
P and Q are forces per unit length of the contact.
Exit status: 0 on success, 2 on bad input (with a one-line message on standard error).
.SH OPTIONS
The text of \\fBhalfslip \\-\\-help\\fR:
.PP
.nf
${help}
.fi
.SH FILES
Installed with the library: the C header \\fIhalfslip/halfslip.h\\fR, the libraries \\fIlibhalfslip\\fR and
\\fIlibhalfslip_fortran\\fR, the CMake package \\fIhalfslip\\fR, the pkg\\-config files \\fIhalfslip.pc\\fR and
\\fIhalfslip\\-fortran.pc\\fR, and the Python package \\fIhalfslip\\fR.
.SH SEE ALSO
docs/api.md, docs/conventions.md, docs/models.md and docs/reference.md in the halfslip sources.
.SH CITATION
If you use halfslip, cite M.R. Moore, R. Ramesh, D.A. Hills, J.R. Barber, \"Half-plane partial slip contact
problems with a constant normal load subject to a shear force and differential bulk tension\",
J. Mech. Phys. Solids (2018), doi:10.1016/j.jmps.2018.05.017, and the library (CITATION.cff).
")
file(RENAME "${OUT}.tmp" "${OUT}")
