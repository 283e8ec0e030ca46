// Certified load histories along one ray through the origin (issue 14): the
// states are sums of monotonic solutions (core/ray_history.hpp, Jäger's memory
// rule; docs/history.md), each solved by the reference backend at a work and a
// check tier. The energies, sums of differences of monotonic energies, are
// formed at both tiers and certified by their agreement, so cancellation shows
// as fewer certified digits.
#pragma once
#include <cstddef>
#include <memory>
#include <string>

#include "backend.hpp"

namespace hs { namespace reference {

class ray_history {
 public:
  // contact: geometry, a, p0, f, E* (its q and s are ignored; no dimensional input)
  ray_history(const text_scene &contact, int digits);
  ~ray_history();
  ray_history(const ray_history &) = delete;
  ray_history &operator=(const ray_history &) = delete;
  // Appends the vertex (decimal Q/fP, sigma/fp0). Throws core::error:
  // not_applicable when it is off the path's ray or a zone would recede on
  // the ramp to the path's farthest vertex (the path then needs the march,
  // in double); gross_sliding, bad_number as a solve. The history is
  // unchanged on error.
  void add(const std::string &q, const std::string &s);
  std::size_t size() const;
  // quantity::b1, b2 (stick zone after the vertex), energy1, energy2 (dissipated
  // in the segment that ends at the vertex); others: bad_option
  certified value(std::size_t vertex, quantity q) const;
  int dir1(std::size_t vertex) const;
  int dir2(std::size_t vertex) const;

 private:
  struct impl;
  std::unique_ptr<impl> p_;
};

}}  // namespace hs::reference
