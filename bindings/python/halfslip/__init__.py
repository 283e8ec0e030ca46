"""halfslip: half-plane partial-slip contact (Python binding of the C ABI).

Pure Python (ctypes, standard library only; numpy arrays are accepted and
returned when numpy is installed, but numpy is not required). The shared library
libhalfslip.so.0 is looked for next to this package first (also in the
library directory recorded by ``cmake --install``), then at the path in the
environment variable ``HALFSLIP_LIBRARY``, then by the system loader
(``ctypes.util.find_library``). Its major version must equal this package's.

    >>> import halfslip
    >>> with halfslip.solve(Q_over_fP=0.3, sigma_over_fp0=2) as sol:
    ...     sol.regime_name, round(sol.b1, 12), sol.slip_dir1
    ('opposite-sign', 0.749058362969, -1)
    >>> halfslip.solve_reference(30, Q_over_fP="0.3", sigma_over_fp0="2").b1
    Certified('7.49058362968990633002635765716e-01', certified=30)

Sign conventions: docs/conventions.md. Errors raise HalfslipError, whose
status is the C status code and whose message is the C library's
hs_strerror text followed by the arguments concerned (e.g. "digits=1000");
an argument that is not a number, or an unknown model or geometry name,
raises ValueError naming the argument and its value.
"""

import array
import collections
import ctypes
import decimal
import enum
import sys
from ctypes import byref, c_char_p, c_double, c_int, c_size_t

from . import _clib

__version__ = "0.4.0"
__all__ = [
    "HalfslipError", "Scene", "Solution", "ReferenceSolution", "Certified", "Model", "Regime", "History",
    "HistoryVertex", "CycleSummary", "Ramp",
    "solve", "solve_batch", "from_hertz_loads", "from_power_law_loads", "from_flat_rounded_loads", "solve_reference", "ref_max_digits",
    "ReferenceHistory", "history_reference",
    "version", "library_version", "library_path", "strerror",
]

# Major version of the C library this package needs.
_EXPECTED_MAJOR = int(__version__.split(".")[0])

# ---- constants (values of capi/include/halfslip/halfslip.h, without HS_) ----
OK = 0
ERR_NULL_POINTER = 1
ERR_STRUCT_SIZE = 2
ERR_NOT_FINITE = 3
ERR_BAD_SIZE = 4
ERR_BAD_FRICTION = 5
ERR_GROSS_SLIDING = 6
ERR_BAD_GEOMETRY = 7
ERR_POINT_OUTSIDE = 8
ERR_BUFFER_TOO_SMALL = 9
ERR_NO_CONVERGENCE = 10
ERR_BAD_OPTION = 11
ERR_OUT_OF_MEMORY = 12
ERR_INTERNAL = 13
ERR_OVERFLOW = 14
ERR_BAD_NUMBER = 15
ERR_TOLERANCE = 16
ERR_NOT_APPLICABLE = 17


class _NamedInt(enum.IntEnum):
    """An int with a name: str() gives the name used by the command line and
    the docs ("closed-form", "same-sign"); it compares equal to the C value."""

    def __str__(self):
        return self.name.lower().replace("_", "-")

    def __format__(self, spec):
        return format(str(self), spec)

    @classmethod
    def _parse(cls, value, what):
        if isinstance(value, str):
            try:
                return cls[value.strip().upper().replace("-", "_")]
            except KeyError:
                pass
        elif not isinstance(value, bool) and isinstance(value, int):
            try:
                return cls(value)
            except ValueError:
                pass
        raise ValueError("halfslip: %s=%r is not a %s (one of %s)"
                         % (what, value, cls.__name__.lower(), ", ".join(str(m) for m in cls)))


class Model(_NamedInt):
    """hs_options.model / hs_summary.model (HS_MODEL_*), docs/models.md. The
    names are the C library's (hs_model_name, hs_model_from_name); "-" and "_"
    and the case are free."""
    DEFAULT = 0
    AUTO = 1
    ASYMPTOTIC = 2
    CLOSED_FORM = 3
    QUADRATURE = 4
    REFERENCE = 5

    def __str__(self):
        return _lib.hs_model_name(int(self)).decode("ascii")

    @classmethod
    def _parse(cls, value, what):
        if isinstance(value, str):
            m = ctypes.c_int()
            name = value.strip().lower().replace("_", "-").encode("utf-8", "replace")
            if _lib.hs_model_from_name(name, ctypes.byref(m)) == OK:
                return cls(m.value)
        return super()._parse(value, what)


MODEL_DEFAULT = Model.DEFAULT
MODEL_AUTO = Model.AUTO
MODEL_ASYMPTOTIC = Model.ASYMPTOTIC
MODEL_CLOSED_FORM = Model.CLOSED_FORM
MODEL_QUADRATURE = Model.QUADRATURE
MODEL_REFERENCE = Model.REFERENCE

GEOMETRY_HERTZ = 1
GEOMETRY_FLAT_ROUNDED = 2
GEOMETRY_POWER_LAW = 3
GEOMETRY_SAMPLES = 4
GEOMETRY_CALLBACK = 5



class Regime(_NamedInt):
    """hs_summary.regime (HS_REGIME_*): the slip zones' directions."""
    STUCK = 0
    SAME_SIGN = 1
    OPPOSITE_SIGN = 2
    BOUNDARY = 3  # one zone at or below the model's zone_resolution (issue 13)


REGIME_STUCK = Regime.STUCK
REGIME_SAME_SIGN = Regime.SAME_SIGN
REGIME_OPPOSITE_SIGN = Regime.OPPOSITE_SIGN
REGIME_BOUNDARY = Regime.BOUNDARY

_REGIME_NAMES = {r: str(r) for r in Regime}


def _enum_or_int(cls, v):
    try:
        return cls(v)
    except ValueError:
        return v
# load histories (since 0.4)
RAMP_SIGMA_FIRST = 0
RAMP_TOGETHER = 1
RAMP_Q_FIRST = 2
_RAMP_NAMES = {"sigma-first": RAMP_SIGMA_FIRST, "together": RAMP_TOGETHER, "q-first": RAMP_Q_FIRST}
# how a history computes its states (History.method)
HISTORY_SUPERPOSITION = 1
HISTORY_STATIC = 2
HISTORY_MARCH = 3
_HISTORY_METHODS = {HISTORY_SUPERPOSITION: "superposition", HISTORY_STATIC: "static", HISTORY_MARCH: "march"}

FIELD_TRACTION = 1
FIELD_SLIP = 2

# stress scalars of Solution.stress_scalar (hs_eval_stress_scalar)
STRESS_XX = 1
STRESS_YY = 2
STRESS_XY = 3
STRESS_VON_MISES = 4
STRESS_MAX_PRINCIPAL = 5
STRESS_MIN_PRINCIPAL = 6
STRESS_MAX_SHEAR = 7
_STRESS_NAMES = {"sxx": STRESS_XX, "syy": STRESS_YY, "sxy": STRESS_XY, "von_mises": STRESS_VON_MISES,
                 "max_principal": STRESS_MAX_PRINCIPAL, "min_principal": STRESS_MIN_PRINCIPAL,
                 "max_shear": STRESS_MAX_SHEAR}

_GEOMETRY_NAMES = {"hertz": GEOMETRY_HERTZ, "flat-rounded": GEOMETRY_FLAT_ROUNDED, "power-law": GEOMETRY_POWER_LAW,
                   "samples": GEOMETRY_SAMPLES, "callback": GEOMETRY_CALLBACK}
_STATUS_NAMES = {v: "HS_" + k for k, v in list(globals().items()) if k == "OK" or k.startswith("ERR_")}

# The arguments a status code is about, named in HalfslipError's message.
_ALL = None
_STATUS_ARGS = {
    ERR_NOT_FINITE: _ALL,
    ERR_BAD_SIZE: ("a", "p0", "E_star", "P", "R", "A", "flat_width", "samples"),
    ERR_BAD_FRICTION: ("f",),
    ERR_GROSS_SLIDING: ("Q_over_fP", "Q", "P", "f"),
    ERR_BAD_GEOMETRY: ("geometry", "flat_over_a", "exponent", "n", "samples", "flat_width", "R", "A", "model"),
    ERR_BAD_OPTION: ("digits", "rtol", "max_iterations", "model", "geometry", "quantity", "nu", "body", "vertex",
                     "component", "y", "threads"),
    ERR_BAD_NUMBER: _ALL,
    ERR_TOLERANCE: ("rtol", "model"),
    ERR_NOT_APPLICABLE: ("model", "geometry", "rtol"),
    ERR_POINT_OUTSIDE: ("x",),
}


