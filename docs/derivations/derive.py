# Symbolic reduction of int_{b1}^1 f(t) dt / Y to Carlson basis via the Moebius map
#   t = (c*b1 + s)/(c + s),  c = 2(1+b2),   dt/Y = ds/sqrt(s(s+P)(s+Q)),  s in (0,inf)
import sympy as sp
b1,b2,x,s = sp.symbols('b1 b2 x s', real=True)
P = 2*(b1+b2); Q=(1+b1)*(1+b2); c = 2*(1+b2); q = c*(b1-x)/(1-x)
RF,RDa,RDb,RJc,RJq = sp.symbols('RF RDa RDb RJc RJq')  # RDa=RD(0,P,Q), RDb=RD(0,Q,P), RJc=RJ(0,P,Q,c), RJq=RJ(0,P,Q,q)
tS = (c*b1+s)/(c+s)
S = s*(s+P)*(s+Q)

def parts(R, poles):
    """partial fractions of rational R(s) given list of (root r, max order m) meaning factors (s+r)^m.
       returns const, dict{(r,j): coeff of 1/(s+r)^j}"""
    R = sp.together(R)
    res = {}
    for r,m in poles:
        g = sp.cancel(R*(s+r)**m)
        for j in range(m,0,-1):
            k = m-j
            coef = sp.diff(g, s, k).subs(s,-r)/sp.factorial(k)
            res[(r,j)] = sp.simplify(coef)
    const = sp.limit(R, s, sp.oo)
    return sp.simplify(const), res

# I2(c) = int ds/((s+c)^2 sigma) from exact relation d/ds[sigma/((s+P)(s+c))]
rel = sp.Rational(1,2)*((s+Q)*(s+P)+s*(P-Q))/((s+P)*(s+c)) - s*(s+Q)/(s+c)**2
base = {}
def I1(r):
    return {P:sp.Rational(2,3)*RDb, Q:sp.Rational(2,3)*RDa, c:sp.Rational(2,3)*RJc, q:sp.Rational(2,3)*RJq}[r]
k0, pr = parts(rel, [(P,1),(c,2)])
# rel integrates to 0:  k0*2RF + pr[P,1]*I1(P) + pr[c,1]*I1(c) + pr[c,2]*I2c = 0
I2c = sp.simplify(-(k0*2*RF + pr[(P,1)]*I1(P) + pr[(c,1)]*I1(c))/pr[(c,2)])
print("I2c =", sp.factor(I2c))
# I3(c) from d/ds[sigma/(s+c)^2] = 0 integrated
v = sp.symbols('v')
Sv = sp.expand(S.subs(s, v-c))
S0,S1,S2 = [Sv.coeff(v,i) for i in range(3)]
# -2 S0 I3 - 3/2 S1 I2 - S2 I1 - 1/2 I0 = 0
I3c = sp.simplify((-sp.Rational(3,2)*S1*I2c - S2*I1(c) - sp.Rational(1,2)*2*RF)/(2*S0))

def reduce(ft, poles):
    R = sp.cancel(sp.together(ft.subs(sp.Symbol('t'), tS)))
    k0, pr = parts(R, poles)
    out = k0*2*RF
    for (r,j),cf in pr.items():
        if cf == 0: continue
        if j==1: out += cf*I1(r)
        elif j==2 and r==c: out += cf*I2c
        elif j==3 and r==c: out += cf*I3c
        else: raise ValueError((r,j))
    return sp.collect(sp.expand(out), [RF,RDa,RDb,RJc,RJq], evaluate=False)

t = sp.Symbol('t')
targets = {
 'A0': ((1-t**2), [(c,2),(Q,1)]),
 'A1': (t*(1-t**2), [(c,3),(Q,1)]),
 'G' : ((1-t**2)/(t-x), [(c,2),(Q,1),(q,1)]),
 'dA0db2': (-sp.Rational(1,2)*(1-t**2)/(t+b2), [(c,2),(Q,1),(P,1)]),
 'dA1db2': (-sp.Rational(1,2)*t*(1-t**2)/(t+b2), [(c,3),(Q,1),(P,1)]),
 'dA0db1': ((-(1-t**2) - (1-b2)/2*(1-t)**2/(t+b2))/(1-b1), [(c,3),(Q,1),(P,1)]),
 'dA1db1': ((-t*(1-t**2) + (1-t)**2*(1+t) - (1-b2)/2*t*(1-t)**2/(t+b2))/(1-b1), [(c,3),(Q,1),(P,1)]),
}
import pickle
results = {}
for name,(ft,poles) in targets.items():
    d = reduce(ft, poles)
    dd = {str(k): sp.factor(sp.simplify(vv)) for k,vv in d.items()}
    results[name] = dd
    print(name)
    for k,vv in dd.items(): print("   ", k, ":", vv)
pickle.dump({n:{k:sp.srepr(v) for k,v in d.items()} for n,d in results.items()}, open('coeffs.pkl','wb'))
