// The `halfslip` command, through the C ABI only:
//   halfslip solve [options]   one scene (double, or --digits N with the MPFR reference)
//   halfslip table [options]   high-precision benchmark table over a grid (reference)
#include <halfslip/halfslip.h>

#include "args.hpp"
#include "pressure_file.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <algorithm>
#include <array>
#include <atomic>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

namespace {

using halfslip_cli::Args;
using halfslip_cli::check;
using halfslip_cli::check_input;
using halfslip_cli::is_dimensional;
using halfslip_cli::kHistoryFlags;
using halfslip_cli::kHistoryKeys;
using halfslip_cli::kSolveFlags;
using halfslip_cli::kSolveKeys;
using halfslip_cli::parse_args;
using halfslip_cli::parse_int;
using halfslip_cli::parse_number;
using halfslip_cli::scene_from_args;

const char *kUsage =
    "usage: halfslip solve [options]\n"
    "  Solves a half-plane partial-slip contact (constant normal load, shear\n"
    "  force Q, differential bulk tension sigma). Conventions: docs/conventions.md.\n"
    "options (dimensionless; a = p0 = f = E* = 1 unless given):\n"
    "  --geometry G            hertz (default), flat-rounded, power-law, samples\n"
    "  --flat-over-a B         flat-rounded: flat half-width over contact half-width (default 0.5)\n"
    "  --exponent N            power-law: profile g = A|x|^N, N > 1 (default 2)\n"
    "  --pressure-file F       samples: the pressure p at x, one sample per line (see below)\n"
    "  --Q-over-fP X           shear force ratio Q/(fP), |X| < 1   (default 0.5)\n"
    "  --sigma-over-fp0 Y      bulk tension ratio sigma/(f p0)      (default 0.5)\n"
    "  --a A --p0 P0 --f F --E-star E   scales\n"
    "options (dimensional Hertz; all six together, in one consistent set of units, e.g. SI):\n"
    "  --P P --R R --E-star E --f F --Q Q --sigma S\n"
    "  (plane strain: P and Q are forces per unit length of the contact, e.g. N/m; R a length;\n"
    "   E* and sigma stresses, e.g. Pa; the report gives lengths, stresses and energies per\n"
    "   unit length in the same units)\n"
    "  (flat-rounded: the same with R the corner radius, plus --flat-width b_f;\n"
    "   power-law: --P --A A --exponent N --E-star E --f F --Q Q --sigma S, profile g = A|x|^N)\n"
    "model (docs/models.md):\n"
    "  --rtol R                the cheapest model whose error estimate (largest relative error of\n"
    "                          d1, d2 and the zone energies) is <= R: asymptotic edge model, closed\n"
    "                          forms or quadrature, reference; R below 1.1e-16 runs the reference\n"
    "                          backend at -log10(R) digits (as --digits)\n"
    "  --model M               force a model: default, asymptotic, closed-form, quadrature, reference\n"
    "output:\n"
    "  --points N              also tabulate B_x, slip h and work W at N points per slip zone\n"
    "  --json                  one JSON object, numbers with 17 significant digits\n"
    "  --pad-bulk S            bulk stress the pad (body 2) carries; the specimen carries sigma + S\n"
    "                          (default 0). Surface stress peaks are in the report and the JSON\n"
    "  --fields FILE           write the stresses of both bodies on a grid |x| <= 2a, |y| <= 2a\n"
    "                          (and the surface, y = 0) as CSV: body,x,y,sxx,syy,sxy,max_principal,\n"
    "                          max_shear,von_mises (plane strain)\n"
    "  --nu V                  Poisson's ratio for von Mises in --fields (default 0.3)\n"
    "  --fields-at PTS         with --fields: the points of file PTS instead of the grid, one\n"
    "                          'x y' per line (whitespace or a comma; '#' comments; a header line);\n"
    "                          y >= 0 is body 1 (specimen), y < 0 body 2 (pad); an optional third\n"
    "                          column 'x y body' (1 or 2) names the body (the pad's surface: y = 0, 2).\n"
    "                          With --digits (no --fields): sxx, syy, sxy at each point to N digits\n"
    "                          with their certified digits, in the report and the JSON (\"fields\");\n"
    "                          --pad-bulk is then read as an exact decimal\n"
    "  --no-energy             skip the zone energies (the slow part with --digits; null in JSON)\n"
    "  --digits N              reference backend (MPFR): every output to N significant digits\n"
    "                          with its certified digit count; inputs are read as exact decimals\n"
    "                          (hertz: N <= 390; flat-rounded, power-law: N <= 170, dimensionless)\n"
    "pressure file (--geometry samples --pressure-file F):\n"
    "  two columns x p per line, separated by spaces, tabs or one comma (CSV); '#' starts a\n"
    "  comment; blank lines are skipped; the first line may be a header (e.g. 'x,p'). Rules:\n"
    "  at least 6 samples; x finite and strictly increasing within [-a, a]; p finite, > 0\n"
    "  inside the contact, 0 at x = -a or a if sampled, sqrt-like near the edges. A file\n"
    "  breaking a rule is rejected with its line number and the rule.\n"
    "\n"
    "usage: halfslip table --Q-over-fP LIST --sigma-over-fp0 LIST [--digits N] [--format csv|jsonl]\n"
    "                      [--threads T] [--shard K/N] [--no-energy] [--progress] [--a A --p0 P0 --f F --E-star E]\n"
    "                      [--geometry flat-rounded --flat-over-a LIST | --geometry power-law --exponent LIST]\n"
    "  High-precision benchmark table over the grid LIST x LIST (reference backend);\n"
    "  for a non-Hertz geometry also over its parameter (first column, outermost loop).\n"
    "  LIST is v1,v2,... or start:step:count (exact decimal arithmetic).\n"
    "  --shard K/N writes the K-th of N contiguous blocks of rows; the N outputs\n"
    "  concatenated in order equal the unsharded output (CSV header in shard 1 only).\n"
    "  The first line records the provenance: CSV '# halfslip VERSION, N significant digits ...,\n"
    "  command: ...', JSONL {\"provenance\": {\"halfslip\", \"digits\", \"energy\", \"command\"}}.\n"
    "  --progress (or stderr being a terminal) prints rows done on stderr.\n"
    "\n"
    "usage: halfslip history (--path \"Q1,S1;Q2,S2;...\" | --cycle Qm,Qa,Sm,Sa,phase_deg [--cycles N]) [options]\n"
    "  Load history at constant normal load (docs/history.md): from (0, 0), (Q, sigma) moves along\n"
    "  straight segments to each vertex; or periodic Q = Qm + Qa sin wt, sigma = Sm + Sa sin(wt + phase).\n"
    "  Loads are ratios Q/fP, sigma/(f p0), or forces per unit length and stresses with the dimensional\n"
    "  options (--P --R --E-star --f; no --Q/--sigma). Geometry and scale options as for solve.\n"
    "  A path along one ray through the origin is solved by superposition; a path whose segments all\n"
    "  advance (no zone recedes) by one static solve per segment; any other by the march (\"method\").\n"
    "  --digits N              certified digits (reference backend) for a --path along one ray\n"
    "  --cycles N              number of cycles (default 10)\n"
    "  --ramp R                how the cycle is reached from zero: sigma-first (default), together, q-first\n"
    "  --segments-per-cycle M  chords per cycle when Q and sigma are out of phase (default 64)\n"
    "  --max-step H            first load step in max(|dQ/fP|, |dsigma/fp0|/4) (default 1/32)\n"
    "  --rtol R                halve the step until steps h and 2h agree to R (default 1e-8; 0: fixed)\n"
    "  --steady-rtol R         steady when zone ends and energies repeat to R (default 1e-6)\n"
    "  --interior-patches P    error (default): stop where a third slip zone would open inside the stick\n"
    "                          zone; merge: merge it with the edge zone (approximate, counted per vertex)\n"
    "  --points N              q(x) and slip h(x) at N points across the contact (and the slip range)\n"
    "  --json                  one object: vertices (b1, b2, slip_dir1/2, energy1/2 per segment),\n"
    "                          cycles_to_steady, energy_per_cycle1/2\n"
    "  --surface-stress        peak surface sigma_xx of both bodies at every vertex (JSON \"surface_stress\"\n"
    "                          per vertex; text: a column per body; costs a panel cache per vertex)\n"
    "  --fields FILE           stresses of both bodies in the state after a vertex, CSV as solve --fields\n"
    "  --fields-vertex I       that vertex, 1 to N as in the table (default N, the last)\n"
    "  --fields-at PTS         with --fields: the points of file PTS ('x y' per line) instead of the grid\n"
    "  --pad-bulk S, --nu V    as for solve (the pad's bulk stress; Poisson's ratio for von Mises)\n"
    "\n"
    "usage: halfslip asymptotic-error --loading shear|bulk --b-over-a X [--json]\n"
    "  Energy dissipated in one slip zone: asymptotic edge model vs full Hertz solution\n"
    "  at the same load (the load that gives slip zone b/a in the full solution).\n"
    "\n"
    "Every option is given as --opt value or --opt=value. halfslip --version prints the version.\n";

[[noreturn]] void die(const std::string &msg) {
  std::fprintf(stderr, "halfslip: %s\n", msg.c_str());
  std::exit(2);
}


std::string num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string g10(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

const char *regime_name(int r) {
  switch (r) {
    case HS_REGIME_STUCK: return "stuck";
    case HS_REGIME_SAME_SIGN: return "same-sign";
    case HS_REGIME_OPPOSITE_SIGN: return "opposite-sign";
    case HS_REGIME_BOUNDARY: return "boundary";
    default: return "unknown";
  }
}


using Args = std::map<std::string, std::string>;



// The command line as one string (for provenance), leaving out the options in skip.
std::string command_line(int argc, char **argv, const std::vector<std::string> &skip) {
  std::string out = "halfslip";
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    const std::string key = a.substr(0, a.find('='));
    if (std::find(skip.begin(), skip.end(), key) != skip.end()) {
      if (key == a && i + 1 < argc) ++i;  // "--key value": skip the value too
      continue;
    }
    const bool plain = !a.empty() && a.find_first_not_of(
                                         "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                         "0123456789_./:=,+-@%") == std::string::npos;
    if (!plain) {  // shell-quoted, so that the line can be run again
      std::string q = "'";
      for (const char c : a) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
      a = q + "'";
    }
    out += " " + a;
  }
  return out;
}



// Check a decimal argument (finite number) and keep its exact text.
std::string decimal_arg(const Args &args, const char *k, const char *def) {
  auto it = args.find(k);
  if (it == args.end()) return def;
  parse_number(k, it->second.c_str());
  return it->second;
}

std::string json_str(const std::string &s) { return "\"" + s + "\""; }

std::string json_escape(const std::string &s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
      continue;
    }
    out += c;
  }
  return out + "\"";
}

