// A model split into a shell and chunks (the workingsteps/features topics) joins back into an
// equal project that writes the same Part 21 file: on corpus programs (CC1 and CC2) with chunks
// small enough to make many, and on a project of every feature and operation type. Bad parts
// (out of order, truncated, an element naming what has not come) are InputErrors.
#include <gtest/gtest.h>

#include "ncbridge/cc1_builder/cc1_builder.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/feature_recognizer/cc1_input.hpp"
#include "ncbridge/feature_recognizer/recognizer.hpp"
#include "ncbridge/feature_recognizer/to_stepnc.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"
#include "ncbridge/step_writer/stepnc_stream_writer.hpp"
#include "ncbridge/stepnc_codec/project_stream.hpp"

namespace ncbridge {
namespace {

stepnc::Project cc1(const std::string& dir, const std::string& program) {
  cc1_builder::Options options;
  options.tools = setup::read_tool_list(dir + "tools.json");
  options.stock = setup::read_stock(dir + "stock.json");
  interpreter::Options interp;
  interp.tools = options.tools;
  cc1_builder::Cc1Builder builder(options);
  interpreter::interpret_file(dir + program, interp, builder);
  return builder.take_project();
}

stepnc::Project cc2(const stepnc::Project& project) {
  const auto stock = feature_recognizer::stock_from_cc1(project);
  const auto features = feature_recognizer::recognize(feature_recognizer::workingsteps_from_cc1(project), *stock);
  return feature_recognizer::cc2_from_cc1(project, features).project;
}

std::string written(const stepnc::Project& p) {
  step_writer::StepncWriteOptions o;
  o.file_name = "x.stp";
  o.unix_time = 0;
  return step_writer::write_stepnc(p, o);
}

stepnc::Project joined(const stepnc_codec::ProjectParts& parts) {
  stepnc_codec::ProjectJoiner joiner;
  joiner.shell(parts.shell);
  for (const std::string& c : parts.chunks) joiner.chunk(c);
  return joiner.take();
}

const std::string kShared = NCBRIDGE_SHARED_DIR;

// Streamed CC1 across the bus: the builder's elements cut into element chunks of about
// `chunk_bytes`, then the shell of the finished project.
struct StreamedModel {
  std::vector<std::string> chunks;
  stepnc::Project shell;
};

class Chunking final : public cc1_builder::WorkplanSink {
 public:
  explicit Chunking(std::size_t chunk_bytes) : chunk_bytes_(chunk_bytes) {}
  void element(const stepnc::Project& project, const stepnc::Executable& element) override {
    chunker_.element(project, element);
    if (chunker_.bytes() >= chunk_bytes_) out.chunks.push_back(chunker_.take_chunk(project));
  }
  void finish(stepnc::Project project) {
    if (chunker_.elements() > 0) out.chunks.push_back(chunker_.take_chunk(project));
    out.shell = std::move(project);
  }
  StreamedModel out;

