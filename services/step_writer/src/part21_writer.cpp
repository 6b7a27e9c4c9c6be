#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "ncbridge/step_writer/part21_writer.hpp"
#include "part21_text.hpp"
#include "utf8.hpp"

namespace ncbridge::step_writer::part21 {
namespace {

constexpr char kHex[] = "0123456789ABCDEF";

void append_hex(std::string& out, std::uint32_t value, int digits) {
  for (int shift = 4 * (digits - 1); shift >= 0; shift -= 4) out += kHex[(value >> shift) & 0xF];
}

// Zero, and values in [1e-3, 1e5) with at most six decimals (most program coordinates): the
// shortest round-trip text is the decimal with the fewest decimals that reads back as the value,
// and std::to_chars writes it in fixed notation (never longer than the exponent form there).
// The value rounded to six decimals reads back as the value exactly when some decimal with at
// most six decimals does, and that one is it without its trailing zeros. nullptr when the value
// is not such a decimal. (Checked against std::to_chars on 16 million such values.)
char* write_short_decimal(char* first, double value) {
  char* p = first;
  if (value == 0) {  // 0. and -0.
    if (std::signbit(value)) *p++ = '-';
    *p++ = '0';
    *p++ = '.';
    return p;
  }
  const double magnitude = std::fabs(value);
  if (!(magnitude >= 1e-3 && magnitude < 1e5)) return nullptr;
  // Rounded to the nearest integer by the 2^52 trick (exact below 2^52; here below 1e11).
  const double scaled = (magnitude * 1e6 + 0x1p52) - 0x1p52;
  if (scaled / 1e6 != magnitude) return nullptr;
  auto digits = static_cast<std::uint64_t>(scaled);
  int decimals = 6;
  while (decimals > 0 && digits % 10 == 0) {
    digits /= 10;
    --decimals;
  }
  // The digits, right-aligned in `text`; at least one before the point.
  char text[24];
  char* q = text + sizeof text;
  int n = 0;
  do {
    *--q = static_cast<char>('0' + digits % 10);
    digits /= 10;
    ++n;
  } while (digits != 0);
  for (; n <= decimals; ++n) *--q = '0';
  if (value < 0) *p++ = '-';
  const std::size_t whole = static_cast<std::size_t>(n - decimals);
  std::memcpy(p, q, whole);
  p += whole;
  *p++ = '.';
  std::memcpy(p, q + whole, static_cast<std::size_t>(decimals));
  return p + decimals;
}

}  // namespace

char* write_real(char* first, double value) {
  if (!std::isfinite(value)) throw std::invalid_argument("Part 21 cannot represent a NaN or infinite real");
  if (char* end = write_short_decimal(first, value)) return end;
  char buf[64];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);  // shortest round-trip form
  std::string_view text(buf, static_cast<std::size_t>(end - buf));
  std::size_t e = text.find('e');
  std::string_view mantissa = text.substr(0, e);
  char* p = std::copy(mantissa.begin(), mantissa.end(), first);
  if (mantissa.find('.') == std::string_view::npos) *p++ = '.';
  if (e != std::string_view::npos) {
    std::string_view exponent = text.substr(e + 1);
    *p++ = 'E';
    if (!exponent.empty() && exponent.front() == '+') exponent.remove_prefix(1);
    p = std::copy(exponent.begin(), exponent.end(), p);
  }
  return p;
}

void append_real(std::string& out, double value) {
  char buf[kMaxRealChars];
  out.append(buf, write_real(buf, value));
}

void append_string(std::string& out, std::string_view utf8) {
  out += '\'';
  if (std::all_of(utf8.begin(), utf8.end(), [](char c) { return c >= 0x20 && c < 0x7F && c != '\'' && c != '\\'; })) {
    out += utf8;  // nothing to escape
    out += '\'';
    return;
  }
  std::size_t i = 0;
  while (i < utf8.size()) {
    unsigned char c = static_cast<unsigned char>(utf8[i]);
    if (c >= 0x20 && c < 0x7F) {
      if (c == '\'') out += "''";
      else if (c == '\\') out += "\\\\";
      else out += static_cast<char>(c);
      ++i;
    } else if (c < 0x80) {
      out += "\\X\\";
      append_hex(out, c, 2);
      ++i;
    } else {
      // A run of non-ASCII characters: one \X2\ (or \X4\ beyond the BMP) group.
      std::vector<std::uint32_t> run;
      while (i < utf8.size() && static_cast<unsigned char>(utf8[i]) >= 0x80)
        run.push_back(decode_utf8(utf8, i));
      bool wide = false;
      for (auto cp : run) wide |= cp > 0xFFFF;
      out += wide ? "\\X4\\" : "\\X2\\";
      for (auto cp : run) append_hex(out, cp, wide ? 8 : 4);
      out += "\\X0\\";
    }
  }
  out += '\'';
}

namespace {

using IdMap = std::unordered_map<InstanceId, InstanceId>;

class ValueWriter {
 public:
  ValueWriter(std::string& out, const IdMap* renumbered, const Graph* graph, std::size_t width)
      : out_(out), renumbered_(renumbered), graph_(graph), width_(width) {}

  void begin_instance() { line_start_ = out_.size(); }

  void value(const Value& v) {
    std::visit([this](const auto& x) { write(x); }, v.data);
  }

