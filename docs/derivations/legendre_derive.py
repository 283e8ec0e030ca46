# Convert the Carlson closed forms to Legendre K(k),E(k),Pi(n,k) and verify numerically.
import sympy as sp, mpmath as mp
b1,b2,x = sp.symbols('b1 b2 x', real=True)
K,E,Pc,Px = sp.symbols('K E Pi_c Pi_x')
e = b1+b2; P = 2*e; Q=(1+b1)*(1+b2); m = (1-b1)*(1-b2)/Q; kp2 = P/Q
nc = -(1-b1)/(1+b1); nx = (1-b1)*(1+x)/((1+b1)*(1-x))
sQ = sp.sqrt(Q)
RF = K/sQ; RDb = 3*(E-kp2*K)/(m*kp2*Q*sQ); RJc = 3*(Pc-K)/(nc*Q*sQ); RJq = 3*(Px-K)/(nx*Q*sQ)
om1,op2,om2 = 1-b1, 1+b2, 1-b2
F = {
 'A0': 2*om1*( RF + (b1-b2)*op2*RJc/3 - om2*e*RDb/3 ),
 'A1': om1*( (3*b1-b2+2)*RF/2 + op2*(3*b1**2-2*b1*b2+3*b2**2-4)*RJc/6 - om2*(b1-b2)*e*RDb/2 ),
 'G' : 4*om1*op2/3*( RJc + (1+x)/(1-x)*RJq ),
 'dA0db1': -2*RF + 2*om1*( op2*RJc - om2*RDb )/3,
 'dA0db2': -2*om1*( op2*RJc + om2*RDb )/3,
 'dA1db1': (1-3*b1)*RF + om1*( (3*b1-b2)*op2*RJc - (3*b1+b2)*om2*RDb )/3,
 'dA1db2': -om1*RF + om1*( -(b1-3*b2)*op2*RJc + (b1+3*b2)*om2*RDb )/3,
}
out = {}
for n,expr in F.items():
    ex = sp.expand(expr*sQ)
    d = {str(s): sp.factor(sp.simplify(ex.coeff(s))) for s in (K,E,Pc,Px)}
    out[n] = d
    print(n, ' = (1/sqrt(Q)) * [', ' + '.join('(%s)*%s'%(v,k) for k,v in d.items() if v!=0), ']')
# numeric check against quadrature at a few points
import closedforms as CF, quadref as QR
mp.mp.dps = 40
worst = 0
for (vb1,ve,vf) in [(0.3,0.5,0.4),(-0.2,0.7,0.9),(0.8,0.05,0.3),(0.1,1.5,0.7),(0.6,0.9,0.01)]:
    p = CF.params(vb1,ve,vf); L = CF.legendre(p)
    B = CF.basis(p)
    subs = {b1:p['b1'], b2:p['b2'], x:p['x']}
    for n,d in out.items():
        val = sum(sp.lambdify((b1,b2,x), v, 'mpmath')(p['b1'],p['b2'],p['x'])*L[{'K':'K','E':'E','Pi_c':'Pi','Pi_x':'Pix'}[k]]
                  for k,v in d.items() if v!=0)/mp.sqrt(p['Q'])
        cf = getattr(CF,n)(p,B)
        worst = max(worst, abs(val-cf)/abs(cf))
print('Legendre forms vs Carlson forms, max rel diff:', mp.nstr(worst,3))
ref = {'A0':QR.I_A0, 'A1':QR.I_A1, 'G':QR.I_G}
