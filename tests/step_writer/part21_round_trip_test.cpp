// Every Part 21 file of the shared corpus reads, and read -> write -> read -> write is stable.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "ncbridge/step_writer/part21_reader.hpp"
#include "ncbridge/step_writer/part21_writer.hpp"

namespace fs = std::filesystem;
using namespace ncbridge::step_writer::part21;

namespace {

std::vector<fs::path> corpus_part21_files() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(NCBRIDGE_SHARED_DIR) / "corpus")) {
    auto ext = entry.path().extension().string();
    if (entry.is_regular_file() && (ext == ".stp" || ext == ".step")) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

bool is_negative_syntax_case(const fs::path& p) {
  auto name = p.filename().string();
  return p.parent_path().filename() == "part21-negative" &&
         (name == "missing_semicolon.stp" || name == "syntax_missing_comma.stp" || name == "dangling_ref.stp");
}

}  // namespace

TEST(Part21RoundTrip, EveryCorpusFileReadsAndRewritesIdentically) {
  auto files = corpus_part21_files();
  ASSERT_GE(files.size(), 26u) << "the shared corpus is missing";
  std::size_t round_tripped = 0;
  for (const auto& path : files) {
    if (is_negative_syntax_case(path)) continue;
    SCOPED_TRACE(path.string());
    ReadResult first = read_part21_file(path);
    ASSERT_FALSE(first.graph.empty());
    std::string written = write_part21(first.graph);
    ReadResult second = read_part21(written, "rewritten");
    EXPECT_EQ(second.graph.size(), first.graph.size());
    EXPECT_TRUE(second.graph == first.graph) << "the written file reads back as a different graph";
    std::string rewritten = write_part21(second.graph);
    EXPECT_EQ(rewritten, written);
    ++round_tripped;
  }
  EXPECT_EQ(round_tripped, files.size() - 3);
}

TEST(Part21RoundTrip, KeepsInstanceCountsAndReferencesOfTheNistExample) {
  auto read = read_part21_file(fs::path(NCBRIDGE_SHARED_DIR) / "corpus/stepnc/nist_ex1.stp");
  const auto& g = read.graph;
  const Instance& ws = g.at(10);
  EXPECT_EQ(ws.entity(), "MACHINING_WORKINGSTEP");
  ASSERT_EQ(ws.attributes().size(), 5u);
  EXPECT_EQ(ws.attributes()[0].as_string(), "WS FINISH PLANAR FACE1");
  EXPECT_EQ(ws.attributes()[1].as_reference(), 62u);
  EXPECT_EQ(ws.attributes()[2].as_reference(), 16u);
  EXPECT_EQ(ws.attributes()[3].as_reference(), 19u);
  EXPECT_TRUE(ws.attributes()[4].is_unset());
  EXPECT_EQ(g.header.schema, (std::vector<std::string>{"MACHINING_SCHEMA", "MILLING_SCHEMA"}));
  EXPECT_EQ(g.header.name, "EXAMPLE1.STP");
  EXPECT_EQ(g.header.time_stamp, "2002-02-02");
}
