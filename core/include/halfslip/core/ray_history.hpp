// Load paths along one ray through the origin, by superposition (issue 14).
//
// At constant normal load, along a path whose vertices all lie on one ray
// (q, s) = t (u_q, u_s) through the origin, every reversal makes both edge
// zones reverse together, and the state follows Jäger's memory rule
// (Ciavarella-Jäger superposition at constant normal load; docs/history.md):
// on the branch that starts at a turning point tau the state is
//     S(t) = S(tau) + 2 M((t - tau)/2),
// M(lambda) the monotonic solution at the load lambda (u_q, u_s) from zero
// (friction f; "2 M(Delta/2)" is the monotonic solution of the increment Delta
// with friction 2f). The branch holds while |t - tau| does not exceed the
// range of the branch before it (twice |tau| for the first reversal); past
// that the memory of the two turning points is wiped and the older branch
// continues (Masing). This needs the stick zone of M to shrink monotonically
// along the ray up to the largest |t| of the path, i.e. no zone recedes on the
// ramp (core::ramp_recedes); the caller checks that.
//
// This header is pure bookkeeping, for any real type T: which monotonic
// solutions, with which coefficients, make the state after each vertex, and
// which differences of monotonic energies make the energy of each segment. The
// monotonic solutions themselves come from any solver (closed forms, the
// general solver, the MPFR reference backend: certified histories).
#pragma once
#include <cmath>
#include <cstddef>
#include <vector>

#include "numerics.hpp"

