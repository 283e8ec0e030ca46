// The `halfslip` command's pressure files (pressure_file.hpp).
#include "pressure_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace halfslip_cli {

namespace {
[[noreturn]] void bad_sample(const samples &s, int ln, const std::string &rule) {
  throw pressure_file_error(s, ln, rule);
}
}  // namespace

std::string g10(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

// Pressure samples (--pressure-file): two columns x p per line, separated by
// whitespace or one comma; '#' starts a comment; blank lines are skipped; the
// first non-comment line may be a header (its first field is not a number).
// Every rejection names the file, the line and the rule broken.
std::string trim(const std::string &t) {
  const size_t b = t.find_first_not_of(" \t"), e = t.find_last_not_of(" \t");
  return b == std::string::npos ? "" : t.substr(b, e - b + 1);
}

// The content of a line of an input file, in place: no CR, no '#' comment, no
// surrounding blanks; false if nothing is left.
bool content_of_line(std::string &t) {
  if (!t.empty() && t.back() == '\r') t.pop_back();
  const size_t hash = t.find('#');
  if (hash != std::string::npos) t.erase(hash);
  t = trim(t);
  return !t.empty();
}

// Fields of one line: comma-separated if it has a comma, else whitespace-separated.
std::vector<std::string> split_fields(const std::string &t) {
  std::vector<std::string> out;
  if (t.find(',') != std::string::npos) {
    size_t b = 0;
    for (;;) {
      const size_t c = t.find(',', b);
      out.push_back(trim(t.substr(b, c == std::string::npos ? std::string::npos : c - b)));
      if (c == std::string::npos) break;
      b = c + 1;
    }
  } else {
    size_t b = 0;
    while ((b = t.find_first_not_of(" \t", b)) != std::string::npos) {
      const size_t e = t.find_first_of(" \t", b);
      out.push_back(t.substr(b, e == std::string::npos ? std::string::npos : e - b));
      b = e;
    }
  }
  return out;
}

bool is_number(const std::string &t, double &v) {
  if (t.empty()) return false;
  char *end = nullptr;
  v = std::strtod(t.c_str(), &end);
  return *end == '\0';
}

samples parse_samples(std::string all, const std::string &path) {
  samples s;
  s.path = path;
  if (all.compare(0, 3, "\xEF\xBB\xBF") == 0) all.erase(0, 3);  // UTF-8 byte order mark
  bool header_allowed = true;
  size_t pos = 0;
  while (pos < all.size()) {
    size_t nl = all.find('\n', pos);
    if (nl == std::string::npos) nl = all.size();
    std::string t = all.substr(pos, nl - pos);
    pos = nl + 1;
    const int ln = ++s.last_line;
    if (!content_of_line(t)) continue;
    const std::vector<std::string> fl = split_fields(t);
    double x = 0, p = 0;
    const bool xnum = is_number(fl[0], x);
    if (!xnum && header_allowed && fl.size() >= 2) {  // a header such as "x p" or "x [m],p [Pa]"
      header_allowed = false;
      continue;
    }
    header_allowed = false;
    if (fl.size() != 2)
      bad_sample(s, ln,
                 std::to_string(fl.size()) + " column" + (fl.size() == 1 ? "" : "s") +
                     ", expected 2 (x p, separated by spaces, tabs or one comma)");
    if (!xnum) bad_sample(s, ln, "x '" + fl[0] + "' is not a number");
    if (!is_number(fl[1], p)) bad_sample(s, ln, "p '" + fl[1] + "' is not a number");
    if (std::isnan(x) || std::isnan(p)) bad_sample(s, ln, std::string(std::isnan(x) ? "x" : "p") + " is NaN");
    if (!std::isfinite(x) || !std::isfinite(p))
      bad_sample(s, ln, std::string(!std::isfinite(x) ? "x" : "p") + " is not finite");
    if (p < 0) bad_sample(s, ln, "negative pressure p = " + fl[1] + " (p must be >= 0)");
    if (!s.x.empty() && !(x > s.x.back()))
      bad_sample(s, ln,
                 "x = " + fl[0] + " does not increase (previous sample, line " + std::to_string(s.line.back()) +
                     ": x = " + g10(s.x.back()) + "; x must increase strictly)");
    s.x.push_back(x);
    s.p.push_back(p);
    s.line.push_back(ln);
  }
  if (s.x.empty())
    bad_sample(s, std::max(1, s.last_line),
               std::string(s.last_line ? "end of file, no samples (only blank, comment or header lines)"
                                       : "the file is empty") +
                   "; need at least 6 lines x p");
  if (s.x.size() < 6)
    bad_sample(s, s.last_line, "end of file after " + std::to_string(s.x.size()) + " samples; need at least 6");
  return s;
}

// The rules that depend on the contact half-width a: x in [-a, a], p > 0
// inside the contact and p = 0 at an edge sample (sqrt edge behaviour).
void check_samples(const samples &s, double a) {
  double pmax = 0;
  for (double p : s.p) pmax = std::max(pmax, p);
  for (size_t i = 0; i < s.x.size(); ++i) {
    const double x = s.x[i], p = s.p[i];
    if (!(x >= -a && x <= a))
      bad_sample(s, s.line[i],
                 "x = " + g10(x) + " is outside the contact [-a, a] = [" + g10(-a) + ", " + g10(a) + "]");
    if ((x == -a || x == a) && p > 64 * 2.220446049250313e-16 * pmax)
      bad_sample(s, s.line[i], "p = " + g10(p) + " at the contact edge x = " + g10(x) + " (p must vanish there)");
    if (x > -a && x < a && !(p > 0))
      bad_sample(s, s.line[i], "p = 0 inside the contact at x = " + g10(x) + " (p must be > 0 for |x| < a)");
  }
}

}  // namespace halfslip_cli