def _detail(status, values):
    """'name=value, ...' for the given arguments that the status concerns."""
    keys = _STATUS_ARGS.get(status, ())
    items = [(k, v) for k, v in values.items() if v is not None and (keys is _ALL or k in keys)]
    return ", ".join("%s=%r" % (k, v) for k, v in items)


def _float(v, name, where):
    """float(v), or ValueError naming the argument and its value."""
    try:
        return float(v)
    except (TypeError, ValueError):
        raise ValueError("halfslip.%s: %s=%r is not a number" % (where, name, v)) from None


# quantity and evaluation selectors of hs_ref_value / hs_ref_eval
_REF_QUANTITIES = {"b1": 1, "b2": 2, "d1": 3, "d2": 4, "energy1": 5, "energy2": 6, "a": 7, "p0": 8}
_REF_EVALS = {"Bx": 1, "slip": 2, "work": 3, "pressure": 4, "traction": 5}


# ---- the library ----------------------------------------------------------------

def _check_version(lib, path, expected_major=None):
    """Raise ImportError unless the loaded library's major version is the one
    this package expects. Returns (major, minor, patch)."""
    if expected_major is None:
        expected_major = _EXPECTED_MAJOR
    ma, mi, pa = c_int(-1), c_int(-1), c_int(-1)
    st = lib.hs_version(byref(ma), byref(mi), byref(pa))
    if st != 0:
        raise ImportError("halfslip: hs_version failed in %s (status %d)" % (path, st))
    if ma.value != expected_major:
        raise ImportError(
            "halfslip: the library %s is version %d.%d.%d, but the Python package halfslip %s needs "
            "major version %d; install matching versions, or set HALFSLIP_LIBRARY to a compatible "
            "libhalfslip" % (path, ma.value, mi.value, pa.value, __version__, expected_major))
    return ma.value, mi.value, pa.value


def _load():
    lib, path = _clib.load_library()
    _clib.declare(lib, path)
    _check_version(lib, path)
    _clib.check_struct_sizes(lib, path)
    return lib, path


_lib, library_path = _load()
library_version = _lib.hs_version_string().decode("ascii")


# ---- errors ------------------------------------------------------------------------

def strerror(status):
    """The C library's message for a status code."""
    return _lib.hs_strerror(int(status)).decode("utf-8", "replace")


class HalfslipError(RuntimeError):
    """A halfslip C function returned an error status.

    Attributes: status (the HS_ERR_* code, also exported here as ERR_*),
    message (hs_strerror's text), function (the C function's name) and
    detail (the arguments concerned with their values, e.g. "digits=1000",
    or "")."""

    def __init__(self, status, function=None, detail=""):
        self.status = int(status)
        self.message = strerror(self.status)
        self.function = function
        self.detail = detail or ""
        name = _STATUS_NAMES.get(self.status, "unknown status")
        where = "%s: " % function if function else ""
        args = ", with %s" % self.detail if self.detail else ""
        super().__init__("%s%s (%s = %d)%s" % (where, self.message, name, self.status, args))

    def __reduce__(self):  # picklable (multiprocessing)
        return (HalfslipError, (self.status, self.function, self.detail))


def _check(status, function, values=None):
    if status != 0:
        raise HalfslipError(status, function, _detail(status, values or {}))


def version():
    """Version of the loaded C library as a tuple (major, minor, patch)."""
    return _check_version(_lib, library_path)


# ---- arrays ---------------------------------------------------------------------------

_NATIVE_DOUBLE = {"d", "@d", "=d", ("<d" if sys.byteorder == "little" else ">d")}


def _flatten(v):
    if isinstance(v, list):
        for item in v:
            yield from _flatten(item)
    else:
        yield v


def _points(x):
    """(ctypes double array or None, n, is_scalar). C-contiguous writable
    buffers of native doubles (array.array('d'), numpy float64, ...) are
    passed without a copy; anything else is converted once."""
    if isinstance(x, (int, float)) and not isinstance(x, bool):
        return (c_double * 1)(float(x)), 1, True
    try:
        mv = memoryview(x)
    except TypeError:
        mv = None
    if mv is not None:
        if mv.ndim == 0:
            return (c_double * 1)(float(mv.tolist())), 1, True
        if mv.format in _NATIVE_DOUBLE and mv.c_contiguous:
            n = mv.nbytes // ctypes.sizeof(c_double)
            if n == 0:
                return None, 0, False
            if mv.readonly:
                return (c_double * n).from_buffer_copy(mv), n, False
            return (c_double * n).from_buffer(mv), n, False
        values = array.array("d", _flatten(mv.tolist()))
    else:
        try:
            values = array.array("d", x)
        except TypeError:
            try:
                values = array.array("d", (float(v) for v in x))
            except (TypeError, ValueError) as e:
                raise TypeError("halfslip: points must be a number or numbers (a sequence, iterable or "
                                "buffer of numbers): %s" % e) from None
    n = len(values)
    if n == 0:
        return None, 0, False
    return (c_double * n).from_buffer(values), n, False


def _numpy_of(x):
    """The numpy module if x is a numpy array (numpy is never imported here)."""
    np = sys.modules.get("numpy")
    if np is not None and isinstance(x, np.ndarray):
        return np
    return None


# ---- double-precision solves ---------------------------------------------------------------

class Scene:
    """A scene in the dimensionless form of the C ABI (hs_scene): contact
    half-width a, reference pressure p0, friction f, composite modulus E_star,
    ratios Q_over_fP (|.| < 1) and sigma_over_fp0. Unset values take the C
    library's defaults (hs_scene_default)."""

    _FIELDS = ("a", "p0", "f", "E_star", "Q_over_fP", "sigma_over_fp0")

    def __init__(self, Q_over_fP=None, sigma_over_fp0=None, *, a=None, p0=None, f=None, E_star=None,
                 geometry=None):
        c = _clib.Scene()
        _check(_lib.hs_scene_default(byref(c)), "hs_scene_default")
        given = dict(a=a, p0=p0, f=f, E_star=E_star, Q_over_fP=Q_over_fP, sigma_over_fp0=sigma_over_fp0)
        for k, v in given.items():
            if v is not None:
                setattr(c, k, _float(v, k, "Scene"))
        if geometry is not None:
            c.geometry = int(geometry)
        self._c = c

    @classmethod
    def _from_c(cls, c):
        self = cls.__new__(cls)
        self._c = c
        return self

    a = property(lambda self: self._c.a, doc="contact half-width")
    p0 = property(lambda self: self._c.p0, doc="reference pressure 2P/(pi a)")
    f = property(lambda self: self._c.f, doc="coefficient of friction")
    E_star = property(lambda self: self._c.E_star, doc="composite plane-strain modulus")
    Q_over_fP = property(lambda self: self._c.Q_over_fP, doc="shear force ratio Q/(fP)")
    sigma_over_fp0 = property(lambda self: self._c.sigma_over_fp0, doc="bulk tension ratio sigma/(f p0)")
    geometry = property(lambda self: self._c.geometry, doc="GEOMETRY_HERTZ")

    def __repr__(self):
        return "Scene(%s)" % ", ".join("%s=%r" % (k, getattr(self, k)) for k in self._FIELDS)

    def solve(self, *, max_iterations=None, rtol=None, geometry=None, flat_over_a=None, exponent=None,
              samples=None, pressure=None, model=None):
        """Solve this scene; returns a Solution. Without geometry arguments the
        pressure is Hertz (closed forms). Otherwise (numerical inversion):
          flat_over_a=b_f/a      flat punch with rounded corners
          exponent=n             power-law profile g = A|x|^n, n > 1
          samples=(x, p)         pressure samples (>= 6, x increasing over
                                 [-a, a], p ~ sqrt at both edges; absolute units)
          pressure=callable      p(x) -> float on (-a, a), absolute units; kept
                                 by the Solution (it is called again by the
                                 evaluations); an exception it raises propagates
        geometry ("hertz", "flat-rounded", "power-law", "samples", "callback"
        or a GEOMETRY_* value) may name the kind explicitly; the C defaults
        fill what is not given (flat_over_a = 0.5, exponent = 2).
        model ("default", "auto", "asymptotic", "closed-form", "quadrature",
        "reference" or a MODEL_* value): with "auto", the cheapest model whose
        error estimate meets rtol (docs/models.md)."""
        opts = None
        if model is not None:
            model = Model._parse(model, "model")
        if max_iterations is not None or rtol is not None or model is not None:
            o = _clib.Options()
            _check(_lib.hs_options_default(byref(o)), "hs_options_default")
            if max_iterations is not None:
                if isinstance(max_iterations, bool) or not isinstance(max_iterations, int):
                    raise ValueError("halfslip.solve: max_iterations=%r is not an integer" % (max_iterations,))
                o.max_iterations = max_iterations
            if rtol is not None:
                o.rtol = _float(rtol, "rtol", "solve")
            if model is not None:
                o.model = model
            opts = byref(o)
        kind = _geometry_kind(geometry, flat_over_a, exponent, samples, pressure)
        values = {k: getattr(self, k) for k in self._FIELDS}
        values.update(geometry=geometry, flat_over_a=flat_over_a, exponent=exponent, rtol=rtol,
                      max_iterations=max_iterations, model=None if model is None else str(model))
        h = _clib.SolutionP()
        if kind is None:
            _check(_lib.hs_solve(byref(self._c), opts, byref(h)), "hs_solve", values)
            return Solution(h, scene=self)
        g, arrays, callback = _geometry_struct(kind, flat_over_a, exponent, samples, pressure, values)
        st = _lib.hs_solve_geometry(byref(self._c), byref(g), opts, byref(h))
        if st != 0 and arrays is not None:
            _sample_detail(g, self._c.a, values)
        del arrays
        if st != 0:
            _raise(st, "hs_solve_geometry", callback, values)
        return Solution(h, callback, scene=self)


