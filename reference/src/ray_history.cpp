// Certified load histories along one ray (issue 14): reference/ray_history.hpp.
#include "halfslip/reference/ray_history.hpp"

#include <boost/multiprecision/mpfr.hpp>
#include <map>
#include <utility>
#include <vector>

#include "halfslip/core/ray_history.hpp"
#include "halfslip/core/status.hpp"

namespace hs { namespace reference {

namespace {
// the loads' arithmetic (differences and halves of the user's decimals) and the
// sums of tier values: far beyond the top tier, so that neither adds an error
// the tiers could see
using D = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<1400>,
                                        boost::multiprecision::et_off>;
constexpr int load_digits = 1000;  // digits of a load passed to a solve (tiers <= 600 + guard)

std::string text(const D &v) {
  if (v == 0) return "0";
  return v.str(load_digits, std::ios_base::scientific);
}
D parse(const std::string &s) {
  D v;
  try {
    v = D(s);
  } catch (const std::exception &) {
    throw core::error(core::status::bad_number, "load-history vertex: not a decimal number");
  }
  if (!boost::multiprecision::isfinite(v))
    throw core::error(core::status::not_finite, "load-history vertex: not finite");
  return v;
}
}  // namespace

struct ray_history::impl {
  text_scene contact;
  int digits;
  core::ray_path<D> path;
  std::map<std::pair<std::string, std::string>, std::shared_ptr<const solution>> cache;
  struct vertex {
    std::shared_ptr<const solution> active;  // its zones and directions are the state's
    bool moved = true;
    certified b1, b2, e1, e2;
    int dir1 = 0, dir2 = 0;
  };
  std::vector<vertex> vertices;

  std::shared_ptr<const solution> at(const core::ray_load<D> &l) {
    const auto key = std::make_pair(text(l.q), text(l.s));
    const auto it = cache.find(key);
    if (it != cache.end()) return it->second;
    text_scene sc = contact;
    sc.q = key.first;
    sc.s = key.second;
    auto sol = std::make_shared<const solution>(sc, digits);
    cache.emplace(key, sol);
    return sol;
  }

  // sum of coef * (E_i(to) - E_i(from)) at one tier
  D energy(const core::ray_vertex_plan<D> &v, quantity q, bool check) {
    D e = 0;
    for (const auto &pc : v.pieces) {
      D d = 0;
      if (!pc.to.zero()) d += D(at(pc.to)->raw(q, check));
      if (!pc.from.zero()) d -= D(at(pc.from)->raw(q, check));
      e += pc.coef * d;
    }
    return e;
  }
  certified combined(const core::ray_vertex_plan<D> &v, quantity q, const solution &any) {
    const D w = energy(v, q, false), c = energy(v, q, true);
    // (str(n, scientific) writes n digits after the point)
    const std::string ws = w == 0 ? std::string("0") : w.str(digits - 1, std::ios_base::scientific);
    const std::string cs =
        c == 0 ? std::string("0") : c.str(int(any.check_digits()) - 1, std::ios_base::scientific);
    return {ws, agreeing_digits(ws, cs, digits)};
  }
};

ray_history::ray_history(const text_scene &contact, int digits) : p_(new impl) {
  if (!contact.P.empty())
    throw core::error(core::status::bad_option, "load-history: dimensional input is not taken (give a, p0, f, E*)");
  if (digits < 1 || digits > max_digits(contact.geometry))
    throw core::error(core::status::bad_option, "digits out of range (1 .. hs_ref_max_digits_geometry())");
  p_->contact = contact;
  p_->digits = digits;
}
ray_history::~ray_history() = default;

std::size_t ray_history::size() const { return p_->vertices.size(); }

void ray_history::add(const std::string &qs, const std::string &ss) {
  impl &m = *p_;
  const D q = parse(qs), s = parse(ss);
  if (!(abs(q) < 1)) throw core::error(core::status::gross_sliding, "history: |Q| >= fP at a path vertex: gross sliding");
  core::ray_path<D> next = m.path;
  if (!next.add(q, s))
    throw core::error(core::status::not_applicable,
                      "load history: the vertex is off the path's ray through the origin (the reference backend "
                      "follows paths along one ray only; march other paths in double)");
  // no zone may recede on the ramp to the farthest vertex: e > 2 |q/s| where |s/q| > 2
  const auto far = next.farthest();
  if (far.q != 0 && far.s != 0 && abs(far.s) > 2 * abs(far.q)) {
    const auto sol = m.at(far);
    const D a = D(sol->raw(quantity::a, false));
    const D e = (D(sol->raw(quantity::b1, false)) + D(sol->raw(quantity::b2, false))) / (2 * a);
    const D target = 2 * abs(far.q / far.s);
    if (!(e > target * (1 + pow(D(10), -m.digits))))
      throw core::error(core::status::not_applicable,
                        "load history: a zone recedes on the ramp to the path's farthest vertex (or too close to "
                        "tell): the states are not sums of monotonic solutions; march the path in double");
  }
  const auto &plan = next.vertices().back();
  impl::vertex v;
  v.moved = plan.moved;
  if (!plan.moved && !m.vertices.empty()) {
    v = m.vertices.back();
    v.moved = false;
    v.e1 = v.e2 = {"0", m.digits};
  } else {
    const auto &act = plan.terms.back().load;
    v.active = m.at(act);  // the zero load too: the stuck state (b = a)
    v.b1 = v.active->value(quantity::b1);
    v.b2 = v.active->value(quantity::b2);
    v.dir1 = act.zero() ? 0 : v.active->dir1();
    v.dir2 = act.zero() ? 0 : v.active->dir2();
    v.e1 = m.combined(plan, quantity::energy1, *v.active);
    v.e2 = m.combined(plan, quantity::energy2, *v.active);
  }
  m.path = std::move(next);
  m.vertices.push_back(std::move(v));
}

certified ray_history::value(std::size_t i, quantity q) const {
  if (i >= p_->vertices.size()) throw core::error(core::status::bad_option, "vertex index out of range");
  const auto &v = p_->vertices[i];
  switch (q) {
    case quantity::b1: return v.b1;
    case quantity::b2: return v.b2;
    case quantity::energy1: return v.e1;
    case quantity::energy2: return v.e2;
    default: throw core::error(core::status::bad_option, "load history: b1, b2, energy1 or energy2 only");
  }
}
int ray_history::dir1(std::size_t i) const {
  if (i >= p_->vertices.size()) throw core::error(core::status::bad_option, "vertex index out of range");
  return p_->vertices[i].dir1;
}
int ray_history::dir2(std::size_t i) const {
  if (i >= p_->vertices.size()) throw core::error(core::status::bad_option, "vertex index out of range");
  return p_->vertices[i].dir2;
}

}}  // namespace hs::reference
