// halfslip core: load histories at constant normal load (issue #14).
//
// Canonical frame: a = 1, p0 = 1, f = 1, E* = 1; loads q = Q/fP, s = sigma/(f p0);
// traction in units of f p0, slip h in f p0 a/E*, energies in f^2 p0^2 a^2/E*.
// Derivation: docs/history.md. In short:
//
//  * While a point x is stuck its slip does not change, and the slip zones
//    carry q = s_i p(x), fixed in time. So at any instant the traction RATE is
//    zero on the slip zones and, on the stick zone (-b2, b1) = (c - e, c + e),
//    is the fully stuck traction of that interval:
//        qdot(x) = [Qdot/2 - (Sdot/4)(x - c)] / sqrt((b1 - x)(x + b2)).
//    The traction at a stuck point is therefore its traction when it last
//    entered the stick zone (s_i p(x), or 0 if it has never slipped) plus the
//    time integral of qdot since then (superposition of stuck-interval rates;
//    locked-in slip is preserved automatically).
//  * An edge of the stick zone where the zone advances (stick shrinking) is
//    fixed by continuity, q(b_i) = s_i p(b_i). The rate's end coefficient
//        r1 = Qdot/2 - Sdot e/4 (end b1),   r2 = Qdot/2 + Sdot e/4 (end -b2)
//    decides each end: s_i r_i > 0 advances; s_i r_i < 0 would make the slip
//    rate next to the end run against the traction, so the end recedes with
//    r_i = 0 (stick half-width held at e* = 2 Qdot/Sdot for end 1,
//    -2 Qdot/Sdot for end 2), or, if that is out of reach, the whole zone sticks
//    at once (e.g. unloading). A stick zone that reaches the contact edge
//    opens a zone of direction sign(r_i) there as soon as r_i != 0.
//  * The slip rate in zone 1 is hdot = 2[r A acosh(v/e) - B sqrt(v^2 - e^2)],
//    v = x - c, A = Qdot/2, B = Sdot/4 (zone 2: + B and |v|), the slip rate of
//    a stuck contact of half-width e; dissipation rate = int s_i p hdot dx.
//
// The path is marched in equal load steps per run; the ends are interpolated
// in time by polynomials through the previous knots of the run (degree up to
// history_options::degree), and each step's contribution to the traction is a
// Gauss-Legendre rule after the substitution u = u* -+ v^2 at the root of the
// nearly vanishing factor. Events (an end switching mode, a receding zone
// closing) are located within the step. Error falls like step^(degree+1/2).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include <boost/math/tools/roots.hpp>

#include "newton.hpp"
#include "numerics.hpp"
#include "pressure.hpp"
#include "history_rates.hpp"
#include "status.hpp"

