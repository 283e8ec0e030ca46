"""A minimal PEP 517 build backend for the halfslip Python package, standard
library only, so that `pip install ./bindings/python` works offline with no
build dependency to download (pyproject.toml: requires = []).

The wheel holds the pure-Python package halfslip. If a halfslip shared library
is found at build time it is bundled next to the package (and the wheel is
tagged for this platform); it is looked for at
  $HALFSLIP_LIBRARY                      (a file libhalfslip.so.N)
  $HALFSLIP_BUILD_DIR/libhalfslip.so.N   (a CMake build directory)
  <repository>/build/libhalfslip.so.N    (the default build directory)
Set HALFSLIP_BUNDLE=0 to build a pure wheel that finds the library at run
time instead (next to the package, in PREFIX/lib when installed under the
same prefix as `cmake --install`, $HALFSLIP_LIBRARY, or the system loader).
"""

import base64
import hashlib
import io
import os
import re
import sysconfig
import tarfile
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
PROJECT = os.path.dirname(HERE)            # bindings/python
REPO = os.path.dirname(os.path.dirname(PROJECT))
NAME = "halfslip"
SUMMARY = "Half-plane partial-slip contact: Python binding (ctypes) of the halfslip C library"


def _version():
    with open(os.path.join(PROJECT, NAME, "__init__.py")) as fh:
        return re.search(r'^__version__ = "([^"]+)"', fh.read(), re.M).group(1)


def _soversion():
    with open(os.path.join(PROJECT, NAME, "_clib.py")) as fh:
        return int(re.search(r"^SOVERSION = (\d+)", fh.read(), re.M).group(1))


def _library():
    """The shared library to bundle, or None."""
    if os.environ.get("HALFSLIP_BUNDLE", "1") == "0":
        return None
    name = "libhalfslip.so.%d" % _soversion()
    candidates = []
    if os.environ.get("HALFSLIP_LIBRARY"):
        candidates.append(os.environ["HALFSLIP_LIBRARY"])
    if os.environ.get("HALFSLIP_BUILD_DIR"):
        candidates.append(os.path.join(os.environ["HALFSLIP_BUILD_DIR"], name))
    candidates.append(os.path.join(REPO, "build", name))
    for c in candidates:
        if os.path.isfile(c):
            return os.path.realpath(c)
    return None


def _metadata(version):
    return ("Metadata-Version: 2.1\nName: %s\nVersion: %s\nSummary: %s\nRequires-Python: >=3.8\n"
            "License: MIT\nClassifier: Programming Language :: Python :: 3\n"
            "Classifier: Topic :: Scientific/Engineering :: Physics\n"
            "Provides-Extra: numpy\nRequires-Dist: numpy; extra == \"numpy\"\n" % (NAME, version, SUMMARY))


def _package_files():
    out = []
    pkg = os.path.join(PROJECT, NAME)
    for f in sorted(os.listdir(pkg)):
        if f.endswith(".py") and f != "_install.py":
            out.append((os.path.join(pkg, f), "%s/%s" % (NAME, f)))
    return out


def _tag(bundled):
    if not bundled:
        return "py3-none-any"
    plat = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return "py3-none-%s" % plat


def _record_line(arcname, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode("ascii")
    return "%s,sha256=%s,%d" % (arcname, digest, len(data))


def _write_wheel(wheel_directory, editable=False):
    version = _version()
    lib = None if editable else _library()
    tag = _tag(lib is not None)
    distinfo = "%s-%s.dist-info" % (NAME, version)
    wheel_name = "%s-%s-%s.whl" % (NAME, version, tag)
    entries = []
    if editable:   # a .pth file pointing at the source tree
        entries.append(("%s.pth" % NAME, (PROJECT + "\n").encode()))
    else:
        for src, arc in _package_files():
            with open(src, "rb") as fh:
                entries.append((arc, fh.read()))
        if lib is not None:
            with open(lib, "rb") as fh:
                entries.append(("%s/libhalfslip.so.%d" % (NAME, _soversion()), fh.read()))
    entries.append(("%s/METADATA" % distinfo, _metadata(version).encode()))
    entries.append(("%s/WHEEL" % distinfo,
                    ("Wheel-Version: 1.0\nGenerator: halfslip_build\nRoot-Is-Purelib: %s\nTag: %s\n"
                     % ("false" if lib else "true", tag)).encode()))
    record = "\n".join(_record_line(a, d) for a, d in entries) + "\n%s/RECORD,,\n" % distinfo
    entries.append(("%s/RECORD" % distinfo, record.encode()))
    path = os.path.join(wheel_directory, wheel_name)
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as zf:
        for arc, data in entries:
            info = zipfile.ZipInfo(arc, date_time=(2020, 1, 1, 0, 0, 0))
            info.external_attr = (0o755 if arc.endswith(".so.%d" % _soversion()) else 0o644) << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            zf.writestr(info, data)
    return wheel_name


# ---- PEP 517 / PEP 660 hooks -------------------------------------------------------------

def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def get_requires_for_build_editable(config_settings=None):
    return []


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    return _write_wheel(wheel_directory)


def build_editable(wheel_directory, config_settings=None, metadata_directory=None):
    return _write_wheel(wheel_directory, editable=True)


def build_sdist(sdist_directory, config_settings=None):
    version = _version()
    base = "%s-%s" % (NAME, version)
    path = os.path.join(sdist_directory, base + ".tar.gz")
    with tarfile.open(path, "w:gz", format=tarfile.PAX_FORMAT) as tf:
        for rel in ["pyproject.toml", "_backend/halfslip_build.py"] + [a for _, a in _package_files()]:
            tf.add(os.path.join(PROJECT, rel), arcname="%s/%s" % (base, rel))
        data = ("Metadata-Version: 2.1\nName: %s\nVersion: %s\nSummary: %s\n" % (NAME, version, SUMMARY)).encode()
        info = tarfile.TarInfo("%s/PKG-INFO" % base)
        info.size = len(data)
        tf.addfile(info, io.BytesIO(data))
    return base + ".tar.gz"