// ---------------------------------------------------------------- solve

// Pressure samples (--pressure-file): the parser and its rules are in
// pressure_file.cpp (shared with its fuzz target, tests/fuzz/fuzz_pressure_file.cpp);
// a rejection there is a pressure_file_error naming the file, the line and the rule.
using halfslip_cli::content_of_line;
using halfslip_cli::is_number;
using halfslip_cli::samples;
using halfslip_cli::split_fields;
using halfslip_cli::trim;

// The whole file named by the option flag (or die naming both).
std::string read_whole_file(const std::string &path, const char *flag) {
  FILE *f = std::fopen(path.c_str(), "r");
  if (!f) die(std::string("bad value for ") + flag + ": cannot open '" + path + "'");
  std::string all;
  char buf[4096];
  for (size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) all.append(buf, n);
  std::fclose(f);
  return all;
}






void check_dimensional(const Args &args) {
  for (const char *k : {"--P", "--R", "--E-star", "--f", "--Q", "--sigma"})
    if (!args.count(k)) die(std::string("dimensional input needs ") + k + " (give --P --R --E-star --f --Q --sigma)");
  for (const char *k : {"--Q-over-fP", "--sigma-over-fp0", "--a", "--p0"})
    if (args.count(k)) die(std::string(k) + " cannot be combined with dimensional --P/--R/--Q/--sigma");
}

// Reference-backend geometry: HS_GEOMETRY_* of --geometry (hertz, flat-rounded,
// power-law), after checking that only its own parameter option is given.
int ref_geometry_kind(const Args &args, const char *what) {
  const std::string g = args.count("--geometry") ? args.at("--geometry") : "hertz";
  if (g == "samples")
    die(std::string(what) + ": the reference backend supports --geometry hertz, flat-rounded and power-law");
  if (args.count("--flat-over-a") && g != "flat-rounded") die("--flat-over-a needs --geometry flat-rounded");
  if (args.count("--exponent") && g != "power-law") die("--exponent needs --geometry power-law");
  if (args.count("--flat-width") && g != "flat-rounded") die("--flat-width needs --geometry flat-rounded");
  if (args.count("--pressure-file")) die("--pressure-file needs --geometry samples (not available with --digits)");
  return g == "flat-rounded" ? HS_GEOMETRY_FLAT_ROUNDED
         : g == "power-law"  ? HS_GEOMETRY_POWER_LAW
                             : HS_GEOMETRY_HERTZ;
}

// A geometry parameter value (exact decimal text) in its range, else die
// (table: the whole grid is checked before the first, possibly long, solve).
void check_geometry_param(int kind, const char *flag, const std::string &v) {
  const double x = parse_number(flag, v.c_str());
  if (kind == HS_GEOMETRY_FLAT_ROUNDED && !(x >= 0 && x < 1))
    die(std::string("bad value for ") + flag + ": need 0 <= b_f/a < 1");
  if (kind == HS_GEOMETRY_POWER_LAW && !(x > 1 && x < 1000))
    die(std::string("bad value for ") + flag + ": need 1 < n < 1000");
}

void check_ref_digits(int kind, int digits, const std::string &flag) {
  const int cap = hs_ref_max_digits_geometry(kind);
  if (digits > cap)
    die("bad value for " + flag + ": at most " + std::to_string(cap) +
        " digits for a non-Hertz geometry (its solve costs about D^3; docs/reference.md)");
}

const char *ref_geometry_name(int kind) {
  return kind == HS_GEOMETRY_FLAT_ROUNDED ? "flat-rounded" : kind == HS_GEOMETRY_POWER_LAW ? "power-law" : "hertz";
}

// --fields-at FILE: points 'x y' per line (whitespace or one comma, '#' comments,
// blank lines, a header line first), optionally a third column body (1 or 2;
// default 1 for y >= 0, 2 for y < 0); errors name the file and the line. The
// exact texts of x and y and the line numbers are kept for the reference backend.
struct field_points {
  std::string path;
  std::vector<double> x, y;
  std::vector<std::string> tx, ty;
  std::vector<int> body, line;
};

// A decimal text that is negative and not a zero ("-1e-400" is, "-0" is not;
// strtod rounds the former to -0)
bool negative_text(const std::string &t, double v) {
  if (v != 0) return v < 0;
  if (t.empty() || t[0] != '-') return false;
  for (const char c : t) {
    if (c == 'e' || c == 'E') break;
    if (c >= '1' && c <= '9') return true;
  }
  return false;
}

field_points read_points(const std::string &path) {
  field_points fp;
  fp.path = path;
  const std::string all = read_whole_file(path, "--fields-at");
  size_t pos = 0;
  int ln = 0;
  bool header_allowed = true;
  while (pos < all.size()) {
    size_t nl = all.find('\n', pos);
    if (nl == std::string::npos) nl = all.size();
    std::string t = all.substr(pos, nl - pos);
    pos = nl + 1;
    ++ln;
    if (!content_of_line(t)) continue;
    const std::vector<std::string> fl = split_fields(t);
    const std::string where = "--fields-at " + path + ": line " + std::to_string(ln) + ": ";
    double x = 0, y = 0;
    if (header_allowed && !is_number(fl[0], x)) {
      header_allowed = false;
      continue;
    }
    header_allowed = false;
    if (fl.size() != 2 && fl.size() != 3)
      die(where + std::to_string(fl.size()) + " columns, expected 2 (x y) or 3 (x y body)");
    if (!is_number(fl[0], x)) die(where + "x '" + fl[0] + "' is not a number");
    if (!is_number(fl[1], y)) die(where + "y '" + fl[1] + "' is not a number");
    if (!std::isfinite(x) || !std::isfinite(y)) die(where + "the point is not finite");
    int body = negative_text(fl[1], y) ? 2 : 1;
    if (fl.size() == 3) {
      if (fl[2] != "1" && fl[2] != "2") die(where + "body '" + fl[2] + "' is not 1 (specimen) or 2 (pad)");
      body = fl[2][0] - '0';
    }
    fp.x.push_back(x);
    fp.y.push_back(y);
    fp.tx.push_back(fl[0]);
    fp.ty.push_back(fl[1]);
    fp.body.push_back(body);
    fp.line.push_back(ln);
  }
  if (fp.x.empty()) die("--fields-at " + path + ": no points");
  return fp;
}

// A status of the library at the i-th point of --fields-at, naming the line and the value
[[noreturn]] void point_error(const field_points &fp, size_t i, int st) {
  const std::string where = "--fields-at " + fp.path + ": line " + std::to_string(fp.line[i]) + ": ";
  if (st == HS_ERR_BAD_OPTION)  // the library's check of the body's side
    die(where + "y = " + fp.ty[i] + " is not in body " + std::to_string(fp.body[i]) +
        (fp.body[i] == 1 ? " (the specimen, y >= 0)" : " (the pad, y <= 0)") + ": " + hs_strerror(st));
  die(where + "x = " + fp.tx[i] + ", y = " + fp.ty[i] + ": " + hs_strerror(st));
}

// One certified decimal string and its certified digits
struct certified_text {
  std::string text;
  int digits = 0;
};

// --digits with --fields-at PTS: sigma_xx, sigma_yy, sigma_xy at each point of the file,
// from hs_ref_eval_stress (the exact decimal texts of the file and of --pad-bulk)
std::vector<std::array<certified_text, 3>> reference_fields(const hs_ref_solution *sol, const field_points &fp,
                                                            const std::string &pad_bulk, int digits) {
  std::vector<std::array<certified_text, 3>> out(fp.x.size());
  std::vector<char> buf(size_t(digits) + 64);
  for (size_t i = 0; i < fp.x.size(); ++i)
    for (int c = HS_STRESS_XX; c <= HS_STRESS_XY; ++c) {
      int cd = 0;
      size_t needed = 0;
      int st = hs_ref_eval_stress(sol, fp.body[i], pad_bulk.c_str(), c, fp.tx[i].c_str(), fp.ty[i].c_str(),
                                  buf.data(), buf.size(), &needed, &cd);
      if (st == HS_ERR_BUFFER_TOO_SMALL) {
        buf.resize(needed);
        st = hs_ref_eval_stress(sol, fp.body[i], pad_bulk.c_str(), c, fp.tx[i].c_str(), fp.ty[i].c_str(), buf.data(),
                                buf.size(), &needed, &cd);
      }
      if (st != HS_OK) point_error(fp, i, st);
      out[i][size_t(c - 1)] = {buf.data(), cd};
    }
  return out;
}

