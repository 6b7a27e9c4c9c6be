// `--dialect auto` when no construct decides: the program is read in each candidate dialect, and
// the first reading that reads it whole is taken. Each reading's canonical calls (comments and
// messages aside) are folded into a digest, so the reason can say whether the readings that read
// the program move the tool alike: then the choice changes nothing.
#include <cstdint>
#include <fstream>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "ncbridge/common/error.hpp"
#include "ncbridge/interpreter/canon_printer.hpp"
#include "ncbridge/interpreter/dialect_detect.hpp"
#include "ncbridge/interpreter/interpreter.hpp"

namespace ncbridge::interpreter {

namespace {

// FNV-1a over the formatted calls that move or set the machine.
class DigestSink final : public canonical::Sink {
 public:
  void call(const canonical::Call& c) override {
    if (std::holds_alternative<canonical::Comment>(c.data) || std::holds_alternative<canonical::Message>(c.data)) return;
    CanonPrinter::format_call(c.data, text_);
    // -0.0000 and 0.0000 are the same position (a reading's arithmetic may leave -1e-15)
    for (std::size_t at = text_.find("-0.0000"); at != std::string::npos; at = text_.find("-0.0000", at)) {
      const bool whole = at + 7 >= text_.size() || text_[at + 7] < '0' || text_[at + 7] > '9';
      if (whole && (at == 0 || text_[at - 1] < '0' || text_[at - 1] > '9')) text_.erase(at, 1); else ++at;
    }
    for (char ch : text_) digest = (digest ^ static_cast<unsigned char>(ch)) * 1099511628211ULL;
    digest = (digest ^ '\n') * 1099511628211ULL;
  }
  std::uint64_t digest = 1469598103934665603ULL;

 private:
  std::string text_;
};

struct Reading {
  Dialect dialect;
  bool whole = false;
  std::uint64_t digest = 0;
  std::string stop;  // where and why it stops, when it does not read the program whole
};

DetectedDialect by_reading(const DetectedDialect& syntax, const Options& options,
                           const std::function<void(const Options&, canonical::Sink&)>& interpret) {
  if (syntax.decisive) return syntax;
  std::vector<Reading> readings;
  for (Dialect d : {Dialect::Rs274Ngc, Dialect::Fanuc, Dialect::Mach3, Dialect::Siemens840D}) {
    Options trial = options;
    trial.dialect = d;
    trial.warning = nullptr;
    trial.strict = false;
    DigestSink sink;
    Reading r{d};
    try {
      interpret(trial, sink);
      r.whole = true;
      r.digest = sink.digest;
    } catch (const InputError& e) {
      r.stop = "line " + std::to_string(e.where().line) + ": " + e.message();
    }
    readings.push_back(std::move(r));
  }
  const Reading* taken = nullptr;
  std::string whole, differing, stops;
  for (const Reading& r : readings) {
    if (r.whole) {
      if (taken == nullptr) taken = &r;
      whole += (whole.empty() ? "" : ", ") + std::string(dialect_name(r.dialect));
      if (r.digest != taken->digest) differing += (differing.empty() ? "" : ", ") + std::string(dialect_name(r.dialect));
    } else {
      stops += (stops.empty() ? "" : "; ") + std::string(dialect_name(r.dialect)) + " stops at " + r.stop;
    }
  }
  DetectedDialect result;
  if (taken == nullptr) {
    result.dialect = Dialect::Rs274Ngc;
    result.reason = "no construct decides and no reading reads the program whole (" + stops + "): RS274/NGC assumed";
    return result;
  }
  result.dialect = taken->dialect;
  result.reason = "no construct decides; read whole as " + whole;
  if (whole.find(',') != std::string::npos) {
    result.reason += differing.empty() ? " with the same tool path" : " (" + differing + " moving the tool differently: give --dialect if the program is for it)";
  }
  if (!stops.empty()) result.reason += "; " + stops;
  result.reason += "; " + std::string(dialect_name(taken->dialect)) + " taken";
  return result;
}

}  // namespace

DetectedDialect detect_dialect_reading(const std::filesystem::path& program, const Options& options) {
  return by_reading(detect_dialect_file(program), options, [&](const Options& o, canonical::Sink& sink) {
    interpret_file(program, o, sink);
  });
}

DetectedDialect detect_dialect_reading(std::string_view text, const std::string& name, const Options& options) {
  return by_reading(detect_dialect(text), options, [&](const Options& o, canonical::Sink& sink) {
    interpret_text(text, name, o, sink);
  });
}

}  // namespace ncbridge::interpreter
