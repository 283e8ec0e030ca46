// The `halfslip` command's argument parsing (issue 13): the options of a
// command, the scene and geometry they describe and the solve's model options.
// Every rejection is a cli_error whose message names the option (and, for a bad
// value, the value); nothing here prints or exits, so that the fuzz target
// tests/fuzz/fuzz_cli_args.cpp can call it. Shared with main.cpp, which prints
// a cli_error as "halfslip: MESSAGE" and exits with status 2.
#pragma once
#include <halfslip/halfslip.h>

#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace halfslip_cli {

class cli_error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};
// --help or -h among the options (main prints the usage and exits with 0)
struct help_requested {};

using Args = std::map<std::string, std::string>;

// The options of each command (keys take a value; flags do not).
extern const std::vector<std::string> kSolveKeys, kSolveFlags, kHistoryKeys, kHistoryFlags;

// Parse "--key value" and "--key=value" pairs (and the flags given) after argv[first].
// Throws cli_error (unknown option, repeated option, missing value, value given to a
// flag, unknown --geometry) or help_requested.
Args parse_args(int argc, const char *const *argv, int first, const std::vector<std::string> &keys,
                const std::vector<std::string> &flags);

// The number text (all of it, finite) given for flag; else cli_error naming both.
double parse_number(const std::string &flag, const char *text);
// An integer in [lo, hi]; else cli_error naming the flag and the range.
int parse_int(const std::string &flag, const std::string &text, int lo, int hi);

// A C status: cli_error "WHAT: MESSAGE" unless HS_OK.
void check(int st, const std::string &what);
// A status of a C call that takes the scene options: the message names the options
// the status is about.
void check_input(int st, const Args &args, const std::string &what = "scene");
bool is_dimensional(const Args &args);

// The bytes of the file named by an option (path, flag); may throw cli_error.
using file_reader = std::function<std::string(const std::string &path, const char *flag)>;

// The scene and geometry of the solve/history options (geometry, sizes, loads);
// sx, sp hold the samples of --pressure-file (read with `read`). With `loads`
// false, the load options are not part of the command (history: the path gives them).
void scene_from_args(const Args &args, hs_scene &scene, hs_geometry &geo, std::vector<double> &sx,
                     std::vector<double> &sp, const file_reader &read, bool loads = true);

// solve: the route that --rtol and --digits choose. digits > 0: the reference
// backend at that many digits (--digits, or --rtol below double's rounding);
// rtol: the --rtol given (0 if none).
struct solve_route {
  int digits = 0;
  double rtol = 0;
};
solve_route solve_route_from_args(const Args &args);
// solve: the options of a double solve (--model, --rtol) and the --points count.
void solve_options_from_args(const Args &args, const solve_route &route, hs_options &opts, int &points);

}  // namespace halfslip_cli