def _sample_detail(g, a, values):
    """The rule a set of samples breaks, naming the sample (hs_check_samples),
    into values["samples"] (shown in the HalfslipError's detail)."""
    verdict, at = ctypes.c_int(0), ctypes.c_size_t(0)
    why = ctypes.create_string_buffer(256)
    if _lib.hs_check_samples(g.n_samples, g.sample_x, g.sample_p, a, byref(verdict), byref(at), why,
                             len(why)) != 0 or verdict.value == 0:
        return
    text = why.value.decode("ascii", "replace")
    if at.value < g.n_samples:
        i = at.value
        text = "sample %d (x=%r, p=%r): %s" % (i, g.sample_x[i], g.sample_p[i], text)
    values["samples"] = "(%d points; %s)" % (g.n_samples, text)


def _geometry_struct(kind, flat_over_a, exponent, samples, pressure, values=None):
    """(hs_geometry, arrays to keep alive during the call, _PressureCallback or None)."""
    g = _clib.Geometry()
    _check(_lib.hs_geometry_default(byref(g)), "hs_geometry_default")
    g.kind = kind
    if flat_over_a is not None:
        g.flat_over_a = _float(flat_over_a, "flat_over_a", "solve")
    if exponent is not None:
        g.exponent = _float(exponent, "exponent", "solve")
    arrays = None
    if samples is not None:
        try:
            xs, ps = samples
        except (TypeError, ValueError):
            raise TypeError("halfslip: samples must be a pair (x, p) of sequences") from None
        (xa, nx, _), (pa, np_, _) = _points(xs), _points(ps)
        if nx != np_:
            raise ValueError("halfslip: samples: %d abscissae but %d pressures" % (nx, np_))
        arrays = (xa, pa)   # alive during the call; the library copies them
        if values is not None:
            values["samples"] = "(%d points)" % nx
        g.n_samples = nx
        if nx:
            g.sample_x = ctypes.cast(xa, ctypes.POINTER(c_double))
            g.sample_p = ctypes.cast(pa, ctypes.POINTER(c_double))
    callback = None
    if pressure is not None:
        callback = _PressureCallback(pressure)
        g.pressure = callback.cfunc
    return g, arrays, callback


def _geometry_kind(geometry, flat_over_a, exponent, samples, pressure):
    implied = [k for k, v in ((GEOMETRY_FLAT_ROUNDED, flat_over_a), (GEOMETRY_POWER_LAW, exponent),
                              (GEOMETRY_SAMPLES, samples), (GEOMETRY_CALLBACK, pressure)) if v is not None]
    if geometry is None:
        if len(implied) > 1:
            raise TypeError("halfslip: give only one of flat_over_a, exponent, samples, pressure")
        return implied[0] if implied else None
    if isinstance(geometry, str):
        try:
            kind = _GEOMETRY_NAMES[geometry]
        except KeyError:
            raise ValueError("halfslip: unknown geometry %r (one of %s)"
                             % (geometry, ", ".join(_GEOMETRY_NAMES))) from None
    else:
        kind = int(geometry)
    if any(k != kind for k in implied):
        raise TypeError("halfslip: the geometry arguments do not match geometry=%r" % (geometry,))
    return kind


class _PressureCallback:
    """A Python pressure function behind a C function pointer. An exception
    it raises is kept, NaN is returned to C (which then fails with
    HS_ERR_NOT_FINITE), and the exception is raised again in Python."""

    def __init__(self, fn):
        if not callable(fn):
            raise TypeError("halfslip: pressure must be callable")
        self.fn = fn
        self.error = None
        self.cfunc = _clib.PressureFn(self._call)

    def _call(self, x, user):
        try:
            return float(self.fn(x))
        except BaseException as e:  # noqa: B902 - re-raised in the caller's thread
            if self.error is None:
                self.error = e
            return float("nan")


def _raise(status, function, callback=None, values=None):
    if callback is not None and callback.error is not None:
        err, callback.error = callback.error, None
        raise err
    raise HalfslipError(status, function, _detail(status, values or {}))


def from_hertz_loads(P, R, E_star, f, Q, sigma):
    """Scene of a cylinder (radius of relative curvature R) pressed by the
    normal load P (per unit length), with shear force Q and bulk tension
    sigma: a = sqrt(4PR/(pi E*)), p0 = 2P/(pi a). Returns a Scene."""
    v = dict(P=P, R=R, E_star=E_star, f=f, Q=Q, sigma=sigma)
    x = [_float(val, k, "from_hertz_loads") for k, val in v.items()]
    c = _clib.Scene()
    _check(_lib.hs_scene_from_hertz_loads(*x, byref(c)), "hs_scene_from_hertz_loads", v)
    return Scene._from_c(c)


def from_power_law_loads(P, A, n, E_star, f, Q, sigma):
    """Scene of a power-law profile g = A|x|^n (solve it with exponent=n)
    under the normal load P: a from P = (E*/2) n A a^n sqrt(pi)
    Gamma((n+1)/2)/Gamma(n/2+1), p0 = 2P/(pi a). Returns a Scene."""
    v = dict(P=P, A=A, n=n, E_star=E_star, f=f, Q=Q, sigma=sigma)
    x = [_float(val, k, "from_power_law_loads") for k, val in v.items()]
    c = _clib.Scene()
    _check(_lib.hs_scene_from_power_law_loads(*x, byref(c)), "hs_scene_from_power_law_loads", v)
    return Scene._from_c(c)


def from_flat_rounded_loads(P, R, flat_width, E_star, f, Q, sigma):
    """Scene of a flat punch (half-width flat_width) with corners of radius R
    under the normal load P. Returns (Scene, flat_over_a); solve the scene
    with flat_over_a=flat_over_a."""
    v = dict(P=P, R=R, flat_width=flat_width, E_star=E_star, f=f, Q=Q, sigma=sigma)
    x = [_float(val, k, "from_flat_rounded_loads") for k, val in v.items()]
    c = _clib.Scene()
    beta = ctypes.c_double(0.0)
    _check(_lib.hs_scene_from_flat_rounded_loads(*x, byref(c), byref(beta)), "hs_scene_from_flat_rounded_loads", v)
    return Scene._from_c(c), beta.value


