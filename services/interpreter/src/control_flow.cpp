#include "control_flow.hpp"

#include <cmath>
#include <cstdio>

#include "active_comments.hpp"
#include "expression.hpp"
#include "ncbridge/common/error.hpp"
#include "rs274ngc/reader.hpp"

namespace ncbridge::interpreter {

using namespace canonical;

namespace {
constexpr std::uint32_t bit(StatementKind k) { return 1u << static_cast<unsigned>(k); }
constexpr int kMaxCallDepth = 200;
}  // namespace

ControlFlowRunner::ControlFlowRunner(const Options& options, Sink& sink)
    : options_(options), sink_(sink), executor_(options, params_, sink) {
  params_.set_computed(&executor_);
}

// Every error names a line and a column: before the first line (an empty file) it is line 1.
void ControlFlowRunner::fail(std::uint32_t column, const std::string& message) const {
  throw InputError({file_name(), line_ == 0 ? 1 : line_, column == 0 ? 1 : column}, message);
}

double ControlFlowRunner::eval(ExprRef ref) const { return evaluate(block_, ref, params_, file_name()); }

std::uint32_t ControlFlowRunner::open_file(const std::filesystem::path& path) {
  for (std::uint32_t i = 0; i < files_.size(); ++i) {
    if (files_[i].name == path.string()) {
      if (!files_[i].source) files_[i].source = open_text_file(path);
      return i;
    }
  }
  auto source = open_text_file(path);
  if (!source) return UINT32_MAX;
  files_.push_back(File{path.string(), std::move(source)});
  auto index = static_cast<std::uint32_t>(files_.size() - 1);
  sink_.source_file(index, files_.back().name);
  return index;
}

bool ControlFlowRunner::read_line(bool control_only) {
  TextSource& src = *files_[current_file_].source;
  line_offset_ = src.tell();
  std::string_view text;
  if (!src.next_line(text)) return false;
  next_offset_ = src.tell();
  ++line_;
  rs274ngc::read_block(text, line_, file_name(), block_, control_only);
  return true;
}

void ControlFlowRunner::seek(std::uint32_t file, std::uint64_t offset, std::uint32_t line_before) {
  current_file_ = file;
  if (!files_[file].source) {
    files_[file].source = open_text_file(files_[file].name);
    if (!files_[file].source) fail(call_column_, "Unable to reopen file " + files_[file].name);
  }
  files_[file].source->seek(offset);
  line_ = line_before;
}

std::string ControlFlowRunner::label_of(const Block& block) const {
  if (block.statement.label_is_name) return std::string(block.label());
  return std::to_string(std::llround(block.statement.label_number));
}

bool ControlFlowRunner::skip_to(const std::string& label, std::uint32_t kinds) {
  while (read_line(true)) {
    if (block_.statement.kind == StatementKind::None) continue;
    if ((bit(block_.statement.kind) & kinds) == 0) continue;
    if (label_of(block_) == label) return true;
  }
  return false;
}

void ControlFlowRunner::run(std::unique_ptr<TextSource> source, const std::string& name) {
  files_.push_back(File{name, std::move(source)});
  sink_.source_file(0, name);
  main_directory_ = std::filesystem::path(name).parent_path();
  executor_.set_source(Source{0, 0, -1, 0});
  executor_.start();
  for (;;) {
    if (!read_line(false)) {
      executor_.end_of_file();
      if (!frames_.empty()) fail(1, "File ended inside subroutine (missing endsub)");
      if (options_.require_program_end || options_.strict) fail(1, "File ended with no percent sign or program end");
      if (options_.warning) {
        options_.warning({file_name(), line_ == 0 ? 1 : line_, 1}, "File ended with no percent sign or program end: the program ends "
                                                  "here, as LinuxCNC ends it after running every block");
      }
      return;
    }
    if (run_block()) return;
  }
}

bool ControlFlowRunner::run_block() {
  if (block_.percent) {
    if (!seen_content_ && current_file_ == 0) {
      percent_mode_ = true;
      seen_content_ = true;
      return false;
    }
    if (percent_mode_ && current_file_ == 0) {
      executor_.end_of_file();
      executor_.set_source(Source{current_file_, line_, -1, 0});
      executor_.emit(Finish{});
      return true;
    }
    return false;
  }
  if (block_.words.empty() && block_.assignments.empty() && block_.comments.empty() &&
      block_.statement.kind == StatementKind::None) {
    return false;
  }
  seen_content_ = true;
  Source source{current_file_, line_, block_.n_number, block_.n_digits};
  executor_.set_source(source);
  if (block_.statement.kind != StatementKind::None) return run_statement();

  // Evaluate every word and assignment with the parameters as they were before the line.
  values_.resize(block_.words.size());
  for (std::size_t i = 0; i < block_.words.size(); ++i) values_[i] = eval(block_.words[i].value);
  assignment_values_.clear();
  for (const Assignment& a : block_.assignments) assignment_values_.emplace_back(a.target, eval(a.value));
  for (const auto& [target, value] : assignment_values_) {
    const ExprNode& node = block_.nodes[target];
    if (node.op == ExprOp::NamedParameter) {
      params_.set_named(block_.name(node.name_begin, node.name_length), value);
    } else {
      params_.set_numbered(parameter_number(block_, target, params_, file_name()), value);
    }
  }
  assemble_command(block_, values_.data(), file_name(), command_);

  if (!command_.comment.empty() && !command_.comment_is_message) run_active_comment();
  if (executor_.execute(command_, source, file_name())) {
    finish_after_end();
    return true;
  }
  return false;
}

// LinuxCNC's active comments: DEBUG (a MESSAGE while #5599 > 0), PRINT, LOG, LOGOPEN,
// LOGAPPEND, LOGCLOSE, ABORT (an error with the text).
void ControlFlowRunner::run_active_comment() {
  using Action = BlockCommand::CommentAction;
  std::string_view rest;
  const ActiveComment kind = classify_comment(command_.comment, rest);
  switch (kind) {
    case ActiveComment::None:
      return;
    case ActiveComment::LogOpen:
    case ActiveComment::LogAppend:
      command_.comment = rest;  // the file name as written
      command_.comment_action = kind == ActiveComment::LogOpen ? Action::LogOpen : Action::LogAppend;
      return;
    case ActiveComment::LogClose:
      command_.comment_action = Action::LogClose;
      return;
    default:
      break;
  }
  message_text_ = expand_comment_parameters(rest, params_);
  command_.comment = message_text_;
  switch (kind) {
    case ActiveComment::Debug:
      if (params_.numbered(5599) > 0.0) {
        command_.comment_is_message = true;
      } else {
        command_.comment_action = Action::Nothing;
      }
      return;
    case ActiveComment::Print: command_.comment_action = Action::Print; return;
    case ActiveComment::Log: command_.comment_action = Action::Log; return;
    case ActiveComment::Abort: {
      std::uint32_t column = 1;
      for (const auto& c : block_.comments) {
        if (c.kind == CommentText::Kind::Plain) column = c.column;
      }
      std::string_view text = message_text_;
      while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
      fail(column, text.empty() ? std::string("(ABORT) in the program") : std::string(text));
    }
    default:
      return;
  }
}

void ControlFlowRunner::finish_after_end() {
  if (!percent_mode_) return;
  // LinuxCNC looks for the closing percent sign after M2/M30.
  TextSource& src = *files_[current_file_].source;
  std::string_view text;
  while (src.next_line(text)) {
    std::size_t i = 0;
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    if (i < text.size() && text[i] == '%') return;
  }
  executor_.emit(Comment{"interpreter: percent sign missing from end of file"});
}

bool ControlFlowRunner::run_statement() {
  const Statement& st = block_.statement;
  const std::string label = label_of(block_);
  const std::uint32_t col = st.column;
  switch (st.kind) {
    case StatementKind::Sub: {
      if (subs_.count(label) != 0) fail(col, "Redefining sub o" + label);
      subs_[label] = SubDefinition{current_file_, next_offset_, line_};
      if (!skip_to(label, bit(StatementKind::EndSub))) fail(col, "Subroutine o" + label + " has no endsub");
      return false;
    }
    case StatementKind::EndSub:
    case StatementKind::Return: {
      if (frames_.empty()) fail(col, "Not in a subroutine definition: o" + label);
      if (st.condition != kNoExpr) {
        params_.set_named("_value", eval(st.condition));
        params_.set_named("_value_returned", 1.0);
      }
      do_return();
      return false;
    }
    case StatementKind::Call: {
      std::vector<double> args;
      args.reserve(st.arguments.size());
      for (ExprRef a : st.arguments) args.push_back(eval(a));
      if (args.size() > static_cast<std::size_t>(Parameters::kLocalCount)) fail(col, "Too many arguments in call");
      if (frames_.size() >= kMaxCallDepth) fail(col, "Too many nested subroutine calls");
      if (++iterations_ >= options_.max_loop_iterations) {
        fail(col, "Subroutine o" + label + " not called: the program's loops and calls ran " +
                      std::to_string(iterations_) + " times, the iteration limit (endless recursion?)");
      }
      frames_.push_back(Frame{current_file_, next_offset_, line_, loops_.size()});
      executor_.enter_call();
      params_.push_scope();
      for (int i = 1; i <= Parameters::kLocalCount; ++i) {
        params_.set_numbered(i, static_cast<std::size_t>(i) <= args.size() ? args[static_cast<std::size_t>(i - 1)] : 0.0);
      }
      params_.set_named("_value", 0.0);
      params_.set_named("_value_returned", 0.0);
      call_column_ = col;
      call(label);
      return false;
    }
    case StatementKind::If: {
      bool taken = eval(st.condition) != 0.0;
      while (!taken) {
        if (!skip_to(label, bit(StatementKind::ElseIf) | bit(StatementKind::Else) | bit(StatementKind::EndIf))) {
          fail(col, "No matching endif for o" + label + " if");
        }
        StatementKind k = block_.statement.kind;
        if (k == StatementKind::ElseIf) {
          taken = eval(block_.statement.condition) != 0.0;
        } else {
          break;  // else: run its branch; endif: done
        }
      }
      return false;
    }
    case StatementKind::ElseIf:
    case StatementKind::Else:
      // reached by running the branch before it: jump to the endif
      if (!skip_to(label, bit(StatementKind::EndIf))) fail(col, "No matching endif for o" + label);
      return false;
    case StatementKind::EndIf:
      return false;
    case StatementKind::Do: {
      if (loops_.empty() || loops_.back().label != label || loops_.back().offset != line_offset_) {
        loops_.push_back(Loop{label, StatementKind::Do, current_file_, line_offset_, next_offset_, line_, 0, col});
      }
      return false;
    }
    case StatementKind::While: {
      bool top_is_this = !loops_.empty() && loops_.back().label == label;
      if (top_is_this && loops_.back().kind == StatementKind::Do) {
        // the end of a do-while loop
        if (eval(st.condition) != 0.0) {
          count_iteration(loops_.back());
          const Loop& l = loops_.back();
          seek(l.file, l.after_offset, l.line);
        } else {
          loops_.pop_back();
        }
        return false;
      }
      bool again = top_is_this && loops_.back().offset == line_offset_ && loops_.back().file == current_file_;
      if (eval(st.condition) != 0.0) {
        if (again) {
          count_iteration(loops_.back());
        } else {
          loops_.push_back(Loop{label, StatementKind::While, current_file_, line_offset_, next_offset_, line_, 0, col});
        }
      } else {
        if (again) loops_.pop_back();
        if (!skip_to(label, bit(StatementKind::EndWhile))) fail(col, "No matching endwhile for o" + label + " while");
      }
      return false;
    }
    case StatementKind::EndWhile: {
      if (loops_.empty() || loops_.back().label != label || loops_.back().kind != StatementKind::While) {
        fail(col, "endwhile without a matching while for o" + label);
      }
      const Loop& l = loops_.back();
      seek(l.file, l.offset, l.line - 1);
      return false;
    }
    case StatementKind::Repeat: {
      const double times = eval(st.condition);
      if (times >= 0.5) {
        const auto count = times < 9e18 ? std::llround(times) : std::int64_t{9'000'000'000'000'000'000};
        loops_.push_back(Loop{label, StatementKind::Repeat, current_file_, line_offset_, next_offset_, line_, count, col});
      } else if (!skip_to(label, bit(StatementKind::EndRepeat))) {
        fail(col, "No matching endrepeat for o" + label + " repeat");
      }
      return false;
    }
    case StatementKind::EndRepeat: {
      if (loops_.empty() || loops_.back().label != label || loops_.back().kind != StatementKind::Repeat) {
        fail(col, "endrepeat without a matching repeat for o" + label);
      }
      Loop& l = loops_.back();
      if (--l.remaining > 0) {
        count_iteration(l);
        seek(l.file, l.after_offset, l.line);
      } else {
        loops_.pop_back();
      }
      return false;
    }
    case StatementKind::Break:
    case StatementKind::Continue: {
      if (loops_.empty() || loops_.back().label != label) fail(col, "break/continue outside loop o" + label);
      Loop l = loops_.back();
      bool brk = st.kind == StatementKind::Break;
      if (l.kind == StatementKind::While) {
        if (brk) {
          loops_.pop_back();
          if (!skip_to(label, bit(StatementKind::EndWhile))) fail(col, "No matching endwhile for o" + label);
        } else {
          seek(l.file, l.offset, l.line - 1);
        }
      } else if (l.kind == StatementKind::Do) {
        if (!skip_to(label, bit(StatementKind::While))) fail(col, "No matching while for o" + label + " do");
        if (brk) {
          loops_.pop_back();
        } else {
          return run_statement();  // evaluate the do-while condition
        }
      } else {
        if (!skip_to(label, bit(StatementKind::EndRepeat))) fail(col, "No matching endrepeat for o" + label);
        if (brk) {
          loops_.pop_back();
        } else {
          return run_statement();
        }
      }
      return false;
    }
    default:
      fail(col, "This control statement is not supported in RS274/NGC");
  }
}

// Endless loops (and endless recursion that stays within the call depth) stop with an error
// at the loop's opening line.
void ControlFlowRunner::count_iteration(Loop& loop) {
  if (++iterations_ < options_.max_loop_iterations) return;
  throw InputError({files_[loop.file].name, loop.line, loop.column},
                   "Loop o" + loop.label + " stopped: the program's loops ran " + std::to_string(iterations_) +
                       " times, the iteration limit (an endless loop?)");
}

void ControlFlowRunner::call(const std::string& label) {
  auto it = subs_.find(label);
  if (it != subs_.end()) {
    seek(it->second.file, it->second.after_offset, it->second.line);
    return;
  }
  // A file named for the subroutine, in the subroutine path or beside the main program.
  std::vector<std::filesystem::path> dirs = options_.subroutine_path;
  dirs.push_back(main_directory_.empty() ? std::filesystem::path(".") : main_directory_);
  for (const auto& dir : dirs) {
    std::filesystem::path candidate = dir / (label + ".ngc");
    std::error_code ec;
    if (!std::filesystem::is_regular_file(candidate, ec)) continue;
    std::uint32_t index = open_file(candidate);
    if (index == UINT32_MAX) continue;
    std::uint32_t caller_line = line_;
    std::uint32_t caller_file = current_file_;
    seek(index, 0, 0);
    if (!skip_to(label, bit(StatementKind::Sub))) {
      current_file_ = caller_file;
      line_ = caller_line;
      fail(call_column_, "Subroutine file " + candidate.string() + " does not define o<" + label + "> sub");
    }
    subs_[label] = SubDefinition{current_file_, next_offset_, line_};
    return;
  }
  // Defined further down in this file: read ahead to it.
  std::uint32_t caller_line = line_;
  if (!skip_to(label, bit(StatementKind::Sub))) {
    line_ = caller_line;
    throw InputError({file_name(), caller_line, call_column_}, "Unable to find subroutine o" + label);
  }
  subs_[label] = SubDefinition{current_file_, next_offset_, line_};
}

void ControlFlowRunner::do_return() {
  Frame f = frames_.back();
  frames_.pop_back();
  executor_.leave_call();
  loops_.resize(f.loop_base);
  params_.pop_scope();
  seek(f.return_file, f.return_offset, f.return_line);
}

}  // namespace ncbridge::interpreter
