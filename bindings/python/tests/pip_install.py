"""`pip install ./bindings/python` works offline and the installed package finds
its library by itself. argv: WORKDIR [LIBRARY]. Installs with
`pip install --no-index --no-build-isolation --target WORKDIR/site bindings/python`
(the in-tree backend needs nothing else), LIBRARY (if given) bundled through
HALFSLIP_LIBRARY at build time; then imports the package in a fresh interpreter
with no HALFSLIP_LIBRARY and checks that it loaded the bundled copy."""
import os
import shutil
import subprocess
import sys

work = os.path.abspath(sys.argv[1])
lib = sys.argv[2] if len(sys.argv) > 2 else None
project = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
site = os.path.join(work, "site")
env = {k: v for k, v in os.environ.items() if not k.startswith(("HALFSLIP_", "PYTHON", "PIP_"))}
env["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
build_env = dict(env)
if lib:
    build_env["HALFSLIP_LIBRARY"] = lib
cmd = [sys.executable, "-m", "pip", "install", "--no-index", "--no-build-isolation", "--no-cache-dir",
       "--target", site, project]
p = subprocess.run(cmd, env=build_env, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                   universal_newlines=True)
print(p.stdout)
assert p.returncode == 0, "pip install failed"
code = ("import halfslip, os\n"
        "assert os.path.dirname(halfslip.library_path) == os.path.dirname(halfslip.__file__), "
        "halfslip.library_path\n"
        "s = halfslip.solve(model='auto')\n"
        "assert abs(s.b1 - 0.8321067811865476) < 1e-14, s.b1\n"
        "try:\n    import numpy\nexcept ImportError:\n    numpy = None\n"
        "if numpy is not None:\n"
        "    assert s.slip(numpy.full((4, 5), 0.95)).shape == (4, 5)\n"
        "print('pip-installed halfslip %s from %s (numpy: %s): ok' % (halfslip.__version__, halfslip.library_path,"
        " numpy is not None))\n")
env["PYTHONPATH"] = site
env["PYTHONDONTWRITEBYTECODE"] = "1"
p = subprocess.run([sys.executable, "-c", code], env=env, cwd=work, stdout=subprocess.PIPE,
                   stderr=subprocess.STDOUT, universal_newlines=True)
print(p.stdout)
sys.exit(p.returncode)
