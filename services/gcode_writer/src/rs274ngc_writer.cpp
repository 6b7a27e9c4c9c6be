// RS274/NGC as LinuxCNC reads it: the word-address writer's defaults are this dialect's words.
// Programs are %-delimited (so a program that ends at its end of tape stays one), o-word
// `repeat` loops carry the repeat construct.
#include "word_address_writer.hpp"

namespace ncbridge::gcode_writer {

namespace {

class Rs274NgcWriter final : public WordAddressWriter {
 public:
  using WordAddressWriter::WordAddressWriter;
};

}  // namespace

std::unique_ptr<DialectWriter> make_rs274ngc_writer(const Options& o, TextOutput& out, const WriterLocation& where) {
  return std::make_unique<Rs274NgcWriter>(o, out, where);
}

}  // namespace ncbridge::gcode_writer
