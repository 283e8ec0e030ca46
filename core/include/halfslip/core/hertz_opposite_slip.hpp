// halfslip core: slip and zone energy of the Hertz opposite-sign regime by
// fixed Gauss-Legendre rules in a variable that makes the integrand analytic
// in a strip of known width (issue 16).
//
// In a slip zone at distance u from the stick edge (stick width e, canonical
// units) the density is b(u) = -2 R(u) (1 + 2 G(u)/pi), R = sqrt(u (u + e)),
// with G the elliptic integral of the other zone (opposite_G_state). With
//   u = e sinh^2(tau/2):   R = du/dtau = (e/2) sinh(tau),  u + e = e cosh^2(tau/2)
// the slip is h(dl) = int_0^T R(u)^2 g(u) dtau, g = -2 (1 + 2G/pi),
// T = 2 asinh(sqrt(dl/e)). The square-root end at u = 0 is gone (R^2 is
// entire in tau), and G(u), whose only singularities lie at u <= -e (the
// characteristic p_x <= 0; the log branch point at u = -e that makes b
// vary on the scale of e when the stick zone is tiny), is analytic in the
// strip |Im tau| < pi: u = -e is tau = i pi. A Gauss-Legendre rule of n nodes
// on a panel of length L inside that strip converges like rho^(-2n),
// rho = a + sqrt(1 + a^2), a = 2 pi / L; for L <= 2 (rho >= 6.4) 12 nodes
// leave < 1e-17 relative (the integrand grows like e^(2 tau), which costs at
// most a factor e^4.2 on the ellipse beyond the panel's right end). A stick
// zone far narrower than the slip zone only makes T long (T ~ ln(4 dl/e)),
// and the integrand's growth e^(2 tau) makes [0, T - 24] worth < 1e-20 of the
// total: at most 12 panels of length <= 2 and one for the rest.
// The zone energy int_0^L Pi(L - u) b(u) du (Pi = pressure_tail) has the
// pressure's c^(3/2) at the contact edge u = L: on the last panel
// tau = T - L_p s^2 makes it s^4 times a function analytic near [0, 1].
// tests/test_hertz.cpp checks both against the tanh-sinh path in long double
// and tests/test_reference.cpp against the MPFR reference backend.
// The slip at a point can also read the integrand from a per-zone Chebyshev
// table in tau (tabulate_g, issue 16 round two: no elliptic integral per node),
// which hertz_solution builds on a zone's first slip and keeps.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>

#include "gauss.hpp"
#include "hertz_opposite.hpp"