def solve(Q_over_fP=None, sigma_over_fp0=None, *, a=None, p0=None, f=None, E_star=None, scene=None,
          max_iterations=None, rtol=None, geometry=None, flat_over_a=None, exponent=None, samples=None,
          pressure=None, model=None):
    """Solve a scene given by its ratios (and optionally a, p0, f, E_star),
    or an existing Scene (scene=...). Unset values take the C defaults. The
    pressure is Hertz unless a geometry is given (see Scene.solve); model
    ("auto" with rtol, "closed-form", ... or a Model) as in Scene.solve.
    Returns a Solution (a context manager that frees the C handle)."""
    if scene is None:
        scene = Scene(Q_over_fP, sigma_over_fp0, a=a, p0=p0, f=f, E_star=E_star)
    elif any(v is not None for v in (Q_over_fP, sigma_over_fp0, a, p0, f, E_star)):
        raise TypeError("solve: give either scene or scene values, not both")
    return scene.solve(max_iterations=max_iterations, rtol=rtol, geometry=geometry, flat_over_a=flat_over_a,
                       exponent=exponent, samples=samples, pressure=pressure, model=model)


class _Handle:
    """Owner of one C handle: close() frees it once (subclasses say how, in
    _release); usable as a context manager; freed at garbage collection."""

    def close(self):
        h, self._h = getattr(self, "_h", None), None
        self._release(h)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    def __del__(self):
        try:
            self.close()
        except Exception:  # interpreter shutdown
            pass


class Solution(_Handle):
    """A solved scene (an immutable C handle; safe to evaluate from several
    threads). Use as a context manager, or call close(); the handle is also
    freed when the object is garbage collected. The summary properties stay
    readable after close()."""

    def __init__(self, handle, callback=None, scene=None):
        self._h = handle
        self._callback = callback   # a pressure callback the C solution calls
        self.scene = scene          # the Scene solved (f and E_star for scaling pictures), or None
        s = _clib.Summary()
        s.struct_size = ctypes.sizeof(s)
        st = _lib.hs_solution_summary(handle, byref(s))
        if st != 0:
            self.close()
            raise HalfslipError(st, "hs_solution_summary")
        self._s = s

    # summary
    regime = property(lambda self: _enum_or_int(Regime, self._s.regime),
                      doc="a Regime (an int): STUCK, SAME_SIGN, OPPOSITE_SIGN or BOUNDARY (one zone at or "
                          "below zone_resolution); str() gives its name")
    regime_name = property(lambda self: _REGIME_NAMES.get(self._s.regime, "unknown"))
    a = property(lambda self: self._s.a, doc="contact half-width")
    b1 = property(lambda self: self._s.b1, doc="the stick zone is (-b2, b1)")
    b2 = property(lambda self: self._s.b2)
    d1 = property(lambda self: self._s.d1, doc="a - b1, to full relative accuracy")
    d2 = property(lambda self: self._s.d2, doc="a - b2")
    slip_dir1 = property(lambda self: self._s.slip_dir1,
                         doc="+1, -1, or 0 if zone 1 is empty or not resolved (d1 <= zone_resolution)")
    slip_dir2 = property(lambda self: self._s.slip_dir2)
    iterations = property(lambda self: self._s.iterations, doc="Newton iterations (0 for closed forms)")
    p0 = property(lambda self: self._s.p0, doc="reference pressure 2P/(pi a) used")
    quadrature_order = property(lambda self: self._s.quadrature_order,
                                doc="Gauss-Legendre order per panel (0: closed forms)")
    model = property(lambda self: _enum_or_int(Model, self._s.model),
                     doc="the Model used (an int: ASYMPTOTIC, CLOSED_FORM, QUADRATURE, REFERENCE); str() gives its name")
    model_name = property(lambda self: str(self.model), doc='"asymptotic", "closed-form", "quadrature" or "reference"')
    error_estimate = property(lambda self: self._s.error_estimate,
                              doc="estimated largest relative error of d1, d2 and the zone energies "
                                  "(zones longer than zone_resolution)")
    zone_resolution = property(lambda self: self._s.zone_resolution,
                               doc="the model's bound on the absolute error of d1 and d2 (units of a); a zone "
                                   "at or below it is unresolved: slip direction 0, regime BOUNDARY (issue 13)")

    def _handle(self):
        if not self._h:
            raise ValueError("halfslip: the solution has been closed")
        return self._h

    def _release(self, h):
        if h:
            _lib.hs_solution_free(h)
        self._callback = None

    def __repr__(self):
        return "<halfslip.Solution %s b1=%.17g b2=%.17g%s>" % (
            self.regime_name, self.b1, self.b2, "" if self._h else " (closed)")

    def energy(self):
        """(E1, E2): energy dissipated in zone 1 (b1, a) and zone 2 (-a, -b2)."""
        e = (c_double * 2)()
        st = _lib.hs_solution_energy(self._handle(), e)
        if st != 0:
            _raise(st, "hs_solution_energy", self._callback)
        return e[0], e[1]

    def _eval(self, fn, name, x):
        h = self._handle()
        np = _numpy_of(x)
        if np is not None:   # numpy in, numpy of the same shape out
            try:
                xs = np.asarray(x, dtype=np.float64, order="C")
            except (TypeError, ValueError) as e:
                raise TypeError("halfslip: points must be numbers: %s" % e) from None
            out = np.empty(xs.shape, dtype=np.float64)
            dp = ctypes.POINTER(c_double)
            st = fn(h, xs.size, xs.ctypes.data_as(dp), out.ctypes.data_as(dp)) if xs.size else 0
            if st != 0:
                _raise(st, name, self._callback, {"x": "array of shape %s" % (xs.shape,)})
            return out[()] if out.ndim == 0 else out
        xs, n, scalar = _points(x)
        out = array.array("d", bytes(n * ctypes.sizeof(c_double)))
        if n:
            st = fn(h, n, xs, (c_double * n).from_buffer(out))
        else:
            st = fn(h, 0, None, None)
        if st != 0:
            _raise(st, name, self._callback, {"x": x if scalar else "%d points" % n})
        return out[0] if scalar else out

    def Bx(self, x):
        """Dislocation density B_x = dh/dx at x (a number or a sequence/buffer
        of numbers, |x| <= a): a float for a number, a numpy array of x's shape
        for a numpy array, else an array.array('d')."""
        return self._eval(_lib.hs_eval_Bx, "hs_eval_Bx", x)

    def slip(self, x):
        """Relative slip h(x), zero at the stick boundaries."""
        return self._eval(_lib.hs_eval_slip, "hs_eval_slip", x)

    def work(self, x):
        """Friction work density W(x) = f p(x) |h(x)| for monotonic loading."""
        return self._eval(_lib.hs_eval_work, "hs_eval_work", x)

    def pressure(self, x):
        """Contact pressure p(x) of the scene's geometry."""
        return self._eval(_lib.hs_eval_pressure, "hs_eval_pressure", x)

    # ---- issue 15: traction and stresses (docs/fields.md) ----
    def traction(self, x):
        """Shear traction q(x) on body 1 (positive in +x, integral Q), |x| <= a."""
        return self._eval(_lib.hs_eval_traction, "hs_eval_traction", x)

    def surface_stress(self, x, body=1, pad_bulk=0.0):
        """sigma_xx(x, 0) of body 1 (specimen, y > 0) or 2 (pad, y < 0) at any x;
        the pad carries pad_bulk, the specimen sigma + pad_bulk."""
        fn = _lib.hs_eval_surface_stress
        return self._eval(lambda h, n, xs, out: fn(h, int(body), float(pad_bulk), n, xs, out),
                          "hs_eval_surface_stress", x)

    def stress(self, x, y, body=None, pad_bulk=0.0):
        """(sigma_xx, sigma_yy, sigma_xy) at points (x, y): a tuple for scalars, else a
        list of tuples. body defaults to 1 for y >= 0 and 2 for y < 0 (all points alike)."""
        h = self._handle()
        xs, n, scalar = _points(x)
        ys, m, _ = _points(y)
        if m != n:
            raise ValueError("x and y differ in length")
        if body is None:
            body = 2 if n and ys[0] < 0 else 1
        out = (c_double * (3 * max(n, 1)))()
        st = _lib.hs_eval_stress(h, int(body), float(pad_bulk), n, xs if n else None, ys if n else None,
                                 out if n else None)
        if st != 0:
            _raise(st, "hs_eval_stress", self._callback)
        res = [(out[3 * i], out[3 * i + 1], out[3 * i + 2]) for i in range(n)]
        return res[0] if scalar else res

    def stress_scalar(self, x, y, quantity="von_mises", body=None, nu=0.3, pad_bulk=0.0):
        """A scalar of the stress at points (x, y) (same shapes): quantity is one of
        "sxx", "syy", "sxy", "von_mises" (plane strain, Poisson's ratio nu),
        "max_principal", "min_principal", "max_shear", or a STRESS_* constant. body
        defaults to 1 for y >= 0 and 2 for y < 0 (all points alike). Returns a float
        for numbers, a numpy array of x's shape for numpy arrays, else an array.array('d')."""
        q = _STRESS_NAMES.get(quantity, quantity) if isinstance(quantity, str) else quantity
        if isinstance(quantity, str) and quantity not in _STRESS_NAMES:
            raise ValueError("halfslip: unknown stress quantity %r (one of %s)"
                             % (quantity, ", ".join(sorted(_STRESS_NAMES))))
        h = self._handle()
        np = _numpy_of(x)
        if np is not None:
            xs = np.ascontiguousarray(x, dtype=np.float64)
            ys = np.ascontiguousarray(y, dtype=np.float64)
            if xs.shape != ys.shape:
                raise ValueError("x and y differ in shape")
            if body is None:
                body = 2 if xs.size and ys.flat[0] < 0 else 1
            out = np.empty(xs.shape, dtype=np.float64)
            dp = ctypes.POINTER(c_double)
            st = _lib.hs_eval_stress_scalar(h, int(body), float(pad_bulk), int(q), float(nu), xs.size,
                                            xs.ctypes.data_as(dp), ys.ctypes.data_as(dp), out.ctypes.data_as(dp)) \
                if xs.size else 0
            if st != 0:
                _raise(st, "hs_eval_stress_scalar", self._callback, {"quantity": quantity, "nu": nu, "body": body})
            return out[()] if out.ndim == 0 else out
        xs, n, scalar = _points(x)
        ys, m, _ = _points(y)
        if m != n:
            raise ValueError("x and y differ in length")
        if body is None:
            body = 2 if n and ys[0] < 0 else 1
        out = array.array("d", bytes(n * ctypes.sizeof(c_double)))
        st = _lib.hs_eval_stress_scalar(h, int(body), float(pad_bulk), int(q), float(nu), n, xs if n else None,
                                        ys if n else None, (c_double * n).from_buffer(out) if n else None)
        if st != 0:
            _raise(st, "hs_eval_stress_scalar", self._callback, {"quantity": quantity, "nu": nu, "body": body})
        return out[0] if scalar else out

    def surface_stress_extremes(self, body=1, pad_bulk=0.0, half_range=0.0):
        """dict max, x_max, min, x_min, bulk of sigma_xx(x, 0) over |x| <= half_range (0: 3a)."""
        h = self._handle()
        out = (c_double * 5)()
        st = _lib.hs_surface_stress_extremes(h, int(body), float(pad_bulk), float(half_range), out)
        if st != 0:
            _raise(st, "hs_surface_stress_extremes", self._callback)
        return dict(zip(("max", "x_max", "min", "x_min", "bulk"), out))

    def ramp(self):
        """Ramp(recedes, at_Q_over_fP) of hs_solution_ramp: whether a
        proportional ramp from zero to this (Q, sigma) makes a slip zone
        recede on the way (the monotonic solution then is not the state such
        a ramp reaches), and the Q/fP where that first happens (NaN if not)."""
        recedes, at = c_int(0), c_double(0.0)
        st = _lib.hs_solution_ramp(self._handle(), byref(recedes), byref(at))
        if st != 0:
            _raise(st, "hs_solution_ramp", self._callback)
        return Ramp(bool(recedes.value), at.value)


    def steady_cycle(self):
        """SteadyCycle(valid, cycles_to_steady, energy_per_cycle1, energy_per_cycle2)
        of hs_solution_steady_cycle: symmetric proportional cycling between
        +(Q, sigma) and -(Q, sigma) in closed form (Ciavarella-Jager). valid is
        False when a zone recedes on the ramp (march it with History instead);
        the slip range over a cycle is 2 * slip(x)."""
        c = _clib.SteadyCycle()
        c.struct_size = ctypes.sizeof(c)
        st = _lib.hs_solution_steady_cycle(self._handle(), byref(c))
        if st != 0:
            _raise(st, "hs_solution_steady_cycle", self._callback)
        return SteadyCycle(bool(c.valid), c.cycles_to_steady, c.energy_per_cycle1, c.energy_per_cycle2)