// The reference scene's contact from the arguments: geometry and its parameter,
// f, E*, as exact decimal texts kept in `in` (sc points into it).
void ref_contact(const Args &args, int kind, std::map<std::string, std::string> &in, hs_ref_scene &sc) {
  hs_ref_scene_default(&sc);
  sc.geometry = kind;
  if (kind == HS_GEOMETRY_FLAT_ROUNDED) {
    in["flat_over_a"] = decimal_arg(args, "--flat-over-a", "0.5");
    sc.flat_over_a = in["flat_over_a"].c_str();
  } else if (kind == HS_GEOMETRY_POWER_LAW) {
    in["exponent"] = decimal_arg(args, "--exponent", "2");
    sc.exponent = in["exponent"].c_str();
  }
  in["f"] = decimal_arg(args, "--f", "1");
  in["E_star"] = decimal_arg(args, "--E-star", "1");
  sc.f = in["f"].c_str();
  sc.E_star = in["E_star"].c_str();
}

int solve_reference(const Args &args, int digits) {
  if (args.count("--points"))
    die("--points is not available with --digits (the C ABI's hs_ref_eval, Python's ReferenceSolution.traction)");
  if (args.count("--fields"))
    die("--fields FILE is not available with --digits: give the points with --fields-at PTS (the certified "
        "stresses are in the report and the JSON)");
  if (args.count("--nu")) die("--nu is not available with --digits (the reference backend gives sxx, syy, sxy)");
  if (args.count("--pad-bulk") && !args.count("--fields-at")) die("--pad-bulk with --digits needs --fields-at PTS");
  const bool json = args.count("--json") > 0;
  const int kind = ref_geometry_kind(args, "--digits");
  if (kind != HS_GEOMETRY_HERTZ && (is_dimensional(args) || args.count("--flat-width")))
    die("dimensional input with --digits is available for --geometry hertz only");
  check_ref_digits(kind, digits, "--digits");
  // exact decimal texts of the inputs
  std::map<std::string, std::string> in;
  hs_ref_scene sc;
  ref_contact(args, kind, in, sc);
  if (is_dimensional(args)) {
    check_dimensional(args);
    for (const char *k : {"--P", "--R", "--Q", "--sigma"}) in[k + 2] = decimal_arg(args, k, "");
    sc.P = in["P"].c_str();
    sc.R = in["R"].c_str();
    sc.Q = in["Q"].c_str();
    sc.sigma = in["sigma"].c_str();
  } else {
    in["Q_over_fP"] = decimal_arg(args, "--Q-over-fP", "0.5");
    in["sigma_over_fp0"] = decimal_arg(args, "--sigma-over-fp0", "0.5");
    in["a"] = decimal_arg(args, "--a", "1");
    in["p0"] = decimal_arg(args, "--p0", "1");
    sc.a = in["a"].c_str();
    sc.p0 = in["p0"].c_str();
    sc.Q_over_fP = in["Q_over_fP"].c_str();
    sc.sigma_over_fp0 = in["sigma_over_fp0"].c_str();
  }
  // --fields-at: read (and check) the points before the solve; the pad's bulk stress as given
  const bool fields = args.count("--fields-at") > 0;
  field_points fp;
  if (fields) fp = read_points(args.at("--fields-at"));
  const std::string pad_bulk = decimal_arg(args, "--pad-bulk", "0");
  hs_ref_solution *sol = nullptr;
  check_input(hs_ref_solve(&sc, digits, &sol), args, "reference solve");  // the C library checks the ranges
  hs_ref_summary sm;
  sm.struct_size = sizeof sm;
  check(hs_ref_solution_summary(sol, &sm), "summary");
  struct item {
    const char *key;
    int id;
  };
  std::vector<item> items = {{"a", HS_REF_A},   {"p0", HS_REF_P0}, {"b1", HS_REF_B1},
                             {"b2", HS_REF_B2}, {"d1", HS_REF_D1}, {"d2", HS_REF_D2}};
  if (!args.count("--no-energy")) {  // the zone energies are the slow part (docs/reference.md)
    items.push_back({"energy1", HS_REF_ENERGY1});
    items.push_back({"energy2", HS_REF_ENERGY2});
  }
  std::vector<std::pair<std::string, int>> vals;
  std::vector<char> buf(size_t(digits) + 64);
  for (const auto &it : items) {
    int cd = 0;
    check(hs_ref_value(sol, it.id, buf.data(), buf.size(), nullptr, &cd), it.key);
    vals.emplace_back(buf.data(), cd);
  }
  std::vector<std::array<certified_text, 3>> stress;
  if (fields) stress = reference_fields(sol, fp, pad_bulk, digits);
  hs_ref_solution_free(sol);
  static const char *const comp[3] = {"sxx", "syy", "sxy"};
  if (json) {
    std::printf(
        "{\"geometry\": \"%s\", \"regime\": \"%s\", \"digits\": %d, \"working_digits\": %d, "
        "\"slip_dir1\": %d, \"slip_dir2\": %d",
        ref_geometry_name(kind), regime_name(sm.regime), digits, sm.working_digits, sm.slip_dir1, sm.slip_dir2);
    std::printf(", \"inputs\": {");
    bool first = true;
    for (const auto &kv : in) {
      if (kv.second.empty()) continue;
      std::printf("%s\"%s\": %s", first ? "" : ", ", kv.first.c_str(), json_str(kv.second).c_str());
      first = false;
    }
    std::printf("}");
    for (size_t i = 0; i < vals.size(); ++i)
      std::printf(", \"%s\": %s, \"%s_digits\": %d", items[i].key, json_str(vals[i].first).c_str(), items[i].key,
                  vals[i].second);
    if (fields) {
      std::printf(", \"pad_bulk\": %s, \"fields\": [", json_escape(pad_bulk).c_str());
      for (size_t i = 0; i < stress.size(); ++i) {
        std::printf("%s{\"x\": %s, \"y\": %s, \"body\": %d", i ? ", " : "", json_escape(fp.tx[i]).c_str(),
                    json_escape(fp.ty[i]).c_str(), fp.body[i]);
        for (int c = 0; c < 3; ++c)
          std::printf(", \"%s\": %s, \"%s_digits\": %d", comp[c], json_str(stress[i][c].text).c_str(), comp[c],
                      stress[i][c].digits);
        std::printf("}");
      }
      std::printf("]");
    }
    std::printf("}\n");
  } else {
    std::printf("halfslip %s reference backend: %s contact, %d significant digits\n", hs_version_string(),
                kind == HS_GEOMETRY_HERTZ ? "Hertz" : ref_geometry_name(kind), digits);
    std::printf("  (working precision %d digits, certified against a %d-digit run)\n", sm.working_digits,
                sm.check_digits);
    for (const auto &kv : in)
      if (!kv.second.empty()) std::printf("  %s = %s\n", kv.first.c_str(), kv.second.c_str());
    std::printf("regime: %s, slip directions %+d (zone 1), %+d (zone 2)\n", regime_name(sm.regime), sm.slip_dir1,
                sm.slip_dir2);
    for (size_t i = 0; i < vals.size(); ++i)
      std::printf("  %-8s = %s   [%d digits certified]\n", items[i].key, vals[i].first.c_str(), vals[i].second);
    if (fields) {
      std::printf("stresses at the points of %s (body 1: specimen, y >= 0; body 2: pad, y <= 0; pad bulk %s):\n",
                  fp.path.c_str(), pad_bulk.c_str());
      for (size_t i = 0; i < stress.size(); ++i) {
        std::printf("  x = %s, y = %s, body %d\n", fp.tx[i].c_str(), fp.ty[i].c_str(), fp.body[i]);
        for (int c = 0; c < 3; ++c)
          std::printf("    %-4s = %s   [%d digits certified]\n", comp[c], stress[i][c].text.c_str(),
                      stress[i][c].digits);
      }
    }
  }
  return 0;
}

// the C library's model names (hs_model_name)
const char *model_name(int m) {
  const char *name = hs_model_name(m);
  return name ? name : "unknown";
}

// issue 15: --fields FILE, the stresses on a grid of both bodies (or at the points of
// --fields-at) as CSV (every number from the C library: components and scalars)
void write_fields(const hs_solution *sol, double a, double pad_bulk, double nu, const std::string &path,
                  const std::string &points_path) {
  const int kinds[3] = {HS_STRESS_MAX_PRINCIPAL, HS_STRESS_MAX_SHEAR, HS_STRESS_VON_MISES};
  std::string text = "body,x,y,sxx,syy,sxy,max_principal,max_shear,von_mises\n";
  char line[512];
  auto rows = [&](int b, const std::vector<double> &x, const std::vector<double> &y) {
    const size_t n = x.size();
    if (n == 0) return;
    std::vector<double> s(3 * n), sc(3 * n);
    check(hs_eval_stress(sol, b, pad_bulk, n, x.data(), y.data(), s.data()), "stress");
    for (int k = 0; k < 3; ++k)
      check(hs_eval_stress_scalar(sol, b, pad_bulk, kinds[k], nu, n, x.data(), y.data(), sc.data() + k * n),
            "--nu " + g10(nu));
    for (size_t i = 0; i < n; ++i) {
      std::snprintf(line, sizeof line, "%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", b, x[i], y[i],
                    s[3 * i], s[3 * i + 1], s[3 * i + 2], sc[i], sc[n + i], sc[2 * n + i]);
      text += line;
    }
  };
  if (!points_path.empty()) {
    const field_points fp = read_points(points_path);
    // in file order, each point in its body
    for (size_t i = 0; i < fp.x.size(); ++i) {
      const int b = fp.body[i];
      const double x = fp.x[i], y = fp.y[i];
      double s[3];
      const int st = hs_eval_stress(sol, b, pad_bulk, 1, &x, &y, s);
      if (st != HS_OK) point_error(fp, i, st);
      rows(b, {x}, {y});
    }
  } else {
    const int nx = 81, ny = 41;
    std::vector<double> x(nx), y(nx);
    for (int b = 1; b <= 2; ++b)
      for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
          x[i] = -2 * a + 4 * a * i / (nx - 1);
          y[i] = (b == 1 ? 1 : -1) * 2 * a * j / (ny - 1);
        }
        rows(b, x, y);
      }
  }
  FILE *out = std::fopen(path.c_str(), "w");
  if (!out) die("--fields: cannot write '" + path + "'");
  const bool ok = std::fwrite(text.data(), 1, text.size(), out) == text.size();
  if (std::fclose(out) != 0 || !ok) die("--fields: error writing '" + path + "'");
}


