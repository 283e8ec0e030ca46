#!/usr/bin/env python3
"""Verification of the closed forms in closedforms.py against mpmath.quad (tanh-sinh, endpoint split).
usage: python3 verify.py [--quick]
Writes results to verify_results.txt (and prints them)."""
import sys, random, time
import mpmath as mp
from multiprocessing import Pool
import closedforms as CF
import quadref as QR

DPS = 40
mpf = mp.mpf

def sample_points(rng):
    pts = []   # (b1, e, f, tag)  ; b2 = e - b1, x = -1 + f(1-b2)
    def rf(): return rng.random()
    # generic
    while len([q for q in pts if q[3]=='generic']) < 100:
        b1 = 2*rf()-1; b2 = 2*rf()-1
        if b1+b2 > 0: pts.append((mpf(b1), mpf(b1)+mpf(b2), mpf(rf()), 'generic'))
    # k -> 1 : b1+b2 = e tiny (b2 negative when b1 > e)
    for e in ['1e-3','1e-8','1e-15','1e-30']:
        for i in range(15):
            b1 = -0.95 + 1.9*rf()
            pts.append((mpf(b1), mpf(e), mpf(rf()), 'e=%s'%e))
    # k -> 0 : b1 = 1-1e-12
    for i in range(15):
        b1 = 1-mpf('1e-12'); b2 = -b1 + (2-1e-3)*rf() + 1e-4   # b2 in (-b1, 1)
        b2 = min(b2, 1-mpf('1e-6'))
        pts.append((b1, b1+b2, mpf(rf()), 'b1=1-1e-12'))
    # k -> 0 : b2 = 1-1e-12
    for i in range(10):
        b2 = 1-mpf('1e-12'); b1 = -b2 + (2-1e-3)*rf() + 1e-4
        b1 = min(b1, 1-mpf('1e-6'))
        pts.append((b1, b1+b2, mpf(rf()), 'b2=1-1e-12'))
    # corner b1 -> -1 (forces b2 -> 1)
    # dyadic values so that the double-precision proxy sees exactly the same inputs
    for kexp in [10, 20, 40]:
        for e in [mpf(2)**-100, mpf(2)**-(kexp+12), mpf(rng.randint(1,15))*mpf(2)**-(kexp+4)]:
            b1 = -1 + mpf(2)**-kexp
            pts.append((b1, e, mpf(rng.randint(1,255))/256, 'b1=-1+2^-%d'%kexp))
    # b2 strongly negative
    for i in range(15):
        b2 = -0.999*rf(); b1 = -b2 + (1+b2)*rf()
        pts.append((mpf(b1), mpf(b1)+mpf(b2), mpf(rf()), 'b2<0'))
    # x at the ends of the left zone, with small and moderate e
    for e in ['0.3','1e-8','1e-30']:
        for f in ['1e-12','1e-6', '0.999999', '0.999999999999']:
            b1 = -0.9 + 1.8*rf()
            if mpf(e) - mpf(b1) >= 1 or mpf(e)-mpf(b1) <= -1: b1 = 0.2
            pts.append((mpf(b1), mpf(e), mpf(f), 'x-end e=%s f=%s'%(e,f)))
    return pts

