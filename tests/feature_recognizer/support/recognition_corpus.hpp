#pragma once
// Test support: the recognition corpus (5 FreeCAD parts + the 2 programs of Xú et al. 2014 +
// 6 hand-designed parts of tests/cc2/parts): committed canonical text
// (tests/feature_recognizer/data, comments stripped), tools, stock and truth.
#include <filesystem>
#include <string>
#include <vector>

#include "ncbridge/feature_recognizer/recognizer.hpp"
#include "ncbridge/feature_recognizer/scoring.hpp"

namespace ncbridge::test_support {

struct RecognitionCase {
  std::string name;
  std::filesystem::path canon, tools, stock, truth;
  std::string truth_program;  // key in a multi-program truth file, else empty
};

std::vector<RecognitionCase> recognition_corpus(const std::filesystem::path& source_dir,
                                                const std::filesystem::path& shared_dir);

std::vector<feature_recognizer::ToolpathWorkingstep> load_workingsteps(const RecognitionCase& c);
std::vector<feature_recognizer::RecognizedFeature> recognize_case(const RecognitionCase& c);

}  // namespace ncbridge::test_support
