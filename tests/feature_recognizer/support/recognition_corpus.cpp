#include "recognition_corpus.hpp"

#include "canon_text_reader.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "toolpath_segmenter.hpp"

namespace ncbridge::test_support {

std::vector<RecognitionCase> recognition_corpus(const std::filesystem::path& source_dir,
                                                const std::filesystem::path& shared_dir) {
  const auto data = source_dir / "tests/feature_recognizer/data";
  const auto cam = shared_dir / "corpus/cam";
  const auto paper = shared_dir / "corpus/paper";
  std::vector<RecognitionCase> cases;
  for (const char* part : {"p01_block_reference", "p02_plate_center_zero", "p03_bracket_steps", "p04_open_pockets",
                           "p05_slots"}) {
    cases.push_back({part, data / (std::string(part) + ".canon"), cam / part / "tools.json", cam / part / "stock.json",
                     cam / part / "truth.json", ""});
  }
  cases.push_back({"paper_face_mill", data / "paper_face_mill.canon", paper / "tools.json", paper / "stock.json",
                   paper / "truth.json", "face_mill.ngc"});
  cases.push_back({"paper_test_part", data / "paper_test_part.canon", paper / "tools.json", paper / "stock.json",
                   paper / "truth.json", "test_part.ngc"});
  // Hand-designed parts of other shapes and strategies (tests/cc2/parts/make_parts.py).
  const auto parts = source_dir / "tests/cc2/parts";
  for (const char* part : {"p06_nested_pockets", "p07_helix_holes", "p08_multi_level", "p09_small_part", "p10_plate",
                           "p11_slots_rotated_pocket", "p12_freecad_style", "p13_hsm_style", "p14_shop_program", "p15_hobby_style"}) {
    cases.push_back({part, data / (std::string(part) + ".canon"), parts / part / "tools.json", parts / part / "stock.json",
                     parts / part / "truth.json", ""});
  }
  return cases;
}

std::vector<feature_recognizer::ToolpathWorkingstep> load_workingsteps(const RecognitionCase& c) {
  return segment_workingsteps(read_canon_text(c.canon), setup::read_tool_list(c.tools));
}

std::vector<feature_recognizer::RecognizedFeature> recognize_case(const RecognitionCase& c) {
  return feature_recognizer::recognize(load_workingsteps(c), setup::read_stock(c.stock));
}

}  // namespace ncbridge::test_support
