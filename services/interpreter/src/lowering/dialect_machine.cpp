#include "lowering/dialect_machine.hpp"

#include <cctype>

#include "ncbridge/common/error.hpp"

namespace ncbridge::interpreter::lowering {

DialectMachine::DialectMachine(const Options& options, canonical::Sink& sink, const DialectTable& table)
    : options_(options), sink_(sink), executor_(options, params_, sink), file_name_(&no_file_) {
  params_.set_computed(&executor_);
  Executor::ArcTolerance arcs;
  arcs.mm = table.setting("center_arc_radius_tolerance_mm", arcs.mm);
  arcs.inch = table.setting("center_arc_radius_tolerance_inch", arcs.inch);
  executor_.set_arc_tolerance(arcs);
  machine_functions_ = table.machine_functions;
  for (int code : options.machine_functions) machine_functions_.emplace(code_key(code), "a machine function");
}

bool DialectMachine::machine_function(double code, std::uint32_t column) {
  auto it = machine_functions_.find(code_key(code));
  if (it == machine_functions_.end()) return false;
  const std::string what = "M" + it->first + " (" + it->second + ")";
  warn(column, what + " is a machine builder's function: read as such, it moves nothing");
  comment("ncbridge: " + what + ": machine function, no motion");
  return true;
}

void DialectMachine::start() {
  executor_.set_source(canonical::Source{0, 0, -1, 0});
  executor_.start();
}

void DialectMachine::at(std::uint32_t file, const std::string& file_name, std::uint32_t line, std::int64_t n_number,
                        std::uint8_t n_digits) {
  source_ = canonical::Source{file, line, n_number, n_digits};
  file_name_ = &file_name;
  line_ = line;
  segments_.clear();
  executor_.set_source(source_);
}

// Every error names a line and a column: an empty file's (or one before any block) is line 1.
void DialectMachine::fail(std::uint32_t column, const std::string& message) const {
  throw InputError(locate(*file_name_, line_, column, segments_), message);
}

void DialectMachine::warn(std::uint32_t column, const std::string& message) const {
  if (options_.strict) fail(column, message + " (refused under --strict)");
  if (options_.warning) options_.warning(locate(*file_name_, line_, column, segments_), message);
}

bool DialectMachine::execute(const NeutralBlock& nb) {
  if (nb.empty()) return false;
  block_.clear();
  block_.line = line_;
  values_.clear();
  for (const NeutralWord& w : nb.words) {
    ExprNode node;
    node.op = ExprOp::Number;
    node.value = w.value;
    node.column = w.column;
    block_.nodes.push_back(node);
    Word word;
    word.letter = w.letter;
    word.value = static_cast<ExprRef>(block_.nodes.size() - 1);
    word.column = w.column;
    block_.words.push_back(word);
    values_.push_back(w.value);
  }
  if (nb.has_comment) {
    CommentText c;
    c.kind = nb.comment_is_message ? CommentText::Kind::Message : CommentText::Kind::Plain;
    c.text = nb.comment;
    c.column = 1;
    block_.comments.push_back(c);
  }
  assemble_command(block_, values_.data(), *file_name_, command_);
  return executor_.execute(command_, source_, *file_name_);
}

void DialectMachine::comment(const std::string& text) { executor_.emit(canonical::Comment{text}); }
void DialectMachine::message(const std::string& text) { executor_.emit(canonical::Message{text}); }

int DialectMachine::tool_number_for_name(const std::string& name, std::uint32_t column) {
  auto same = [](std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
    }
    return true;
  };
  for (const setup::Tool& t : options_.tools.tools()) {
    if (same(t.name, name)) return t.number;
  }
  if (!options_.tools.empty()) fail(column, "Tool \"" + name + "\" is not in the tool list");
  for (std::size_t i = 0; i < unlisted_tool_names_.size(); ++i) {
    if (same(unlisted_tool_names_[i], name)) return static_cast<int>(i + 1);
  }
  unlisted_tool_names_.push_back(name);
  int number = static_cast<int>(unlisted_tool_names_.size());
  comment("ncbridge: tool \"" + name + "\" has no tool list entry: numbered T" + std::to_string(number));
  return number;
}

Point3 DialectMachine::position() const {
  const canonical::Pose& p = executor_.state().position;
  return frame.from_executor({p.x, p.y, p.z});
}

void DialectMachine::put_axes(NeutralBlock& block, std::optional<double> x, std::optional<double> y,
                              std::optional<double> z, std::uint32_t column) const {
  if (!x && !y && !z) return;
  Point3 here = position();
  Point3 target{x.value_or(here.x), y.value_or(here.y), z.value_or(here.z)};
  Point3 e = frame.to_executor(target);
  if (x || y) {
    if (x || frame.rotation_deg != 0) block.add('x', e.x, column);
    if (y || frame.rotation_deg != 0) block.add('y', e.y, column);
  }
  if (z) block.add('z', e.z, column);
}

void DialectMachine::put_xy_arc(NeutralBlock& block, bool clockwise, std::optional<double> x, std::optional<double> y,
                                std::optional<double> z, double cx, double cy, std::uint32_t column) const {
  Point3 here = position();
  block.g(clockwise ? 2 : 3, column);
  Point3 target{x.value_or(here.x), y.value_or(here.y), z.value_or(here.z)};
  Point3 e = frame.to_executor(target);
  block.add('x', e.x, column);
  block.add('y', e.y, column);
  if (z) block.add('z', e.z, column);
  Point3 offset = frame.rotate({cx - here.x, cy - here.y, 0});
  block.add('i', offset.x, column);
  block.add('j', offset.y, column);
}

}  // namespace ncbridge::interpreter::lowering