SteadyCycle = collections.namedtuple("SteadyCycle", "valid cycles_to_steady energy_per_cycle1 energy_per_cycle2")
SteadyCycle.__doc__ = "Result of Solution.steady_cycle() (hs_solution_steady_cycle)."

Ramp = collections.namedtuple("Ramp", "recedes at_Q_over_fP")
Ramp.__doc__ = "Result of Solution.ramp() (hs_solution_ramp)."


# ---- load histories (since 0.4) ----------------------------------------------------------------

HistoryVertex = collections.namedtuple(
    "HistoryVertex", "Q_over_fP sigma_over_fp0 b1 b2 slip_dir1 slip_dir2 energy1 energy2 cycle steps step "
    "error_estimate interior_merges patch_dir patch_l patch_r energy_patch")
HistoryVertex.__doc__ = """State after a vertex of a History (struct hs_history_vertex): the loads,
the stick zone (-b2, b1), the slip direction of each edge zone (+1, -1, or 0
where that edge does not slip at the vertex), the energy dissipated in zone 1
(x > b1) and zone 2 over the segment that ends here, the cycle (0: path or
ramp; k >= 1: the k-th cycle of add_cycles), the load steps marched so far, the
load step after refinement, the march's error estimate (rtol), the number of
interior slip patches merged with an edge zone so far (an approximation), and an
interior slip zone open at the vertex (patch_dir +1 or -1, 0: none; its ends
patch_l, patch_r) with the energy dissipated in interior slip zones over the
segment (energy_patch, not part of energy1, energy2)."""

CycleSummary = collections.namedtuple(
    "CycleSummary",
    "cycles cycles_to_steady shakedown energy_per_cycle1 energy_per_cycle2 energy_per_cycle_patch "
    "cycles_repeated repeated_change")
CycleSummary.__doc__ = """Periodic loading of a History (struct hs_cycle_summary): cycles computed,
the first cycle that the next repeats (-1: not reached), whether the last
cycle dissipates nothing, and the energy of each zone over the last cycle
(energy_per_cycle_patch: in interior slip zones), and how many cycles were
copies of a cycle that left the state as it found it (cycles_repeated), with
that cycle's change of the state (repeated_change; docs/history.md, "The
steady cycle")."""


