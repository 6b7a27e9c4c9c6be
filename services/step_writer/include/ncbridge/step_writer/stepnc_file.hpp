#pragma once
// The ISO 14649 model (ncbridge::stepnc::Project) <-> Part 21 files (ISO 10303-21), with the
// entity names and attribute orders of the ISO 14649-10/-11/-111 EXPRESS schemas (2002 drafts).
// Writing is deterministic: the same project and options give the same bytes. Ids are numbered
// bottom-up (every reference points back, but to the setup's security plane, whose id is taken
// after the workpiece and which is written with the SETUP; PROJECT is the last instance), so the
// file is written as a stream without holding an instance graph (also while the workplan is
// being built: stepnc_stream_writer.hpp). Reading a file this writer wrote gives back an
// equal project (apart from SourceLines, which files do not carry), so write -> read -> write is
// byte-identical. stepnc_to_graph gives the same instances and ids as a Graph (for the schema
// check); writing that Graph with write_part21 differs only in line breaks.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ncbridge/step_writer/diagnostic.hpp"
#include "ncbridge/step_writer/part21_graph.hpp"
#include "ncbridge/stepnc/project.hpp"

namespace ncbridge::step_writer {

struct StepncWriteOptions {
  std::string file_name;                // FILE_NAME.name
  std::vector<std::string> description{"ISO 14649 CC1 program written by ncbridge"};
  std::optional<std::int64_t> unix_time;  // unset: SOURCE_DATE_EPOCH, else the clock
  // FILE_NAME.preprocessor_version and originating_system; empty: "ncbridge <version>".
  std::string preprocessor_version;
  std::string originating_system;
};

// The instance graph of a project (header filled from the options).
part21::Graph stepnc_to_graph(const stepnc::Project& project, const StepncWriteOptions& options = {});
std::string write_stepnc(const stepnc::Project& project, const StepncWriteOptions& options = {});
// The same text handed to `write_chunk` piece by piece (about 1 MB each) as it is made, so the
// whole file is never held in memory (e.g. straight into an AtomicFile); returns its size in bytes.
std::uint64_t write_stepnc(const stepnc::Project& project, const StepncWriteOptions& options,
                           const std::function<void(std::string_view)>& write_chunk);

struct StepncReadResult {
  stepnc::Project project;
  std::vector<Diagnostic> warnings;  // entities read but not kept (e.g. CC2 features not mapped yet)
};

// Throws ncbridge::InputError (file, line of the instance) when the file is not a project this
// model can hold: no PROJECT, a reference to the wrong entity, a missing required attribute.
StepncReadResult stepnc_from_graph(const part21::Graph& graph, const std::string& file_name);
StepncReadResult read_stepnc(std::string_view text, const std::string& file_name);
StepncReadResult read_stepnc_file(const std::filesystem::path& path);

}  // namespace ncbridge::step_writer
