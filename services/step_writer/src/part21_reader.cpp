#include <cctype>
#include <charconv>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "ncbridge/step_writer/part21_reader.hpp"
#include "part21_tokenizer.hpp"
#include "utf8.hpp"

namespace ncbridge::step_writer::part21 {
namespace {

constexpr int kMaxNesting = 200;  // deeper lists than this are garbage, not STEP

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

// Reads `digits` hex digits at raw[i]; -1 when they are not all there.
std::int64_t read_hex(std::string_view raw, std::size_t i, int digits) {
  if (i + static_cast<std::size_t>(digits) > raw.size()) return -1;
  std::int64_t v = 0;
  for (int k = 0; k < digits; ++k) {
    int h = hex_value(raw[i + static_cast<std::size_t>(k)]);
    if (h < 0) return -1;
    v = v * 16 + h;
  }
  return v;
}

void append_code_point(std::string& out, std::uint32_t cp) {
  if (cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) cp = 0xFFFD;
  append_utf8(out, cp);
}

// Part 21 string escapes to UTF-8. Unknown backslash sequences are kept as written; bytes that
// are not UTF-8 are read as ISO 8859-1, so a decoded string is always valid UTF-8.
std::string decode_string(std::string_view raw) {
  std::string out;
  out.reserve(raw.size());
  std::size_t i = 0;
  while (i < raw.size()) {
    char c = raw[i];
    if (c == '\'') {  // the tokenizer only lets '' through
      out += '\'';
      i += 2;
      continue;
    }
    if (static_cast<unsigned char>(c) >= 0x80) {  // raw 8-bit text (ed.3 allows UTF-8): kept as UTF-8
      append_code_point(out, decode_utf8(raw, i));
      continue;
    }
    if (c != '\\') {
      out += c;
      ++i;
      continue;
    }
    std::string_view rest = raw.substr(i);
    if (rest.substr(0, 2) == "\\\\") {
      out += '\\';
      i += 2;
    } else if (rest.substr(0, 3) == "\\X\\" && read_hex(raw, i + 3, 2) >= 0) {
      append_code_point(out, static_cast<std::uint32_t>(read_hex(raw, i + 3, 2)));
      i += 5;
    } else if (rest.substr(0, 4) == "\\X2\\" || rest.substr(0, 4) == "\\X4\\") {
      int digits = rest[2] == '2' ? 4 : 8;
      std::size_t k = i + 4;
      std::uint32_t pending_high = 0;
      while (read_hex(raw, k, digits) >= 0) {
        auto unit = static_cast<std::uint32_t>(read_hex(raw, k, digits));
        k += static_cast<std::size_t>(digits);
        if (digits == 4 && unit >= 0xD800 && unit <= 0xDBFF) {
          if (pending_high) append_code_point(out, 0xFFFD);
          pending_high = unit;
          continue;
        }
        if (digits == 4 && unit >= 0xDC00 && unit <= 0xDFFF && pending_high) {
          append_code_point(out, 0x10000 + ((pending_high - 0xD800) << 10) + (unit - 0xDC00));
          pending_high = 0;
          continue;
        }
        if (pending_high) append_code_point(out, 0xFFFD);
        pending_high = 0;
        append_code_point(out, unit);
      }
      if (pending_high) append_code_point(out, 0xFFFD);
      if (raw.substr(k, 4) == "\\X0\\") k += 4;
      i = k;
    } else if (rest.substr(0, 3) == "\\S\\" && rest.size() >= 4) {
      // Upper half of the current ISO 8859 page; read as ISO 8859-1 (see docs/formats/part21.md).
      append_code_point(out, static_cast<unsigned char>(rest[3]) | 0x80u);
      i += 4;
    } else if (rest.size() >= 4 && rest[1] == 'P' && rest[3] == '\\' && rest[2] >= 'A' && rest[2] <= 'I') {
      i += 4;  // a code page switch, \PA\ to \PI\.
    } else {
      out += '\\';
      ++i;
    }
  }
  return out;
}

class Parser {
 public:
  Parser(std::string_view text, const std::string& file) : tokens_(text, file) { advance(); }

