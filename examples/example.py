"""halfslip from Python: the scene of example.c (a steel cylinder, radius
50 mm, on a steel half-plane: P = 100 kN/m, Q = 18 kN/m, bulk tension 20 MPa;
SI units, loads per unit length), the slip along the contact (numpy arrays if
numpy is installed), and b1 to 30 certified digits.

    PYTHONPATH=PREFIX/lib/python3/dist-packages python3 example.py   (after cmake --install)
    pip install ./bindings/python && python3 example.py
"""
import halfslip

P, R, E_star, f, Q, sigma = 1.0e5, 0.05, 1.154e11, 0.6, 1.8e4, 2.0e7   # N/m, m, Pa, -, N/m, Pa

scene = halfslip.from_hertz_loads(P=P, R=R, E_star=E_star, f=f, Q=Q, sigma=sigma)
with scene.solve(model="auto", rtol=1e-12) as sol:
    print("halfslip %s, Python example (model %s, %s regime)" % (halfslip.library_version, sol.model, sol.regime))
    print("contact half-width a = %.7g mm, peak pressure p0 = %.7g MPa" % (sol.a * 1e3, sol.p0 * 1e-6))
    print("stick zone: b1 = %.7g mm, b2 = %.7g mm" % (sol.b1 * 1e3, sol.b2 * 1e3))
    E1, E2 = sol.energy()
    print("energy dissipated: E1 = %.7g J/m, E2 = %.7g J/m" % (E1, E2))
    try:
        import numpy
        x = numpy.linspace(-sol.a, sol.a, 5)
    except ImportError:
        x = [sol.a * (-1 + 2 * i / 4) for i in range(5)]
    for xi, hi in zip(x, sol.slip(x)):
        print("  slip h(%.5g mm) = %.5g um" % (xi * 1e3, hi * 1e6))

ref = halfslip.solve_reference(30, P="1e5", R="0.05", E_star="1.154e11", f="0.6", Q="1.8e4", sigma="2e7")
print("b1 = %s m (%d digits certified)" % (ref.b1, ref.b1.certified))

try:
    halfslip.solve(scene=halfslip.from_hertz_loads(P, R, E_star, f, 2 * f * P, sigma))
except halfslip.HalfslipError as e:
    print("Q = 2fP:", e)
