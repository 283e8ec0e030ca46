// The `halfslip` command's argument parsing (args.hpp), moved out of main.cpp so
// that a fuzz target can call it (issue 13).
#include "args.hpp"

#include "pressure_file.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace halfslip_cli {

namespace {
[[noreturn]] void fail(const std::string &msg) { throw cli_error(msg); }
}  // namespace

double parse_number(const std::string &flag, const char *text) {
  char *end = nullptr;
  const double v = std::strtod(text, &end);
  if (end == text || *end != '\0') fail("bad value for " + flag + ": '" + text + "' is not a number");
  if (!std::isfinite(v)) fail("bad value for " + flag + ": '" + text + "' is not finite");
  return v;
}

void check(int st, const std::string &what) {
  if (st != HS_OK) fail(what + ": " + hs_strerror(st));
}


// Edit distance, ignoring case (for "did you mean").
size_t edit_distance(const std::string &a, const std::string &b) {
  std::vector<size_t> d(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) d[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t prev = d[0];
    d[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t cur = d[j];
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      d[j] = std::min({d[j] + 1, d[j - 1] + 1, prev + (same ? 0 : 1)});
      prev = cur;
    }
  }
  return d[b.size()];
}

[[noreturn]] void unknown_option(const std::string &a, const std::vector<std::string> &keys,
                                 const std::vector<std::string> &flags) {
  std::string best;
  size_t bd = std::string::npos;
  for (const auto *list : {&keys, &flags})
    for (const auto &k : *list) {
      const size_t d = edit_distance(a, k);
      if (d < bd) {
        bd = d;
        best = k;
      }
    }
  const size_t tol = std::max<size_t>(2, a.size() / 4);
  fail("unknown option '" + a + "'" + (bd <= tol ? "; did you mean " + best + "?" : "") + " (see halfslip --help)");
}

// Parse "--key value" and "--key=value" pairs (and the boolean flags given) after argv[first].
Args parse_args(int argc, const char *const *argv, int first, const std::vector<std::string> &keys,
                const std::vector<std::string> &flags) {
  Args args;
  for (int i = first; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--help" || a == "-h") throw help_requested{};
    std::string value;
    bool inline_value = false;
    const size_t eq = a.find('=');
    if (a.compare(0, 2, "--") == 0 && eq != std::string::npos) {
      value = a.substr(eq + 1);
      a.erase(eq);
      inline_value = true;
    }
    if (std::find(flags.begin(), flags.end(), a) != flags.end()) {
      if (inline_value) fail("option " + a + " takes no value");
      args[a] = "1";
      continue;
    }
    if (std::find(keys.begin(), keys.end(), a) == keys.end()) unknown_option(a, keys, flags);
    if (args.count(a)) fail("option " + a + " given twice");
    if (!inline_value) {
      if (i + 1 >= argc) fail("option " + a + " needs a value");
      value = argv[++i];
    }
    args[a] = value;
  }
  if (args.count("--geometry")) {
    const std::string g = args["--geometry"];
    if (g != "hertz" && g != "flat-rounded" && g != "power-law" && g != "samples")
      fail("bad value for --geometry: '" + g + "' (known: hertz, flat-rounded, power-law, samples)");
  }
  return args;
}

