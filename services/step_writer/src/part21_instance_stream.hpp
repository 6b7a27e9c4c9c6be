#pragma once
// Writes Part 21 instances as text, straight from attribute values, with consecutive ids from 1,
// and hands the text on in chunks of about a megabyte: a file of any size is written without
// holding it, or an instance graph, in memory. Attributes are separated and lines wrapped (after a
// comma, past kLineWidth) as the generic writer does.
//
//   const InstanceId p = s.begin("CARTESIAN_POINT"); s.string(""); s.open_list(); s.real(1); ... s.close_list(); s.end();
#include <charconv>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "ncbridge/step_writer/part21_value.hpp"
#include "part21_text.hpp"

namespace ncbridge::step_writer::part21 {

class InstanceStream {
 public:
  using ChunkSink = std::function<void(std::string_view)>;
  static constexpr std::size_t kChunk = std::size_t{1} << 20;
  static constexpr std::size_t kLineWidth = 100;

  explicit InstanceStream(const ChunkSink& sink) : sink_(sink) { out_.reserve(kChunk + kChunk / 4); }

  // Text outside the DATA section (header, ENDSEC), written as is.
  void raw(std::string_view text) { out_ += text; }

  InstanceId begin(std::string_view entity) {
    line_start_ = out_.size();
    out_ += '#';
    append_id(next_);
    out_ += '=';
    out_ += entity;
    out_ += '(';
    first_ = true;
    return next_;
  }
  InstanceId end() {
    out_ += ");\n";
    if (out_.size() >= kChunk) flush();
    return next_++;
  }

  void real(double v) {
    separator();
    char buf[kMaxRealChars];
    out_.append(buf, write_real(buf, v));
  }
  void integer(std::int64_t v) {
    separator();
    char buf[24];
    out_.append(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
  }
  void ref(InstanceId id) {
    separator();
    out_ += '#';
    append_id(id);
  }
  void unset() {
    separator();
    out_ += '$';
  }
  void string(std::string_view utf8) {
    separator();
    append_string(out_, utf8);
  }
  void enumeration(std::string_view name) {  // upper case, without the dots
    separator();
    out_ += '.';
    out_ += name;
    out_ += '.';
  }
  void boolean(bool v) { enumeration(v ? "T" : "F"); }
  void opt_real(const std::optional<double>& v) { v ? real(*v) : unset(); }
  void opt_boolean(const std::optional<bool>& v) { v ? boolean(*v) : unset(); }
  void opt_ref(InstanceId id) { id != 0 ? ref(id) : unset(); }  // 0: no instance, written $
  void typed_real(std::string_view type, double v) {  // PARAMETER_VALUE(30.)
    separator();
    out_ += type;
    out_ += '(';
    first_ = true;
    real(v);
    out_ += ')';
  }
  void open_list() {
    separator();
    out_ += '(';
    first_ = true;
  }
  void close_list() {
    out_ += ')';
    first_ = false;
  }
  template <class Ids>
  void refs(const Ids& ids) {
    open_list();
    for (InstanceId id : ids) ref(id);
    close_list();
  }

  // Hands on what is left; returns the number of bytes written in all.
  std::uint64_t finish() {
    flush();
    return written_;
  }
  InstanceId next_id() const { return next_; }

 private:
  void separator() {
    if (first_) {
      first_ = false;
      return;
    }
    out_ += ',';
    if (out_.size() - line_start_ > kLineWidth) {
      out_ += "\n  ";
      line_start_ = out_.size() - 2;
    }
  }
  void append_id(InstanceId id) {
    char buf[24];
    out_.append(buf, std::to_chars(buf, buf + sizeof buf, id).ptr);
  }
  void flush() {
    if (out_.empty()) return;
    written_ += out_.size();
    sink_(out_);
    out_.clear();
    line_start_ = 0;
  }

  const ChunkSink& sink_;
  std::string out_;
  std::size_t line_start_ = 0;
  bool first_ = true;
  InstanceId next_ = 1;
  std::uint64_t written_ = 0;
};

}  // namespace ncbridge::step_writer::part21
