// Reference backend benchmark: median time per MPFR solve at 30, 50, 100 and
// 300 digits in each regime, for one precision tier alone (the work run) and
// for the certified solve (work run + wider check run). Writes CSV rows
// kind,method,regime,digits,median_ms.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "halfslip/reference/backend.hpp"

namespace ref = hs::reference;

template <class F> double median_ms(F &&f, int reps) {
  f();  // warm-up
  std::vector<double> t;
  for (int r = 0; r < reps; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

int main(int argc, char **argv) {
  const std::string csv = argc > 1 ? argv[1] : "bench/results/reference.csv";
  std::ofstream out(csv);
  out << "kind,method,regime,digits,median_ms\n";
  struct scene {
    const char *regime, *q, *s;
  };
  const scene scenes[] = {{"same-sign", "0.5", "0.2"}, {"opposite-sign", "0.3", "2"}};
  std::printf("%-14s %7s %18s %18s\n", "regime", "digits", "one tier [ms]", "certified [ms]");
  for (const auto &sc : scenes) {
    ref::text_scene t;
    t.q = sc.q;
    t.s = sc.s;
    for (int digits : {30, 50, 100, 300}) {
      unsigned D = 0;
      for (unsigned d : ref::tiers())
        if (D == 0 && int(d) >= digits + ref::guard_digits) D = d;
      const int reps = digits >= 300 ? 5 : 15;
      const double one = median_ms(
          [&] {
            auto s = ref::solve_at(D, t, 1000);
            (void)s->value(ref::quantity::b1, digits);
          },
          reps);
      const double cert = median_ms(
          [&] {
            ref::solution s(t, digits);
            (void)s.value(ref::quantity::b1);
            (void)s.value(ref::quantity::b2);
          },
          reps);
      std::printf("%-14s %7d %18.3f %18.3f\n", sc.regime, digits, one, cert);
      out << "solve,halfslip-one-tier," << sc.regime << "," << digits << "," << one << "\n";
      out << "solve,halfslip-certified," << sc.regime << "," << digits << "," << cert << "\n";
    }
  }
  std::printf("CSV written to %s\n", csv.c_str());
}
