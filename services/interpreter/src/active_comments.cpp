#include "active_comments.hpp"

#include <cmath>
#include <cstdio>
#include <optional>

namespace ncbridge::interpreter {

namespace {

char lower(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

bool starts_with(std::string_view text, std::string_view keyword) {
  if (text.size() < keyword.size()) return false;
  for (std::size_t i = 0; i < keyword.size(); ++i) {
    if (lower(text[i]) != keyword[i]) return false;
  }
  return true;
}

}  // namespace

ActiveComment classify_comment(std::string_view text, std::string_view& rest) {
  while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
  static constexpr std::pair<std::string_view, ActiveComment> kKeywords[] = {
      {"debug,", ActiveComment::Debug},         {"print,", ActiveComment::Print},
      {"log,", ActiveComment::Log},             {"logopen,", ActiveComment::LogOpen},
      {"logappend,", ActiveComment::LogAppend}, {"abort,", ActiveComment::Abort}};
  for (const auto& [keyword, kind] : kKeywords) {
    if (starts_with(text, keyword)) {
      rest = text.substr(keyword.size());
      return kind;
    }
  }
  if (text.size() == 8 && starts_with(text, "logclose")) {  // the whole comment, nothing after it
    rest = {};
    return ActiveComment::LogClose;
  }
  return ActiveComment::None;
}

std::string expand_comment_parameters(std::string_view text, const Parameters& parameters) {
  std::string out;
  std::string format = "%f";
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '%') {
      ++i;
      if (i < text.size() && text[i] == 'd') {
        format = "%.0f";
        ++i;
      } else if (i < text.size() && text[i] == 'f') {
        format = "%.4f";
        ++i;
      } else if (i < text.size() && text[i] == '.') {
        ++i;
        if (i + 1 < text.size() && is_digit(text[i]) && text[i + 1] == 'f') {
          format = std::string("%.") + text[i] + "f";
          i += 2;
        } else {
          out.push_back('.');  // not a format: the % is dropped, the rest read as text
        }
      } else {
        out.push_back('%');
      }
      continue;
    }
    if (c != '#') {
      out.push_back(c);
      ++i;
      continue;
    }
    ++i;
    if (i >= text.size()) return out;  // "Named parameter not terminated": rs274 keeps what came before
    std::optional<double> value;
    if (is_digit(text[i])) {
      long number = 0;
      while (i < text.size() && is_digit(text[i])) {
        if (number < 100000) number = number * 10 + (text[i] - '0');
        ++i;
      }
      if (number == 0) {
        value = 0.0;  // #0 is read (LinuxCNC's parameters[0])
      } else if (number < Parameters::kCount) {
        value = parameters.numbered(static_cast<int>(number));
      }
    } else if (text[i] == '<') {
      ++i;
      std::string name;
      while (i < text.size() && text[i] != '>') {
        if (!is_space(text[i])) name.push_back(lower(text[i]));
        ++i;
      }
      if (i >= text.size()) return out;  // no '>': as above
      ++i;
      value = parameters.named(name);
    } else {
      out.push_back('#');  // neither a number nor a name: the # stays, the rest is text
      continue;
    }
    if (!value) {
      out += "######";
      continue;
    }
    const double v = std::fabs(*value) < 0.0001 ? 0.0 : *value;
    char buffer[400];
    const int n = std::snprintf(buffer, sizeof buffer, format.c_str(), v);
    // LinuxCNC prints into 30 characters (VAL_LEN) and shows ###### for a value that does not fit.
    constexpr int kValueLength = 30;
    out += (n < 0 || n >= kValueLength) ? std::string("######") : std::string(buffer, static_cast<std::size_t>(n));
  }
  return out;
}

}  // namespace ncbridge::interpreter
