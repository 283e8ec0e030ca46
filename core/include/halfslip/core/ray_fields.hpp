// The contact state (tractions, stresses) of a load-history state made by
// superposition of monotonic solutions (core/ray_history.hpp, issue 14):
// q = sum c_k q_k with the one pressure p. The Cauchy integrals of q and the
// surface Hilbert transform are the same sums of the parts' own (closed
// forms, panels or reference quadrature), so no new panels are built.
#pragma once
#include <complex>
#include <memory>
#include <utility>
#include <vector>

#include "fields.hpp"

namespace hs { namespace core {

template <class T> struct superposed_part {
  T coef;
  contact_state<T> state;
};

// parts: non-empty, all of one pressure; sigma: the state's bulk tension
// (body 1 carries sigma + bulk2 far away); the stick zone (stick_lo, stick_hi).
template <class T>
contact_state<T> superposed_state(std::vector<superposed_part<T>> parts, const T &sigma, const T &bulk2,
                                  const T &stick_lo, const T &stick_hi) {
  if (parts.empty()) throw error(status::internal, "superposed state: no parts");
  auto sp = std::make_shared<const std::vector<superposed_part<T>>>(std::move(parts));
  const auto &first = sp->front().state;
  contact_state<T> st;
  st.a = first.a;
  st.bulk2 = bulk2;
  st.bulk1 = sigma + bulk2;
  st.p = first.p;
  st.q = [sp](const T &x) {
    T r = 0;
    for (const auto &pt : *sp) r += pt.coef * pt.state.q(x);
    return r;
  };
  for (const auto &pt : *sp) {
    st.breaks.insert(st.breaks.end(), pt.state.breaks.begin(), pt.state.breaks.end());
    st.kinks.insert(st.kinks.end(), pt.state.kinks.begin(), pt.state.kinks.end());
    // each part's stick ends are kinks of q (memory points of the state)
    for (const T &b : {pt.state.stick_lo, pt.state.stick_hi})
      if (b > -st.a && b < st.a) st.breaks.push_back(b);
  }
  std::sort(st.breaks.begin(), st.breaks.end());
  st.breaks.erase(std::unique(st.breaks.begin(), st.breaks.end()), st.breaks.end());
  std::sort(st.kinks.begin(), st.kinks.end());
  st.kinks.erase(std::unique(st.kinks.begin(), st.kinks.end()), st.kinks.end());
  st.stick_lo = stick_lo;
  st.stick_hi = stick_hi;
  st.q_analytic_on_stick = false;
  // P from the first part (the pressure is shared), Q summed
  st.closed = [sp](const std::complex<T> &zeta, cauchy_pair<T> &P, cauchy_pair<T> &Q) {
    P = {};
    Q = {};
    bool have_p = false;
    for (const auto &pt : *sp) {
      cauchy_pair<T> Pk, Qk;
      pt.state.cauchy(zeta, Pk, Qk);
      if (!have_p) {
        P = Pk;
        have_p = true;
      }
      Q.F0 += pt.coef * Qk.F0;
      Q.F1 += pt.coef * Qk.F1;
    }
    return true;
  };
  // (2/pi) PV int q_k/(x - t) dt of each part from its own surface stress:
  // sigma_xx(x, 0) in body 1 is -p - H_k + bulk1_k
  st.hilbert_q = [sp](const T &x) {
    T r = 0;
    for (const auto &pt : *sp) r += pt.coef * (pt.state.bulk1 - pt.state.p(x) - surface_sxx(pt.state, 1, x));
    return r;
  };
  st.hilbert_fast = true;
  return st;
}

}}  // namespace hs::core
