// libFuzzer target: the AP224 path of `ncbridge plan` (Part 21 reader -> AP224 reader ->
// process planner -> CC2 writer). Whatever the bytes, every stage either accepts them or throws
// ncbridge::InputError; nothing crashes, and what is planned writes.
#include <cstdint>
#include <string_view>

#include "ncbridge/common/error.hpp"
#include "ncbridge/part_reader/ap224_reader.hpp"
#include "ncbridge/process_planner/planner.hpp"
#include "ncbridge/step_writer/part21_reader.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"

namespace {

const ncbridge::setup::ToolList& tools() {
  static const auto list = ncbridge::setup::parse_tool_list(R"([
    {"number": 1, "type": "face_mill", "diameter": 50, "flute_length": 6},
    {"number": 2, "type": "flat_end_mill", "diameter": 20, "flute_length": 60},
    {"number": 3, "type": "flat_end_mill", "diameter": 6, "flute_length": 30},
    {"number": 4, "type": "flat_end_mill", "diameter": 1, "flute_length": 10},
    {"number": 5, "type": "spot_drill", "diameter": 10, "point_angle": 90},
    {"number": 6, "type": "drill", "diameter": 6.35, "point_angle": 118},
    {"number": 7, "type": "chamfer_mill", "diameter": 20, "point_angle": 90}])",
                                                                 "fuzz_tools.json");
  return list;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ncbridge;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto read = step_writer::part21::read_part21(text, "fuzz.stp");
    const part_reader::Part part = part_reader::read_ap224(read.graph, "fuzz.stp");
    setup::Stock stock{{-500, -500, -500}, {500, 500, 500}};
    if (part.stock) {
      const auto box = part_reader::bounding_box(*part.stock);
      stock = {box.min, box.max};
    }
    const auto plan = process_planner::plan(part, stock, tools());
    step_writer::StepncWriteOptions options;
    options.unix_time = 0;
    (void)step_writer::write_stepnc(plan.project, options);
  } catch (const InputError&) {
  }
  return 0;
}
