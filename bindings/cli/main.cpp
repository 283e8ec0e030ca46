// The `halfslip` command: solve a scene from the command line, through the C ABI.
//
//   halfslip solve [--geometry hertz] [--Q-over-fP X] [--sigma-over-fp0 Y]
//                  [--a A] [--p0 P0] [--f F] [--E-star E]
//                  [--P P --R R --E-star E --f F --Q Q --sigma S]
//                  [--points N] [--json]
#include <halfslip/halfslip.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace {

const char *kUsage =
    "usage: halfslip solve [options]\n"
    "  Solves a half-plane partial-slip contact (constant normal load, shear\n"
    "  force Q, differential bulk tension sigma). Conventions: docs/conventions.md.\n"
    "options (dimensionless; a = p0 = f = E* = 1 unless given):\n"
    "  --geometry hertz        contact geometry (only hertz so far)\n"
    "  --Q-over-fP X           shear force ratio Q/(fP), |X| < 1   (default 0.5)\n"
    "  --sigma-over-fp0 Y      bulk tension ratio sigma/(f p0)      (default 0.5)\n"
    "  --a A --p0 P0 --f F --E-star E   scales\n"
    "options (dimensional Hertz; all six together):\n"
    "  --P P --R R --E-star E --f F --Q Q --sigma S\n"
    "output:\n"
    "  --points N              also tabulate B_x, slip h and work W at N points per slip zone\n"
    "  --json                  one JSON object, numbers with 17 significant digits\n";

[[noreturn]] void die(const std::string &msg) {
  std::fprintf(stderr, "halfslip: %s\n", msg.c_str());
  std::exit(2);
}

double parse_number(const std::string &flag, const char *text) {
  char *end = nullptr;
  const double v = std::strtod(text, &end);
  if (end == text || *end != '\0') die("bad value for " + flag + ": '" + text + "' is not a number");
  if (!std::isfinite(v)) die("bad value for " + flag + ": '" + text + "' is not finite");
  return v;
}

std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

const char *regime_name(int r) {
  switch (r) {
    case HS_REGIME_STUCK: return "stuck";
    case HS_REGIME_SAME_SIGN: return "same-sign";
    case HS_REGIME_OPPOSITE_SIGN: return "opposite-sign";
    default: return "unknown";
  }
}

void check(int st, const std::string &what) {
  if (st != HS_OK) die(what + ": " + hs_strerror(st));
}

}  // namespace

