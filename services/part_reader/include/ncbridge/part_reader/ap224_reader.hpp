#pragma once
// AP224 (ISO 10303-224, feature_based_process_planning) files: the machining features and the
// stock are read from the instance graph the project's own Part 21 reader builds (complex
// instances included), following each feature's parameter representation (placement, measures)
// and the feature components hung on its shape aspects (profiles, paths, hole bottoms, slot
// ends), in the file's units. docs/plan.md lists what is read and what is only listed.
#include <filesystem>
#include <string>

#include "ncbridge/part_reader/part.hpp"
#include "ncbridge/step_writer/part21_graph.hpp"

namespace ncbridge::part_reader {

// The file says it is AP224 (FILE_SCHEMA feature_based_process_planning).
bool is_ap224(const step_writer::part21::Header& header);

// Throws ncbridge::InputError (file, line of the instance) for what cannot be read: a feature
// without the parameters its kind needs, a reference to the wrong kind of instance, units that
// do not resolve. Features it does not map are listed (Part::listed) with a warning.
Part read_ap224(const step_writer::part21::Graph& graph, const std::string& file_name, const ReadOptions& options = {});
Part read_ap224_file(const std::filesystem::path& path, const ReadOptions& options = {});

}  // namespace ncbridge::part_reader