int cmd_solve(int argc, char **argv) {
  const Args args = parse_args(argc, argv, 2, kSolveKeys, kSolveFlags);
  const std::string geometry = args.count("--geometry") ? args.at("--geometry") : "hertz";
  // --rtol below double's rounding, or --digits: the reference backend
  const halfslip_cli::solve_route route = halfslip_cli::solve_route_from_args(args);
  if (route.digits > 0) return solve_reference(args, route.digits);
  const bool json = args.count("--json") > 0;
  hs_geometry geo;
  hs_scene scene;
  std::vector<double> sx, sp;
  scene_from_args(args, scene, geo, sx, sp, read_whole_file);
  int npts = 0;
  hs_options opts;
  halfslip_cli::solve_options_from_args(args, route, opts, npts);
  hs_solution *sol = nullptr;
  check_input(hs_solve_geometry(&scene, &geo, &opts, &sol), args, "solve");
  hs_summary sm;
  sm.struct_size = sizeof sm;
  check(hs_solution_summary(sol, &sm), "summary");
  const bool want_energy = !args.count("--no-energy");
  double energy[2] = {NAN, NAN};
  if (want_energy) check(hs_solution_energy(sol, energy), "energy");

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
  const double P = M_PI * sm.a * sm.p0 / 2;
  int recedes = 0;
  double recedes_at = 0;
  // the ramp note is extra: its failure (its monotonic solves along the ray, e.g. near
  // sliding where only the reference answered the scene) is reported, not fatal
  const int ramp_status = hs_solution_ramp(sol, &recedes, &recedes_at);

  // issue 15: peak surface stresses of each body (not for the reference model: its point
  // evaluations are too slow for the search) and the optional field grid
  const double pad_bulk = args.count("--pad-bulk") ? parse_number("--pad-bulk", args.at("--pad-bulk").c_str()) : 0.0;
  const bool have_surface = sm.model != HS_MODEL_REFERENCE;
  double surf[2][5] = {};
  if (have_surface)
    for (int b = 0; b < 2; ++b)
      check(hs_surface_stress_extremes(sol, b + 1, pad_bulk, 0.0, surf[b]), "surface stress");
  const double nu = args.count("--nu") ? parse_number("--nu", args.at("--nu").c_str()) : 0.3;
  if (args.count("--fields-at") && !args.count("--fields")) die("--fields-at needs --fields FILE (the output)");
  if (args.count("--fields"))
    write_fields(sol, sm.a, pad_bulk, nu, args.at("--fields"),
                 args.count("--fields-at") ? args.at("--fields-at") : "");

  if (json) {
    std::printf(
        "{\"geometry\": \"%s\", \"regime\": \"%s\", \"a\": %s, \"p0\": %s, \"P\": %s, \"f\": %s, "
        "\"E_star\": %s, \"Q_over_fP\": %s, \"sigma_over_fp0\": %s, \"b1\": %s, \"b2\": %s, "
        "\"d1\": %s, \"d2\": %s, \"slip_dir1\": %d, \"slip_dir2\": %d, \"energy1\": %s, "
        "\"energy2\": %s, \"iterations\": %d",
        geometry.c_str(), regime_name(sm.regime), num(sm.a).c_str(), num(sm.p0).c_str(), num(P).c_str(),
        num(scene.f).c_str(), num(scene.E_star).c_str(), num(scene.Q_over_fP).c_str(),
        num(scene.sigma_over_fp0).c_str(), num(sm.b1).c_str(), num(sm.b2).c_str(), num(sm.d1).c_str(),
        num(sm.d2).c_str(), sm.slip_dir1, sm.slip_dir2, want_energy ? num(energy[0]).c_str() : "null",
        want_energy ? num(energy[1]).c_str() : "null", sm.iterations);
    std::printf(", \"quadrature_order\": %d, \"model\": \"%s\", \"error_estimate\": %s", sm.quadrature_order,
                model_name(sm.model), num(sm.error_estimate).c_str());
    std::printf(", \"zone_resolution\": %s", num(sm.zone_resolution).c_str());
    if (ramp_status == HS_OK)
      std::printf(", \"ramp_recedes\": %s, \"ramp_recedes_at_Q_over_fP\": %s", recedes ? "true" : "false",
                  recedes ? num(recedes_at).c_str() : "null");
    else  // unknown: not decided
      std::printf(", \"ramp_recedes\": null, \"ramp_recedes_at_Q_over_fP\": null, \"ramp_error\": \"%s\"",
                  hs_strerror(ramp_status));
    if (have_surface) {
      std::printf(", \"surface_stress\": {");
      for (int b = 0; b < 2; ++b)
        std::printf("%s\"body%d\": {\"max\": %s, \"x_max\": %s, \"min\": %s, \"x_min\": %s, \"bulk\": %s}",
                    b ? ", " : "", b + 1, num(surf[b][0]).c_str(), num(surf[b][1]).c_str(), num(surf[b][2]).c_str(),
                    num(surf[b][3]).c_str(), num(surf[b][4]).c_str());
      std::printf("}");
    }
    if (!xs.empty()) {
      std::printf(", \"points\": [");
      for (size_t i = 0; i < xs.size(); ++i)
        std::printf("%s{\"x\": %s, \"Bx\": %s, \"h\": %s, \"W\": %s}", i ? ", " : "", num(xs[i]).c_str(),
                    num(B[i]).c_str(), num(h[i]).c_str(), num(W[i]).c_str());
      std::printf("]");
    }
    std::printf("}\n");
  } else {
    std::printf("halfslip %s: %s contact, constant normal load\n", hs_version_string(), geometry.c_str());
    if (geometry == "flat-rounded") std::printf("  flat half-width b_f/a = %.10g\n", geo.flat_over_a);
    if (geometry == "power-law") std::printf("  profile exponent n = %.10g\n", geo.exponent);
    if (geometry == "samples") std::printf("  %zu pressure samples\n", geo.n_samples);
    // Units: whatever consistent set the inputs use (SI: m, Pa, N/m); without
    // dimensional input, a = p0 = f = E* = 1 unless given (docs/conventions.md).
    const bool dim = is_dimensional(args);
    std::printf("  units: %s\n", dim ? "those of the inputs (SI inputs: lengths in m, p0 and E* in Pa, P in N/m)"
                                     : "dimensionless (lengths in units of a, stresses in units of p0 unless given)");
    std::printf("  a = %.10g [length], p0 = %.10g [stress], P = %.10g [force per unit length]\n", sm.a, sm.p0, P);
    std::printf("  f = %.10g, E* = %.10g [stress]\n", scene.f, scene.E_star);
    std::printf("  Q/fP = %.10g, sigma/(f p0) = %.10g (dimensionless)\n", scene.Q_over_fP, scene.sigma_over_fp0);
    std::printf("regime: %s\n", regime_name(sm.regime));
    std::printf("  stick zone (-b2, b1): b1/a = %.15g, b2/a = %.15g\n", sm.b1 / sm.a, sm.b2 / sm.a);
    std::printf("                        b1 = %.15g, b2 = %.15g [length]\n", sm.b1, sm.b2);
    std::printf("  slip zone 1 (b1, a):  d1/a = %.15g, slip direction %+d\n", sm.d1 / sm.a, sm.slip_dir1);
    std::printf("  slip zone 2 (-a,-b2): d2/a = %.15g, slip direction %+d\n", sm.d2 / sm.a, sm.slip_dir2);
    if (want_energy) {
      std::printf("energy dissipated (monotonic loading) [energy per unit length = force]:\n");
      std::printf("  zone 1: %.10g, zone 2: %.10g, total: %.10g\n", energy[0], energy[1], energy[0] + energy[1]);
    } else {
      std::printf("energy dissipated: not computed (--no-energy)\n");
    }
    if (sm.iterations) std::printf("  (Newton iterations: %d)\n", sm.iterations);
    if (sm.quadrature_order) std::printf("  (quadrature: Gauss-Legendre order %d per panel)\n", sm.quadrature_order);
    std::printf("model: %s, estimated error %.2g (largest relative error of d1, d2 and the energies)\n",
                model_name(sm.model), sm.error_estimate);
    if (sm.regime == HS_REGIME_BOUNDARY)
      std::printf(
          "note: slip zone %d is at or below the model's zone resolution %.2g a: it may be empty or slip\n"
          "  either way (the regime boundary), so its direction is reported as 0 and it is left out of the\n"
          "  estimate (docs/models.md)\n",
          sm.slip_dir1 == 0 ? 1 : 2, sm.zone_resolution / sm.a);
    if (ramp_status != HS_OK)
      std::printf("note: whether a proportional ramp from zero recedes a zone was not decided: %s\n",
                  hs_strerror(ramp_status));
    if (recedes)
      std::printf(
          "note: this is the monotonic state (every slip zone grown from zero). A proportional ramp from\n"
          "  zero to this load makes a slip zone recede from Q/fP = %.10g on, and reaches a different\n"
          "  state: use 'halfslip history --path \"%.10g,%.10g\"' (docs/history.md).\n",
          recedes_at, scene.Q_over_fP, scene.sigma_over_fp0);
    if (have_surface) {
      std::printf("surface direct stress sigma_xx(x, 0), |x| <= 3a (body 1 specimen y > 0, body 2 pad y < 0):\n");
      for (int b = 0; b < 2; ++b)
        std::printf("  body %d: max %.10g at x/a = %.6g, min %.10g at x/a = %.6g (bulk %.10g)\n", b + 1, surf[b][0],
                    surf[b][1] / sm.a, surf[b][2], surf[b][3] / sm.a, surf[b][4]);
    }
    if (!xs.empty()) {
      std::printf("%22s %22s %22s %22s\n", "x [length]", "B_x", "h [length]", "W [force/length]");
      for (size_t i = 0; i < xs.size(); ++i)
        std::printf("%22.15g %22.15g %22.15g %22.15g\n", xs[i], B[i], h[i], W[i]);
    }
  }
  hs_solution_free(sol);
  return 0;
}

