// The reader: Part 21 syntax it must accept, and errors with the right place for what it must not.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>

#include "ncbridge/common/error.hpp"
#include "ncbridge/step_writer/part21_reader.hpp"
#include "ncbridge/step_writer/part21_writer.hpp"

namespace fs = std::filesystem;
using namespace ncbridge::step_writer::part21;
using ncbridge::InputError;

namespace {

const char* kHead = "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\nFILE_NAME('','',(''),(''),'','','');\n"
                    "FILE_SCHEMA(('S'));\nENDSEC;\n";  // 6 lines

std::string file_with(const std::string& data) { return std::string(kHead) + "DATA;\n" + data + "ENDSEC;\nEND-ISO-10303-21;\n"; }

// Line and column of the InputError reading `text` throws.
std::pair<std::uint32_t, std::uint32_t> error_place(const std::string& text) {
  try {
    read_part21(text, "t.stp");
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, "t.stp");
    return {e.where().line, e.where().column};
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return {0, 0};
}

}  // namespace

TEST(Part21Reader, ReadsCommentsMultiLineAndComplexInstances) {
  std::string text = file_with(
      "/* a comment\n over lines */ #1 = CARTESIAN_POINT ( 'a' , /* inline */ ( 1. , 2 , -3.5E+2 ) ) ;\n"
      "#2=(A(1)B('x',#1)\n  C());\n"
      "#3=thing(.t.,.Unknown.,\"1F\",*,$,LENGTH_MEASURE(2.),(()),'it''s');\n");
  ReadResult r = read_part21(text, "t.stp");
  const Graph& g = r.graph;
  ASSERT_EQ(g.size(), 3u);
  const Instance& p = g.at(1);
  EXPECT_EQ(p.entity(), "CARTESIAN_POINT");
  EXPECT_EQ(p.line, 9u);
  EXPECT_EQ(p.attributes()[1].as_list()[2].as_number(), -350.0);
  EXPECT_TRUE(p.attributes()[1].as_list()[1].is_integer());
  const Instance& c = g.at(2);
  EXPECT_TRUE(c.complex);
  ASSERT_EQ(c.records.size(), 3u);
  EXPECT_EQ(c.record("B")->attributes[1].as_reference(), 1u);
  const Instance& t = g.at(3);
  EXPECT_EQ(t.entity(), "THING");  // keywords are read upper case
  EXPECT_EQ(t.attributes()[0].as_enumeration(), "T");
  EXPECT_EQ(t.attributes()[1].as_enumeration(), "UNKNOWN");
  EXPECT_TRUE(t.attributes()[3].is_derived());
  EXPECT_TRUE(t.attributes()[4].is_unset());
  EXPECT_EQ(t.attributes()[5].typed_if()->type, "LENGTH_MEASURE");
  EXPECT_EQ(t.attributes()[5].as_number(), 2.0);
  EXPECT_EQ(t.attributes()[7].as_string(), "it's");
  EXPECT_TRUE(r.warnings.empty());
}

TEST(Part21Reader, DecodesStringEscapes) {
  ReadResult r = read_part21(file_with("#1=S('\\X2\\00C400DF\\X0\\-\\X\\E9-\\S\\D-\\PA\\x-\\X4\\0001F529\\X0\\-\\\\-\\X2\\D83DDD29\\X0\\');\n"), "t");
  EXPECT_EQ(r.graph.at(1).attributes()[0].as_string(), "Äß-é-Ä-x-🔩-\\-🔩");
  // Raw 8-bit text: UTF-8 is kept, other bytes are read as ISO 8859-1.
  ReadResult raw = read_part21(file_with("#1=S('Ma\xC3\x9F caf\xE9');\n"), "t");
  EXPECT_EQ(raw.graph.at(1).attributes()[0].as_string(), "Ma\xC3\x9F caf\xC3\xA9");
}

TEST(Part21Reader, ReadsHeaderFields) {
  ReadResult r = read_part21_file(fs::path(NCBRIDGE_SHARED_DIR) / "corpus/stepnc/nist_ex1.stp");
  const Header& h = r.graph.header;
  EXPECT_EQ(h.description.size(), 2u);
  EXPECT_EQ(h.implementation_level, "1");
  EXPECT_EQ(h.author, (std::vector<std::string>{"YONG TAK HYUN", "JOCHEN WOLF"}));
  EXPECT_EQ(h.originating_system, "ISO 14649");
}

