// halfslip core: status codes and the exception used inside the C++ core.
// The numeric values equal the HS_ERR_* macros of the C ABI (checked there).
#pragma once
#include <exception>

namespace hs { namespace core {

enum class status : int {
  ok = 0,
  null_pointer = 1,
  struct_size = 2,
  not_finite = 3,
  bad_size = 4,
  bad_friction = 5,
  gross_sliding = 6,
  bad_geometry = 7,
  point_outside = 8,
  buffer_too_small = 9,
  no_convergence = 10,
  bad_option = 11,
  out_of_memory = 12,
  internal = 13,
  overflow = 14,
  bad_number = 15,
  tolerance = 16,
  not_applicable = 17
};

// Thrown by the core on invalid input or failure; carries a status and a
// static message (no allocation, so it can be thrown under memory pressure).
class error : public std::exception {
 public:
  error(status s, const char *msg) noexcept : s_(s), msg_(msg) {}
  status code() const noexcept { return s_; }
  const char *what() const noexcept override { return msg_; }

 private:
  status s_;
  const char *msg_;
};

// For every loop that can run out (as Boost.Math's check_series_iterations):
// `used` is the count at exit, equal to `max` only when the loop ran out
// without meeting its stopping rule; then the result is not converged and
// this throws no_convergence (the C ABI returns HS_ERR_NO_CONVERGENCE).
inline void check_iterations(long used, long max, const char *what) {
  if (used >= max) throw error(status::no_convergence, what);
}

}}  // namespace hs::core