// ---------------------------------------------------------------- history

// "Q1,S1;Q2,S2;..." -> pairs
std::vector<std::pair<double, double>> parse_path(const std::string &t) {
  std::vector<std::pair<double, double>> out;
  size_t p = 0;
  while (p <= t.size()) {
    const size_t q = t.find(';', p);
    std::string v = t.substr(p, q == std::string::npos ? std::string::npos : q - p);
    const size_t c = v.find(',');
    if (c == std::string::npos)
      die("bad value for --path: vertex " + std::to_string(out.size() + 1) + " '" + v + "' is not 'Q,sigma'");
    const std::string a = v.substr(0, c), b = v.substr(c + 1);
    out.emplace_back(parse_number("--path (vertex " + std::to_string(out.size() + 1) + ")", a.c_str()),
                     parse_number("--path (vertex " + std::to_string(out.size() + 1) + ")", b.c_str()));
    if (q == std::string::npos) break;
    p = q + 1;
  }
  return out;
}

// "Q1,S1;Q2,S2;..." -> the decimal texts of each vertex (for the reference backend)
std::vector<std::pair<std::string, std::string>> path_texts(const std::string &t) {
  std::vector<std::pair<std::string, std::string>> out;
  const auto nums = parse_path(t);  // the same checks and messages as the double path
  size_t p = 0;
  for (size_t i = 0; i < nums.size(); ++i) {
    const size_t q = t.find(';', p);
    const std::string v = t.substr(p, q == std::string::npos ? std::string::npos : q - p);
    const size_t c = v.find(',');
    auto trim = [](std::string x) {
      const size_t a = x.find_first_not_of(" \t"), b = x.find_last_not_of(" \t");
      return a == std::string::npos ? std::string() : x.substr(a, b - a + 1);
    };
    out.emplace_back(trim(v.substr(0, c)), trim(v.substr(c + 1)));
    p = q + 1;
  }
  return out;
}

// history --digits N --path ...: certified states along one ray (hs_ref_history_*)
int history_reference(const Args &args, bool json) {
  for (const char *k : {"--cycle", "--points", "--fields", "--surface-stress", "--max-step", "--rtol", "--pad-bulk",
                        "--nu"})
    if (args.count(k))
      die(std::string(k) + " is not available with --digits (certified histories: --path along one ray only)");
  if (!args.count("--path")) die("history --digits needs --path (a path along one ray through the origin)");
  const int kind = ref_geometry_kind(args, "--digits");
  if (is_dimensional(args) || args.count("--flat-width"))
    die("history --digits takes the ratios (--path of Q/fP, sigma/fp0) and --a, --p0, --f, --E-star");
  const int digits = parse_int("--digits", args.at("--digits"), 1, hs_ref_max_digits());
  check_ref_digits(kind, digits, "--digits");
  std::map<std::string, std::string> in;
  hs_ref_scene sc;
  ref_contact(args, kind, in, sc);
  in["a"] = decimal_arg(args, "--a", "1");
  in["p0"] = decimal_arg(args, "--p0", "1");
  sc.a = in["a"].c_str();
  sc.p0 = in["p0"].c_str();
  const auto path = path_texts(args.at("--path"));
  hs_ref_history *h = nullptr;
  check_input(hs_ref_history_new(&sc, digits, &h), args, "reference history");
  for (size_t i = 0; i < path.size(); ++i) {
    const char *q = path[i].first.c_str(), *s = path[i].second.c_str();
    const int st = hs_ref_history_add_vertices(h, 1, &q, &s);
    if (st != HS_OK) {
      hs_ref_history_free(h);
      die("history --digits: vertex " + std::to_string(i + 1) + " (Q/fP = " + path[i].first +
          ", sigma/fp0 = " + path[i].second + "): " + hs_strerror(st) +
          (st == HS_ERR_NOT_APPLICABLE ? " (certified histories follow paths along one ray through the origin, "
                                         "with no zone receding on the ramp; drop --digits to march the path)"
                                       : ""));
    }
  }
  static const char *const keys[4] = {"b1", "b2", "energy1", "energy2"};
  static const int ids[4] = {HS_REF_B1, HS_REF_B2, HS_REF_ENERGY1, HS_REF_ENERGY2};
  std::vector<char> buf(size_t(digits) + 64);
  if (json)
    std::printf("{\"geometry\": \"%s\", \"digits\": %d, \"method\": \"superposition\", \"vertices\": [",
                ref_geometry_name(kind), digits);
  else {
    std::printf("halfslip %s reference backend: load history along one ray, %s contact, %d significant digits\n",
                hs_version_string(), kind == HS_GEOMETRY_HERTZ ? "Hertz" : ref_geometry_name(kind), digits);
    std::printf("  states are sums of certified monotonic solutions (docs/history.md); [n] = certified digits\n");
  }
  for (size_t i = 0; i < path.size(); ++i) {
    int d1 = 0, d2 = 0;
    check(hs_ref_history_slip_dirs(h, i, &d1, &d2), "slip directions");
    if (json)
      std::printf("%s{\"Q_over_fP\": %s, \"sigma_over_fp0\": %s, \"slip_dir1\": %d, \"slip_dir2\": %d",
                  i ? ", " : "", json_str(path[i].first).c_str(), json_str(path[i].second).c_str(), d1, d2);
    else
      std::printf("vertex %zu: Q/fP = %s, sigma/fp0 = %s, slip directions %+d, %+d\n", i + 1, path[i].first.c_str(),
                  path[i].second.c_str(), d1, d2);
    for (int k = 0; k < 4; ++k) {
      int cd = 0;
      check(hs_ref_history_value(h, i, ids[k], buf.data(), buf.size(), nullptr, &cd), keys[k]);
      if (json) std::printf(", \"%s\": %s, \"%s_digits\": %d", keys[k], json_str(buf.data()).c_str(), keys[k], cd);
      else std::printf("  %-8s = %s   [%d]\n", keys[k], buf.data(), cd);
    }
    if (json) std::printf("}");
  }
  if (json) std::printf("]}\n");
  hs_ref_history_free(h);
  return 0;
}

// what a failed march most likely met (the C ABI gives the status only)
// the library's own reason for a failed history call (hs_history_last_error), and what to try
std::string history_hint(const hs_history *h, int st, const hs_history_options &ho) {
  char why[512] = "";
  hs_history_last_error(h, why, sizeof why);
  std::string r = why[0] ? std::string(" (here: ") + why : std::string(" (");
  if (st == HS_ERR_NOT_APPLICABLE && ho.interior_patches == HS_PATCHES_ERROR && std::strstr(why, "interior"))
    r += std::string(why[0] ? "; " : "") +
         "--interior-patches merge merges it with the edge zone, an approximation counted per vertex";
  if (st == HS_ERR_NOT_APPLICABLE || st == HS_ERR_NO_CONVERGENCE)
    r += std::string(r.size() > 2 ? "; " : "") + "docs/history.md, Limits";
  r += ")";
  return r == " ()" ? std::string() : r;
}