  ReadResult parse() {
    expect_keyword("ISO-10303-21");
    expect(TokenKind::Semicolon, "after ISO-10303-21");
    parse_header();
    bool data_seen = false;
    for (;;) {
      if (current_.kind != TokenKind::Keyword) fail_here("expected DATA, ENDSEC or END-ISO-10303-21");
      std::string keyword = upper(current_.text);
      if (keyword == "DATA") {
        parse_data();
        data_seen = true;
      } else if (keyword == "ANCHOR" || keyword == "REFERENCE") {
        skip_section(keyword);
      } else if (keyword == "END-ISO-10303-21") {
        advance();
        if (current_.kind != TokenKind::Semicolon) expect(TokenKind::Semicolon, "after END-ISO-10303-21");
        break;  // not past the ';': what follows need not be Part 21 tokens
      } else {
        fail_here("expected DATA or END-ISO-10303-21, found " + std::string(current_.text));
      }
    }
    if (!data_seen) warn(current_, "the file has no DATA section");
    if (!tokens_.only_blanks_left())
      warn(current_, "text after END-ISO-10303-21; (e.g. a SIGNATURE section) is ignored");
    check_references();
    return std::move(result_);
  }

 private:
  void advance() {
    previous_ = current_;
    current_ = tokens_.next();
  }
  [[noreturn]] void fail_at(const Token& t, const std::string& message) const {
    tokens_.fail(t.line, t.column, message);
  }
  [[noreturn]] void fail_here(const std::string& message) const { fail_at(current_, message); }
  std::string found() const {
    if (current_.kind == TokenKind::End) return "the end of the file";
    std::string text(current_.text.substr(0, 40));
    if (current_.kind == TokenKind::InstanceName) text.insert(0, "#");
    return std::string(describe(current_.kind)) + " '" + text + "'";
  }
  void warn(const Token& t, std::string message) {
    Diagnostic d;
    d.severity = Severity::Warning;
    d.where = tokens_.location(t.line, t.column);
    d.message = std::move(message);
    result_.warnings.push_back(std::move(d));
  }

  void expect(TokenKind kind, const std::string& context) {
    if (current_.kind != kind) {
      if (kind == TokenKind::Semicolon && previous_.kind != TokenKind::End) {
        // A missing ';' belongs to the end of what came before it, usually the line above.
        tokens_.fail(previous_.end_line, previous_.end_column,
                     "expected ';' " + context + ", found " + found());
      }
      fail_here("expected " + std::string(describe(kind)) + " " + context + ", found " + found());
    }
    advance();
  }
  void expect_keyword(std::string_view keyword) {
    if (current_.kind != TokenKind::Keyword || upper(current_.text) != keyword)
      fail_here("expected " + std::string(keyword) + ", found " + found());
    advance();
  }

  void skip_section(const std::string& name) {
    warn(current_, name + " section is not supported and is skipped");
    if (current_.kind == TokenKind::Keyword) {
      // The tokenizer already stands after the keyword; the body may hold <anchor> syntax.
      Token section = current_;
      advance();
      if (current_.kind != TokenKind::Semicolon) fail_here("expected ';' after " + name);
      tokens_.skip_to_endsec();
      advance();
      if (!(current_.kind == TokenKind::Keyword && upper(current_.text) == "ENDSEC"))
        fail_at(section, name + " section has no ENDSEC");
    }
    advance();
    expect(TokenKind::Semicolon, "after ENDSEC");
  }

  // ---- HEADER
  void parse_header() {
    expect_keyword("HEADER");
    expect(TokenKind::Semicolon, "after HEADER");
    Header& h = result_.graph.header;
    h = Header{};
    bool has_description = false, has_name = false, has_schema = false;
    while (!(current_.kind == TokenKind::Keyword && upper(current_.text) == "ENDSEC")) {
      if (current_.kind != TokenKind::Keyword) fail_here("expected a header entity or ENDSEC, found " + found());
      Token at = current_;
      Record record = parse_record(false);
      expect(TokenKind::Semicolon, "after header entity " + record.entity);
      if (record.entity == "FILE_DESCRIPTION") {
        has_description = true;
        h.description = strings_of(record, 0, at);
        h.implementation_level = string_of(record, 1, at);
      } else if (record.entity == "FILE_NAME") {
        has_name = true;
        h.name = string_of(record, 0, at);
        h.time_stamp = string_of(record, 1, at);
        h.author = strings_of(record, 2, at);
        h.organization = strings_of(record, 3, at);
        h.preprocessor_version = string_of(record, 4, at);
        h.originating_system = string_of(record, 5, at);
        h.authorization = string_of(record, 6, at);
      } else if (record.entity == "FILE_SCHEMA") {
        has_schema = true;
        h.schema = strings_of(record, 0, at);
      } else {
        h.others.push_back(std::move(record));
      }
    }
    advance();
    expect(TokenKind::Semicolon, "after ENDSEC");
    if (!has_description) warn(current_, "HEADER has no FILE_DESCRIPTION");
    if (!has_name) warn(current_, "HEADER has no FILE_NAME");
    if (!has_schema) warn(current_, "HEADER has no FILE_SCHEMA");
  }