TEST(Part21Reader, SkipsAnchorAndReferenceSectionsWithAWarning) {
  std::string text = std::string(kHead) + "ANCHOR;\n<a>=#1;\nENDSEC;\nREFERENCE;\n#5=<http://x#y>;\nENDSEC;\nDATA;\n#1=A();\nENDSEC;\n"
                     "DATA;\n#2=B(#1);\nENDSEC;\nEND-ISO-10303-21;\nSIGNATURE;\nxyz\nENDSEC;\n";
  ReadResult r = read_part21(text, "t");
  EXPECT_EQ(r.graph.size(), 2u);
  EXPECT_EQ(r.warnings.size(), 3u);
}

TEST(Part21Reader, RejectsBadSyntaxAtTheRightPlace) {
  // line 8 is the first DATA line
  EXPECT_EQ(error_place(file_with("#1=A(1,2)\n#2=B();\n")), std::make_pair(8u, 10u));  // missing ';' after line 8
  EXPECT_EQ(error_place(file_with("#1=A(1 2);\n")).first, 8u);
  EXPECT_EQ(error_place(file_with("#1=A('x);\n")), std::make_pair(8u, 6u));             // unterminated string
  EXPECT_EQ(error_place(file_with("#1=A(1);\n/* open\n")), std::make_pair(9u, 1u));     // unterminated comment
  EXPECT_EQ(error_place(file_with("#1=A(#2);\n")), std::make_pair(8u, 6u));             // dangling reference
  EXPECT_EQ(error_place(file_with("#1=A();\n#1=B();\n")), std::make_pair(9u, 1u));      // duplicate id
  EXPECT_EQ(error_place(file_with("#1=A(1.E);\n")).first, 8u);
  EXPECT_EQ(error_place(file_with("#1=A(99999999999999999999);\n")).first, 8u);
  EXPECT_EQ(error_place(file_with("#0=A();\n")).first, 8u);
  EXPECT_EQ(error_place(file_with("#1=A(@);\n")), std::make_pair(8u, 6u));
  EXPECT_EQ(error_place(file_with("#1=();\n")).first, 8u);
  EXPECT_EQ(error_place(file_with("#1=A(.X);\n")).first, 8u);
  EXPECT_EQ(error_place(file_with("#1=A(\"12G\");\n")).first, 8u);
  EXPECT_EQ(error_place(std::string(kHead) + "DATA;\n#1=A();\n").first, 9u);  // no ENDSEC
  EXPECT_EQ(error_place("ISO-10303-21;\nDATA;\n"), std::make_pair(2u, 1u));     // no HEADER
  EXPECT_EQ(error_place(""), std::make_pair(1u, 1u));
  EXPECT_EQ(error_place(file_with("#1=A(" + std::string(1000, '(') + std::string(1000, ')') + ");\n")).first, 8u);
}

TEST(Part21Reader, NegativeCorpusSyntaxCasesAreRejectedOnTheBrokenLine) {
  fs::path dir = fs::path(NCBRIDGE_SHARED_DIR) / "corpus/part21-negative";
  struct Case { const char* file; std::uint32_t line; const char* says; };
  for (const Case& c : {Case{"missing_semicolon.stp", 58, "expected ';'"},
                        Case{"syntax_missing_comma.stp", 74, "expected ',' or ')'"},
                        Case{"dangling_ref.stp", 59, "#9999"}}) {
    SCOPED_TRACE(c.file);
    try {
      read_part21_file(dir / c.file);
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where().line, c.line);
      EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
      EXPECT_NE(e.where().file.find(c.file), std::string::npos);
    }
  }
}

TEST(Part21Reader, NeverCrashesOnMutatedFiles) {
  std::string base = write_part21(read_part21_file(fs::path(NCBRIDGE_SHARED_DIR) / "corpus/stepnc/nist_ex1.stp").graph);
  std::mt19937 random(21);
  const std::string alphabet = "#$*(),;='\".\\/ABZ019-E\n";
  int rejected = 0, accepted = 0;
  for (int k = 0; k < 2000; ++k) {
    std::string text = base;
    int edits = 1 + static_cast<int>(random() % 4);
    for (int e = 0; e < edits; ++e) {
      std::size_t at = random() % text.size();
      switch (random() % 3) {
        case 0: text[at] = alphabet[random() % alphabet.size()]; break;
        case 1: text.erase(at, 1 + random() % 8); break;
        default: text.insert(at, 1, alphabet[random() % alphabet.size()]); break;
      }
    }
    try {
      read_part21(text, "m");
      ++accepted;
    } catch (const InputError& e) {
      EXPECT_GT(e.where().line, 0u);
      ++rejected;
    }
  }
  EXPECT_GT(rejected, 500);
  EXPECT_EQ(rejected + accepted, 2000);
}
