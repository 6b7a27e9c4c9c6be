// `ncbridge plan PART.stp [--stock S | --stock-step S.stp] --tools T -o OUT.stp [--report R.json]
// [--html R.html]`: part_reader -> process_planner -> step_writer in one process (docs/plan.md).
// Every output of a run is made first and then written together: a failed run leaves none.
#include <CLI/CLI.hpp>

#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cc2_to_cc1.hpp"
#include "commands.hpp"
#include "errors.hpp"
#include "html_report.hpp"
#include "input_files.hpp"
#include "output_files.hpp"
#include "tool_source.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/gcode_writer/dialect.hpp"
#include "ncbridge/gcode_writer/program_writer.hpp"
#include "ncbridge/gcode_writer/stepnc_interpreter.hpp"
#include "ncbridge/part_reader/brep_reader.hpp"
#include "ncbridge/part_reader/setup_frame.hpp"
#include "ncbridge/process_planner/planner.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/setup/yaml_input.hpp"
#include "ncbridge/step_writer/part21_reader.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"
#include "plan_report.hpp"

namespace ncbridge::cli {

namespace {

namespace pr = part_reader;
using Clock = std::chrono::steady_clock;

struct PlanArguments {
  std::string part;
  ToolSource tools;
  std::string stock;
  std::string stock_step;
  std::string output;
  std::string report;
  std::string html;
  std::string setup = "+z";
  std::vector<double> part_offset;
  std::string material = "steel";
  double security_clearance = 10;
  std::string gcode;            // also the program: the plan's toolpaths generated and written
  std::string to = "rs274ngc";  // in this dialect
};

double ms(Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

// Where the stock file says the part's box starts (its optional "part_bbox_min"), if it does.
std::optional<std::array<double, 3>> part_min_of(const std::string& stock_file) {
  const YAML::Node root = setup::parse_yaml_document(setup::read_text_file(stock_file), stock_file);
  const YAML::Node n = root["part_bbox_min"];
  if (!n) return std::nullopt;
  if (!n.IsSequence() || n.size() != 3) throw InputError(setup::location_of(n, stock_file), "stock: 'part_bbox_min' must be [x, y, z]");
  double scale = 1;
  if (auto units = setup::optional_string(root, "units", stock_file); units && (*units == "inch" || *units == "in")) scale = 25.4;
  std::array<double, 3> p{};
  for (std::size_t i = 0; i < 3; ++i) p[i] = n[i].as<double>() * scale;
  return p;
}

setup::Stock box_stock(const pr::Box& b) { return setup::Stock{b.min, b.max}; }

std::string text_of(const std::array<double, 3>& v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "[%g, %g, %g]", v[0], v[1], v[2]);
  return buf;
}

// The shop's tools; a tool table's kinds read from its comments, a tool whose comment names none
// said (the plan cannot choose it).
setup::ToolList tools_for_planning(const ToolSource& source) {
  setup::ToolList tools = source.read();
  if (source.tool_table.empty()) return tools;
  std::vector<int> unnamed;
  tools = with_kinds_from_names(tools, unnamed);
  for (int number : unnamed) {
    const setup::Tool* t = tools.find(number);
    print_warning({source.tool_table, 0, 0},
                  "tool T" + std::to_string(number) + " (\"" + t->name +
                      "\"): its comment names no kind of tool (drill, end mill, face mill, ...); the plan does not use it");
  }
  return tools;
}

int run_plan(const PlanArguments& args) {
  const auto t0 = Clock::now();
  pr::ReadOptions read_options;
  const auto up = pr::setup_up_from_string(args.setup);
  if (!up) throw UsageError("--setup must be one of +z, -z, +x, -x, +y, -y");
  read_options.up = *up;
  process_planner::Options options;
  const auto material = process_planner::material_from_string(args.material);
  if (!material) throw UsageError("--material must be steel, aluminium, stainless, cast_iron, brass or plastic");
  if (!args.stock.empty() && !args.stock_step.empty()) throw UsageError("give --stock or --stock-step, not both");
  // Every input and output checked before the work starts; the outputs appear together at the end.
  require_input_file(args.part, "part");
  if (!args.tools.given()) throw UsageError("the shop's tools are needed: --tools or --tool-table");
  args.tools.check();
  if (!args.stock.empty()) require_input_file(args.stock, "--stock");
  if (!args.stock_step.empty()) require_input_file(args.stock_step, "--stock-step");
  OutputSet outputs;
  OutputFile& stp = outputs.add(args.output, "-o");
  OutputFile* report_file = args.report.empty() ? nullptr : &outputs.add(args.report, "--report");
  OutputFile* html_file = args.html.empty() ? nullptr : &outputs.add(args.html, "--html");
  OutputFile* gcode_file = args.gcode.empty() ? nullptr : &outputs.add(args.gcode, "--gcode");
  for (const std::string* input : {&args.part, &args.tools.file(), &args.stock, &args.stock_step}) {
    if (!input->empty()) outputs.protect(*input);
  }
  options.material = *material;
  options.security_clearance = args.security_clearance;
  const setup::ToolList tools = tools_for_planning(args.tools);

  pr::Part part = pr::read_part_file(args.part, read_options);
  std::string stock_source;
  std::optional<setup::Stock> stock;
  std::array<double, 3> offset{0, 0, 0};
  if (!args.part_offset.empty()) {
    offset = {args.part_offset[0], args.part_offset[1], args.part_offset[2]};
  } else if (!args.stock.empty()) {
    if (auto min = part_min_of(args.stock)) {
      if (!part.bounds) throw InputError({args.stock, 0, 0}, "part_bbox_min needs a B-rep part (its box); give --part-offset");
      for (std::size_t i = 0; i < 3; ++i) offset[i] = (*min)[i] - part.bounds->min[i];
    }
  }
  if (offset != std::array<double, 3>{0, 0, 0}) pr::move_part(part, offset);
  if (!args.stock.empty()) {
    stock = setup::read_stock(args.stock);
    stock_source = args.stock;
  } else if (!args.stock_step.empty()) {
    stock = box_stock(pr::read_step_box(args.stock_step));
    stock_source = args.stock_step + " (its bounding box)";
  } else if (part.stock) {
    stock = box_stock(pr::bounding_box(*part.stock));
    stock_source = std::string("the file's ") + (part.stock->shape == pr::StockShape::Block ? "block" : "cylinder (its bounding box)") +
                   " " + part.stock->source;
  } else if (part.bounds) {
    stock = box_stock(*part.bounds);
    stock_source = "the part's bounding box";
  } else {
    throw InputError({args.part, 0, 0}, "no stock: the file defines none; give --stock");
  }
  if (part.bounds) {
    for (std::size_t i = 0; i < 3; ++i) {
      if (part.bounds->min[i] < stock->min[i] - 1e-3 || part.bounds->max[i] > stock->max[i] + 1e-3) {
        throw InputError({args.part, 0, 0}, "the part (box " + text_of(part.bounds->min) + " to " + text_of(part.bounds->max) +
                                                ") does not lie inside the stock (" + text_of(stock->min) + " to " + text_of(stock->max) +
                                                "): place it with --part-offset or a stock file's part_bbox_min");
      }
    }
  }
  pr::add_stock_features(part, pr::Box{stock->min, stock->max});
  const auto t_read = Clock::now();

  const process_planner::Plan plan = process_planner::plan(part, *stock, tools, options);
  const Cc2Output cc2 = plan_as_cc2(part, plan, *stock);
  const auto t_planned = Clock::now();

  step_writer::StepncWriteOptions write;
  write.file_name = stp.file_name();
  write.description = {"ISO 14649 CC2 program written by ncbridge"};
  const std::string cc2_text = step_writer::write_stepnc(plan.project, write);
  const auto t_written = Clock::now();

  std::vector<std::string> warnings;
  for (const auto& w : part.warnings) warnings.push_back((w.where.empty() ? "" : w.where + ": ") + w.message);
  for (const auto& w : plan.warnings) warnings.push_back((w.where.empty() ? "" : w.where + ": ") + w.message);
  for (const auto& w : warnings) print_warning({args.part, 0, 0}, w);

  std::string report_text, html_text;
  if (!args.report.empty()) {
    using json = nlohmann::ordered_json;
    json workingsteps = json::array();
    for (const auto& e : plan.project.main_workplan.its_elements) {
      const auto& ws = std::get<stepnc::MachiningWorkingstep>(e);
      const auto& op = plan.project.operation(ws.its_operation);
      const auto& mop = stepnc::machining_operation(op);
      const auto& t = plan.project.technology(mop.its_technology);
      json w{{"kind", "MACHINING_WORKINGSTEP"}, {"id", ws.its_id}, {"operation", stepnc::entity_name(op)},
             {"feature", stepnc::feature_id(plan.project.feature(ws.its_feature))}, {"tool", plan.project.tool(mop.its_tool).its_id}};
      if (t.feedrate) w["feedrate_m_per_s"] = *t.feedrate;
      if (t.spindle) w["spindle_rev_per_s"] = *t.spindle;
      workingsteps.push_back(std::move(w));
    }
    json tool_list = json::array();
    for (const auto& t : plan.project.tools) tool_list.push_back({{"number", t.number}, {"id", t.its_id}, {"diameter_mm", t.dimension.diameter}});
    json warning_list = json::array();
    const std::vector<const std::vector<pr::Warning>*> lists{&part.warnings, &plan.warnings};
    for (const auto* list : lists) {
      for (const auto& w : *list) warning_list.push_back({{"where", args.part + (w.where.empty() ? "" : " " + w.where)}, {"message", w.message}});
    }
    json report;
    report["part"] = args.part;
    report["output"] = args.output;
    report["level"] = "cc2";
    report["format"] = part.format;
    report["file_units"] = part.file_units;
    report["product"] = part.name;
    report["setup"] = args.setup;
    report["part_offset"] = {offset[0], offset[1], offset[2]};
    report["stock"] = {{"source", stock_source}, {"min", {stock->min[0], stock->min[1], stock->min[2]}},
                       {"max", {stock->max[0], stock->max[1], stock->max[2]}}};
    report["material"] = std::string(process_planner::to_string(options.material));
    report["output_bytes"] = cc2_text.size();
    report["workingsteps"] = workingsteps;
    report["tools"] = tool_list;
    report["features"] = cc2_features_json(cc2);
    const json sections = part_sections(part, plan);
    for (const auto& [key, value] : sections.items()) report[key] = value;
    report["warnings"] = warning_list;
    report["timings_ms"] = {{"read_part", ms(t_read - t0)}, {"plan", ms(t_planned - t_read)}, {"step_writer", ms(t_written - t_planned)},
                            {"total", ms(Clock::now() - t0)}};
    report_text = report.dump(2) + "\n";
  }
  // The plan's toolpaths, generated (as `convert --level cc1` does) for the program and the page.
  // The program needs them (a refusal leaves every output unwritten); the page without a program
  // shows the plan and says why they are missing.
  std::optional<stepnc::Project> cc1;
  std::vector<std::string> page_warnings = warnings;
  if (gcode_file || !args.html.empty()) {
    std::vector<std::string> notes;
    try {
      cc1 = generate_cc1(plan.project, *stock, args.part, notes);
    } catch (const InputError& e) {
      if (gcode_file) throw;
      page_warnings.push_back("toolpaths not generated: " + e.message());
    }
    if (gcode_file) {
      for (const auto& n : notes) print_warning({args.part, 0, 0}, n);
    }
    page_warnings.insert(page_warnings.end(), notes.begin(), notes.end());
  }
  if (!args.html.empty()) {
    HtmlReportInput page;
    page.title = std::filesystem::path(args.part).filename().string() + " (planned)";
    page.stock = *stock;
    page.model = &plan.project;
    if (cc1) page.toolpaths = &*cc1;
    page.warnings = page_warnings;
    html_text = html_report(page);
  }

  // The program: the generated toolpaths written (as `gcode` does).
  std::string program_text;
  if (gcode_file) {
    gcode_writer::Options writer_options;
    writer_options.dialect = *gcode_writer::parse_dialect(args.to);
    writer_options.tools = gcode_writer::stepnc_tools(*cc1);
    std::string name = std::filesystem::path(gcode_file->file_name()).stem().string();
    for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : '_';
    if (!name.empty()) writer_options.program_name = name;
    gcode_writer::ProgramWriter writer(writer_options, [&](std::string_view piece) { program_text += piece; });
    gcode_writer::interpret_stepnc(*cc1, args.part, gcode_writer::StepncOptions{}, writer);
  }

  stp.write(cc2_text);
  if (gcode_file) gcode_file->write(program_text);
  if (report_file) report_file->write(report_text);
  if (html_file) html_file->write(html_text);
  outputs.commit();
  return 0;
}

}  // namespace

void add_plan_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<PlanArguments>();
  CLI::App* cmd = app.add_subcommand("plan", "Plan a STEP part (AP224 features or a B-rep) into an ISO 14649 CC2 file");
  cmd->add_option("part", args->part, "STEP part: AP224 (features) or AP203/AP214/AP242 (B-rep)")->required();
  add_tool_source_options(*cmd, args->tools, "; a tool table's comments name each tool's kind (docs/plan.md)");
  cmd->add_option("--stock", args->stock, "Stock block (docs/formats/stock.md); its part_bbox_min places the part");
  cmd->add_option("--stock-step", args->stock_step, "Stock as a STEP solid (its bounding box)");
  cmd->add_option("-o,--output", args->output, "CC2 Part 21 file to write")->required();
  cmd->add_option("--gcode", args->gcode, "Also write the program: the plan's toolpaths generated, in the dialect --to");
  cmd->add_option("--to", args->to, "Dialect of --gcode (default rs274ngc)")
      ->check(CLI::IsMember({"rs274ngc", "fanuc", "mach3", "siemens840d", "heidenhain"}));
  cmd->add_option("--report", args->report, "Also write a JSON report (docs/plan.md)");
  cmd->add_option("--html", args->html, "Also write an HTML page of the planned features and their generated toolpaths");
  cmd->add_option("--setup", args->setup, "The part's side facing the spindle: +z (default), -z, +x, -x, +y, -y");
  cmd->add_option("--part-offset", args->part_offset, "Move the part by X,Y,Z mm into the program frame")->expected(3)->delimiter(',');
  cmd->add_option("--material", args->material, "Work material for default cutting data: steel, aluminium, stainless, cast_iron, brass, plastic");
  cmd->add_option("--security-clearance", args->security_clearance, "Security plane height above the stock top, mm (default 10)");
  cmd->callback([args, &exit_code]() { exit_code = run_plan(*args); });
}

}  // namespace ncbridge::cli
