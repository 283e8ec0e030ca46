// libFuzzer target: the CLI's argument parsing (bindings/cli/args.cpp, issue 13).
// The input is the command line: tokens separated by NUL bytes; the first byte
// picks the command (bit 0: solve or history) and whether the last token is the
// pressure file's bytes (bit 1; any --pressure-file path reads it, nothing is read
// from disk). Asserts:
//   - a rejection of the options names an option or a token of the command line;
//     "bad value for --X..." names an option that was given;
//   - accepted options are known keys or flags; "--k=v" and "--k v" parse alike
//     (both routes give the same options);
//   - the scene of accepted options: a rejection names an option given (or the
//     pressure file); an accepted scene has the values given (dimensionless input)
//     or finite positive sizes and finite ratios (dimensional input);
//   - solve's route and model options: a rejection names an option; --model is
//     the model named; the solve (bounded loads) gives a known status, an error
//     message that names an option for a status about an input, and on success
//     finite zones within [0, 2a].
#include <halfslip/halfslip.h>

#include "../../bindings/cli/args.hpp"
#include "fuzz_input.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

namespace {
using namespace halfslip_cli;
using hs_fuzz::known;
bool contains(const std::string &s, const std::string &t) { return s.find(t) != std::string::npos; }
bool starts_with(const std::string &s, const std::string &p) { return s.compare(0, p.size(), p) == 0; }
// the option of a token: "--k=v" -> "--k"
std::string key_of(const std::string &t) {
  const size_t eq = t.find('=');
  return t.compare(0, 2, "--") == 0 && eq != std::string::npos ? t.substr(0, eq) : t;
}

Args parse(const std::vector<std::string> &tok, const std::vector<std::string> &keys,
           const std::vector<std::string> &flags) {
  std::vector<const char *> argv = {"halfslip", "cmd"};
  for (const auto &t : tok) argv.push_back(t.c_str());
  return parse_args(int(argv.size()), argv.data(), 2, keys, flags);
}

// A message "bad value for --X[, --Y or --Z]: ..." names at least one option given.
bool names_given_option(const std::string &msg, const Args &args) {
  if (!starts_with(msg, "bad value for ")) return true;
  const size_t colon = msg.find(':');
  const std::string list = msg.substr(14, colon == std::string::npos ? std::string::npos : colon - 14);
  for (const auto &kv : args)
    if (contains(list, kv.first)) return true;
  return false;
}
// A message names an option of the command (a known key or flag, with its "--").
bool names_an_option(const std::string &msg, const std::vector<std::string> &keys,
                     const std::vector<std::string> &flags) {
  for (const auto *list : {&keys, &flags})
    for (const auto &k : *list)
      if (contains(msg, k)) return true;
  return false;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size == 0) return 0;
  const uint8_t mode = data[0];
  const bool solve = !(mode & 1);
  std::vector<std::string> tok;
  std::string cur;
  for (size_t i = 1; i < size; ++i) {
    if (data[i] == 0) {
      tok.push_back(cur);
      cur.clear();
    } else {
      cur += char(data[i]);
    }
  }
  tok.push_back(cur);
  std::string file;
  if (mode & 2) {
    file = tok.back();
    tok.pop_back();
  }
  if (tok.size() > 40) return 0;
  const auto &keys = solve ? kSolveKeys : kHistoryKeys;
  const auto &flags = solve ? kSolveFlags : kHistoryFlags;

  Args args;
  try {
    args = parse(tok, keys, flags);
  } catch (const help_requested &) {
    bool asked = false;
    for (const auto &t : tok) asked = asked || t == "--help" || t == "-h";
    HS_REQUIRE(asked);
    return 0;
  } catch (const cli_error &e) {
    const std::string msg = e.what();
    bool named = false;
    for (const auto &t : tok) {
      const std::string k = key_of(t);
      named = named || (k.empty() ? contains(msg, "''") : contains(msg, k));
    }
    HS_REQUIRE(!msg.empty() && named);
    return 0;
  }
  // every option is known, and both spellings of the command line parse alike
  std::vector<std::string> inline_form, split_form;
  for (const auto &kv : args) {
    const bool is_flag = std::find(flags.begin(), flags.end(), kv.first) != flags.end();
    HS_REQUIRE(is_flag ? kv.second == "1" : std::find(keys.begin(), keys.end(), kv.first) != keys.end());
    if (is_flag) {
      inline_form.push_back(kv.first);
      split_form.push_back(kv.first);
    } else {
      inline_form.push_back(kv.first + "=" + kv.second);
      split_form.push_back(kv.first);
      split_form.push_back(kv.second);
    }
  }
  HS_REQUIRE(parse(inline_form, keys, flags) == args);
  HS_REQUIRE(parse(split_form, keys, flags) == args);

