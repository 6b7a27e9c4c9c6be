#include "canon_listing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace ncbridge::testing {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::vector<std::string> split_arguments(std::string_view args) {
  std::vector<std::string> out;
  args = trim(args);
  if (args.size() >= 2 && args.front() == '"' && args.back() == '"') {  // COMMENT("..."), MESSAGE("...")
    out.emplace_back(args);
    return out;
  }
  std::string current;
  for (char c : args) {
    if (c == ',' || c == ' ' || c == '\t') {
      if (!current.empty()) out.push_back(std::move(current));
      current.clear();
    } else {
      current.push_back(c);
    }
  }
  if (!current.empty()) out.push_back(std::move(current));
  return out;
}

CanonLine parse_line(std::string_view line) {
  CanonLine parsed;
  parsed.text = std::string(line);
  std::string_view rest = trim(line);
  const auto counter_end = rest.find_first_not_of("0123456789");
  if (counter_end == 0 || counter_end == std::string_view::npos) return parsed;
  rest = trim(rest.substr(counter_end));
  if (rest.empty() || rest.front() != 'N') return parsed;
  const auto n_end = rest.find_first_of(" \t");
  if (n_end == std::string_view::npos) return parsed;
  std::string_view n_column = rest.substr(0, n_end);
  rest = trim(rest.substr(n_end));
  const auto open = rest.find('(');
  if (open == std::string_view::npos || rest.back() != ')') return parsed;
  parsed.n_column = std::string(n_column);
  parsed.name = std::string(rest.substr(0, open));
  parsed.args = split_arguments(rest.substr(open + 1, rest.size() - open - 2));
  return parsed;
}

bool parse_number(const std::string& s, double& value) {
  if (s.empty()) return false;
  char* end = nullptr;
  value = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

// Why two lines differ, or empty when they agree.
std::string line_difference(const CanonLine& e, const CanonLine& a, double tolerance) {
  if (e.name != a.name) return "call name differs";
  if (e.n_column != a.n_column) return "N column differs";
  if (e.args.size() != a.args.size()) return "number of arguments differs";
  for (std::size_t i = 0; i < e.args.size(); ++i) {
    double ev = 0, av = 0;
    const bool e_num = parse_number(e.args[i], ev), a_num = parse_number(a.args[i], av);
    if (e_num && a_num) {
      // Both sides print 4 decimals: allow a last-digit rounding difference beyond the tolerance.
      if (std::fabs(ev - av) > tolerance * (1 + 1e-6)) return "argument " + std::to_string(i + 1) + " differs";
    } else if (e.args[i] != a.args[i]) {
      return "argument " + std::to_string(i + 1) + " differs";
    }
  }
  return {};
}

void append_context(std::ostringstream& out, const char* title, const std::vector<CanonLine>& lines,
                    std::size_t at) {
  out << "  " << title << ":\n";
  const std::size_t from = at >= 3 ? at - 3 : 0;
  const std::size_t to = std::min(lines.size(), at + 4);
  for (std::size_t i = from; i < to; ++i) out << (i == at ? "  > " : "    ") << lines[i].text << '\n';
  if (at >= lines.size()) out << "  > (end of listing)\n";
}

}  // namespace

std::vector<CanonLine> parse_canon_listing(std::string_view listing) {
  std::vector<CanonLine> lines;
  while (!listing.empty()) {
    const auto eol = listing.find('\n');
    std::string_view line = listing.substr(0, eol);
    if (!trim(line).empty()) lines.push_back(parse_line(line));
    if (eol == std::string_view::npos) break;
    listing.remove_prefix(eol + 1);
  }
  return lines;
}

ListingComparison compare_canon_listings(const std::vector<CanonLine>& expected,
                                         const std::vector<CanonLine>& actual, double tolerance) {
  ListingComparison result;
  const std::size_t common = std::min(expected.size(), actual.size());
  std::size_t at = 0;
  std::string why;
  for (; at < common; ++at) {
    why = line_difference(expected[at], actual[at], tolerance);
    if (!why.empty()) break;
  }
  if (at == common && expected.size() == actual.size()) return result;
  if (why.empty()) why = expected.size() > actual.size() ? "output ends early" : "output has extra calls";
  result.equal = false;
  std::ostringstream out;
  out << "first difference at call " << at + 1 << " (" << why << "); expected " << expected.size()
      << " calls, got " << actual.size() << "\n";
  append_context(out, "expected (rs274)", expected, at);
  append_context(out, "actual (ncbridge)", actual, at);
  result.report = out.str();
  return result;
}

}  // namespace ncbridge::testing
