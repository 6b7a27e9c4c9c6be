// The writer: real syntax, string escapes, header, determinism, wrapping, renumbering.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstring>
#include <cstdlib>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "ncbridge/step_writer/part21_reader.hpp"
#include "ncbridge/step_writer/part21_writer.hpp"

using namespace ncbridge::step_writer::part21;

namespace {

Graph small_graph() {
  Graph g;
  g.header.description = {"test"};
  g.header.name = "small.stp";
  g.header.schema = {"MACHINING_SCHEMA", "MILLING_SCHEMA"};
  InstanceId p = g.add("CARTESIAN_POINT", {string("origin"), list_of_reals({0, 0.5, -25.4})});
  InstanceId d = g.add("DIRECTION", {string("z"), list_of_reals({0, 0, 1})});
  g.add("AXIS2_PLACEMENT_3D", {string("frame"), ref(p), ref(d), unset()});
  return g;
}

double read_back_real(const std::string& text) {
  Graph g;
  g.header.schema = {"S"};
  std::string file = "ISO-10303-21;HEADER;FILE_SCHEMA(('S'));ENDSEC;DATA;#1=X(" + text + ");ENDSEC;END-ISO-10303-21;";
  return read_part21(file, "real").graph.at(1).attributes().at(0).as_number();
}

}  // namespace

TEST(Part21Writer, RealsAlwaysHaveADecimalPointAndAnUpperCaseExponent) {
  EXPECT_EQ(format_real(5), "5.");
  EXPECT_EQ(format_real(-0.5), "-0.5");
  EXPECT_EQ(format_real(1e-5), "1.E-05");
  EXPECT_EQ(format_real(0.01), "0.01");
  EXPECT_EQ(format_real(1.5e20), "1.5E20");
  EXPECT_EQ(format_real(0), "0.");
  EXPECT_EQ(format_real(-0.0), "-0.");
  EXPECT_EQ(format_real(100), "100.");
  EXPECT_THROW(format_real(std::nan("")), std::invalid_argument);
  EXPECT_THROW(format_real(std::numeric_limits<double>::infinity()), std::invalid_argument);
}

TEST(Part21Writer, RealsRoundTripExactly) {
  std::mt19937_64 random(14649);
  std::uniform_int_distribution<std::uint64_t> bits;
  int checked = 0;
  for (int k = 0; k < 20000; ++k) {
    std::uint64_t b = bits(random);
    double d;
    std::memcpy(&d, &b, sizeof d);
    if (!std::isfinite(d)) continue;
    std::string text = format_real(d);
    ASSERT_NE(text.find('.'), std::string::npos) << text;
    ASSERT_EQ(text.find('e'), std::string::npos) << text;
    double back = read_back_real(text);
    ASSERT_EQ(std::memcmp(&back, &d, sizeof d), 0) << text;
    ++checked;
  }
  for (double d : {0.1, 1.0 / 3, 2.5e-308, 1.7976931348623157e308, 4.9e-324, 123456.789}) {
    EXPECT_EQ(read_back_real(format_real(d)), d) << format_real(d);
    ++checked;
  }
  EXPECT_GT(checked, 19000);
}

// Program coordinates (a few decimals) take a path of their own in the writer; it must give
// exactly the text of the general one: std::to_chars' shortest form in Part 21 syntax.
std::string shortest_in_part21_syntax(double d) {
  char buf[64];
  std::string text(buf, std::to_chars(buf, buf + sizeof buf, d).ptr);
  const std::size_t e = text.find('e');
  std::string mantissa = text.substr(0, e);
  if (mantissa.find('.') == std::string::npos) mantissa += '.';
  if (e == std::string::npos) return mantissa;
  std::string exponent = text.substr(e + 1);
  if (exponent.front() == '+') exponent.erase(0, 1);
  return mantissa + "E" + exponent;
}

