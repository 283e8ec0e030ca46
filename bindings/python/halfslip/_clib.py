"""Loading of the halfslip C library and its ctypes signatures.

Only the structs that are passed by value to or from C are declared here
(hs_scene, hs_options, hs_summary, hs_geometry, hs_ref_scene, hs_ref_summary,
and since 0.4 hs_history_options, hs_history_vertex, hs_cycle_summary), from
capi/include/halfslip/halfslip.h; their sizes are checked against the
library's struct_size when the library is loaded. Solutions are opaque
handles read through getters, as are load histories (hs_history).
"""

import ctypes
import ctypes.util
import os
import sys

from ctypes import POINTER, c_char_p, c_double, c_int, c_size_t

# SOVERSION of the shared library this package is written for (the file
# name libhalfslip.so.<SOVERSION>).
SOVERSION = 0


class Scene(ctypes.Structure):
    """struct hs_scene"""
    _fields_ = [
        ("struct_size", c_size_t),
        ("geometry", c_int),
        ("a", c_double),
        ("p0", c_double),
        ("f", c_double),
        ("E_star", c_double),
        ("Q_over_fP", c_double),
        ("sigma_over_fp0", c_double),
    ]


class Options(ctypes.Structure):
    """struct hs_options"""
    _fields_ = [
        ("struct_size", c_size_t),
        ("max_iterations", c_int),
        ("rtol", c_double),
        ("model", c_int),  # since 0.3
    ]


class Summary(ctypes.Structure):
    """struct hs_summary"""
    _fields_ = [
        ("struct_size", c_size_t),
        ("regime", c_int),
        ("slip_dir1", c_int),
        ("slip_dir2", c_int),
        ("iterations", c_int),
        ("a", c_double),
        ("b1", c_double),
        ("b2", c_double),
        ("d1", c_double),
        ("d2", c_double),
        ("p0", c_double),
        ("quadrature_order", c_int),
        ("model", c_int),  # since 0.3
        ("error_estimate", c_double),
        ("zone_resolution", c_double),  # after 0.4 (issue 13)
    ]


# double (*pressure)(double x, void *user)
PressureFn = ctypes.CFUNCTYPE(c_double, c_double, ctypes.c_void_p)


class BatchResult(ctypes.Structure):
    """struct hs_batch_result (issue 16; no struct_size: hs_solve_batch takes its size)"""
    _fields_ = [
        ("status", c_int),
        ("regime", c_int),
        ("slip_dir1", c_int),
        ("slip_dir2", c_int),
        ("model", c_int),
        ("iterations", c_int),
        ("b1", c_double),
        ("b2", c_double),
        ("d1", c_double),
        ("d2", c_double),
        ("error_estimate", c_double),
        ("energy1", c_double),
        ("energy2", c_double),
    ]


class Geometry(ctypes.Structure):
    """struct hs_geometry"""
    _fields_ = [
        ("struct_size", c_size_t),
        ("kind", c_int),
        ("flat_over_a", c_double),
        ("exponent", c_double),
        ("n_samples", c_size_t),
        ("sample_x", POINTER(c_double)),
        ("sample_p", POINTER(c_double)),
        ("pressure", PressureFn),
        ("user", ctypes.c_void_p),
    ]


class RefScene(ctypes.Structure):
    """struct hs_ref_scene (decimal strings; NULL means the C default)"""
    _fields_ = [
        ("struct_size", c_size_t),
        ("geometry", c_int),
        ("a", c_char_p),
        ("p0", c_char_p),
        ("f", c_char_p),
        ("E_star", c_char_p),
        ("Q_over_fP", c_char_p),
        ("sigma_over_fp0", c_char_p),
        ("P", c_char_p),
        ("R", c_char_p),
        ("Q", c_char_p),
        ("sigma", c_char_p),
        ("flat_over_a", c_char_p),   # since 0.3
        ("exponent", c_char_p),      # since 0.3
    ]


