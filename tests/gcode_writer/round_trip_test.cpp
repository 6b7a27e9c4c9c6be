// The round trip of every corpus program through every dialect writer: the program read (in its
// own dialect), written as a program of dialect d, and that program read back by d's front-end
// make the same motion (support/same_motion.hpp) — or the writer refuses, and then exactly as
// expected_refusals.txt says: the construct d cannot express, at the source line that has it.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "ncbridge/common/error.hpp"
#include "ncbridge/gcode_writer/program_writer.hpp"
#include "support/corpus.hpp"
#include "support/listing.hpp"
#include "support/same_motion.hpp"

namespace fs = std::filesystem;
using namespace ncbridge;
using ncbridge::testing::CorpusProgram;

namespace {

const gcode_writer::Dialect kDialects[] = {gcode_writer::Dialect::Rs274Ngc, gcode_writer::Dialect::Fanuc,
                                           gcode_writer::Dialect::Mach3, gcode_writer::Dialect::Siemens840D,
                                           gcode_writer::Dialect::Heidenhain};

interpreter::Dialect reader_of(gcode_writer::Dialect d) {
  switch (d) {
    case gcode_writer::Dialect::Fanuc: return interpreter::Dialect::Fanuc;
    case gcode_writer::Dialect::Mach3: return interpreter::Dialect::Mach3;
    case gcode_writer::Dialect::Siemens840D: return interpreter::Dialect::Siemens840D;
    case gcode_writer::Dialect::Heidenhain: return interpreter::Dialect::Heidenhain;
    case gcode_writer::Dialect::Rs274Ngc: break;
  }
  return interpreter::Dialect::Rs274Ngc;
}

// expected_refusals.txt: `PROGRAM DIALECT message fragment`
std::map<std::pair<std::string, std::string>, std::string> expected_refusals() {
  std::map<std::pair<std::string, std::string>, std::string> out;
  std::ifstream in(fs::path(NCBRIDGE_SOURCE_DIR) / "tests/gcode_writer/expected_refusals.txt");
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string program, dialect, fragment;
    if (!(words >> program) || program[0] == '#') continue;
    words >> dialect;
    std::getline(words >> std::ws, fragment);
    out[{program, dialect}] = fragment;
  }
  return out;
}

struct Case {
  CorpusProgram program;
  gcode_writer::Dialect to;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.program.name << " to " << gcode_writer::dialect_name(c.to); }

std::vector<Case> cases() {
  std::vector<Case> out;
  for (const CorpusProgram& p : ncbridge::testing::corpus_programs()) {
    for (gcode_writer::Dialect d : kDialects) out.push_back({p, d});
  }
  return out;
}

class RoundTrip : public ::testing::TestWithParam<Case> {};

TEST_P(RoundTrip, ReadsBackAsTheSameMotion) {
  const Case& c = GetParam();
  const std::string to(gcode_writer::dialect_name(c.to));
  const interpreter::Options reading = ncbridge::testing::reading_options(c.program);
  gcode_writer::Options writing;
  writing.dialect = c.to;
  writing.tools = reading.tools;
  std::string written, source_listing;
  std::optional<InputError> refused;
  try {
    gcode_writer::ProgramWriter writer(writing, [&](std::string_view piece) { written.append(piece); });
    source_listing = ncbridge::testing::canon_listing(c.program.program, reading, &writer);
  } catch (const InputError& e) {
    refused = e;
  }
  static const auto refusals = expected_refusals();
  if (auto it = refusals.find({c.program.name, to}); it != refusals.end()) {
    ASSERT_TRUE(refused) << "expected_refusals.txt says " << to << " refuses " << c.program.name << " (" << it->second
                         << "), but it was written";
    EXPECT_NE(std::string(refused->what()).find(it->second), std::string::npos) << refused->what();
    EXPECT_NE(std::string(refused->what()).find(to + " cannot express"), std::string::npos) << refused->what();
    EXPECT_GT(refused->where().line, 0u) << "the refusal names no source line: " << refused->what();
    EXPECT_FALSE(refused->where().file.empty()) << refused->what();
    return;
  }
  ASSERT_FALSE(refused) << refused->what();
  interpreter::Options back = reading;
  back.dialect = reader_of(c.to);
  back.heidenhain_feed_units = interpreter::Options::FeedUnits::PerMinute;
  std::string back_listing;
  try {
    back_listing = ncbridge::testing::canon_listing_of_text(
        written, "written" + std::string(gcode_writer::program_extension(c.to)), back);
  } catch (const InputError& e) {
    FAIL() << to << " reads the written program with an error: " << e.what() << "\n--- written:\n" << written.substr(0, 4000);
  }
  const auto comparison = ncbridge::testing::compare_motion(source_listing, back_listing);
  EXPECT_TRUE(comparison.equal) << comparison.report << "\n--- written (start):\n" << written.substr(0, 3000);
  EXPECT_GT(comparison.actions, 0u);
}

INSTANTIATE_TEST_SUITE_P(Corpus, RoundTrip, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& case_info) {
                           return ncbridge::testing::test_name(case_info.param.program.name) + "_to_" +
                                  std::string(gcode_writer::dialect_name(case_info.param.to));
                         });

}  // namespace
