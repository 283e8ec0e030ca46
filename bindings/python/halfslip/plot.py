"""Pictures of halfslip solutions (issue 15), drawn with matplotlib.

matplotlib (and numpy, which it needs) is an optional dependency: it is
imported when a function here is first called, and a missing matplotlib raises
ImportError with the way to install it (Debian: apt install python3-matplotlib;
elsewhere: pip install matplotlib). Every number drawn comes from the C library
through the halfslip binding; this module only lays it out. Lengths are drawn
in units of the contact half-width a, stresses and tractions in units of p0.

  tractions(sol)        p(x), q(x) and +-f p(x), the stick zone shaded
  slip(sol)             the slip h(x) (zero on the stick zone)
  surface_stress(sol)   sigma_xx(x, 0) of both bodies, their extremes marked
  stress_contour(sol)   a subsurface scalar (von Mises, principal, shear, components)
  regime_map()          the paper's Figure 3: contours of b1/a over (Q/fP, sigma/fp0),
                        and the boundary between same-sign and opposite-sign slip
  overview(sol)         the first four on one figure
  chart(series)         plain x-y chart (lines or markers, log axes), used by the
                        benchmark scripts

Each function takes an optional matplotlib Axes `ax` (a new figure when None)
and returns the Axes it drew on.
"""

import halfslip as _hs

_INSTALL = ("halfslip.plot needs matplotlib (and numpy): on Debian `apt install python3-matplotlib`, "
            "elsewhere `pip install matplotlib`")


def _mpl():
    """(numpy, matplotlib.pyplot), imported on first use."""
    try:
        import numpy as np
        import matplotlib
        import matplotlib.pyplot as plt
    except ImportError as e:
        raise ImportError("%s (%s)" % (_INSTALL, e)) from None
    del matplotlib
    return np, plt


def _axes(ax, size=(6.4, 4.0)):
    np, plt = _mpl()
    if ax is None:
        _, ax = plt.subplots(figsize=size, layout="constrained")
    return np, ax


def _shade_stick(ax, sol):
    ax.axvspan(-sol.b2 / sol.a, sol.b1 / sol.a, color="0.9", zorder=0, label="stick zone")


def tractions(sol, ax=None, n=801):
    """p(x), q(x) and the friction limits +-f p(x) over the contact, the stick zone shaded."""
    np, ax = _axes(ax)
    a, p0, f = sol.a, sol.p0, _friction(sol)
    x = a * np.linspace(-1, 1, n)
    p = sol.pressure(x)
    q = sol.traction(x)
    _shade_stick(ax, sol)
    ax.plot(x / a, p / p0, color="k", label="p")
    ax.plot(x / a, f * p / p0, color="0.5", ls="--", lw=1, label="±f p")
    ax.plot(x / a, -f * p / p0, color="0.5", ls="--", lw=1)
    ax.plot(x / a, q / p0, color="C3", label="q")
    ax.axhline(0, color="0.6", lw=0.5)
    ax.set_xlabel("x / a")
    ax.set_ylabel("traction / p0")
    ax.set_title("tractions (%s)" % sol.regime_name)
    ax.legend(loc="best", fontsize="small")
    return ax


def slip(sol, ax=None, n=801):
    """The slip h(x) = u_x(body 2) - u_x(body 1), zero on the stick zone, in units of f p0 a / E*."""
    np, ax = _axes(ax)
    a = sol.a
    x = a * np.linspace(-1, 1, n)
    h = sol.slip(x)
    scale = _friction(sol) * sol.p0 * a / _estar(sol)
    _shade_stick(ax, sol)
    ax.plot(x / a, h / scale, color="C0")
    ax.axhline(0, color="0.6", lw=0.5)
    ax.set_xlabel("x / a")
    ax.set_ylabel("h / (f p0 a / E*)")
    ax.set_title("slip")
    return ax