int cmd_history(int argc, char **argv) {
  const Args args = parse_args(argc, argv, 2, kHistoryKeys, kHistoryFlags);
  const bool json = args.count("--json") > 0;
  if (args.count("--digits")) return history_reference(args, json);
  const bool want_surface = args.count("--surface-stress") > 0;
  for (const char *k : {"--fields-vertex", "--fields-at"})
    if (args.count(k) && !args.count("--fields")) die(std::string(k) + " needs --fields FILE (the output)");
  hs_steady_cycle closed;
  bool have_closed = false;
  if (args.count("--path") == args.count("--cycle"))
    die("history needs exactly one of --path \"Q1,S1;Q2,S2;...\" and --cycle Qm,Qa,Sm,Sa,phase_deg");
  for (const char *k : {"--cycles", "--ramp", "--segments-per-cycle", "--steady-rtol"})
    if (args.count(k) && !args.count("--cycle")) die(std::string(k) + " needs --cycle");
  hs_geometry geo;
  hs_scene scene;
  std::vector<double> sx, sp;
  scene_from_args(args, scene, geo, sx, sp, read_whole_file, false);
  const bool dim = is_dimensional(args);
  const double P = M_PI * scene.a * scene.p0 / 2;
  // dimensional loads (force per unit length, stress) -> ratios
  const double qs = dim ? 1 / (scene.f * P) : 1, ss = dim ? 1 / (scene.f * scene.p0) : 1;
  hs_history_options ho;
  hs_history_options_default(&ho);
  if (args.count("--max-step")) ho.max_step = parse_number("--max-step", args.at("--max-step").c_str());
  if (args.count("--rtol")) ho.rtol = parse_number("--rtol", args.at("--rtol").c_str());
  if (args.count("--segments-per-cycle"))
    ho.segments_per_cycle = parse_int("--segments-per-cycle", args.at("--segments-per-cycle"), 4, 100000);
  if (args.count("--steady-rtol")) ho.steady_rtol = parse_number("--steady-rtol", args.at("--steady-rtol").c_str());
  if (args.count("--interior-patches")) {
    const std::string r = args.at("--interior-patches");
    if (r == "error") ho.interior_patches = HS_PATCHES_ERROR;
    else if (r == "merge") ho.interior_patches = HS_PATCHES_MERGE;
    else die("bad value for --interior-patches: '" + r + "' (error or merge)");
  }
  if (args.count("--ramp")) {
    const std::string r = args.at("--ramp");
    if (r == "sigma-first") ho.ramp_order = HS_RAMP_SIGMA_FIRST;
    else if (r == "together") ho.ramp_order = HS_RAMP_TOGETHER;
    else if (r == "q-first") ho.ramp_order = HS_RAMP_Q_FIRST;
    else die("bad value for --ramp: '" + r + "' (sigma-first, together or q-first)");
  }
  hs_history *h = nullptr;
  check_input(hs_history_new(&scene, &geo, &ho, &h), args, "history");
  bool cyc = false;
  if (args.count("--path")) {
    const auto path = parse_path(args.at("--path"));
    for (size_t i = 0; i < path.size(); ++i) {
      const double q = path[i].first * qs, s = path[i].second * ss;
      const int st = hs_history_add_vertices(h, 1, &q, &s);
      if (st != HS_OK)
        die("history: vertex " + std::to_string(i + 1) + " (Q/fP = " + num(q) + ", sigma/fp0 = " + num(s) +
            "): " + hs_strerror(st) + history_hint(h, st, ho));
    }
  } else {
    const std::string t = args.at("--cycle");
    std::vector<double> c;
    size_t p = 0;
    while (p <= t.size()) {
      const size_t q = t.find(',', p);
      c.push_back(parse_number("--cycle", t.substr(p, q == std::string::npos ? std::string::npos : q - p).c_str()));
      if (q == std::string::npos) break;
      p = q + 1;
    }
    if (c.size() != 5) die("bad value for --cycle: need Qm,Qa,Sm,Sa,phase_deg (5 numbers)");
    const int n = args.count("--cycles") ? parse_int("--cycles", args.at("--cycles"), 1, 100000) : 10;
    const int st = hs_history_add_cycles(h, c[0] * qs, c[1] * qs, c[2] * ss, c[3] * ss, c[4], n);
    if (st != HS_OK) die(std::string("history: ") + hs_strerror(st) + history_hint(h, st, ho));
    cyc = true;
    // symmetric proportional cycling (zero means, in phase or anti-phase or one amplitude
    // zero): the closed form (Ciavarella-Jager) of the library, printed beside the march
    const double ph = std::fmod(std::fabs(c[4]), 180.0);
    if (c[0] == 0 && c[2] == 0 && (ph == 0 || c[1] == 0 || c[3] == 0) && (c[1] != 0 || c[3] != 0)) {
      hs_scene amp = scene;
      amp.Q_over_fP = c[1] * qs;
      amp.sigma_over_fp0 = c[3] * ss * std::cos(c[4] * M_PI / 180);
      hs_solution *ms = nullptr;
      if (hs_solve_geometry(&amp, &geo, nullptr, &ms) == HS_OK) {
        closed.struct_size = sizeof closed;
        if (hs_solution_steady_cycle(ms, &closed) == HS_OK) have_closed = true;
        hs_solution_free(ms);
      }
    }
  }
  size_t nv = 0;
  check(hs_history_vertex_count(h, &nv), "history");
  std::vector<hs_history_vertex> vs(nv);
  for (size_t i = 0; i < nv; ++i) {
    vs[i].struct_size = sizeof vs[i];
    check(hs_history_vertex_get(h, i, &vs[i]), "history");
  }
  hs_cycle_summary cs;
  cs.struct_size = sizeof cs;
  if (cyc) check(hs_history_cycle_summary(h, &cs), "history");
  const int npts = args.count("--points") ? parse_int("--points", args.at("--points"), 0, 100000) : 0;
  std::vector<double> xs;
  for (int i = 0; i < npts; ++i) xs.push_back(npts == 1 ? 0.0 : scene.a * (-1 + 2.0 * i / (npts - 1)));
  std::vector<double> qv(xs.size()), hv(xs.size()), dh(xs.size());
  if (cyc && !xs.empty()) check(hs_history_slip_range(h, xs.size(), xs.data(), dh.data()), "slip range");
  const std::string geometry = args.count("--geometry") ? args.at("--geometry") : "hertz";
  // issue 15: stresses of the states (hs_history_state: a solution handle per vertex)
  const double pad_bulk = args.count("--pad-bulk") ? parse_number("--pad-bulk", args.at("--pad-bulk").c_str()) : 0.0;
  const double nu = args.count("--nu") ? parse_number("--nu", args.at("--nu").c_str()) : 0.3;
  std::vector<std::array<double, 10>> surf(want_surface ? nv : 0);
  for (size_t i = 0; i < surf.size(); ++i) {
    hs_solution *st = nullptr;
    check(hs_history_state(h, i, &st), "history state");
    for (int b = 0; b < 2; ++b) {
      const int r = hs_surface_stress_extremes(st, b + 1, pad_bulk, 0.0, surf[i].data() + 5 * b);
      if (r != HS_OK) hs_solution_free(st);
      check(r, "surface stress (--pad-bulk " + g10(pad_bulk) + ")");
    }
    hs_solution_free(st);
  }
  if (args.count("--fields")) {
    if (nv == 0) die("--fields: the history has no vertex");
    const size_t iv = args.count("--fields-vertex")
                          ? size_t(parse_int("--fields-vertex", args.at("--fields-vertex"), 1, int(nv)))
                          : nv;
    hs_solution *st = nullptr;
    check(hs_history_state(h, iv - 1, &st), "history state");
    write_fields(st, scene.a, pad_bulk, nu, args.at("--fields"),
                 args.count("--fields-at") ? args.at("--fields-at") : "");
    hs_solution_free(st);
  }
  // how the history took its states (superposition, static solves, march)
  int method = HS_HISTORY_MARCH;
  hs_history_method(h, &method);
  const bool superposed = nv > 0 && method == HS_HISTORY_SUPERPOSITION;
  const bool statics = nv > 0 && method == HS_HISTORY_STATIC;
  if (json) {
    // whole-path figures: the smallest step and the largest (per-segment) estimate
    double smin = nv ? vs[0].step : ho.max_step, emax = 0;
    for (const auto &v : vs) {
      smin = std::min(smin, v.step);
      emax = std::max(emax, v.error_estimate);
    }
    std::printf(
        "{\"geometry\": \"%s\", \"a\": %s, \"p0\": %s, \"P\": %s, \"f\": %s, \"E_star\": %s, "
        "\"rtol\": %s, \"method\": \"%s\", \"step\": %s, \"error_estimate\": %s, \"vertices\": [",
        geometry.c_str(), num(scene.a).c_str(), num(scene.p0).c_str(), num(P).c_str(), num(scene.f).c_str(),
        num(scene.E_star).c_str(), num(ho.rtol).c_str(), superposed ? "superposition" : statics ? "static" : "march",
        num(smin).c_str(),
        num(emax).c_str());
    for (size_t i = 0; i < nv; ++i) {
      const auto &v = vs[i];
      std::printf(
          "%s{\"Q_over_fP\": %s, \"sigma_over_fp0\": %s, \"b1\": %s, \"b2\": %s, \"slip_dir1\": %d, "
          "\"slip_dir2\": %d, \"energy1\": %s, \"energy2\": %s, \"cycle\": %d, \"steps\": %ld",
          i ? ", " : "", num(v.Q_over_fP).c_str(), num(v.sigma_over_fp0).c_str(), num(v.b1).c_str(),
          num(v.b2).c_str(), v.slip_dir1, v.slip_dir2, num(v.energy1).c_str(), num(v.energy2).c_str(), v.cycle,
          v.steps);
      std::printf(", \"step\": %s, \"error_estimate\": %s, \"interior_merges\": %ld", num(v.step).c_str(),
                  num(v.error_estimate).c_str(), v.interior_merges);
      // an interior slip zone open at the vertex (the static solves' two-interval solve)
      std::printf(", \"patch_dir\": %d, \"patch_l\": %s, \"patch_r\": %s, \"energy_patch\": %s", v.patch_dir,
                  v.patch_dir ? num(v.patch_l).c_str() : "null", v.patch_dir ? num(v.patch_r).c_str() : "null",
                  num(v.energy_patch).c_str());
      if (want_surface) {
        std::printf(", \"surface_stress\": {");
        for (int b = 0; b < 2; ++b)
          std::printf("%s\"body%d\": {\"max\": %s, \"x_max\": %s, \"min\": %s, \"x_min\": %s, \"bulk\": %s}",
                      b ? ", " : "", b + 1, num(surf[i][5 * b]).c_str(), num(surf[i][5 * b + 1]).c_str(),
                      num(surf[i][5 * b + 2]).c_str(), num(surf[i][5 * b + 3]).c_str(),
                      num(surf[i][5 * b + 4]).c_str());
        std::printf("}");
      }
      if (!xs.empty()) {
        check(hs_history_eval(h, i, HS_FIELD_TRACTION, xs.size(), xs.data(), qv.data()), "traction");
        check(hs_history_eval(h, i, HS_FIELD_SLIP, xs.size(), xs.data(), hv.data()), "slip");
        std::printf(", \"points\": [");
        for (size_t k = 0; k < xs.size(); ++k)
          std::printf("%s{\"x\": %s, \"q\": %s, \"h\": %s}", k ? ", " : "", num(xs[k]).c_str(), num(qv[k]).c_str(),
                      num(hv[k]).c_str());
        std::printf("]");
      }
      std::printf("}");
    }
    std::printf("]");
    if (cyc) {
      std::printf(
          ", \"cycles\": %d, \"cycles_to_steady\": %s, \"shakedown\": %s, \"energy_per_cycle1\": %s, "
          "\"energy_per_cycle2\": %s, \"energy_per_cycle_patch\": %s",
          cs.cycles, cs.cycles_to_steady < 0 ? "null" : std::to_string(cs.cycles_to_steady).c_str(),
          cs.shakedown ? "true" : "false", num(cs.energy_per_cycle1).c_str(), num(cs.energy_per_cycle2).c_str(),
          num(cs.energy_per_cycle_patch).c_str());
      std::printf(", \"cycles_repeated\": %d, \"repeated_change\": %s", cs.cycles_repeated,
                  num(cs.repeated_change).c_str());
      if (have_closed)
        std::printf(
            ", \"closed_form_valid\": %s, \"closed_form_energy_per_cycle1\": %s, "
            "\"closed_form_energy_per_cycle2\": %s",
            closed.valid ? "true" : "false", closed.valid ? num(closed.energy_per_cycle1).c_str() : "null",
            closed.valid ? num(closed.energy_per_cycle2).c_str() : "null");
      if (!xs.empty()) {
        std::printf(", \"slip_range\": [");
        for (size_t k = 0; k < xs.size(); ++k)
          std::printf("%s{\"x\": %s, \"dh\": %s}", k ? ", " : "", num(xs[k]).c_str(), num(dh[k]).c_str());
        std::printf("]");
      }
    }
    std::printf("}\n");
  } else {
    std::printf("halfslip %s: load history, %s contact, constant normal load\n", hs_version_string(),
                geometry.c_str());
    std::printf("  a = %.10g, p0 = %.10g, P = %.10g (per unit length), f = %.10g, E* = %.10g\n", scene.a, scene.p0, P,
                scene.f, scene.E_star);
    std::printf("  energies per unit length; stick zone (-b2, b1); slip direction 0: that edge does not slip\n");
    if (nv && superposed) {
      double emax = 0;
      for (const auto &v : vs) emax = std::max(emax, v.error_estimate);
      std::printf(
          "  a path along one ray: states by superposition of monotonic solutions (no march), estimated error "
          "%.2g\n",
          emax);
    } else if (statics) {
      std::printf(
          "  static solves, one per segment from the state before it (no march; docs/history.md), to within "
          "rtol %.2g\n",
          ho.rtol);
    } else if (nv) {
      double smin = vs[0].step, smax = vs[0].step, emax = 0;
      for (const auto &v : vs) {
        smin = std::min(smin, v.step);
        smax = std::max(smax, v.step);
        emax = std::max(emax, v.error_estimate);
      }
      std::printf(
          "  load steps %.6g to %.6g after refinement per segment, estimated error %.2g (rtol %.2g per segment)\n",
          smin, smax, emax, ho.rtol);
    }
    if (nv && vs.back().interior_merges > 0)
      std::printf("  APPROXIMATE: %ld interior slip patches merged with an edge zone (--interior-patches merge; "
                  "docs/history.md)\n",
                  vs.back().interior_merges);
    std::printf("%6s %5s %13s %13s %12s %12s %5s %5s %13s %13s %8s", "vertex", "cycle", "Q/fP", "sigma/fp0", "b1/a",
                "b2/a", "dir1", "dir2", "energy1", "energy2", "steps");
    if (want_surface) std::printf(" %13s %13s", "max sxx(1)", "max sxx(2)");
    std::printf("\n");
    for (size_t i = 0; i < nv; ++i) {
      const auto &v = vs[i];
      std::printf("%6zu %5d %13.6g %13.6g %12.8f %12.8f %+5d %+5d %13.6g %13.6g %8ld", i + 1, v.cycle, v.Q_over_fP,
                  v.sigma_over_fp0, v.b1 / scene.a, v.b2 / scene.a, v.slip_dir1, v.slip_dir2, v.energy1, v.energy2,
                  v.steps);
      if (want_surface) std::printf(" %13.6g %13.6g", surf[i][0], surf[i][5]);
      std::printf("\n");
      if (v.patch_dir != 0 || v.energy_patch != 0)
        std::printf("%6s interior slip zone: (%.8f, %.8f) a, direction %+d; energy %.6g\n", "", v.patch_l / scene.a,
                    v.patch_r / scene.a, v.patch_dir, v.energy_patch);
    }
    if (cyc) {
      std::printf("cycles: %d; steady from cycle %s%s\n", cs.cycles,
                  cs.cycles_to_steady < 0 ? "(not reached)" : std::to_string(cs.cycles_to_steady).c_str(),
                  cs.shakedown ? " (shakedown: no slip in the last cycle)" : "");
      std::printf("energy per cycle (last cycle): zone 1 %.10g, zone 2 %.10g", cs.energy_per_cycle1,
                  cs.energy_per_cycle2);
      if (cs.energy_per_cycle_patch != 0) std::printf(", interior slip zones %.10g", cs.energy_per_cycle_patch);
      std::printf("\n");
      if (cs.cycles_repeated > 0)
        std::printf(
            "the last %d cycle%s copies of the last cycle solved, which left the state as it found it (to %.2g; "
            "docs/history.md, \"The steady cycle\")\n",
            cs.cycles_repeated, cs.cycles_repeated > 1 ? "s are" : " is", cs.repeated_change);
      if (have_closed && closed.valid)
        std::printf("closed form (Ciavarella-Jager, steady from the first reversal): zone 1 %.10g, zone 2 %.10g\n",
                    closed.energy_per_cycle1, closed.energy_per_cycle2);
      else if (have_closed)
        std::printf("closed form (Ciavarella-Jager) does not apply: a zone recedes on the ramp\n");
    }
    if (!xs.empty()) {
      check(hs_history_eval(h, nv - 1, HS_FIELD_TRACTION, xs.size(), xs.data(), qv.data()), "traction");
      check(hs_history_eval(h, nv - 1, HS_FIELD_SLIP, xs.size(), xs.data(), hv.data()), "slip");
      std::printf("state after the last vertex:\n%22s %22s %22s%s\n", "x", "q", "h",
                  cyc ? "        slip range dh" : "");
      for (size_t k = 0; k < xs.size(); ++k) {
        std::printf("%22.15g %22.15g %22.15g", xs[k], qv[k], hv[k]);
        if (cyc) std::printf(" %22.15g", dh[k]);
        std::printf("\n");
      }
    }
  }
  hs_history_free(h);
  return 0;
}

