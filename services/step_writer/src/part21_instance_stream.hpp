#pragma once
// Writes Part 21 instances as text, straight from attribute values, with consecutive ids from 1
// (an id may be reserved for an instance written later),
// and hands the text on in chunks of about a megabyte: a file of any size is written without
// holding it, or an instance graph, in memory. Attributes are separated and lines wrapped (after a
// comma, past kLineWidth) as the generic writer does.
//
//   const InstanceId p = s.begin("CARTESIAN_POINT"); s.string(""); s.open_list(); s.real(1); ... s.close_list(); s.end();
#include <algorithm>
#include <charconv>
#include <cstring>
#include <memory>
#include <cstddef>
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

  explicit InstanceStream(const ChunkSink& sink) : sink_(sink), capacity_(kChunk + kChunk / 4), buf_(new char[capacity_]) {}

  // Text outside the DATA section (header, ENDSEC), written as is.
  void raw(std::string_view text) { put(text); }

  InstanceId begin(std::string_view entity) { return begin_instance(next_++, entity); }
  // An id taken now for an instance written later (with begin(reserved, entity)), so that
  // instances written before it can refer to it.
  InstanceId reserve() { return next_++; }
  InstanceId begin(InstanceId reserved, std::string_view entity) { return begin_instance(reserved, entity); }
  // A complex instance #n=(A(...)B(...)): begin_complex(), then for each partial entity, in
  // alphabetical order, record("A"), its attributes, end_record(); then end().
  InstanceId begin_complex() {
    current_ = next_++;
    line_start_ = static_cast<std::ptrdiff_t>(len_);
    char* p = room(kMaxIdChars + 3);
    *p++ = '#';
    p = write_id(p, current_);
    *p++ = '=';
    *p++ = '(';
    len_ = static_cast<std::size_t>(p - buf_.get());
    return current_;
  }
  void record(std::string_view entity) {
    put(entity);
    put("(");
    first_ = true;
  }
  void end_record() { put(")"); }
  InstanceId end() {
    put(");\n");
    if (len_ >= kChunk) flush();
    return current_;
  }

  void real(double v) {
    char* p = separator(room(kSeparatorChars + kMaxRealChars));
    len_ = static_cast<std::size_t>(write_real(p, v) - buf_.get());
  }
  void integer(std::int64_t v) {
    char* p = separator(room(kSeparatorChars + kMaxIdChars));
    len_ = static_cast<std::size_t>(std::to_chars(p, p + kMaxIdChars, v).ptr - buf_.get());
  }
  void ref(InstanceId id) {
    char* p = separator(room(kSeparatorChars + 1 + kMaxIdChars));
    *p++ = '#';
    len_ = static_cast<std::size_t>(write_id(p, id) - buf_.get());
  }
  // Inside a long list (a workplan's elements), hands on what is made so far once it is a chunk.
  void flush_if_full() {
    if (len_ >= kChunk) flush();
  }
  void unset() { token("$"); }
  void string(std::string_view utf8) {
    if (std::all_of(utf8.begin(), utf8.end(), [](char c) { return c >= 0x20 && c < 0x7F && c != '\'' && c != '\\'; })) {
      char* p = separator(room(kSeparatorChars + utf8.size() + 2));  // nothing to escape
      *p++ = '\'';
      p = copy(utf8, p);
      *p++ = '\'';
      len_ = static_cast<std::size_t>(p - buf_.get());
      return;
    }
    scratch_.clear();
    append_string(scratch_, utf8);
    token(scratch_);
  }
  void enumeration(std::string_view name) {  // upper case, without the dots
    char* p = separator(room(kSeparatorChars + name.size() + 2));
    *p++ = '.';
    p = copy(name, p);
    *p++ = '.';
    len_ = static_cast<std::size_t>(p - buf_.get());
  }
  void boolean(bool v) { token(v ? ".T." : ".F."); }
  void unknown() { token(".U."); }  // LOGICAL unknown
  void opt_real(const std::optional<double>& v) { v ? real(*v) : unset(); }
  void opt_boolean(const std::optional<bool>& v) { v ? boolean(*v) : unset(); }
  void opt_ref(InstanceId id) { id != 0 ? ref(id) : unset(); }  // 0: no instance, written $
  void typed_real(std::string_view type, double v) {  // PARAMETER_VALUE(30.)
    char* p = separator(room(kSeparatorChars + type.size() + 1));
    p = copy(type, p);
    *p++ = '(';
    len_ = static_cast<std::size_t>(p - buf_.get());
    first_ = true;
    real(v);
    put(")");
  }
  void open_list() {
    token("(");
    first_ = true;
  }
  void close_list() {
    put(")");
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
  static constexpr std::size_t kMaxIdChars = 24;
  static constexpr std::size_t kIdDigits = 20;  // of the largest 64-bit id
  static constexpr std::size_t kSeparatorChars = 4;  // ",\n  "

  InstanceId begin_instance(InstanceId id, std::string_view entity) {
    current_ = id;
    line_start_ = static_cast<std::ptrdiff_t>(len_);
    char* p = room(kMaxIdChars + entity.size() + 3);
    *p++ = '#';
    p = write_id(p, id);
    *p++ = '=';
    p = copy(entity, p);
    *p++ = '(';
    len_ = static_cast<std::size_t>(p - buf_.get());
    first_ = true;
    return id;
  }

  // Decimal digits of an id, two at a time from the end (ids are most of a file's numbers).
  // Copies a fixed kIdDigits bytes to `p`, which has room for them (kMaxIdChars); those past the
  // digits are overwritten by what follows.
  static char* write_id(char* p, InstanceId id) {
    static constexpr char kPairs[] =
        "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
        "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
        "8081828384858687888990919293949596979899";
    char digits[2 * kIdDigits];
    char* q = digits + kIdDigits;
    while (id >= 100) {
      q -= 2;
      std::memcpy(q, kPairs + 2 * (id % 100), 2);
      id /= 100;
    }
    if (id >= 10) {
      q -= 2;
      std::memcpy(q, kPairs + 2 * id, 2);
    } else {
      *--q = static_cast<char>('0' + id);
    }
    std::memcpy(p, q, kIdDigits);
    return p + (digits + kIdDigits - q);
  }

  // At least n free bytes at the end of the buffer.
  char* room(std::size_t n) {
    if (capacity_ - len_ < n) grow(n);
    return buf_.get() + len_;
  }
  void grow(std::size_t n) {
    const std::size_t capacity = std::max(2 * capacity_, len_ + n);
    std::unique_ptr<char[]> bigger(new char[capacity]);
    std::memcpy(bigger.get(), buf_.get(), len_);
    buf_ = std::move(bigger);
    capacity_ = capacity;
  }
  static char* copy(std::string_view text, char* to) {
    std::memcpy(to, text.data(), text.size());
    return to + text.size();
  }
  void put(std::string_view text) {
    copy(text, room(text.size()));
    len_ += text.size();
  }
  void token(std::string_view text) {
    char* p = separator(room(kSeparatorChars + text.size()));
    len_ = static_cast<std::size_t>(copy(text, p) - buf_.get());
  }
  // The comma before every attribute but the first of its list, and a line break after it once
  // the line is long; `p` has room for both.
  char* separator(char* p) {
    if (first_) {
      first_ = false;
      return p;
    }
    *p++ = ',';
    const std::size_t at = static_cast<std::size_t>(p - buf_.get());
    if (static_cast<std::ptrdiff_t>(at) - line_start_ > static_cast<std::ptrdiff_t>(kLineWidth)) {
      *p++ = '\n';
      line_start_ = static_cast<std::ptrdiff_t>(at) + 1;
      *p++ = ' ';
      *p++ = ' ';
    }
    return p;
  }
  void flush() {
    if (len_ == 0) return;
    written_ += len_;
    sink_(std::string_view(buf_.get(), len_));
    line_start_ -= static_cast<std::ptrdiff_t>(len_);  // may be before the buffer: an instance goes on
    len_ = 0;
  }

  const ChunkSink& sink_;
  std::size_t capacity_;
  std::unique_ptr<char[]> buf_;
  std::size_t len_ = 0;
  std::ptrdiff_t line_start_ = 0;  // in the buffer; negative once an instance's start was handed on
  bool first_ = true;
  InstanceId next_ = 1;
  InstanceId current_ = 0;
  std::uint64_t written_ = 0;
  std::string scratch_;
};

}  // namespace ncbridge::step_writer::part21