class RefSummary(ctypes.Structure):
    """struct hs_ref_summary"""
    _fields_ = [
        ("struct_size", c_size_t),
        ("regime", c_int),
        ("slip_dir1", c_int),
        ("slip_dir2", c_int),
        ("iterations", c_int),
        ("digits", c_int),
        ("working_digits", c_int),
        ("check_digits", c_int),
    ]


class HistoryOptions(ctypes.Structure):
    """struct hs_history_options (since 0.4)"""
    _fields_ = [
        ("struct_size", c_size_t),
        ("max_step", c_double),
        ("max_steps", c_int),
        ("segments_per_cycle", c_int),
        ("ramp_order", c_int),
        ("steady_rtol", c_double),
        ("rtol", c_double),
        ("interior_patches", c_int),  # since issue 14 (after 0.4.0)
    ]


class HistoryVertex(ctypes.Structure):
    """struct hs_history_vertex (since 0.4)"""
    _fields_ = [
        ("struct_size", c_size_t),
        ("Q_over_fP", c_double),
        ("sigma_over_fp0", c_double),
        ("b1", c_double),
        ("b2", c_double),
        ("slip_dir1", c_int),
        ("slip_dir2", c_int),
        ("energy1", c_double),
        ("energy2", c_double),
        ("cycle", c_int),
        ("steps", ctypes.c_long),
        ("step", c_double),
        ("error_estimate", c_double),
        ("interior_merges", ctypes.c_long),
        ("patch_dir", c_int),  # after 0.4.0: an interior slip zone open at the vertex
        ("patch_l", c_double),
        ("patch_r", c_double),
        ("energy_patch", c_double),
    ]


class CycleSummary(ctypes.Structure):
    """struct hs_cycle_summary (since 0.4)"""
    _fields_ = [
        ("struct_size", c_size_t),
        ("cycles", c_int),
        ("cycles_to_steady", c_int),
        ("shakedown", c_int),
        ("energy_per_cycle1", c_double),
        ("energy_per_cycle2", c_double),
        ("energy_per_cycle_patch", c_double),  # after 0.4.0
        ("cycles_repeated", c_int),  # session 21
        ("repeated_change", c_double),
    ]


class SteadyCycle(ctypes.Structure):
    """struct hs_steady_cycle (after 0.4.0)"""
    _fields_ = [
        ("struct_size", c_size_t),
        ("valid", c_int),
        ("cycles_to_steady", c_int),
        ("energy_per_cycle1", c_double),
        ("energy_per_cycle2", c_double),
    ]


class _Solution(ctypes.Structure):
    """opaque struct hs_solution"""


class _RefSolution(ctypes.Structure):
    """opaque struct hs_ref_solution"""


class _History(ctypes.Structure):
    """opaque struct hs_history"""


class _RefHistory(ctypes.Structure):
    """opaque struct hs_ref_history (issue 14)"""


SolutionP = POINTER(_Solution)
HistoryP = POINTER(_History)
RefSolutionP = POINTER(_RefSolution)
RefHistoryP = POINTER(_RefHistory)
_DoubleP = POINTER(c_double)
_CharP = POINTER(ctypes.c_char)  # output buffers (create_string_buffer)

