#pragma once
// Test support: a part program through the forward pipeline (interpreter -> cc1_builder ->
// feature recogniser), giving the CC1 model and the recognised CC2 model with the program's
// explicit toolpaths: what `ncbridge convert --level cc2` writes.
#include <filesystem>
#include <string>
#include <vector>

#include "ncbridge/setup/stock.hpp"
#include "ncbridge/stepnc/project.hpp"

namespace ncbridge::test_support {

struct PipelineResult {
  stepnc::Project cc1;
  stepnc::Project cc2;
  setup::Stock stock;
};

// `program` is read with every comment stripped (recognition must not read them).
PipelineResult run_forward_pipeline(const std::filesystem::path& program, const std::filesystem::path& tools,
                                    const std::filesystem::path& stock);

// A program in any dialect, read as `ncbridge convert` reads it (no M2 needed at its end), its
// subprograms from `subroutine_path`; comments are not stripped (recognition reads only
// geometry, tools and the stock).
struct ProgramInput {
  std::filesystem::path program, tools, stock;
  std::string dialect = "rs274ngc";  // rs274ngc, fanuc, mach3, siemens840d, heidenhain
  std::vector<std::filesystem::path> subroutine_path;
};
PipelineResult run_forward_pipeline(const ProgramInput& input);

// The corpus parts: name -> program, tools, stock (cam/, paper/, tests/cc2/parts/).
struct CorpusPart {
  std::string name;
  std::filesystem::path program, tools, stock;
};
CorpusPart corpus_part(const std::string& name);

}  // namespace ncbridge::test_support
