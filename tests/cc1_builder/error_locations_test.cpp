// Every error about the user's input names file:line:column (issue 16): an empty program (line 1,
// column 1, in every dialect), a program without its end (its last line), a cut with a tool the
// tool list lacks (the block's line), a tool number given twice (its second place), a Part 21
// reference to an instance the file lacks (the referring instance).
#include <gtest/gtest.h>

#include <string>

#include "ncbridge/cc1_builder/cc1_builder.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"

namespace ncbridge::cc1_builder::testing {
namespace {

struct Discard final : canonical::Sink {
  void call(const canonical::Call&) override {}
};

template <class F>
InputError error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no error";
  return InputError({}, "");
}

InputError interpret_error(const std::string& text, interpreter::Dialect dialect) {
  return error_of([&] {
    interpreter::Options options;
    options.dialect = dialect;
    Discard sink;
    interpreter::interpret_text(text, "part.prog", options, sink);
  });
}

TEST(ErrorLocations, AnEmptyProgramIsRefusedAtLine1Column1InEveryDialect) {
  for (auto dialect : {interpreter::Dialect::Rs274Ngc, interpreter::Dialect::Fanuc, interpreter::Dialect::Mach3,
                       interpreter::Dialect::Siemens840D, interpreter::Dialect::Heidenhain}) {
    for (const std::string text : {"", "\n", "   \n\n"}) {
      SCOPED_TRACE(static_cast<int>(dialect));
      const InputError e = interpret_error(text, dialect);
      EXPECT_EQ(e.where().file, "part.prog");
      EXPECT_GE(e.where().line, 1u);
      EXPECT_EQ(e.where().column, 1u);
      if (text.empty()) {
        EXPECT_EQ(e.where().line, 1u);
        EXPECT_EQ(e.where().to_string(), "part.prog:1:1");
      }
    }
  }
}

TEST(ErrorLocations, AProgramWithoutItsEndIsRefusedAtItsLastLine) {
  const InputError e = interpret_error("G21 G90\nG0 X1\nG1 X2 F100\n", interpreter::Dialect::Rs274Ngc);
  EXPECT_EQ(e.where().line, 3u);
  EXPECT_EQ(e.where().column, 1u);
  const InputError sub = interpret_error("o100 sub\nG0 X1\no100 endsub\no100 call\n", interpreter::Dialect::Rs274Ngc);
  EXPECT_EQ(sub.where().line, 4u);
}

TEST(ErrorLocations, ACutWithAToolTheListLacksNamesItsBlock) {
  setup::Tool mill;
  mill.number = 1;
  mill.diameter = 10;
  mill.length = 50;
  Options o;
  o.tools = setup::ToolList({mill});
  interpreter::Options io;
  io.tools = o.tools;
  const InputError e = error_of([&] {
    Cc1Builder builder(o);
    interpreter::interpret_text("G21 G90\nT2 M6\nG0 X0 Y0 Z5\nG1 Z-1 F100\nM2\n", "part.ngc", interpreter::Options{}, builder);
  });
  EXPECT_EQ(e.where().to_string(), "part.ngc:4:1") << e.what();
}

TEST(ErrorLocations, AToolNumberGivenTwiceIsNamedWhereItIsGivenAgain) {
  const InputError json = error_of([] {
    setup::parse_tool_list("[{\"number\": 3, \"diameter\": 6},\n {\"number\": 3, \"diameter\": 8}]", "tools.json");
  });
  EXPECT_EQ(json.where().to_string(), "tools.json:2:13");
  const InputError table = error_of([] {
    setup::parse_linuxcnc_tool_table("T1 P1 D0.25\nT2 P2 D0.5\n  T1 P3 D0.5\n", setup::LengthUnits::Inches, "tools.tbl");
  });
  EXPECT_EQ(table.where().to_string(), "tools.tbl:3:3");
}

TEST(ErrorLocations, AReferenceToAnInstanceTheFileLacksIsNamedWhereItIsMade) {
  const std::string text =
      "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\nFILE_NAME('x','',(''),(''),'','','');\n"
      "FILE_SCHEMA(('MACHINING_SCHEMA'));\nENDSEC;\nDATA;\n#1=WORKPLAN('W',(),$,#9,$);\n"
      "#2=PROJECT('P',#1,(),$,$,$);\nENDSEC;\nEND-ISO-10303-21;\n";
  const InputError e = error_of([&] { step_writer::read_stepnc(text, "part.stp"); });
  EXPECT_EQ(e.where().file, "part.stp");
  EXPECT_EQ(e.where().line, 8u) << e.what();
  EXPECT_EQ(e.where().column, 22u);  // the #9
  const InputError none = error_of([] {
    step_writer::read_stepnc("ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\nFILE_NAME('x','',(''),(''),'','','');\n"
                             "FILE_SCHEMA(('MACHINING_SCHEMA'));\nENDSEC;\nDATA;\nENDSEC;\nEND-ISO-10303-21;\n",
                             "empty.stp");
  });
  EXPECT_EQ(none.where().to_string(), "empty.stp:1:1");
}

}  // namespace
}  // namespace ncbridge::cc1_builder::testing