def check_point(args):
    b1, e, f, tag, do_deriv = args
    mp.mp.dps = DPS
    p = CF.params(b1, e, f); B = CF.basis(p)
    res = {}
    vals = {'A0': (CF.A0(p,B), QR.I_A0(p)), 'A1': (CF.A1(p,B), QR.I_A1(p)), 'G': (CF.G(p,B), QR.I_G(p)),
            'A0_single': (CF.A0_single(p,B), None), 'A1_single': (CF.A1_single(p,B), None)}
    vals['A0_single'] = (vals['A0_single'][0], vals['A0'][1]); vals['A1_single'] = (vals['A1_single'][0], vals['A1'][1])
    for k,(cf,ref) in vals.items():
        res[k] = (abs(cf-ref)/abs(ref), ref)
    # A1 can vanish (b1<0): also report error relative to int |t| w/R <= A0
    res['A1/A0'] = (abs(vals['A1'][0]-vals['A1'][1])/abs(vals['A0'][1]), None)
    res['A1_single/A0'] = (abs(vals['A1_single'][0]-vals['A1'][1])/abs(vals['A0'][1]), None)
    del res['A1_single']
    # mirror (left-zone) identities, closed forms only
    pm = CF.params(p['b2'], e); Bm = CF.basis(pm)
    lhs0 = CF.A0(pm,Bm) - CF.A0(p,B); rhs0 = mp.pi*(p['b1']-p['b2'])/2
    lhs1 = -CF.A1(pm,Bm) - CF.A1(p,B); b1_, b2_ = p['b1'], p['b2']
    rhs1 = mp.pi*(mpf(3)/8*(b1_**2+b2_**2) - b1_*b2_/4 - mpf(1)/2)
    res['diffid0'] = (abs(lhs0-rhs0)/max(abs(rhs0), vals['A0'][1]), None)
    res['diffid1'] = (abs(lhs1-rhs1)/max(abs(rhs1), vals['A0'][1]), None)
    # Legendre forms (only where the K,E,Pi route is numerically meaningful at dps 40)
    if e > mpf('1e-6') and p['om1'] > mpf('1e-6') and p['om2'] > mpf('1e-6'):
        L = CF.legendre(p); BL = CF.basis_from_legendre(p, L)
        res['legendre'] = (max(abs(CF.A0(p,BL)-vals['A0'][1])/abs(vals['A0'][1]),
                               abs(CF.A1(p,BL)-vals['A1'][1])/abs(vals['A0'][1]),
                               abs(CF.G(p,BL)-vals['G'][1])/abs(vals['G'][1])), None)
    # double precision conditioning: closed forms evaluated at 53 bits with double inputs
    d_in = (float(b1), float(e), float(f))
    mp.mp.prec = 53
    pd = CF.params(*d_in); Bd = CF.basis(pd)
    dv = {'A0': CF.A0(pd,Bd), 'A1': CF.A1(pd,Bd), 'G': CF.G(pd,Bd), 'A0_single': CF.A0_single(pd,Bd), 'A1_single': CF.A1_single(pd,Bd),
          'dA0db1': CF.dA0db1(pd,Bd), 'dA0db2': CF.dA0db2(pd,Bd),
          'dA1db1': CF.dA1db1(pd,Bd), 'dA1db2': CF.dA1db2(pd,Bd)}
    mp.mp.dps = DPS
    ph = CF.params(*[mpf(v) for v in d_in]); Bh = CF.basis(ph)
    hv = {'A0': CF.A0(ph,Bh), 'A1': CF.A1(ph,Bh), 'G': CF.G(ph,Bh), 'A0_single': CF.A0(ph,Bh), 'A1_single': CF.A1(ph,Bh),
          'dA0db1': CF.dA0db1(ph,Bh), 'dA0db2': CF.dA0db2(ph,Bh),
          'dA1db1': CF.dA1db1(ph,Bh), 'dA1db2': CF.dA1db2(ph,Bh)}
    for k in dv:
        scale = abs(hv[k]) if k not in ('A1','A1_single','dA1db1','dA1db2') else max(abs(hv[k]), abs(hv['A0']) if k in ('A1','A1_single') else abs(hv['dA0db1'])+abs(hv['dA0db2']))
        res['dbl_'+k] = (abs(dv[k]-hv[k])/scale / mpf(2)**-53, None)
    if do_deriv:
        res.update(check_derivs(b1, e))
    return (b1, e, f, tag), res

def check_derivs(b1, e):
    """numerical d/db1 (b2 fixed) and d/db2 (b1 fixed) of the quadrature: central differences + one Richardson step"""
    mp.mp.dps = 70
    b1 = mpf(b1); e = mpf(e)
    p0 = CF.params(b1, e)
    h = mpf('1e-15')*min(e, p0['om1'], p0['om2'], mpf(1))
    def Fq(db1, db2):
        pp = CF.params(b1+db1, e+db1+db2)
        return QR.I_A0(pp), QR.I_A1(pp)
    def D(which, hh):
        if which == 1: a = Fq(hh,0); b = Fq(-hh,0)
        else:          a = Fq(0,hh); b = Fq(0,-hh)
        return [(a[i]-b[i])/(2*hh) for i in range(2)]
    out = {}
    mp.mp.dps = 70
    for which in (1,2):
        d1 = D(which, h); d2 = D(which, h/2)
        num = [(4*d2[i]-d1[i])/3 for i in range(2)]
        mp.mp.dps = DPS
        pp = CF.params(b1, e); Bp = CF.basis(pp)
        if which == 1: cf = [CF.dA0db1(pp,Bp), CF.dA1db1(pp,Bp)]
        else:          cf = [CF.dA0db2(pp,Bp), CF.dA1db2(pp,Bp)]
        out['dA0db%d'%which] = (abs(cf[0]-num[0])/abs(num[0]), num[0])
        out['dA1db%d'%which] = (abs(cf[1]-num[1])/abs(num[1]), num[1])
        out['dA1db%d/scale'%which] = (abs(cf[1]-num[1])/max(abs(num[1]), abs(num[0])), None)
        mp.mp.dps = 70
    mp.mp.dps = DPS
    return out

