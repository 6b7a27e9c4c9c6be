// The model codec of the workingsteps/features topics: lossless on real programs (the written
// Part 21 text is the same from the decoded model, and -0.0 / NaN keep their bits), and every
// malformed input is an InputError, never a crash.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

#include "ncbridge/cc1_builder/cc1_builder.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"
#include "ncbridge/stepnc_codec/project_codec.hpp"

namespace ncbridge {
namespace {

stepnc::Project convert(const std::string& program, const std::string& tools, const std::string& stock) {
  cc1_builder::Options options;
  options.tools = setup::read_tool_list(tools);
  options.stock = setup::read_stock(stock);
  interpreter::Options interp;
  interp.tools = options.tools;
  cc1_builder::Cc1Builder builder(options);
  interpreter::interpret_file(program, interp, builder);
  return builder.take_project();
}

std::string written(const stepnc::Project& p) {
  step_writer::StepncWriteOptions o;
  o.file_name = "x.stp";
  o.unix_time = 0;
  return step_writer::write_stepnc(p, o);
}

const std::string kPaper = std::string(NCBRIDGE_SHARED_DIR) + "/corpus/paper/";

TEST(StepncCodec, CorpusProgramsRoundTripToTheSameFile) {
  for (const char* program : {"face_mill.ngc", "test_part.ngc"}) {
    const stepnc::Project p = convert(kPaper + program, kPaper + "tools.json", kPaper + "stock.json");
    ASSERT_FALSE(p.main_workplan.its_elements.empty()) << program;
    const std::string bytes = stepnc_codec::encode_project(p);
    const stepnc::Project back = stepnc_codec::decode_project(bytes);
    EXPECT_EQ(back, p) << program;
    EXPECT_EQ(written(back), written(p)) << program;
    EXPECT_EQ(stepnc_codec::encode_project(back), bytes) << program;
  }
}

TEST(StepncCodec, KeepsTheBitsOfEveryDouble) {
  stepnc::Project p;
  p.its_id = "bits";
  p.workpiece.global_tolerance = -0.0;
  p.setup.its_secplane.position.location.z = std::numeric_limits<double>::quiet_NaN();
  stepnc::ClosedPocket pocket;
  pocket.its_id = "pocket";
  pocket.slope = std::numeric_limits<double>::infinity();
  pocket.feature_boundary = stepnc::CircularClosedProfile{std::nullopt, {12.5, 0.1, -0.1, 3}};
  p.features.emplace_back(pocket);
  const stepnc::Project back = stepnc_codec::decode_project(stepnc_codec::encode_project(p));
  EXPECT_TRUE(std::signbit(*back.workpiece.global_tolerance));
  EXPECT_TRUE(std::isnan(back.setup.its_secplane.position.location.z));
  const auto& q = std::get<stepnc::ClosedPocket>(back.features.at(0));
  EXPECT_TRUE(std::isinf(*q.slope));
  EXPECT_EQ(std::get<stepnc::CircularClosedProfile>(q.feature_boundary).diameter.theoretical_size, 12.5);
}

TEST(StepncCodec, EveryTruncationAndCorruptionIsAnInputError) {
  const stepnc::Project p = convert(kPaper + "face_mill.ngc", kPaper + "tools.json", kPaper + "stock.json");
  const std::string bytes = stepnc_codec::encode_project(p);
  for (std::size_t n = 0; n < bytes.size(); n += 1 + n / 64) {
    EXPECT_THROW(stepnc_codec::decode_project(bytes.substr(0, n)), InputError) << "prefix " << n;
  }
  EXPECT_THROW(stepnc_codec::decode_project(bytes + "x"), InputError);
  std::string wrong_magic = bytes;
  wrong_magic[0] = 'X';
  EXPECT_THROW(stepnc_codec::decode_project(wrong_magic), InputError);
  // Flipping any byte either still decodes (a value changed) or is rejected: never a crash.
  for (std::size_t i = 0; i < bytes.size(); i += 7) {
    std::string flipped = bytes;
    flipped[i] = static_cast<char>(flipped[i] ^ 0xFF);
    try {
      (void)stepnc_codec::decode_project(flipped);
    } catch (const InputError&) {
    }
  }
}

}  // namespace
}  // namespace ncbridge