  // the scene
  hs_scene scene;
  hs_geometry geo;
  std::vector<double> sx, sp;
  const file_reader read = [&](const std::string &, const char *) { return file; };
  try {
    scene_from_args(args, scene, geo, sx, sp, read, solve);
  } catch (const cli_error &e) {
    const std::string msg = e.what();
    HS_REQUIRE(names_given_option(msg, args));
    HS_REQUIRE(names_an_option(msg, keys, flags) || starts_with(msg, "bad --pressure-file '"));
    return 0;
  }
  const bool dim = is_dimensional(args);
  auto given = [&](const char *k, double def) { return args.count(k) ? std::strtod(args.at(k).c_str(), nullptr) : def; };
  if (!dim) {
    HS_REQUIRE(scene.a == given("--a", 1) && scene.p0 == given("--p0", 1) && scene.f == given("--f", 1) &&
            scene.E_star == given("--E-star", 1));
    if (solve)
      HS_REQUIRE(scene.Q_over_fP == given("--Q-over-fP", 0.5) && scene.sigma_over_fp0 == given("--sigma-over-fp0", 0.5));
  } else {
    // the C library accepted the dimensional input: finite positive sizes, finite ratios
    HS_REQUIRE(std::isfinite(scene.a) && scene.a > 0 && std::isfinite(scene.p0) && scene.p0 > 0);
    HS_REQUIRE(std::isfinite(scene.Q_over_fP) && std::isfinite(scene.sigma_over_fp0));
  }
  if (geo.kind == HS_GEOMETRY_SAMPLES) HS_REQUIRE(geo.n_samples == sx.size() && sx.size() >= 6);
  if (!solve) return 0;

  // solve: route and options
  solve_route route;
  hs_options opts;
  int points = 0;
  try {
    route = solve_route_from_args(args);
    if (route.digits > 0) return 0;  // the reference backend (its own target, fuzz_ref)
    solve_options_from_args(args, route, opts, points);
  } catch (const cli_error &e) {
    const std::string msg = e.what();
    HS_REQUIRE(names_given_option(msg, args) && names_an_option(msg, keys, flags));
    return 0;
  }
  HS_REQUIRE(points >= 0 && points <= 100000);
  if (args.count("--model")) HS_REQUIRE(args.at("--model") == hs_model_name(opts.model));
  // bounded cost: the loads for which every geometry solves in milliseconds
  if (geo.kind != HS_GEOMETRY_HERTZ && !(std::fabs(scene.sigma_over_fp0) < 50 && std::fabs(scene.Q_over_fP) < 0.999))
    return 0;
  if (opts.model == HS_MODEL_REFERENCE || opts.model == HS_MODEL_AUTO) return 0;
  hs_solution *sol = nullptr;
  const int st = hs_solve_geometry(&scene, &geo, &opts, &sol);
  HS_REQUIRE(known(st) && (st == HS_OK) == (sol != nullptr));
  if (st != HS_OK) {
    try {
      check_input(st, args, "solve");
      HS_REQUIRE(false);
    } catch (const cli_error &e) {
      HS_REQUIRE(names_given_option(e.what(), args));
    }
    return 0;
  }
  hs_summary sm;
  sm.struct_size = sizeof sm;
  HS_REQUIRE(hs_solution_summary(sol, &sm) == HS_OK);
  HS_REQUIRE(std::isfinite(sm.d1) && std::isfinite(sm.d2) && sm.d1 >= 0 && sm.d2 >= 0 && sm.d1 <= 2 * sm.a &&
          sm.d2 <= 2 * sm.a);
  hs_solution_free(sol);
  return 0;
}
