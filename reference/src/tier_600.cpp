// Precision tier 600 decimal digits (explicit instantiation, own translation unit).
#include "tier_impl.hpp"

namespace hs { namespace reference {
template class tier_solution_impl<600>;
std::unique_ptr<tier_solution> make_tier_600(const text_scene &sc, int max_iterations) {
  return make_tier<600>(sc, max_iterations);
}
}}  // namespace hs::reference