# name: (restype, argtypes) for every symbol the package uses.
_SIGNATURES = {
    "hs_version": (c_int, [POINTER(c_int), POINTER(c_int), POINTER(c_int)]),
    "hs_version_string": (c_char_p, []),
    "hs_strerror": (c_char_p, [c_int]),
    "hs_model_name": (c_char_p, [c_int]),  # since 0.4
    "hs_model_from_name": (c_int, [c_char_p, POINTER(c_int)]),
    "hs_scene_default": (c_int, [POINTER(Scene)]),
    "hs_scene_from_hertz_loads": (c_int, [c_double] * 6 + [POINTER(Scene)]),
    "hs_scene_from_power_law_loads": (c_int, [c_double] * 7 + [POINTER(Scene)]),
    "hs_scene_from_flat_rounded_loads": (c_int, [c_double] * 7 + [POINTER(Scene), POINTER(c_double)]),
    "hs_options_default": (c_int, [POINTER(Options)]),
    "hs_solve": (c_int, [POINTER(Scene), POINTER(Options), POINTER(SolutionP)]),
    "hs_geometry_default": (c_int, [POINTER(Geometry)]),
    "hs_solve_geometry": (c_int, [POINTER(Scene), POINTER(Geometry), POINTER(Options), POINTER(SolutionP)]),
    "hs_check_samples": (c_int, [c_size_t, _DoubleP, _DoubleP, c_double, POINTER(c_int), POINTER(c_size_t),
                                 ctypes.c_char_p, c_size_t]),  # issue 13
    "hs_solution_free": (None, [SolutionP]),
    "hs_solution_summary": (c_int, [SolutionP, POINTER(Summary)]),
    "hs_solution_energy": (c_int, [SolutionP, _DoubleP]),
    "hs_solve_batch": (c_int, [c_size_t, POINTER(Scene), POINTER(Options), c_int, c_int, POINTER(BatchResult),
                               c_size_t]),  # issue 16
    "hs_eval_Bx": (c_int, [SolutionP, c_size_t, _DoubleP, _DoubleP]),
    "hs_eval_slip": (c_int, [SolutionP, c_size_t, _DoubleP, _DoubleP]),
    "hs_eval_work": (c_int, [SolutionP, c_size_t, _DoubleP, _DoubleP]),
    "hs_eval_pressure": (c_int, [SolutionP, c_size_t, _DoubleP, _DoubleP]),
    # issue 15: traction and stresses
    "hs_eval_traction": (c_int, [SolutionP, c_size_t, _DoubleP, _DoubleP]),
    "hs_eval_surface_stress": (c_int, [SolutionP, c_int, c_double, c_size_t, _DoubleP, _DoubleP]),
    "hs_eval_stress": (c_int, [SolutionP, c_int, c_double, c_size_t, _DoubleP, _DoubleP, _DoubleP]),
    "hs_surface_stress_extremes": (c_int, [SolutionP, c_int, c_double, c_double, _DoubleP]),
    "hs_eval_stress_scalar": (c_int, [SolutionP, c_int, c_double, c_int, c_double, c_size_t, _DoubleP, _DoubleP,
                                      _DoubleP]),
    "hs_solution_ramp": (c_int, [SolutionP, POINTER(c_int), _DoubleP]),
    "hs_history_options_default": (c_int, [POINTER(HistoryOptions)]),
    "hs_history_new": (c_int, [POINTER(Scene), POINTER(Geometry), POINTER(HistoryOptions), POINTER(HistoryP)]),
    "hs_history_free": (None, [HistoryP]),
    "hs_history_add_vertices": (c_int, [HistoryP, c_size_t, _DoubleP, _DoubleP]),
    "hs_history_add_cycles": (c_int, [HistoryP, c_double, c_double, c_double, c_double, c_double, c_int]),
    "hs_history_vertex_count": (c_int, [HistoryP, POINTER(c_size_t)]),
    "hs_history_method": (c_int, [HistoryP, POINTER(c_int)]),
    "hs_history_last_error": (c_int, [HistoryP, ctypes.c_char_p, c_size_t]),
    "hs_history_vertex_get": (c_int, [HistoryP, c_size_t, POINTER(HistoryVertex)]),
    "hs_history_eval": (c_int, [HistoryP, c_size_t, c_int, c_size_t, _DoubleP, _DoubleP]),
    "hs_history_cycle_summary": (c_int, [HistoryP, POINTER(CycleSummary)]),
    "hs_history_state": (c_int, [HistoryP, c_size_t, POINTER(SolutionP)]),
    "hs_solution_steady_cycle": (c_int, [SolutionP, POINTER(SteadyCycle)]),
    "hs_history_slip_range": (c_int, [HistoryP, c_size_t, _DoubleP, _DoubleP]),
    "hs_ref_scene_default": (c_int, [POINTER(RefScene)]),
    "hs_ref_max_digits": (c_int, []),
    "hs_ref_max_digits_geometry": (c_int, [c_int]),
    "hs_ref_solve": (c_int, [POINTER(RefScene), c_int, POINTER(RefSolutionP)]),
    "hs_ref_solution_free": (None, [RefSolutionP]),
    "hs_ref_history_new": (c_int, [POINTER(RefScene), c_int, POINTER(RefHistoryP)]),
    "hs_ref_history_free": (None, [RefHistoryP]),
    "hs_ref_history_add_vertices": (c_int, [RefHistoryP, c_size_t, POINTER(c_char_p), POINTER(c_char_p)]),
    "hs_ref_history_vertex_count": (c_int, [RefHistoryP, POINTER(c_size_t)]),
    "hs_ref_history_value": (c_int, [RefHistoryP, c_size_t, c_int, _CharP, c_size_t, POINTER(c_size_t),
                                     POINTER(c_int)]),
    "hs_ref_history_slip_dirs": (c_int, [RefHistoryP, c_size_t, POINTER(c_int), POINTER(c_int)]),
    "hs_ref_solution_summary": (c_int, [RefSolutionP, POINTER(RefSummary)]),
    "hs_ref_value": (c_int, [RefSolutionP, c_int, _CharP, c_size_t, POINTER(c_size_t), POINTER(c_int)]),
    "hs_ref_eval": (c_int, [RefSolutionP, c_int, c_char_p, _CharP, c_size_t, POINTER(c_size_t),
                            POINTER(c_int)]),
    "hs_ref_eval_stress": (c_int, [RefSolutionP, c_int, c_char_p, c_int, c_char_p, c_char_p, _CharP, c_size_t,
                                   POINTER(c_size_t), POINTER(c_int)]),
}


