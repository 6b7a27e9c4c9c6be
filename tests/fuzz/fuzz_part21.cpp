// libFuzzer target: the Part 21 reader must reject garbage with an InputError, never crash; what
// it accepts must write, read back to the same graph, and write to the same bytes; the schema
// check must cope with whatever graph it is given, and the ISO 14649 reader (read_stepnc) with
// whatever file.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "ncbridge/common/error.hpp"
#include "ncbridge/step_writer/part21_reader.hpp"
#include "ncbridge/step_writer/part21_writer.hpp"
#include "ncbridge/step_writer/schema_check.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"

namespace {

const ncbridge::step_writer::express::Schema& small_schema() {
  static const auto schema = ncbridge::step_writer::express::Schema::parse(R"(SCHEMA fuzz;
    TYPE label = STRING; END_TYPE;
    TYPE length_measure = REAL; END_TYPE;
    TYPE side = ENUMERATION OF (left, right); END_TYPE;
    TYPE measure_select = SELECT (length_measure, label); END_TYPE;
    ENTITY item ABSTRACT SUPERTYPE; name : label; END_ENTITY;
    ENTITY point SUBTYPE OF (item); coordinates : LIST [1:3] OF length_measure; END_ENTITY;
    ENTITY line SUBTYPE OF (item); start, finish : point; hand : OPTIONAL side; END_ENTITY;
    ENTITY group SUBTYPE OF (item); members : SET [1:?] OF item; size : measure_select; flag : LOGICAL; END_ENTITY;
    END_SCHEMA;)", "fuzz.exp");
  return schema;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ncbridge::step_writer;
  std::string_view text(reinterpret_cast<const char*>(data), size);
  part21::ReadResult first;
  try {
    first = part21::read_part21(text, "fuzz.stp");
  } catch (const ncbridge::InputError&) {
    return 0;
  }
  check_instances(first.graph, small_schema(), {"fuzz.stp"});
  try {  // as an ISO 14649 program (toolpath curves, B-splines, ...): an InputError or a model
    read_stepnc(text, "fuzz.stp");
  } catch (const ncbridge::InputError&) {
  }
  part21::WriteOptions options;
  options.unix_time = 0;
  std::string written;
  try {
    written = part21::write_part21(first.graph, options);
  } catch (const std::invalid_argument&) {
    return 0;  // e.g. a real the reader took but that overflows to infinity is refused, not written
  }
  part21::ReadResult second = part21::read_part21(written, "rewritten.stp");  // must not throw
  if (!(second.graph.instances() == first.graph.instances())) std::abort();
  if (part21::write_part21(second.graph, options) != written) std::abort();
  return 0;
}
