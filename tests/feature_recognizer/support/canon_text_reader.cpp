#include "canon_text_reader.hpp"

#include <charconv>
#include <fstream>
#include <sstream>

#include "ncbridge/common/error.hpp"

namespace ncbridge::test_support {
namespace {

struct LineParser {
  std::string_view line;
  std::string file;
  std::uint32_t line_no;

  [[noreturn]] void fail(std::size_t at, const std::string& message) const {
    throw InputError({file, line_no, static_cast<std::uint32_t>(at + 1)}, message);
  }

  // Arguments between the parentheses, split at commas and blanks (rs274 mixes both).
  std::vector<std::string_view> arguments(std::size_t open, std::size_t close) const {
    std::vector<std::string_view> out;
    std::size_t i = open + 1;
    while (i < close) {
      while (i < close && (line[i] == ',' || line[i] == ' ')) ++i;
      std::size_t j = i;
      while (j < close && line[j] != ',' && line[j] != ' ') ++j;
      if (j > i) out.push_back(line.substr(i, j - i));
      i = j;
    }
    return out;
  }

  double number(std::string_view token, std::size_t at) const {
    double value = 0;
    const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc{} || ptr != token.data() + token.size()) fail(at, "bad number '" + std::string(token) + "'");
    return value;
  }
};

}  // namespace

std::vector<canonical::Call> parse_canon_text(std::string_view text, const std::string& file_name) {
  std::vector<canonical::Call> calls;
  std::uint32_t line_no = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    LineParser p{line, file_name, line_no};
    const std::size_t n = line.find(" N");
    if (line.find_first_not_of(" \t\r") == std::string_view::npos) continue;
    if (n == std::string_view::npos) p.fail(0, "expected '<sequence> N<number> NAME(...)'");
    const std::size_t name_at = line.find(' ', n + 1);
    const std::size_t open = line.find('(', name_at == std::string_view::npos ? n : name_at);
    const std::size_t close = line.rfind(')');
    if (name_at == std::string_view::npos || open == std::string_view::npos || close == std::string_view::npos ||
        close < open) {
      p.fail(n, "expected NAME(arguments)");
    }
    const std::string_view name = line.substr(name_at + 1, open - name_at - 1);
    const auto args = p.arguments(open, close);
    auto num = [&](std::size_t i) {
      if (i >= args.size()) p.fail(close, std::string(name) + " needs more arguments");
      return p.number(args[i], open + 1);
    };
    auto pose = [&] {
      canonical::Pose q;
      q.x = num(0), q.y = num(1), q.z = num(2);
      return q;
    };
    canonical::Call call;
    call.source.line = line_no;
    if (name == "USE_LENGTH_UNITS") {
      call.data = canonical::UseLengthUnits{args.size() == 1 && args[0] == "CANON_UNITS_INCHES"
                                                ? canonical::Units::Inches
                                                : canonical::Units::Millimeters};
    } else if (name == "STRAIGHT_TRAVERSE") {
      call.data = canonical::StraightTraverse{pose()};
    } else if (name == "STRAIGHT_FEED") {
      call.data = canonical::StraightFeed{pose()};
    } else if (name == "ARC_FEED") {
      canonical::ArcFeed a{};
      a.first_end = num(0), a.second_end = num(1), a.first_axis = num(2), a.second_axis = num(3);
      a.rotation = static_cast<int>(num(4));
      a.axis_end_point = num(5);
      call.data = a;
    } else if (name == "SET_FEED_RATE") {
      call.data = canonical::SetFeedRate{num(0)};
    } else if (name == "SET_SPINDLE_SPEED") {
      call.data = canonical::SetSpindleSpeed{static_cast<int>(num(0)), num(1)};
    } else if (name == "SELECT_TOOL") {
      call.data = canonical::SelectTool{static_cast<int>(num(0))};
    } else if (name == "CHANGE_TOOL") {
      call.data = canonical::ChangeTool{static_cast<int>(num(0))};
    } else if (name == "SELECT_PLANE") {
      canonical::Plane plane = canonical::Plane::XY;
      if (!args.empty() && args[0] == "CANON_PLANE_YZ") plane = canonical::Plane::YZ;
      if (!args.empty() && args[0] == "CANON_PLANE_XZ") plane = canonical::Plane::XZ;
      call.data = canonical::SelectPlane{plane};
    } else if (name == "PROGRAM_END") {
      call.data = canonical::ProgramEnd{};
    } else {
      continue;  // comments, coolant, offsets already applied by rs274, ...
    }
    calls.push_back(std::move(call));
  }
  return calls;
}

std::vector<canonical::Call> read_canon_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw InputError({file.string(), 0, 0}, "cannot open canonical text");
  std::ostringstream s;
  s << in.rdbuf();
  return parse_canon_text(s.str(), file.string());
}

}  // namespace ncbridge::test_support
