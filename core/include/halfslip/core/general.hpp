// halfslip core: partial slip under constant normal load for a general
// contact pressure (issue #4): Hertz, flat punch with rounded corners, power
// law, sampled or callback pressure (pressure.hpp).
//
// Canonical frame (as hertz.hpp): a = 1, p_hat = p/p0 (p0 = 2P/(pi a)),
// f = E* = 1, q = Q/fP >= 0, s = sigma/(f p0) >= 0 after the symmetries
// (Q, sigma) -> (-Q, -sigma) (all slips flip) and sigma -> -sigma (mirror
// x -> -x; for an asymmetric pressure the mirrored pressure is used).
// Zone R = (b1, 1) slips with sign sR, zone L = (-1, -b2) with sL = +1;
// sR = +1 (same sign) or -1 (opposite sign). Side conditions (docs/conventions.md):
//   F1 = sL I1L - sR I1R - pi s/4                          = 0
//   F2 = sL I2L - sR I2R - pi s (b1 - b2)/8 + pi q/2       = 0
// with I_jZ = int_Z p_hat(t) t^(j-1) / sqrt(|t-b1||t+b2|) dt. The solver uses
// F2 - c F1 in place of F2, c = (b1 - b2)/2 the stick-zone centre: the
// moment about the centre, sL K_L - sR K_R + pi q/2 with K_Z = int_Z p_hat
// (t - c)/sqrt(|t-b1||t+b2|) dt. The pi s terms cancel exactly and t - c
// = +-(distance to the stick edge + e/2) has no cancellation, so the second
// condition keeps full accuracy as s grows (as s -> infinity it becomes the
// balance q pi/2 = int_{-1}^{x0} p_hat - int_{x0}^{1} p_hat; issue 13).
//
// Unknowns. One Newton iteration covers both regimes: x1 = +d1 (same sign) or
// -d1 (opposite sign), d1 = 1 - b1 the length of zone R, and x2 = ln e, e = b1 + b2
// the stick-zone length (tiny for large s). Since I_jR = O(d1) as d1 -> 0, the
// residual sR(x1) I_jR(|x1|) is C^1 across x1 = 0 (the regime boundary) and
// the iteration crosses it freely; the regime is the sign of x1 at the
// solution. This is the rule "solve same-sign first; if it has no solution
// with b1 < a, the scene is opposite-sign": a same-sign solution is exactly
// a root with x1 > 0.
//
// Zone integrals: t = b1 + d1 sin^2(theta) (zone R), t = -b2 - d2 sin^2(theta)
// (zone L) turn both end behaviours (sqrt at the contact edge, 1/sqrt at the
// stick edge) into the smooth weight 2 d cos^2(theta). The remaining factor
// 1/sqrt(e + d sin^2 theta) is nearly singular at theta = 0 when e << d:
// panels are graded geometrically towards 0 from theta ~ sqrt(e/d). Pressure
// kinks are panel ends; at graded kinks (log-singular p') the panel is mapped
// polynomially, theta = end + L u^m (m from the precision). Gauss-Legendre
// of order N per panel, nodes computed in T. N doubles until the residual
// evaluated with 2N agrees with zero to the tolerance; the order used is
// reported.
//
// Zone energies and slips (general_solution::energy_hat, hhat) reuse these
// panels with fixed Gauss-Legendre rules: h' at the nodes of order M from
// Cauchy sums over the nodes of order M + 1 (interlacing on shared panels),
// the pressure tail cumulated on the same nodes (Legendre integration
// matrix); M doubles until two orders agree to max(rtol, eps^(3/4)).
// Beyond long double, graded kinks get geometric layers of panels and the
// own zone's graded panels a high-order inner rule (see make_panels and
// graded_inner_order). The
// nested adaptive evaluations remain as energy_hat_adaptive / hhat_adaptive
// (reference only: ~1000x slower).
//
// The pieces: general_panels.hpp (quadrature panels in theta, node maps,
// node caches), general_residual.hpp (the zone integrals and the residual),
// general_post.hpp (general_solution: energies, slips, traction),
// general_solver.hpp (Newton, starts, continuation, order control).
#pragma once
#include "general_panels.hpp"
#include "general_post.hpp"
#include "general_residual.hpp"
#include "general_solver.hpp"