  void values(const std::vector<Value>& items) {
    out_ += '(';
    for (std::size_t k = 0; k < items.size(); ++k) {
      if (k) separator();
      value(items[k]);
    }
    out_ += ')';
  }

 private:
  void separator() {
    out_ += ',';
    if (width_ && out_.size() - line_start_ > width_) {
      out_ += "\n  ";
      line_start_ = out_.size() - 2;
    }
  }
  void write(const Unset&) { out_ += '$'; }
  void write(const Derived&) { out_ += '*'; }
  void write(std::int64_t i) { out_ += std::to_string(i); }
  void write(double d) { append_real(out_, d); }
  void write(const std::string& s) { append_string(out_, s); }
  void write(const Enumeration& e) {
    out_ += '.';
    out_ += e.name;
    out_ += '.';
  }
  void write(const Binary& b) {
    out_ += '"';
    out_ += b.digits;
    out_ += '"';
  }
  void write(const Reference& r) {
    InstanceId id = r.id;
    if (graph_ && !graph_->contains(id))
      throw std::invalid_argument("Part 21 reference to #" + std::to_string(id) + ", which is not in the graph");
    if (renumbered_) id = renumbered_->at(id);
    out_ += '#';
    out_ += std::to_string(id);
  }
  void write(const List& l) { values(l.items); }
  void write(const TypedParameter& t) {
    out_ += t.type;
    values(t.value);
  }

  std::string& out_;
  const IdMap* renumbered_;
  const Graph* graph_;
  std::size_t width_;
  std::size_t line_start_ = 0;
};

void append_string_list(std::string& out, const std::vector<std::string>& items) {
  out += '(';
  if (items.empty()) out += "''";
  for (std::size_t k = 0; k < items.size(); ++k) {
    if (k) out += ',';
    append_string(out, items[k]);
  }
  out += ')';
}

void append_header(std::string& out, const Header& h, const WriteOptions& options) {
  out += "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(";
  append_string_list(out, h.description);
  out += ',';
  append_string(out, h.implementation_level);
  out += ");\nFILE_NAME(";
  append_string(out, h.name);
  out += ',';
  append_string(out, !h.time_stamp.empty() ? h.time_stamp
                     : options.unix_time   ? time_stamp_of(*options.unix_time)
                                           : time_stamp_now());
  out += ',';
  append_string_list(out, h.author);
  out += ',';
  append_string_list(out, h.organization);
  out += ',';
  append_string(out, h.preprocessor_version);
  out += ',';
  append_string(out, h.originating_system);
  out += ',';
  append_string(out, h.authorization);
  out += ");\nFILE_SCHEMA(";
  append_string_list(out, h.schema);
  out += ");\n";
  ValueWriter writer(out, nullptr, nullptr, 0);
  for (const auto& record : h.others) {
    out += record.entity;
    writer.values(record.attributes);
    out += ";\n";
  }
  out += "ENDSEC;\n";
}

}  // namespace

std::string format_real(double value) {
  std::string s;
  append_real(s, value);
  return s;
}

std::string format_string(std::string_view utf8) {
  std::string s;
  append_string(s, utf8);
  return s;
}

std::string format_value(const Value& value) {
  std::string s;
  ValueWriter(s, nullptr, nullptr, 0).value(value);
  return s;
}

std::string time_stamp_of(std::int64_t unix_seconds) {
  std::time_t t = static_cast<std::time_t>(unix_seconds);
  std::tm tm{};
  if (!gmtime_r(&t, &tm)) throw std::invalid_argument("time stamp out of range");
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &tm);
  return buf;
}

std::string time_stamp_now() {
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) {
    std::int64_t seconds = 0;
    std::string_view text(epoch);
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), seconds);
    if (ec == std::errc() && end == text.data() + text.size() && !text.empty())
      return time_stamp_of(seconds);
  }
  return time_stamp_of(static_cast<std::int64_t>(std::time(nullptr)));
}

std::string write_part21(const Graph& graph, const WriteOptions& options) {
  std::string out;
  out.reserve(256 + graph.size() * 64);
  append_header(out, graph.header, options);
  out += "DATA;\n";

  IdMap renumbered;
  if (options.renumber) {
    InstanceId next = 1;
    for (const auto& instance : graph.instances()) renumbered.emplace(instance.id, next++);
  }
  ValueWriter writer(out, options.renumber ? &renumbered : nullptr, &graph, options.line_width);
  for (const auto& instance : graph.instances()) {
    if (instance.records.empty())
      throw std::invalid_argument("Part 21 instance #" + std::to_string(instance.id) + " was reserved but never set");
    writer.begin_instance();
    out += '#';
    out += std::to_string(options.renumber ? renumbered.at(instance.id) : instance.id);
    out += '=';
    if (instance.complex) out += '(';
    for (const auto& record : instance.records) {
      out += record.entity;
      writer.values(record.attributes);
    }
    if (instance.complex) out += ')';
    out += ";\n";
  }
  out += "ENDSEC;\nEND-ISO-10303-21;\n";
  return out;
}

void write_part21(const Graph& graph, std::ostream& out, const WriteOptions& options) {
  std::string text = write_part21(graph, options);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

}  // namespace ncbridge::step_writer::part21