namespace hs { namespace core {

template <class T> struct ray_load {
  T q{0}, s{0};  // Q/fP, sigma/fp0
  bool zero() const { return q == 0 && s == 0; }
};

// coef * M(load)
template <class T> struct ray_term {
  int coef = 1;
  ray_load<T> load;
};

// the energy of zone i over a part of a segment: coef * (E_i(to) - E_i(from)),
// E_i(lambda) the monotonic energy of zone i at the load lambda (E_i(0) = 0).
// For coef 2 the points slip by 2 dh_M at the traction f p (not 2f p).
template <class T> struct ray_piece {
  int coef = 1;
  ray_load<T> from, to;
};

template <class T> struct ray_vertex_plan {
  ray_load<T> at;                  // the vertex
  std::vector<ray_term<T>> terms;  // the state after the vertex: sum of coef * M(load)
  std::vector<ray_piece<T>> pieces;  // the energy of the segment that ends here
  // the last term is the active branch: its zones and slip directions are the
  // state's. moved = false: a zero-length segment (no slip, no energy; the
  // directions are those of the vertex before, as in the march)
  bool moved = true;
  T t{0};  // position on the ray, in units of the first non-zero vertex
};

template <class T> class ray_path {
 public:
  // Whether (q, s) lies on the path's ray (any point does while the path has
  // only zero vertices): collinear with the first non-zero vertex to 8 eps.
  bool on_ray(const T &q, const T &s) const {
    using std::abs;
    if (!have_dir_ || (q == 0 && s == 0)) return true;
    const T cross = q * us_ - s * uq_;
    return abs(cross) <= 8 * eps<T>() * (abs(q * us_) + abs(s * uq_));
  }

  // Appends a vertex; false (path unchanged) when it is not on the ray.
  bool add(const T &q, const T &s) {
    using std::abs;
    if (!on_ray(q, s)) return false;
    if (!have_dir_ && !(q == 0 && s == 0)) {
      have_dir_ = true;
      uq_ = q;
      us_ = s;
    }
    ray_vertex_plan<T> v;
    v.at = {q, s};
    const T tn = position(q, s);
    v.t = tn;
    if (tn == t_) {
      v.moved = false;
      v.terms = terms();
      plans_.push_back(v);
      return true;
    }
    const int d = tn > t_ ? 1 : -1;
    if (dir_ != 0 && d != dir_) turns_.push_back({t_, cur_});
    dir_ = d;
    for (;;) {
      const std::size_t m = turns_.size();
      if (m == 0) {  // the virgin curve, always away from zero here
        v.pieces.push_back({1, cur_, v.at});
        break;
      }
      const turn &tm = turns_.back();
      const T range = m == 1 ? 2 * abs(tm.t) : abs(tm.t - turns_[m - 2].t);
      if (!(abs(tn - tm.t) > range)) {
        v.pieces.push_back({2, half_from(tm.l, cur_), half_from(tm.l, v.at)});
        break;
      }
      // past the end of this branch: the state is back on the older one
      const ray_load<T> end = m == 1 ? ray_load<T>{-tm.l.q, -tm.l.s} : turns_[m - 2].l;
      const T tend = m == 1 ? -tm.t : turns_[m - 2].t;
      v.pieces.push_back({2, half_from(tm.l, cur_), half_from(tm.l, end)});
      cur_ = end;
      t_ = tend;
      turns_.pop_back();
      if (m >= 2) turns_.pop_back();
    }
    cur_ = v.at;
    t_ = tn;
    v.terms = terms();
    plans_.push_back(v);
    return true;
  }

  const std::vector<ray_vertex_plan<T>> &vertices() const { return plans_; }
  // the vertex of largest |t| so far (the no-recede condition is checked there)
  ray_load<T> farthest() const {
    using std::abs;
    ray_load<T> r;
    T best = -1;
    for (const auto &p : plans_)
      if (abs(p.t) > best) {
        best = abs(p.t);
        r = p.at;
      }
    return r;
  }

 private:
  struct turn {
    T t;
    ray_load<T> l;
  };
  T position(const T &q, const T &s) const {
    if (!have_dir_) return 0;
    using std::abs;
    // the larger component gives t to rounding
    return abs(uq_) >= abs(us_) ? q / uq_ : s / us_;
  }
  static ray_load<T> half_from(const ray_load<T> &from, const ray_load<T> &to) {
    return {(to.q - from.q) / 2, (to.s - from.s) / 2};
  }
  std::vector<ray_term<T>> terms() const {
    std::vector<ray_term<T>> r;
    if (turns_.empty()) {
      r.push_back({1, cur_});
      return r;
    }
    r.push_back({1, turns_[0].l});
    for (std::size_t j = 1; j < turns_.size(); ++j) r.push_back({2, half_from(turns_[j - 1].l, turns_[j].l)});
    r.push_back({2, half_from(turns_.back().l, cur_)});
    return r;
  }

  bool have_dir_ = false;
  T uq_{0}, us_{0};
  std::vector<turn> turns_;
  T t_{0};
  ray_load<T> cur_{};
  int dir_ = 0;
  std::vector<ray_vertex_plan<T>> plans_;
};

// The zones, directions and energies of a vertex from monotonic solutions.
// mono(load) returns an object with b1, b2 (stick zone (-b2, b1)), dir1, dir2,
// E1, E2 (monotonic energies) of the monotonic solution at that load; it is
// called for non-zero loads only. prev: the result of the vertex before (for a
// zero-length segment; nullptr at the first vertex).
template <class T> struct ray_vertex_result {
  T b1{1}, b2{1};
  int dir1 = 0, dir2 = 0;
  T energy1{0}, energy2{0};
};
template <class T, class Mono>
ray_vertex_result<T> ray_evaluate(const ray_vertex_plan<T> &v, const Mono &mono, const T &a,
                                  const ray_vertex_result<T> *prev) {
  ray_vertex_result<T> r;
  r.b1 = a;
  r.b2 = a;
  if (!v.moved) {
    if (prev) {
      r = *prev;
      r.energy1 = 0;
      r.energy2 = 0;
    }
    return r;
  }
  const auto &act = v.terms.back().load;
  if (!act.zero()) {
    const auto m = mono(act);
    r.b1 = m.b1;
    r.b2 = m.b2;
    r.dir1 = m.dir1;
    r.dir2 = m.dir2;
  }
  for (const auto &p : v.pieces) {
    T e1 = 0, e2 = 0;
    if (!p.to.zero()) {
      const auto m = mono(p.to);
      e1 += m.E1;
      e2 += m.E2;
    }
    if (!p.from.zero()) {
      const auto m = mono(p.from);
      e1 -= m.E1;
      e2 -= m.E2;
    }
    r.energy1 += p.coef * e1;
    r.energy2 += p.coef * e2;
  }
  return r;
}

}}  // namespace hs::core
