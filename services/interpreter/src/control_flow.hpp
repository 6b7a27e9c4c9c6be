#pragma once
// The generic control-flow runner: reads blocks through a dialect front-end, runs the control
// statements of the neutral block model (subroutines, calls and returns, loops, conditionals)
// over the parameter store, and hands every other block, evaluated, to the executor.
//
// Like LinuxCNC, it never holds the program in memory: loops and calls seek back to remembered
// line offsets, forward jumps read ahead looking only at control statements, and subroutine
// files are opened when called.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "block_command.hpp"
#include "block_model.hpp"
#include "executor.hpp"
#include "ncbridge/interpreter/interpreter.hpp"
#include "parameters.hpp"
#include "text_source.hpp"

namespace ncbridge::interpreter {

class ControlFlowRunner {
 public:
  ControlFlowRunner(const Options& options, canonical::Sink& sink);

  // Runs a whole program; `source` is the main file's text, `name` its name for messages.
  void run(std::unique_ptr<TextSource> source, const std::string& name);

 private:
  struct File {
    std::string name;
    std::unique_ptr<TextSource> source;
  };
  struct Frame {
    std::uint32_t return_file;
    std::uint64_t return_offset;
    std::uint32_t return_line;
    std::size_t loop_base;
  };
  struct Loop {
    std::string label;
    StatementKind kind;
    std::uint32_t file;
    std::uint64_t offset, after_offset;  // of the loop's opening line
    std::uint32_t line;                  // its line number
    std::int64_t remaining;
    std::uint32_t column = 1;            // of its statement, for errors
  };
  struct SubDefinition {
    std::uint32_t file;
    std::uint64_t after_offset;
    std::uint32_t line;
  };

  bool read_line(bool control_only);
  void seek(std::uint32_t file, std::uint64_t offset, std::uint32_t line_before);
  std::string label_of(const Block& block) const;
  bool skip_to(const std::string& label, std::uint32_t kinds);
  [[noreturn]] void fail(std::uint32_t column, const std::string& message) const;
  double eval(ExprRef ref) const;

  // returns true when the program ended
  bool run_block();
  bool run_statement();
  void count_iteration(Loop& loop);
  void call(const std::string& label);
  void do_return();
  void finish_after_end();
  void run_active_comment();
  std::uint32_t open_file(const std::filesystem::path& path);
  const std::string& file_name() const { return files_[current_file_].name; }

  const Options& options_;
  canonical::Sink& sink_;
  Parameters params_;
  Executor executor_;
  std::vector<File> files_;
  std::uint32_t current_file_ = 0;
  std::uint32_t line_ = 0;              // line number of the block just read
  std::uint64_t line_offset_ = 0;       // its byte offset
  std::uint64_t next_offset_ = 0;       // offset of the line after it
  Block block_;
  BlockCommand command_;
  std::vector<double> values_;
  std::vector<std::pair<ExprRef, double>> assignment_values_;
  std::string message_text_;
  std::vector<Frame> frames_;
  std::vector<Loop> loops_;
  std::unordered_map<std::string, SubDefinition> subs_;
  std::filesystem::path main_directory_;
  std::uint32_t call_column_ = 1;
  std::uint64_t iterations_ = 0;  // loop iterations and calls so far (Options::max_loop_iterations)
  bool percent_mode_ = false;
  bool seen_content_ = false;
};

}  // namespace ncbridge::interpreter