TEST(Part21Writer, ShortDecimalsAreWrittenAsTheirShortestRoundTripText) {
  std::mt19937_64 random(1464911);
  std::uniform_int_distribution<std::int64_t> digits(-300000000000, 300000000000);
  std::uniform_int_distribution<int> decimals(0, 8);
  const double scale[] = {1, 10, 100, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8};
  for (int k = 0; k < 200000; ++k) {
    const int n = decimals(random);
    const double d = static_cast<double>(digits(random) % 100000000000) / scale[n];
    ASSERT_EQ(format_real(d), shortest_in_part21_syntax(d)) << d;
  }
  for (double d : {0.001, -0.001, 0.0001, 0.00123, 99999.999999, 100000.0, 99999.0, 10000.0, 1e-3 * 7, 150.494,
                   -9.293, 1.2018999999999997, 0.1 + 0.2, 5.0, 12345.6789}) {
    EXPECT_EQ(format_real(d), shortest_in_part21_syntax(d)) << d;
    EXPECT_EQ(read_back_real(format_real(d)), d) << format_real(d);
  }
}

TEST(Part21Writer, StringsAreEscapedAndReadBackToTheSameText) {
  EXPECT_EQ(format_string("it's"), "'it''s'");
  EXPECT_EQ(format_string("C:\\nc"), "'C:\\\\nc'");
  EXPECT_EQ(format_string("Fräsen"), "'Fr\\X2\\00E4\\X0\\sen'");
  EXPECT_EQ(format_string("\xE2\x8C\x80 30"), "'\\X2\\2300\\X0\\ 30'");  // U+2300 diameter sign
  EXPECT_EQ(format_string("\xF0\x9F\x94\xA9"), "'\\X4\\0001F529\\X0\\'");
  EXPECT_EQ(format_string("a\tb"), "'a\\X\\09b'");
  for (std::string text : {std::string("it's a 'quote'"), std::string("back\\slash\\"), std::string("Übermaß ⌀ 10 🔩"),
                           std::string("tab\tnew\nline"), std::string(""), std::string("''''")}) {
    Graph g;
    g.header.schema = {"S"};
    g.add("X", {string(text)});
    std::string written = write_part21(g, {.unix_time = 0});
    for (unsigned char c : written) ASSERT_TRUE(c == '\n' || (c >= 0x20 && c < 0x7F)) << "non-ASCII byte written";
    EXPECT_EQ(read_part21(written, "s").graph.at(1).attributes()[0].as_string(), text);
  }
}

TEST(Part21Writer, InvalidUtf8IsWrittenAsLatin1AndThenStable) {
  Graph g;
  g.header.schema = {"S"};
  g.add("X", {string("caf\xE9")});
  std::string first = write_part21(g, {.unix_time = 0});
  EXPECT_NE(first.find("'caf\\X2\\00E9\\X0\\'"), std::string::npos);
  Graph again = read_part21(first, "s").graph;
  EXPECT_EQ(again.at(1).attributes()[0].as_string(), "caf\xC3\xA9");
  EXPECT_EQ(write_part21(again, {.unix_time = 0}), first);
}

TEST(Part21Writer, WritesTheWholeStructureDeterministically) {
  Graph g = small_graph();
  std::string text = write_part21(g, {.unix_time = 1700000000});
  EXPECT_EQ(text,
            "ISO-10303-21;\n"
            "HEADER;\n"
            "FILE_DESCRIPTION(('test'),'2;1');\n"
            "FILE_NAME('small.stp','2023-11-14T22:13:20',(''),(''),'ncbridge','ncbridge','');\n"
            "FILE_SCHEMA(('MACHINING_SCHEMA','MILLING_SCHEMA'));\n"
            "ENDSEC;\n"
            "DATA;\n"
            "#1=CARTESIAN_POINT('origin',(0.,0.5,-25.4));\n"
            "#2=DIRECTION('z',(0.,0.,1.));\n"
            "#3=AXIS2_PLACEMENT_3D('frame',#1,#2,$);\n"
            "ENDSEC;\n"
            "END-ISO-10303-21;\n");
  EXPECT_EQ(write_part21(small_graph(), {.unix_time = 1700000000}), text);
}

