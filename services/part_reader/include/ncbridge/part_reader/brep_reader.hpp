#pragma once
// B-rep STEP parts (AP203, AP214, AP242; mm, inch, m): read with Open CASCADE, then features
// recognised from the faces, their surfaces and how they meet (docs/plan.md): round holes
// (through, blind with a flat or conical bottom) with counterbores and countersinks, circular
// and rectangular pockets and pockets of any outline, slots, steps, open pockets, and the part's
// outline from above for the top face and the outside profile (add_stock_features). Holes on
// other axes are kept with their axis and warned; faces no feature explains are warned.
#include <filesystem>
#include <string>

#include "ncbridge/part_reader/part.hpp"

namespace ncbridge::part_reader {

// Where the time of a read goes (benchmarks): Open CASCADE reading the file into a solid, that
// solid described as plain faces and edges, recognition.
struct BrepTimings {
  double occt_ms = 0, model_ms = 0, recognition_ms = 0;
};

// Throws ncbridge::InputError: not a STEP file, no solid, several solids.
Part read_brep_file(const std::filesystem::path& path, const ReadOptions& options = {}, BrepTimings* timings = nullptr);

// The bounding box of the solid in a STEP file (a stock given as --stock-step), in its frame.
Box read_step_box(const std::filesystem::path& path);

// Either kind of STEP part: AP224 files (FILE_SCHEMA feature_based_process_planning) through the
// AP224 reader, any other STEP file as a B-rep. Syntax errors are located (file, line, column).
Part read_part_file(const std::filesystem::path& path, const ReadOptions& options = {});

}  // namespace ncbridge::part_reader
