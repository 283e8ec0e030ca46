// Reference backend benchmark: median time per MPFR solve at 30, 50, 100 and
// 300 digits in each regime, for one precision tier alone (the work run) and
// for the certified solve (work run + wider check run); then (issue 16) the
// flat punch and power law scenes of docs/reference.md's cost table, certified
// b1, b2 with and without the zone energies at 50 and 100 digits. Writes CSV
// rows kind,method,regime,digits,median_ms (regime: the scene for the latter).
// Usage: bench_reference [CSV [GENERAL_CSV [--general-only]]] (defaults
// bench/results/reference.csv, bench/results/reference_general.csv; --general-only:
// the general rows alone, CSV untouched). Times: CPU time of the calling thread.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <time.h>

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

// CPU time of the calling thread in ms
static double cpu_ms() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec * 1e3 + ts.tv_nsec * 1e-6;
}

int main(int argc, char **argv) {
  const std::string csv = argc > 1 ? argv[1] : "bench/results/reference.csv";
  const std::string gcsv = argc > 2 ? argv[2] : "bench/results/reference_general.csv";
  const bool general_only = argc > 3 && std::string(argv[3]) == "--general-only";
  std::ofstream out;
  if (!general_only) {
    out.open(csv);
    out << "kind,method,regime,digits,median_ms\n";
  }
  struct scene {
    const char *regime, *q, *s;
  };
  const scene scenes[] = {{"same-sign", "0.5", "0.2"}, {"opposite-sign", "0.3", "2"}};
  if (!general_only) std::printf("%-14s %7s %18s %18s\n", "regime", "digits", "one tier [ms]", "certified [ms]");
  for (const auto &sc : scenes) {
    if (general_only) break;
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
  // Issue 16: the flat punch and the power law (the four scenes of docs/reference.md's cost
  // table), certified b1 and b2 ("b") and b1, b2 and both zone energies ("b+E"), at 50 and
  // 100 digits. "first" is the first call of the process for that digit count (it makes the
  // Gauss-Legendre rules of both tiers; later scenes reuse them), "median" the median of
  // the repeated calls (warm rule cache). CPU time of this thread (the machine is shared).
  struct gscene {
    const char *name;
    int geometry;
    const char *param, *q, *s;
  };
  const gscene gscenes[] = {{"flat0.5-same", ref::geometry_flat_rounded, "0.5", "0.5", "0.5"},
                            {"flat0.5-opposite", ref::geometry_flat_rounded, "0.5", "0.3", "2"},
                            {"power3-same", ref::geometry_power_law, "3", "0.5", "0.5"},
                            {"power1.5-opposite", ref::geometry_power_law, "1.5", "0.3", "2"}};
  if (!general_only) std::printf("CSV written to %s\n", csv.c_str());
  std::ofstream gout(gcsv);
  gout << "kind,method,scene,digits,ms\n";
  std::printf("\n%-18s %7s %6s %14s %14s\n", "scene", "digits", "what", "first [ms]", "median [ms]");
  for (int digits : {50, 100}) {
    for (bool energies : {false, true}) {
      for (const auto &g : gscenes) {
        ref::text_scene t;
        t.geometry = g.geometry;
        if (g.geometry == ref::geometry_flat_rounded) t.flat_over_a = g.param;
        else t.exponent = g.param;
        t.q = g.q;
        t.s = g.s;
        auto call = [&] {
          ref::solution s(t, digits);
          (void)s.value(ref::quantity::b1);
          (void)s.value(ref::quantity::b2);
          if (energies) {
            (void)s.value(ref::quantity::energy1);
            (void)s.value(ref::quantity::energy2);
          }
        };
        const double t0 = cpu_ms();
        call();
        const double first = cpu_ms() - t0;
        const int reps = energies ? 3 : 5;
        std::vector<double> v;
        for (int r = 0; r < reps; ++r) {
          const double a = cpu_ms();
          call();
          v.push_back(cpu_ms() - a);
        }
        std::sort(v.begin(), v.end());
        const double med = v[v.size() / 2];
        const char *what = energies ? "b+E" : "b";
        std::printf("%-18s %7d %6s %14.1f %14.1f\n", g.name, digits, what, first, med);
        gout << "general-" << what << ",halfslip-certified-first-call," << g.name << "," << digits << "," << first << "\n";
        gout << "general-" << what << ",halfslip-certified-median," << g.name << "," << digits << "," << med << "\n";
      }
    }
  }
  std::printf("CSV written to %s\n", gcsv.c_str());
}
