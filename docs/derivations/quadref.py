"""Reference values by tanh-sinh quadrature (mpmath.quad), endpoint-split.
Substitution t = b1 + tau, tau = e sinh^2(u), u in (0,U), U = asinh(sqrt((1-b1)/e)):
   dt / R(t) = 2 du  exactly  (R = sqrt(tau (tau+e))),
   1-t = e sinh(U-u) sinh(U+u),  1+t = (1+b1)+tau.
so int_{b1}^1 g(t) w(t)/R(t) dt = 2 int_0^U g(t) sqrt((1-t)(1+t)) du; the interval (0,U) is split
into pieces of length <= 1 (U ~ 35 for e=1e-30)."""
import mpmath as mp

def zone_quad(p, g):
    b1, e = p['b1'], p['e']
    U = mp.asinh(mp.sqrt(p['om1']/e))
    def F(u):
        sh = mp.sinh(u); tau = e*sh*sh
        omt = e*mp.sinh(U-u)*mp.sinh(U+u)
        if omt < 0: omt = mp.mpf(0)     # roundoff at the node next to u=U
        opt = p['op1'] + tau
        return 2*g(b1+tau, tau, omt, opt)*mp.sqrt(omt*opt)
    n = int(mp.ceil(U)) + 1
    pts = [U*k/n for k in range(n+1)]
    return mp.quad(F, pts)

def I_A0(p):  return zone_quad(p, lambda t,tau,omt,opt: 1)
def I_A1(p):  return zone_quad(p, lambda t,tau,omt,opt: t)
def I_G(p):   return zone_quad(p, lambda t,tau,omt,opt: 1/(tau + p['b1mx']))   # t-x = tau + (b1-x)