 private:
  std::size_t chunk_bytes_;
  stepnc_codec::ElementChunker chunker_;
};

StreamedModel streamed_cc1(const std::string& dir, const std::string& program, std::size_t chunk_bytes) {
  cc1_builder::Options options;
  options.tools = setup::read_tool_list(dir + "tools.json");
  options.stock = setup::read_stock(dir + "stock.json");
  interpreter::Options interp;
  interp.tools = options.tools;
  Chunking chunking(chunk_bytes);
  cc1_builder::Cc1Builder builder(options, &chunking);
  interpreter::interpret_file(dir + program, interp, builder);
  chunking.finish(builder.take_project());
  return std::move(chunking.out);
}

std::string written_from_chunks(const StreamedModel& m) {
  step_writer::StepncWriteOptions o;
  o.file_name = "x.stp";
  o.unix_time = 0;
  std::string text;
  step_writer::StepncStreamWriter writer(o, [&](std::string_view bytes) { text += bytes; });
  stepnc_codec::ElementUnchunker unchunker;
  for (const std::string& c : m.chunks)
    unchunker.chunk(c, [&](const stepnc::Project& p, const stepnc::Executable& e) { writer.element(p, e); });
  writer.finish(m.shell);
  return text;
}

TEST(ProjectStream, StreamedCc1ElementChunksWriteTheWholeModelsFile) {
  const std::vector<std::pair<std::string, std::string>> programs{{kShared + "/corpus/paper/", "face_mill.ngc"},
                                                                  {kShared + "/corpus/paper/", "test_part.ngc"},
                                                                  {kShared + "/corpus/cam/p01_block_reference/", "part.nc"}};
  for (const auto& [dir, program] : programs) {
    const std::string expected = written(cc1(dir, program));
    for (const std::size_t chunk_bytes : {std::size_t{1}, std::size_t{4096}, std::size_t{1} << 20}) {
      const StreamedModel m = streamed_cc1(dir, program, chunk_bytes);
      ASSERT_FALSE(m.chunks.empty()) << program;
      if (chunk_bytes == 1) {
        EXPECT_GT(m.chunks.size(), 2u) << program;
      }
      EXPECT_EQ(written_from_chunks(m), expected) << program << " in chunks of " << chunk_bytes;
    }
  }
}

TEST(ProjectStream, BadElementChunksAreInputErrors) {
  const StreamedModel m = streamed_cc1(kShared + "/corpus/paper/", "test_part.ngc", 1);
  ASSERT_GT(m.chunks.size(), 2u);
  const auto ignore = [](const stepnc::Project&, const stepnc::Executable&) {};
  // The second chunk alone: it names tools and technologies that came with the first.
  bool second_alone_rejected = false;
  for (std::size_t i = 1; i < m.chunks.size() && !second_alone_rejected; ++i) {
    try {
      stepnc_codec::ElementUnchunker fresh;
      fresh.chunk(m.chunks[i], ignore);
    } catch (const InputError&) {
      second_alone_rejected = true;
    }
  }
  EXPECT_TRUE(second_alone_rejected) << "no later chunk needs what an earlier one brought";
  stepnc_codec::ElementUnchunker u;
  EXPECT_THROW(u.chunk(m.chunks[0].substr(0, m.chunks[0].size() - 1), ignore), InputError);
  EXPECT_THROW(u.chunk("NCBS" + m.chunks[0].substr(4), ignore), InputError);
  EXPECT_THROW(u.chunk(m.chunks[0] + "x", ignore), InputError);
  // Every truncation and every flipped byte: decoded or rejected, never a crash.
  for (std::size_t i = 0; i < m.chunks[0].size(); ++i) {
    std::string bad = m.chunks[0];
    bad[i] = static_cast<char>(bad[i] ^ 0x5A);
    try {
      stepnc_codec::ElementUnchunker fresh;
      fresh.chunk(bad, ignore);
    } catch (const InputError&) {
    }
  }
}

TEST(ProjectStream, AToolpathNamingATechnologyThatHasNotComeIsAnInputError) {
  stepnc::Project project;
  stepnc::RapidMovement rapid;
  rapid.its_id = "RAPID_1";
  stepnc::CutterLocationTrajectory trajectory;
  trajectory.its_technology = stepnc::TechnologyRef{5};
  rapid.its_toolpath = stepnc::ToolpathList{{trajectory}};
  stepnc_codec::ElementChunker chunker;
  chunker.element(project, stepnc::Executable{rapid});
  const std::string chunk = chunker.take_chunk(project);
  stepnc_codec::ElementUnchunker unchunker;
  const auto ignore = [](const stepnc::Project&, const stepnc::Executable&) {};
  EXPECT_THROW(unchunker.chunk(chunk, ignore), InputError);
}

TEST(ProjectStream, CorpusModelsJoinBackToTheSameFile) {
  std::vector<std::pair<std::string, std::string>> programs{{kShared + "/corpus/paper/", "face_mill.ngc"},
                                                            {kShared + "/corpus/paper/", "test_part.ngc"},
                                                            {kShared + "/corpus/cam/p01_block_reference/", "part.nc"}};
  for (const auto& [dir, program] : programs) {
    const stepnc::Project one = cc1(dir, program);
    for (const stepnc::Project& p : {one, cc2(one)}) {
      for (std::size_t chunk_bytes : {std::size_t{1}, std::size_t{4096}, std::size_t{1} << 20}) {
        const auto parts = stepnc_codec::split_project(p, chunk_bytes);
        if (chunk_bytes == 1) {
          EXPECT_EQ(parts.chunks.size(), p.main_workplan.its_elements.size()) << program;
        }
        const stepnc::Project back = joined(parts);
        EXPECT_EQ(back, p) << program << " chunks of " << chunk_bytes;
        EXPECT_EQ(written(back), written(p)) << program;
      }
    }
  }
}

TEST(ProjectStream, EachChunkNamesOnlyWhatCameBeforeOrWithIt) {
  const stepnc::Project p = cc2(cc1(kShared + "/corpus/paper/", "test_part.ngc"));
  const auto parts = stepnc_codec::split_project(p, 1);
  stepnc_codec::ProjectJoiner joiner;
  joiner.shell(parts.shell);
  for (const std::string& c : parts.chunks) {
    ASSERT_NO_THROW(joiner.chunk(c));  // the joiner checks every reference of the chunk
  }
  EXPECT_EQ(joiner.elements(), p.main_workplan.its_elements.size());
}

TEST(ProjectStream, BadPartsAreInputErrors) {
  const stepnc::Project p = cc1(kShared + "/corpus/paper/", "face_mill.ngc");
  const auto parts = stepnc_codec::split_project(p, 1);
  ASSERT_GE(parts.chunks.size(), 2u);
  {
    stepnc_codec::ProjectJoiner joiner;
    EXPECT_THROW(joiner.chunk(parts.chunks[0]), InputError);  // before the shell
    EXPECT_THROW(joiner.shell(parts.chunks[0]), InputError);  // a chunk is no shell
  }
  {
    stepnc_codec::ProjectJoiner joiner;
    joiner.shell(parts.shell);
    EXPECT_THROW(joiner.chunk(parts.shell), InputError);
    const std::string& c = parts.chunks[0];
    for (std::size_t n = 0; n < c.size(); n += 1 + n / 16) EXPECT_THROW(joiner.chunk(c.substr(0, n)), InputError) << n;
  }
  // Flipping any byte of a chunk either still decodes (a value changed) or is rejected: never a crash.
  for (const std::string& c : parts.chunks) {
    for (std::size_t i = 0; i < c.size(); i += 3) {
      std::string flipped = c;
      flipped[i] = static_cast<char>(flipped[i] ^ 0x5A);
      stepnc_codec::ProjectJoiner joiner;
      joiner.shell(parts.shell);
      try {
        joiner.chunk(flipped);
      } catch (const InputError&) {
      }
    }
  }
  {
    // A chunk whose workingstep names a feature and operation that have not come.
    stepnc::Project q;
    stepnc::MachiningWorkingstep ws;
    ws.its_feature = stepnc::FeatureRef{3};
    ws.its_operation = stepnc::OperationRef{3};
    q.main_workplan.its_elements.emplace_back(ws);
    const auto bad = stepnc_codec::split_project(q, 1);
    stepnc_codec::ProjectJoiner joiner;
    joiner.shell(bad.shell);
    EXPECT_THROW(joiner.chunk(bad.chunks[0]), InputError);
  }
}

}  // namespace
}  // namespace ncbridge