class History(_Handle):
    """A load history (hs_history): the normal load is applied first and held;
    then (Q, sigma) moves along straight segments between vertices, starting
    from (0, 0). The contact is given as to solve(): a, p0, f, E_star (or
    scene=, whose ratios are ignored) and optionally a geometry (geometry=,
    flat_over_a=, exponent=, samples=, pressure=; see Scene.solve). Options
    (unset: the C defaults of hs_history_options_default): max_step (largest
    load step, default 1/128), max_steps, segments_per_cycle, ramp_order
    ("sigma-first" (default), "together", "q-first" or a RAMP_* value) and
    steady_rtol. Use as a context manager, or call close(); the handle is
    also freed when the object is garbage collected.

    Vertices are numbered from 0 in the order they were reached (vertex_count
    of them, add_cycles' ramp and cycle vertices included)."""

    def __init__(self, *, a=None, p0=None, f=None, E_star=None, scene=None, geometry=None, flat_over_a=None,
                 exponent=None, samples=None, pressure=None, max_step=None, max_steps=None,
                 segments_per_cycle=None, ramp_order=None, steady_rtol=None, rtol=None,
                 interior_patches=None):
        self._h = None
        self._callback = None
        if scene is None:
            scene = Scene(a=a, p0=p0, f=f, E_star=E_star)
        elif any(v is not None for v in (a, p0, f, E_star)):
            raise TypeError("History: give either scene or scene values, not both")
        opts = None
        given = dict(max_step=max_step, max_steps=max_steps, segments_per_cycle=segments_per_cycle,
                     ramp_order=ramp_order, steady_rtol=steady_rtol, rtol=rtol,
                     interior_patches=interior_patches)
        if any(v is not None for v in given.values()):
            o = _clib.HistoryOptions()
            _check(_lib.hs_history_options_default(byref(o)), "hs_history_options_default")
            if max_step is not None:
                o.max_step = float(max_step)
            if max_steps is not None:
                o.max_steps = int(max_steps)
            if segments_per_cycle is not None:
                o.segments_per_cycle = int(segments_per_cycle)
            if ramp_order is not None:
                if isinstance(ramp_order, str):
                    try:
                        o.ramp_order = _RAMP_NAMES[ramp_order]
                    except KeyError:
                        raise ValueError("halfslip: unknown ramp_order %r (one of %s)"
                                         % (ramp_order, ", ".join(_RAMP_NAMES))) from None
                else:
                    o.ramp_order = int(ramp_order)
            if steady_rtol is not None:
                o.steady_rtol = float(steady_rtol)
            if rtol is not None:
                o.rtol = float(rtol)
            if interior_patches is not None:
                # "error" (default): HalfslipError (ERR_NOT_APPLICABLE) where a third slip zone
                # would open inside the stick zone; "merge": merged with the edge zone (approximate)
                names = {"error": 0, "merge": 1}
                if interior_patches not in names:
                    raise ValueError("halfslip: interior_patches=%r (one of error, merge)" % (interior_patches,))
                o.interior_patches = names[interior_patches]
            opts = byref(o)
        kind = _geometry_kind(geometry, flat_over_a, exponent, samples, pressure)
        g, arrays, callback = None, None, None
        if kind is not None:
            g, arrays, callback = _geometry_struct(kind, flat_over_a, exponent, samples, pressure)
        h = _clib.HistoryP()
        st = _lib.hs_history_new(byref(scene._c), None if g is None else byref(g), opts, byref(h))
        del arrays
        if st != 0:
            _raise(st, "hs_history_new", callback)
        self._h = h
        self._callback = callback   # a pressure callback the C history calls
        self.scene = scene          # the Scene (a, p0, f, E_star; its ratios unused)

    def _handle(self):
        if not self._h:
            raise ValueError("halfslip: the history has been closed")
        return self._h

    def _release(self, h):
        if h:
            _lib.hs_history_free(h)
        self._callback = None

    def _status(self, st, name):
        if st != 0:
            why = ""
            if self._h and name in ("hs_history_add_vertices", "hs_history_add_cycles"):
                buf = ctypes.create_string_buffer(512)
                if _lib.hs_history_last_error(self._h, buf, len(buf)) == 0:
                    why = buf.value.decode("utf-8", "replace")
            if why and (self._callback is None or self._callback.error is None):
                raise HalfslipError(st, name, "reason: " + why)
            _raise(st, name, self._callback)

    def __repr__(self):
        if not self._h:
            return "<halfslip.History (closed)>"
        return "<halfslip.History %d vertices>" % self.vertex_count

    def add_vertices(self, Q_over_fP, sigma_over_fp0):
        """Append vertices (Q/fP, sigma/fp0), two numbers or two sequences of
        the same length, and march to them (hs_history_add_vertices). On error
        the history keeps the vertices reached before the failing one, and the
        HalfslipError's detail gives the library's reason (hs_history_last_error:
        e.g. an interior slip zone, or part of an edge zone slipping back)."""
        h = self._handle()
        (qa, nq, _), (sa, ns, _) = _points(Q_over_fP), _points(sigma_over_fp0)
        if nq != ns:
            raise ValueError("halfslip: add_vertices: %d values of Q_over_fP but %d of sigma_over_fp0" % (nq, ns))
        self._status(_lib.hs_history_add_vertices(h, nq, qa, sa), "hs_history_add_vertices")

    def add_path(self, points):
        """add_vertices from a sequence of pairs [(Q/fP, sigma/fp0), ...]."""
        pts = [(float(q), float(s)) for q, s in points]
        self.add_vertices([p[0] for p in pts], [p[1] for p in pts])

    def add_cycles(self, Qm_over_fP, Qa_over_fP, Sm_over_fp0, Sa_over_fp0, phase_deg, cycles):
        """Periodic loading Q(t) = Qm + Qa sin(wt), sigma(t) = Sm + Sa sin(wt + phase),
        reached from the current state by the ramp_order option, then `cycles`
        cycles (hs_history_add_cycles)."""
        self._status(_lib.hs_history_add_cycles(self._handle(), float(Qm_over_fP), float(Qa_over_fP),
                                                float(Sm_over_fp0), float(Sa_over_fp0), float(phase_deg),
                                                int(cycles)), "hs_history_add_cycles")

    @property
    def vertex_count(self):
        """Number of vertices reached."""
        n = c_size_t(0)
        self._status(_lib.hs_history_vertex_count(self._handle(), byref(n)), "hs_history_vertex_count")
        return n.value

    @property
    def method(self):
        """How the states are computed: "superposition" (one ray through the origin), "static"
        (every segment advances: one static solve per segment) or "march" (load steps)."""
        m = c_int(0)
        self._status(_lib.hs_history_method(self._handle(), byref(m)), "hs_history_method")
        return _HISTORY_METHODS[m.value]

    def vertex(self, i):
        """The HistoryVertex i (0 <= i < vertex_count)."""
        v = _clib.HistoryVertex()
        v.struct_size = ctypes.sizeof(v)
        self._status(_lib.hs_history_vertex_get(self._handle(), int(i), byref(v)), "hs_history_vertex_get")
        return HistoryVertex(*(getattr(v, k) for k in HistoryVertex._fields))

    @property
    def vertices(self):
        """All vertices, a list of HistoryVertex."""
        return [self.vertex(i) for i in range(self.vertex_count)]

    def _eval(self, vertex, field, x):
        h = self._handle()
        xs, n, scalar = _points(x)
        out = array.array("d", bytes(n * ctypes.sizeof(c_double)))
        if n:
            st = _lib.hs_history_eval(h, int(vertex), field, n, xs, (c_double * n).from_buffer(out))
        else:
            st = _lib.hs_history_eval(h, int(vertex), field, 0, None, None)
        self._status(st, "hs_history_eval")
        return out[0] if scalar else out

    def traction(self, vertex, x):
        """Shear traction q(x) in the state after vertex `vertex` (x as in
        Solution.Bx: a number or numbers, |x| <= a)."""
        return self._eval(vertex, FIELD_TRACTION, x)

    def slip(self, vertex, x):
        """Accumulated slip h(x), locked-in slip included, after vertex `vertex`."""
        return self._eval(vertex, FIELD_SLIP, x)

    def state(self, vertex):
        """The state after vertex `vertex` (negative: from the end) as a
        read-only Solution (hs_history_state): traction, slip (accumulated,
        locked-in slip included), pressure, surface_stress, stress,
        stress_scalar, surface_stress_extremes and the summary (b1, b2,
        slip_dir1/2, regime) apply, and so do the pictures of halfslip.plot;
        energy(), Bx() and work() raise HalfslipError ERR_NOT_APPLICABLE. The
        Solution holds a copy of the steps up to the vertex: it stays valid
        when the history grows or is closed."""
        h = self._handle()
        i = int(vertex)
        if i < 0:
            i += self.vertex_count
        if i < 0:
            raise IndexError("halfslip: History.state: vertex %d out of range (%d vertices)"
                             % (int(vertex), self.vertex_count))
        s = _clib.SolutionP()
        st = _lib.hs_history_state(h, i, byref(s))
        if st != 0:
            _raise(st, "hs_history_state", self._callback, {"vertex": int(vertex)})
        return Solution(s, callback=self._callback, scene=self.scene)

    def cycle_summary(self):
        """CycleSummary of the last add_cycles (HalfslipError ERR_NOT_APPLICABLE without one)."""
        c = _clib.CycleSummary()
        c.struct_size = ctypes.sizeof(c)
        self._status(_lib.hs_history_cycle_summary(self._handle(), byref(c)), "hs_history_cycle_summary")
        return CycleSummary(c.cycles, c.cycles_to_steady, bool(c.shakedown), c.energy_per_cycle1,
                            c.energy_per_cycle2, c.energy_per_cycle_patch, c.cycles_repeated, c.repeated_change)

    def slip_range(self, x):
        """Slip range max h - min h over the vertices of the last cycle, at x."""
        h = self._handle()
        xs, n, scalar = _points(x)
        out = array.array("d", bytes(n * ctypes.sizeof(c_double)))
        if n:
            st = _lib.hs_history_slip_range(h, n, xs, (c_double * n).from_buffer(out))
        else:
            st = _lib.hs_history_slip_range(h, 0, None, None)
        self._status(st, "hs_history_slip_range")
        return out[0] if scalar else out


