// The `halfslip` command's pressure files (--pressure-file): two columns x p
// per line, separated by whitespace or one comma; '#' starts a comment; blank
// lines are skipped; the first non-comment line may be a header (its first
// field is not a number). Every rejection names the file, the line and the rule
// broken (a pressure_file_error). Shared by the CLI (main.cpp) and the fuzz
// target tests/fuzz/fuzz_pressure_file.cpp.
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

namespace halfslip_cli {

struct samples {
  std::string path;
  std::vector<double> x, p;
  std::vector<int> line;  // line number of each sample
  int last_line = 0;      // number of lines in the file
};

// "bad --pressure-file 'PATH', line L: RULE"
class pressure_file_error : public std::runtime_error {
 public:
  pressure_file_error(const samples &s, int line, const std::string &rule)
      : std::runtime_error("bad --pressure-file '" + s.path + "', line " + std::to_string(line) + ": " + rule),
        line_(line) {}
  int line() const { return line_; }

 private:
  int line_;
};

// The samples of a file's bytes (path: for the messages); throws pressure_file_error.
samples parse_samples(std::string bytes, const std::string &path);
// The rules that depend on the contact half-width a: x in [-a, a], p > 0
// inside the contact and p = 0 at an edge sample; throws pressure_file_error.
void check_samples(const samples &s, double a);

// Line helpers (also used for --fields-at files)
std::string trim(const std::string &t);
// The content of a line, in place: no CR, no '#' comment, no surrounding blanks; false if nothing is left.
bool content_of_line(std::string &t);
// Fields of one line: comma-separated if it has a comma, else whitespace-separated.
std::vector<std::string> split_fields(const std::string &t);
// v = the number t (all of it); false if t is not a number.
bool is_number(const std::string &t, double &v);
// %.10g
std::string g10(double v);

}  // namespace halfslip_cli
