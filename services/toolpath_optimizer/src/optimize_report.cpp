// The --report JSON of `ncbridge optimize` (docs/formats/optimize-report.md).
#include <nlohmann/json.hpp>

#include "ncbridge/interpreter/dialect_detect.hpp"
#include "ncbridge/toolpath_optimizer/pipeline.hpp"

namespace ncbridge::toolpath_optimizer {

std::string report_json(const OptimizeRequest& request, const OptimizeResult& r) {
  using json = nlohmann::ordered_json;
  json report;
  report["input"] = request.input.string();
  report["output"] = request.output_name;
  if (request.input_kind == InputKind::Cnc) report["dialect"] = std::string(interpreter::dialect_name(request.cnc.dialect));
  else report["flavor"] = std::string(printer_flavor_name(request.flavor));
  report["to"] = request.output == OutputFormat::Krl ? "krl" : "gcode";
  report["tolerance_mm"] = request.optimizer.tolerance_mm;
  report["min_segment_mm"] = request.optimizer.min_segment_mm;
  report["input_counts"] = {{"bytes", r.bytes_in}, {"lines", r.lines_in}, {"commands", r.commands_in},
                            {"motion_blocks", r.motion_blocks_in}, {"arcs", r.arcs_in}};
  report["output_counts"] = {{"bytes", r.bytes_out}, {"lines", r.lines_out}, {"commands", r.commands_out},
                             {"motion_blocks", r.motion_blocks_out}};
  report["motion_block_reduction"] =
      r.motion_blocks_in ? 1.0 - double(r.motion_blocks_out) / double(r.motion_blocks_in) : 0.0;
  report["made"] = {{"arcs", r.stats.arcs}, {"merged_lines", r.stats.lines_merged}, {"folded_moves", r.stats.folded},
                    {"loops", r.loops.loops}, {"layers_in_loops", r.loops.layers_in_loops}};
  if (r.deviation) {
    const DeviationReport& d = *r.deviation;
    json layers = json::array();
    for (const auto& l : d.worst_layers) {
      layers.push_back({{"z", l.z}, {"input_to_output_mm", l.input_to_output},
                        {"output_to_input_mm", l.output_to_input}, {"output_motions", l.output_motions}});
    }
    report["deviation"] = {{"checked", true},
                           {"largest_mm", d.largest()},
                           {"input_to_output_mm", d.input_to_output},
                           {"output_to_input_mm", d.output_to_input},
                           {"extrusion_error_mm", d.extrusion_error},
                           {"worst_output_line", d.worst_output_line},
                           {"spans", d.spans},
                           {"layers", d.layer_count},
                           {"worst_layers", layers},
                           {"problems", d.problems}};
  } else {
    report["deviation"] = {{"checked", false}};
  }
  report["time_ms"] = {{"total", r.optimize_seconds * 1000}, {"check", r.check_seconds * 1000}};
  return report.dump(2) + "\n";
}

}  // namespace ncbridge::toolpath_optimizer