# ---- arbitrary-precision reference backend ---------------------------------------------------

class Certified(str):
    """A decimal string (scientific notation) with the number of its leading
    significant digits that are certified, in the attribute `certified`."""

    def __new__(cls, text, certified):
        self = super().__new__(cls, text)
        self.certified = certified
        return self

    def __repr__(self):
        return "Certified(%s, certified=%d)" % (str.__repr__(self), self.certified)


def ref_max_digits(geometry=None):
    """Largest number of digits solve_reference accepts: for Hertz, or for the
    given geometry (a GEOMETRY_* value or name; lower for the flat punch and
    the power law, 0 for a geometry the reference backend does not solve)."""
    if geometry is None:
        return _lib.hs_ref_max_digits()
    return _lib.hs_ref_max_digits_geometry(_geometry_kind(geometry, None, None, None, None))


def _decimal(v, name="value", where="solve_reference"):
    if v is None:
        return None
    if isinstance(v, bool) or not isinstance(v, (str, int, float)) and not hasattr(v, "as_tuple"):
        raise ValueError("halfslip.%s: %s=%r is not a decimal number (give a str, int, float "
                         "or decimal.Decimal)" % (where, name, v))
    try:
        return (v if isinstance(v, str) else str(v)).encode("ascii")
    except UnicodeEncodeError:
        raise ValueError("halfslip.%s: %s=%r is not a decimal number" % (where, name, v)) from None


def solve_reference(digits, Q_over_fP=None, sigma_over_fp0=None, *, a=None, p0=None, f=None, E_star=None,
                    P=None, R=None, Q=None, sigma=None, geometry=None, flat_over_a=None, exponent=None):
    """Solve to `digits` significant digits with the MPFR reference backend.
    Inputs are decimal strings (exact decimals stay exact; numbers are
    converted with str()); unset ones take the C defaults. With P given, the
    dimensional input P, R, Q, sigma (with E_star, f) is used (Hertz only).
    flat_over_a=b_f/a (flat punch with rounded corners) or exponent=n (power
    law) selects that geometry, as does geometry= (a GEOMETRY_* value or
    name; the parameter then defaults to "0.5" or "2"); at most
    ref_max_digits(geometry) digits. Returns a ReferenceSolution whose values
    are Certified strings."""
    c = _clib.RefScene()
    _check(_lib.hs_ref_scene_default(byref(c)), "hs_ref_scene_default")
    if isinstance(digits, bool) or not isinstance(digits, int):
        raise ValueError("halfslip.solve_reference: digits=%r is not an integer" % (digits,))
    keep = {}
    values = dict(a=a, p0=p0, f=f, E_star=E_star, Q_over_fP=Q_over_fP, sigma_over_fp0=sigma_over_fp0,
                  P=P, R=R, Q=Q, sigma=sigma, flat_over_a=flat_over_a, exponent=exponent)
    for k, v in values.items():
        if v is not None:
            keep[k] = _decimal(v, k)
            setattr(c, k, keep[k])
    kind = _geometry_kind(geometry, flat_over_a, exponent, None, None)
    if kind is not None:
        c.geometry = kind
    values.update(digits=digits, geometry=geometry)
    h = _clib.RefSolutionP()
    st = _lib.hs_ref_solve(byref(c), digits, byref(h))
    if st == ERR_BAD_OPTION and not 1 <= digits <= ref_max_digits(c.geometry):
        raise HalfslipError(st, "hs_ref_solve", "digits=%d (1 to %d for this geometry)"
                            % (digits, ref_max_digits(c.geometry)))
    _check(st, "hs_ref_solve", values)
    return ReferenceSolution(h)


def history_reference(digits, path, *, a=None, p0=None, f=None, E_star=None, geometry=None, flat_over_a=None,
                      exponent=None):
    """Certified load history along one ray through the origin (issue 14): path
    is a list of (Q/fP, sigma/fp0) vertices (decimal strings, or numbers
    converted with str()), all on one ray through the origin, with no zone
    receding on the ramp to the farthest one; each state is a sum of monotonic
    solutions of the reference backend (docs/history.md). Other paths raise
    HalfslipError (HS_ERR_NOT_APPLICABLE): march them in double with History.
    Returns a ReferenceHistory."""
    c = _clib.RefScene()
    _check(_lib.hs_ref_scene_default(byref(c)), "hs_ref_scene_default")
    if isinstance(digits, bool) or not isinstance(digits, int):
        raise ValueError("halfslip.history_reference: digits=%r is not an integer" % (digits,))
    keep = {}
    for k, v in dict(a=a, p0=p0, f=f, E_star=E_star, flat_over_a=flat_over_a, exponent=exponent).items():
        if v is not None:
            keep[k] = _decimal(v, k, "history_reference")
            setattr(c, k, keep[k])
    kind = _geometry_kind(geometry, flat_over_a, exponent, None, None)
    if kind is not None:
        c.geometry = kind
    h = _clib.RefHistoryP()
    _check(_lib.hs_ref_history_new(byref(c), digits, byref(h)), "hs_ref_history_new",
           dict(digits=digits, geometry=geometry))
    r = ReferenceHistory(h)
    try:
        for i, (q, s) in enumerate(path):
            qs, ss = _decimal(q, "Q_over_fP", "history_reference"), _decimal(s, "sigma_over_fp0", "history_reference")
            qa, sa = (c_char_p * 1)(qs), (c_char_p * 1)(ss)
            _check(_lib.hs_ref_history_add_vertices(h, 1, qa, sa), "hs_ref_history_add_vertices",
                   {"vertex": i + 1, "Q_over_fP": q, "sigma_over_fp0": s})
    except BaseException:
        r.close()
        raise
    return r


class ReferenceHistory(_Handle):
    """A certified load history along one ray (history_reference). For vertex i:
    value(i, 'b1' | 'b2' | 'energy1' | 'energy2') is a Certified string (the
    stick zone after the vertex, the energy of the segment ending there) and
    slip_dirs(i) the directions (+1, -1, 0)."""

    def __init__(self, handle):
        self._h = handle

    def _handle(self):
        if not self._h:
            raise ValueError("halfslip: the reference history has been closed")
        return self._h

    def _release(self, h):
        if h:
            _lib.hs_ref_history_free(h)

    @property
    def vertex_count(self):
        n = c_size_t(0)
        _check(_lib.hs_ref_history_vertex_count(self._handle(), byref(n)), "hs_ref_history_vertex_count")
        return n.value

    def value(self, vertex, quantity):
        q = {"b1": 1, "b2": 2, "energy1": 5, "energy2": 6}.get(quantity)
        if q is None:
            raise ValueError("halfslip: quantity %r (one of b1, b2, energy1, energy2)" % (quantity,))
        return _ref_text(_lib.hs_ref_history_value, "hs_ref_history_value", (self._handle(), vertex, q),
                         {"vertex": vertex})

    def slip_dirs(self, vertex):
        d1, d2 = c_int(0), c_int(0)
        _check(_lib.hs_ref_history_slip_dirs(self._handle(), vertex, byref(d1), byref(d2)),
               "hs_ref_history_slip_dirs", {"vertex": vertex})
        return d1.value, d2.value

    def __repr__(self):
        return "<halfslip.ReferenceHistory, %s>" % ("%d vertices" % self.vertex_count if self._h else "closed")


def _ref_text(fn, name, args, values=None):
    """Call hs_ref_value / hs_ref_eval / hs_ref_eval_stress, growing the buffer on
    HS_ERR_BUFFER_TOO_SMALL; values: the arguments named in an error's message."""
    size = 64
    while True:
        buf = ctypes.create_string_buffer(size)
        needed, certified = c_size_t(0), c_int(-1)
        st = fn(*args, buf, size, byref(needed), byref(certified))
        if st == ERR_BUFFER_TOO_SMALL and needed.value > size:
            size = needed.value
            continue
        _check(st, name, values)
        return Certified(buf.value.decode("ascii"), certified.value)