namespace hs { namespace core {

// pressure_tail (numerics.hpp) of the Hertz pressure with sin(2 theta) =
// 2 (1 - c) sqrt(c (2 - c)) (theta = acos(1 - c)) in place of a sine where
// y - sin y does not cancel (y = 2 theta > 1)
// (2 theta > 1.01 for c > 1/8); below c = 1/8 the series
//   int_0^c sqrt(t (2 - t)) dt = sqrt(2) c^(3/2) sum_k binom(1/2, k) (-c/2)^k / (k + 3/2)
// (ratio <= 1/16: 18 terms reach 1e-21).
template <class T> T hertz_pressure_tail(const T &c) {
  using std::asin;
  using std::sqrt;
  if (!(c > 0)) return T(0);
  if (c > T(0.125)) {
    const T y = 4 * asin(sqrt(c / 2));  // 2 theta
    return (y - 2 * (1 - c) * sqrt(c * (2 - c))) / 4;
  }
  struct coefficients {
    T a[18];
    coefficients() {
      T bk = 1;  // binom(1/2, k) (-1/2)^k
      for (int k = 0; k < 18; ++k) {
        a[k] = bk / (T(k) + T(1.5));
        bk *= (T(0.5) - T(k)) / T(k + 1) * T(-0.5);
      }
    }
  };
  static const coefficients co;
  T sum = co.a[17];
  for (int k = 16; k >= 0; --k) sum = sum * c + co.a[k];
  return boost::math::constants::root_two<T>() * c * sqrt(c) * sum;
}

// The integrals of one slip zone. st is the state as opposite_G_state takes
// it: the other zone first (st.d1 is the length of the zone whose traction
// drives G, st.d2 the length of this zone).
template <class T> class opposite_zone_integrals {
 public:
  // tabulate: also build the per-solution table of 1 + 2G/pi over the zone
  // (tabulate_g) that slip reads at a point; the plain object (false) is what
  // one evaluation needs.
  explicit opposite_zone_integrals(const opposite_state<T> &st, bool tabulate = false) : st_(st) {
    using std::log;
    using std::sqrt;
    le_ = log_width(st);
    op2_ = st.d1 + st.e;
    op1_ = st.d2 + st.e;
    Q_ = op1_ * op2_;
    const T sQ = sqrt(Q_);
    ks_ = cel_switch<T>();
    if (st.e >= boost::math::tools::min_value<T>()) {
      kc_ = sqrt(2 * st.e / Q_);
      // ln kc is read only below the switch (cel_log, and the continuation)
      lkc_ = kc_ > ks_ ? std::numeric_limits<T>::quiet_NaN() : T(log(kc_));
    } else {
      lkc_ = (log(T(2)) + le_ - log(Q_)) / 2;
      using std::exp;
      kc_ = exp(lkc_);
    }
    rj_scale_ = 3 / (Q_ * sQ);
    static const T lks = log(cel_switch<T>());
    lks_ = lks;
    agm_init(kc_ > ks_ ? kc_ : ks_);
    two_op1_ = 2 / op1_;
    coef_ = 4 * st.d1 * op2_ / 3;
    g2_ = 2 * coef_ / pi<T>();
    if (tabulate) tabulate_g();
  }

  // the state this object was built for (a cache checks it before use)
  bool same_state(const opposite_state<T> &st) const {
    return st.d1 == st_.d1 && st.d2 == st_.d2 && st.e == st_.e && st.le == st_.le;
  }
  // whether slip reads 1 + 2G/pi from the table (tabulate_g)
  bool tabulated() const { return tab_n_ > 0; }

  // slip int_0^dl b(u) du (dl >= 0)
  T slip(const T &dl) const {
    using std::exp;
    using std::expm1;
    if (!(dl > 0)) return T(0);
    const T tmax = tau_of(dl);
    if (tab_n_ > 0 && tmax <= tab_end_) return slip_tabulated(tmax);
    const T em1T = expm1(-tmax);
    const T eT = exp(-tmax);  // not 1 + em1T: that cancels for large T
    const T dlb = dl / (em1T * em1T);
    return integrate(tmax, [&](const T &sig, const T &esig, T &u, T &v) {
      uv(dlb, tmax, eT, sig, esig, u, v);
      return T(1);
    });
  }

  // int_0^L Pi(L - u) b(u) du, L the length of this zone
  T energy(const T &L) const {
    using std::exp;
    using std::expm1;
    if (!(L > 0)) return T(0);
    const T tmax = tau_of(L);
    const T em1T = expm1(-tmax), em2T = expm1(-2 * tmax);
    const T eT = exp(-tmax), e2T = exp(-2 * tmax);
    const T dlb = L / (em1T * em1T);
    return integrate(
        tmax,
        [&](const T &sig, const T &esig, T &u, T &v) {
          // c = L - u = L expm1(-sig) expm1(sig - 2T) / expm1(-T)^2 and
          // em = expm1(-tau), tau = T - sig: below sig = 1 all from
          // E1 = expm1(-sig) (the differences (expm1(-T) - E1)/(1 + E1) lose
          // digits only where tau -> 0, whose nodes carry ~tau^2 of the
          // integral); beyond it from e^-sig (then 2T - sig >= T >= 1)
          T E1, es, em, b;
          if (sig < 1) {
            E1 = expm1(-sig);
            es = 1 + E1;
            em = (em1T - E1) / es;
            b = (em2T - E1) / es;
          } else {
            es = esig;
            E1 = es - 1;
            em = eT / es - 1;
            b = e2T / es - 1;
          }
          const T base = dlb * es;
          u = base * em * em;
          v = base * (2 + em) * (2 + em);
          return hertz_pressure_tail(dlb * E1 * b);
        },
        true);
  }

  // b(u) (as opposite_G_state and hertz_solution::bhat), u > 0
  T bhat(const T &u) const {
    using std::sqrt;
    const T v = u + st_.e;
    return -2 * sqrt(u * v) * gfac(u, v);
  }

 private:
  opposite_state<T> st_;
  T le_, op1_, op2_, Q_, kc_, lkc_, rj_scale_, coef_, two_op1_, g2_, ks_, lks_;
  // the AGM of the modulus in cel's loop (elliptic.hpp), which does not depend
  // on p: every cel(kc, p, 0, 1) of the zone runs only its p-stream on it
  static constexpr int agm_max = 40;
  T agm_e_[agm_max];
  T agm_em_ = 1;
  int agm_n_ = 0;  // 0: not available (the generic cel_log is used)

  // The table (issue 16, slip at a point). With u = e sinh^2(tau/2),
  // R = (e/2) sinh(tau), the slip is
  //   h(dl) = int_0^T -2 R^2 (1 + 2G/pi) dtau = -(e^2/2) int_0^T tau^2 f(tau) dtau,
  //   f = (sinh(tau)/tau)^2 (1 + 2G/pi),  T = tau(dl).
  // f is analytic in |Im tau| < pi (the second factor, above; the first is
  // entire), so on [0, tab_end_] (tab_end_ just beyond tau(L), L this zone's
  // length) its Chebyshev interpolant at the points of the first kind
  // converges like rho^(-N), rho = pi/hw + sqrt(1 + (pi/hw)^2), hw the half
  // length: hw <= 1/2 (rho >= 12.6) with N = 16 and hw <= 1 (rho >= 6.4) with
  // N = 24 leave < 1e-17 of f's size on the Bernstein ellipse (sinh^2 adds at
  // most a factor ~5 there). Built once per zone of a solution (N gfac
  // evaluations side by side; hertz_solution keeps it), for double, and only
  // where tau(L) <= 2, a stick zone not much narrower than the slip zone
  // (longer ranges would need more terms than a solve's worth of set-up; they
  // keep the direct evaluation). The series is stored in powers
  // of x = 2 tau/tab_end_ - 1 (tab_a_), evaluated by Estrin's scheme (short
  // dependency chains): with rho >= 6.4 > 1 + sqrt(2) the monomial
  // coefficients stay of the order of the Chebyshev ones (the largest
  // coefficient of T_k grows like (1 + sqrt 2)^k), so |x| <= 1 costs no digits.
  static constexpr int tab_max = 24;
  int tab_n_ = 0;  // 0: no table
  T tab_end_ = 0, tab_scale_ = 0;  // tab_scale_ = 2/tab_end_
  T tab_a_[tab_max];
  T e2h_ = 0;  // e^2/2

  template <int N> struct cheb_cos {
    // cos(pi k (j + 1/2)/N) and the nodes cos(pi (j + 1/2)/N)
    T c[N][N];
    T x[N];
    // the coefficients of T_k in powers of x (integers, exact)
    T t[N][N];
    cheb_cos() {
      // cos(pi m/(2N)) with m = k (2j + 1) reduced mod 4N first: an angle
      // rounded at k (j + 1/2) pi/N would be off by up to ~N^2 eps
      using std::cos;
      for (int j = 0; j < N; ++j) {
        x[j] = cos(pi<T>() * T(2 * j + 1) / T(2 * N));
        for (int k = 0; k < N; ++k) c[k][j] = cos(pi<T>() * T((k * (2 * j + 1)) % (4 * N)) / T(2 * N));
      }
      for (int k = 0; k < N; ++k)
        for (int j = 0; j < N; ++j) t[k][j] = 0;
      t[0][0] = 1;
      if (N > 1) t[1][1] = 1;
      for (int k = 2; k < N; ++k)
        for (int j = 0; j < N; ++j) t[k][j] = (j > 0 ? 2 * t[k - 1][j - 1] : T(0)) - t[k - 2][j];
    }
  };
  template <int N> void tabulate_n(const T &end) {
    using std::expm1;
    // (immutable after its thread-safe initialisation)
    static const cheb_cos<N> cc;
    T u[N], v[N], g[N];
    for (int j = 0; j < N; ++j) {
      const T tau = end * (1 + cc.x[j]) / 2;
      // sinh(tau/2) from expm1 (no cancellation near tau = 0)
      const T E = expm1(tau / 2);
      const T sh = (E + E / (E + 1)) / 2;
      u[j] = st_.e * sh * sh;
      v[j] = u[j] + st_.e;
    }
    for (int j = 0; j < N; j += 16) gfac_batch(std::min(16, N - j), u + j, v + j, g + j);
    for (int j = 0; j < N; ++j) {
      // (sinh(tau)/tau)^2 = 4 u v/(e tau)^2
      const T tau = end * (1 + cc.x[j]) / 2;
      const T et = st_.e * tau;
      g[j] *= 4 * u[j] * v[j] / (et * et);
    }
    // the transform of f - f0 (its rounding relative to the variation of f),
    // f0 added back to c_0
    const T f0 = g[N / 2];
    T c[N];
    for (int k = 0; k < N; ++k) {
      T a = 0;
      for (int j = 0; j < N; ++j) a += cc.c[k][j] * (g[j] - f0);
      c[k] = (k == 0 ? T(1) : T(2)) * a / N;
    }
    c[0] += f0;
    for (int j = 0; j < N; ++j) {
      T a = 0;
      for (int k = N - 1; k >= j; --k) a += c[k] * cc.t[k][j];
      tab_a_[j] = a;
    }
    tab_n_ = N;
  }
  void tabulate_g() {
    // double only: the table's 1e-17 is not long double's precision (wider
    // types keep the direct evaluation)
    if constexpr (std::numeric_limits<T>::digits > 53) return;
    // (e^2/2 below is far from underflow)
    if (!(st_.e >= T(1e-100)) || !(agm_n_ > 0)) return;
    const T TL = tau_of(st_.d2);
    if (!(TL > 0) || !(TL <= 2)) return;
    const T end = TL * (1 + 64 * boost::math::tools::epsilon<T>());
    if (end <= 1) tabulate_n<16>(end);
    else tabulate_n<24>(end);
    tab_end_ = end;
    tab_scale_ = 2 / end;
    e2h_ = st_.e * st_.e / 2;
  }
  // The slip at tau(dl) = tmax <= tab_end_ (<= 2) from the table:
  // -(e^2/2) int_0^tmax tau^2 f(tau) dtau by the Gauss-Legendre rule
  // integrate gives [0, tmax] (the same integrand up to the factor e^2/2,
  // analytic in the same strip), with no transcendental call per node: nodes
  // tau_k = (tmax/2)(1 -+ x_k) (1 - x_k exact), f by the table.
  T slip_tabulated(const T &tmax) const {
    if (tmax <= T(0.25)) return tab_n_ == 16 ? slip_tabulated_n<6, 16>(tmax) : slip_tabulated_n<6, 24>(tmax);
    if (tmax <= T(0.75)) return tab_n_ == 16 ? slip_tabulated_n<8, 16>(tmax) : slip_tabulated_n<8, 24>(tmax);
    if (tmax <= T(1.25)) return tab_n_ == 16 ? slip_tabulated_n<10, 16>(tmax) : slip_tabulated_n<10, 24>(tmax);
    return tab_n_ == 16 ? slip_tabulated_n<12, 16>(tmax) : slip_tabulated_n<12, 24>(tmax);
  }
  // (n nodes and N terms fixed: the nodes' arrays stay in registers)
  template <int n, int N> T slip_tabulated_n(const T &tmax) const {
    const auto &r = rule(n);
    const T h = tmax / 2;
    T tau[n], w[n], x[n], p[n], q[N / 2][n];
    for (int i = 0; i < n / 2; ++i) {
      const T xi = r.x[n - 1 - i];  // > 0
      tau[2 * i] = h * (1 - xi);
      tau[2 * i + 1] = h * (1 + xi);
      w[2 * i] = w[2 * i + 1] = r.w[i];
    }
    for (int k = 0; k < n; ++k) x[k] = tau[k] * tab_scale_ - 1;
    // Estrin: pairs, then pairs of pairs with x^2, x^4, ...
    for (int j = 0; j < N / 2; ++j)
      for (int k = 0; k < n; ++k) q[j][k] = tab_a_[2 * j] + tab_a_[2 * j + 1] * x[k];
    for (int k = 0; k < n; ++k) p[k] = x[k] * x[k];
    for (int m = N / 2; m > 1; m = (m + 1) / 2) {
      for (int j = 0; j < m / 2; ++j)
        for (int k = 0; k < n; ++k) q[j][k] = q[2 * j][k] + q[2 * j + 1][k] * p[k];
      if (m % 2)
        for (int k = 0; k < n; ++k) q[m / 2][k] = q[m - 1][k];
      for (int k = 0; k < n; ++k) p[k] *= p[k];
    }
    T sum = 0;
    for (int k = 0; k < n; ++k) sum += w[k] * (tau[k] * tau[k]) * q[0][k];
    return -e2h_ * h * sum;
  }
  void agm_init(T kc) {
    using std::abs;
    using std::sqrt;
    const T ca = sqrt(boost::math::tools::epsilon<T>());
    T e = kc, em = T(1);
    for (int i = 0; i < agm_max; ++i) {
      agm_e_[i] = e;
      const T g = em;
      em += kc;
      if (abs(g - kc) <= g * ca) {
        agm_n_ = i + 1;
        agm_em_ = em;
        return;
      }
      kc = sqrt(e);
      kc += kc;
      e = kc * em;
    }
    agm_n_ = 0;
  }
  // cel(kc_seq, p, 0, 1) by the p-stream of cel's loop on the stored AGM (one
  // division per step: the reciprocal of p serves both quotients)
  T cel_stream(const T &px) const {
    using std::sqrt;
    T p = sqrt(px);
    T ip = 1 / p;
    T a = 0, b = ip;
    for (int i = 0; i < agm_n_; ++i) {
      const T f = a;
      a += b * ip;
      const T g = agm_e_[i] * ip;
      b += f * g;
      b += b;
      p += g;
      ip = 1 / p;
    }
    return boost::math::constants::half_pi<T>() * (b + a * agm_em_) * ip / (agm_em_ * (agm_em_ * ip + 1));
  }
  // cel(kc, p, 0, 1) through cel_log's switch (ks min(1, sqrt p))
  T cel_fast(const T &p) const {
    using std::sqrt;
    if (agm_n_ > 0) {
      if (p >= 1) {
        const T r = cel_stream(p);
        // below the switch the stream ran on ks: cel_log's continuation
        return kc_ > ks_ ? r : T(r + (lks_ - lkc_) / p);
      }
      if (kc_ > ks_ && kc_ > ks_ * sqrt(p)) return cel_stream(p);
    }
    return cel_log(kc_, lkc_, p, T(0), T(1));
  }

  // tau at distance dl: sinh^2(tau/2) = dl/e
  T tau_of(const T &dl) const {
    using std::asinh;
    using std::log;
    using std::sqrt;
    if (st_.e >= boost::math::tools::min_value<T>() && dl / st_.e < T(1e150)) return 2 * asinh(sqrt(dl / st_.e));
    // 2 asinh(z) = 2 ln(2z) + O(1/z^2), z^2 = dl/e > 1e150
    return log(4 * dl) - le_;
  }
  // 1 + 2 G(u)/pi at u with v = u + e (both to full relative accuracy):
  // b(u) = -2 sqrt(u v) gfac(u, v)
  T gfac(const T &u, const T &v) const {
    T g;
    gfac_batch(1, &u, &v, &g);
    return g;
  }
  // gfac at n <= 16 points at once: the p-streams of their cel run side by
  // side (independent chains of divisions, which the processor overlaps)
  // (The constant R_J(0,P,Q,2(1+beta2)) of G, cel(kc, 2/op1, 0, 1), rides
  // along as one more stream.)
  void gfac_batch(int n, const T *u, const T *v, T *g) const {
    T px[17], r[16], c[17];
    for (int k = 0; k < n; ++k) {
      const T iomx = 1 / (st_.d1 + v[k]);  // 1/(1 - x)
      px[k] = two_op1_ * v[k] * iomx;
      r[k] = (st_.d2 - u[k]) * iomx;  // (1 + x)/(1 - x)
    }
    px[n] = two_op1_;
    cel_batch(n + 1, px, c);
    const T RJc = rj_scale_ * c[n];
    for (int k = 0; k < n; ++k) g[k] = 1 + g2_ * (RJc + r[k] * rj_scale_ * c[k]);
  }
  // cel(kc, p_k, 0, 1) for n <= 17 values p_k with cel_log's switch
  // (ks min(1, sqrt p)): by the p-streams on the stored AGM (on kc, or on ks
  // with cel_log's continuation below it) where that applies, side by side.
  void cel_batch(int n, const T *px, T *c) const {
    using std::sqrt;
    T p[17], ip[17], a[17], b[17];
    if (agm_n_ > 0) {
      for (int k = 0; k < n; ++k) {
        p[k] = sqrt(px[k]);
        ip[k] = 1 / p[k];
        a[k] = 0;
        b[k] = ip[k];
      }
      for (int i = 0; i < agm_n_; ++i) {
        const T E = agm_e_[i];
        for (int k = 0; k < n; ++k) {
          const T f = a[k];
          a[k] += b[k] * ip[k];
          const T gg = E * ip[k];
          b[k] += f * gg;
          b[k] += b[k];
          p[k] += gg;
          ip[k] = 1 / p[k];
        }
      }
    }
    const T em = agm_em_, hp = boost::math::constants::half_pi<T>();
    for (int k = 0; k < n; ++k) {
      if (agm_n_ > 0 && (px[k] >= 1 || (kc_ > ks_ && kc_ > ks_ * sqrt(px[k])))) {
        c[k] = hp * (b[k] + a[k] * em) * ip[k] / (em * (em * ip[k] + 1));
        if (!(kc_ > ks_)) c[k] += (lks_ - lkc_) / px[k];
      } else {
        c[k] = cel_log(kc_, lkc_, px[k], T(0), T(1));
      }
    }
  }
  // u and v = u + e at tau = T - sig, T = tau(dl), relative to dl
  // (sinh^2(T/2) = dl/e), so that neither the rounding of T (absolute eps T
  // when the stick zone is tiny) nor an underflowing e enters them:
  //   u = dl e^(-sig) (expm1(-tau)/expm1(-T))^2, v = dl e^(-sig) ((2 + expm1(-tau))/expm1(-T))^2
  // dlb = dl/expm1(-T)^2, eT = e^-T, esig = e^-sig. expm1(-tau) by expm1
  // below tau = 1, beyond it as e^-T/e^-sig - 1 (within ~1.2 ulp there).
  // The integrand R^2 g = R b there is -2 u v gfac(u, v).
  // Below tau = 1 e^-sig = e^-T / (1 + expm1(-tau)) (esig is not read there).
  void uv(const T &dlb, const T &tmax, const T &eT, const T &sig, const T &esig, T &u, T &v) const {
    using std::expm1;
    const T tau = tmax - sig;
    T em, base;
    if (tau < 1) {
      em = expm1(-tau);
      base = dlb * (eT / (1 + em));
    } else {
      em = eT / esig - 1;
      base = dlb * esig;
    }
    u = base * em * em;
    v = base * (2 + em) * (2 + em);
  }
  // int_0^tmax f(sig, e^-sig) dsig (sig = T - tau: the distance from the point in
  // tau) on fixed panels from sig = 0. The integrand decays like e^(-sig)
  // away from the point (u = dl e^(-sig) for large T), so the panels may
  // lengthen as the part they carry shrinks; each keeps rho^(-2n) e^(-sig_a)
  // below 1e-17 for the strip |Im| < pi. What lies beyond sig = 40 carries
  // less than e^(-40) = 4e-18 of the total: one panel up to 80, and beyond
  // 80 nothing (measured: F(40)/F(0) = 4e-18 at sigma/(f p0) = 12, Q/fP = 1 - 1e-6). last_edge: the first
  // panel carries the contact edge (edge_panel).
  template <class Fn> T integrate(const T &tmax, const Fn &f, bool last_edge = false) const {
    struct piece {
      double end;
      int n;
    };
    static constexpr piece pieces[] = {{2, 12}, {4, 12}, {6, 12}, {10, 16}, {16, 16}, {24, 16}, {32, 16}, {40, 16}};
    T sum = 0, a = 0;
    for (const piece &p : pieces) {
      const T b = tmax < T(p.end) ? tmax : T(p.end);
      if (last_edge && a == 0) sum += edge_panel(a, b, f);
      else
        sum += panel(a, b, b - a <= T(0.25) ? 6 : b - a <= T(0.75) ? 8 : b - a <= T(1.25) ? 10 : p.n, f,
                     last_edge || tmax - a >= 1);
      a = b;
      if (!(a < tmax)) return sum;
    }
    // [40, 80] once, roughly (its share is < e^(-40)); beyond 80 (< e^(-80))
    // nothing, where u, v would underflow
    return sum + panel(a, tmax < T(80) ? tmax : T(80), 12, f);
  }
  // The sum of w_k f(sig_k) (-2 u v gfac) over nodes sig_k: f gives the
  // factor and u, v at a node; far below the point (sig beyond ~700) u and v
  // underflow, and what is left there is below e^(-40) of the total (see
  // integrate): such nodes count zero.
  template <class Fn> T node_sum(int n, const T *sig, const T *esig, const T *w, const Fn &f) const {
    // (u, v zeroed only to spare GCC's -Wmaybe-uninitialized: f sets them)
    T u[16] = {}, v[16] = {}, m[16], g[16];
    for (int k = 0; k < n; ++k) {
      m[k] = f(sig[k], esig[k], u[k], v[k]);
      if (!(v[k] > 0)) {
        m[k] = 0;
        u[k] = v[k] = 1;
      }
    }
    gfac_batch(n, u, v, g);
    T s = 0;
    for (int k = 0; k < n; ++k)
      if (m[k] != 0) s += w[k] * m[k] * (-2 * (u[k] * v[k]) * g[k]);
    return s;
  }
  // Gauss-Legendre on [a, b]: the nodes come in pairs m -+ h x, whose
  // exponentials are e^-m times e^(+-h x), one exp per pair
  // need_esig = false: the integrand does not read e^-sig on this panel
  template <class Fn> T panel(const T &a, const T &b, int n, const Fn &f, bool need_esig = true) const {
    using std::exp;
    const auto &r = rule(n);
    const T h = (b - a) / 2, m = (a + b) / 2;
    const T em = exp(-m);
    T sig[16], esig[16], w[16];
    for (int i = 0; i < n / 2; ++i) {
      const T hx = h * r.x[n - 1 - i];  // > 0
      const T ex = need_esig ? T(exp(hx)) : T(1);
      sig[2 * i] = m - hx;
      esig[2 * i] = em * ex;
      sig[2 * i + 1] = m + hx;
      esig[2 * i + 1] = em / ex;
      w[2 * i] = w[2 * i + 1] = r.w[i];
    }
    return node_sum(n, sig, esig, w, f) * h;
  }
  // int_0^b f(sig) dsig with the contact edge at sig = 0, where c = L - u
  // = L (1 - e^-sig)(1 - e^(sig - 2T))/(1 - e^-T)^2 vanishes and Pi(c) ~ c^(3/2):
  // sig = b (1 - cos phi), phi in [0, pi/2], makes sig^(3/2) ~ sin^3 phi; when
  // b = T it also makes the mirror branch point sig = 2T (c = 0 again) regular
  // (sig (2T - sig) = T^2 sin^2 phi), which the map sig = b s^2 would put
  // at s = sqrt(2), 0.41 beyond the rule's end (measured: 4e-14 with 12 nodes).
  template <class Fn> T edge_panel(const T &a, const T &b, const Fn &f) const {
    using std::cos;
    using std::exp;
    using std::sin;
    const T L = b - a;
    const T h = pi<T>() / 4;
    // the rule in phi: 2 sin^2(phi/2) and w sin(phi) at its nodes
    struct edge_rule {
      T s2[16], w[16];
      edge_rule() {
        const auto &r = rule(16);
        const T hh = pi<T>() / 4;
        for (int i = 0; i < 16; ++i) {
          const T phi = hh * (1 + r.x[i]);
          const T sh = sin(phi / 2);
          s2[i] = 2 * sh * sh;
          w[i] = r.w[i] * sin(phi);
        }
      }
    };
    static const edge_rule er;
    T sig[16], esig[16];
    for (int i = 0; i < 16; ++i) {
      sig[i] = a + L * er.s2[i];
      esig[i] = sig[i] < 1 ? T(0) : T(exp(-sig[i]));  // read only beyond sig = 1
    }
    return node_sum(16, sig, esig, er.w, f) * L * h;
  }
  static const gl_rule<T> &rule(int n) {
    // immutable after their thread-safe initialisation (the rule cache's shared rules)
    static const auto r6 = gauss_legendre<T>(6), r8 = gauss_legendre<T>(8), r10 = gauss_legendre<T>(10),
                      r12 = gauss_legendre<T>(12), r16 = gauss_legendre<T>(16);
    switch (n) {
      case 6: return *r6;
      case 8: return *r8;
      case 10: return *r10;
      case 12: return *r12;
      default: return *r16;
    }
  }
};

}}  // namespace hs::core