def surface_stress(sol, ax=None, half_range=3.0, pad_bulk=0.0, n=1201):
    """sigma_xx(x, 0) of body 1 (specimen) and body 2 (pad) over |x| <= half_range a,
    with each body's maximum and minimum (hs_surface_stress_extremes) marked."""
    np, ax = _axes(ax)
    a, p0 = sol.a, sol.p0
    x = a * np.linspace(-half_range, half_range, n)
    _shade_stick(ax, sol)
    for body, color, name in ((1, "C3", "body 1 (specimen)"), (2, "C0", "body 2 (pad)")):
        s = sol.surface_stress(x, body=body, pad_bulk=pad_bulk)
        ax.plot(x / a, s / p0, color=color, label=name)
        e = sol.surface_stress_extremes(body=body, pad_bulk=pad_bulk, half_range=half_range * a)
        ax.plot([e["x_max"] / a], [e["max"] / p0], "^", color=color, ms=6)
        ax.plot([e["x_min"] / a], [e["min"] / p0], "v", color=color, ms=6)
        if body == 1:
            ax.annotate("max %.3g p0" % (e["max"] / p0), (e["x_max"] / a, e["max"] / p0),
                        textcoords="offset points", xytext=(6, 4), fontsize="small", color=color)
    ax.axhline(0, color="0.6", lw=0.5)
    ax.set_xlabel("x / a")
    ax.set_ylabel("σ_xx(x, 0) / p0")
    ax.set_title("surface direct stress")
    ax.legend(loc="best", fontsize="small")
    return ax


_LABELS = {"sxx": "σ_xx", "syy": "σ_yy", "sxy": "σ_xy", "von_mises": "von Mises",
           "max_principal": "max principal stress", "min_principal": "min principal stress",
           "max_shear": "max shear stress"}


def stress_contour(sol, quantity="von_mises", body=1, ax=None, extent=(-2.0, 2.0, 0.0, 1.5), nx=200, ny=100,
                   nu=0.3, pad_bulk=0.0, levels=24, cmap="viridis"):
    """Filled contours of a stress scalar (Solution.stress_scalar: "von_mises", "max_principal",
    "min_principal", "max_shear", "sxx", "syy", "sxy") in body 1 (depth y > 0 drawn downwards) or
    body 2 (y < 0), on an nx x ny grid over extent = (x0, x1, depth0, depth1) in units of a."""
    np, ax = _axes(ax)
    a, p0 = sol.a, sol.p0
    x0, x1, d0, d1 = extent
    depth = np.linspace(max(d0, 1e-3 * (d1 - d0)), d1, ny)
    X, D = np.meshgrid(np.linspace(x0, x1, nx), depth)
    Y = D if body == 1 else -D
    v = sol.stress_scalar(np.ascontiguousarray(X * a), np.ascontiguousarray(Y * a), quantity, body=body, nu=nu,
                          pad_bulk=pad_bulk)
    cs = ax.contourf(X, D, v / p0, levels=levels, cmap=cmap)
    ax.contour(X, D, v / p0, levels=cs.levels[::3], colors="k", linewidths=0.3)
    ax.figure.colorbar(cs, ax=ax, label="%s / p0" % _LABELS.get(quantity, quantity))
    ax.invert_yaxis()
    ax.plot([-1, 1], [d0, d0], color="k", lw=3, solid_capstyle="butt")
    ax.plot([-sol.b2 / a, sol.b1 / a], [d0, d0], color="w", lw=1.5, solid_capstyle="butt")
    ax.set_xlabel("x / a")
    ax.set_ylabel("depth / a (body %d)" % body)
    ax.set_title("%s in body %d%s" % (_LABELS.get(quantity, quantity), body,
                                      " (ν = %g)" % nu if quantity == "von_mises" else ""))
    ax.set_aspect("equal")
    return ax


