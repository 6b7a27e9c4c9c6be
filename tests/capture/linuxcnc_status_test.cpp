#include <gtest/gtest.h>

#include "ncbridge/capture/linuxcnc_status.hpp"
#include "ncbridge/common/error.hpp"

using namespace ncbridge::capture;

TEST(LinuxcncStatus, ReadsTheStatusReadersRecords) {
  auto r = parse_linuxcnc_status_line(
      R"({"kind":"sample","mode":"auto","interp":"paused","program":"/nc/a.ngc","line":12,"fault":""})");
  EXPECT_EQ(r.kind, LinuxcncRecord::Kind::Sample);
  EXPECT_EQ(r.sample.interp, ControllerSample::Interp::Paused);
  EXPECT_EQ(r.sample.program, "/nc/a.ngc");
  EXPECT_EQ(r.sample.line, 12u);
  EXPECT_FALSE(r.sample.fault);
  r = parse_linuxcnc_status_line(R"({"kind":"sample","mode":"mdi","interp":"idle","program":"","line":0,"fault":"e-stop"})");
  EXPECT_EQ(r.sample.mode, ControllerSample::Mode::Mdi);
  EXPECT_TRUE(r.sample.fault);
  r = parse_linuxcnc_status_line(R"({"kind":"tools","table":"T1 P1 Z1 D0.25\n","inch":true})");
  EXPECT_EQ(r.kind, LinuxcncRecord::Kind::Tools);
  EXPECT_TRUE(r.inch);
  r = parse_linuxcnc_status_line(R"({"kind":"lost","reason":"no LinuxCNC controller"})");
  EXPECT_EQ(r.kind, LinuxcncRecord::Kind::Lost);
}

TEST(LinuxcncStatus, MalformedRecordsAreInputErrors) {
  EXPECT_THROW(parse_linuxcnc_status_line("not json"), ncbridge::InputError);
  EXPECT_THROW(parse_linuxcnc_status_line(R"({"kind":"sample"})"), ncbridge::InputError);
  EXPECT_THROW(parse_linuxcnc_status_line(R"({"kind":"weather"})"), ncbridge::InputError);
  EXPECT_THROW(parse_linuxcnc_status_line(R"([1,2])"), ncbridge::InputError);
}

TEST(LinuxcncStatus, TheStatusReaderIsCompiledIn) {
  EXPECT_NE(linuxcnc_status_script().find("import linuxcnc"), std::string_view::npos);
}