// ---------------------------------------------------------------- table
// Exact decimal grid values: mantissa * 10^-scale with a 128-bit mantissa.
struct decimal {
  __int128 m = 0;
  int scale = 0;
};

decimal parse_decimal_exact(const std::string &flag, const std::string &t) {
  decimal d;
  size_t i = 0;
  bool neg = false, any = false, dot = false;
  if (i < t.size() && (t[i] == '-' || t[i] == '+')) neg = t[i++] == '-';
  for (; i < t.size(); ++i) {
    if (t[i] == '.' && !dot) {
      dot = true;
      continue;
    }
    if (!std::isdigit(static_cast<unsigned char>(t[i])))
      die("bad value for " + flag + ": '" + t + "' is not a plain decimal");
    if (d.m > (__int128(1) << 100)) die("bad value for " + flag + ": '" + t + "' has too many digits");
    d.m = d.m * 10 + (t[i] - '0');
    if (dot) ++d.scale;
    any = true;
  }
  if (!any) die("bad value for " + flag + ": '" + t + "' is not a number");
  if (neg) d.m = -d.m;
  return d;
}

std::string decimal_text(decimal d) {
  const bool neg = d.m < 0;
  __int128 m = neg ? -d.m : d.m;
  std::string s;
  do {
    s.insert(s.begin(), char('0' + int(m % 10)));
    m /= 10;
  } while (m > 0);
  if (d.scale > 0) {
    while (int(s.size()) <= d.scale) s.insert(s.begin(), '0');
    s.insert(s.end() - d.scale, '.');
  }
  return (neg ? "-" : "") + s;
}

std::vector<std::string> parse_list(const std::string &flag, const std::string &t) {
  std::vector<std::string> out;
  if (t.find(':') != std::string::npos) {
    const size_t c1 = t.find(':'), c2 = t.find(':', c1 + 1);
    if (c2 == std::string::npos) die("bad value for " + flag + ": use start:step:count");
    decimal a = parse_decimal_exact(flag, t.substr(0, c1)),
            h = parse_decimal_exact(flag, t.substr(c1 + 1, c2 - c1 - 1));
    const int n = parse_int(flag, t.substr(c2 + 1), 1, 100000);
    while (a.scale < h.scale) {
      a.m *= 10;
      ++a.scale;
    }
    while (h.scale < a.scale) {
      h.m *= 10;
      ++h.scale;
    }
    for (int i = 0; i < n; ++i) out.push_back(decimal_text({a.m + h.m * i, a.scale}));
  } else {
    size_t p = 0;
    while (p <= t.size()) {
      const size_t q = t.find(',', p);
      const std::string v = t.substr(p, q == std::string::npos ? std::string::npos : q - p);
      parse_number(flag, v.c_str());
      out.push_back(v);
      if (q == std::string::npos) break;
      p = q + 1;
    }
  }
  return out;
}

