#pragma once
// Open CASCADE's side of the B-rep reader: a STEP file (AP203, AP214, AP242) read and turned
// into the setup frame, then described as a plain brep::Model. The only part_reader files that
// include Open CASCADE headers are brep_extract.cpp and brep_stock.cpp.
#include <filesystem>

#include "brep_model.hpp"
#include "ncbridge/part_reader/part.hpp"
#include "ncbridge/part_reader/setup_frame.hpp"

namespace ncbridge::part_reader::brep {

// Throws InputError: not a STEP file Open CASCADE can read, no solid, several solids.
// `occt_ms` (when given) gets the time Open CASCADE took to read the file into the turned solid.
Model load_step(const std::filesystem::path& path, const SetupFrame& frame, double* occt_ms = nullptr);

// The axis-aligned box of the solid(s) of a STEP file (for --stock-step), in its own frame.
Box step_box(const std::filesystem::path& path);

}  // namespace ncbridge::part_reader::brep