class ReferenceSolution(_Handle):
    """A reference (MPFR) solution. Values are Certified strings: b1, b2, d1,
    d2, a, p0, energy(), the point evaluations Bx(x), slip(x), work(x),
    pressure(x), traction(x) at a decimal point x (or a list of them), and the
    stresses stress(x, y, body, pad_bulk) in either body."""

    def __init__(self, handle):
        self._h = handle
        s = _clib.RefSummary()
        s.struct_size = ctypes.sizeof(s)
        st = _lib.hs_ref_solution_summary(handle, byref(s))
        if st != 0:
            self.close()
            raise HalfslipError(st, "hs_ref_solution_summary")
        self._s = s

    regime = property(lambda self: _enum_or_int(Regime, self._s.regime))
    regime_name = property(lambda self: _REGIME_NAMES.get(self._s.regime, "unknown"))
    slip_dir1 = property(lambda self: self._s.slip_dir1)
    slip_dir2 = property(lambda self: self._s.slip_dir2)
    iterations = property(lambda self: self._s.iterations)
    digits = property(lambda self: self._s.digits, doc="requested significant digits")
    working_digits = property(lambda self: self._s.working_digits, doc="digits of the working precision")
    check_digits = property(lambda self: self._s.check_digits, doc="digits of the certifying run")

    def _handle(self):
        if not self._h:
            raise ValueError("halfslip: the reference solution has been closed")
        return self._h

    def _release(self, h):
        if h:
            _lib.hs_ref_solution_free(h)

    def __repr__(self):
        return "<halfslip.ReferenceSolution %s, %d digits%s>" % (
            self.regime_name, self.digits, "" if self._h else " (closed)")

    def value(self, quantity):
        """One of 'b1', 'b2', 'd1', 'd2', 'energy1', 'energy2', 'a', 'p0'."""
        try:
            q = _REF_QUANTITIES[quantity]
        except KeyError:
            raise ValueError("halfslip: unknown reference quantity %r (one of %s)"
                             % (quantity, ", ".join(_REF_QUANTITIES))) from None
        return _ref_text(_lib.hs_ref_value, "hs_ref_value", (self._handle(), q))

    b1 = property(lambda self: self.value("b1"))
    b2 = property(lambda self: self.value("b2"))
    d1 = property(lambda self: self.value("d1"))
    d2 = property(lambda self: self.value("d2"))
    a = property(lambda self: self.value("a"))
    p0 = property(lambda self: self.value("p0"))

    def energy(self):
        return self.value("energy1"), self.value("energy2")

    def _eval(self, what, x):
        h = self._handle()
        if isinstance(x, (str, bytes, int, float)):
            return _ref_text(_lib.hs_ref_eval, "hs_ref_eval",
                             (h, _REF_EVALS[what], x if isinstance(x, bytes) else _decimal(x, "x", what)),
                             {"x": x})
        return [self._eval(what, v) for v in x]

    def Bx(self, x):
        return self._eval("Bx", x)

    def slip(self, x):
        return self._eval("slip", x)

    def work(self, x):
        return self._eval("work", x)

    def pressure(self, x):
        return self._eval("pressure", x)

    def traction(self, x):
        """Shear traction q(x) on body 1 (positive in +x, integral Q) at the decimal
        point x, |x| <= a (HS_REF_EVAL_TRACTION), or a list of them."""
        return self._eval("traction", x)

    def stress(self, x, y, body=None, pad_bulk="0"):
        """(sigma_xx, sigma_yy, sigma_xy) as Certified strings at the decimal point
        (x, y) of body 1 (specimen, y >= 0) or 2 (pad, y <= 0); y = 0 is the surface.
        body defaults to 1 for y >= 0 and 2 for y < 0 (as Solution.stress; give
        body=2 for the pad's surface). pad_bulk: the pad's bulk stress (a decimal;
        the specimen carries sigma + pad_bulk). Lists x, y give a list of tuples."""
        h = self._handle()
        if not isinstance(x, (str, bytes, int, float)):
            ys = list(y)
            xs = list(x)
            if len(xs) != len(ys):
                raise ValueError("x and y differ in length")
            return [self.stress(u, v, body, pad_bulk) for u, v in zip(xs, ys)]
        cx = x if isinstance(x, bytes) else _decimal(x, "x", "ReferenceSolution.stress")
        cy = y if isinstance(y, bytes) else _decimal(y, "y", "ReferenceSolution.stress")
        cb = None if pad_bulk is None else _decimal(pad_bulk, "pad_bulk", "ReferenceSolution.stress")
        if body is None:  # exact sign of the decimal (a bad string is reported by the C library)
            try:
                body = 2 if decimal.Decimal(cy.decode("ascii")) < 0 else 1
            except (decimal.InvalidOperation, ValueError):
                body = 1
        values = {"x": x, "y": y, "body": body, "pad_bulk": pad_bulk}
        return tuple(_ref_text(_lib.hs_ref_eval_stress, "hs_ref_eval_stress", (h, int(body), cb, c, cx, cy), values)
                     for c in (STRESS_XX, STRESS_YY, STRESS_XY))

# ---- batches (issue 16) -----------------------------------------------------------------

BATCH_FIELDS = ("status", "regime", "slip_dir1", "slip_dir2", "model", "iterations", "b1", "b2", "d1", "d2",
                "error_estimate", "energy1", "energy2")


def solve_batch(Q_over_fP, sigma_over_fp0, *, a=1.0, p0=1.0, f=1.0, E_star=1.0, energies=False, threads=0,
                max_iterations=None, rtol=None, model=None):
    """Solve many Hertz scenes at once with hs_solve_batch (std::threads in the C
    library; threads=0: one per core). Q_over_fP and sigma_over_fp0 are
    sequences of equal length (lists, array.array, numpy arrays, ...); a, p0,
    f, E_star are shared. Returns a dict of lists, one entry per scene, keyed by
    BATCH_FIELDS: "status" (0 or the scene's ERR_*; strerror gives the message),
    regime, slip directions, model, iterations, b1, b2, d1, d2,
    error_estimate, and with energies=True energy1, energy2 (else 0). Each
    entry is bitwise what solve() and the Solution's summary (and energies)
    give for that scene; a failing scene does not stop the others. Raises
    HalfslipError for bad arguments of the call itself (threads, options)."""
    q = [float(v) for v in Q_over_fP]
    s = [float(v) for v in sigma_over_fp0]
    if len(q) != len(s):
        raise ValueError("halfslip.solve_batch: Q_over_fP has %d values, sigma_over_fp0 %d" % (len(q), len(s)))
    if isinstance(threads, bool) or not isinstance(threads, int):
        raise ValueError("halfslip.solve_batch: threads=%r is not an integer" % (threads,))
    n = len(q)
    scenes = (_clib.Scene * max(n, 1))()
    base = _clib.Scene()
    _check(_lib.hs_scene_default(byref(base)), "hs_scene_default")
    base.a, base.p0, base.f, base.E_star = (_float(v, k, "solve_batch") for v, k in
                                            ((a, "a"), (p0, "p0"), (f, "f"), (E_star, "E_star")))
    for i in range(n):
        scenes[i] = base
        scenes[i].Q_over_fP = q[i]
        scenes[i].sigma_over_fp0 = s[i]
    opts = None
    if max_iterations is not None or rtol is not None or model is not None:
        o = _clib.Options()
        _check(_lib.hs_options_default(byref(o)), "hs_options_default")
        if max_iterations is not None:
            o.max_iterations = int(max_iterations)
        if rtol is not None:
            o.rtol = _float(rtol, "rtol", "solve_batch")
        if model is not None:
            o.model = Model._parse(model, "model")
        opts = byref(o)
    out = (_clib.BatchResult * max(n, 1))()
    flags = 1 if energies else 0  # HS_BATCH_ENERGIES
    st = _lib.hs_solve_batch(n, scenes, opts, flags, threads, out, ctypes.sizeof(_clib.BatchResult))
    _check(st, "hs_solve_batch", {"threads": threads, "max_iterations": max_iterations, "rtol": rtol,
                                  "model": None if model is None else str(model)})
    return {k: [getattr(out[i], k) for i in range(n)] for k in BATCH_FIELDS}
