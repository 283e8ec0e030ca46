"""The Python package installed by cmake --install finds the installed library
by itself (no HALFSLIP_LIBRARY). argv[1]: the installed library directory."""
import math
import os
import sys

import halfslip

libdir = os.path.realpath(sys.argv[1])
assert "HALFSLIP_LIBRARY" not in os.environ
assert os.path.realpath(halfslip.library_path).startswith(libdir + os.sep), (halfslip.library_path, libdir)
assert os.path.realpath(halfslip.__file__).startswith(os.path.realpath(sys.argv[2]) + os.sep), halfslip.__file__
with halfslip.solve(Q_over_fP=0.5, sigma_over_fp0=0.2) as sol:
    assert abs(sol.b1 - (math.sqrt(0.5) + 0.05)) <= 1e-15, sol.b1
b1 = halfslip.solve_reference(30, Q_over_fP="0.3", sigma_over_fp0="2").b1
assert b1.startswith("7.490583629689906330026357657") and b1.certified == 30, repr(b1)
print("consumer python: halfslip %s from %s: ok" % (halfslip.__version__, halfslip.library_path))