def _library_names():
    if sys.platform == "win32":
        return ["halfslip.dll", "libhalfslip.dll"]
    if sys.platform == "darwin":
        return ["libhalfslip.%d.dylib" % SOVERSION, "libhalfslip.dylib"]
    return ["libhalfslip.so.%d" % SOVERSION, "libhalfslip.so"]


def _package_dirs():
    """Directories searched first: the package itself, then the library
    directory recorded by `cmake --install` (halfslip/_install.py), then the
    library directory of the prefix the package is installed in (the nearest
    ancestor named lib* within three levels: PREFIX/lib for
    PREFIX/lib/python3.X/site-packages/halfslip), so that a package installed
    by pip under the prefix of `cmake --install` finds that library."""
    here = os.path.dirname(os.path.abspath(__file__))
    dirs = [here]
    try:
        from . import _install  # written by cmake --install
    except ImportError:
        _install = None
    if _install is not None:
        dirs.append(os.path.normpath(os.path.join(here, _install.LIBDIR)))
    d = here
    for _ in range(3):
        d = os.path.dirname(d)
        if os.path.basename(d).startswith("lib"):
            if d not in dirs:
                dirs.append(d)
            break
    return dirs


def load_library():
    """Find and load the shared library: next to the package first, then the
    file named by $HALFSLIP_LIBRARY, then the system loader. Returns
    (CDLL, path or name). Raises ImportError with what was tried."""
    tried = []
    for d in _package_dirs():
        for name in _library_names():
            path = os.path.join(d, name)
            if os.path.isfile(path):
                try:
                    return ctypes.CDLL(path), path
                except OSError as e:
                    raise ImportError("halfslip: cannot load %s: %s" % (path, e)) from e
            tried.append(path)
    env = os.environ.get("HALFSLIP_LIBRARY")
    if env:
        try:
            return ctypes.CDLL(env), env
        except OSError as e:
            raise ImportError("halfslip: cannot load the library named by HALFSLIP_LIBRARY=%s: %s"
                              % (env, e)) from e
    tried.append("$HALFSLIP_LIBRARY (not set)")
    found = ctypes.util.find_library("halfslip")
    if found:
        try:
            return ctypes.CDLL(found), found
        except OSError as e:
            raise ImportError("halfslip: cannot load %s (found by the system loader): %s"
                              % (found, e)) from e
    tried.append("ctypes.util.find_library('halfslip') (not found)")
    raise ImportError("halfslip: cannot find the halfslip shared library; tried:\n  "
                      + "\n  ".join(tried)
                      + "\nSet HALFSLIP_LIBRARY to the path of libhalfslip.so.%d." % SOVERSION)


