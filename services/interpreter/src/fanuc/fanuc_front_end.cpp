// Fanuc / Mach3 front-end: reads each block (word-address syntax and custom macro B), runs the
// macro statements and subprogram calls itself, and lowers every other block through the
// dialect table onto neutral RS274 blocks for the executor (lowering/dialect_machine.hpp).
#include "fanuc/fanuc_front_end.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>

#include "block_model.hpp"
#include "expression.hpp"
#include "fanuc/block_reader.hpp"
#include "fanuc/boring_cycles.hpp"
#include "lowering/dialect_machine.hpp"
#include "lowering/dialect_table.hpp"
#include "lowering/infix_expression.hpp"
#include "ncbridge/common/error.hpp"

namespace ncbridge::interpreter::fanuc {

using lowering::DialectMachine;
using lowering::DialectTable;
using lowering::ExpressionSyntax;
using lowering::InfixParser;
using lowering::NeutralBlock;
using lowering::Point3;
using lowering::ProgramText;

Flavour fanuc_flavour() { return Flavour{}; }

namespace {

constexpr std::size_t kMaxCallDepth = 32;

struct File {
  ProgramText text;
  std::map<long, std::size_t> programs;  // O number -> line index
};

// The number after a leading O or N of a line ("N120 G1 ..." -> 'N', 120), or letter 0.
std::pair<char, long> leading_number(std::string_view l) {
  std::size_t p = 0;
  while (p < l.size() && (l[p] == ' ' || l[p] == '\t')) ++p;
  if (p + 1 >= l.size()) return {0, 0};
  const char c = lowering::upper(l[p]);
  if ((c != 'O' && c != 'N') || !lowering::is_digit(l[p + 1])) return {0, 0};
  ++p;
  long number = 0;
  while (p < l.size() && lowering::is_digit(l[p]) && number < 100000000) number = number * 10 + (l[p++] - '0');
  return {c, number};
}

// Fanuc G65 argument specification I: address -> local variable.
int argument_variable(char letter) {
  switch (letter) {
    case 'a': return 1; case 'b': return 2; case 'c': return 3; case 'i': return 4; case 'j': return 5;
    case 'k': return 6; case 'd': return 7; case 'e': return 8; case 'f': return 9; case 'h': return 11;
    case 'm': return 13; case 'q': return 17; case 'r': return 18; case 's': return 19; case 't': return 20;
    case 'u': return 21; case 'v': return 22; case 'w': return 23; case 'x': return 24; case 'y': return 25;
    case 'z': return 26; default: return 0;
  }
}

struct Value {
  double v = 0;
  std::uint32_t column = 0;
  bool had_point = true;
  double raw = 0;  // before least-increment scaling (K is a dimension in arcs, a count in cycles)
};

class Runner {
 public:
  Runner(const Options& options, canonical::Sink& sink, const Flavour& flavour)
      : options_(options), flavour_(flavour), table_(lowering::load_dialect_table(flavour.table)),
        vacant_(Parameters::kCount, 0), m_(options, sink, table_), reader_(flavour) {
    vacant_[0] = 1;
    for (int i = 1; i <= 33; ++i) vacant_[static_cast<std::size_t>(i)] = 1;
    for (int i = 100; i <= 199; ++i) vacant_[static_cast<std::size_t>(i)] = 1;
    for (int i = 500; i <= 999; ++i) vacant_[static_cast<std::size_t>(i)] = 1;
    vacant_test_ = [this](int number) {
      return number >= 0 && static_cast<std::size_t>(number) < vacant_.size() && vacant_[static_cast<std::size_t>(number)] != 0;
    };
  }

  void run(ProgramText main);

 private:
  struct Call {
    std::size_t file, return_pc;
    std::size_t start_file, start_pc;
    int remaining;
    bool macro;
  };
  struct Loop {
    int id;
    std::size_t file, pc;  // the WHILE/DO line
  };

  std::size_t add_file(ProgramText text);
  bool step();  // false when the program ended
  bool run_statement();
  bool run_block();
  void jump_to_sequence(double n, std::uint32_t column, std::size_t in_file);
  void call_program(double number, int repeats, bool macro, std::uint32_t column);
  bool return_from_program(std::optional<double> sequence, std::uint32_t column);
  std::size_t find_program(long number, std::size_t& start, std::uint32_t column);
  double eval(ExprRef ref) {
    if (flavour_.macro_b) return evaluate(line_.block, ref, m_.parameters(), m_.file_name(), vacant_test_);
    return evaluate(line_.block, ref, m_.parameters(), m_.file_name());
  }
  bool vacant(ExprRef ref) {
    return flavour_.macro_b && vacant_reference(line_.block, ref, m_.parameters(), m_.file_name(), vacant_test_);
  }
  void assign(const Assignment& a);
  void set_variable(int number, double value, bool is_vacant);
  // G65: a new set of local variables #1-#33, all vacant but the arguments
  void push_locals();
  void pop_locals();
  // G10: work offsets (L2 P1-P6, L20 the additional G54.1 P1-P48) and tool offsets (L1, L10-L13)
  void data_setting(NeutralBlock& nb, std::map<char, Value>& w, std::uint32_t column);
  bool machine_function(double code, std::uint32_t column);
  double scaled(std::size_t word, double v) const;

  // lowering helpers
  std::optional<double> axis_target(char letter, const std::map<char, Value>& w, const Point3& here) const;
  void lower_motion(NeutralBlock& nb, const std::map<char, Value>& w);
  void copy_skip_position();
  void lower_cycle(NeutralBlock& nb, const std::map<char, Value>& w);
  void spell_boring(NeutralBlock& nb, Point3 hole, double dx, double dy, double r_abs, double z_abs, int repeats,
                    std::uint32_t col);

  const Options& options_;
  const Flavour& flavour_;
  DialectTable table_;
  // custom macro B: which numbered variables are vacant (#0 always; the locals, #100-#199 and
  // #500-#999 from the start: an offline reading knows no values the control kept)
  std::vector<char> vacant_;
  VacantTest vacant_test_;
  struct SavedLocals {
    std::array<char, 34> vacant{};
    std::array<double, 3> high{};  // #31-#33 (the parameter store keeps #1-#30 per call)
  };
  std::vector<SavedLocals> saved_locals_;
  std::map<int, Point3> extended_offsets_;  // G10 L20 Pn: G54.1 Pn, in mm
  // G10 L2 P0: the external work offset (EXOFS), in mm. Fanuc adds it to every work offset
  // (G54-G59, G54.1); the G54-G59 offsets handed on below hold the sum.
  Point3 external_offset_;
  bool rigid_tapping_ = false;              // M29 given: the next G84/G74 is rigid
  bool tool_changes_seen_ = false;          // an M6 was programmed (else tools are loaded by hand)
  DialectMachine m_;
  LineReader reader_;
  Line line_;
  std::vector<File> files_;
  std::size_t file_ = 0, pc_ = 0;
  std::vector<Call> calls_;
  std::vector<Loop> loops_;
  std::map<std::tuple<std::size_t, std::size_t, long>, std::size_t> goto_targets_;  // (file, from, N) -> line
  bool seen_content_ = false;
  std::uint64_t steps_ = 0;
  std::size_t last_index_ = 0;
  std::uint64_t backward_jumps_ = 0;
  std::uint64_t executed_blocks_ = 0;

