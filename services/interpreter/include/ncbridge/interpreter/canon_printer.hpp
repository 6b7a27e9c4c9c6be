#pragma once
// Prints a canonical call stream in the exact line format of LinuxCNC's standalone `rs274`
// (src/emc/sai/saicanon.cc): a `%5d ` call counter, the N column (`N12345 ` or `N..... `),
// then `NAME(args)` with reals as `%.4f`. Output is diffable byte for byte with rs274's.
//
// Output is buffered and written in large chunks; nothing is formatted through iostreams.
#include <cstdint>
#include <cstdio>
#include <string>

#include "ncbridge/canonical/call.hpp"

namespace ncbridge::interpreter {

class CanonPrinter final : public canonical::Sink {
 public:
  // Writes to `out` (not owned). The buffer is flushed when full, by flush(), end() and the
  // destructor.
  explicit CanonPrinter(std::FILE* out);
  ~CanonPrinter() override;
  CanonPrinter(const CanonPrinter&) = delete;
  CanonPrinter& operator=(const CanonPrinter&) = delete;

  void call(const canonical::Call& call) override;
  void end() override;
  void flush();

  // rs274 prints two ON_RESET() with an empty N column when it stops, whatever the reason
  // (program end, error, end of file). Printing them is the caller's choice.
  void print_driver_reset();

  // Formats one call (without counter, N column or newline) into `out`, replacing its content.
  // `units` are the program's length units at that call: rs274's machine works in inches, and
  // it prints SET_TOOL_TABLE_ENTRY lengths in them.
  static void format_call(const canonical::Data& data, std::string& out,
                          canonical::Units units = canonical::Units::Millimeters);

 private:
  void write_prefix(const canonical::Source& source);
  std::FILE* out_;
  std::string buffer_;
  std::uint64_t counter_ = 1;
  canonical::Units units_ = canonical::Units::Millimeters;
};

}  // namespace ncbridge::interpreter