def declare(lib, path):
    """Set restype and argtypes of every symbol used; ImportError if one is missing."""
    for name, (restype, argtypes) in _SIGNATURES.items():
        try:
            fn = getattr(lib, name)
        except AttributeError as e:
            raise ImportError("halfslip: %s is not a compatible halfslip library (no symbol %s)"
                              % (path, name)) from e
        fn.restype = restype
        fn.argtypes = argtypes
    return lib


def check_struct_sizes(lib, path):
    """The structs filled by the library's *_default functions have the size
    the library expects (catches a layout drift between this file and C)."""
    for cls, fn in ((Scene, lib.hs_scene_default), (Options, lib.hs_options_default),
                    (Geometry, lib.hs_geometry_default), (RefScene, lib.hs_ref_scene_default),
                    (HistoryOptions, lib.hs_history_options_default)):
        s = cls()
        st = fn(ctypes.byref(s))
        if st != 0 or s.struct_size != ctypes.sizeof(cls):
            raise ImportError("halfslip: struct %s of the Python binding has size %d, the library %s "
                              "expects %d (status %d); the binding and the library do not match"
                              % (cls.__doc__.split()[1], ctypes.sizeof(cls), path, s.struct_size, st))
    # The summaries are filled by the library, which checks the struct_size the
    # caller sets: one cheap solve of the default scene with each backend.
    sc, h, sm = Scene(), SolutionP(), Summary()
    lib.hs_scene_default(ctypes.byref(sc))
    st = lib.hs_solve(ctypes.byref(sc), None, ctypes.byref(h))
    if st == 0:
        sm.struct_size = ctypes.sizeof(sm)
        st = lib.hs_solution_summary(h, ctypes.byref(sm))
        lib.hs_solution_free(h)
    _summary_status(lib, path, "hs_summary", st)
    rsc, rh, rsm = RefScene(), RefSolutionP(), RefSummary()
    lib.hs_ref_scene_default(ctypes.byref(rsc))
    st = lib.hs_ref_solve(ctypes.byref(rsc), 1, ctypes.byref(rh))
    if st == 0:
        rsm.struct_size = ctypes.sizeof(rsm)
        st = lib.hs_ref_solution_summary(rh, ctypes.byref(rsm))
        lib.hs_ref_solution_free(rh)
    _summary_status(lib, path, "hs_ref_summary", st)
    # The history's vertex and cycle summary, likewise: one cycle of a small
    # shear amplitude (a few load steps).
    hh, v, cs = HistoryP(), HistoryVertex(), CycleSummary()
    struct = "hs_history"
    st = lib.hs_history_new(ctypes.byref(sc), None, None, ctypes.byref(hh))
    if st == 0:
        st = lib.hs_history_add_cycles(hh, 0.0, 0.01, 0.0, 0.0, 0.0, 1)
        if st == 0:
            struct = "hs_history_vertex"
            v.struct_size = ctypes.sizeof(v)
            st = lib.hs_history_vertex_get(hh, 0, ctypes.byref(v))
        if st == 0:
            struct = "hs_cycle_summary"
            cs.struct_size = ctypes.sizeof(cs)
            st = lib.hs_history_cycle_summary(hh, ctypes.byref(cs))
        lib.hs_history_free(hh)
    _summary_status(lib, path, struct, st)


def _summary_status(lib, path, struct, st):
    if st != 0:
        raise ImportError("halfslip: checking struct %s against the library %s failed with status %d (%s)"
                          % (struct, path, st, lib.hs_strerror(st).decode("utf-8", "replace")))
