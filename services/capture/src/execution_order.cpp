// How the execution order is learnt: every block of a copy of the program is preceded by a
// comment line naming its line, and our interpreter's COMMENT calls come out in the order the
// lines ran; the motion calls after a marker belong to its block.
#include "ncbridge/capture/execution_order.hpp"

#include <cctype>
#include <sstream>
#include <string_view>

#include "ncbridge/canonical/call.hpp"
#include "ncbridge/common/error.hpp"

namespace ncbridge::capture {
namespace {

constexpr std::string_view kMarker = "ncbridge-capture-line ";

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
  }
  return lines;
}

bool blank(std::string_view line) { return line.find_first_not_of(" \t") == std::string_view::npos; }

bool percent_line(std::string_view line) {
  const std::size_t i = line.find_first_not_of(" \t");
  return i != std::string_view::npos && line[i] == '%';
}

// The o-word of a line ("sub", "call", "while", ...), lower case, or "" when it has none.
std::string o_word_keyword(std::string_view line) {
  std::size_t i = line.find_first_not_of(" \t/");
  if (i != std::string_view::npos && (line[i] == 'n' || line[i] == 'N')) {  // an N word first
    ++i;
    while (i < line.size() && (std::isdigit(static_cast<unsigned char>(line[i])) || line[i] == '.')) ++i;
    i = line.find_first_not_of(" \t", i);
  }
  if (i == std::string_view::npos || (line[i] != 'o' && line[i] != 'O')) return "";
  ++i;
  if (i < line.size() && line[i] == '<') {
    i = line.find('>', i);
    if (i == std::string_view::npos) return "";
    ++i;
  } else {
    const std::size_t digits = i;
    while (i < line.size() && std::isdigit(static_cast<unsigned char>(line[i]))) ++i;
    if (i == digits) return "";
  }
  i = line.find_first_not_of(" \t", i);
  std::string keyword;
  while (i < line.size() && std::isalpha(static_cast<unsigned char>(line[i])))
    keyword.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(line[i++]))));
  return keyword;
}

// "o100 call [1] [2+#3]" -> "#1=[1] #2=[2+#3]"; "" when the call has no arguments.
std::string call_arguments_as_parameters(std::string_view line) {
  std::string out;
  std::size_t at = line.find_first_of("lL", line.find_first_of("cC", line.find_first_of("oO")));
  int n = 0, depth = 0;
  std::string arg;
  for (std::size_t i = at; at != std::string_view::npos && i < line.size(); ++i) {
    const char c = line[i];
    if (c == '(' || c == ';') break;  // a comment
    if (c == '[') {
      if (depth++ > 0) arg.push_back(c);
    } else if (c == ']') {
      if (--depth > 0) {
        arg.push_back(c);
      } else {
        out += (out.empty() ? "" : " ") + ("#" + std::to_string(++n) + "=[" + arg + "]");
        arg.clear();
      }
    } else if (depth > 0) {
      arg.push_back(c);
    }
  }
  return out;
}

bool is_motion(const canonical::Data& d) {
  return std::holds_alternative<canonical::StraightTraverse>(d) || std::holds_alternative<canonical::StraightFeed>(d) ||
         std::holds_alternative<canonical::ArcFeed>(d) || std::holds_alternative<canonical::StraightProbe>(d) ||
         std::holds_alternative<canonical::RigidTap>(d);
}

// Collects the order in which the marked lines ran, and which of them moved.
class LineTrace final : public canonical::Sink {
 public:
  void call(const canonical::Call& c) override {
    const auto* comment = std::get_if<canonical::Comment>(&c.data);
    if (comment && comment->text.starts_with(kMarker)) {
      runs.push_back({static_cast<std::uint32_t>(std::stoul(comment->text.substr(kMarker.size()))), false});
    } else if (!runs.empty() && is_motion(c.data)) {
      runs.back().second = true;
    }
  }
  std::vector<std::pair<std::uint32_t, bool>> runs;  // (line, moved)
};

}  // namespace

std::vector<ExecutedLine> execution_order(const std::string& program_name, const std::string& text,
                                          const setup::ToolList& tools, interpreter::Dialect dialect) {
  const std::vector<std::string> lines = split_lines(text);
  std::vector<ExecutedLine> out;
  if (dialect != interpreter::Dialect::Rs274Ngc) {
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (!blank(lines[i])) out.push_back({static_cast<std::uint32_t>(i + 1), lines[i], true});
    }
    return out;
  }
  std::string marked;
  std::vector<std::uint32_t> original_line{0};  // marked line -> program line
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string keyword = o_word_keyword(lines[i]);
    if (!blank(lines[i]) && !percent_line(lines[i]) && (keyword.empty() || keyword == "call")) {
      marked += "(" + std::string(kMarker) + std::to_string(i + 1) + ")\n";
      original_line.push_back(static_cast<std::uint32_t>(i + 1));
    }
    marked += lines[i] + "\n";
    original_line.push_back(static_cast<std::uint32_t>(i + 1));
  }
  interpreter::Options options;
  options.tools = tools;
  LineTrace trace;
  try {
    interpreter::interpret_text(marked, program_name, options, trace);
  } catch (const InputError& e) {  // name the program's own line, not the marked copy's
    SourceLocation where = e.where();
    if (where.file == program_name && where.line < original_line.size()) where.line = original_line[where.line];
    throw InputError(where, e.message());
  }
  for (const auto& [n, moved] : trace.runs) {
    const std::string& line = lines.at(n - 1);
    if (o_word_keyword(line) == "call") {
      const std::string parameters = call_arguments_as_parameters(line);
      if (!parameters.empty()) out.push_back({n, parameters, false});
      continue;
    }
    out.push_back({n, line, moved});
  }
  return out;
}

}  // namespace ncbridge::capture
