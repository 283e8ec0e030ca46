"""Closed forms (Carlson) for the single-zone integrals.  Parameters: b1, e=b1+b2 (passed separately
for accuracy as e->0), optionally f in (0,1) with x = -1 + f*(1-b2) (left-zone point)."""
import mpmath as mp

def params(b1, e, f=None):
    p = {}
    b1 = mp.mpf(b1); e = mp.mpf(e)
    b2 = e - b1
    p['b1'] = b1; p['b2'] = b2; p['e'] = e
    p['om1'] = 1 - b1            # 1-b1  (exact if b1 is a double close to 1)
    p['op1'] = 1 + b1
    p['op2'] = (1 - b1) + e      # 1+b2 = (1-b1)+(b1+b2)  : sum of positives
    # 1-b2 = 1+b1-e with a single rounding: for e>=1/2, 1-e is exact (Sterbenz); for e<1/2 the
    # dangerous case (b2 -> 1) has b1 < -1/2, where 1+b1 is exact.
    p['om2'] = ((1 - e) + b1) if e >= mp.mpf(0.5) else (p['op1'] - e)
    p['d12'] = 2*b1 - e          # b1-b2 formed from the inputs (one rounding)
    p['P'] = 2*e                 # (a-d)(b-c) = 2(b1+b2)
    p['Q'] = p['op1']*p['op2']   # (a-c)(b-d) = (1+b1)(1+b2)
    p['c'] = 2*p['op2']          # 2(1+b2)
    if f is not None:
        f = mp.mpf(f)
        p['f'] = f
        p['opx'] = f*p['om2']                 # 1+x
        p['x'] = -1 + p['opx']
        p['b1mx'] = e + (1-f)*p['om2']        # b1 - x = (b1+b2) + (-b2-x)
        p['omx'] = 2 - p['opx']               # 1-x
        p['q'] = p['c']*p['b1mx']/p['omx']    # 2(1+b2)(b1-x)/(1-x)
    return p

def basis(p):
    P,Q,c = p['P'],p['Q'],p['c']
    B = {}
    B['RF']  = mp.elliprf(0, P, Q)
    B['RDa'] = mp.elliprd(0, P, Q)   # R_D(0,P,Q)
    B['RDb'] = mp.elliprd(0, Q, P)   # R_D(0,Q,P)
    B['RJc'] = mp.elliprj(0, P, Q, c)
    if 'q' in p: B['RJq'] = mp.elliprj(0, P, Q, p['q'])
    return B

# ---------------- closed forms -----------------
# --- single-formula versions (valid everywhere, but condition number ~ 1/(1+b1) as b1 -> -1) ---
def A0_single(p, B):
    om1, op2, om2, e, b1, b2 = p['om1'], p['op2'], p['om2'], p['e'], p['b1'], p['b2']
    return 2*om1*( B['RF'] + (b1-b2)*op2*B['RJc']/3 - om2*e*B['RDb']/3 )

def A1_single(p, B):
    om1, op2, om2, e, b1, b2 = p['om1'], p['op2'], p['om2'], p['e'], p['b1'], p['b2']
    return om1*( (3*b1-b2+2)*B['RF']/2
                 + op2*(3*b1**2-2*b1*b2+3*b2**2-4)*B['RJc']/6
                 - om2*(b1-b2)*e*B['RDb']/2 )

# --- recommended versions: kernel + mirror branch (all terms positive for A0) ---
def _A0k(d12, om1, op1, op2, om2, RF, RDa, RJ):
    # d12 = b1-b2 >= 0 for positivity of all terms; RJ = R_J(0,P,Q,2(1+b2))
    return om1*op2*( RF + op1*om2*RDa/3 + 2*d12*RJ/3 )

def _A1k(b1, b2, d12, e, om1, op2, om2, RF, RDb, RJ):
    return om1*( (3*b1-b2+2)*RF/2 + op2*(3*b1**2-2*b1*b2+3*b2**2-4)*RJ/6 - om2*d12*e*RDb/2 )

def _RJc2(p, B):
    if 'RJc2' not in B: B['RJc2'] = mp.elliprj(0, p['P'], p['Q'], 2*p['op1'])   # R_J(0,P,Q,2(1+b1))
    return B['RJc2']

