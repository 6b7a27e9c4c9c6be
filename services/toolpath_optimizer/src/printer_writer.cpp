// Printer G-code writer (printer_writer.hpp).
#include "ncbridge/toolpath_optimizer/printer_writer.hpp"

#include <stdexcept>

#include "ncbridge/toolpath_optimizer/geometry.hpp"
#include "ncbridge/toolpath_optimizer/number_text.hpp"

namespace ncbridge::toolpath_optimizer {

namespace {

// Text handed on in pieces of about this size: large enough for few calls, small enough that
// the deviation checker reading the output back is never far behind the input.
constexpr std::size_t kPiece = 8 << 10;

void word(std::string& out, char letter, double value, int decimals) {
  out.push_back(' ');
  out.push_back(letter);
  append_number(out, value, decimals);
}

}  // namespace

PrinterWriter::PrinterWriter(std::function<void(std::string_view)> out, int centre_decimals)
    : out_(std::move(out)), centre_decimals_(centre_decimals) {
  buffer_.reserve(kPiece + 256);
}

PrinterWriter::~PrinterWriter() = default;

void PrinterWriter::format_motion(const Motion& m, std::string& out, int centre_decimals) {
  const int d = m.printer.xyz_decimals;
  const int dc = centre_decimals >= 0 ? centre_decimals : std::min(d + 1, 6);
  if (m.kind == MotionKind::Arc) {
    out.append(m.arc.ccw ? "G3" : "G2");
    const PlanePoint s = to_plane(m.start, m.arc.plane);
    const PlanePoint e = to_plane(m.end, m.arc.plane);
    // The plane's axes always (a full circle ends where it starts), the normal when it moves.
    const char* letters = m.arc.plane == canonical::Plane::YZ ? "YZX" : m.arc.plane == canonical::Plane::XZ ? "ZXY" : "XYZ";
    const char* offsets = m.arc.plane == canonical::Plane::YZ ? "JK" : m.arc.plane == canonical::Plane::XZ ? "KI" : "IJ";
    // In the order X Y Z, I J K.
    double value[3];
    bool write[3];
    for (int i = 0; i < 3; ++i) write[i] = false;
    const double plane_values[3] = {e.first, e.second, e.normal};
    for (int i = 0; i < 3; ++i) {
      const int axis = letters[i] - 'X';
      value[axis] = plane_values[i];
      write[axis] = i < 2 || e.normal != s.normal;
    }
    for (int axis = 0; axis < 3; ++axis) {
      if (write[axis]) word(out, static_cast<char>('X' + axis), value[axis], d);
    }
    double offset[3] = {0, 0, 0};
    bool has_offset[3] = {false, false, false};
    offset[offsets[0] - 'I'] = m.arc.first_centre - s.first;
    offset[offsets[1] - 'I'] = m.arc.second_centre - s.second;
    has_offset[offsets[0] - 'I'] = has_offset[offsets[1] - 'I'] = true;
    for (int k = 0; k < 3; ++k) {
      if (has_offset[k]) word(out, static_cast<char>('I' + k), offset[k], dc);
    }
    if (m.arc.extra_turns > 0) word(out, 'P', m.arc.extra_turns + 1, 0);
  } else {
    out.append(m.kind == MotionKind::Traverse ? "G0" : "G1");
    if (m.end.x != m.start.x) word(out, 'X', m.end.x, d);
    if (m.end.y != m.start.y) word(out, 'Y', m.end.y, d);
    if (m.end.z != m.start.z) word(out, 'Z', m.end.z, d);
  }
  if (m.printer.has_e) word(out, 'E', m.printer.relative_e ? m.extrusion : m.printer.e_position, m.printer.e_decimals);
  if (m.printer.has_f) word(out, 'F', m.feed, 3);
}

void PrinterWriter::write(std::string_view text, bool command) {
  buffer_.append(text);
  ++lines_;
  if (command) ++commands_;
  bytes_ += text.size();
  if (buffer_.size() >= kPiece) flush();
}

void PrinterWriter::element(Element&& e) {
  if (auto* m = std::get_if<Motion>(&e.item)) {
    ++motion_blocks_;
    if (!m->printer.text.empty()) {
      write(m->printer.text, true);
      return;
    }
    std::string line;
    format_motion(*m, line, centre_decimals_);
    line.append(m->printer.crlf ? "\r\n" : "\n");
    write(line, true);
  } else if (auto* t = std::get_if<TextLine>(&e.item)) {
    const bool command = t->role != LineRole::Blank && t->role != LineRole::Comment;
    if (t->role == LineRole::MotionMode) ++motion_blocks_;  // `G1 F1800` is a motion block
    write(t->text, command);
  } else if (std::holds_alternative<Loop>(e.item)) {
    throw std::logic_error("printer G-code has no loops: a loop reached the printer writer");
  } else {
    throw std::logic_error("a canonical call reached the printer writer");
  }
}

void PrinterWriter::flush() {
  if (buffer_.empty()) return;
  out_(buffer_);
  buffer_.clear();
}

void PrinterWriter::end() { flush(); }

}  // namespace ncbridge::toolpath_optimizer
