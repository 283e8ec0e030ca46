// One precision tier of the reference backend: the core templates
// instantiated on the MPFR type of HS_TIER_DIGITS decimal digits. This one
// source is compiled once per tier of the ladder (CMake option
// HALFSLIP_REF_TIERS) with -DHS_TIER_DIGITS=D; backend.cpp finds the tiers
// through the generated list tiers.inc.
#include "tier_impl.hpp"

#ifndef HS_TIER_DIGITS
#  error "compile reference/src/tier.cpp with -DHS_TIER_DIGITS=<decimal digits of the tier>"
#endif

#define HS_TIER_CAT2(a, b) a##b
#define HS_TIER_CAT(a, b)  HS_TIER_CAT2(a, b)

namespace hs { namespace reference {

template class tier_solution_impl<HS_TIER_DIGITS>;

// make_tier_D, declared in backend.cpp for every D of tiers.inc
std::unique_ptr<tier_solution> HS_TIER_CAT(make_tier_, HS_TIER_DIGITS)(const text_scene &sc, int max_iterations) {
  return make_tier<HS_TIER_DIGITS>(sc, max_iterations);
}

}}  // namespace hs::reference
