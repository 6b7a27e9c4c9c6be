#include "lowering/run_dialect.hpp"

#include "fanuc/fanuc_front_end.hpp"
#include "heidenhain/heidenhain_front_end.hpp"
#include "mach3/mach3_flavour.hpp"
#include "ncbridge/interpreter/dialect_detect.hpp"
#include "siemens840d/siemens_front_end.hpp"

namespace ncbridge::interpreter::lowering {

Dialect resolve_dialect(const Options& options, std::string_view text, const std::string& name) {
  if (options.dialect != Dialect::Auto) return options.dialect;
  return detect_dialect_reading(text, name, options).dialect;
}

bool run_dialect(Dialect dialect, ProgramText program, const Options& options, canonical::Sink& sink) {
  switch (dialect) {
    case Dialect::Fanuc: {
      const fanuc::Flavour flavour = fanuc::fanuc_flavour();
      fanuc::run(std::move(program), options, sink, flavour);
      return true;
    }
    case Dialect::Mach3: {
      const fanuc::Flavour flavour = mach3::mach3_flavour();
      fanuc::run(std::move(program), options, sink, flavour);
      return true;
    }
    case Dialect::Heidenhain:
      heidenhain::run(std::move(program), options, sink);
      return true;
    case Dialect::Siemens840D:
      siemens840d::run(std::move(program), options, sink);
      return true;
    default:
      return false;
  }
}

}  // namespace ncbridge::interpreter::lowering

namespace ncbridge::interpreter::lowering {

bool interpret_dialect_file(const std::filesystem::path& program, const Options& options, canonical::Sink& sink) {
  if (options.dialect == Dialect::Rs274Ngc) return false;
  Dialect dialect = options.dialect;
  if (dialect == Dialect::Auto) {
    dialect = detect_dialect_reading(program, options).dialect;
    if (dialect == Dialect::Rs274Ngc) return false;
  }
  run_dialect(dialect, ProgramText::from_file(program), options, sink);
  sink.end();
  return true;
}

bool interpret_dialect_text(std::string_view text, const std::string& name, const Options& options,
                            canonical::Sink& sink) {
  Dialect dialect = resolve_dialect(options, text, name);
  if (dialect == Dialect::Rs274Ngc) return false;
  run_dialect(dialect, ProgramText::from_text(std::string(text), name), options, sink);
  sink.end();
  return true;
}

}  // namespace ncbridge::interpreter::lowering
