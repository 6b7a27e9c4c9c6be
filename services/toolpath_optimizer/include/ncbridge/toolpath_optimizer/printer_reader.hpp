#pragma once
// The printer front-end: 3D-printer G-code (Marlin, RepRapFirmware, Klipper) as an element
// stream. G0/G1/G2/G3 become motions with their extrusion; every other line (temperatures, fans,
// homing, M-codes, comments, blank lines) becomes a text line, in place and byte for byte.
//
// What the front-end tracks (docs/optimize.md, "Printer G-code"):
// - G90/G91 for X Y Z, M82/M83 for E, and how each firmware lets G90/G91 touch E: Marlin: the
//   last of G90/G91/M82/M83 decides (G90/G91 clear M83/M82); RepRapFirmware: only M82/M83;
//   Klipper: E is relative under G91 or M83.
// - G92 sets axes (a letter without a number sets 0); G28/G29 leave the homed axes unknown until
//   a move names them absolutely; G20/G21 switch units; G17/G18/G19 the arc plane.
// - A motion line with anything beyond G0/G1 and X Y Z E F (an N number, a checksum, a comment,
//   another word, relative coordinates) is kept as written: the optimizer never rewrites it.
// Bad input (a malformed number on an axis, binary data) throws InputError with line and column.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "ncbridge/toolpath_optimizer/toolpath.hpp"

namespace ncbridge::toolpath_optimizer {

enum class PrinterFlavor : std::uint8_t { Marlin, RepRapFirmware, Klipper };

// "marlin", "reprap" (or "reprapfirmware", "rrf"), "klipper"; false for anything else.
bool parse_printer_flavor(std::string_view name, PrinterFlavor& flavor);
std::string_view printer_flavor_name(PrinterFlavor flavor);

struct PrinterCounts {
  std::uint64_t lines = 0;
  std::uint64_t commands = 0;       // lines with a command (not blank, not only a comment)
  std::uint64_t motion_blocks = 0;  // G0..G3 lines
  std::uint64_t arcs = 0;           // G2/G3 lines
  std::uint64_t bytes = 0;
};

// Reads line by line and streams elements into the sink.
class PrinterReader {
 public:
  PrinterReader(std::string file_name, PrinterFlavor flavor, ElementSink& sink);
  // One line, with its line ending (the last line of a file may have none).
  void line(std::string_view text);
  // Any piece of the text (lines may be split across pieces); finish() reads what is left.
  void text(std::string_view piece);
  // Ends the stream (sink.end()).
  void finish();
  const PrinterCounts& counts() const { return counts_; }

 private:
  [[noreturn]] void fail(std::size_t column, const std::string& message) const;

  std::string file_;
  std::string pending_;  // an unfinished line from text()
  PrinterFlavor flavor_;
  ElementSink& sink_;
  PrinterCounts counts_;
  std::uint32_t line_number_ = 0;
  Vec3 position_{};
  double e_position_ = 0;
  double feed_ = 0;
  bool relative_xyz_ = false;
  bool m83_ = false;         // M83 in force (Marlin: the last of G90/G91/M82/M83)
  bool inches_ = false;
  canonical::Plane plane_ = canonical::Plane::XY;
};

// Reads a file in 1 MiB chunks (memory stays flat in file length). Throws InputError when the
// file cannot be read.
PrinterCounts read_printer_file(const std::filesystem::path& path, PrinterFlavor flavor, ElementSink& sink);
PrinterCounts read_printer_text(std::string_view text, const std::string& name, PrinterFlavor flavor,
                                ElementSink& sink);

// Calls `each(line)` for every line of `text`, each with its ending.
template <typename Each>
void for_each_line(std::string_view text, Each&& each) {
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    end = end == std::string_view::npos ? text.size() : end + 1;
    each(text.substr(begin, end - begin));
    begin = end;
  }
}

}  // namespace ncbridge::toolpath_optimizer