int main(int argc, char **argv) {
  if (argc < 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0) {
    std::fputs(kUsage, argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  if (std::strcmp(argv[1], "--version") == 0) {
    std::printf("halfslip %s\n", hs_version_string());
    return 0;
  }
  if (std::strcmp(argv[1], "solve") != 0) die(std::string("unknown command '") + argv[1] + "'\n" + kUsage);

  const char *known[] = {"--geometry", "--Q-over-fP", "--sigma-over-fp0", "--a", "--p0", "--f", "--E-star",
                         "--P", "--R", "--Q", "--sigma", "--points"};
  std::map<std::string, std::string> args;
  bool json = false;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--json") { json = true; continue; }
    if (a == "--help" || a == "-h") { std::fputs(kUsage, stdout); return 0; }
    bool ok = false;
    for (const char *k : known) ok = ok || a == k;
    if (!ok) die("unknown option '" + a + "'");
    if (i + 1 >= argc) die("option " + a + " needs a value");
    if (args.count(a)) die("option " + a + " given twice");
    args[a] = argv[++i];
  }
  if (args.count("--geometry") && args["--geometry"] != "hertz")
    die("bad value for --geometry: '" + args["--geometry"] + "' (known: hertz)");

  auto get = [&](const char *k, double def) {
    return args.count(k) ? parse_number(k, args[k].c_str()) : def;
  };

  hs_scene scene;
  hs_scene_default(&scene);
  const bool dimensional = args.count("--P") || args.count("--R") || args.count("--Q") || args.count("--sigma");
  if (dimensional) {
    for (const char *k : {"--P", "--R", "--E-star", "--f", "--Q", "--sigma"})
      if (!args.count(k)) die(std::string("dimensional input needs ") + k + " (give --P --R --E-star --f --Q --sigma)");
    for (const char *k : {"--Q-over-fP", "--sigma-over-fp0", "--a", "--p0"})
      if (args.count(k)) die(std::string(k) + " cannot be combined with dimensional --P/--R/--Q/--sigma");
    const double P = get("--P", 0), R = get("--R", 0), E = get("--E-star", 0), f = get("--f", 0);
    const double Q = get("--Q", 0), sg = get("--sigma", 0);
    if (!(P > 0)) die("bad value for --P: must be > 0");
    if (!(R > 0)) die("bad value for --R: must be > 0");
    if (!(E > 0)) die("bad value for --E-star: must be > 0");
    if (!(f > 0)) die("bad value for --f: must be > 0");
    if (!(std::fabs(Q) < f * P)) die("bad value for --Q: |Q| >= fP means gross sliding");
    check(hs_scene_from_hertz_loads(P, R, E, f, Q, sg, &scene), "scene");
  } else {
    scene.Q_over_fP = get("--Q-over-fP", 0.5);
    scene.sigma_over_fp0 = get("--sigma-over-fp0", 0.5);
    scene.a = get("--a", 1.0);
    scene.p0 = get("--p0", 1.0);
    scene.f = get("--f", 1.0);
    scene.E_star = get("--E-star", 1.0);
    if (!(std::fabs(scene.Q_over_fP) < 1)) die("bad value for --Q-over-fP: |Q/fP| must be < 1 (gross sliding)");
    if (!(scene.a > 0)) die("bad value for --a: must be > 0");
    if (!(scene.p0 > 0)) die("bad value for --p0: must be > 0");
    if (!(scene.f > 0)) die("bad value for --f: must be > 0");
    if (!(scene.E_star > 0)) die("bad value for --E-star: must be > 0");
  }
  int npts = 0;
  if (args.count("--points")) {
    const double v = parse_number("--points", args["--points"].c_str());
    if (!(v >= 0 && v <= 100000 && v == std::floor(v))) die("bad value for --points: need an integer in [0, 100000]");
    npts = int(v);
  }

  hs_solution *sol = nullptr;
  check(hs_solve(&scene, nullptr, &sol), "solve");
  hs_summary sm;
  sm.struct_size = sizeof sm;
  check(hs_solution_summary(sol, &sm), "summary");
  double energy[2];
  check(hs_solution_energy(sol, energy), "energy");

  // Points: N per slip zone, from the stick boundary to the contact edge.
  std::vector<double> xs;
  for (int z = 0; z < 2 && npts > 0; ++z) {
    const double d = z == 0 ? sm.d1 : sm.d2;
    if (!(d > 0)) continue;
    for (int i = 1; i <= npts; ++i) {
      const double t = double(i) / npts;
      xs.push_back(z == 0 ? sm.a - d * (1 - t) : -sm.a + d * (1 - t));
    }
  }
  std::vector<double> B(xs.size()), h(xs.size()), W(xs.size());
  if (!xs.empty()) {
    check(hs_eval_Bx(sol, xs.size(), xs.data(), B.data()), "B_x");
    check(hs_eval_slip(sol, xs.size(), xs.data(), h.data()), "slip");
    check(hs_eval_work(sol, xs.size(), xs.data(), W.data()), "work");
  }
  const double P = M_PI * scene.a * scene.p0 / 2;

  if (json) {
    std::printf("{\"geometry\": \"hertz\", \"regime\": \"%s\", \"a\": %s, \"p0\": %s, \"P\": %s, \"f\": %s, "
                "\"E_star\": %s, \"Q_over_fP\": %s, \"sigma_over_fp0\": %s, \"b1\": %s, \"b2\": %s, "
                "\"d1\": %s, \"d2\": %s, \"slip_dir1\": %d, \"slip_dir2\": %d, \"energy1\": %s, "
                "\"energy2\": %s, \"iterations\": %d",
                regime_name(sm.regime), num(sm.a).c_str(), num(scene.p0).c_str(), num(P).c_str(),
                num(scene.f).c_str(), num(scene.E_star).c_str(), num(scene.Q_over_fP).c_str(),
                num(scene.sigma_over_fp0).c_str(), num(sm.b1).c_str(), num(sm.b2).c_str(), num(sm.d1).c_str(),
                num(sm.d2).c_str(), sm.slip_dir1, sm.slip_dir2, num(energy[0]).c_str(), num(energy[1]).c_str(),
                sm.iterations);
    if (!xs.empty()) {
      std::printf(", \"points\": [");
      for (size_t i = 0; i < xs.size(); ++i)
        std::printf("%s{\"x\": %s, \"Bx\": %s, \"h\": %s, \"W\": %s}", i ? ", " : "", num(xs[i]).c_str(),
                    num(B[i]).c_str(), num(h[i]).c_str(), num(W[i]).c_str());
      std::printf("]");
    }
    std::printf("}\n");
  } else {
    std::printf("halfslip %s: Hertz contact, constant normal load\n", hs_version_string());
    std::printf("  a = %.10g, p0 = %.10g, P = %.10g, f = %.10g, E* = %.10g\n", sm.a, scene.p0, P, scene.f,
                scene.E_star);
    std::printf("  Q/fP = %.10g, sigma/(f p0) = %.10g\n", scene.Q_over_fP, scene.sigma_over_fp0);
    std::printf("regime: %s\n", regime_name(sm.regime));
    std::printf("  stick zone (-b2, b1): b1/a = %.15g, b2/a = %.15g\n", sm.b1 / sm.a, sm.b2 / sm.a);
    std::printf("  slip zone 1 (b1, a):  d1/a = %.15g, slip direction %+d\n", sm.d1 / sm.a, sm.slip_dir1);
    std::printf("  slip zone 2 (-a,-b2): d2/a = %.15g, slip direction %+d\n", sm.d2 / sm.a, sm.slip_dir2);
    std::printf("energy dissipated (monotonic loading, per unit length):\n");
    std::printf("  zone 1: %.10g, zone 2: %.10g, total: %.10g\n", energy[0], energy[1], energy[0] + energy[1]);
    if (sm.iterations) std::printf("  (Newton iterations: %d)\n", sm.iterations);
    if (!xs.empty()) {
      std::printf("%22s %22s %22s %22s\n", "x", "B_x", "h", "W");
      for (size_t i = 0; i < xs.size(); ++i)
        std::printf("%22.15g %22.15g %22.15g %22.15g\n", xs[i], B[i], h[i], W[i]);
    }
  }
  hs_solution_free(sol);
  return 0;
}