def H_check(rng, n=20):
    """H(x;b1,b2) = int_{-1}^{-b2} w/(R (t-x)) dt, b1<x<1, by direct naive t-quadrature,
    vs. the mapping H = -G(-x; b2, b1)."""
    mp.mp.dps = DPS
    worst = mpf(0)
    for i in range(n):
        while True:
            b1 = 2*rng.random()-1; b2 = 2*rng.random()-1
            if b1+b2 > 0.05: break
        b1 = mpf(b1); b2 = mpf(b2); x = b1 + (1-b1)*mpf(rng.random())
        # plain mpmath tanh-sinh loses ~18 digits at 1/sqrt endpoint singularities (node abscissae
        # are not accurate near the ends), so use tau = -b2 - t = (1-b2) sin^2(th), th in (0, pi/2):
        # (t-b1)(t+b2) = (b1+b2+tau) tau, 1+t = (1-b2) cos^2 th, 1-t = 1+b2+tau
        e = b1 + b2
        def hint(th):
            tau = (1-b2)*mp.sin(th)**2; t = -b2 - tau
            return 2*(1-b2)*mp.cos(th)**2*mp.sqrt((1+b2+tau)/(e+tau))/(t-x)
        ref = mp.quad(hint, [0, mp.pi/4, mp.pi/2])
        # mirrored parameters: b1' = b2, b2' = b1, x' = -x  -> f' = (1+x')/(1-b2') = (1-x)/(1-b1)
        pm = CF.params(b2, b1+b2, (1-x)/(1-b1)); Bm = CF.basis(pm)
        val = -CF.G(pm, Bm)
        worst = max(worst, abs(val-ref)/abs(ref))
    return worst

def naive_check(rng, n=20):
    """independent check of the u-substitution quadrature: plain tanh-sinh in t on (b1,1)."""
    mp.mp.dps = DPS
    worst = mpf(0)
    for i in range(n):
        while True:
            b1 = 2*rng.random()-1; b2 = 2*rng.random()-1
            if b1+b2 > 0.05: break
        b1 = mpf(b1); e = b1 + mpf(b2); f = mpf(rng.random())
        p = CF.params(b1, e, f); x = p['x']
        # independent substitution t = b1 + (1-b1) sin^2(th): w/R dt = 2(1-b1)cos^2(th) sqrt((1+t)/(t+b2)) dth
        om1 = 1 - b1
        def g(th):
            sn2 = mp.sin(th)**2
            return 2*om1*(1-sn2)*mp.sqrt((1+b1+om1*sn2)/(e+om1*sn2))
        iv = [0, mp.pi/4, mp.pi/2]
        tt = lambda th: b1 + om1*mp.sin(th)**2
        for k, ref in (('A0', mp.quad(g, iv)),
                       ('A1', mp.quad(lambda th: tt(th)*g(th), iv)),
                       ('G',  mp.quad(lambda th: g(th)/(tt(th)-x), iv))):
            other = {'A0':QR.I_A0, 'A1':QR.I_A1, 'G':QR.I_G}[k](p)
            worst = max(worst, abs(other-ref)/abs(ref))
    return worst

if __name__ == '__main__':
    quick = '--quick' in sys.argv
    rng = random.Random(12345)
    mp.mp.dps = DPS
    pts = sample_points(rng)
    if quick: pts = pts[::10]
    # derivatives on every point
    jobs = [(b1,e,f,tag, True) for i,(b1,e,f,tag) in enumerate(pts)]
    t0 = time.time()
    with Pool(2) as pool:
        results = pool.map(check_point, jobs, chunksize=1)
    worst = {}; where = {}; count = {}
    for key, res in results:
        for k,(err,_) in res.items():
            count[k] = count.get(k,0)+1
            if k not in worst or err > worst[k]:
                worst[k] = err; where[k] = key
    lines = []
    lines.append('verify.py: %d parameter points, mp.dps=%d, elapsed %.1fs' % (len(pts), DPS, time.time()-t0))
    lines.append('%-14s %6s %12s   worst point (b1, b1+b2, f, tag)' % ('quantity','#pts','max error'))
    order = ['A0','A1','A1/A0','A0_single','A1_single/A0','G','dA0db1','dA0db2','dA1db1','dA1db2','dA1db1/scale','dA1db2/scale',
             'diffid0','diffid1','legendre']
    for k in order + sorted(k for k in worst if k not in order):
        if k in worst:
            b1,e,f,tag = where[k]
            unit = ' (units of 2^-53)' if k.startswith('dbl_') else ''
            lines.append('%-14s %6d %12s   (%s, %s, %s, %s)%s' % (k, count[k], mp.nstr(worst[k],3),
                         mp.nstr(b1,17), mp.nstr(e,5), mp.nstr(f,5), tag, unit))
    lines.append('H mapping  (H = -G(-x;b2,b1)) vs direct quadrature, 20 pts: max rel err %s' % mp.nstr(H_check(rng),3))
    lines.append('u-subst. quadrature vs theta-subst. quadrature, 20 pts:     max rel err %s' % mp.nstr(naive_check(rng),3))
    out = '\n'.join(lines)
    print(out)
    if not quick:
        open('verify_results.txt','w').write(out+'\n')
