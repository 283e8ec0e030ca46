// halfslip core: the contact state after a number of steps of a load history,
// for the stresses of fields.hpp (issue 15; docs/fields.md, docs/history.md).
//
// The state is p(x) and the history's q(x) (the traction of its stuck points
// sums the stuck-interval rates of every step since each point entered the
// stick zone: O(steps) per point, evaluated once per state at the panels'
// nodes). Its breakpoints are the current stick ends, the pressure's kinks and
// the history's memory points (history::memory_points): the panels are then
// spectrally accurate on every piece. There is no cheap Hilbert transform of
// q (the slip gradient includes locked-in slip), so the surface stress on the
// contact comes from the panels' principal value as well.
#pragma once
#include <memory>
#include <vector>

#include "fields.hpp"
#include "history.hpp"
#include "static_history.hpp"

namespace hs { namespace core {

// p and q of the state after nsteps steps of h in physical units: x in units of
// length, p = p0 p^(x/a), q = f p0 q^(x/a), 0 outside |x| < a. The one
// definition for the stresses (below) and the C ABI's history-state handle.
template <class T> T history_pressure_at(const history<T> &h, const T &x, const T &a, const T &p0) {
  const T xi = x / a;
  return xi > -1 && xi < 1 ? p0 * h.pressure().p(xi) : T(0);
}
template <class T>
T history_traction_at(const history<T> &h, std::size_t nsteps, const T &x, const T &a, const T &p0, const T &f) {
  const T xi = x / a;
  return xi > -1 && xi < 1 ? f * p0 * h.traction(xi, nsteps) : T(0);
}

// The state after nsteps steps of h (nsteps <= h->step_count()), in the units
// of a, p0, f: x in units of length with the contact |x| < a, p = p0 p^(x/a),
// q = f p0 q^(x/a), sigma = s f p0 with s the loads after nsteps. bulk2: the
// pad's bulk stress (body 1 carries sigma + bulk2). The state shares h.
template <class T> contact_state<T> history_contact_state(std::shared_ptr<const history<T>> h, std::size_t nsteps,
                                                          const T &a, const T &p0, const T &f,
                                                          const T &bulk2 = T(0)) {
  if (!h) throw error(status::null_pointer, "history state: no history");
  if (nsteps > h->step_count()) throw error(status::bad_option, "history state: step count beyond the march");
  contact_state<T> st;
  T qload, sload;
  h->loads_after(nsteps, qload, sload);
  const T sigma = sload * f * p0;
  st.a = a;
  st.bulk2 = bulk2;
  st.bulk1 = sigma + bulk2;
  st.p = [h, a, p0](const T &x) { return history_pressure_at(*h, x, a, p0); };
  st.q = [h, nsteps, a, p0, f](const T &x) { return history_traction_at(*h, nsteps, x, a, p0, f); };
  for (const T &m : h->memory_points(nsteps)) st.breaks.push_back(a * m);
  for (const auto &bp : h->pressure().breakpoints()) {
    st.breaks.push_back(a * bp.x);
    st.kinks.push_back(a * bp.x);
  }
  if (nsteps > 0) {
    const auto &last = h->steps()[nsteps - 1];
    st.stick_lo = -a * last.b2b();
    st.stick_hi = a * last.b1b();
  } else {
    st.stick_lo = -a;
    st.stick_hi = a;
  }
  st.q_analytic_on_stick = false;
  return st;
}

// The state of a history taken by static solves (static_history.hpp, issue 14), as above:
// q from the state's panels (O(1) per point), breakpoints at its memory points.
template <class T> contact_state<T> static_contact_state(std::shared_ptr<const static_history<T>> h, const T &a,
                                                         const T &p0, const T &f, const T &bulk2 = T(0)) {
  if (!h) throw error(status::null_pointer, "history state: no history");
  contact_state<T> st;
  st.a = a;
  st.bulk2 = bulk2;
  st.bulk1 = h->s() * f * p0 + bulk2;
  st.p = [h, a, p0](const T &x) {
    const T xi = x / a;
    return xi > -1 && xi < 1 ? p0 * h->pressure().p(xi) : T(0);
  };
  st.q = [h, a, p0, f](const T &x) {
    const T xi = x / a;
    return xi > -1 && xi < 1 ? f * p0 * h->traction(xi) : T(0);
  };
  for (const T &m : h->memory_points()) st.breaks.push_back(a * m);
  for (const auto &bp : h->pressure().breakpoints()) {
    st.breaks.push_back(a * bp.x);
    st.kinks.push_back(a * bp.x);
  }
  st.stick_lo = -a * h->b2();
  st.stick_hi = a * h->b1();
  st.q_analytic_on_stick = false;
  return st;
}

}}  // namespace hs::core