def A0(p, B):
    if p['d12'] >= 0:
        return _A0k(p['d12'], p['om1'], p['op1'], p['op2'], p['om2'], B['RF'], B['RDa'], B['RJc'])
    # mirror: A0(b1,b2) = A0(b2,b1) + pi (b2-b1)/2 ; swapped: om1'=om2, op1'=op2, op2'=op1, om2'=om1
    return _A0k(-p['d12'], p['om2'], p['op2'], p['op1'], p['om1'], B['RF'], B['RDa'], _RJc2(p,B)) - mp.pi*p['d12']/2

def A1(p, B):
    b1, b2, e = p['b1'], p['b2'], p['e']
    if p['d12'] >= 0:
        return _A1k(b1, b2, p['d12'], e, p['om1'], p['op2'], p['om2'], B['RF'], B['RDb'], B['RJc'])
    # S = 3/8 (b1^2+b2^2) - b1 b2/4 - 1/2 = (b1-b2)^2/4 + ((b1+b2)^2-4)/8, with (b1+b2)-2 = -(om1+om2)
    S = p['d12']**2/4 - (p['om1']+p['om2'])*(2+e)/8
    return -_A1k(b2, b1, -p['d12'], e, p['om2'], p['op1'], p['om1'], B['RF'], B['RDb'], _RJc2(p,B)) - mp.pi*S

def G(p, B):
    om1, op2 = p['om1'], p['op2']
    return 4*om1*op2/3*( B['RJc'] + p['opx']/p['omx']*B['RJq'] )

def dA0db1(p, B):
    om1, op2, om2 = p['om1'], p['op2'], p['om2']
    return -2*B['RF'] + 2*om1*( op2*B['RJc'] - om2*B['RDb'] )/3

def dA0db2(p, B):
    om1, op2, om2 = p['om1'], p['op2'], p['om2']
    return -2*om1*( op2*B['RJc'] + om2*B['RDb'] )/3

def dA1db1(p, B):
    om1, op2, om2, b1, b2 = p['om1'], p['op2'], p['om2'], p['b1'], p['b2']
    return (1-3*b1)*B['RF'] + om1*( (3*b1-b2)*op2*B['RJc'] - (3*b1+b2)*om2*B['RDb'] )/3

def dA1db2(p, B):
    om1, op2, om2, b1, b2 = p['om1'], p['op2'], p['om2'], p['b1'], p['b2']
    return -om1*B['RF'] + om1*( -(b1-3*b2)*op2*B['RJc'] + (b1+3*b2)*om2*B['RDb'] )/3

# ---------------- Legendre forms (documentation) -----------------
def legendre(p):
    """K,E,Pi with m=k^2, n = -(1-b1)/(1+b1) (RJc) and n_x=(1-b1)(1+x)/((1+b1)(1-x)) (RJq)."""
    Q = p['Q']; m = p['om1']*p['om2']/Q
    K = mp.ellipk(m); E = mp.ellipe(m)
    n = -p['om1']/p['op1']
    Pi = mp.ellippi(n, m)
    out = dict(m=m, K=K, E=E, n=n, Pi=Pi)
    if 'q' in p:
        nx = p['om1']*p['opx']/(p['op1']*p['omx'])
        out['nx'] = nx; out['Pix'] = mp.ellippi(nx, m)
    return out

def basis_from_legendre(p, L):
    """RF, RDb, RJc (and RJq) expressed through K,E,Pi -- used to check the Legendre forms."""
    Q = p['Q']; m = L['m']; kp2 = 1-m; sQ = mp.sqrt(Q)
    B = {}
    B['RF'] = L['K']/sQ
    B['RDa'] = 3*(L['K']-L['E'])/(m*Q*sQ)
    B['RDb'] = 3*(L['E']-kp2*L['K'])/(m*kp2*Q*sQ)
    B['RJc'] = 3*(L['Pi']-L['K'])/(L['n']*Q*sQ)
    if 'Pix' in L: B['RJq'] = 3*(L['Pix']-L['K'])/(L['nx']*Q*sQ)
    return B