def regime_map(ax=None, nq=60, ns=81, s_max=4.0, levels=(-0.75, -0.5, -0.25, 0, 0.25, 0.5, 0.75, 0.9)):
    """The paper's Figure 3 regenerated from the library (Hertz): contours of b1/a over
    Q/fP in (0, 1) and sigma/(f p0) in [-s_max, s_max], and the boundary between
    same-sign and opposite-sign slip (where the solved regime changes; dotted).
    b2/a is the same map with sigma reversed."""
    np, ax = _axes(ax)
    qs = np.linspace(0.0, 1.0, nq + 2)[1:-1]
    ss = np.linspace(-s_max, s_max, ns)
    b1 = np.full((ns, nq), np.nan)
    reg = np.full((ns, nq), np.nan)
    for j, s in enumerate(ss):
        for i, q in enumerate(qs):
            try:
                with _hs.solve(Q_over_fP=float(q), sigma_over_fp0=float(s)) as sol:
                    b1[j, i] = sol.b1 / sol.a
                    reg[j, i] = int(sol.regime)
            except _hs.HalfslipError:
                pass
    Qg, Sg = np.meshgrid(qs, ss)
    cs = ax.contour(Qg, Sg, b1, levels=list(levels), cmap="viridis")
    ax.clabel(cs, fontsize="small", fmt="%g")
    ax.contour(Qg, Sg, reg, levels=[1.5], colors="k", linestyles=":", linewidths=1.2)
    ax.plot([], [], "k:", label="same sign | opposite sign")
    ax.set_xlabel("Q / fP")
    ax.set_ylabel("σ / (f p0)")
    ax.set_title("contours of b1/a (Hertz)")
    ax.legend(loc="lower left", fontsize="small")
    return ax


def overview(sol, title=None, quantity="von_mises", pad_bulk=0.0, nu=0.3):
    """tractions, slip, surface stress and a subsurface contour of one solution on one figure."""
    np, plt = _mpl()
    fig, axs = plt.subplots(2, 2, figsize=(11, 7.2), layout="constrained")
    tractions(sol, ax=axs[0, 0])
    slip(sol, ax=axs[0, 1])
    surface_stress(sol, ax=axs[1, 0], pad_bulk=pad_bulk)
    stress_contour(sol, quantity=quantity, ax=axs[1, 1], pad_bulk=pad_bulk, nu=nu)
    if title:
        fig.suptitle(title)
    return fig


def chart(series, ax=None, title=None, xlabel=None, ylabel=None, logx=False, logy=False, legend="best",
          size=(7.6, 4.6)):
    """A plain x-y chart. series: iterable of dicts with keys x, y and optional label,
    style ("line", "marker" or "hollow"), color, marker, ls. Returns the Axes."""
    np, ax = _axes(ax, size)
    for k, s in enumerate(series):
        style = s.get("style", "line")
        color = s.get("color", "C%d" % (k % 10))
        kw = {"label": s.get("label")}
        if style == "line":
            ax.plot(s["x"], s["y"], color=color, ls=s.get("ls", "-"), marker=s.get("marker"), ms=3, **kw)
        else:
            ax.plot(s["x"], s["y"], ls="none", marker=s.get("marker", "o"), ms=6, color=color,
                    mfc="none" if style == "hollow" else color, **kw)
    if logx:
        ax.set_xscale("log")
    if logy:
        ax.set_yscale("log")
    ax.grid(True, which="major", color="0.9")
    if title:
        ax.set_title(title, fontsize="medium")
    if xlabel:
        ax.set_xlabel(xlabel)
    if ylabel:
        ax.set_ylabel(ylabel)
    if legend and any(s.get("label") for s in series):
        ax.legend(loc=legend, fontsize="x-small")
    return ax


def save(fig_or_ax, path, dpi=100):
    """Write a figure (or the figure of an Axes) to path and close it."""
    _, plt = _mpl()
    fig = getattr(fig_or_ax, "figure", fig_or_ax)
    fig.savefig(path, dpi=dpi, metadata={"Date": None} if str(path).endswith(".svg") else None)
    plt.close(fig)


def _scene(sol):
    if getattr(sol, "scene", None) is None:
        raise ValueError("halfslip.plot: the solution does not carry its Scene (f, E_star); "
                         "solve it with halfslip.solve or Scene.solve")
    return sol.scene


def _friction(sol):
    return _scene(sol).f


def _estar(sol):
    return _scene(sol).E_star