  std::string string_of(const Record& r, std::size_t index, const Token& at) {
    if (index >= r.attributes.size()) {
      warn(at, r.entity + " has no attribute " + std::to_string(index + 1));
      return {};
    }
    const Value& v = r.attributes[index];
    if (const auto* s = v.string_if()) return *s;
    if (!v.is_unset()) warn(at, r.entity + " attribute " + std::to_string(index + 1) + " is not a string");
    return {};
  }
  std::vector<std::string> strings_of(const Record& r, std::size_t index, const Token& at) {
    std::vector<std::string> out;
    if (index >= r.attributes.size()) {
      warn(at, r.entity + " has no attribute " + std::to_string(index + 1));
      return out;
    }
    const Value& v = r.attributes[index];
    if (const auto* s = v.string_if()) {  // a lone string where a list belongs: keep it
      out.push_back(*s);
      return out;
    }
    if (const auto* l = v.list_if()) {
      for (const auto& item : l->items) {
        if (const auto* s = item.string_if()) out.push_back(*s);
        else warn(at, r.entity + " attribute " + std::to_string(index + 1) + " holds a non-string");
      }
    } else if (!v.is_unset()) {
      warn(at, r.entity + " attribute " + std::to_string(index + 1) + " is not a list of strings");
    }
    return out;
  }

  // ---- DATA
  void parse_data() {
    advance();  // DATA
    if (current_.kind == TokenKind::LeftParen) parse_list(0);  // ed.3 section name and schema
    expect(TokenKind::Semicolon, "after DATA");
    for (;;) {
      if (current_.kind == TokenKind::InstanceName) {
        parse_instance();
      } else if (current_.kind == TokenKind::Keyword && upper(current_.text) == "ENDSEC") {
        advance();
        expect(TokenKind::Semicolon, "after ENDSEC");
        return;
      } else {
        fail_here("expected an instance (#n=...) or ENDSEC, found " + found());
      }
    }
  }

  InstanceId instance_id(const Token& t) {
    InstanceId id = 0;
    auto [end, ec] = std::from_chars(t.text.data(), t.text.data() + t.text.size(), id);
    if (ec != std::errc() || end != t.text.data() + t.text.size())
      fail_at(t, "instance number #" + std::string(t.text.substr(0, 30)) + " is too large");
    if (id == 0) fail_at(t, "instance number #0 is not allowed");
    return id;
  }

  void parse_instance() {
    Token name = current_;
    Instance instance;
    instance.id = instance_id(name);
    instance.line = name.line;
    instance.column = name.column;
    if (result_.graph.contains(instance.id)) {
      const Instance& first = result_.graph.at(instance.id);
      fail_at(name, "instance #" + std::to_string(instance.id) + " is defined twice (first on line " +
                        std::to_string(first.line) + ")");
    }
    advance();
    expect(TokenKind::Equals, "after #" + std::to_string(instance.id));
    if (current_.kind == TokenKind::LeftParen) {
      instance.complex = true;
      advance();
      while (current_.kind != TokenKind::RightParen) {
        if (current_.kind != TokenKind::Keyword)
          fail_here("expected an entity name in complex instance #" + std::to_string(instance.id) + ", found " + found());
        instance.records.push_back(parse_record(true));
      }
      if (instance.records.empty()) fail_here("complex instance #" + std::to_string(instance.id) + " is empty");
      advance();
    } else if (current_.kind == TokenKind::Keyword) {
      instance.records.push_back(parse_record(true));
    } else {
      fail_here("expected an entity name after #" + std::to_string(instance.id) + "=, found " + found());
    }
    expect(TokenKind::Semicolon, "after instance #" + std::to_string(instance.id));
    result_.graph.insert(std::move(instance));
  }