namespace hs { namespace core {

template <class T> struct history_options {
  T max_step = T(1) / 128;  // largest load step, in max(|dq|, |ds|/4)
  int degree = 3;           // interpolation degree of the stick-zone ends in time
  int order = 8;            // Gauss-Legendre nodes per step integral
  int max_steps = 20000;    // total steps over the whole history (the march costs ~ steps^2)
  int max_newton = 60;      // Newton iterations per step
  int grade_steps = 4;      // first steps of each run at 2^-(G-1), 2^-(G-1), ..., 1/4, 1/2 of the step
  // An interior slip patch (the friction limit reached away from the stick-zone
  // end) needs a third zone, which the march does not model. false (default):
  // the march stops with status::not_applicable (issue 14: "detect it and return
  // a clear status"); true: the patch and the band between it and the end are
  // merged into the edge zone, an approximation counted in interior_merges.
  bool merge_interior_patches = false;
};

// State after a path vertex (canonical frame; b's in units of a).
template <class T> struct history_vertex {
  T q{0}, s{0};
  T b1{1}, b2{1};
  int dir1 = 0, dir2 = 0;      // slip direction of each edge zone at the vertex (0: stuck)
  T energy1{0}, energy2{0};    // dissipated over the segment that ends here
  T energyp{0};                // ... in interior slip zones (the static solves' patches; 0 in a march)
  // the part of energy_i that the edge side of zone i spends slipping back against the
  // zone's direction (>= 0; step_energy): where it is not small the exact solution has a
  // stick band or a reverse slip zone near the contact edge, which the march does not
  // model (refined_history::backslip_limit)
  T backslip1{0}, backslip2{0};
  size_t step_end = 0;         // number of steps up to this vertex
  int cycle = 0;               // 0: path; k >= 1: k-th cycle of add_cycles
  size_t interior_merges = 0;  // interior slip patches merged so far (history::interior_merges)
  T step{0};                   // load step the segment was marched at (refined_history; 0: max_step)
  T error_estimate{0};         // refined_history: the segment's h/2h difference over 7
};

namespace hdetail {
// the status message of an interior slip patch (history::erase_at_limit, refined_history)
constexpr const char *interior_vertex_message =
    "history: an interior slip zone is open at this vertex (the marched stick traction passes the friction limit "
    "inside the stick zone; history_options::merge_interior_patches goes on, an approximation)";
constexpr const char *edge_vertex_message =
    "history: the marched stick traction passes the friction limit next to a contact edge where a zone closed "
    "(the march's step missed the zone's reopening; a smaller max_step or rtol > 0 resolves it)";
constexpr const char *interior_patch_message =
    "history: an interior slip zone opens away from the stick-zone end (more zones than the march models; "
    "history_options::merge_interior_patches merges it into the edge zone, an approximation)";

// b(u) = bb + (u - 1) g(u), g a polynomial in u of degree <= 3: exact at u = 1.
template <class T> struct endpoly {
  T bb{1};
  std::array<T, 6> g{{T(0), T(0), T(0), T(0), T(0), T(0)}};
  int deg = 0;  // degree of g
  T val(const T &u) const { return bb + (u - 1) * gval(u); }
  T gval(const T &u) const {
    T r = g[deg];
    for (int k = deg - 1; k >= 0; --k) r = r * u + g[k];
    return r;
  }
  T der(const T &u) const {  // b'(u) = g(u) + (u - 1) g'(u)
    T gd = 0;
    for (int k = deg; k >= 1; --k) gd = gd * u + T(k) * g[k];
    return gval(u) + (u - 1) * gd;
  }
};

// Polynomial through (u_j, b_j), j = 0..m, with u_m = 1 (the new knot), written
// as bb + (u - 1) g(u) (Newton form from the node u = 1 backwards).
template <class T> endpoly<T> interpolate(const std::vector<T> &b, const std::vector<T> &u) {
  const int m = int(b.size()) - 1;  // degree
  endpoly<T> p;
  p.bb = b[m];
  if (m == 0) return p;
  std::vector<T> nodes(m + 1), c(m + 1);
  for (int j = 0; j <= m; ++j) {
    nodes[j] = u[m - j];
    c[j] = b[m - j];
  }
  for (int k = 1; k <= m; ++k)
    for (int j = m; j >= k; --j) c[j] = (c[j] - c[j - 1]) / (nodes[j] - nodes[j - k]);
  // b(u) = c0 + (u - n0)[c1 + (u - n1)[c2 + (u - n2) c3]], n0 = 1: g = c1 + (u - n1)(c2 + ...)
  std::array<T, 6> acc{{c[m], T(0), T(0), T(0), T(0), T(0)}};
  int d = 0;
  for (int k = m - 1; k >= 1; --k) {
    std::array<T, 6> nx{{T(0), T(0), T(0), T(0), T(0), T(0)}};
    for (int j = 0; j <= d; ++j) {
      nx[j + 1] += acc[j];
      nx[j] -= nodes[k] * acc[j];
    }
    ++d;
    nx[0] += c[k];
    acc = nx;
  }
  p.g = acc;
  p.deg = d;
  return p;
}

}  // namespace hdetail

// One step of the march: loads linear in u in [0, 1], stick-zone ends b1(u), b2(u).
template <class T> struct history_step {
  T q0, s0, dq, ds;
  T len{0};  // length of the step as a fraction of its segment
  hdetail::endpoly<T> e1, e2;
  T b1a, b2a;              // ends at u = 0 (the knots of the previous step)
  int s1 = 0, s2 = 0;      // zone directions during the step (0: no zone)
  T E1{0}, E2{0};          // energy dissipated in each zone during the step
  T R1{0}, R2{0};          // of which slipping back against the zone's direction (>= 0; step_energy)
  bool run_start = false;  // the first step of a run (a segment, or after an event or a jump)
  T b1(const T &u) const { return e1.val(u); }
  T b2(const T &u) const { return e2.val(u); }
  T b1b() const { return e1.bb; }
  T b2b() const { return e2.bb; }
};

template <class T> class history {
 public:
  using pressure_ptr = std::shared_ptr<const pressure_model<T>>;
  history(pressure_ptr pm, const history_options<T> &o = {}) : pm_(std::move(pm)), opt_(o) {
    if (!pm_) throw error(status::null_pointer, "history: no pressure model");
    if (!(opt_.max_step >= min_max_step()) || !(opt_.max_step <= 1))
      throw error(status::bad_option, "history: max_step must be in [1e-6, 1]");
    if (opt_.degree < 1 || opt_.degree > 5) throw error(status::bad_option, "history: degree must be in 1..5");
    if (opt_.order < 2 || opt_.order > 64) throw error(status::bad_option, "history: order must be in 2..64");
  }

  // The smallest max_step: a segment's step and work budgets scale with 1/step (and
  // a million steps per unit of load is far past max_steps); below it they would
  // overflow (found by fuzz_history: max_step = 1e-304).
  static T min_max_step() { return T(1e-6); }

  // March from the current loads to (q, s) along a straight segment.
  void add_vertex(const T &qn, const T &sn) {
    using boost::math::isfinite;
    using std::abs;
    using std::ceil;
    using std::max;
    using std::min;
    if (!isfinite(qn) || !isfinite(sn)) throw error(status::not_finite, "history: a path vertex is not finite");
    if (!(abs(qn) < 1)) throw error(status::gross_sliding, "history: |Q| >= fP at a path vertex: gross sliding");
    const T dq = qn - q_, ds = sn - s_;
    const T len = max(abs(dq), abs(ds) / 4);
    T E1 = 0, E2 = 0, R1 = 0, R2 = 0;
    noop_erase_ = 0;
    mem_skip1_ = mem_skip2_ = T(2);  // memory points passed without landing (pass_memory), per segment
    mem_run_ = size_t(-1);
    if (len > 0) {
      // steps of the segment at max_step: beyond max_steps the march could not finish
      // (and the budgets below, ~1/h, would not fit a size_t: fuzz_history, sigma/fp0 = 1e111)
      const T nseg = max(T(1), ceil(len / opt_.max_step));
      if (!(nseg <= T(opt_.max_steps)))
        throw error(status::no_convergence,
                    "history: the segment needs more load steps than max_steps (max(|dQ/fP|, |dsigma/fp0|/4) / "
                    "max_step)");
      decide(dq, ds);
      const T h = T(1) / nseg;
      T done = 0;  // fraction of the segment done
      T hrun = h;
      // the ends may move at most max_step (units of a) per step: where an end runs
      // fast the step shrinks (the knots of a run may be unequally spaced)
      const T db_max = opt_.max_step;
      size_t run_seen = size_t(-1);
      T cur = h;
      // a march that keeps taking tiny steps without getting on (an end caught at a
      // kink of the traction it cannot pass) stops with a status instead of running on
      const size_t seg_first = steps_.size();
      const size_t seg_budget = size_t(64) * size_t(nseg) + 256;
      work_ = 0;
      work_budget_ = 4000 * size_t(nseg) + 40000;  // residual evaluations per segment
      while (done < 1) {
        if (steps_.size() - seg_first > seg_budget)
          throw error(status::no_convergence,
                      "history: the march of a segment makes no progress (steps shrink without end)");
        if ((m1_ == rec && b1_ >= 1 - 16 * eps<T>()) || (m2_ == rec && b2_ >= 1 - 16 * eps<T>())) {
          after_event(m1_ == rec && b1_ >= 1 - 16 * eps<T>() ? 3 : 4);
          decide(dq, ds);
          run_start_ = steps_.size();
        }
        // graded start of each run (its first steps use low-degree interpolation),
        // then the step doubles back up to hrun
        if (run_seen != run_start_) {
          run_seen = run_start_;
          cur = std::ldexp(hrun, -std::max(0, opt_.grade_steps - 1));
        }
        T frac = min(cur, 1 - done);
        if (1 - done - frac < hrun / 1024) frac = 1 - done;
        // a remainder under a quarter step is shared with this step (two even steps): a
        // sliver of a last step makes the end's interpolation lopsided and leaves a kink
        // in the traction next to the vertex (a memory point)
        else if (1 - done - frac < hrun / 4) frac = (1 - done) / 2;
        // a step that cannot keep an advancing end advancing ends beyond an
        // event: shorten it until it solves (the event is then located below)
        history_step<T> st;
        // an end that would move more than db_max (or a step that does not
        // converge) is driven by the end instead: the step ends where that end
        // has moved db_max / 2
        auto by_end = [&](const T &fmax) -> bool {
          for (int i = 1; i <= 2; ++i) {
            const mode mi = i == 1 ? m1_ : m2_;
            if (mi != adv) continue;
            const T bi = i == 1 ? b1_ : b2_;
            history_step<T> se;
            if (end_driven_step(dq, ds, i, bi - db_max / 2, fmax, se)) {
              const T mv = max(abs(se.e1.bb - b1_), abs(se.e2.bb - b2_));
              if (mv <= db_max) {
                st = se;
                frac = se.len;
                return true;
              }
            }
          }
          return false;
        };
        // a step that would carry an advancing end past a memory point (a cusp of
        // the traction) ends exactly there, driven by that end; the run restarts
        bool at_memory = false;
        // the end that landed on its memory point (1 or 2). A landing step is not held to
        // db_max: it ends on the point, where the run restarts (holding it to db_max made
        // 3 of the 162 periodic loadings of bench_history stagnate)
        int landed = 0;
        auto by_memory = [&](const T &fmax) -> bool {
          update_memory_targets();
          bool found = false;
          for (int i = 1; i <= 2; ++i) {
            const mode mi = i == 1 ? m1_ : m2_;
            const bool ok = i == 1 ? mem1_ok_ : mem2_ok_;
            if (mi != adv || !ok) continue;
            const T bt = i == 1 ? mem1_ : -mem2_;
            history_step<T> se;
            if (end_driven_step(dq, ds, i, bt, found ? frac : fmax, se) && (!found || se.len < frac)) {  // no end moves more than a step
              st = se;
              frac = se.len;
              found = true;
              landed = i;
            }
          }
          return found;
        };
        // a crossing that cannot be landed on. An end that a step left just short of its
        // point, where the continuity residual already has the far side's sign (the stuck
        // traction there is past the limit, so the end belongs further in), sweeps to the
        // next root inwards: a zero-load jump over a band of the width of the step's own
        // error, found by doubling then bisection; the run restarts there. Any other
        // crossing (the end-driven step did not converge) is marched through as an
        // ordinary step. Either way the point is no longer a target.
        auto pass_memory = [&]() -> bool {
          const T w = b1_ + b2_;
          bool jumped = false;
          for (int i = 1; i <= 2; ++i) {
            const mode mi = i == 1 ? m1_ : m2_;
            const bool ok = i == 1 ? mem1_ok_ : mem2_ok_;
            const T bi = i == 1 ? b1_ : b2_, bm = i == 1 ? mem1_ : -mem2_;
            const T bn = i == 1 ? st.e1.bb : st.e2.bb;
            // a step that stopped just short of the point (the 1 % window of `crosses`)
            // keeps it as a target: the next step crosses it and lands
            if (mi != adv || !ok || !(bn < bm)) continue;
            (i == 1 ? mem_skip1_ : mem_skip2_) = i == 1 ? mem1_ : mem2_;
            mem_run_ = size_t(-1);
            if (!(bi - bm < T(1e-6) * w)) continue;
            const int si = i == 1 ? s1_ : s2_;
            auto G = [&](const T &b) {
              const T x = i == 1 ? b : -b;
              return T(si) * (stick_traction(x, steps_.size(), nullptr) - T(si) * pm_->p(x));
            };
            T hi = bm, d = bi - bm;
            if (!(G(hi) > 0)) continue;
            T lo = hi;
            bool bracket = false;
            for (int k = 0; k < 40 && d < T(1e-3) * w; ++k, d *= 2) {
              lo = bm - d;
              if (G(lo) < 0) {
                bracket = true;
                break;
              }
              hi = lo;
            }
            if (!bracket) continue;
            for (int it = 0; it < 200 && hi - lo > 4 * eps<T>() * w; ++it) {
              const T mid = (lo + hi) / 2;
              if (G(mid) < 0) lo = mid;
              else hi = mid;
            }
            if (i == 1) jump(hi, b2_);
            else jump(b1_, hi);
            jumped = true;
          }
          if (jumped) run_start_ = steps_.size();
          return jumped;
        };
        bool restarted = false;
        auto crosses = [&](const history_step<T> &t) {
          update_memory_targets();
          // a step that ends just short of the point (within 1 % of its own move) counts
          // too: next to the cusp the continuity residual can have a second, spurious root
          // there, where the end would stall instead of passing the point
          // (not for the segment's last step: at a vertex an end may stop just short of a
          // point, as when a cycle returns to its previous turning point)
          const bool last = !(done + t.len < 1);
          const T g1 = last ? T(0) : abs(t.e1.bb - b1_) / 100, g2 = last ? T(0) : abs(t.e2.bb - b2_) / 100;
          return (m1_ == adv && mem1_ok_ && t.e1.bb < mem1_ + g1) || (m2_ == adv && mem2_ok_ && -t.e2.bb > mem2_ - g2) ||
                 stalls_short(t, 1) || stalls_short(t, 2);
        };
        int near_erases = 0, end_driven = 0;
        for (int tries = 0;; ++tries) {
          try {
            st = take_step(dq, ds, frac);
            if (crosses(st)) {
              if (by_memory(frac)) {
                at_memory = true;
                break;
              }
              if (pass_memory()) {
                restarted = true;
                break;
              }
            }
            const T moved = max(abs(st.e1.bb - b1_), abs(st.e2.bb - b2_));
            if (moved > db_max && tries < 40 && frac > hrun / 65536) {
              if (end_driven++ < 2 && by_end(frac)) break;
              frac /= 2;
              continue;
            }
            break;
          } catch (const error &err) {
            if (err.code() != status::no_convergence || tries >= 20) throw;
            if (tries == 0 && by_memory(frac)) {
              at_memory = true;
              break;
            }
            if (near_erases < 8) {
              // an end stalls against a region already within 1e-5 of the limit
              // (a Masing return the limit events did not catch): sweep it
              bool erased = false;
              for (int i = 1; i <= 2; ++i)
                if ((i == 1 ? m1_ : m2_) == adv) erased = erase_at_limit(i, T(1e-5)) || erased;
              if (erased) {
                ++near_erases;
                frac = min(cur, 1 - done);
                tries = -1;
                continue;
              }
            }
            if (tries >= 1 && end_driven++ < 2 && by_end(frac)) break;
            frac /= 2;
          }
        }
        if (restarted) continue;
        // events within the step
        int ev = event_in(st);
        if (at_memory && ev == 8 + landed) ev = 0;  // landed on the point: no bisection
        if ((ev == 7 || ev == 8) &&
            abs(event_value(ev, nullptr, dq, ds, T(0))) <= 64 * eps<T>() * (abs(dq) + abs(ds))) {
          after_event(ev);  // the zone opens at the start of the step (r_i was zero there)
          run_start_ = steps_.size();
          continue;
        }
        if (ev != 0) {
          T lo = 0, hi = frac;
          // bisection/secant on the fraction at which the event happens
          T fl = event_value(ev, nullptr, dq, ds, T(0)), fh = event_value(ev, &st, dq, ds, frac);
          // the step kept is the last one tried (within rounding of the event) or the
          // nearest one past it
          history_step<T> best = st;
          T best_frac = frac;
          for (int it = 0; it < 60; ++it) {
            T mid = (fl != fh) ? lo + (hi - lo) * fl / (fl - fh) : (lo + hi) / 2;
            if (!(mid > lo + (hi - lo) / 16) || !(mid < hi - (hi - lo) / 16)) mid = (lo + hi) / 2;
            history_step<T> sm;
            if (!try_step(dq, ds, mid, sm)) {  // beyond the event: shrink from above
              hi = mid;
              continue;
            }
            const T fm = event_value(ev, &sm, dq, ds, mid);
            if ((fm > 0) == (fl > 0)) {
              lo = mid;
              fl = fm;
            } else {
              hi = mid;
              fh = fm;
              best = sm;
              best_frac = mid;
            }
            if (hi - lo <= 8 * eps<T>() * frac || abs(fm) <= 8 * eps<T>()) {
              best = sm;
              best_frac = mid;
              break;
            }
          }
          frac = best_frac;
          st = best;
          if (event_value(ev, &st, dq, ds, frac) != 0) apply_event_limit(ev, st);
          commit(st, dq, ds, frac);
          done += frac;
          E1 += st.E1;
          E2 += st.E2;
          R1 += st.R1;
          R2 += st.R2;
          after_event(ev);
          decide(dq, ds);
          run_start_ = steps_.size();
          // rest of the segment in equal steps
          const T rest = 1 - done;
          if (rest > 0) hrun = rest / max(T(1), ceil(rest / h));
          continue;
        }
        commit(st, dq, ds, frac);
        done += frac;
        E1 += st.E1;
        E2 += st.E2;
        R1 += st.R1;
        R2 += st.R2;
        cur = min(2 * frac, hrun);
        if (at_memory) {
          // a memory point where an earlier zone of the same direction ended (Masing's
          // memory rule): the region just inside is at the friction limit, and the end
          // sweeps over it at once
          for (int i = 1; i <= 2; ++i)
            if (i == landed && (i == 1 ? m1_ : m2_) == adv) erase_at_limit(i, limit_tol());
          run_start_ = steps_.size();
          const T rest = 1 - done;
          if (rest > 0) hrun = rest / max(T(1), ceil(rest / h));
        }
      }
    }
    history_vertex<T> v;
    v.q = qn;
    v.s = sn;
    q_ = qn;
    s_ = sn;
    v.b1 = b1_;
    v.b2 = b2_;
    v.dir1 = s1_;
    v.dir2 = s2_;
    v.energy1 = E1;
    v.energy2 = E2;
    v.backslip1 = R1;
    v.backslip2 = R2;
    v.step_end = steps_.size();
    v.interior_merges = interior_merges_;
    vertices_.push_back(v);
    run_start_ = steps_.size();
  }

  const std::vector<history_vertex<T>> &vertices() const { return vertices_; }
  void tag_last_vertex(int cycle) { vertices_.back().cycle = cycle; }
  void note_last_vertex(const T &step, const T &estimate) {
    vertices_.back().step = step;
    vertices_.back().error_estimate = estimate;
  }
  // the largest load step of later segments
  void set_max_step(const T &h) {
    if (!(h >= min_max_step()) || !(h <= 1)) throw error(status::bad_option, "history: max_step must be in [1e-6, 1]");
    opt_.max_step = h;
  }
  // merge interior slip patches into the edge zone (true) or stop at the first (false)
  void set_merge_interior_patches(bool m) { opt_.merge_interior_patches = m; }
  T q() const { return q_; }
  T s() const { return s_; }
  const std::vector<history_step<T>> &steps() const { return steps_; }
  const pressure_model<T> &pressure() const { return *pm_; }

  // Traction q(x) after `nsteps` steps (canonical units f p0).
  T traction(const T &x, size_t nsteps) const {
    if (nsteps == 0) return T(0);
    const history_step<T> &last = steps_[nsteps - 1];
    if (x >= last.b1b() && last.s1 != 0 && x > last.b1b()) return T(last.s1) * pm_->p(x);
    if (x <= -last.b2b() && last.s2 != 0 && x < -last.b2b()) return T(last.s2) * pm_->p(x);
    return stick_traction(x, nsteps, nullptr);
  }
  // The largest |q|/p - 1 of the state after the last step over 64 points of the stick zone's
  // interior (Chebyshev points of its middle 98 %; the traction tends to s_i p at the ends). The
  // march's own check of the friction limit samples 8 points from each advancing end over 3/4 of
  // the stick zone, with that end's sign, and misses a patch elsewhere (Hertz (0, 1.5) -> (0.15,
  // 1.5) -> (0.25, 1.2): a patch of the other direction than zone 2 at (-0.74, -0.58) a in
  // (-0.99, 0.89)); refined_history checks the vertex's state with this. Positive: an interior slip
  // zone is open at the vertex. (-1: no stick zone.) where: the point of the largest.
  T interior_excess(T *where = nullptr) const {
    using std::abs;
    using std::cos;
    if (steps_.empty()) return T(-1);
    const history_step<T> &last = steps_.back();
    const T l = -last.b2b(), r = last.b1b();
    if (!(r > l)) return T(-1);
    const T mid = (l + r) / 2, hw = (r - l) / 2 * T(0.98);
    const int M = 64;
    T worst = -1;
    for (int k = 0; k < M; ++k) {
      const T x = mid + hw * cos(pi<T>() * (T(k) + T(0.5)) / T(M));
      const T p = pm_->p(x);
      if (!(p > 0)) continue;
      const T v = abs(stick_traction(x, steps_.size(), nullptr)) / p - 1;
      if (v > worst) {
        worst = v;
        if (where) *where = x;
      }
    }
    return worst;
  }
  // Accumulated slip h(x) after nsteps (canonical units f p0 a / E*).
  T slip(const T &x, size_t nsteps) const {
    T h = 0;
    for (size_t k = 0; k < nsteps; ++k) h += step_slip(steps_[k], x);
    return h;
  }
  size_t step_count() const { return steps_.size(); }
  // A history that holds the first nsteps steps only, shared by a state's
  // handle: the traction, slip and memory points after those steps need the
  // steps and the pressure only (not the march's working state).
  std::shared_ptr<const history> prefix(size_t nsteps) const {
    if (nsteps > steps_.size()) throw error(status::bad_option, "history: step count beyond the march");
    auto r = std::make_shared<history>(pm_, opt_);
    r->steps_.assign(steps_.begin(), steps_.begin() + std::ptrdiff_t(nsteps));
    loads_after(nsteps, r->q_, r->s_);
    return r;
  }
  // Loads after nsteps steps.
  // The loads after the first nsteps steps. A step's (q0, s0) is the start of
  // its segment and (dq, ds) its own increment (len of the segment), so the
  // load is the segment's start plus the steps of the segment so far; at a
  // vertex, the vertex's loads exactly. (Before: q0 + dq of the last step, the
  // load at the segment's start plus one step, which gave the stresses of a
  // history state the bulk tension of the vertex before; found by the
  // superposition of issue 14, tests/test_ray_history.cpp.)
  void loads_after(size_t nsteps, T &q, T &s) const {
    q = s = T(0);
    if (nsteps == 0) return;
    for (const auto &v : vertices_)
      if (v.step_end == nsteps) {
        q = v.q;
        s = v.s;
        return;
      }
    const history_step<T> &last = steps_[nsteps - 1];
    T dq = 0, ds = 0;
    for (size_t k = nsteps; k-- > 0;) {
      const history_step<T> &st = steps_[k];
      if (!(st.q0 == last.q0 && st.s0 == last.s0)) break;
      dq += st.dq;
      ds += st.ds;
    }
    q = last.q0 + dq;
    s = last.s0 + ds;
  }
  // The points of the stick zone after nsteps steps (and its ends) where that
  // state's traction may be non-smooth (issue 15: the breakpoints of the field
  // panels). A stuck point carries the traction it had when it last entered
  // the stick zone plus the stuck-interval rates since then, which behave like
  // 1/sqrt(distance) at the ends of each interval: q is non-smooth where an end
  // stopped, started, jumped or turned and the point has stayed stuck since
  // (Masing's memory points; for unloading, the ends of the loading). Within
  // a run the ends are smooth in time apart from the knots of their cubic
  // interpolation, whose kinks are at the level of the march's own error.
  // Candidates: the end positions at the start of every run, both sides of every
  // jump (a zero-load step), and the current ends; one is kept if no end has
  // crossed it since (it is inside or at the end of every later stick zone).
  std::vector<T> memory_points(size_t nsteps) const {
    using std::max;
    using std::min;
    std::vector<T> out;
    if (nsteps == 0) return out;
    if (nsteps > steps_.size()) throw error(status::bad_option, "history: step count beyond the march");
    // the innermost position of each end over steps k..n-1 (m1: smallest b1, m2: smallest b2)
    std::vector<T> m1(nsteps + 1), m2(nsteps + 1);
    m1[nsteps] = steps_[nsteps - 1].b1b();
    m2[nsteps] = steps_[nsteps - 1].b2b();
    for (size_t k = nsteps; k-- > 0;) {
      const history_step<T> &st = steps_[k];
      m1[k] = min(m1[k + 1], min(st.b1a, st.b1b()));
      m2[k] = min(m2[k + 1], min(st.b2a, st.b2b()));
    }
    const T tol = 64 * eps<T>();
    auto keep = [&](const T &x, size_t from) {  // x stuck over steps from..n-1
      if (x <= -1 || x >= 1) return;
      if (x <= m1[from] + tol && x >= -m2[from] - tol) out.push_back(x);
    };
    for (size_t k = 0; k < nsteps; ++k) {
      const history_step<T> &st = steps_[k];
      const bool jump = st.dq == 0 && st.ds == 0;
      if (st.run_start || jump || k == 0) {
        keep(st.b1a, k);
        keep(-st.b2a, k);
      }
      if (jump) {
        keep(st.b1b(), k + 1);
        keep(-st.b2b(), k + 1);
      }
    }
    keep(steps_[nsteps - 1].b1b(), nsteps);
    keep(-steps_[nsteps - 1].b2b(), nsteps);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }
  // Interior slip patches (the friction limit reached inside the stick zone, away
  // from the ends) are merged at once with the nearer edge zone, the band between
  // included: an approximation, counted here (0: every state is exact to the march).
  size_t interior_merges() const { return interior_merges_; }

 private:
  enum mode { edge, adv, rec };
  pressure_ptr pm_;
  history_options<T> opt_;
  std::vector<history_step<T>> steps_;
  std::vector<history_vertex<T>> vertices_;
  T q_{0}, s_{0}, b1_{1}, b2_{1};
  int s1_ = 0, s2_ = 0;
  mode m1_ = edge, m2_ = edge;
  T estar_{0};
  size_t run_start_ = 0;
  struct jac_cache {
    bool valid = false, a1 = false, a2 = false;
    size_t run = 0;
    T len{0};
    T j[4];
  };
  mutable jac_cache jac_;       // march state only (const evaluations never touch it)
  int noop_erase_ = 0;          // limit events located short of the limit in this segment
  size_t interior_merges_ = 0;  // interior slip patches merged with an edge zone (approximation)
  mutable int open_sign_ = 0;   // direction of the zone that event 7/8 opens
  mutable size_t work_ = 0, work_budget_ = size_t(-1);  // residual evaluations in the current segment
  // memory-point targets of the advancing ends (events 9/10), for the run mem_run_
  mutable size_t mem_run_ = size_t(-1);
  mutable T mem1_{0}, mem2_{0};
  T mem_skip1_{2}, mem_skip2_{2};  // memory points passed without landing (pass_memory)
  mutable bool mem1_ok_ = false, mem2_ok_ = false;

  static int sgn(const T &v) { return (v > 0) - (v < 0); }
  static T r(int i, const T &dq, const T &ds, const T &e) { return hist_rate_end(i, dq, ds, e); }

  // A zero-load step that moves the ends outwards at once (part of a zone sticks).
  void jump(const T &b1n, const T &b2n) {
    if (steps_.size() >= size_t(opt_.max_steps))
      throw error(status::no_convergence, "history: step limit reached (history_options::max_steps)");
    if (!(b1n + b2n > 0)) throw error(status::no_convergence, "history: a jump of an end would empty the stick zone");
    history_step<T> st;
    st.q0 = q_;
    st.s0 = s_;
    st.dq = 0;
    st.ds = 0;
    st.b1a = b1_;
    st.b2a = b2_;
    st.e1.bb = b1n;
    st.e1.g[0] = b1n - b1_;
    st.e1.deg = 0;
    st.e2.bb = b2n;
    st.e2.g[0] = b2n - b2_;
    st.e2.deg = 0;
    st.s1 = s1_;
    st.s2 = s2_;
    steps_.push_back(st);
    b1_ = b1n;
    b2_ = b2n;
    run_start_ = steps_.size();
  }

  void decide(const T &dq, const T &ds) {
    for (int pass = 0; pass < 8; ++pass) {
      const T e = (b1_ + b2_) / 2;
      bool changed = false;
      for (int i = 1; i <= 2 && !changed; ++i) {
        int &si = i == 1 ? s1_ : s2_;
        mode &mi = i == 1 ? m1_ : m2_;
        const T bo = i == 1 ? b2_ : b1_;
        const T bi = i == 1 ? b1_ : b2_;
        const T ri = r(i, dq, ds, e);
        if (si == 0) {
          if (ri != 0) {
            si = sgn(ri);
            mi = adv;
            changed = true;
            run_start_ = steps_.size();
          } else mi = edge;
          continue;
        }
        if (T(si) * ri > 0) {
          if (mi != adv) {
            mi = adv;
            run_start_ = steps_.size();
          }
          continue;
        }
        // recede with r_i = 0 if the stick zone can grow to e*, else the zone sticks whole
        bool can = false;
        T es = 0;
        if (ds != 0) {
          es = (i == 1 ? 2 : -2) * dq / ds;
          using std::abs;
          if (es < e && es >= e - 64 * eps<T>() * (1 + abs(e))) es = e;  // at the event itself
          can = es >= e && 2 * es - bo < 1;
        }
        if (can) {
          const T bn = 2 * es - bo;
          if (bn > bi) {
            if (i == 1) jump(bn, b2_);
            else jump(b1_, bn);
          }
          mi = rec;
          estar_ = es;
          run_start_ = steps_.size();
        } else {
          if (i == 1) jump(T(1), b2_);
          else jump(b1_, T(1));
          si = 0;
          mi = edge;
          changed = true;
        }
      }
      if (!changed) {
        if (m1_ == rec && m2_ != adv) throw error(status::internal, "history: receding end without an advancing one");
        if (m2_ == rec && m1_ != adv) throw error(status::internal, "history: receding end without an advancing one");
        return;
      }
    }
    throw error(status::internal, "history: the slip-zone modes did not settle");
  }

  // Build the trial step to fraction `frac` of the segment with given end values.
  history_step<T> make_step(const T &dq, const T &ds, const T &frac, const T &b1n, const T &b2n) const {
    history_step<T> st;
    st.q0 = q_;
    st.s0 = s_;
    st.dq = dq * frac;
    st.ds = ds * frac;
    st.b1a = b1_;
    st.b2a = b2_;
    st.s1 = s1_;
    st.s2 = s2_;
    st.len = frac;
    // knots of the run: the starts of its previous steps (up to degree - 1 of them)
    std::vector<T> k1, k2, ku;
    const size_t have = steps_.size() - run_start_;
    int m = std::min<int>(opt_.degree, int(have) + 1);
    // earlier knots only while they lie within 20 step lengths: a step much shorter
    // than the ones before it (an event being located, a shrunken step) would make
    // the interpolation ill-conditioned in u
    {
      T span = 0;
      int keep = 1;
      for (int j = 1; j <= m - 1; ++j) {
        span += steps_[steps_.size() - j].len;
        if (!(span <= 20 * frac)) break;
        keep = j + 1;
      }
      m = keep;
    }
    T back = 0;
    for (int j = 1; j <= m - 1; ++j) back += steps_[steps_.size() - j].len;
    for (int j = m - 1; j >= 1; --j) {
      const auto &p = steps_[steps_.size() - j];
      k1.push_back(p.b1a);
      k2.push_back(p.b2a);
      ku.push_back(-back / frac);
      back -= p.len;
    }
    k1.push_back(b1_);
    k2.push_back(b2_);
    ku.push_back(T(0));
    k1.push_back(b1n);
    k2.push_back(b2n);
    ku.push_back(T(1));
    st.e1 = hdetail::interpolate(k1, ku);
    st.e2 = hdetail::interpolate(k2, ku);
    if (m1_ == rec) st.e1 = mirror_end(st.e2, b1n);
    if (m2_ == rec) st.e2 = mirror_end(st.e1, b2n);
    return st;
  }
  // receding end: b_i(u) = 2 e* - b_j(u)
  hdetail::endpoly<T> mirror_end(const hdetail::endpoly<T> &o, const T &bn) const {
    hdetail::endpoly<T> p = o;
    p.bb = bn;
    for (auto &c : p.g) c = -c;
    return p;
  }

  // ---- traction at a stuck point -------------------------------------------
  // sum over the steps since x last entered the stick zone (steps_[0..n) plus an
  // optional trial step after them)
  T stick_traction(const T &x, size_t n, const history_step<T> *trial) const {
    T total = 0;
    long k = long(n) - 1;
    bool first = trial != nullptr;
#ifdef HS_PROF_CALL
    HS_PROF_CALL
#endif
    while (first || k >= 0) {
#ifdef HS_PROF_WALK
      HS_PROF_WALK
#endif
      const history_step<T> &st = first ? *trial : steps_[size_t(k)];
      const bool in_start = st.b1a > x && x > -st.b2a;
      if (in_start) {
        total += contrib(st, x, T(0), T(1));
      } else {
        const T ua = entry_u(st, x);
        total += contrib(st, x, ua, T(1));
        if (x >= st.b1a) total += T(st.s1) * pm_->p(x);
        else total += T(st.s2) * pm_->p(x);
        return total;
      }
      if (first) first = false;
      else --k;
    }
    return total;  // stuck since the start: q was 0
  }

  // last u in [0, 1] at which x enters the stick zone during the step
  T entry_u(const history_step<T> &st, const T &x) const {
    using std::abs;
    if (st.dq == 0 && st.ds == 0) return T(1);  // a jump: entered at its end
    auto inside = [&](const T &u) { return st.b1(u) - x > 0 && x + st.b2(u) > 0; };
    T lo = 0, hi = 1;  // outside at lo, inside at hi
    for (int it = 0; it < 200 && hi - lo > 4 * eps<T>(); ++it) {
      const T mid = (lo + hi) / 2;
      if (inside(mid)) hi = mid;
      else lo = mid;
    }
    // 200 halvings reach 4 eps for T up to ~60 digits; beyond, say so
    if (!(hi - lo <= 4 * eps<T>()))
      throw error(status::no_convergence, "history: stick-zone entry bisection ran out");
    return hi;
  }

  // int_ua^ub [dq/2 - ds/4 (x - c(u))] / sqrt(L1 L2) du, L1 = b1(u) - x, L2 = x + b2(u)
  T contrib(const history_step<T> &st, const T &x, const T &ua, const T &ub) const {
    if ((st.dq == 0 && st.ds == 0) || !(ub > ua)) return T(0);
    auto L1 = [&](const T &u) { return (st.e1.bb - x) + (u - 1) * st.e1.gval(u); };
    auto L2 = [&](const T &u) { return (x + st.e2.bb) + (u - 1) * st.e2.gval(u); };
    auto f = [&](const T &u) {
      using std::sqrt;
      const T l1 = L1(u), l2 = L2(u);
      if (!(l1 > 0) || !(l2 > 0)) return T(0);
      const T c = (st.b1(u) - st.b2(u)) / 2;
      return (st.dq / 2 - st.ds / 4 * (x - c)) / sqrt(l1 * l2);
    };
    return integrate_rsing(f, L1, L2, st, ua, ub, 0);
  }

  // Gauss-Legendre on [ua, ub] of f = g / sqrt(L1 L2), with u = u* -+ v^2 at a
  // nearly vanishing factor (root u* at or just outside the interval).
  template <class F, class G1, class G2> T integrate_rsing(const F &f, const G1 &L1, const G2 &L2,
                                                           const history_step<T> &st, const T &ua, const T &ub,
                                                           int depth) const {
    using std::abs;
    using std::sqrt;
    const T l1a = L1(ua), l1b = L1(ub), l2a = L2(ua), l2b = L2(ub);
    auto ratio = [](const T &a, const T &b) {
      const T lo = std::min(a, b), hi = std::max(a, b);
      return hi - lo > 0 ? lo / (hi - lo) : T(1e30);
    };
    const T r1 = ratio(l1a, l1b), r2 = ratio(l2a, l2b);
    const bool n1 = r1 < 2, n2 = r2 < 2;
    const int end1 = l1a < l1b ? -1 : +1, end2 = l2a < l2b ? -1 : +1;
    if (n1 && n2 && end1 != end2 && depth < 4) {
      const T mid = (ua + ub) / 2;
      return integrate_rsing(f, L1, L2, st, ua, mid, depth + 1) + integrate_rsing(f, L1, L2, st, mid, ub, depth + 1);
    }
    const bool far = r1 > 8 && r2 > 8;  // both factors far from vanishing: half the nodes do
    const auto rule = gauss_legendre<T>(far ? (opt_.order + 1) / 2 : opt_.order * ((n1 && n2) ? 2 : 1));
    if (!n1 && !n2) {
      T sum = 0;
      const T hw = (ub - ua) / 2, mid = (ua + ub) / 2;
      for (size_t j = 0; j < rule->x.size(); ++j) sum += rule->w[j] * f(mid + hw * rule->x[j]);
      return sum * hw;
    }
    // the factor to remove: the nearer one
    const bool use1 = n1 && (!n2 || r1 <= r2);
    const int end = use1 ? end1 : end2;
    const T ue = end > 0 ? ub : ua;
    auto Lv = [&](const T &u) { return use1 ? L1(u) : L2(u); };
    auto Ld = [&](const T &u) { return use1 ? st.e1.der(u) : -T(0) + st.e2.der(u); };
    // root u* outward of ue: Newton on L from ue. The root only centres the
    // substitution below (u = us -+ v^2 is exact for any us outward of the
    // interval; at the root it also makes the integrand smooth), so the
    // iteration limit is not an error: the last iterate is a valid centre.
    // (It is reached in tests/test_history.cpp, proportional ray sigma = 3Q:
    // checking it as a failure broke that test.)
    T us = ue;
    T lv = Lv(ue);
    if (lv > 0) {
      for (int it = 0; it < 40; ++it) {
        const T d = Ld(us);
        if (d == 0) break;
        const T stp = Lv(us) / d;  // L' has the sign that makes L grow into the interval
        const T nu = us - stp;
        if ((end > 0 && !(nu >= ue)) || (end < 0 && !(nu <= ue))) break;
        if (abs(nu - us) <= 4 * eps<T>() * (1 + abs(us))) {
          us = nu;
          break;
        }
        us = nu;
      }
    }
    T sum = 0;
    if (end > 0) {  // u = us - v^2
      const T vlo = sqrt(std::max(T(0), us - ub)), vhi = sqrt(us - ua);
      const T hw = (vhi - vlo) / 2, mid = (vhi + vlo) / 2;
      for (size_t j = 0; j < rule->x.size(); ++j) {
        const T v = mid + hw * rule->x[j];
        sum += rule->w[j] * 2 * v * f(us - v * v);
      }
      return sum * hw;
    }
    const T vlo = sqrt(std::max(T(0), ua - us)), vhi = sqrt(ub - us);
    const T hw = (vhi - vlo) / 2, mid = (vhi + vlo) / 2;
    for (size_t j = 0; j < rule->x.size(); ++j) {
      const T v = mid + hw * rule->x[j];
      sum += rule->w[j] * 2 * v * f(us + v * v);
    }
    return sum * hw;
  }

  // A step whose length is set by how far advancing end i moves: end i is held at
  // bt and the fraction of the segment is the root in (0, frac_max] of its
  // continuity residual (toms748 on a bracket). Where the end runs fast through
  // a region whose traction is already close to the friction limit (the memory
  // of an earlier zone of the same direction) the residual hardly depends on
  // the end's position, so the usual step (fraction given, ends solved for)
  // cannot converge, while the residual as a function of the load is regular.
  bool end_driven_step(const T &dq, const T &ds, int i, const T &bt, const T &frac_max, history_step<T> &out) const {
    using std::abs;
    const int si = i == 1 ? s1_ : s2_;
    auto G = [&](const T &w, history_step<T> *keep) -> T {
      const history_step<T> st = take_step(dq, ds, w, i, bt);
      if (keep) *keep = st;
      return T(si) * residual_end(i, st);
    };
    try {
      T lo = frac_max * T(1e-12), hi = frac_max;
      T glo = G(lo, nullptr);
      if (!(glo < 0)) return false;  // the end is already at the limit there: a jump, not a step
      T ghi = G(hi, nullptr);
      if (!(ghi > 0)) {
        // G(w) is the residual of a step that moves the end to bt over the fraction w: a
        // w much longer than the end needs gives an unnaturally slow end, whose residual
        // can have the sign of "not reached" again. Look for the earliest w at which the
        // end is past bt on a grid (the first sign change from below brackets it).
        bool found = false;
        T wprev = lo;
        for (int k = 1; k <= 16 && !found; ++k) {
          const T w = frac_max * T(k) / 16;
          if (w >= hi) break;
          const T gw = G(w, nullptr);
          if (gw > 0) {
            lo = wprev;
            glo = G(lo, nullptr);
            hi = w;
            ghi = gw;
            found = glo < 0;
          } else wprev = w;
        }
        if (!found) return false;  // the end does not reach bt within frac_max
      }
      std::uintmax_t it = 40;
      auto tol = [](const T &a, const T &b) { return abs(b - a) <= 4 * eps<T>() * abs(b); };
      auto r = boost::math::tools::toms748_solve([&](const T &w) { return G(w, nullptr); }, lo, hi, glo, ghi, tol,
                                                 it);
      if (it >= 40) return false;
      const T w = r.second;  // the side past the root: s_i F >= 0
      G(w, &out);
      // G need not be monotone in w: a root past the one the end reaches first leaves the stick
      // traction just inside the end past the friction limit (a step too long for its move; on
      // a Q cycle at sigma/fp0 = 0.5 the landing step on a memory point was 16 times too long,
      // the traction inside 19 % past the limit, and the vertex 3.9e-4 a off). Then the
      // earliest sign change on a geometric grid below w is taken, if there is one.
      if (past_limit_inside(i, out, abs(bt - (i == 1 ? b1_ : b2_)))) {
        T wp = lo, gp = glo;
        for (int k = 12; k >= 1; --k) {
          const T wk = std::ldexp(w, -k);
          if (!(wk > wp)) continue;
          const T gk = G(wk, nullptr);
          if (gk > 0) {
            std::uintmax_t it2 = 40;
            auto r2 = boost::math::tools::toms748_solve([&](const T &v) { return G(v, nullptr); }, wp, wk, gp, gk,
                                                        tol, it2);
            if (it2 < 40) G(r2.second, &out);
            else G(w, &out);
            break;
          }
          wp = wk;
          gp = gk;
        }
      }
      return true;
    } catch (const error &err) {
      if (err.code() != status::no_convergence) throw;
      return false;
    }
  }

  bool try_step(const T &dq, const T &ds, const T &frac, history_step<T> &out) const {
    try {
      out = take_step(dq, ds, frac);
      return true;
    } catch (const error &err) {
      if (err.code() != status::no_convergence) throw;
      return false;
    }
  }

  // ---- one step -----------------------------------------------------------
  T residual_end(int i, const history_step<T> &st) const {
    const T x = i == 1 ? st.e1.bb : -st.e2.bb;
    const int si = i == 1 ? st.s1 : st.s2;
    return stick_traction(x, steps_.size(), &st) - T(si) * pm_->p(x);
  }

  // One step to fraction `frac` of the segment. pin = 1 or 2 holds that advancing
  // end at pin_b instead of solving for it (see end_driven_step).
  history_step<T> take_step(const T &dq, const T &ds, const T &frac, int pin = 0, const T &pin_b = T(0)) const {
    using std::abs;
    using std::max;
    using std::min;
    using std::sqrt;
    const bool a1 = m1_ == adv && pin != 1, a2 = m2_ == adv && pin != 2;
    auto ends = [&](const T &z1, const T &z2, T &b1n, T &b2n) {
      b1n = pin == 1 ? pin_b : a1 ? z1 : (m1_ == edge ? b1_ : T(0));
      b2n = pin == 2 ? pin_b : a2 ? z2 : (m2_ == edge ? b2_ : T(0));
      if (m1_ == rec) b1n = 2 * estar_ - b2n;
      if (m2_ == rec) b2n = 2 * estar_ - b1n;
    };
    // starting guess: extrapolation within the run, else a small zone
    T g1 = b1_, g2 = b2_;
    const T len = max(abs(dq), abs(ds) / 4) * frac;
    if (steps_.size() > run_start_) {
      const auto &p = steps_.back();
      const T r = frac * max(abs(dq), abs(ds) / 4) / max(abs(p.dq), abs(p.ds) / 4);
      g1 = b1_ + (b1_ - p.b1a) * r;
      g2 = b2_ + (b2_ - p.b2a) * r;
    } else {
      g1 = b1_ - len / 4;
      g2 = b2_ - len / 4;
    }
    const T w0 = b1_ + b2_;
    auto clampz = [&](T &z, const T &b) {
      if (!(z < b)) z = b - (b + T(1)) * T(1e-3) * len - eps<T>();
    };
    T z1 = g1, z2 = g2;
    if (a1) clampz(z1, b1_);
    if (a2) clampz(z2, b2_);
    const int n = int(a1) + int(a2);
    T b1n, b2n;
    ends(z1, z2, b1n, b2n);
    if (n == 0) return make_step(dq, ds, frac, b1n, b2n);
    auto resid = [&](const T &y1, const T &y2, T &f1, T &f2, bool strict = true) -> bool {
      if (++work_ > work_budget_)
        throw error(status::no_convergence,
                    "history: the march of a segment makes no progress (residual evaluations without end)");
      T c1, c2;
      ends(y1, y2, c1, c2);
      if (!strict && c1 + c2 > 0 && c1 < 1 + T(1e-3) && c2 < 1 + T(1e-3)) {
        const history_step<T> st = make_step(dq, ds, frac, c1, c2);
        if (a1) f1 = residual_end(1, st);
        if (a2) f2 = residual_end(2, st);
        return true;
      }
      // an advancing end moves inwards (outwards the continuity condition holds
      // trivially: the receding case, decided by r_i instead)
      // (a receding end may pass the contact edge within a trial step: the event
      // search then finds where it reaches it)
      const T lim1 = m1_ == rec ? T(1) + T(1) / 64 : T(1), lim2 = m2_ == rec ? T(1) + T(1) / 64 : T(1);
      if (!(c1 + c2 > 0) || !(c1 <= lim1) || !(c2 <= lim2) || (a1 && !(c1 <= b1_)) || (a2 && !(c2 <= b2_)))
        return false;
      const history_step<T> st = make_step(dq, ds, frac, c1, c2);
      if (a1) f1 = residual_end(1, st);
      if (a2) f2 = residual_end(2, st);
      return true;
    };
    T f1 = 0, f2 = 0;
    if (!resid(z1, z2, f1, f2)) {
      bool found = false;
      for (T tiny = T(1e-3); tiny > T(1e-14) && !found; tiny /= 32) {
        z1 = a1 ? b1_ - w0 * tiny : z1;
        z2 = a2 ? b2_ - w0 * tiny : z2;
        found = resid(z1, z2, f1, f2);
      }
      if (!found) throw error(status::no_convergence, "history: no valid start for a step");
    }
    const T tol = 16 * eps<T>();
    // The Jacobian of the previous step of the run (same length, same modes)
    // serves as long as it contracts the residual (chord iterations).
    const bool reuse = jac_.valid && jac_.run == run_start_ && jac_.len == frac && jac_.a1 == a1 && jac_.a2 == a2;
    T j11 = 1, j12 = 0, j21 = 0, j22 = 1;
    bool fresh = !reuse;
    if (reuse) {
      j11 = jac_.j[0];
      j12 = jac_.j[1];
      j21 = jac_.j[2];
      j22 = jac_.j[3];
    }
    T prev_fn = -1;
    int stall = 0;
    for (int it = 0; it < opt_.max_newton; ++it) {
      const T fn = max(abs(f1), abs(f2));
      if (!fresh && prev_fn >= 0 && fn > prev_fn / 8) fresh = true;  // chord too slow: new Jacobian
      prev_fn = fn;
      // Jacobian by differences (one-sided, inwards)
      const T hz = sqrt(eps<T>()) * max(w0, T(1e-300));
      T g1a = 0, g2a = 0;
      if (fresh && a1) {
        if (!resid(z1 - hz, z2, g1a, g2a, false)) throw error(status::no_convergence, "history: step Jacobian");
        j11 = (f1 - g1a) / hz;
        j21 = a2 ? (f2 - g2a) / hz : T(0);
      }
      if (fresh && a2) {
        T h1 = 0, h2 = 0;
        if (!resid(z1, z2 - hz, h1, h2, false)) throw error(status::no_convergence, "history: step Jacobian");
        j22 = (f2 - h2) / hz;
        j12 = a1 ? (f1 - h1) / hz : T(0);
      }
      if (fresh) {
        jac_.valid = true;
        jac_.run = run_start_;
        jac_.len = frac;
        jac_.a1 = a1;
        jac_.a2 = a2;
        jac_.j[0] = j11;
        jac_.j[1] = j12;
        jac_.j[2] = j21;
        jac_.j[3] = j22;
      }
      const bool was_fresh = fresh;
      fresh = false;
      T d1 = 0, d2 = 0;
      if (a1 && a2) {
        const auto x = solve2x2(j11, j12, j21, j22, f1, f2);
        d1 = x.x1;
        d2 = x.x2;
      } else if (a1) {
        d1 = f1 / j11;
      } else {
        d2 = f2 / j22;
      }
      T lam = 1;
      bool ok = false;
      T n1 = 0, n2 = 0, nf1 = 0, nf2 = 0;
      for (int ls = 0; ls < 40; ++ls) {
        n1 = z1 - lam * d1;
        n2 = z2 - lam * d2;
        if (resid(n1, n2, nf1, nf2) && max(abs(nf1), abs(nf2)) < (1 - lam / 4) * fn + tol) {
          ok = true;
          break;
        }
        lam /= 2;
      }
#ifdef HS_HISTORY_DEBUG
      fprintf(stderr, "it %d z %.17g %.17g f %.3e %.3e d %.3e %.3e J %.3e %.3e %.3e %.3e ok %d\n", it, double(z1),
              double(z2), double(f1), double(f2), double(d1), double(d2), double(j11), double(j12), double(j21),
              double(j22), int(ok));
#endif
      if (!ok && !was_fresh) {  // the old Jacobian failed: retry with a new one
        fresh = true;
        prev_fn = -1;
        continue;
      }
      if (!ok) {
        if ((!a1 || abs(f1) <= 256 * eps<T>() * (1 + abs(j11 * z1))) &&
            (!a2 || abs(f2) <= 256 * eps<T>() * (1 + abs(j22 * z2))))
          break;  // at the rounding floor
        throw error(status::no_convergence, "history: the stick-zone ends of a step did not converge");
      }
      const T dz = max(abs(z1 - n1), abs(z2 - n2));
      // a residual that changes sign with little decrease has a kink at the root
      // (the new end at an earlier end position, where the traction has a square-root
      // cusp): the slope across the bracket replaces the one-sided slope (secant)
      if (a1 && n1 != z1 && sgn(nf1) * sgn(f1) < 0 && abs(nf1) > abs(f1) / 8) {
        j11 = (f1 - nf1) / (z1 - n1);
        fresh = false;
        prev_fn = -1;
      }
      if (a2 && n2 != z2 && sgn(nf2) * sgn(f2) < 0 && abs(nf2) > abs(f2) / 8) {
        j22 = (f2 - nf2) / (z2 - n2);
        fresh = false;
        prev_fn = -1;
      }
      z1 = n1;
      z2 = n2;
      f1 = nf1;
      f2 = nf2;
      // at the rounding floor: |F_i| within a few ulps of z_i times dF_i/dz_i
      const bool c1 = !a1 || abs(f1) <= 64 * eps<T>() * (1 + abs(j11 * z1));
      const bool c2 = !a2 || abs(f2) <= 64 * eps<T>() * (1 + abs(j22 * z2));
      if (dz <= 4 * eps<T>() * max(w0, T(1e-300)) || max(abs(f1), abs(f2)) <= tol || (c1 && c2)) break;
      // stagnation (a residual flat in an end: the end against a region at the
      // friction limit): give up early, the march reacts (add_vertex)
      const T fnew = max(abs(f1), abs(f2));
      stall = fnew > T(0.99) * fn ? stall + 1 : 0;
      if (stall >= 8) throw error(status::no_convergence, "history: the stick-zone ends of a step stagnate");
      if (it + 1 == opt_.max_newton)
        throw error(status::no_convergence, "history: Newton iteration limit for a step reached");
    }
    ends(z1, z2, b1n, b2n);
    return make_step(dq, ds, frac, b1n, b2n);
  }

  // ---- events ---------------------------------------------------------------
  // 1/2: advancing end i reaches r_i = 0; 3/4: receding end i reaches the edge
  // 5/6: the stick zone next to advancing end i reaches the friction limit
  // (a loop of the path closes: the slip of an earlier zone of the same
  // direction resumes at once, and the end jumps inwards; Masing's memory rule).
  int event_in(const history_step<T> &st) const {
    const T e = (st.e1.bb + st.e2.bb) / 2;
    if (m1_ == adv && T(s1_) * r(1, st.dq, st.ds, e) <= 0) return 1;
    if (m2_ == adv && T(s2_) * r(2, st.dq, st.ds, e) <= 0) return 2;
    if (m1_ == rec && st.e1.bb >= 1) return 3;
    if (m2_ == rec && st.e2.bb >= 1) return 4;
    // 7/8: an end stuck at the contact edge whose rate coefficient r_i turns non-zero: a zone opens
    {
      const T e0 = (b1_ + b2_) / 2;
      using std::abs;
      const T small = 64 * eps<T>() * (abs(st.dq) + abs(st.ds));
      auto turns = [&](int i) {  // r_i non-zero at the end, zero (to rounding) or of the other sign at the start
        const T re = r(i, st.dq, st.ds, e), rs = r(i, st.dq, st.ds, e0);
        return abs(re) > small && (abs(rs) <= small || sgn(re) != sgn(rs));
      };
      if (m1_ == edge && turns(1)) {
        open_sign_ = sgn(r(1, st.dq, st.ds, e));
        return 7;
      }
      if (m2_ == edge && turns(2)) {
        open_sign_ = sgn(r(2, st.dq, st.ds, e));
        return 8;
      }
    }
    if (noop_erase_ < 3 && m1_ == adv && limit_margin(1, &st) > limit_tol()) return 5;
    if (noop_erase_ < 3 && m2_ == adv && limit_margin(2, &st) > limit_tol()) return 6;
    // 9/10: advancing end i reaches a memory point of the stick zone (an earlier end
    // position still remembered by the traction). There the traction has a
    // square-root cusp, so the end is not smooth in the load across it: the run
    // restarts at the crossing and its interpolation never straddles the cusp.
    if (m1_ == adv || m2_ == adv) {
      update_memory_targets();
      if (m1_ == adv && mem1_ok_ && st.e1.bb < mem1_) return 9;
      if (m2_ == adv && mem2_ok_ && -st.e2.bb > mem2_) return 10;
    }
    return 0;
  }
  // the nearest memory point inwards of each end of the current stick zone
  // (recomputed once per run: memory_points costs O(steps))
  void update_memory_targets() const {
    if (mem_run_ == run_start_) return;
    mem_run_ = run_start_;
    mem1_ok_ = mem2_ok_ = false;
    if (steps_.empty()) return;
    const T w = b1_ + b2_;
    // a point this close to an end is the end itself: memory points closer than 1e-4 of
    // the largest step's move come in clusters (a cycle returning to nearly the same ends)
    // and landing on each costs an end-driven step for nothing (the cusps merge)
    using std::max;
    const T gap = max(w * T(1e-9), opt_.max_step * T(1e-4));
    for (const T &x : memory_points(steps_.size())) {
      if (x == mem_skip1_ || x == mem_skip2_) continue;
      if (x < b1_ - gap && x > -b2_ + gap) {
        if (!mem1_ok_ || x > mem1_) mem1_ = x;
        if (!mem2_ok_ || x < mem2_) mem2_ = x;
        mem1_ok_ = mem2_ok_ = true;
      }
    }
  }
  static T limit_tol() {
    using std::sqrt;
    return sqrt(eps<T>()) * 64;
  }
  // v(x) = s_i q(x)/p(x) - 1 at a stuck point (<= 0 where the stick condition holds)
  T limit_ratio(int i, const T &x, const history_step<T> *st) const {
    const int si = i == 1 ? s1_ : s2_;
    const T p = pm_->p(x);
    if (!(p > 0)) return T(-1);
    return T(si) * stick_traction(x, steps_.size(), st) / p - 1;
  }
  // Largest v over sample points of the stick zone, quadratically spaced from end i
  // inwards over 3/4 of it (near the other end, with the same direction, q tends to
  // s p from below). Positive: the friction limit is passed inside the stick zone,
  // next to the end (a closed loop: Masing's memory rule) or further in (an
  // interior slip patch); erase_at_limit then moves the end.
  T limit_margin(int i, const history_step<T> *st) const {
    const T b1 = st ? st->e1.bb : b1_, b2 = st ? st->e2.bb : b2_;
    const T L = b1 + b2;
    const int M = 8;
    T worst = -1;
    for (int k = 1; k <= M; ++k) {
      const T d = L * T(k * k) / T(M * M) * T(0.75);
      const T x = i == 1 ? b1 - d : -b2 + d;
      const T v = limit_ratio(i, x, st);
      if (v > worst) worst = v;
    }
    return worst;
  }
  // The stick traction just inside advancing end i of step t past the friction limit (the
  // end's root is spurious: the end belongs further in), sampled at move/4 and move (the end's
  // move in the step) and 1e-3, 4e-3 of the stick zone in from the end.
  bool past_limit_inside(int i, const history_step<T> &t, const T &move) const {
    const T b = i == 1 ? t.e1.bb : t.e2.bb, L = t.e1.bb + t.e2.bb;
    for (const T &d : {move / 4, move, L / 1000, L / 250}) {
      if (!(d > 0) || !(d < L / 2)) continue;
      if (limit_ratio(i, i == 1 ? b - d : -(b - d), &t) > limit_tol()) return true;
    }
    return false;
  }
  // A step whose advancing end i stops short of its memory point while the stick traction
  // between the point and the new end is past the friction limit: the continuity residual
  // had a spurious root there, and the end belongs at (or past) the point. Found where an
  // end runs fast through the memory of an earlier zone of the same direction and that
  // region ends at the point (the end of the earlier zone): the end stalled up to twice its
  // own move short of the point with the traction just inside it 3e-3 past the limit, and
  // later steps kept the lag (5e-4 a and 4e-3 of the energy on bench_history's periodic
  // loadings at sigma_m = 1.5, against the static solves and the BEM; docs/history.md).
  // limit_margin() samples from 1 % of the stick zone in from the end, and a band this
  // thin falls between its points: here the band between the end and the point is sampled,
  // quadratically spaced from the end (b - gap k^2/16, k = 1..3), within 3/4 of the stick zone
  // from the end as in limit_margin() (near the other end, slipping the same way, q tends to
  // s p from below). Not at the point itself: where it is the end of an earlier zone of the
  // same direction the traction there is at the limit to the march's error (1.2e-6 past it at
  // the other end's earlier position made a Q_a 0.6, sigma_a 1 loading stagnate).
  bool stalls_short(const history_step<T> &t, int i) const {
    const mode mi = i == 1 ? m1_ : m2_;
    const bool ok = i == 1 ? mem1_ok_ : mem2_ok_;
    if (mi != adv || !ok) return false;
    const T m = i == 1 ? mem1_ : -mem2_;  // the point as a value of end i
    const T bn = i == 1 ? t.e1.bb : t.e2.bb;
    const T gap = bn - m, L = t.e1.bb + t.e2.bb;
    if (!(gap > 0)) return false;
    for (int k = 1; k <= 3; ++k) {
      const T b = bn - gap * T(k * k) / 16;
      if (!(bn - b <= T(0.75) * L)) break;
      if (limit_ratio(i, i == 1 ? b : -b, &t) > limit_tol()) return true;
    }
    return false;
  }
  // Jump end i inwards over the contiguous region next to it that is at the friction limit.
  // near > 0: a step cannot converge because the region next to the end is within
  // `near` of the limit (a degenerate Masing return): sweep the region within it.
  bool erase_at_limit(int i, const T &near = T(0)) {
    using std::abs;
    const T b1 = b1_, b2 = b2_, L = b1 + b2;
    const int M = 8;
    const T below = near > 0 ? -near : -limit_tol();  // inside the friction cone
    auto xat = [&](const T &d) { return i == 1 ? b1 - d : -b2 + d; };
    T d_in = 0, d_out = -1;
    if (near > 0) {
      // only a region that starts at the end: bracket its inner edge by doubling
      const T d1 = L * T(1) / T(M * M) * T(0.75) / 64;
      if (!(limit_ratio(i, xat(d1), nullptr) >= below)) return false;
      d_in = d1;
      // doubling within 3/4 of the stick zone (beyond, near the other end, q tends to s p
      // when both zones slip the same way, which is not the limit of this end's region)
      for (;;) {
        const T dn = 2 * d_in;
        if (dn >= T(0.75) * L) {
          if (limit_ratio(i, xat(T(0.75) * L), nullptr) >= below)
            throw error(status::no_convergence, "history: the whole stick zone reached the friction limit");
          d_out = T(0.75) * L;
          break;
        }
        if (!(limit_ratio(i, xat(dn), nullptr) >= below)) {
          d_out = dn;
          break;
        }
        d_in = dn;
      }
    } else {
      if (!(limit_margin(i, nullptr) > limit_tol() / 2)) {  // located short of the limit: nothing to do
        ++noop_erase_;
        return false;
      }
      // the contiguous region at the limit next to the end; if the limit is reached
      // only further in (an interior slip patch), the band between is merged with
      // the zone: the patch and the band slip together (counted in interior_merges)
      bool at_end = true;
      for (int k = 1; k <= M; ++k) {
        const T d = L * T(k * k) / T(M * M) * T(0.75);
        const T v = limit_ratio(i, xat(d), nullptr);
        if (v >= below) {
          d_in = d;
          continue;
        }
        if (d_in == 0 && at_end) {
          at_end = false;
          // look further in for the patch
          bool patch = false;
          for (int j = k + 1; j <= M; ++j) {
            const T dj = L * T(j * j) / T(M * M) * T(0.75);
            if (limit_ratio(i, xat(dj), nullptr) >= below) {
              patch = true;
              d_in = dj;
              k = j;
              break;
            }
          }
          if (!patch) break;
          if (!opt_.merge_interior_patches)
            throw error(status::not_applicable,
                        hdetail::interior_patch_message);
          ++interior_merges_;
          continue;
        }
        d_out = d;
        break;
      }
      if (d_in == 0) {
        ++noop_erase_;
        return false;
      }
      if (d_out < 0) throw error(status::no_convergence, "history: the whole stick zone reached the friction limit");
    }
    for (int it = 0; it < 200 && d_out - d_in > 4 * eps<T>() * (1 + L); ++it) {
      const T m = (d_in + d_out) / 2;
      if (limit_ratio(i, xat(m), nullptr) >= below) d_in = m;
      else d_out = m;
    }
    if (!(d_out - d_in <= 4 * eps<T>() * (1 + L)))
      throw error(status::no_convergence, "history: friction-limit bisection ran out");
    if (i == 1) jump(b1 - d_in, b2_);
    else jump(b1_, b2 - d_in);
    return true;
  }
  T event_value(int ev, const history_step<T> *st, const T &dq, const T &ds, const T &) const {
    const T b1 = st ? st->e1.bb : b1_, b2 = st ? st->e2.bb : b2_;
    const T e = (b1 + b2) / 2;
    switch (ev) {
      case 1: return T(s1_) * r(1, dq, ds, e);
      case 2: return T(s2_) * r(2, dq, ds, e);
      case 3: return 1 - b1;
      case 4: return 1 - b2;
      case 5: return limit_tol() - limit_margin(1, st);
      case 6: return limit_tol() - limit_margin(2, st);
      case 9: return b1 - mem1_;
      case 10: return b2 + mem2_;
      case 7: return -T(open_sign_) * r(1, dq, ds, e);  // > 0 before r_1 takes the sign of the opening
      default: return -T(open_sign_) * r(2, dq, ds, e);
    }
  }
  void apply_event_limit(int ev, history_step<T> &st) const {
    if (ev == 3 && st.e1.bb > 1) st.e1.bb = 1;
    if (ev == 4 && st.e2.bb > 1) st.e2.bb = 1;
  }
  void after_event(int ev) {
    if (ev == 3 && b1_ >= 1 - 16 * eps<T>()) {
      s1_ = 0;
      m1_ = edge;
      b1_ = 1;
    }
    if (ev == 4 && b2_ >= 1 - 16 * eps<T>()) {
      s2_ = 0;
      m2_ = edge;
      b2_ = 1;
    }
    if (ev == 5) erase_at_limit(1);
    if (ev == 6) erase_at_limit(2);
    if (ev == 7 && m1_ == edge) {
      s1_ = open_sign_;
      m1_ = adv;
    }
    if (ev == 8 && m2_ == edge) {
      s2_ = open_sign_;
      m2_ = adv;
    }
  }

  // ---- commit: energies ----------------------------------------------------
  void commit(history_step<T> &st, const T &dq, const T &ds, const T &frac) {
    (void)dq;
    (void)ds;
    (void)frac;
    if (steps_.size() >= size_t(opt_.max_steps))
      throw error(status::no_convergence, "history: step limit reached (history_options::max_steps)");
    step_energy(st);
    // the slip rate grows like log(1/e) as the stick zone closes; where its interpolated
    // half-width reaches zero within a step (gross sliding at hand) the energies are not
    // defined: a status, never a NaN (found by fuzz_history at Q/fP = -0.95, sigma/fp0 = -2.5)
    {
      using boost::math::isfinite;
      if (!isfinite(st.E1) || !isfinite(st.E2))
        throw error(status::no_convergence,
                    "history: the stick zone closes within a step (gross sliding is near): energies undefined");
    }
    st.run_start = steps_.size() == run_start_;
    steps_.push_back(st);
    b1_ = st.e1.bb;
    b2_ = st.e2.bb;
  }

  // slip rate (per unit u) in zone z (+1 right of the stick zone, -1 left) at x
  static T hdot(int z, const T &A, const T &B, const T &c, const T &e, const T &x) {
    return hist_hdot(z, A, B, c, e, x);
  }

  // dissipation over the step: int_0^1 du int_zone s_i p hdot dx
  void step_energy(history_step<T> &st) const {
    using std::cos;
    using std::sin;
    using std::sqrt;
    st.E1 = st.E2 = st.R1 = st.R2 = 0;
    if (st.dq == 0 && st.ds == 0) return;
    const auto ru = gauss_legendre<T>(opt_.order);
    const T A = st.dq / 2, B = st.ds / 4;
    for (size_t j = 0; j < ru->x.size(); ++j) {
      const T u = (1 + ru->x[j]) / 2, wu = ru->w[j] / 2;
      const T b1 = st.b1(u), b2 = st.b2(u);
      const T c = (b1 - b2) / 2, e = (b1 + b2) / 2;
      if (st.s1 != 0 && b1 < 1) {
        st.E1 += wu * T(st.s1) * zone_rate(+1, A, B, c, e, b1, T(1));
        st.R1 += wu * back_rate(+1, st.s1, A, B, c, e, b1, T(1));
      }
      if (st.s2 != 0 && b2 < 1) {
        st.E2 += wu * T(st.s2) * zone_rate(-1, A, B, c, e, T(-1), -b2);
        st.R2 += wu * back_rate(-1, st.s2, A, B, c, e, T(-1), -b2);
      }
    }
    // The slip rate has the sign of r_i at the stick end and changes sign at most once
    // along the zone (a sum of two monotone terms). Where it changes, the part near the
    // contact edge would slip back: a zone of the other direction opens there (a zone
    // structure the march does not model; near a Hertz edge p is small and so is the
    // error). A zone whose net dissipation over the step is clearly negative is past
    // that: a status, never a negative energy. "Clearly": beyond 1 % of the step's total
    // and beyond 5 % of the step's load scale |dQ/2| + |dsigma/4| (a step dissipates at
    // most about that, f p times a slip of that order over a zone shorter than a): found
    // by fuzz_history, flat punch, Q/fP = -0.95, sigma/fp0 = -2.4, -8.4e-4 = 23 % of the
    // scale; the r_i = 0 events of bench_history's periodic loadings leave up to 0.4 %
    // (-2.6e-9 in steps of 1.5e-5), a zone about to stop slipping back within the step.
    using std::abs;
    using std::max;
    const T floor = max((abs(st.E1) + abs(st.E2)) / 100, (abs(A) + abs(B)) / 20);
    if (st.E1 < -floor || st.E2 < -floor)
      throw error(status::no_convergence,
                  "history: a slip zone dissipates a negative energy over a step: part of it would slip back "
                  "(more zones than the march models)");
  }
  // The dissipation rate of the part of zone z (on [lo, hi], direction sz) next to the
  // contact edge that slips back against sz, as a positive number (0 if none). The slip
  // rate changes sign at most once along the zone (above), so that part is (x*, edge) with
  // x* its one root, found by bisection to 2^-40 of the zone (an indicator, not a result).
  T back_rate(int z, int sz, const T &A, const T &B, const T &c, const T &e, const T &lo, const T &hi) const {
    using std::abs;
    const T edge = z > 0 ? hi : lo, end = z > 0 ? lo : hi;
    if (!(T(sz) * hdot(z, A, B, c, e, edge) < 0)) return T(0);
    T in = end, out = edge;  // sz hdot >= 0 at in (or in = the stick end), < 0 at out
    for (int it = 0; it < 40; ++it) {
      const T m = (in + out) / 2;
      if (T(sz) * hdot(z, A, B, c, e, m) < 0) out = m;
      else in = m;
    }
    const T r = z > 0 ? zone_rate(z, A, B, c, e, in, hi) : zone_rate(z, A, B, c, e, lo, in);
    return abs(r);
  }
  // int_lo^hi p(x) hdot(x) dx over a slip zone (core/history_rates.hpp)
  T zone_rate(int z, const T &A, const T &B, const T &c, const T &e, const T &lo, const T &hi) const {
    return hist_zone_rate(*pm_, opt_.order * 2, z, A, B, c, e, lo, hi);
  }

  // slip accumulated at x over one step
  T step_slip(const history_step<T> &st, const T &x) const {
    using std::sqrt;
    if (st.dq == 0 && st.ds == 0) return T(0);
    const T A = st.dq / 2, B = st.ds / 4;
    T h = 0;
    for (int z = -1; z <= 1; z += 2) {
      const int sz = z > 0 ? st.s1 : st.s2;
      if (sz == 0) continue;
      // g(u) = distance of x into the zone; the zone holds x where g > 0
      auto g = [&](const T &u) { return z > 0 ? x - st.b1(u) : -st.b2(u) - x; };
      const T g0 = g(T(0)), g1 = g(T(1));
      if (!(g0 > 0) && !(g1 > 0)) {
        // a zone could still pass over x within the step; check the middle
        if (!(g(T(0.5)) > 0)) continue;
      }
      // sub-interval where g > 0: find crossings by bisection
      auto cross = [&](T lo, T hi) {  // g(lo) and g(hi) of opposite signs
        const bool plo = g(lo) > 0;
        for (int it = 0; it < 200 && hi - lo > 4 * eps<T>(); ++it) {
          const T m = (lo + hi) / 2;
          if ((g(m) > 0) == plo) lo = m;
          else hi = m;
        }
        if (!(hi - lo <= 4 * eps<T>())) throw error(status::no_convergence, "history: crossing bisection ran out");
        return (lo + hi) / 2;
      };
      T ua = 0, ub = 1;
      const bool in0 = g0 > 0, in1 = g1 > 0;
      if (!in0 && in1) ua = cross(T(0), T(1));
      else if (in0 && !in1) ub = cross(T(0), T(1));
      else if (!in0 && !in1) {
        ua = cross(T(0), T(0.5));
        ub = cross(T(0.5), T(1));
      }
      auto rate = [&](const T &u) {
        const T b1 = st.b1(u), b2 = st.b2(u);
        return hdot(z, A, B, (b1 - b2) / 2, (b1 + b2) / 2, x);
      };
      // hdot ~ sqrt(g) at a crossing: u = end + (other - end) w^2 at each crossing end
      const auto rule = gauss_legendre<T>(opt_.order);
      const bool sa = ua > 0, sb = ub < 1;
      const T mid = (ua + ub) / 2;
      auto piece = [&](const T &from, const T &to, bool sing_from) {
        T s = 0;
        for (size_t j = 0; j < rule->x.size(); ++j) {
          const T w = (1 + rule->x[j]) / 2, ww = rule->w[j] / 2;
          if (sing_from) s += ww * 2 * w * (to - from) * rate(from + (to - from) * w * w);
          else s += ww * (to - from) * rate(from + (to - from) * w);
        }
        return s;
      };
      if (sa || sb) h += piece(ua, mid, sa) - piece(ub, mid, sb);
      else h += piece(ua, ub, false);
    }
    return h;
  }
};

enum class ramp_order { sigma_first = 0, together = 1, q_first = 2 };

template <class T> struct cycle_result {
  int cycles = 0;
  int cycles_to_steady = -1;                        // first cycle that the next repeats; -1: not reached
  // cycles taken as copies of the last one solved (a history whose adapter repeats cycles, below):
  // how many, and the state's change over that cycle they are copies of (0: none)
  int cycles_repeated = 0;
  T repeated_change{0};
  bool shakedown = false;                           // the last cycle dissipates nothing
  T energy1{0}, energy2{0};                         // over the last cycle
  T energyp{0};                                     // ... in interior slip zones
  size_t last_cycle_first = 0, last_cycle_end = 0;  // vertex range [first - 1, end) of the last cycle
};

// The arguments of add_cycles, checked before any vertex is added (the C ABI checks
// them before it tries a method, so that a bad argument leaves the history as it was)
template <class T>
void check_cycles(const T &qm, const T &qa, const T &sm, const T &sa, const T &phase_deg, int cycles, int segments) {
  using boost::math::isfinite;
  using std::abs;
  if (!isfinite(qm) || !isfinite(qa) || !isfinite(sm) || !isfinite(sa) || !isfinite(phase_deg))
    throw error(status::not_finite, "cycles: a parameter is not finite");
  if (cycles < 1 || cycles > 100000) throw error(status::bad_option, "cycles: need 1 <= cycles <= 100000");
  if (segments < 4 || segments > 100000)
    throw error(status::bad_option, "cycles: segments per cycle out of 4..100000");
  if (!(abs(qm) + abs(qa) < 1)) throw error(status::gross_sliding, "cycles: |Qm| + |Qa| >= fP: gross sliding");
}

namespace hdetail {
// A history that can repeat a cycle (add_cycles): cycle_change(first), the change of its state over
// the cycle whose vertices start at index first (-1: not comparable, or no point stays stuck
// through it), state_accuracy(), refused(exception_ptr) (an exception of add_vertex that is the
// history's refusal of a segment, not an error), truncate(n) and repeat_cycle(first, end, cycle, extra)
template <class H, class = void> struct repeats_cycles : std::false_type {};
template <class H> struct repeats_cycles<H, std::void_t<decltype(std::declval<H &>().cycle_change(std::size_t(0)))>>
    : std::true_type {};
}  // namespace hdetail

// Periodic loading q(t) = qm + qa sin(wt), s(t) = sm + sa sin(wt + phase),
// reached from the current state (ramp order), then `cycles` cycles. A cycle
// that traces a straight line (in phase, or one amplitude zero) is marched
// through its turning points exactly; otherwise by `segments` chords.
// H: history<T> or refined_history<T> (add_vertex, vertices, tag_last_vertex, q, s).
//
// The steady cycle (issue 14). At constant normal load the friction limit f p(x) does not change
// with time: the contact is a Tresca friction problem, a sweeping process whose evolution does not
// increase the distance between two states under the same loads (Moreau; Krejci). The state is the
// traction q(x): the loads and q decide everything that follows. So once a cycle leaves the state
// as it found it (within tol), every later cycle repeats it: it is within that distance of the
// cycle solved, and the next within it of that one. Where the history can compare states and
// repeat a cycle (hdetail::repeats_cycles: the static solves), the cycles after such a cycle are
// its copies when that bound, the change times the number of cycles left, is within the history's
// own accuracy (its rtol). They are not solved again, which also spares the static solves the
// degenerate returns of a steady cycle, where every end meets the memory point of the cycle before
// at the same load (periodic (Q_m, Q_a, sigma_m, sigma_a, phase) = (0, 0.1, 0, 0.3, 45 deg): the
// third cycle's solves stopped at those). A copy
// needs a point that stays stuck through the cycle: then the slip over it is zero (a slip whose
// traction change is zero on the contact is C arcsin(x/a) + c, zero on an interval only if zero),
// and the accumulated slip of the copies is the cycle's. The change counted is the state's, tau,
// times the energies' Lipschitz factor in it where that exceeds 1, measured from the two cycles
// before (below). If a later cycle cannot be solved (the history refused a segment) and the last
// one solved changed by at most max(1e-6, rtol), the cycles from the failed one on are copies too.
// Every copy has k times the change in its error estimate (k: its distance in cycles from the one
// copied), and copies count as steady (cycles_to_steady) only where the change was within
// steady_rtol.
template <class T, class H> cycle_result<T> add_cycles(H &h, const T &qm, const T &qa, const T &sm, const T &sa,
                                                       const T &phase_deg, int cycles, ramp_order order, int segments,
                                                       const T &steady_rtol) {
  using std::abs;
  using std::fmod;
  using std::max;
  using std::sin;
  check_cycles(qm, qa, sm, sa, phase_deg, cycles, segments);
  const T pi_ = pi<T>();
  const T ph = phase_deg * pi_ / 180;
  auto at = [&](const T &th, T &q, T &s) {
    q = qm + qa * sin(th);
    s = sm + sa * sin(th + ph);
  };
  T q0, s0;
  at(T(0), q0, s0);
  auto go = [&](const T &q, const T &s) {
    if (q != h.q() || s != h.s()) h.add_vertex(q, s);
  };
  if (order == ramp_order::sigma_first) {
    go(h.q(), s0);
    go(q0, s0);
  } else if (order == ramp_order::q_first) {
    go(q0, h.s());
    go(q0, s0);
  } else go(q0, s0);
  // straight-line cycle: the phase is a multiple of 180 degrees or one amplitude is zero
  const T pm = fmod(abs(phase_deg), T(180));
  const bool line = qa == 0 || sa == 0 || pm == 0;
  std::vector<T> ths;
  if (line) {
    // turning points of sin(th) (and of sin(th + ph) = +-sin th)
    ths = {pi_ / 2, 3 * pi_ / 2, 2 * pi_};
  } else {
    for (int k = 1; k <= segments; ++k) ths.push_back(2 * pi_ * T(k) / T(segments));
  }
  cycle_result<T> res;
  T pE1 = -1, pE2 = -1, pEp = -1, pb1 = -1, pb2 = -1;
  // (the cycle being copied, [copy_first, copy_end) of the vertices, and whether the copies are
  // within tol of a solved cycle: steady)
  size_t copy_first = 0, copy_end = 0;
  bool copying = false, copies_steady = false;
  T change = -1;    // the last solved cycle's change, with the energies' factor (-1: none)
  T prev_tau = -1;  // the state's change over the cycle before
  int copied = 0;
  for (int c = 1; c <= cycles; ++c) {
    const size_t first = h.vertices().size();
    T E1 = 0, E2 = 0, Ep = 0;
    auto solve_cycle = [&] {
      for (const T &th : ths) {
        T q, s;
        at(th, q, s);
        h.add_vertex(q, s);
        h.tag_last_vertex(c);
      }
    };
    if constexpr (hdetail::repeats_cycles<H>::value) {
      if (!copying) {
        try {
          solve_cycle();
        } catch (...) {
          // (the fallback above: the cycles from this one on are copies of the last one solved;
          // only where the history refused a segment, every other error goes on to the caller)
          if (!h.refused(std::current_exception()) || !(change >= 0 && change <= max(T(1e-6), h.state_accuracy())))
            throw;
          h.truncate(first);
          copying = true;
          copy_first = res.last_cycle_first;
          copy_end = res.last_cycle_end;
          copies_steady = change <= steady_rtol;
        }
      }
      if (copying) {
        ++copied;
        h.repeat_cycle(copy_first, copy_end, c, T(copied) * change);
      }
    } else {
      solve_cycle();
    }
    for (size_t k = first; k < h.vertices().size(); ++k) {
      E1 += h.vertices()[k].energy1;
      E2 += h.vertices()[k].energy2;
      Ep += h.vertices()[k].energyp;
    }
    const auto &v = h.vertices().back();
    res.cycles = c;
    res.energy1 = E1;
    res.energy2 = E2;
    res.energyp = Ep;
    res.last_cycle_first = first;
    res.last_cycle_end = h.vertices().size();
    const T scale = max(max(max(abs(E1), abs(E2)), max(abs(pE1), abs(pE2))), max(abs(Ep), abs(pEp)));
    if (c > 1 && res.cycles_to_steady < 0 && (!copying || copies_steady)) {
      const bool same = abs(E1 - pE1) <= steady_rtol * scale + 64 * eps<T>() * scale &&
                        abs(E2 - pE2) <= steady_rtol * scale + 64 * eps<T>() * scale &&
                        abs(Ep - pEp) <= steady_rtol * scale + 64 * eps<T>() * scale &&
                        abs(v.b1 - pb1) <= steady_rtol && abs(v.b2 - pb2) <= steady_rtol;
      if (same) res.cycles_to_steady = c - 1;
    }
    if constexpr (hdetail::repeats_cycles<H>::value) {
      if (!copying) {
        // the state's change over this cycle, tau, and the Lipschitz factor of the cycle's energies
        // in it, measured: this cycle's energies moved from the last one's by dE (over the larger
        // zone's) for a start that had moved by the last cycle's tau. The copies' bound is then
        // tau max(1, dE / last tau) a cycle (energies are not 1-Lipschitz in this distance: a review
        // found a copy's zone energy 6 times its tau off the BEM without the factor). None in the
        // first cycle, whose start (the ramp's end) has no cycle before it.
        const T tau = h.cycle_change(first);
        change = -1;
        if (c > 1 && tau >= 0 && prev_tau >= 0) {
          using std::isfinite;
          const T dE = scale > 0 ? max(max(abs(E1 - pE1), abs(E2 - pE2)), abs(Ep - pEp)) / scale : T(0);
          const T lip = prev_tau > 0 ? dE / prev_tau : T(dE > 0 ? std::numeric_limits<T>::infinity() : 1);
          change = tau == 0 ? (dE == 0 ? T(0) : dE) : tau * max(T(1), lip);
          if (!isfinite(change)) change = -1;
        }
        prev_tau = tau;
        if (change >= 0 && T(cycles - c) * change <= h.state_accuracy()) {
          copying = true;
          copies_steady = change <= steady_rtol;
          copy_first = first;
          copy_end = h.vertices().size();
        }
      }
    }
    pE1 = E1;
    pE2 = E2;
    pEp = Ep;
    pb1 = v.b1;
    pb2 = v.b2;
  }
  res.cycles_repeated = copied;
  res.repeated_change = copied > 0 ? change : T(0);
  res.shakedown = !(res.energy1 > 0) && !(res.energy2 > 0) && !(res.energyp > 0);
  return res;
}

// Along the proportional ramp t (q, s), t in (0, 1], zone i recedes once the
// stick half-width e(t) falls to 2/lambda, lambda = |s/q| > 2 (r_i = 0; see
// the top of this file). e_of(q', s') is the monotonic stick half-width.
// Returns true and the q where it first happens (e decreases along the ramp:
// Illinois regula falsi on ln e(t) - ln target, bracketed, e(0) = 1; ln e is
// nearly linear in t once sigma shrinks the stick zone, e ~ exp(-c s t). Each
// e_of is a solve: the bisection's ~53 of them took 11.7 s for the power law
// n = 999 at sigma/fp0 = 1e4, issue 13).
template <class T, class EOf> bool ramp_recedes(const T &q, const T &s, const EOf &e_of, T &at_q) {
  using std::abs;
  if (q == 0 || s == 0) return false;
  const T lam = abs(s / q);
  if (!(lam > 2)) return false;
  const T target = 2 / lam;
  const T e1 = e_of(q, s);
  if (e1 > target) return false;
  using std::log;
  const T lt = log(target);
  // (a width below the range of T counts as the smallest normal: a finite
  // secant point, far on the right side)
  const T lmin = log(boost::math::tools::min_value<T>());
  auto lg = [&](const T &e) { return (e > 0 ? T(log(e)) : lmin) - lt; };
  auto g = [&](const T &t) { return lg(e_of(t * q, t * s)); };
  T lo = 0, hi = 1;  // e(lo) > target >= e(hi)
  T flo = -lt, fhi = lg(e1);
  int side = 0;
  // to the noise of e: t within 4 eps relative, or ln e within 4 eps of ln target
  for (int it = 0; it < 200 && hi - lo > 4 * eps<T>() * hi; ++it) {
    T mid = (lo * fhi - hi * flo) / (fhi - flo);
    // safeguard: inside the bracket, and not within an ulp of an end
    if (!(mid > lo && mid < hi) || mid - lo <= eps<T>() || hi - mid <= eps<T>()) mid = (lo + hi) / 2;
    const T fm = g(mid);
    if (abs(fm) <= 4 * eps<T>()) {
      hi = mid;
      fhi = 0;
      break;
    }
    if (fm > 0) {
      lo = mid;
      flo = fm;
      if (side == +1) fhi /= 2;
      side = +1;
    } else {
      hi = mid;
      fhi = fm;
      if (fm == 0) break;
      if (side == -1) flo /= 2;
      side = -1;
    }
  }
  if (!(hi - lo <= 4 * eps<T>() * hi) && !(fhi == 0))
    throw error(status::no_convergence, "history: load bisection ran out");
  at_q = hi * q;
  return true;
}

// A history marched twice, at load steps h and h/2, with the step halved (and
// the path replayed from zero) until the two agree to rtol at every vertex:
// zone ends in units of a, energies relative to the largest energy of the
// path. The error estimate of the finer march is that difference.
// Symmetric proportional cycling between +(q, s) and -(q, s), reached by the
// proportional ramp from zero to +(q, s): Ciavarella-Jager superposition at
// constant normal load (docs/history.md). Each reversal subtracts the monotonic
// solution of twice the load with friction 2f, whose zones are those of the
// monotonic solution at (q, s): the cycle is steady from the first reversal, the
// zones at +-(q, s) are the monotonic ones (directions flipped at -(q, s)), each
// zone dissipates 4 E_i per cycle (E_i its monotonic energy) and the slip range
// over a cycle is 2 h(x) (h the monotonic slip). It holds only when no zone
// receded on the ramp: e(q, s) > 2 / |s/q| whenever |s/q| > 2 (e the monotonic
// stick half-width in units of a, which falls along the ramp); otherwise the
// cycle must be marched (history, add_cycles).
template <class T> struct proportional_cycle {
  bool valid = false;        // the superposition applies (no zone receded on the ramp)
  int cycles_to_steady = 1;  // the first reversal already gives the steady cycle
  T energy1{0}, energy2{0};  // per cycle, in the units of E1, E2
};
// e_of(): the monotonic stick half-width at (q, s), called only where a zone can recede.
template <class T, class EOf>
proportional_cycle<T> proportional_steady_cycle(const T &q, const T &s, const EOf &e_of, const T &E1, const T &E2) {
  using std::abs;
  proportional_cycle<T> r;
  const bool can_recede = q != 0 && s != 0 && abs(s) > 2 * abs(q);
  r.valid = !(can_recede && !(e_of() > 2 * abs(q) / abs(s)));
  r.energy1 = 4 * E1;
  r.energy2 = 4 * E2;
  return r;
}

template <class T> class refined_history {
 public:
  using pressure_ptr = typename history<T>::pressure_ptr;
  // Each segment is marched from the state before it at steps 2h, h, h/2, ... (h =
  // o.max_step) until two consecutive marches agree to rtol at the segment's end
  // (zone ends in units of a, energies relative to the largest so far): local error
  // control, as in an ODE solver, so a hard segment costs its own refinement only.
  // The kept march is the finer one; its step and the sum of the estimates (each the
  // difference over 7) up to it are stored in the vertex. Refinement stops at min_step (default 1/512: the
  // march's cost grows like the square of its step count, and near a fast end sweep
  // it converges erratically); the estimate then stays above rtol.
  refined_history(pressure_ptr pm, const history_options<T> &o, const T &rtol, const T &min_step = T(1) / 512)
      : pm_(std::move(pm)), opt_(o), rtol_(rtol), min_step_(min_step) {
    // interior patches: every march merges them, and the accepted (finest) march
    // decides; a coarse march of the refinement can see a patch that the finer
    // ones do not (near a Masing return), which must not stop the history
    strict_patches_ = !opt_.merge_interior_patches;
    opt_.merge_interior_patches = true;
    if (!(rtol_ >= 0)) throw error(status::bad_option, "history: rtol must be >= 0");
    if (!(min_step_ >= history<T>::min_max_step()) || !(min_step_ <= 1))
      throw error(status::bad_option, "history: min_step must be in [1e-6, 1]");
    fine_.reset(new history<T>(pm_, opt_));
  }
  void add_vertex(const T &q, const T &s) {
    using std::abs;
    using std::max;
    using std::min;
    const history<T> &base = *fine_;
    // a march that fails after merging an interior patch in this segment (patched_failure):
    // two such at consecutive steps are the patch's, not the step's (a march that merges a
    // real patch and goes on can lose its way: Hertz (0.95, 2.5) -> (0.95, -2.5) failed at
    // every step from 1/16 to 1/512, 19 s, with NO_CONVERGENCE)
    bool patched_failure = false;
    auto march = [&](const T &step, bool merge = true) {
      std::unique_ptr<history<T>> r(new history<T>(base));
      r->set_max_step(step);
      r->set_merge_interior_patches(merge);
      patched_failure = false;
      try {
        r->add_vertex(q, s);
      } catch (const error &e) {
        patched_failure = e.code() == status::no_convergence && r->interior_merges() > base.interior_merges();
        throw;
      }
      return r;
    };
    // (and the state at the vertex: a patch open there that the march's sparse check did not see;
    // past the limit by more than 1e-6, above the march's own traction error away from the ends)
    auto check_patches = [&](const history<T> &accepted) {
      if (strict_patches_ && accepted.interior_merges() > base.interior_merges())
        throw error(status::not_applicable, hdetail::interior_patch_message);
      T at = 0;
      if (strict_patches_ && accepted.interior_excess(&at) > T(1e-6)) {
        // next to an end at the contact edge (a zone closed there), the step missed the zone's
        // reopening (Hertz (0.95, 2.5) from zero at step 1/16: zone 1 closed where it had reversed,
        // b1 = 0.8486 by the static solves and at step 1/32), not an interior zone
        const auto &v = accepted.vertices().back();
        if ((v.b1 >= 1 && at > v.b1 - (v.b1 + v.b2) / 10) || (v.b2 >= 1 && at < -v.b2 + (v.b1 + v.b2) / 10))
          throw error(status::no_convergence, hdetail::edge_vertex_message);
        throw error(status::not_applicable, hdetail::interior_vertex_message);
      }
    };
    if (!(rtol_ > 0)) {
      // one march, which is the accepted one: it merges only if the caller asked for it
      // (a strict march stops at the first patch, where a merging one went on for 0.9 s to
      // NO_CONVERGENCE on the path above)
      auto r = march(opt_.max_step, !strict_patches_);
      check_patches(*r);
      est_ += check_backslip(*r);  // at fixed steps the estimate is the back-slip's alone
      r->note_last_vertex(opt_.max_step, est_);
      fine_ = std::move(r);
      return;
    }
    auto diff = [&](const history<T> &a, const history<T> &b) {
      const auto &va = a.vertices().back(), &vb = b.vertices().back();
      const T emax = largest_energy(b);
      T d = max(abs(va.b1 - vb.b1), abs(va.b2 - vb.b2));
      if (emax > 0) d = max(d, max(abs(va.energy1 - vb.energy1), abs(va.energy2 - vb.energy2)) / emax);
      return d / 7;  // the march converges like h^3.4 away from events (2^3 - 1)
    };
    std::unique_ptr<history<T>> prev, cur;
    T h = min(T(1), 2 * opt_.max_step), est = 0, lastd = -1;
    // A segment shorter than the step is marched in one step at every step above its length, and
    // two such marches are the same march: their difference, 0, was taken for the estimate, and the
    // march accepted. Hertz (0, 0.3) -> (0.3 sin(2 pi/64), 0.3 cos(2 pi/64)) (a chord of a periodic
    // loading, length 0.029 in max(|dq|, |ds|/4)) at max_step 1/32 was accepted at one step, 1.1e-7
    // a off in b2, with no estimate added. The refinement starts at the segment's length, and goes
    // down to a quarter of it where that is below min_step (a short segment needs few steps).
    const T len = max(abs(q - base.q()), abs(s - base.s()) / 4);
    if (len > 0 && len < h) h = max(len, history<T>::min_max_step());
    const T floor_step = max(len > 0 ? min(min_step_, len / 4) : min_step_, history<T>::min_max_step());
    int no_gain = 0;
    bool last_patched_failure = false;
    try {
      prev = march(h);
    } catch (const error &e) {
      if (e.code() != status::no_convergence) throw;
      last_patched_failure = patched_failure;
    }
    for (;;) {
      const T hn = h / 2;
      if (prev && hn < floor_step) {
        est = T(-1);
        break;
      }
      std::unique_ptr<history<T>> next;
      try {
        next = march(hn);
      } catch (const error &e) {
        if (e.code() != status::no_convergence) throw;
        if (strict_patches_ && patched_failure && last_patched_failure) throw error(status::not_applicable, hdetail::interior_patch_message);
        last_patched_failure = patched_failure;
        if (!prev && hn / 2 >= floor_step) {
          h = hn;
          continue;
        }  // neither converged yet: finer
        if (!prev) throw;
        refine_failed_ = true;  // keep the coarser march; its estimate stays above rtol
        est = T(-1);
        break;
      }
      last_patched_failure = false;
      h = hn;
      if (prev) {
        const T before = lastd;
        est = diff(*prev, *next);
        lastd = est;
        cur = std::move(next);
        if (est <= rtol_) break;
        // the differences do not shrink twice in a row (an erratic segment, e.g. a fast
        // end sweep): halving further costs much and gains nothing; keep this march and
        // its estimate. (Once is not enough: a coarse march can be lucky, e.g. steps
        // 1/16, 1/32, 1/64 off by 1.1e-7, 2.9e-7, 1.1e-7 a on an oracle segment that
        // then converges like step^2.7.)
        if (before > 0 && est > before / 2) {
          if (++no_gain >= 2) break;
        } else no_gain = 0;
        prev = std::move(cur);
        cur.reset();
      } else {
        prev = std::move(next);
      }
    }
    if (!cur) {  // stopped at min_step or on a failure: the finest march that converged
      cur = std::move(prev);
      est = lastd >= 0 ? lastd : T(1);  // 1: a single march converged, no estimate
    }
    // the errors of the segments add up along the path: the vertex reports the sum of
    // the local estimates so far (on a steady cycle at rtol 1e-8 the true error was
    // 6.6e-8 against a largest local estimate of 7.4e-9)
    check_patches(*cur);
    est_ += est + check_backslip(*cur);
    cur->note_last_vertex(h, est_);
    step_ = h;
    fine_ = std::move(cur);
  }
  cycle_result<T> add_cycles(const T &qm, const T &qa, const T &sm, const T &sa, const T &phase_deg, int cycles,
                             ramp_order order, int segments, const T &steady_rtol) {
    last_cycles_ = hs::core::add_cycles<T>(*this, qm, qa, sm, sa, phase_deg, cycles, order, segments, steady_rtol);
    return last_cycles_;
  }
  // Back-slip (history_vertex::backslip_i) is energy that part of an edge zone next to the
  // contact edge would spend slipping against the zone's direction: where the exact solution
  // has a stuck band or a reverse slip zone there, which the march does not model. It stays
  // as the step shrinks (it is the path's, not the march's), and the march's energies are off
  // by 0.3 to 2.3 times it (bench/stress_history.cpp, 300 paths: back-slip 1.2e-3, 6.1e-3 and
  // 1.6e-2 of the largest zone energy, each confirmed by the BEM, a stuck band near the edge
  // and in one a reverse zone at the edge; energies 5-8 % off or negative). Elsewhere it came
  // from steps across an event (a zone about to stop), at most 2.4e-7 at steps of 1/4 to
  // 1/16, shrinking with the step, and once from a real band 3.7e-7 (Hertz, BEM-invisible).
  // So the segment's estimate grows by 3 times the back-slip over the largest energy, and
  // past max(rtol, 1e-5) (1e-5: the largest error a result may carry for a zone structure it
  // does not model, 100 times below the BEM's energy accuracy at 400 elements) the segment
  // is status::not_applicable, never a silently wrong state.
  // the largest zone energy of a segment of the path so far: the scale of the energy
  // differences (add_vertex) and of the back-slip
  static T largest_energy(const history<T> &h) {
    using std::abs;
    using std::max;
    T emax = 0;
    for (const auto &v : h.vertices()) emax = max(emax, max(abs(v.energy1), abs(v.energy2)));
    return emax;
  }
  T backslip_estimate(const history<T> &h) const {
    using std::max;
    const auto &vs = h.vertices();
    if (vs.empty()) return T(0);
    const T emax = largest_energy(h);
    const auto &v = vs.back();
    return emax > 0 ? 3 * max(v.backslip1, v.backslip2) / emax : T(0);
  }
  T backslip_limit() const { return std::max(rtol_, T(1e-5)); }
  const history<T> &fine() const { return *fine_; }
  const std::vector<history_vertex<T>> &vertices() const { return fine_->vertices(); }
  void tag_last_vertex(int cycle) { fine_->tag_last_vertex(cycle); }
  T q() const { return fine_->q(); }
  T s() const { return fine_->s(); }
  T error_estimate() const { return est_; }
  // a finer march did not converge: the result is the coarser one (error_estimate > rtol)
  bool refinement_failed() const { return refine_failed_; }
  T step() const { return step_ > 0 ? step_ : opt_.max_step; }

  T check_backslip(const history<T> &h) const {
    const T est = backslip_estimate(h);
    if (!(est > backslip_limit())) return est;
    const auto &v = h.vertices().back();
    if (v.backslip1 >= v.backslip2)
      throw error(status::not_applicable,
                  "history: next to the contact edge, part of zone 1 (x > b1) would slip back against the zone's "
                  "direction: it sticks or reverses (a stick band or a reverse slip zone inside the edge zone, "
                  "zones the march does not model)");
    throw error(status::not_applicable,
                "history: next to the contact edge, part of zone 2 (x < -b2) would slip back against the zone's "
                "direction: it sticks or reverses (a stick band or a reverse slip zone inside the edge zone, "
                "zones the march does not model)");
  }

 private:
  pressure_ptr pm_;
  history_options<T> opt_;
  bool strict_patches_ = true;  // the caller asked for no merges (its options)
  T rtol_, min_step_;
  std::unique_ptr<history<T>> fine_;
  cycle_result<T> last_cycles_;
  T est_{0}, step_{0};
  bool refine_failed_ = false;
};

}}  // namespace hs::core