TEST(Part21Writer, TimeStampComesFromSourceDateEpoch) {
  ::setenv("SOURCE_DATE_EPOCH", "86400", 1);
  EXPECT_EQ(time_stamp_now(), "1970-01-02T00:00:00");
  std::string a = write_part21(small_graph());
  EXPECT_NE(a.find("'1970-01-02T00:00:00'"), std::string::npos);
  EXPECT_EQ(write_part21(small_graph()), a);
  ::setenv("SOURCE_DATE_EPOCH", "not a number", 1);
  EXPECT_NE(time_stamp_now(), "1970-01-02T00:00:00");  // falls back to the clock
  ::unsetenv("SOURCE_DATE_EPOCH");
  EXPECT_EQ(time_stamp_now().size(), 19u);
}

TEST(Part21Writer, AllValueKinds) {
  Graph g;
  g.header.schema = {"S"};
  g.add("ALL", {unset(), derived(), integer(-42), real(2.5), string("s"), enumeration("tcp"), boolean(true),
                Value{Binary{"0F3"}}, ref(1), list({}), list({list({integer(1)}), unset()}),
                typed("length_measure", real(5)), typed("LABEL", string("x"))});
  EXPECT_EQ(write_part21(g, {.unix_time = 0}).substr(write_part21(g, {.unix_time = 0}).find("#1=")),
            "#1=ALL($,*,-42,2.5,'s',.TCP.,.T.,\"0F3\",#1,(),((1),$),LENGTH_MEASURE(5.),LABEL('x'));\n"
            "ENDSEC;\nEND-ISO-10303-21;\n");
}

TEST(Part21Writer, WrapsLongInstancesAfterCommas) {
  Graph g;
  g.header.schema = {"S"};
  std::vector<double> many(200, 1.25);
  g.add("POLY", {string("p"), list_of_reals(many)});
  std::string text = write_part21(g, {.line_width = 80, .unix_time = 0});
  std::size_t data = text.find("DATA;\n") + 6;
  std::size_t longest = 0, lines = 0;
  for (std::size_t start = data; start < text.size();) {
    std::size_t end = text.find('\n', start);
    longest = std::max(longest, end - start);
    start = end + 1;
    ++lines;
  }
  EXPECT_LE(longest, 90u);
  EXPECT_GT(lines, 5u);
  EXPECT_EQ(read_part21(text, "w").graph, read_part21(write_part21(g, {.line_width = 0, .unix_time = 0}), "w").graph);
}

TEST(Part21Writer, RenumbersInGraphOrderAndFollowsReferences) {
  Graph g;
  g.header.schema = {"S"};
  Instance a;
  a.id = 100;
  a.records.push_back({"A", {ref(7)}});
  Instance b;
  b.id = 7;
  b.records.push_back({"B", {}});
  g.insert(a);
  g.insert(b);
  std::string text = write_part21(g, {.renumber = true, .unix_time = 0});
  EXPECT_NE(text.find("#1=A(#2);\n#2=B();\n"), std::string::npos);
  EXPECT_NE(write_part21(g, {.unix_time = 0}).find("#100=A(#7);\n#7=B();\n"), std::string::npos);
}

TEST(Part21Writer, ComplexInstancesAreSortedAndForwardReferencesWork) {
  Graph g;
  g.header.schema = {"S"};
  InstanceId later = g.reserve();
  g.add_complex({{"REPRESENTATION_CONTEXT", {string("c"), string("3D")}},
                 {"GEOMETRIC_REPRESENTATION_CONTEXT", {integer(3)}}});
  EXPECT_THROW(write_part21(g), std::invalid_argument);  // reserved but not set yet
  g.set(later, "USES", {ref(2)});
  std::string text = write_part21(g, {.unix_time = 0});
  EXPECT_NE(text.find("#1=USES(#2);\n#2=(GEOMETRIC_REPRESENTATION_CONTEXT(3)REPRESENTATION_CONTEXT('c','3D'));\n"),
            std::string::npos);
  EXPECT_EQ(read_part21(text, "c").graph.instances(), g.instances());
}

TEST(Part21Writer, RefusesReferencesOutsideTheGraph) {
  Graph g;
  g.header.schema = {"S"};
  g.add("A", {ref(99)});
  EXPECT_THROW(write_part21(g), std::invalid_argument);
}