int cmd_table(int argc, char **argv) {
  const Args args = parse_args(argc, argv, 2,
                               {"--geometry", "--Q-over-fP", "--sigma-over-fp0", "--digits", "--format", "--threads",
                                "--shard", "--a", "--p0", "--f", "--E-star", "--flat-over-a", "--exponent"},
                               {"--no-energy", "--progress"});
  if (!args.count("--Q-over-fP") || !args.count("--sigma-over-fp0"))
    die("table needs --Q-over-fP LIST and --sigma-over-fp0 LIST");
  const auto qs = parse_list("--Q-over-fP", args.at("--Q-over-fP"));
  const auto ss = parse_list("--sigma-over-fp0", args.at("--sigma-over-fp0"));
  const int digits = args.count("--digits") ? parse_int("--digits", args.at("--digits"), 1, hs_ref_max_digits()) : 40;
  // geometry parameter: one value or a LIST (outermost loop); a leading column
  // for a non-Hertz geometry, so that Hertz tables keep their format
  const int kind = ref_geometry_kind(args, "table");
  check_ref_digits(kind, digits, "--digits");
  const char *pflag = kind == HS_GEOMETRY_FLAT_ROUNDED ? "--flat-over-a" : "--exponent";
  const char *pkey = kind == HS_GEOMETRY_FLAT_ROUNDED ? "flat_over_a" : "exponent";
  std::vector<std::string> gs{""};
  if (kind != HS_GEOMETRY_HERTZ) {
    gs = parse_list(pflag, args.count(pflag) ? args.at(pflag) : (kind == HS_GEOMETRY_FLAT_ROUNDED ? "0.5" : "2"));
    for (const auto &g : gs) check_geometry_param(kind, pflag, g);
  }
  const std::string fmt = args.count("--format") ? args.at("--format") : "csv";
  if (fmt != "csv" && fmt != "jsonl" && fmt != "json") die("bad value for --format: '" + fmt + "' (csv or jsonl)");
  const bool jsonl = fmt != "csv";
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  const int threads = args.count("--threads") ? parse_int("--threads", args.at("--threads"), 1, 1024) : int(hw);
  int shard = 1, nshards = 1;
  if (args.count("--shard")) {
    const std::string t = args.at("--shard");
    const size_t sl = t.find('/');
    if (sl == std::string::npos) die("bad value for --shard: use K/N");
    nshards = parse_int("--shard", t.substr(sl + 1), 1, 1000000);
    shard = parse_int("--shard", t.substr(0, sl), 1, nshards);
  }
  const bool energy = !args.count("--no-energy");
  const std::string a = decimal_arg(args, "--a", "1"), p0 = decimal_arg(args, "--p0", "1"),
                    f = decimal_arg(args, "--f", "1"), E = decimal_arg(args, "--E-star", "1");
  // rows in order geometry parameter, then q, then sigma; shard k gets the k-th contiguous block
  const size_t total = gs.size() * qs.size() * ss.size();
  const size_t lo = total * size_t(shard - 1) / size_t(nshards), hi = total * size_t(shard) / size_t(nshards);
  struct item {
    const char *key;
    int id;
  };
  std::vector<item> items = {{"b1", HS_REF_B1}, {"b2", HS_REF_B2}, {"d1", HS_REF_D1}, {"d2", HS_REF_D2}};
  if (energy) {
    items.push_back({"energy1", HS_REF_ENERGY1});
    items.push_back({"energy2", HS_REF_ENERGY2});
  }
  std::vector<std::string> lines(hi - lo);
  // progress on stderr: when it is a terminal, or with --progress
  const bool progress = args.count("--progress") || isatty(2);
  std::atomic<size_t> done(0);
  std::mutex progress_mutex;
  std::atomic<size_t> next(lo);
  auto worker = [&]() {
    for (size_t r = next++; r < hi; r = next++) {
      const std::string &g = gs[r / (qs.size() * ss.size())], &q = qs[r / ss.size() % qs.size()],
                        &s = ss[r % ss.size()];
      hs_ref_scene sc;
      hs_ref_scene_default(&sc);
      sc.a = a.c_str();
      sc.p0 = p0.c_str();
      sc.f = f.c_str();
      sc.E_star = E.c_str();
      sc.Q_over_fP = q.c_str();
      sc.sigma_over_fp0 = s.c_str();
      sc.geometry = kind;
      if (kind == HS_GEOMETRY_FLAT_ROUNDED) sc.flat_over_a = g.c_str();
      if (kind == HS_GEOMETRY_POWER_LAW) sc.exponent = g.c_str();
      hs_ref_solution *sol = nullptr;
      std::string line;
      const int st = hs_ref_solve(&sc, digits, &sol);
      hs_ref_summary sm;
      sm.struct_size = sizeof sm;
      if (st == HS_OK) hs_ref_solution_summary(sol, &sm);
      const char *reg = st == HS_OK ? regime_name(sm.regime)
                                    : (st == HS_ERR_GROSS_SLIDING ? "gross-sliding" : "error");
      const std::string gcol = kind == HS_GEOMETRY_HERTZ ? "" : g + ",";
      const std::string gkey = kind == HS_GEOMETRY_HERTZ ? ""
                                                         : "\"" + std::string(pkey) + "\": " + json_str(g) + ", ";
      if (jsonl)
        line = "{" + gkey + "\"Q_over_fP\": " + json_str(q) + ", \"sigma_over_fp0\": " + json_str(s) +
               ", \"regime\": " + json_str(reg) + ", \"status\": " + std::to_string(st);
      else line = gcol + q + "," + s + "," + reg + "," + std::to_string(st);
      std::vector<char> buf(size_t(digits) + 64);
      for (const auto &it : items) {
        int cd = 0;
        std::string v;
        if (st == HS_OK && hs_ref_value(sol, it.id, buf.data(), buf.size(), nullptr, &cd) == HS_OK) v = buf.data();
        if (jsonl)
          line += std::string(", \"") + it.key + "\": " + (v.empty() ? "null" : json_str(v)) + ", \"" + it.key +
                  "_digits\": " + std::to_string(cd);
        else line += "," + v + "," + std::to_string(cd);
      }
      if (jsonl) line += "}";
      hs_ref_solution_free(sol);
      lines[r - lo] = line;
      if (progress) {
        std::lock_guard<std::mutex> lock(progress_mutex);
        std::fprintf(stderr, "\rhalfslip table: %zu/%zu rows", size_t(++done), hi - lo);
        std::fflush(stderr);
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (auto &t : pool) t.join();
  if (progress) std::fprintf(stderr, "\n");
  // provenance (first shard only, without --shard, --threads and --progress, so that
  // the shards concatenate to the unsharded output): version, digits, command line
  const std::string cmd = command_line(argc, argv, {"--shard", "--threads", "--progress"});
  if (shard == 1) {
    if (jsonl)
      std::printf("{\"provenance\": {\"halfslip\": %s, \"digits\": %d, \"energy\": %s, \"command\": %s}}\n",
                  json_str(hs_version_string()).c_str(), digits, energy ? "true" : "false", json_escape(cmd).c_str());
    else
      std::printf("# halfslip %s, %d significant digits (reference backend), command: %s\n", hs_version_string(),
                  digits, cmd.c_str());
  }
  if (!jsonl && shard == 1) {
    if (kind != HS_GEOMETRY_HERTZ) std::printf("%s,", pkey);
    std::printf("Q_over_fP,sigma_over_fp0,regime,status");
    for (const auto &it : items) std::printf(",%s,%s_digits", it.key, it.key);
    std::printf("\n");
  }
  for (const auto &l : lines) std::printf("%s\n", l.c_str());
  return 0;
}

// ---------------------------------------------------------------- asymptotic-error
int cmd_asymptotic_error(int argc, char **argv) {
  const Args args = parse_args(argc, argv, 2, {"--loading", "--b-over-a"}, {"--json"});
  if (!args.count("--loading") || !args.count("--b-over-a"))
    die("asymptotic-error needs --loading shear|bulk and --b-over-a X");
  const std::string l = args.at("--loading");
  if (l != "shear" && l != "bulk") die("bad value for --loading: '" + l + "' (shear or bulk)");
  const double b = parse_number("--b-over-a", args.at("--b-over-a").c_str());
  hs_asymptotic_comparison c;
  c.struct_size = sizeof c;
  // the C library checks 0 < b/a < 1
  check(hs_asymptotic_error(l == "shear" ? HS_LOADING_SHEAR : HS_LOADING_BULK, b, &c),
        "bad value for --b-over-a " + g10(b));
  if (args.count("--json")) {
    std::printf(
        "{\"loading\": \"%s\", \"b_over_a\": %s, \"Q_over_fP\": %s, \"sigma_over_fp0\": %s, "
        "\"d_full\": %s, \"d_asymptotic\": %s, \"energy_full\": %s, \"energy_asymptotic\": %s, "
        "\"fractional_error\": %s}\n",
        l.c_str(), num(b).c_str(), num(c.Q_over_fP).c_str(), num(c.sigma_over_fp0).c_str(), num(c.d_full).c_str(),
        num(c.d_asymptotic).c_str(), num(c.energy_full).c_str(), num(c.energy_asymptotic).c_str(),
        num(c.fractional_error).c_str());
  } else {
    std::printf("asymptotic edge model vs full Hertz solution, %s loading, b/a = %.10g (a = p0 = f = E* = 1)\n",
                l.c_str(), b);
    std::printf("  load: Q/fP = %.10g, sigma/(f p0) = %.10g (held equal)\n", c.Q_over_fP, c.sigma_over_fp0);
    std::printf("  slip zone: full d/a = %.10g, asymptotic d/a = %.10g\n", c.d_full, c.d_asymptotic);
    std::printf("  energy per zone: full %.10g, asymptotic %.10g\n", c.energy_full, c.energy_asymptotic);
    std::printf("  fractional error (asymptotic - full)/full = %.6g\n", c.fractional_error);
  }
  return 0;
}

int run(int argc, char **argv) {
  if (argc < 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0) {
    std::fputs(kUsage, argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  if (std::strcmp(argv[1], "--version") == 0) {
    std::printf("halfslip %s\n", hs_version_string());
    return 0;
  }
  if (std::strcmp(argv[1], "solve") == 0) return cmd_solve(argc, argv);
  if (std::strcmp(argv[1], "table") == 0) return cmd_table(argc, argv);
  if (std::strcmp(argv[1], "history") == 0) return cmd_history(argc, argv);
  if (std::strcmp(argv[1], "asymptotic-error") == 0) return cmd_asymptotic_error(argc, argv);
  die(std::string("unknown command '") + argv[1] +
      "' (solve, history, table or asymptotic-error; see halfslip --help)");
}

}  // namespace

int main(int argc, char **argv) {
  try {
    return run(argc, argv);
  } catch (const halfslip_cli::help_requested &) {
    std::fputs(kUsage, stdout);
    return 0;
  } catch (const halfslip_cli::cli_error &e) {
    die(e.what());
  }
}