  // modal state the executor does not keep
  bool incremental_ = false;
  bool polar_ = false;
  double polar_radius_ = 0, polar_angle_ = 0;
  bool arc_centre_absolute_ = false;
  int motion_ = 0;   // 0,1,2,3 or a cycle number (73..89); 80 = none
  int plane_ = 17;
  std::optional<double> cycle_r_, cycle_z_, cycle_q_, cycle_p_;
  std::optional<double> last_r_, last_q_;
  double initial_z_ = 0;
  Point3 local_offset_;  // G52
  std::uint32_t cycle_column_ = 0;  // column of this block's canned-cycle G code, 0 if none
};

std::size_t Runner::add_file(ProgramText text) {
  File f;
  f.text = std::move(text);
  for (std::size_t i = 0; i < f.text.size(); ++i) {
    const auto [letter, number] = leading_number(f.text.line(i));
    if (letter == 'O') f.programs.emplace(number, i);
  }
  files_.push_back(std::move(f));
  std::size_t index = files_.size() - 1;
  m_.announce_file(static_cast<std::uint32_t>(index), files_[index].text.name);
  return index;
}

void Runner::run(ProgramText main) {
  add_file(std::move(main));
  m_.at(0, files_[0].text.name, 0);
  m_.start();
  while (step()) {
  }
}

bool Runner::step() {
  File& f = files_[file_];
  if (pc_ >= f.text.size()) {
    m_.at(static_cast<std::uint32_t>(file_), f.text.name, static_cast<std::uint32_t>(f.text.size()));
    if (!calls_.empty()) m_.fail(1, "Subprogram ended without M99");
    if (options_.require_program_end) m_.fail(1, "File ended with no program end (M30/M2) or closing '%'");
    m_.warn(1, "File ended with no program end (M30/M2) or closing '%': the program ends here");
    return false;
  }
  if (++steps_ > 50'000'000) m_.fail(1, "Program runs too long (endless loop?)");
  std::size_t index = pc_++;
  // every jump back to an earlier block is a loop iteration; a program that loops a million
  // times is taken as an endless loop (LinuxCNC's rs274 would run forever)
  if (steps_ > 1 && index <= last_index_ && ++backward_jumps_ > options_.max_loop_iterations) {
    m_.fail(1, "Loop repeated more than " + std::to_string(options_.max_loop_iterations) + " times (endless loop?)");
  }
  last_index_ = index;
  try {
    reader_.read(f.text.line(index), static_cast<std::uint32_t>(index + 1), f.text.name, line_);
  } catch (const InputError&) {
    // A title line before the first block (FreeCAD's Fanuc post writes the file name there).
    if (executed_blocks_ != 0 || !title_line(f.text.line(index))) throw;
    m_.at(static_cast<std::uint32_t>(file_), f.text.name, static_cast<std::uint32_t>(index + 1));
    m_.comment("ncbridge: line " + std::to_string(index + 1) + " is not a block (a program title?): ignored");
    return true;
  }
  const Block& b = line_.block;
  m_.at(static_cast<std::uint32_t>(file_), f.text.name, static_cast<std::uint32_t>(index + 1), b.n_number, b.n_digits);
  if (b.percent) {
    if (!seen_content_) {
      seen_content_ = true;
      return true;
    }
    return calls_.empty() ? false : true;  // the closing '%' ends the tape
  }
  if (line_.program_number) {
    // Reaching the next program's O line in the main flow ends the main program's text.
    if (seen_content_ && calls_.empty() && file_ == 0 && index > 0 && !files_[0].programs.empty() &&
        files_[0].programs.begin()->second != index) {
      if (options_.require_program_end) m_.fail(1, "Main program ran into program O" + std::to_string(static_cast<long>(line_.o_number)) + " without M30/M2");
      return false;
    }
  }
  seen_content_ = true;
  if (b.statement.kind != StatementKind::None) return run_statement();
  return run_block();
}

void Runner::assign(const Assignment& a) {
  int number = parameter_number(line_.block, a.target, m_.parameters(), m_.file_name());
  const double value = eval(a.value);
  if (number == 3000) {
    std::string text = line_.block.comments.empty() ? std::string() : std::string(line_.block.comments.front().text);
    m_.fail(a.column, "Macro alarm " + std::to_string(static_cast<long>(value)) + (text.empty() ? "" : ": " + text));
  }
  // #2 = #1 copies a vacant #1; any arithmetic gives a value (a vacant variable reads 0)
  set_variable(number, value, vacant(a.value));
}

void Runner::set_variable(int number, double value, bool is_vacant) {
  m_.parameters().set_numbered(number, is_vacant ? 0.0 : value);
  if (number >= 0 && static_cast<std::size_t>(number) < vacant_.size()) vacant_[static_cast<std::size_t>(number)] = is_vacant;
}

void Runner::push_locals() {
  SavedLocals saved;
  for (int i = 1; i <= 33; ++i) saved.vacant[static_cast<std::size_t>(i)] = vacant_[static_cast<std::size_t>(i)];
  for (int i = 31; i <= 33; ++i) saved.high[static_cast<std::size_t>(i - 31)] = m_.parameters().numbered(i);
  saved_locals_.push_back(saved);
  m_.parameters().push_scope();
  for (int i = 1; i <= 33; ++i) set_variable(i, 0.0, true);
}

void Runner::pop_locals() {
  m_.parameters().pop_scope();
  if (saved_locals_.empty()) return;
  const SavedLocals& saved = saved_locals_.back();
  for (int i = 1; i <= 33; ++i) vacant_[static_cast<std::size_t>(i)] = saved.vacant[static_cast<std::size_t>(i)];
  for (int i = 31; i <= 33; ++i) m_.parameters().set_numbered(i, saved.high[static_cast<std::size_t>(i - 31)]);
  saved_locals_.pop_back();
}

bool Runner::run_statement() {
  const Statement& st = line_.block.statement;
  switch (st.kind) {
    case StatementKind::If: {
      bool taken = eval(st.condition) != 0.0;
      if (line_.then_form) {
        if (taken) {
          for (const Assignment& a : line_.block.assignments) assign(a);
        }
        return true;
      }
      if (taken) jump_to_sequence(eval(st.arguments.front()), st.column, file_);
      return true;
    }
    case StatementKind::Goto:
      jump_to_sequence(eval(st.arguments.front()), st.column, file_);
      return true;
    case StatementKind::While: {
      int id = static_cast<int>(st.label_number);
      std::size_t here = pc_ - 1;
      bool again = !loops_.empty() && loops_.back().id == id && loops_.back().pc == here && loops_.back().file == file_;
      if (eval(st.condition) != 0.0) {
        if (!again) loops_.push_back(Loop{id, file_, here});
        return true;
      }
      if (again) loops_.pop_back();
      // skip to the matching END
      const File& f = files_[file_];
      int depth = 0;
      Line scan;
      for (std::size_t i = pc_; i < f.text.size(); ++i) {
        reader_.read(f.text.line(i), static_cast<std::uint32_t>(i + 1), f.text.name, scan);
        StatementKind k = scan.block.statement.kind;
        if ((k == StatementKind::While || k == StatementKind::Do) && scan.block.statement.label_number == id) ++depth;
        if (k == StatementKind::EndWhile && scan.block.statement.label_number == id) {
          if (depth == 0) {
            pc_ = i + 1;
            return true;
          }
          --depth;
        }
      }
      m_.fail(st.column, "WHILE ... DO " + std::to_string(id) + " has no END " + std::to_string(id));
    }
    case StatementKind::Do: {
      int id = static_cast<int>(st.label_number);
      std::size_t here = pc_ - 1;
      if (loops_.empty() || loops_.back().pc != here || loops_.back().file != file_) loops_.push_back(Loop{id, file_, here});
      return true;
    }
    case StatementKind::EndWhile: {
      int id = static_cast<int>(st.label_number);
      if (loops_.empty() || loops_.back().id != id || loops_.back().file != file_) {
        m_.fail(st.column, "END " + std::to_string(id) + " without a matching DO " + std::to_string(id));
      }
      pc_ = loops_.back().pc;
      return true;
    }
    default:
      m_.fail(st.column, "Statement not supported in this dialect");
  }
}

void Runner::jump_to_sequence(double n, std::uint32_t column, std::size_t in_file) {
  long target = std::lround(n);
  const File& f = files_[in_file];
  // The search stays in the current program (from its O line to the next one): forward from
  // the current block, then from the program's start.
  std::size_t begin = 0, end = f.text.size();
  for (const auto& [number, line] : f.programs) {
    if (line < pc_ && line >= begin) begin = line;
  }
  for (const auto& [number, line] : f.programs) {
    if (line >= pc_ && line < end) end = line;
  }
  // The program is read as a stream: the search reads the lines (forward from here to the end
  // of the program, then from its start); a jump taken again (a loop) is remembered.
  const auto key = std::make_tuple(in_file, pc_, target);
  std::optional<std::size_t> best;
  if (auto hit = goto_targets_.find(key); hit != goto_targets_.end()) {
    best = hit->second;
  } else {
    auto search = [&](std::size_t from, std::size_t to) -> std::optional<std::size_t> {
      for (std::size_t i = from; i < to; ++i) {
        const auto [letter, number] = leading_number(f.text.line(i));
        if (letter == 'N' && number == target) return i;
      }
      return std::nullopt;
    };
    best = search(pc_, end);
    if (!best) best = search(begin, std::min(pc_, end));
    if (best && goto_targets_.size() < 4096) goto_targets_.emplace(key, *best);
  }
  if (!best) m_.fail(column, "GOTO " + std::to_string(target) + ": no block N" + std::to_string(target) + " in this program");
  // leaving loops whose range the jump leaves is what the controller does implicitly
  while (!loops_.empty() && loops_.back().file == in_file && *best < loops_.back().pc) loops_.pop_back();
  file_ = in_file;
  pc_ = *best;
}

std::size_t Runner::find_program(long number, std::size_t& start, std::uint32_t column) {
  for (std::size_t i : {file_, std::size_t{0}}) {
    auto it = files_[i].programs.find(number);
    if (it != files_[i].programs.end()) {
      start = it->second + 1;
      return i;
    }
  }
  for (std::size_t i = 1; i < files_.size(); ++i) {
    auto it = files_[i].programs.find(number);
    if (it != files_[i].programs.end()) {
      start = it->second + 1;
      return i;
    }
  }
  std::vector<std::filesystem::path> dirs = options_.subroutine_path;
  dirs.push_back(std::filesystem::path(files_[0].text.name).parent_path());
  char o4[16];
  std::snprintf(o4, sizeof o4, "O%04ld", number);
  std::vector<std::string> names;
  for (const std::string& stem : {std::string(o4), "O" + std::to_string(number), std::to_string(number)}) {
    for (const char* ext : {"", ".nc", ".NC", ".tap", ".txt"}) names.push_back(stem + ext);
  }
  for (const auto& dir : dirs) {
    for (const auto& name : names) {
      std::filesystem::path candidate = (dir.empty() ? std::filesystem::path(".") : dir) / name;
      std::error_code ec;
      if (!std::filesystem::is_regular_file(candidate, ec)) continue;
      std::size_t index = add_file(ProgramText::from_file(candidate));
      auto it = files_[index].programs.find(number);
      start = it == files_[index].programs.end() ? 0 : it->second + 1;
      return index;
    }
  }
  m_.fail(column, "Subprogram O" + std::to_string(number) + " not found (in this file or as a file named " +
                      std::string(o4) + " in the subroutine path)");
}

void Runner::call_program(double number, int repeats, bool macro, std::uint32_t column) {
  if (calls_.size() >= kMaxCallDepth) m_.fail(column, "Too many nested subprogram calls");
  if (repeats < 1) return;
  std::size_t start = 0;
  std::size_t file = find_program(std::lround(number), start, column);
  calls_.push_back(Call{file_, pc_, file, start, repeats - 1, macro});
  file_ = file;
  pc_ = start;
}

bool Runner::return_from_program(std::optional<double> sequence, std::uint32_t column) {
  if (calls_.empty()) {
    // M99 in a main program restarts it on the control; as a conversion, it ends the program.
    m_.comment("ncbridge: M99 in the main program ends it (a controller would restart it)");
    return false;
  }
  Call& c = calls_.back();
  if (c.remaining > 0) {
    --c.remaining;
    file_ = c.start_file;
    pc_ = c.start_pc;
    return true;
  }
  if (c.macro) pop_locals();
  file_ = c.file;
  pc_ = c.return_pc;
  calls_.pop_back();
  while (!loops_.empty() && loops_.back().file != file_) loops_.pop_back();
  if (sequence) jump_to_sequence(*sequence, column, file_);
  return true;
}

double Runner::scaled(std::size_t word, double v) const {
  if (!line_.literal[word] || line_.had_point[word]) return v;
  switch (line_.block.words[word].letter) {
    case 'x': case 'y': case 'z': case 'a': case 'b': case 'c': case 'u': case 'v': case 'w':
    case 'i': case 'j': case 'k': case 'r': case 'q': {
      double inc = m_.state().units == canonical::Units::Inches ? table_.setting("least_input_increment_inch", 0)
                                                               : table_.setting("least_input_increment_mm", 0);
      return inc > 0 ? v * inc : v;
    }
    default:
      return v;
  }
}

bool Runner::run_block() {
  const Block& b = line_.block;
  if (b.words.empty() && b.assignments.empty() && b.comments.empty()) return true;
  if (!b.words.empty()) ++executed_blocks_;
  for (const Assignment& a : b.assignments) assign(a);

  NeutralBlock nb;
  std::map<char, Value> w;
  std::vector<Value> gs, ms;
  std::vector<std::pair<char, Value>> in_order;  // G65's arguments, in the order written
  std::optional<Value> repeated_ijk;             // I, J or K again: only G65 (argument list II) takes it
  char repeated_letter = 0;
  for (std::size_t i = 0; i < b.words.size(); ++i) {
    const Word& word = b.words[i];
    if (vacant(word.value)) continue;  // an address with a vacant variable is not there
    double raw = eval(word.value);
    Value v{scaled(i, raw), word.column, line_.had_point[i], raw};
    if (word.letter == 'g') {
      gs.push_back(v);
    } else if (word.letter == 'm') {
      ms.push_back(v);
    } else {
      in_order.emplace_back(word.letter, v);
      if (w.count(word.letter)) {
        if (word.letter == 'i' || word.letter == 'j' || word.letter == 'k') {
          if (!repeated_ijk) {
            repeated_ijk = v;
            repeated_letter = word.letter;
          }
          continue;
        }
        m_.fail(word.column, std::string("Multiple ") + static_cast<char>(word.letter - 'a' + 'A') + " words on one line");
      }
      w[word.letter] = v;
    }
  }
  for (const auto& c : b.comments) {
    nb.comment = std::string(c.text);
    nb.has_comment = true;
  }

  // G codes through the dictionary
  cycle_column_ = 0;
  enum class Special { None, Dwell, Rotation, Local, Macro, DataSetting, Home, Machine, SetOrigin, Skip };
  Special special = Special::None;
  bool rotation_on = false;
  std::uint32_t cancel_column = 0;
  for (const Value& g : gs) {
    const lowering::CodeEntry* e = table_.g(g.v);
    if (e == nullptr) m_.fail(g.column, "G" + lowering::code_key(g.v) + " is not a " + table_.dialect + " G code ncbridge supports");
    const std::string& meta = e->meta;
    if (e->cycle) {
      cycle_column_ = g.column;
      bool was_cycle = motion_ == 73 || motion_ == 74 || motion_ == 76 || (motion_ >= 81 && motion_ <= 89);
      if (!was_cycle) initial_z_ = m_.position().z;  // the initial level G91 R is measured from
      motion_ = *e->cycle;
    } else if (meta == "rapid" || meta == "linear" || meta == "circular_cw" || meta == "circular_ccw") {
      motion_ = static_cast<int>(*e->rs274);
      cycle_r_.reset(); cycle_z_.reset(); cycle_q_.reset(); cycle_p_.reset();
    } else if (meta == "cycle_cancel") {
      motion_ = 80;
      rigid_tapping_ = false;
      cancel_column = g.column;
      cycle_r_.reset(); cycle_z_.reset(); cycle_q_.reset(); cycle_p_.reset();
    } else if (meta == "absolute") {
      incremental_ = false;
    } else if (meta == "incremental") {
      incremental_ = true;
    } else if (meta == "arc_centre_absolute") {
      arc_centre_absolute_ = true;
    } else if (meta == "arc_centre_incremental") {
      arc_centre_absolute_ = false;
    } else if (meta == "polar_on" || meta == "polar_off") {
      polar_ = meta == "polar_on";
      if (polar_) {
        Point3 here = m_.position();
        polar_radius_ = std::hypot(here.x, here.y);
        polar_angle_ = std::atan2(here.y, here.x) * 180.0 / std::numbers::pi;
      }
    } else if (meta == "rotation_on" || meta == "rotation_off") {
      special = Special::Rotation;
      rotation_on = meta == "rotation_on";
    } else if (meta == "dwell") {
      special = Special::Dwell;
    } else if (meta == "local_coordinate_system") {
      special = Special::Local;
    } else if (meta == "macro_call") {
      special = Special::Macro;
    } else if (meta == "data_setting") {
      special = Special::DataSetting;
    } else if (meta == "skip") {
      special = Special::Skip;
    } else if (meta == "additional_work_offset") {
      // G54.1 Pn: the additional work offset n (set by G10 L20 Pn), carried by coordinate
      // system 9 (G59.3), which no Fanuc program otherwise names
      if (!w.count('p')) m_.fail(g.column, "G54.1 needs P (the additional work offset, 1-48)");
      const long n = std::lround(w['p'].v);
      if (n < 1 || n > 48) m_.fail(w['p'].column, "G54.1 P must be 1-48");
      Point3 o = extended_offsets_[static_cast<int>(n)];
      o.x += external_offset_.x, o.y += external_offset_.y, o.z += external_offset_.z;
      const double k = m_.state().mm_per_unit();
      NeutralBlock load;
      load.g(10, g.column);
      load.add('l', 2, g.column);
      load.add('p', 9, g.column);
      load.add('x', o.x / k, g.column);
      load.add('y', o.y / k, g.column);
      load.add('z', o.z / k, g.column);
      m_.execute(load);
      m_.comment("ncbridge: G54.1 P" + std::to_string(n) + " (additional work offset) as coordinate system 9");
      w.erase('p');
      nb.g(59.3, g.column);
    } else if (meta == "exact_stop_block") {
      // G9: exact stop for this block; the canonical model has no per-block stop
    } else if (e->rs274) {
      if (meta == "plane_xy") plane_ = 17;
      if (meta == "plane_xz") plane_ = 18;
      if (meta == "plane_yz") plane_ = 19;
      if (meta == "reference_return") special = Special::Home;
      if (meta == "machine_coordinates") special = Special::Machine;
      if (meta == "set_work_coordinates") special = Special::SetOrigin;
      nb.g(*e->rs274, g.column);
    } else {
      m_.fail(g.column, "G" + lowering::code_key(g.v) + " (" + meta + ") is not supported yet");
    }
  }

  if (repeated_ijk && special != Special::Macro) {
    m_.fail(repeated_ijk->column, std::string("Multiple ") + static_cast<char>(repeated_letter - 'a' + 'A') + " words on one line");
  }
  // G80 with G0/G1 in the same block: the motion code cancels the cycle by itself
  if (cancel_column != 0 && motion_ == 80) nb.g(80, cancel_column);

  // M codes through the dictionary; subprogram calls run after the block
  std::optional<Value> call, ret;
  for (const Value& mv : ms) {
    const lowering::CodeEntry* e = table_.m(mv.v);
    if (e == nullptr) {
      if (m_.machine_function(mv.v, mv.column)) continue;
      m_.fail(mv.column, "M" + lowering::code_key(mv.v) + " is not a " + table_.dialect + " M code ncbridge supports");
    }
    if (e->meta == "rigid_tapping_mode") {
      // M29 S..: the next G84/G74 taps with the spindle synchronised to the feed; the tool
      // moves as in the cycle, so the reading is the same
      rigid_tapping_ = true;
      m_.comment("ncbridge: M29 rigid tapping mode for the next tapping cycle");
      continue;
    }
    if (e->meta == "subprogram_call") {
      call = mv;
    } else if (e->meta == "subprogram_return") {
      ret = mv;
    } else if (e->rs274) {
      nb.m(static_cast<int>(*e->rs274), mv.column);
      if (e->meta == "tool_change") tool_changes_seen_ = true;
    } else {
      m_.fail(mv.column, "M" + lowering::code_key(mv.v) + " (" + e->meta + ") is not supported yet");
    }
  }

  // words that pass through unchanged
  for (char letter : {'f', 's', 't', 'h', 'd'}) {
    if (special == Special::Macro) break;
    auto it = w.find(letter);
    if (it != w.end()) nb.add(letter, it->second.v, it->second.column);
  }

  // G65 takes any argument address; elsewhere an address nothing uses is an error, not ignored
  const std::string_view used = special == Special::Macro ? "abcdefhijklpqrstuvwxyz" : "abcdfhijklpqrstxyz";
  for (const auto& [letter, v] : w) {
    bool dwell_u = letter == 'u' && special == Special::Dwell;
    if (used.find(letter) == std::string_view::npos && !dwell_u) {
      m_.fail(v.column, std::string("Address ") + static_cast<char>(letter - 'a' + 'A') + " is not supported here");
    }
  }
  switch (special) {
    case Special::Dwell: {
      double seconds = 0;
      std::uint32_t col = gs.front().column;
      if (w.count('p')) {
        seconds = flavour_.dwell_p_in_ms && !w['p'].had_point ? w['p'].v / 1000.0 : w['p'].v;
      } else if (w.count('x')) {
        seconds = w['x'].v;
      } else if (w.count('u')) {
        seconds = w['u'].v;
      } else {
        m_.fail(col, "G4 needs a dwell time (P or X)");
      }
      nb.g(4, col);
      nb.add('p', seconds, col);
      break;
    }
    case Special::Rotation: {
      Point3 here = m_.position();
      if (rotation_on) {
        double cx = w.count('x') ? w['x'].v : here.x;
        double cy = w.count('y') ? w['y'].v : here.y;
        double angle = w.count('r') ? w['r'].v : 0.0;
        Point3 centre = m_.frame.to_executor({cx, cy, 0});
        Point3 base_offset = local_offset_;
        m_.frame.rotation_deg = (incremental_ ? m_.frame.rotation_deg : 0.0) + angle;
        // the centre stays where it is: offset = centre - R * (centre - base offset)
        lowering::Frame r{{0, 0, 0}, m_.frame.rotation_deg};
        Point3 rel{centre.x - base_offset.x, centre.y - base_offset.y, 0};
        Point3 rr = r.rotate(rel);
        m_.frame.offset = {centre.x - rr.x, centre.y - rr.y, base_offset.z};
      } else {
        m_.frame.rotation_deg = 0;
        m_.frame.offset = local_offset_;
      }
      break;
    }
    case Special::Local: {
      // G52: local coordinate system shift relative to the work system (absolute values)
      local_offset_ = {w.count('x') ? w['x'].v : 0.0, w.count('y') ? w['y'].v : 0.0, w.count('z') ? w['z'].v : 0.0};
      if (m_.frame.rotation_deg != 0) m_.fail(gs.front().column, "G52 while G68 rotation is active is not supported");
      m_.frame.offset = local_offset_;
      break;
    }
    case Special::DataSetting:
      data_setting(nb, w, gs.front().column);
      break;
    case Special::Machine:
    case Special::SetOrigin:
      for (char letter : {'x', 'y', 'z', 'a', 'b', 'c'}) {
        if (w.count(letter)) nb.add(letter, w[letter].v, w[letter].column);
      }
      if (special == Special::Machine) nb.g(motion_ == 1 ? 1 : 0, gs.front().column);
      break;
    case Special::Home: {
      Point3 here = m_.position();
      m_.put_axes(nb, axis_target('x', w, here), axis_target('y', w, here), axis_target('z', w, here), gs.front().column);
      break;
    }
    case Special::Skip: {
      // G31 (Fanuc skip function, Mach3 probe): a straight move that stops where the skip (probe)
      // signal comes, without an alarm when it does not: LinuxCNC's G38.3. One-shot: the motion
      // mode stays. The skip position is read as the end point (no machine here).
      const std::uint32_t col = gs.front().column;
      Point3 here = m_.position();
      const auto x = axis_target('x', w, here), y = axis_target('y', w, here), z = axis_target('z', w, here);
      if (!x && !y && !z) m_.fail(col, "G31 needs an X, Y or Z end point");
      if (w.count('p')) m_.fail(w.at('p').column, "not supported: multi-step skip (G31 P)");
      nb.g(38.3, col);
      m_.put_axes(nb, x, y, z, col);
      break;
    }
    case Special::Macro:
      break;
    case Special::None:
      lower_motion(nb, w);
      break;
  }

  // G41/G42 D (or H, on controls set so) name an offset number: the tool list's tool of that
  // number gives the radius. The control's offset table is not known offline: an offset number
  // the list does not have is read as radius 0 (the tool centre on the programmed contour), said
  // in a warning.
  for (auto& word : nb.words) {
    if (word.letter != 'g' || (word.value != 41 && word.value != 42) || !flavour_.macro_b) continue;
    const char letter = w.count('d') ? 'd' : w.count('h') ? 'h' : 0;
    if (letter == 0) break;
    const int offset = static_cast<int>(std::lround(w[letter].v));
    if (offset != 0 && options_.tools.find(offset) == nullptr) {
      m_.warn(w[letter].column, "G" + std::to_string(static_cast<int>(word.value)) + " " +
                                    std::string(1, static_cast<char>(letter - 'a' + 'A')) + std::to_string(offset) +
                                    ": offset " + std::to_string(offset) +
                                    " is not in the tool list, its radius is not known: radius 0 used (the tool "
                                    "centre on the programmed contour)");
      word.value += 0.1;  // G41.1/G42.1 D0
      nb.words.erase(std::remove_if(nb.words.begin(), nb.words.end(),
                                    [&](const lowering::NeutralWord& x) { return x.letter == letter; }),
                     nb.words.end());
      nb.add('d', 0.0, w[letter].column);
    } else if (letter == 'h') {
      for (auto& other : nb.words) {
        if (other.letter == 'h') other.letter = 'd';
      }
    }
    break;
  }

  // A program that changes no tool by M6 (the operator loads each tool at an M0, as the
  // program's comments say) names the tool by its length offset: G43 Hn takes tool n, when the
  // tool list has it, as the tool in the spindle (said in a warning).
  if (!tool_changes_seen_ && w.count('h') && nb.has('g')) {
    bool g43 = false;
    for (const auto& word : nb.words) g43 |= word.letter == 'g' && word.value == 43;
    const int h = static_cast<int>(std::lround(w['h'].v));
    if (g43 && h > 0 && h != m_.state().tool_in_spindle && options_.tools.find(h) != nullptr) {
      m_.warn(w['h'].column, "no tool change (M6) before G43 H" + std::to_string(h) + ": tool " + std::to_string(h) +
                                 " of the tool list taken as the tool loaded by hand");
      NeutralBlock load;
      load.m(61, w['h'].column);
      load.add('q', h, w['h'].column);
      m_.execute(load);
    }
  }

  bool ended = m_.execute(nb);
  if (ended) return false;
  if (special == Special::Skip) copy_skip_position();

  if (special == Special::Macro) {
    std::uint32_t col = gs.front().column;
    if (!w.count('p')) m_.fail(col, "G65 needs P (the macro's program number)");
    int repeats = w.count('l') ? static_cast<int>(std::lround(w['l'].v)) : 1;
    // argument specification I (A B C I J K D E F H M Q R S T U V W X Y Z) and II (A B C and up to
    // ten I J K sets: I1 J1 K1 -> #4-#6 ... I10 J10 K10 -> #31-#33); an I, J or K that does not
    // follow the previous one within its set starts the next set; a later argument for the same
    // variable wins, as on the control
    std::vector<std::pair<int, double>> args;
    int set = 0, last_in_set = -1;
    for (const auto& [letter, v] : in_order) {
      if (letter == 'p' || letter == 'l') continue;
      int var = argument_variable(letter);
      if (letter == 'i' || letter == 'j' || letter == 'k') {
        const int at = letter - 'i';
        if (set == 0 || at <= last_in_set) ++set;
        last_in_set = at;
        if (set > 10) m_.fail(v.column, "More than ten I J K argument sets in G65");
        var = 4 + 3 * (set - 1) + at;
      }
      if (var == 0) m_.fail(v.column, std::string("Address ") + static_cast<char>(letter - 'a' + 'A') + " cannot carry a G65 argument");
      args.emplace_back(var, v.v);
    }
    push_locals();
    for (const auto& [var, v] : args) set_variable(var, v, false);
    call_program(w['p'].v, 1, true, col);
    calls_.back().remaining = repeats - 1;
    return true;
  }
  if (call) {
    if (!w.count('p')) m_.fail(call->column, "M98 needs P (the subprogram number)");
    double p = w['p'].v;
    int repeats = w.count('l') ? static_cast<int>(std::lround(w['l'].v)) : 1;
    if (flavour_.packed_m98_count && !w.count('l') && p >= 10000) {
      repeats = static_cast<int>(p / 10000);
      p = std::fmod(p, 10000);
    }
    call_program(p, repeats, false, call->column);
    return true;
  }
  if (ret) {
    std::optional<double> sequence;
    if (w.count('p')) sequence = w['p'].v;
    return return_from_program(sequence, ret->column);
  }
  return true;
}

// The skip position: Fanuc keeps it in #5061.. as LinuxCNC does (the executor sets them); a
// dialect whose probe writes elsewhere names the first variable in its table (Mach3: #2000-#2005,
// X Y Z A B C).
void Runner::copy_skip_position() {
  const double first = table_.setting("probe_result_variable", 5061);
  if (first == 5061) return;
  for (int i = 0; i < 6; ++i) {
    m_.parameters().set_numbered(static_cast<int>(first) + i, m_.parameters().numbered(5061 + i));
  }
}

void Runner::data_setting(NeutralBlock& nb, std::map<char, Value>& w, std::uint32_t column) {
  if (!flavour_.macro_b) {
    // Mach: LinuxCNC's G10 (L1 tool table, L2/L20 coordinate systems)
    nb.g(10, column);
    for (char letter : {'l', 'p', 'x', 'y', 'z', 'a', 'b', 'c', 'r'}) {
      if (w.count(letter)) nb.add(letter, w[letter].v, w[letter].column);
    }
    return;
  }
  if (!w.count('l')) m_.fail(column, "G10 needs L (L2 work offset, L20 additional offset, L1/L10-L13 tool offset)");
  if (!w.count('p')) m_.fail(column, "G10 needs P");
  const long l = std::lround(w['l'].raw), p = std::lround(w['p'].raw);
  const std::uint32_t lc = w['l'].column, pc = w['p'].column;
  const double k = m_.state().mm_per_unit();
  if (l == 2) {
    // P1-P6: G54-G59; in G91 the values are added to the offset's present value
    // the parameter store holds offsets in inches (rs274's machine unit)
    auto present = [&](int system, int axis) {
      const double v = m_.parameters().numbered(5201 + 20 * system + axis);
      return axis < 3 ? v * 25.4 / k : v;
    };
    const char* axes = "xyzabc";
    if (p == 0) {
      // EXOFS: every work offset moves by its change (in G91 the values are added to it)
      for (char a : {'a', 'b', 'c'}) {
        if (w.count(a) && w[a].v != 0) m_.fail(w[a].column, "G10 L2 P0: an external work offset of a rotary axis is not supported");
      }
      Point3 next = external_offset_;
      double* coordinate[3] = {&next.x, &next.y, &next.z};
      for (int i = 0; i < 3; ++i) {
        if (w.count(axes[i])) *coordinate[i] = (incremental_ ? *coordinate[i] : 0.0) + w[axes[i]].v * k;
      }
      const double change[3] = {next.x - external_offset_.x, next.y - external_offset_.y, next.z - external_offset_.z};
      external_offset_ = next;
      if (change[0] == 0 && change[1] == 0 && change[2] == 0) return;
      for (int system = 1; system <= 6; ++system) {
        NeutralBlock shift;
        shift.g(10, column);
        shift.add('l', 2, lc);
        shift.add('p', static_cast<double>(system), pc);
        for (int i = 0; i < 3; ++i) {
          if (change[i] != 0) shift.add(axes[i], present(system, i) + change[i] / k, column);
        }
        m_.execute(shift);
      }
      return;
    }
    if (p < 1 || p > 6) m_.fail(pc, "G10 L2 P must be 0-6 (P1-P6: G54-G59)");
    nb.g(10, column);
    nb.add('l', 2, lc);
    nb.add('p', static_cast<double>(p), pc);
    const double external[3] = {external_offset_.x, external_offset_.y, external_offset_.z};
    for (int i = 0; i < 6; ++i) {
      const char a = axes[i];
      if (!w.count(a)) continue;
      double v = w[a].v;
      if (incremental_) {
        v += present(static_cast<int>(p), i);
      } else if (i < 3) {
        v += external[i] / k;  // the offset set, plus EXOFS
      }
      nb.add(a, v, w[a].column);
    }
    return;
  }
  if (l == 20) {
    if (p < 1 || p > 48) m_.fail(pc, "G10 L20 P must be 1-48 (the additional work offsets of G54.1)");
    Point3& o = extended_offsets_[static_cast<int>(p)];
    if (w.count('x')) o.x = (incremental_ ? o.x : 0.0) + w['x'].v * k;
    if (w.count('y')) o.y = (incremental_ ? o.y : 0.0) + w['y'].v * k;
    if (w.count('z')) o.z = (incremental_ ? o.z : 0.0) + w['z'].v * k;
    return;
  }
  if (l == 1 || l == 10 || l == 12) {
    // tool offset n: L1 (memory A) and L10 its length, L12 its radius (from R)
    if (!w.count('r')) m_.fail(column, "G10 L" + std::to_string(l) + " needs R (the offset value)");
    if (incremental_) m_.fail(w['r'].column, "G10 L" + std::to_string(l) + " in G91 (adding to a tool offset) is not supported");
    nb.g(10, column);
    nb.add('l', 1, lc);
    nb.add('p', static_cast<double>(p), pc);
    nb.add(l == 12 ? 'r' : 'z', w['r'].v, w['r'].column);
    return;
  }
  if (l == 11 || l == 13) {
    m_.warn(lc, "G10 L" + std::to_string(l) + " sets a tool " + (l == 11 ? "length" : "radius") +
                    " wear offset, which changes no tool-tip path: not applied");
    return;
  }
  m_.fail(lc, "G10 L" + std::to_string(l) + " is not supported (L2, L20, L1, L10-L13 are)");
}

std::optional<double> Runner::axis_target(char letter, const std::map<char, Value>& w, const Point3& here) const {
  auto it = w.find(letter);
  if (it == w.end()) return std::nullopt;
  double current = letter == 'x' ? here.x : letter == 'y' ? here.y : here.z;
  return incremental_ ? current + it->second.v : it->second.v;
}

void Runner::lower_motion(NeutralBlock& nb, const std::map<char, Value>& w) {
  bool axes = w.count('x') || w.count('y') || w.count('z') || w.count('a') || w.count('b') || w.count('c');
  bool is_cycle = motion_ == 73 || motion_ == 74 || motion_ == 76 || (motion_ >= 81 && motion_ <= 89);
  if (is_cycle) {
    if (axes || w.count('r')) lower_cycle(nb, w);
    return;
  }
  if (!axes && !(motion_ == 2 || motion_ == 3)) return;
  if ((motion_ == 2 || motion_ == 3) && !axes && !w.count('i') && !w.count('j') && !w.count('k')) return;
  if (motion_ == 80) m_.fail(w.begin()->second.column, "Axis words with no motion mode (G80 is active)");
  Point3 here = m_.position();
  std::optional<double> x = axis_target('x', w, here), y = axis_target('y', w, here), z = axis_target('z', w, here);
  std::uint32_t col = w.empty() ? 1 : w.begin()->second.column;
  if (polar_ && plane_ == 17 && (w.count('x') || w.count('y'))) {
    if (w.count('x')) polar_radius_ = incremental_ ? polar_radius_ + w.at('x').v : w.at('x').v;
    if (w.count('y')) polar_angle_ = incremental_ ? polar_angle_ + w.at('y').v : w.at('y').v;
    double a = polar_angle_ * std::numbers::pi / 180.0;
    x = polar_radius_ * std::cos(a);
    y = polar_radius_ * std::sin(a);
  }
  for (char letter : {'a', 'b', 'c'}) {
    auto it = w.find(letter);
    if (it == w.end()) continue;
    const canonical::Pose& p = m_.state().position;
    double current = letter == 'a' ? p.a : letter == 'b' ? p.b : p.c;
    nb.add(letter, incremental_ ? current + it->second.v : it->second.v, it->second.column);
  }
  if (motion_ == 0 || motion_ == 1) {
    nb.g(motion_, col);
    m_.put_axes(nb, x, y, z, col);
    return;
  }
  // arcs
  bool clockwise = motion_ == 2;
  if (plane_ == 17) {
    if (w.count('r')) {
      nb.g(motion_, col);
      m_.put_axes(nb, x, y, z, col);
      if (!nb.has('x') && !nb.has('y')) {
        Point3 e = m_.frame.to_executor({x.value_or(here.x), y.value_or(here.y), 0});
        nb.add('x', e.x, col);
        nb.add('y', e.y, col);
      }
      nb.add('r', w.at('r').v, w.at('r').column);
      return;
    }
    double i = w.count('i') ? w.at('i').v : 0.0, j = w.count('j') ? w.at('j').v : 0.0;
    double cx = arc_centre_absolute_ ? i : here.x + i;
    double cy = arc_centre_absolute_ ? j : here.y + j;
    m_.put_xy_arc(nb, clockwise, x, y, z, cx, cy, col);
    return;
  }
  if (m_.frame.rotation_deg != 0) m_.fail(col, "Arcs outside the XY plane under G68 rotation are not supported");
  nb.g(motion_, col);
  m_.put_axes(nb, x, y, z, col);
  for (char letter : {'i', 'j', 'k', 'r'}) {
    auto it = w.find(letter);
    if (it == w.end()) continue;
    double v = it->second.v;
    if (arc_centre_absolute_ && letter != 'r') {
      double current = letter == 'i' ? here.x : letter == 'j' ? here.y : here.z;
      v -= current;
    }
    nb.add(letter, v, it->second.column);
  }
}

void Runner::lower_cycle(NeutralBlock& nb, const std::map<char, Value>& w) {
  const std::string key = std::to_string(motion_);
  auto roles_it = table_.cycle_words.find(key);
  // errors name the cycle's G code, or the block's first position word when the cycle is modal
  std::uint32_t col = cycle_column_;
  for (char letter : {'x', 'y', 'z', 'r'}) {
    if (col == 0 && w.count(letter)) col = w.at(letter).column;
  }
  if (col == 0) col = w.begin()->second.column;
  if (roles_it == table_.cycle_words.end()) m_.fail(col, "G" + key + " is not a canned cycle of " + table_.dialect);
  const auto& roles = roles_it->second;
  int repeats = 1;
  std::optional<double> dwell;
  for (const auto& [letter, v] : w) {
    auto r = roles.find(std::string(1, static_cast<char>(letter - 'a' + 'A')));
    if (r == roles.end()) continue;
    const std::string& role = r->second;
    if (role == "retract_plane") cycle_r_ = last_r_ = v.v;
    else if (role == "bottom") cycle_z_ = v.v;
    else if (role == "peck" || role == "shift") cycle_q_ = last_q_ = v.v;
    else if (role == "repeat") repeats = v.raw > 2e9 ? 2'000'000'000 : v.raw < -2e9 ? -1 : static_cast<int>(std::lround(v.raw));
    else if (role == "dwell") {
      if (v.had_point) {
        m_.comment("ncbridge: P" + std::to_string(v.v) + " has a decimal point: read as seconds (Fanuc takes P in ms)");
        dwell = v.v;
      } else {
        dwell = v.v / 1000.0;
      }
      cycle_p_ = dwell;
    } else if (role == "dwell_seconds") {
      dwell = cycle_p_ = v.v;
    }
  }
  const std::string g = "G" + key;
  if (!cycle_r_) {
    if (!last_r_) m_.fail(col, g + " needs R (the R point)");
    m_.comment("ncbridge: " + g + " without R: the previous cycle's R point is used");
    cycle_r_ = last_r_;
  }
  if (!cycle_z_) m_.fail(col, g + " needs Z (the hole bottom)");
  bool needs_q = motion_ == 73 || motion_ == 83;
  if (needs_q && !cycle_q_) {
    if (!last_q_) m_.fail(col, g + " needs Q (the peck depth)");
    m_.comment("ncbridge: " + g + " without Q: the previous cycle's peck depth is used");
    cycle_q_ = last_q_;
  }
  if (repeats < 0) m_.fail(w.count('k') ? w.at('k').column : col, "Negative repeat count");
  if (static_cast<std::uint64_t>(repeats) > options_.max_loop_iterations) {
    m_.fail(w.count('k') ? w.at('k').column : w.at('l').column,
            "K asks for more repeats than the iteration limit (" + std::to_string(options_.max_loop_iterations) + ")");
  }
  if (repeats == 0) return;  // K0: store the cycle data, drill nothing

  Point3 here = m_.position();
  double r_abs = incremental_ ? initial_z_ + *cycle_r_ : *cycle_r_;
  double z_abs = incremental_ ? r_abs + *cycle_z_ : *cycle_z_;
  double dx = 0, dy = 0;
  Point3 hole = here;
  if (incremental_) {
    dx = w.count('x') ? w.at('x').v : 0.0;
    dy = w.count('y') ? w.at('y').v : 0.0;
  } else {
    if (w.count('x')) hole.x = w.at('x').v;
    if (w.count('y')) hole.y = w.at('y').v;
  }
  if (polar_ && (w.count('x') || w.count('y'))) {
    if (w.count('x')) polar_radius_ = w.at('x').v;
    if (w.count('y')) polar_angle_ = w.at('y').v;
    double a = polar_angle_ * std::numbers::pi / 180.0;
    hole.x = polar_radius_ * std::cos(a);
    hole.y = polar_radius_ * std::sin(a);
    dx = dy = 0;
  }
  if (motion_ == 76 || motion_ == 87) {
    spell_boring(nb, hole, dx, dy, r_abs, z_abs, repeats, col);
    return;
  }
  for (int k = 0; k < repeats; ++k) {
    if (k > 0) nb.clear();
    hole.x += dx;
    hole.y += dy;
    Point3 e = m_.frame.to_executor({hole.x, hole.y, 0});
    nb.g(motion_, col);
    nb.add('x', e.x, col);
    nb.add('y', e.y, col);
    nb.add('z', z_abs + m_.frame.offset.z, col);
    nb.add('r', r_abs + m_.frame.offset.z, col);
    if (needs_q) nb.add('q', *cycle_q_, col);
    bool needs_p = motion_ == 82 || motion_ == 86 || motion_ == 88 || motion_ == 89;
    if (needs_p || ((motion_ == 84 || motion_ == 74) && cycle_p_)) nb.add('p', cycle_p_.value_or(0.0), col);
    if (k + 1 < repeats) {
      if (m_.execute(nb)) return;
    }
  }
}

void Runner::spell_boring(NeutralBlock& nb, Point3 hole, double dx, double dy, double r_abs, double z_abs,
                          int repeats, std::uint32_t col) {
  // the block's other words (F, S, G98/G99, ...) first, then the holes as plain blocks
  m_.execute(nb);
  nb.clear();
  if (plane_ != 17) m_.fail(col, "G" + std::to_string(motion_) + " outside the XY plane (G17) is not supported");
  if (!cycle_q_) m_.comment("ncbridge: G" + std::to_string(motion_) + " without Q: no shift at the bottom");
  const double q = std::fabs(cycle_q_.value_or(0.0));
  // parameter 5101 RD2 RD1: 0 = +X, 1 = -X, 2 = +Y, 3 = -Y, in machine axes (not rotated)
  const int direction = static_cast<int>(table_.setting("boring_shift_direction", 0));
  BoringHole h;
  h.shift_x = direction == 0 ? q : direction == 1 ? -q : 0.0;
  h.shift_y = direction == 2 ? q : direction == 3 ? -q : 0.0;
  h.q = q;
  h.initial = initial_z_ + m_.frame.offset.z;
  h.r = r_abs + m_.frame.offset.z;
  h.z = z_abs + m_.frame.offset.z;
  h.dwell = cycle_p_.value_or(0.0);
  h.repeat = repeats;
  for (int k = 0; k < repeats; ++k) {
    hole.x += dx;
    hole.y += dy;
    const Point3 e = m_.frame.to_executor({hole.x, hole.y, 0});
    h.x = e.x;
    h.y = e.y;
    if (motion_ == 76) fine_boring(m_, h, col); else back_boring(m_, h, col);
  }
}

}  // namespace

void run(ProgramText program, const Options& options, canonical::Sink& sink, const Flavour& flavour) {
  Runner runner(options, sink, flavour);
  runner.run(std::move(program));
}

}  // namespace ncbridge::interpreter::fanuc