int parse_int(const std::string &flag, const std::string &text, int lo, int hi) {
  const double v = parse_number(flag, text.c_str());
  if (!(v >= lo && v <= hi && v == std::floor(v)))
    fail("bad value for " + flag + ": need an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return int(v);
}

const std::vector<std::string> kSolveKeys = {"--geometry",
                                             "--Q-over-fP",
                                             "--sigma-over-fp0",
                                             "--a",
                                             "--p0",
                                             "--f",
                                             "--E-star",
                                             "--P",
                                             "--R",
                                             "--Q",
                                             "--sigma",
                                             "--points",
                                             "--digits",
                                             "--flat-over-a",
                                             "--flat-width",
                                             "--exponent",
                                             "--pressure-file",
                                             "--rtol",
                                             "--model",
                                             "--A",
                                             "--pad-bulk",
                                             "--fields",
                                             "--nu",
                                             "--fields-at"};  // issue 15

samples read_samples(const std::string &path, const file_reader &read) {
  try {
    return parse_samples(read(path, "--pressure-file"), path);
  } catch (const pressure_file_error &e) {
    fail(e.what());
  }
}

void check_samples_or_fail(const samples &s, double a) {
  try {
    check_samples(s, a);
  } catch (const pressure_file_error &e) {
    fail(e.what());
  }
}

[[noreturn]] void bad_sample(const samples &s, int ln, const std::string &rule) {
  fail(pressure_file_error(s, ln, rule).what());
}

bool is_dimensional(const Args &args) {
  return args.count("--P") || args.count("--R") || args.count("--A") || args.count("--Q") || args.count("--sigma");
}

// A status of a C call that takes the scene options: the C library checked
// the ranges; its message (hs_strerror) is printed after the options whose
// values it is about.
void check_input(int st, const Args &args, const std::string &what) {
  if (st == HS_OK) return;
  const bool dim = is_dimensional(args);
  std::string flags;
  switch (st) {
    case HS_ERR_GROSS_SLIDING: flags = dim ? "--Q" : "--Q-over-fP"; break;
    case HS_ERR_BAD_FRICTION: flags = "--f"; break;
    case HS_ERR_BAD_SIZE: flags = dim ? "--P, --R, --A or --E-star" : "--a, --p0 or --E-star"; break;
    case HS_ERR_BAD_GEOMETRY:  // a geometry parameter given (else: the model or geometry)
      for (const char *k : {"--flat-over-a", "--flat-width", "--exponent"})
        if (args.count(k)) flags = k;
      break;
    default: break;
  }
  if (!flags.empty()) fail("bad value for " + flags + ": " + hs_strerror(st));
  check(st, what);
}

// The scene and geometry of the solve/history options (geometry, sizes, loads);
// sx, sp hold the samples of --pressure-file. With `loads` false, the load
// options are not part of the command (history: the path gives them).
void scene_from_args(const Args &args, hs_scene &scene, hs_geometry &geo, std::vector<double> &sx,
                     std::vector<double> &sp, const file_reader &read, bool loads) {
  auto get = [&](const char *k, double def) { return args.count(k) ? parse_number(k, args.at(k).c_str()) : def; };
  const std::string geometry = args.count("--geometry") ? args.at("--geometry") : "hertz";
  hs_geometry_default(&geo);
  hs_scene_default(&scene);
  samples samp;
  if (geometry == "flat-rounded") {
    geo.kind = HS_GEOMETRY_FLAT_ROUNDED;
    if (args.count("--flat-over-a")) geo.flat_over_a = get("--flat-over-a", 0.5);
  } else if (geometry == "power-law") {
    geo.kind = HS_GEOMETRY_POWER_LAW;
    geo.exponent = get("--exponent", 2.0);
  } else if (geometry == "samples") {
    geo.kind = HS_GEOMETRY_SAMPLES;
    if (!args.count("--pressure-file")) fail("--geometry samples needs --pressure-file F (two columns x p)");
    samp = read_samples(args.at("--pressure-file"), read);
    sx = samp.x;
    sp = samp.p;
    geo.n_samples = sx.size();
    geo.sample_x = sx.data();
    geo.sample_p = sp.data();
  }
  for (const char *k : {"--flat-over-a", "--flat-width"})
    if (args.count(k) && geometry != "flat-rounded") fail(std::string(k) + " needs --geometry flat-rounded");
  if (args.count("--exponent") && geometry != "power-law") fail("--exponent needs --geometry power-law");
  if (args.count("--pressure-file") && geometry != "samples") fail("--pressure-file needs --geometry samples");
  if (is_dimensional(args)) {
    // dimensional input: P, E*, f, Q, sigma and the geometry's size parameters
    // (hertz: R; flat-rounded: corner radius R and --flat-width b_f; power-law: --A, --exponent n)
    const bool pl = geometry == "power-law";
    if (geometry != "hertz" && geometry != "flat-rounded" && !pl)
      fail("dimensional input (--P ...) is available for hertz, flat-rounded and power-law");
    for (const char *k : {"--P", "--E-star", "--f", "--Q", "--sigma", pl ? "--A" : "--R"})
      if (!args.count(k) && (loads || (std::strcmp(k, "--Q") != 0 && std::strcmp(k, "--sigma") != 0)))
        fail(std::string("dimensional input needs ") + k +
            (pl ? " (give --P --A --exponent --E-star --f --Q --sigma)"
                : " (give --P --R --E-star --f --Q --sigma)"));
    for (const char *k : {"--Q-over-fP", "--sigma-over-fp0", "--a", "--p0"})
      if (args.count(k)) fail(std::string(k) + " cannot be combined with dimensional --P/--Q/--sigma");
    if (pl && args.count("--R")) fail("--R is not a power-law parameter (the profile is --A |x|^--exponent)");
    if (!pl && args.count("--A")) fail("--A needs --geometry power-law");
    const double P = get("--P", 0), E = get("--E-star", 0), f = get("--f", 0);
    const double Q = get("--Q", 0), sg = get("--sigma", 0);
    // the C library checks the ranges; its message names the rule broken
    if (pl) {
      const double A = get("--A", 0);
      check_input(hs_scene_from_power_law_loads(P, A, geo.exponent, E, f, Q, sg, &scene), args);
    } else {
      const double R = get("--R", 0);
      if (geometry == "flat-rounded") {
        if (!args.count("--flat-width")) fail("dimensional flat-rounded input needs --flat-width (b_f)");
        if (args.count("--flat-over-a"))
          fail("--flat-over-a cannot be combined with dimensional input (give --flat-width)");
        const double bf = get("--flat-width", 0);
        check_input(hs_scene_from_flat_rounded_loads(P, R, bf, E, f, Q, sg, &scene, &geo.flat_over_a), args);
      } else {
        check_input(hs_scene_from_hertz_loads(P, R, E, f, Q, sg, &scene), args);
      }
    }
  } else {
    scene.Q_over_fP = loads ? get("--Q-over-fP", 0.5) : 0.0;
    scene.sigma_over_fp0 = loads ? get("--sigma-over-fp0", 0.5) : 0.0;
    scene.a = get("--a", 1.0);
    scene.p0 = get("--p0", 1.0);
    scene.f = get("--f", 1.0);
    scene.E_star = get("--E-star", 1.0);
    // the scene's ranges are checked by the C library when it solves (check_input);
    // the samples' rules are checked here, against a, to name the file's line
    if (geometry == "samples") {
      if (!(scene.a > 0)) fail("bad value for --a: must be > 0");
      check_samples_or_fail(samp, scene.a);
      // the library's remaining rules (the sqrt edge behaviour), with the sample they are about
      int verdict = HS_OK;
      size_t at = 0;
      char why[256];
      check(hs_check_samples(samp.x.size(), samp.x.data(), samp.p.data(), scene.a, &verdict, &at, why, sizeof why),
            "samples");
      if (verdict != HS_OK) {
        if (at < samp.x.size())
          bad_sample(samp, samp.line[at], "x = " + g10(samp.x[at]) + ", p = " + g10(samp.p[at]) + ": " + why);
        bad_sample(samp, samp.last_line, why);
      }
    }
  }
}

const std::vector<std::string> kHistoryKeys = {"--geometry",
                                               "--a",
                                               "--p0",
                                               "--f",
                                               "--E-star",
                                               "--P",
                                               "--R",
                                               "--A",
                                               "--flat-over-a",
                                               "--flat-width",
                                               "--exponent",
                                               "--pressure-file",
                                               "--path",
                                               "--digits",
                                               "--cycle",
                                               "--cycles",
                                               "--ramp",
                                               "--segments-per-cycle",
                                               "--max-step",
                                               "--points",
                                               "--steady-rtol",
                                               "--rtol",
                                               "--interior-patches",
                                               "--fields",
                                               "--fields-vertex",
                                               "--fields-at",
                                               "--pad-bulk",
                                               "--nu"};

const std::vector<std::string> kSolveFlags = {"--json", "--no-energy"};
const std::vector<std::string> kHistoryFlags = {"--json", "--surface-stress"};

solve_route solve_route_from_args(const Args &args) {
  solve_route r;
  // --rtol below double's rounding: the reference backend at that many digits
  if (args.count("--rtol")) {
    r.rtol = parse_number("--rtol", args.at("--rtol").c_str());
    if (!(r.rtol > 0 && r.rtol <= 0.5)) fail("bad value for --rtol: must lie in (0, 0.5]");
    if (r.rtol < std::ldexp(1.0, -53) && !args.count("--digits")) {
      if (args.count("--model")) fail("--rtol below 1.1e-16 needs the reference backend: drop --model");
      r.digits = int(std::ceil(-std::log10(r.rtol)));
      if (r.digits > hs_ref_max_digits()) fail("bad value for --rtol: beyond the reference backend's digits");
      return r;
    }
  }
  if (args.count("--digits")) r.digits = parse_int("--digits", args.at("--digits"), 1, hs_ref_max_digits());
  return r;
}

void solve_options_from_args(const Args &args, const solve_route &route, hs_options &opts, int &points) {
  points = args.count("--points") ? parse_int("--points", args.at("--points"), 0, 100000) : 0;
  hs_options_default(&opts);
  if (args.count("--model")) {
    if (hs_model_from_name(args.at("--model").c_str(), &opts.model) != HS_OK) {
      std::string names;
      for (int m = 0; hs_model_name(m); ++m)
        names += std::string(m == 0 ? "" : hs_model_name(m + 1) ? ", " : " or ") + hs_model_name(m);
      fail("bad value for --model: '" + args.at("--model") + "' (known: " + names + ")");
    }
  } else if (args.count("--rtol")) {
    opts.model = HS_MODEL_AUTO;
  }
  opts.rtol = route.rtol;
}

}  // namespace halfslip_cli