  Record parse_record(bool data_section) {
    Record record;
    record.entity = upper(current_.text);
    if (data_section && record.entity.find('-') != std::string::npos)
      fail_here("'" + record.entity + "' is not an entity name");
    advance();
    if (current_.kind != TokenKind::LeftParen)
      fail_here("expected '(' after " + record.entity + ", found " + found());
    record.attributes = parse_list(0).items;
    return record;
  }

  // At '(' : reads "( [parameter {, parameter}] )".
  List parse_list(int depth) {
    if (depth > kMaxNesting) fail_here("lists nested deeper than " + std::to_string(kMaxNesting));
    advance();  // (
    List list;
    if (current_.kind == TokenKind::RightParen) {
      advance();
      return list;
    }
    for (;;) {
      list.items.push_back(parse_parameter(depth + 1));
      if (current_.kind == TokenKind::Comma) {
        advance();
        continue;
      }
      if (current_.kind == TokenKind::RightParen) {
        advance();
        return list;
      }
      fail_here("expected ',' or ')' between parameters, found " + found());
    }
  }

  Value parse_parameter(int depth) {
    const Token t = current_;
    switch (t.kind) {
      case TokenKind::Dollar: advance(); return unset();
      case TokenKind::Star: advance(); return derived();
      case TokenKind::Integer: {
        std::int64_t v = 0;
        const char* first = t.text.data() + (t.text.front() == '+' ? 1 : 0);
        auto [end, ec] = std::from_chars(first, t.text.data() + t.text.size(), v);
        if (ec != std::errc() || end != t.text.data() + t.text.size())
          fail_at(t, "integer " + std::string(t.text.substr(0, 30)) + " is out of range");
        advance();
        return integer(v);
      }
      case TokenKind::Real: {
        double v = 0;
        const char* first = t.text.data() + (t.text.front() == '+' ? 1 : 0);
        auto [end, ec] = std::from_chars(first, t.text.data() + t.text.size(), v);
        if (ec != std::errc() || end != t.text.data() + t.text.size())
          fail_at(t, "real " + std::string(t.text.substr(0, 30)) + " is out of range");
        advance();
        return real(v);
      }
      case TokenKind::String: advance(); return string(decode_string(t.text));
      case TokenKind::Enumeration: advance(); return Value{Enumeration{upper(t.text)}};
      case TokenKind::Binary: advance(); return Value{Binary{upper(t.text)}};
      case TokenKind::InstanceName: {
        InstanceId id = instance_id(t);
        pending_.push_back({id, t.line, t.column});
        advance();
        return ref(id);
      }
      case TokenKind::LeftParen: return Value{parse_list(depth)};
      case TokenKind::Keyword: {
        std::string type = upper(t.text);
        advance();
        if (current_.kind != TokenKind::LeftParen) fail_here("expected '(' after typed parameter " + type);
        advance();
        TypedParameter typed{std::move(type), {}};
        typed.value.push_back(parse_parameter(depth + 1));
        if (current_.kind != TokenKind::RightParen)
          fail_here("expected ')' closing typed parameter " + typed.type + ", found " + found());
        advance();
        return Value{std::move(typed)};
      }
      default: fail_here("expected a parameter, found " + found());
    }
  }

  void check_references() {
    for (const auto& r : pending_)
      if (!result_.graph.contains(r.id))
        tokens_.fail(r.line, r.column, "reference to #" + std::to_string(r.id) + ", which is not defined in the file");
  }

  struct PendingReference {
    InstanceId id;
    std::uint32_t line, column;
  };

  Tokenizer tokens_;
  Token current_, previous_;
  ReadResult result_;
  std::vector<PendingReference> pending_;
};

}  // namespace

ReadResult read_part21(std::string_view text, const std::string& file_name) {
  Parser parser(text, file_name);
  return parser.parse();
}

ReadResult read_part21_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(SourceLocation{path.string(), 0, 0}, "cannot open the file");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  std::string text = std::move(buffer).str();
  return read_part21(text, path.string());
}

}  // namespace ncbridge::step_writer::part21
