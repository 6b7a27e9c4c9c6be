// Heidenhain conversational: one block at a time, read into a small word list, evaluated, then
// lowered. Corner rounding (RND) and chamfers (CHF) look one path block ahead, as the control
// does, to shorten the element before the corner.
#include "heidenhain/heidenhain_front_end.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <optional>
#include <set>

#include "block_model.hpp"
#include "expression.hpp"
#include "heidenhain/block_reader.hpp"
#include "heidenhain/corner_rounding.hpp"
#include "heidenhain/pocket_cycles.hpp"
#include "heidenhain/sl_cycles.hpp"
#include "lowering/dialect_machine.hpp"
#include "lowering/dialect_table.hpp"
#include "lowering/infix_expression.hpp"
#include "ncbridge/common/error.hpp"

namespace ncbridge::interpreter::heidenhain {

using lowering::DialectMachine;
using lowering::InfixParser;
using lowering::NeutralBlock;
using lowering::Point3;
using lowering::ProgramText;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct CornerPlan {
  bool active = false;
  bool chamfer = false;
  Point3 t1, t2, centre;
  bool ccw = false;
};

class Runner {
 public:
  Runner(const Options& options, canonical::Sink& sink)
      : options_(options), table_(lowering::load_dialect_table("heidenhain")), m_(options, sink, table_) {}
  void run(ProgramText program);

 private:
  struct Call {
    std::size_t return_pc;
    std::size_t start_pc;
    int remaining;
  };
  bool step();
  // Reads the block that starts at line `index` (and the lines a `~` continues it onto) into
  // `b`; returns the number of lines it spans.
  std::size_t read_block(std::size_t index, HBlock& b);
  double eval(const HBlock& b, ExprRef ref) {
    if (ref == kNoExpr) m_.fail(b.column, "A word of this block has no value");
    return evaluate(b.exprs, ref, m_.parameters(), m_.file_name());
  }
  double eval(const HBlock& b, const HWord& w) {
    if (w.value == kNoExpr) m_.fail(w.column, (w.name.empty() ? std::string("A word") : w.name) + " has no value");
    return evaluate(b.exprs, w.value, m_.parameters(), m_.file_name());
  }
  const HWord* find(const HBlock& b, std::string_view name) const {
    for (const HWord& w : b.words) if (w.name == name) return &w;
    return nullptr;
  }
  double feed(double f) const {
    return options_.heidenhain_feed_units == Options::FeedUnits::PerSecond ? f * 60.0 : f;
  }
  std::size_t find_label(const HBlock& b);
  bool tool_call(const HBlock& b);
  void sysread(const HBlock& b);
  bool path(const HBlock& b, std::size_t index);
  bool approach_or_depart(const HBlock& b, std::size_t index);
  void cycle_def(const HBlock& b);
  bool touch_probe(const HBlock& b);
  void cycle_call(std::uint32_t column);
  // SL cycles: the contours of the labels cycle 14 names, as their blocks draw them
  std::vector<SlContour> sl_contours(std::uint32_t column);
  void sl_cycle(std::map<std::string, double>& v, std::uint32_t column);
  void pocket_cycle(std::map<std::string, double>& v, std::uint32_t column);
  void point_pattern(const HBlock& b, const lowering::CycleEntry& pattern);
  void bore_milling(std::map<std::string, double>& v, double r, double bottom, double clearance, std::uint32_t column);
  void split_m(const HBlock& b, NeutralBlock& before, NeutralBlock& after);
  void add_feed(NeutralBlock& nb, std::uint32_t column);
  void plan_chamfer(const HBlock& chf, std::size_t index, const Point3& start, const Point3& corner, const Point3& next);
  ContourElement next_element(const HBlock& b, std::size_t index, const Point3& start, std::size_t corner_index,
                              std::uint32_t corner_column, std::optional<Point3> pole);
  // An error about the block at line index `index` of the running program (a block read ahead).
  [[noreturn]] void fail_at(std::size_t index, std::uint32_t column, const std::string& message) {
    throw InputError({prog().text.name, static_cast<std::uint32_t>(index + 1), column}, message);
  }

  const Options& options_;
  lowering::DialectTable table_;
  DialectMachine m_;
  Reader reader_;
  // The running program and the programs that called it (CALL PGM), each with its own labels.
  struct Program {
    ProgramText text;
    std::uint32_t file = 0;  // index in the canonical stream's file table
    std::size_t pc = 0;
    std::vector<Call> calls;
    std::map<std::string, std::size_t> labels;
    std::map<std::size_t, int> section_repeats;  // CALL LBL .. REP line -> repeats left
  };
  std::vector<Program> programs_;
  std::map<std::string, std::uint32_t> file_index_;
  Program& prog() { return programs_.back(); }
  void enter_program(ProgramText text);
  void call_program(const HBlock& b);

  double feed_ = 0;              // the last programmed F (control units)
  std::string probe_result_;     // TCH PROBE 0.0: the result's Q parameter (its key), axis, direction
  int probe_axis_ = 2;
  double probe_direction_ = -1;
  double pole_x_ = 0, pole_y_ = 0;
  bool have_pole_ = false;
  Point3 tangent_{1, 0, 0};      // direction at the end of the last path element
  bool have_tangent_ = false;
  CornerPlan corner_;
  std::optional<Point3> next_cr_centre_;     // a CR after the planned RND: its centre, from the corner
  std::optional<Point3> rounded_cr_centre_;  // ... handed to that CR block
  bool cycle_on_every_move_ = false;  // M89
  std::string cycle_;            // the defined cycle number
  std::map<std::string, double> cycle_values_;
  std::vector<std::string> sl_labels_;  // cycle 14: the contour labels
  std::optional<SlData> sl_data_;       // cycle 20
  std::set<std::string> defined_since_cycle_def_;  // Q numbers / old-style lines given since CYCL DEF
  std::uint32_t cycle_def_line_ = 0;
  std::uint64_t steps_ = 0;
  std::size_t last_index_ = 0;
  std::uint64_t backward_jumps_ = 0;
  std::string block_text_;                         // the block read last, joined and with points
  std::vector<lowering::LineSegment> segments_;    // where its parts come from
};

// Where the code of a line ends: at a `;` comment outside quotes (or the line's end).
std::size_t code_end(std::string_view l) {
  bool quoted = false;
  for (std::size_t i = 0; i < l.size(); ++i) {
    if (l[i] == '"') quoted = !quoted;
    if (!quoted && l[i] == ';') return i;
  }
  return l.size();
}

// A line whose last character (before trailing blanks) is `~` continues on the next line.
bool continued_line(std::string_view l, std::size_t& tilde) {
  std::size_t e = l.size();
  while (e > 0 && (l[e - 1] == ' ' || l[e - 1] == '\t' || l[e - 1] == '\r')) --e;
  if (e == 0 || l[e - 1] != '~') return false;
  tilde = e - 1;
  return true;
}

// A line that is a comment block: `;`/`*` first (after the block number).
bool comment_line(std::string_view l) {
  std::size_t p = 0;
  while (p < l.size() && (l[p] == ' ' || l[p] == '\t')) ++p;
  while (p < l.size() && lowering::is_digit(l[p])) ++p;
  while (p < l.size() && (l[p] == ' ' || l[p] == '\t')) ++p;
  return p < l.size() && (l[p] == ';' || l[p] == '*');
}

// Comma decimal separators (`+18,85`, `0,001`, as TNCs set to a comma write them) read as points.
void comma_decimals(std::string& s, std::size_t from, std::size_t to) {
  bool quoted = false;
  for (std::size_t i = from; i < to && i < s.size(); ++i) {
    if (s[i] == '"') quoted = !quoted;
    if (!quoted && s[i] == ',' && i > 0 && lowering::is_digit(s[i - 1]) && i + 1 < s.size() && lowering::is_digit(s[i + 1])) {
      s[i] = '.';
    }
  }
}

std::size_t Runner::read_block(std::size_t index, HBlock& b) {
  const ProgramText& text = prog().text;
  block_text_.assign(text.line(index));
  segments_.clear();
  std::size_t tilde = 0;
  std::size_t lines = 1;
  if (continued_line(block_text_, tilde)) {
    // a block over several lines: one comment (kept whole), or code whose lines' own `;`
    // comments are dropped (cycle parameters carry their names as comments)
    const bool comment = comment_line(block_text_);
    block_text_.resize(comment ? tilde : code_end(std::string_view(block_text_).substr(0, tilde)));
    segments_.push_back({0, static_cast<std::uint32_t>(index + 1), 1});
    bool more = true;
    while (more && index + lines < text.size()) {
      std::string_view next = text.line(index + lines);
      more = continued_line(next, tilde);
      std::size_t end = more ? tilde : next.size();
      std::size_t begin = 0;
      while (begin < end && (next[begin] == ' ' || next[begin] == '\t')) ++begin;
      if (!comment) end = std::min(end, begin + code_end(next.substr(begin, end - begin)));
      while (!block_text_.empty() && block_text_.back() == ' ') block_text_.pop_back();
      block_text_.push_back(' ');
      segments_.push_back({static_cast<std::uint32_t>(block_text_.size()), static_cast<std::uint32_t>(index + lines + 1),
                           static_cast<std::uint32_t>(begin + 1)});
      block_text_.append(next.substr(begin, end - begin));
      ++lines;
    }
  }
  if (!comment_line(block_text_)) comma_decimals(block_text_, 0, code_end(block_text_));
  reader_.read(block_text_, static_cast<std::uint32_t>(index + 1), text.name, b, &segments_);
  return lines;
}

void Runner::run(ProgramText program) {
  // Q, QL and QR parameters exist from the start, at 0 (as on the control)
  for (int i = 0; i < 2000; ++i) m_.parameters().set_named("_q" + std::to_string(i), 0.0);
  for (int i = 0; i < 500; ++i) {
    m_.parameters().set_named("_ql" + std::to_string(i), 0.0);
    m_.parameters().set_named("_qr" + std::to_string(i), 0.0);
  }
  enter_program(std::move(program));
  m_.at(0, prog().text.name, 0);
  m_.start();
  while (step()) {
  }
}

void Runner::enter_program(ProgramText text) {
  auto [it, added] = file_index_.emplace(text.name, static_cast<std::uint32_t>(file_index_.size()));
  if (added) m_.announce_file(it->second, text.name);
  Program p;
  p.file = it->second;
  p.text = std::move(text);
  // labels: LBL n / LBL "name"
  HBlock b;
  for (std::size_t i = 0; i < p.text.size(); ++i) {
    std::string_view l = p.text.line(i);
    // only blocks that are a label: LBL first after the block number
    std::size_t k = 0;
    while (k < l.size() && (l[k] == ' ' || l[k] == '\t')) ++k;
    while (k < l.size() && lowering::is_digit(l[k])) ++k;
    while (k < l.size() && (l[k] == ' ' || l[k] == '\t')) ++k;
    if (up(l.substr(k, 3)) != "LBL") continue;
    reader_.read(l, static_cast<std::uint32_t>(i + 1), p.text.name, b);
    if (b.kind != Kind::Label) continue;
    std::string key = b.label_is_name ? b.text : std::to_string(std::lround(b.label_number));
    if (key != "0") p.labels.emplace(key, i);
  }
  programs_.push_back(std::move(p));
}

// CALL PGM name: the program file beside the calling one or on the subroutine path (as named,
// or with .h/.H), run from its start to its END PGM, then back after the call.
void Runner::call_program(const HBlock& b) {
  if (programs_.size() >= 16) m_.fail(b.column, "Too many nested program calls (CALL PGM)");
  std::string written = b.text;
  if (written.size() >= 2 && written.front() == '"' && written.back() == '"') written = written.substr(1, written.size() - 2);
  std::replace(written.begin(), written.end(), '\\', '/');
  const std::filesystem::path caller_dir = std::filesystem::path(prog().text.name).parent_path();
  if (written.find(':') == std::string::npos && written.find('/') != std::string::npos) {
    // a path relative to the calling program
    std::error_code ec;
    const std::filesystem::path relative = (caller_dir.empty() ? std::filesystem::path(".") : caller_dir) / written;
    if (std::filesystem::is_regular_file(relative, ec)) {
      enter_program(ProgramText::from_file(relative));
      return;
    }
  }
  // a drive path (TNC:\\PARTS\\SUB.H) or a plain name: the file name, beside the caller, the
  // main program or on the subroutine path
  std::string name = written;
  const std::size_t cut = name.find_last_of("/:");
  if (cut != std::string::npos) name = name.substr(cut + 1);
  if (name.empty()) m_.fail(b.column, "CALL PGM needs a program name");
  std::vector<std::filesystem::path> dirs;
  dirs.push_back(caller_dir);
  dirs.push_back(std::filesystem::path(programs_.front().text.name).parent_path());
  for (const auto& d : options_.subroutine_path) dirs.push_back(d);
  for (const auto& dir : dirs) {
    for (const char* ext : {"", ".h", ".H"}) {
      const std::filesystem::path candidate = (dir.empty() ? std::filesystem::path(".") : dir) / (name + ext);
      std::error_code ec;
      if (!std::filesystem::is_regular_file(candidate, ec)) continue;
      enter_program(ProgramText::from_file(candidate));
      return;
    }
  }
  m_.fail(b.column, "CALL PGM " + written + ": no program file " + name + " (or " + name +
                        ".h) beside the calling program or on the subroutine path");
}

bool Runner::step() {
  if (prog().pc >= prog().text.size()) {
    m_.at(prog().file, prog().text.name, static_cast<std::uint32_t>(prog().text.size()));
    if (programs_.size() > 1) {  // a called program without END PGM ends at its last line
      if (!prog().calls.empty()) m_.fail(1, "Called program ended inside a called label (LBL 0 missing)");
      programs_.pop_back();
      return true;
    }
    if (options_.require_program_end) m_.fail(1, "File ended without END PGM");
    m_.warn(1, "File ended without END PGM: the program ends here");
    return false;
  }
  if (++steps_ > 50'000'000) m_.fail(1, "Program runs too long (endless loop?)");
  std::size_t index = prog().pc++;
  // every jump back to an earlier block is a loop iteration; a program that loops a million
  // times is taken as an endless loop (LinuxCNC's rs274 would run forever)
  if (steps_ > 1 && index <= last_index_ && ++backward_jumps_ > options_.max_loop_iterations) {
    m_.fail(1, "Loop repeated more than " + std::to_string(options_.max_loop_iterations) + " times (endless loop?)");
  }
  last_index_ = index;
  HBlock b;
  prog().pc = index + read_block(index, b);
  m_.at(prog().file, prog().text.name, static_cast<std::uint32_t>(index + 1), b.n);
  if (segments_.size() > 1) m_.continued(segments_);
  switch (b.kind) {
    case Kind::Empty:
    case Kind::BlkForm:
      return true;
    case Kind::Comment: {
      NeutralBlock nb;
      nb.comment = b.text;
      nb.has_comment = true;
      m_.execute(nb);
      return true;
    }
    case Kind::BeginPgm: {
      NeutralBlock nb;
      if (b.text.find("INCH") != std::string::npos) nb.g(20, b.column);
      else nb.g(21, b.column);
      m_.execute(nb);
      return true;
    }
    case Kind::EndPgm: {
      if (!prog().calls.empty()) m_.fail(b.column, "END PGM inside a called label (LBL 0 missing)");
      if (programs_.size() > 1) {  // the end of a called program: back to the caller
        programs_.pop_back();
        return true;
      }
      NeutralBlock nb;
      nb.m(30, b.column);
      m_.execute(nb);
      return false;
    }
    case Kind::ToolCall:
    case Kind::ToolDef:
      return tool_call(b);
    case Kind::CyclDef:
      cycle_def(b);
      return true;
    case Kind::TchProbe:
      return touch_probe(b);
    case Kind::CyclCall: {
      NeutralBlock before, after;
      split_m(b, before, after);
      if (m_.execute(before)) return false;
      if (b.keyword == "POS") {
        NeutralBlock nb;
        const HWord* fmax = find(b, "FMAX");
        nb.g(fmax ? 0 : 1, b.column);
        if (!fmax) {
          if (const HWord* f = find(b, "F")) feed_ = eval(b, *f);
          add_feed(nb, b.column);
        }
        std::optional<double> x, y, z;
        Point3 here = m_.position();
        for (const HWord& w : b.words) {
          if (w.value == kNoExpr) continue;
          double v = eval(b, w.value);
          if (w.name == "X") x = v; else if (w.name == "Y") y = v; else if (w.name == "Z") z = v;
          else if (w.name == "IX") x = here.x + v; else if (w.name == "IY") y = here.y + v; else if (w.name == "IZ") z = here.z + v;
        }
        m_.put_axes(nb, x, y, z, b.column);
        if (m_.execute(nb)) return false;
      }
      cycle_call(b.column);
      return !m_.execute(after);
    }
    case Kind::Label: {
      bool end = !b.label_is_name && b.label_number == 0;
      if (end) {
        if (prog().calls.empty()) return true;  // LBL 0 reached in the main flow: nothing to return from
        Call& c = prog().calls.back();
        if (c.remaining > 0) {
          --c.remaining;
          prog().pc = c.start_pc;
        } else {
          prog().pc = c.return_pc;
          prog().calls.pop_back();
        }
      }
      return true;
    }
    case Kind::CallLabel: {
      std::size_t target = find_label(b);
      if (const HWord* rep = find(b, "REP")) {
        // program section repeat: back to LBL n, REP more times, then on after this block
        if (target >= index) m_.fail(b.column, "CALL LBL ... REP repeats a section: the LBL must come before it");
        auto it = prog().section_repeats.find(index);
        if (it == prog().section_repeats.end()) {
          int repeats = static_cast<int>(std::lround(eval(b, *rep)));
          if (repeats < 0) m_.fail(rep->column, "REP must not be negative");
          it = prog().section_repeats.emplace(index, repeats).first;
        }
        if (it->second > 0) {
          --it->second;
          prog().pc = target + 1;
        } else {
          prog().section_repeats.erase(it);
        }
        return true;
      }
      if (prog().calls.size() >= 32) m_.fail(b.column, "Too many nested label calls");
      prog().calls.push_back(Call{prog().pc, target + 1, 0});
      prog().pc = target + 1;
      return true;
    }
    case Kind::CallPgm:
      call_program(b);
      return true;
    case Kind::Assign: {
      const ExprNode& t = b.exprs.nodes[b.target];
      std::string_view name = b.exprs.name(t.name_begin, t.name_length);
      m_.parameters().set_named(name, eval(b, b.value));
      defined_since_cycle_def_.insert("Q" + std::string(name.substr(2)));
      return true;
    }
    case Kind::FnJump: {
      double a = eval(b, b.value), c = eval(b, b.value2);
      bool taken = b.op == "EQU" ? a == c : b.op == "NE" ? a != c : b.op == "GT" ? a > c : a < c;
      if (taken) prog().pc = find_label(b) + 1;
      return true;
    }
    case Kind::Functions: {
      // M functions alone: those acting at the block's start, then those acting at its end;
      // M99 calls the cycle here
      bool m99 = false;
      for (const HWord& w : b.words) {
        if (w.name != "M" && w.name != "F") m_.fail(w.column, "Word " + w.name + " in a block of M functions");
        if (w.name == "F") feed_ = eval(b, w);
        if (w.name == "M" && eval(b, w) == 99) m99 = true;
      }
      NeutralBlock before, after;
      split_m(b, before, after);
      if (m_.execute(before)) return false;
      if (m99) cycle_call(b.column);
      return !m_.execute(after);
    }
    case Kind::SysRead:
      sysread(b);
      return true;
    case Kind::Stop: {
      NeutralBlock before, after;
      split_m(b, before, after);
      before.m(0, b.column);
      if (m_.execute(before)) return false;
      return !m_.execute(after);
    }
    case Kind::Path:
      return path(b, index);
  }
  return true;
}

std::size_t Runner::find_label(const HBlock& b) {
  std::string key = b.label_is_name ? b.text : std::to_string(std::lround(b.label_number));
  auto it = prog().labels.find(key);
  if (it == prog().labels.end()) m_.fail(b.column, "LBL " + key + " not found");
  return it->second;
}

// M functions that act at the start of a block go before its motion; the others after it.
void Runner::split_m(const HBlock& b, NeutralBlock& before, NeutralBlock& after) {
  for (const HWord& w : b.words) {
    if (w.name != "M" || w.value == kNoExpr) continue;
    double code = eval(b, w.value);
    const lowering::CodeEntry* e = table_.m(code);
    if (e == nullptr) {
      if (m_.machine_function(code, w.column)) continue;
      m_.fail(w.column, "M" + lowering::code_key(code) + " is not a Heidenhain M function ncbridge supports");
    }
    if (e->meta == "spindle_cw_coolant" || e->meta == "spindle_ccw_coolant") {
      before.m(e->meta == "spindle_cw_coolant" ? 3 : 4, w.column);
      before.m(8, w.column);
    } else if (e->meta == "cycle_call_block") {
      // M99: handled by the path block (after its motion)
    } else if (e->meta == "cycle_call_modal") {
      cycle_on_every_move_ = true;
    } else if (e->meta == "spindle_cw" || e->meta == "spindle_ccw" || e->meta == "coolant_flood") {
      before.m(static_cast<int>(*e->rs274), w.column);
    } else if (e->rs274) {
      after.m(static_cast<int>(*e->rs274), w.column);
    }
  }
}

void Runner::add_feed(NeutralBlock& nb, std::uint32_t column) {
  double f = feed(feed_);
  if (f <= 0) m_.fail(column, "Feed move with no feed rate programmed");
  if (std::fabs(m_.state().feed_rate - f) > 1e-9) nb.add('f', f, column);
}

bool Runner::tool_call(const HBlock& b) {
  NeutralBlock nb;
  int tool = 0;
  if (!b.tool_name.empty()) {
    tool = m_.tool_number_for_name(b.tool_name, b.column);
  } else if (const HWord* t = find(b, "T")) {
    tool = static_cast<int>(std::lround(eval(b, *t)));
  } else if (b.kind == Kind::ToolCall) {
    tool = m_.state().tool_in_spindle;  // TOOL CALL Z S..: new data for the tool in the spindle
  }
  if (b.kind == Kind::ToolDef) {
    nb.add('t', tool, b.column);
    return !m_.execute(nb);
  }
  if (b.text == "X" && m_.state().plane != canonical::Plane::YZ) nb.g(19, b.column);
  if (b.text == "Y" && m_.state().plane != canonical::Plane::XZ) nb.g(18, b.column);
  if (b.text == "Z" && m_.state().plane != canonical::Plane::XY) nb.g(17, b.column);
  double delta_length = 0;
  for (const HWord& w : b.words) {
    if (w.name == "S") nb.add('s', eval(b, w), w.column);
    else if (w.name == "F") feed_ = eval(b, w);
    else if (w.name == "DL" && w.value != kNoExpr) delta_length = eval(b, w.value);
    else if (w.name == "DR" && w.value != kNoExpr && eval(b, w.value) != 0.0) {
      // a radius oversize acts through radius compensation (RL/RR) only
      m_.comment("ncbridge: TOOL CALL DR" + std::to_string(eval(b, w.value)) + " noted: it changes compensated paths only");
    }
  }
  if (tool != m_.state().tool_in_spindle || find(b, "T") || !b.tool_name.empty() || delta_length != 0) {
    nb.add('t', tool, b.column);
    nb.m(6, b.column);
    nb.g(43, b.column);
    if (delta_length == 0) {
      nb.add('h', tool, b.column);
    } else {
      // DL: the tool's length plus the oversize, as a dynamic length offset (G43.1)
      const setup::Tool* t = options_.tools.find(tool);
      if (t == nullptr) m_.fail(b.column, "TOOL CALL DL needs the tool's length: tool " + std::to_string(tool) + " is not in the tool list");
      nb.words.pop_back();
      nb.g(43.1, b.column);
      nb.add('z', t->length / m_.state().mm_per_unit() + delta_length, b.column);
    }
  }
  if (m_.execute(nb)) return false;
  // the system Q parameters a TOOL CALL sets, from the tool list: Q108 the active tool radius
  // (with DR), Q114 its length (with DL), Q109 the tool axis (0 X, 1 Y, 2 Z), Q113 the unit
  if (const setup::Tool* t = options_.tools.find(tool)) {
    double delta_radius = 0;
    if (const HWord* dr = find(b, "DR"); dr && dr->value != kNoExpr) delta_radius = eval(b, dr->value);
    const double k = m_.state().mm_per_unit();
    m_.parameters().set_named("_q108", t->diameter / k / 2.0 + delta_radius);
    m_.parameters().set_named("_q114", t->length / k + delta_length);
  }
  m_.parameters().set_named("_q109", b.text == "X" ? 0.0 : b.text == "Y" ? 1.0 : 2.0);
  m_.parameters().set_named("_q113", m_.state().units == canonical::Units::Inches ? 1.0 : 0.0);
  return true;
}

// FN 18 SYSREAD, for the system data an offline reading knows: ID10 NR1 (unit), ID20 (NR1
// active tool, NR2 prepared tool, NR3 tool axis, NR4 spindle speed, NR5 spindle status, NR8
// coolant, NR9 feed rate), ID50 (tool table: NR1 length L, NR2 radius R, NR3 radius R2 from the
// tool list; NR4-NR6 the oversizes DL, DR, DR2, which a tool list does not hold: 0; IDX the
// tool, else the active one) and ID270 NR1 IDX1-3 (the current position in the active
// coordinate system). The TNC gives lengths in mm whatever the program's unit. Any other ID
// belongs to the machine (its datum tables, probes, PLC): refused, naming it.
void Runner::sysread(const HBlock& b) {
  double id = -1, nr = -1, idx = -1;
  std::uint32_t id_column = b.column;
  for (const HWord& w : b.words) {
    const double v = eval(b, w);
    if (w.name == "ID") { id = v; id_column = w.column; }
    else if (w.name == "NR") nr = v;
    else idx = v;
  }
  const int group = static_cast<int>(std::lround(id)), number = static_cast<int>(std::lround(nr));
  const std::string what = "FN 18: SYSREAD ID" + std::to_string(group) + " NR" + std::to_string(number);
  const ModalState& s = m_.state();
  std::optional<double> value;
  if (group == 10 && number == 1) {
    value = s.units == canonical::Units::Inches ? 1.0 : 0.0;
  } else if (group == 20) {
    switch (number) {
      case 1: value = s.tool_in_spindle; break;
      case 2: value = s.selected_tool; break;
      case 3: value = s.plane == canonical::Plane::YZ ? 0.0 : s.plane == canonical::Plane::XZ ? 1.0 : 2.0; break;
      case 4: value = s.speed; break;
      case 5: value = s.spindle == canonical::Direction::Clockwise ? 0.0
                      : s.spindle == canonical::Direction::Counterclockwise ? 1.0 : -1.0; break;
      case 8: value = s.flood || s.mist ? 1.0 : 0.0; break;
      case 9: value = feed(feed_); break;
      default: break;
    }
  } else if (group == 50 && number >= 1 && number <= 6) {
    const int tool = idx >= 0 ? static_cast<int>(std::lround(idx)) : s.tool_in_spindle;
    if (number >= 4) {
      value = 0.0;  // DL, DR, DR2: a tool list holds no oversizes
    } else {
      const setup::Tool* t = options_.tools.find(tool);
      if (t == nullptr) m_.fail(id_column, what + ": tool " + std::to_string(tool) + " is not in the tool list");
      value = number == 1 ? t->length : number == 2 ? t->diameter / 2.0 : t->corner_radius;
    }
  } else if (group == 270 && number == 1 && idx >= 1 && idx <= 3) {
    const Point3 p = m_.position();
    value = (idx < 1.5 ? p.x : idx < 2.5 ? p.y : p.z) * s.mm_per_unit();
  }
  if (!value) {
    m_.fail(id_column, what + (idx >= 0 ? " IDX" + std::to_string(std::lround(idx)) : std::string()) +
                           " is machine data an offline reading does not have (known: ID10 NR1, ID20 NR1-5/8/9, "
                           "ID50 NR1-6, ID270 NR1)");
  }
  const ExprNode& t = b.exprs.nodes[b.target];
  m_.parameters().set_named(b.exprs.name(t.name_begin, t.name_length), *value);
}

// CHF between two straight lines: the corner cut at `size` from it along both lines.
void Runner::plan_chamfer(const HBlock& chf, std::size_t index, const Point3& start, const Point3& corner,
                          const Point3& next) {
  double ux = corner.x - start.x, uy = corner.y - start.y;
  double vx = next.x - corner.x, vy = next.y - corner.y;
  const double lu = std::hypot(ux, uy), lv = std::hypot(vx, vy);
  if (lu < 1e-9 || lv < 1e-9) fail_at(index, chf.column, "CHF between elements of zero length");
  ux /= lu; uy /= lu; vx /= lv; vy /= lv;
  if (std::fabs(ux * vy - uy * vx) < 1e-9) fail_at(index, chf.column, "CHF at a corner without a change of direction");
  // CHF 5: the length is the block's first value
  double size = 0;
  for (const HWord& w : chf.words) {
    if (w.value != kNoExpr && w.name.empty()) size = eval(chf, w.value);
  }
  if (size == 0 && !chf.words.empty() && chf.words.front().value != kNoExpr) size = eval(chf, chf.words.front().value);
  if (size <= 0) fail_at(index, chf.column, "CHF size must be positive");
  if (size > lu + 1e-9 || size > lv + 1e-9) fail_at(index, chf.column, "CHF too large for the elements it joins");
  corner_ = CornerPlan{};
  corner_.active = true;
  corner_.chamfer = true;
  corner_.t1 = {corner.x - ux * size, corner.y - uy * size, corner.z};
  corner_.t2 = {corner.x + vx * size, corner.y + vy * size, corner.z};
}

// APPR/DEP: approaching the contour's first point PA and leaving its last point PE, as the TNC
// manual describes them. LT: on a straight line, tangential to the first (last) element, from
// (to) an auxiliary point LEN away along it; LN: perpendicular to it, LEN away on the tool's
// side; CT: on an arc of radius R and angle CCA tangential to it, its centre on the tool's side
// (R < 0: the other side); LCT: on a straight line tangential to such an arc that joins the
// element tangentially at PA (PE), the line from the start point (to the end point X Y). APPR
// switches the radius compensation it names on with its first move (the compensation's entry
// move, as R0 -> RL/RR), DEP switches it off with its last.
bool Runner::approach_or_depart(const HBlock& b, std::size_t index) {
  const bool approach = b.keyword == "APPR";
  std::string form;
  std::optional<double> x, y, z, len, cca, radius;
  int comp = m_.state().comp_side == canonical::Side::Left ? 41 : m_.state().comp_side == canonical::Side::Right ? 42 : 40;
  bool rapid = false;
  const Point3 here = m_.position();
  for (const HWord& w : b.words) {
    const std::string& n = w.name;
    if (n == "LT" || n == "LN" || n == "CT" || n == "LCT") { form = n; continue; }
    if (n == "RL") { comp = 41; continue; }
    if (n == "RR") { comp = 42; continue; }
    if (n == "FMAX") { rapid = true; continue; }
    if (n == "M") continue;
    if (w.value == kNoExpr) {
      if (n == "F" || n == "R") continue;
      m_.fail(w.column, n + " has no value");
    }
    const double v = eval(b, w.value);
    if (n == "X") x = v; else if (n == "Y") y = v; else if (n == "Z") z = v;
    else if (n == "IX") x = here.x + v; else if (n == "IY") y = here.y + v; else if (n == "IZ") z = here.z + v;
    else if (n == "LEN") len = v;
    else if (n == "CCA") cca = v;
    else if (n == "R") {
      if (v == 0) comp = 40; else radius = v;
    }
    else if (n == "F") feed_ = v;
    else m_.fail(w.column, "Word " + n + " is not supported in " + b.keyword + " " + form);
  }
  (void)rapid;  // the approach and departure run at the feed (the TNC's first move to PH aside)
  if (form.empty()) m_.fail(b.column, b.keyword + " needs LT, LN, CT or LCT");
  if ((form == "LT" || form == "LN") && (!len || *len <= 0)) m_.fail(b.column, b.keyword + " " + form + " needs LEN > 0");
  if ((form == "CT" || form == "LCT") && (!radius || *radius == 0)) m_.fail(b.column, b.keyword + " " + form + " needs R");
  if (form == "CT" && (!cca || *cca <= 0 || *cca >= 360)) m_.fail(b.column, b.keyword + " CT needs CCA between 0 and 360");
  if (comp == 40 && approach) m_.fail(b.column, "APPR needs the radius compensation RL or RR");
  const bool left = comp == 41;
  NeutralBlock before, after;
  split_m(b, before, after);
  Point3 contour{}, tangent{};  // the contour point and the element's direction there
  if (approach) {
    if (!x || !y) m_.fail(b.column, "APPR needs the first contour point X and Y");
    contour = {*x, *y, z.value_or(here.z)};
    // the first contour element: the next path block
    std::size_t j = prog().pc;
    HBlock next;
    while (j < prog().text.size()) {
      const std::size_t lines = read_block(j, next);
      if (next.kind != Kind::Empty && next.kind != Kind::Comment) break;
      j += lines;
    }
    std::optional<Point3> pole;
    if (next.kind == Kind::Path && next.keyword == "CC") {
      Point3 c{pole_x_, pole_y_, 0};
      for (const HWord& w : next.words) {
        if (w.value == kNoExpr) continue;
        const double v = eval(next, w.value);
        if (w.name == "X") c.x = v; else if (w.name == "Y") c.y = v;
        else if (w.name == "IX") c.x = contour.x + v; else if (w.name == "IY") c.y = contour.y + v;
      }
      pole = c;
      j += read_block(j, next);
      while (j < prog().text.size() && (next.kind == Kind::Empty || next.kind == Kind::Comment)) j += read_block(j, next);
    }
    if (j >= prog().text.size() || next.kind != Kind::Path) fail_at(index, b.column, "APPR must be followed by the first contour element");
    const ContourElement e = next_element(next, j, contour, index, b.column, pole);
    if (e.arc) {
      const double rx = contour.x - e.cx, ry = contour.y - e.cy, l = std::hypot(rx, ry);
      tangent = e.cw ? Point3{ry / l, -rx / l, 0} : Point3{-ry / l, rx / l, 0};
    } else {
      const double dx = e.end.x - contour.x, dy = e.end.y - contour.y, l = std::hypot(dx, dy);
      if (l < 1e-9) fail_at(index, b.column, "APPR: the first contour element has no length");
      tangent = {dx / l, dy / l, 0};
    }
  } else {
    if (!have_tangent_) m_.fail(b.column, "DEP needs a contour element before it");
    contour = here;
    tangent = tangent_;
  }
  // the normal towards the tool's side (RL: left of the direction of travel)
  const Point3 side = left ? Point3{-tangent.y, tangent.x, 0} : Point3{tangent.y, -tangent.x, 0};
  NeutralBlock nb = approach ? before : NeutralBlock{};
  auto move_line = [&](const Point3& to, bool first) {
    if (first && approach && comp != 40) nb.g(comp, b.column);
    add_feed(nb, b.column);
    nb.g(1, b.column);
    m_.put_axes(nb, to.x, to.y, std::nullopt, b.column);
    if (m_.execute(nb)) m_.fail(b.column, b.keyword + " ended the program");
    nb.clear();
  };
  auto move_arc = [&](const Point3& to, const Point3& centre, bool cw, bool first) {
    if (first && approach && comp != 40) nb.g(comp, b.column);
    add_feed(nb, b.column);
    m_.put_xy_arc(nb, cw, to.x, to.y, std::nullopt, centre.x, centre.y, b.column);
    if (m_.execute(nb)) m_.fail(b.column, b.keyword + " ended the program");
    nb.clear();
  };
  const double sign = radius && *radius < 0 ? -1.0 : 1.0;
  const double r = radius ? std::fabs(*radius) : 0.0;
  // an arc whose centre lies on the tool's side (R > 0) turns towards it: counter-clockwise for RL
  const bool arc_cw = (sign > 0) ? !left : left;
  const Point3 centre{contour.x + sign * side.x * r, contour.y + sign * side.y * r, 0};
  auto rotate_about = [&](const Point3& p, double degrees) {
    const double a = degrees * kDeg, c = std::cos(a), s2 = std::sin(a);
    const double dx = p.x - centre.x, dy = p.y - centre.y;
    return Point3{centre.x + c * dx - s2 * dy, centre.y + s2 * dx + c * dy, 0};
  };
  // the point where a line from (to) `p` touches the arc's circle, on the side the arc runs
  auto touching = [&](const Point3& p, bool incoming) -> Point3 {
    const double dx = p.x - centre.x, dy = p.y - centre.y, d = std::hypot(dx, dy);
    if (d <= r + 1e-9) m_.fail(b.column, b.keyword + " LCT: the point is inside the arc's circle");
    const double base = std::atan2(dy, dx), off = std::acos(r / d);
    // the tangent point at which the arc's direction of travel points away from (towards) p
    for (double sgn : {1.0, -1.0}) {
      const double a = base + sgn * off;
      const Point3 t{centre.x + r * std::cos(a), centre.y + r * std::sin(a), 0};
      const Point3 dir = arc_cw ? Point3{std::sin(a), -std::cos(a), 0} : Point3{-std::sin(a), std::cos(a), 0};
      const double along = (t.x - p.x) * dir.x + (t.y - p.y) * dir.y;
      if ((incoming && along > 0) || (!incoming && along < 0)) return t;
    }
    m_.fail(b.column, b.keyword + " LCT: no tangent from the point to the arc");
  };
  if (approach) {
    if (form == "LT" || form == "LN") {
      const Point3 aux = form == "LT" ? Point3{contour.x - tangent.x * *len, contour.y - tangent.y * *len, 0}
                                      : Point3{contour.x + side.x * *len, contour.y + side.y * *len, 0};
      move_line(aux, true);
      move_line(contour, false);
    } else if (form == "CT") {
      const Point3 start = rotate_about(contour, arc_cw ? *cca : -*cca);
      move_line(start, true);
      move_arc(contour, centre, arc_cw, false);
    } else {
      const Point3 start = touching(here, true);
      move_line(start, true);
      move_arc(contour, centre, arc_cw, false);
    }
    have_tangent_ = true;
    tangent_ = tangent;
  } else {
    Point3 end{};
    if (form == "LT" || form == "LN") {
      end = form == "LT" ? Point3{contour.x + tangent.x * *len, contour.y + tangent.y * *len, 0}
                         : Point3{contour.x + side.x * *len, contour.y + side.y * *len, 0};
      nb.g(40, b.column);
      move_line(end, false);
    } else if (form == "CT") {
      end = rotate_about(contour, arc_cw ? -*cca : *cca);
      move_arc(end, centre, arc_cw, false);
      // the compensation ends here: the next move leaves the contour
      nb.g(40, b.column);
      if (m_.execute(nb)) return false;
      nb.clear();
    } else {
      if (!x || !y) m_.fail(b.column, "DEP LCT needs the end point X and Y");
      const Point3 target{*x, *y, 0};
      const Point3 leave = touching(target, false);
      move_arc(leave, centre, arc_cw, false);
      nb.g(40, b.column);
      move_line(target, false);
    }
    if (z) {
      nb.g(1, b.column);
      m_.put_axes(nb, std::nullopt, std::nullopt, *z, b.column);
      if (m_.execute(nb)) return false;
      nb.clear();
    }
  }
  return !m_.execute(after);
}

bool Runner::path(const HBlock& b, std::size_t index) {
  const std::string& k = b.keyword;
  if (k == "APPR" || k == "DEP") return approach_or_depart(b, index);
  Point3 here = m_.position();
  std::optional<double> x, y, z;
  bool rapid = false, cw = false, dr = false;
  std::optional<double> radius, pa, ipa, pr;
  bool comp_given = false;
  int comp = 40;
  bool m99 = false;
  for (const HWord& w : b.words) {
    const std::string& n = w.name;
    if (n == "FMAX") { rapid = true; continue; }
    if (n == "FAUTO") continue;
    if (n == "F" && w.value == kNoExpr) continue;  // F AUTO / F MAX spelled apart
    if (n == "DR") {
      dr = true;
      cw = w.sign == '-' || (w.value != kNoExpr && eval(b, w.value) < 0);
      continue;
    }
    if (n == "RL" || n == "RR") { comp_given = true; comp = n == "RL" ? 41 : 42; continue; }
    if (n == "M") {
      if (w.value != kNoExpr) {
        double code = eval(b, w.value);
        if (code == 99) m99 = true;
      }
      continue;
    }
    // an address without a value (old TNC output: "L X+32,000 R F5000 M") changes nothing
    if (w.value == kNoExpr && (n == "R" || n == "M" || n == "F")) continue;
    if (w.value == kNoExpr) {
      if (n == "X" || n == "Y" || n == "Z") m_.fail(w.column, n + " has no value");
      m_.fail(w.column, "Unknown word " + n);
    }
    double v = eval(b, w.value);
    if (n == "X") x = v;
    else if (n == "Y") y = v;
    else if (n == "Z") z = v;
    else if (n == "IX") x = here.x + v;
    else if (n == "IY") y = here.y + v;
    else if (n == "IZ") z = here.z + v;
    else if (n == "F") feed_ = v;
    else if (n == "R") {
      if (k == "CR" && !radius) radius = v;
      else if (k == "RND") radius = v;
      else if (v == 0) { comp_given = true; comp = 40; }
      else m_.fail(w.column, "R" + std::to_string(v) + ": radius compensation is R0, RL or RR");
    }
    else if (n == "PA") pa = v;
    else if (n == "IPA") ipa = v;
    else if (n == "PR") pr = v;
    else if (n == "IPR") pr = v;  // incremental polar radius: relative to the current radius
    else if (n == "S") continue;
    else if (k == "CHF" && n.empty()) radius = v;
    else m_.fail(w.column, "Word " + n + " is not supported in an " + k + " block");
  }
  NeutralBlock before, after;
  split_m(b, before, after);
  if (comp_given && (comp != 40 || m_.state().comp_side != canonical::Side::Off)) before.g(comp, b.column);
  if (k == "CC") {
    pole_x_ = x.value_or(here.x);
    pole_y_ = y.value_or(here.y);
    have_pole_ = true;
    return !m_.execute(before) && !m_.execute(after);
  }
  if (k == "RND" || k == "CHF") {
    if (!corner_.active) m_.fail(b.column, k + " must follow a straight or circular path block and precede another");
    NeutralBlock nb = before;
    add_feed(nb, b.column);
    if (corner_.chamfer) {
      nb.g(1, b.column);
      m_.put_axes(nb, corner_.t2.x, corner_.t2.y, std::nullopt, b.column);
    } else {
      m_.put_xy_arc(nb, !corner_.ccw, corner_.t2.x, corner_.t2.y, std::nullopt, corner_.centre.x, corner_.centre.y, b.column);
    }
    corner_.active = false;
    if (!corner_.chamfer) {
      const double rx = corner_.t2.x - corner_.centre.x, ry = corner_.t2.y - corner_.centre.y;
      const double l = std::hypot(rx, ry);
      if (l > 0) tangent_ = corner_.ccw ? Point3{-ry / l, rx / l, 0} : Point3{ry / l, -rx / l, 0};
    } else {
      const double dx = corner_.t2.x - corner_.t1.x, dy = corner_.t2.y - corner_.t1.y;
      const double l = std::hypot(dx, dy);
      if (l > 0) tangent_ = {dx / l, dy / l, 0};
    }
    rounded_cr_centre_ = next_cr_centre_;
    next_cr_centre_.reset();
    if (m_.execute(nb)) return false;
    return !m_.execute(after);
  }

  Point3 end{x.value_or(here.x), y.value_or(here.y), z.value_or(here.z)};
  NeutralBlock nb = before;
  bool arc = false;
  double cx = 0, cy = 0;
  if (k == "L" || k == "LP") {
    if (k == "LP") {
      if (!have_pole_) m_.fail(b.column, "LP without a pole: program CC first");
      double r0 = std::hypot(here.x - pole_x_, here.y - pole_y_);
      double a0 = std::atan2(here.y - pole_y_, here.x - pole_x_) / kDeg;
      double r = pr.value_or(r0);
      double a = pa.value_or(a0) + ipa.value_or(0.0);
      end.x = pole_x_ + r * std::cos(a * kDeg);
      end.y = pole_y_ + r * std::sin(a * kDeg);
      x = end.x;
      y = end.y;
    }
  } else if (k == "C" || k == "CP") {
    if (!have_pole_) m_.fail(b.column, k + " without a circle centre: program CC first");
    if (!dr) m_.fail(b.column, k + " needs the direction DR+ or DR-");
    arc = true;
    cx = pole_x_;
    cy = pole_y_;
    if (k == "CP") {
      double r0 = std::hypot(here.x - cx, here.y - cy);
      double a0 = std::atan2(here.y - cy, here.x - cx) / kDeg;
      double a = pa ? *pa : a0 + ipa.value_or(0.0);
      end.x = cx + r0 * std::cos(a * kDeg);
      end.y = cy + r0 * std::sin(a * kDeg);
      x = end.x;
      y = end.y;
      if (ipa && std::fabs(*ipa) >= 360.0 - 1e-9) {
        // a helix of whole turns: the executor takes the extra turns as P
        int turns = static_cast<int>(std::floor(std::fabs(*ipa) / 360.0 + 1e-9));
        if (std::fabs(std::fmod(std::fabs(*ipa), 360.0)) < 1e-9) nb.add('p', turns, b.column);
        else nb.add('p', turns + 1, b.column);
      }
    }
  } else if (k == "CR") {
    if (!radius) m_.fail(b.column, "CR needs R (the radius)");
    if (!dr) m_.fail(b.column, "CR needs the direction DR+ or DR-");
    if (rounded_cr_centre_) {
      // after a RND the arc is the one programmed from the corner point, now entered at the
      // rounding's end
      cx = rounded_cr_centre_->x;
      cy = rounded_cr_centre_->y;
    } else {
      if (std::hypot(end.x - here.x, end.y - here.y) < 1e-9) m_.fail(b.column, "CR to its own start point");
      if (!radius_arc_centre(here, end, *radius, cw, cx, cy)) m_.fail(b.column, "CR radius too small to reach the end point");
    }
    arc = true;
    pole_x_ = cx;  // the control takes a CR's centre as the new pole
    pole_y_ = cy;
  } else if (k == "CT") {
    if (!have_tangent_) m_.fail(b.column, "CT needs a preceding contour element to be tangent to");
    double dx = end.x - here.x, dy = end.y - here.y;
    double nx = -tangent_.y, ny = tangent_.x;  // left normal of the incoming direction
    double nd = nx * dx + ny * dy;
    if (std::fabs(nd) > 1e-9) {  // else the end lies on the tangent: a straight line
      double kk = (dx * dx + dy * dy) / (2 * nd);
      cx = here.x + nx * kk;
      cy = here.y + ny * kk;
      cw = kk < 0;
      arc = true;
    }
  }

  rounded_cr_centre_.reset();

  // A RND/CHF after this block shortens it to the corner's first tangent point.
  Point3 final_end = end;
  {
    std::size_t j = prog().pc;
    HBlock nb2;
    while (j < prog().text.size()) {
      const std::size_t lines = read_block(j, nb2);
      if (nb2.kind != Kind::Empty && nb2.kind != Kind::Comment) break;
      j += lines;
    }
    if (j < prog().text.size() && nb2.kind == Kind::Path && (nb2.keyword == "RND" || nb2.keyword == "CHF")) {
      if (rapid) fail_at(j, nb2.column, nb2.keyword + " after a rapid (FMAX) block: a corner is cut at feed");
      // the element after the corner
      std::size_t j2 = j + 1;
      HBlock after_block;
      while (j2 < prog().text.size()) {
        const std::size_t lines = read_block(j2, after_block);
        if (after_block.kind != Kind::Empty && after_block.kind != Kind::Comment) break;
        j2 += lines;
      }
      // a CC between the corner and a C block sets the C block's centre
      std::optional<Point3> pole;
      while (j2 < prog().text.size() && after_block.kind == Kind::Path && after_block.keyword == "CC") {
        Point3 c{pole_x_, pole_y_, 0};
        for (const HWord& w : after_block.words) {
          if (w.value == kNoExpr) continue;
          const double v = eval(after_block, w.value);
          if (w.name == "X") c.x = v; else if (w.name == "Y") c.y = v;
          else if (w.name == "IX") c.x = end.x + v; else if (w.name == "IY") c.y = end.y + v;
        }
        pole = c;
        do {
          ++j2;
          if (j2 >= prog().text.size()) break;
          read_block(j2, after_block);
        } while (after_block.kind == Kind::Empty || after_block.kind == Kind::Comment);
      }
      if (j2 >= prog().text.size() || after_block.kind != Kind::Path) {
        fail_at(j, nb2.column, nb2.keyword + " must be followed by a contour block (L, C or CR)");
      }
      if (nb2.keyword == "CHF") {
        // the TNC chamfers only between two straight lines
        if (arc) fail_at(j, nb2.column, "CHF joins two straight lines: the block before it is an arc (use RND)");
        if (after_block.keyword != "L") {
          fail_at(j, nb2.column, "CHF joins two straight lines: the block after it is not L (use RND)");
        }
        ContourElement out = next_element(after_block, j2, end, j, nb2.column, pole);
        plan_chamfer(nb2, j, here, end, out.end);
      } else {
        ContourElement in{here, end, arc, cx, cy, cw};
        ContourElement out = next_element(after_block, j2, end, j, nb2.column, pole);
        const HWord* r = find(nb2, "R");
        if (!r || r->value == kNoExpr) fail_at(j, nb2.column, "RND needs R");
        const double size = eval(nb2, r->value);
        if (size <= 0) fail_at(j, nb2.column, "RND size must be positive");
        const RoundedCorner rc = round_corner(in, out, size);
        if (!rc.ok) fail_at(j, nb2.column, rc.error);
        corner_ = CornerPlan{};
        corner_.active = true;
        corner_.t1 = rc.t1;
        corner_.t2 = rc.t2;
        corner_.centre = rc.centre;
        corner_.ccw = rc.ccw;
        if (out.arc && after_block.keyword == "CR") next_cr_centre_ = Point3{out.cx, out.cy, 0};
      }
      final_end = corner_.t1;
      x = final_end.x;
      y = final_end.y;
    }
  }

  if (rapid) {
    nb.g(0, b.column);
    m_.put_axes(nb, x, y, z, b.column);
  } else {
    add_feed(nb, b.column);
    if (arc) {
      m_.put_xy_arc(nb, cw, final_end.x, final_end.y, z, cx, cy, b.column);
    } else {
      nb.g(1, b.column);
      m_.put_axes(nb, x, y, z, b.column);
    }
  }
  if (arc) {
    // tangent at the end of the arc: perpendicular to the radius, in the direction of travel
    double rx = final_end.x - cx, ry = final_end.y - cy;
    double l = std::hypot(rx, ry);
    if (l > 0) tangent_ = cw ? Point3{ry / l, -rx / l, 0} : Point3{-ry / l, rx / l, 0};
    have_tangent_ = true;
  } else {
    double dx = final_end.x - here.x, dy = final_end.y - here.y;
    double l = std::hypot(dx, dy);
    if (l > 1e-12) {
      tangent_ = {dx / l, dy / l, 0};
      have_tangent_ = true;
    }
  }
  if (m_.execute(nb)) return false;
  if (m99 || (cycle_on_every_move_ && (x || y))) cycle_call(b.column);
  return !m_.execute(after);
}

// The contour element a path block describes, starting at `start` (the nominal corner point):
// what a RND or CHF before it needs to know. L, C (about the current CC) and CR.
ContourElement Runner::next_element(const HBlock& b, std::size_t index, const Point3& start, std::size_t corner_index,
                                    std::uint32_t corner_column, std::optional<Point3> pole) {
  ContourElement e;
  e.start = start;
  e.end = start;
  std::optional<double> radius;
  bool dr = false;
  for (const HWord& w : b.words) {
    if (w.name == "DR") {
      dr = true;
      e.cw = w.sign == '-' || (w.value != kNoExpr && eval(b, w.value) < 0);
      continue;
    }
    if (w.value == kNoExpr) continue;
    const double v = eval(b, w.value);
    if (w.name == "X") e.end.x = v;
    else if (w.name == "Y") e.end.y = v;
    else if (w.name == "Z") e.end.z = v;
    else if (w.name == "IX") e.end.x = start.x + v;
    else if (w.name == "IY") e.end.y = start.y + v;
    else if (w.name == "IZ") e.end.z = start.z + v;
    else if (w.name == "R" && b.keyword == "CR") radius = v;
  }
  if (b.keyword == "L") return e;
  if (b.keyword == "C") {
    if (!have_pole_ && !pole) fail_at(index, b.column, "C without a circle centre: program CC first");
    if (!dr) fail_at(index, b.column, "C needs the direction DR+ or DR-");
    e.arc = true;
    e.cx = pole ? pole->x : pole_x_;
    e.cy = pole ? pole->y : pole_y_;
    return e;
  }
  if (b.keyword == "CR") {
    if (!radius) fail_at(index, b.column, "CR needs R (the radius)");
    if (!dr) fail_at(index, b.column, "CR needs the direction DR+ or DR-");
    e.arc = true;
    if (!radius_arc_centre(start, e.end, *radius, e.cw, e.cx, e.cy)) {
      fail_at(index, b.column, "CR radius too small to reach the end point");
    }
    return e;
  }
  fail_at(corner_index, corner_column, "RND/CHF followed by " + b.keyword + ": only L, C or CR can follow a corner here");
}

void Runner::cycle_def(const HBlock& b) {
  const std::string& number = b.keyword;
  std::size_t dot = number.find('.');
  std::string cycle = dot == std::string::npos ? number : number.substr(0, dot);
  std::string sub = dot == std::string::npos ? "" : number;
  if (cycle == "9") {
    // 9 DWELL TIME acts at once: CYCL DEF 9.1 DWELL seconds
    if (sub != "9.1") return;
    std::size_t p = 0;
    const std::string& text = b.text;
    while (p < text.size() && !(lowering::is_digit(text[p]) || text[p] == '.')) ++p;
    double seconds = 0;
    if (!lowering::read_decimal(text, p, seconds)) m_.fail(b.column, "CYCL DEF 9.1 needs the dwell time in seconds");
    NeutralBlock nb;
    nb.g(4, b.column);
    nb.add('p', seconds, b.column);
    m_.execute(nb);
    return;
  }
  if (cycle == "7" || cycle == "10") {
    // coordinate transformation cycles act at once: 7 DATUM SHIFT, 10 ROTATION
    if (sub.empty() || sub == cycle + ".0") return;
    std::string text = b.text;
    auto value_after = [&](std::string_view key, double& v) {
      std::size_t p = text.find(key);
      if (p == std::string::npos) return false;
      p += key.size();
      while (p < text.size() && text[p] == ' ') ++p;
      return lowering::read_decimal(text, p, v);
    };
    double v = 0;
    if (cycle == "10") {
      if (!value_after("ROT", v)) m_.fail(b.column, "CYCL DEF 10.1 needs ROT");
      // the rotation turns about the current datum
      m_.frame.rotation_deg = v;
    } else {
      if (value_after("IX", v)) m_.frame.shift_within({v, 0, 0});
      else if (value_after("X", v)) m_.frame.offset.x = v;
      if (value_after("IY", v)) m_.frame.shift_within({0, v, 0});
      else if (value_after("Y", v)) m_.frame.offset.y = v;
      if (value_after("IZ", v)) m_.frame.offset.z += v;
      else if (value_after("Z", v)) m_.frame.offset.z = v;
    }
    return;
  }
  if (cycle == "32") {
    // 32 TOLERANCE: 32.1 T (the contour tolerance) is the path blending tolerance (G64 P);
    // 32.2 HSC-MODE and TA (the rotary axes' tolerance) change no path in three axes
    if (sub != "32.1") return;
    std::size_t p = b.text.find('T');
    double t = 0;
    if (p != std::string::npos) ++p;
    if (p == std::string::npos || !lowering::read_decimal(b.text, p, t)) m_.fail(b.column, "CYCL DEF 32.1 needs T (the tolerance)");
    NeutralBlock nb;
    nb.g(64, b.column);
    if (t > 0) nb.add('p', t, b.column);
    m_.execute(nb);
    return;
  }
  if (cycle == "14") {
    // 14 CONTOUR GEOMETRY: 14.1 CONTOUR LABEL1 /2 /3 (any language): the labels, in order
    if (sub != "14.1") return;
    sl_labels_.clear();
    for (std::size_t i = 0; i < b.text.size();) {
      if (!lowering::is_digit(b.text[i])) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j < b.text.size() && lowering::is_digit(b.text[j])) ++j;
      sl_labels_.push_back(std::to_string(std::stol(b.text.substr(i, j - i))));
      i = j;
    }
    if (sl_labels_.empty()) m_.fail(b.column, "CYCL DEF 14.1 names no contour label");
    return;
  }
  if (cycle == "20") {
    // 20 CONTOUR DATA acts at its definition: Q1-Q9
    for (const auto& [target, value] : b.parameters) {
      const ExprNode& t = b.exprs.nodes[target];
      m_.parameters().set_named(b.exprs.name(t.name_begin, t.name_length), eval(b, value));
    }
    auto q = [&](int n) { return m_.parameters().named("_q" + std::to_string(n)).value_or(0.0); };
    SlData d;
    d.depth = q(1);
    d.overlap = q(2) > 0 ? q(2) : 1.0;
    d.side_allowance = q(3);
    d.floor_allowance = q(4);
    d.surface = q(5);
    d.setup = q(6);
    d.clearance = q(7);
    d.direction = q(9) < 0 ? -1.0 : 1.0;
    if (d.depth == 0) m_.fail(b.column, "CYCL DEF 20 needs the milling depth Q1");
    sl_data_ = d;
    return;
  }
  if (auto pattern = table_.patterns.find(cycle); pattern != table_.patterns.end()) {
    point_pattern(b, pattern->second);
    return;
  }
  auto it = table_.cycles.find(cycle);
  if (it == table_.cycles.end()) m_.fail(b.column, "CYCL DEF " + cycle + " is not a cycle ncbridge supports");
  if (sub.empty() || sub == cycle + ".0") {
    cycle_ = cycle;
    cycle_values_.clear();
    defined_since_cycle_def_.clear();
    cycle_def_line_ = m_.line();
    for (const auto& [target, value] : b.parameters) {
      const ExprNode& t = b.exprs.nodes[target];
      const std::string_view name = b.exprs.name(t.name_begin, t.name_length);
      m_.parameters().set_named(name, eval(b, value));
      defined_since_cycle_def_.insert("Q" + std::string(name.substr(2)));
    }
    return;
  }
  // old-style cycle lines: "1.1 SET UP -2", "1.2 DEPTH -20", "1.5 F100" (any language)
  auto role = it->second.roles.find(sub);
  if (role == it->second.roles.end()) m_.fail(b.column, "CYCL DEF " + sub + " is not a line of cycle " + cycle);
  const std::string& text = b.text;
  std::size_t p = 0;
  while (p < text.size() && !(lowering::is_digit(text[p]) || text[p] == '-' || text[p] == '+' || text[p] == '.')) ++p;
  double v = 0;
  if (!lowering::read_decimal(text, p, v)) m_.fail(b.column, "CYCL DEF " + sub + " has no value");
  cycle_values_[role->second] = v;
  defined_since_cycle_def_.insert(sub);
  // old pocket cycles add words to a line: "5.3 PECKG -1.5 F50" (the plunging feed), "5.5 F50 DR-"
  // (the milling feed and the direction)
  if (role->second == "plunge_depth") {
    const std::size_t f = text.find(" F", p);
    double feed = 0;
    std::size_t q = f == std::string::npos ? f : f + 2;
    if (q != std::string::npos && lowering::read_decimal(text, q, feed)) cycle_values_["plunge_feed"] = feed;
  }
  if (const std::size_t dr = text.find("DR"); dr != std::string::npos && dr + 2 < text.size()) {
    cycle_values_["direction"] = text[dr + 2] == '-' ? -1.0 : 1.0;
    // "4.6 F100 DR+ RADIUS 2": the pocket's corner radius follows the direction
    std::size_t q = dr + 3;
    while (q < text.size() && !(lowering::is_digit(text[q]) || text[q] == '.')) ++q;
    double corner = 0;
    if (q < text.size() && lowering::read_decimal(text, q, corner)) cycle_values_["corner_radius"] = corner;
  }
}

// TCH PROBE 0 REFERENCE PLANE (0.0: result parameter and probing axis with direction, "Q5 X-";
// 0.1: the pre-position): rapid to the pre-position, probe along the axis at the probing feed
// (LinuxCNC's G38.3) up to the probe's measuring range, save the touched coordinate in the Q
// parameter, return to the pre-position. The probe is taken to touch at the end of its range
// (there is no machine here). Range and feed are the machine's (MP6130, MP6120): table settings.
// Other probing cycles are a located "not supported: probing cycle N".
bool Runner::touch_probe(const HBlock& b) {
  const std::string& number = b.keyword;
  const std::string cycle = number.substr(0, number.find('.'));
  if (cycle != "0") m_.fail(b.column, "not supported: probing cycle " + cycle + " (TCH PROBE " + number + ")");
  const std::string& text = b.text;
  if (number == "0" || number == "0.0") {
    std::size_t q = text.find('Q');
    while (q != std::string::npos && (q + 1 >= text.size() || !lowering::is_digit(text[q + 1]))) q = text.find('Q', q + 1);
    std::size_t digits = q == std::string::npos ? q : q + 1;
    while (digits != std::string::npos && digits < text.size() && lowering::is_digit(text[digits])) ++digits;
    if (q == std::string::npos || digits == q + 1) m_.fail(b.column, "TCH PROBE 0.0 needs the Q parameter for its result");
    std::size_t p = digits;
    while (p < text.size() && text[p] == ' ') ++p;
    if (p + 1 >= text.size() || (text[p] != 'X' && text[p] != 'Y' && text[p] != 'Z') || (text[p + 1] != '+' && text[p + 1] != '-')) {
      m_.fail(b.column, "TCH PROBE 0.0 needs the probing axis and direction after the Q parameter (X-, Z+, ...)");
    }
    probe_result_ = "_q" + text.substr(q + 1, digits - q - 1);
    probe_axis_ = text[p] - 'X';
    probe_direction_ = text[p + 1] == '+' ? 1.0 : -1.0;
    return true;
  }
  if (number != "0.1") m_.fail(b.column, "TCH PROBE " + number + " is not a line of probing cycle 0");
  if (probe_result_.empty()) m_.fail(b.column, "TCH PROBE 0.1 without its TCH PROBE 0.0");
  std::optional<double> pre[3];
  for (const HWord& w : b.words) {
    if (w.value == kNoExpr) continue;
    const int axis = w.name == "X" ? 0 : w.name == "Y" ? 1 : w.name == "Z" ? 2 : -1;
    if (axis < 0) m_.fail(w.column, "TCH PROBE 0.1 takes the pre-position X, Y, Z");
    pre[axis] = eval(b, w);
  }
  const bool inch = m_.state().units == canonical::Units::Inches;
  const double range = table_.setting("touch_probe_measuring_range_mm", 20.0) / (inch ? 25.4 : 1.0);
  const double probing_feed = table_.setting("touch_probe_feed_mm_per_min", 100.0) / (inch ? 25.4 : 1.0);
  NeutralBlock nb;
  nb.g(0, b.column);
  m_.put_axes(nb, pre[0], pre[1], pre[2], b.column);
  if (m_.execute(nb)) return false;
  const Point3 start = m_.position();
  Point3 end = start;
  (probe_axis_ == 0 ? end.x : probe_axis_ == 1 ? end.y : end.z) += probe_direction_ * range;
  nb.clear();
  nb.g(38.3, b.column);
  nb.add('f', probing_feed, b.column);
  m_.put_axes(nb, end.x, end.y, end.z, b.column);
  if (m_.execute(nb)) return false;
  m_.parameters().set_named(probe_result_, probe_axis_ == 0 ? end.x : probe_axis_ == 1 ? end.y : end.z);
  nb.clear();
  nb.g(0, b.column);
  m_.put_axes(nb, start.x, start.y, start.z, b.column);
  const double f = feed(feed_);
  if (f > 0) nb.add('f', f, b.column);  // the program's feed again
  probe_result_.clear();
  return !m_.execute(nb);
}

// Cycle 208 BORE MILLING: from the hole centre at the set-up clearance, out to the bore circle,
// down on a helix of at most Q334 per turn to the depth, one more full circle at the depth, back
// to the centre and up to the clearance. Climb milling (Q351=+1) runs counter-clockwise with M3.
void Runner::bore_milling(std::map<std::string, double>& v, double r, double bottom, double clearance,
                          std::uint32_t column) {
  const setup::Tool* tool = options_.tools.find(m_.state().tool_in_spindle);
  if (tool == nullptr) m_.fail(column, "Cycle 208 needs the tool's diameter: the tool is not in the tool list");
  const double diameter = v.count("nominal_diameter") ? v["nominal_diameter"] : 0.0;
  const double radius = (diameter - tool->diameter / m_.state().mm_per_unit()) / 2.0;
  if (radius <= 0) m_.fail(column, "Cycle 208: the tool is not smaller than the bore diameter Q335");
  const double pitch = v.count("helix_depth") ? std::fabs(v["helix_depth"]) : 0.0;
  if (pitch <= 0) m_.fail(column, "Cycle 208 needs the infeed per helix Q334");
  const bool ccw = !v.count("climb_or_up_cut") || v["climb_or_up_cut"] >= 0;
  const double f = feed(v.count("plunge_feed") ? v["plunge_feed"] : feed_);
  if (f <= 0) m_.fail(column, "Cycle 208 has no feed rate");
  const Point3 centre = m_.position();
  auto run = [&](NeutralBlock& nb) {
    if (m_.execute(nb)) m_.fail(column, "Cycle 208 ended the program");
    nb.clear();
  };
  NeutralBlock nb;
  if (clearance > centre.z + 1e-9) {
    nb.g(0, column);
    m_.put_axes(nb, std::nullopt, std::nullopt, clearance, column);
    run(nb);
  }
  nb.g(0, column);
  m_.put_axes(nb, std::nullopt, std::nullopt, r, column);
  run(nb);
  nb.g(1, column);
  nb.add('f', f, column);
  m_.put_axes(nb, centre.x + radius, centre.y, std::nullopt, column);
  run(nb);
  const int turns = std::max(1, static_cast<int>(std::ceil((r - bottom) / pitch - 1e-9)));
  m_.put_xy_arc(nb, !ccw, centre.x + radius, centre.y, bottom, centre.x, centre.y, column);
  nb.add('p', turns, column);
  run(nb);
  m_.put_xy_arc(nb, !ccw, centre.x + radius, centre.y, std::nullopt, centre.x, centre.y, column);
  run(nb);
  nb.g(1, column);
  m_.put_axes(nb, centre.x, centre.y, std::nullopt, column);
  run(nb);
  nb.g(0, column);
  m_.put_axes(nb, std::nullopt, std::nullopt, std::max(r, clearance), column);
  run(nb);
}

std::vector<SlContour> Runner::sl_contours(std::uint32_t column) {
  if (sl_labels_.empty()) m_.fail(column, "SL cycle " + cycle_ + " without contours: CYCL DEF 14 names them");
  std::vector<SlContour> contours;
  for (const std::string& label : sl_labels_) {
    auto at = prog().labels.find(label);
    if (at == prog().labels.end()) m_.fail(column, "SL contour LBL " + label + " not found");
    SlContour c;
    Point3 here{};
    bool started = false;
    int side = 0;  // 41 RL, 42 RR
    double pole_x = 0, pole_y = 0;
    bool have_pole = false;
    const std::string where = "SL contour LBL " + label;
    auto arc_points = [&](double cx, double cy, const Point3& end, bool cw) {
      const double r = std::hypot(here.x - cx, here.y - cy);
      const double a0 = std::atan2(here.y - cy, here.x - cx);
      double a1 = std::atan2(end.y - cy, end.x - cx);
      double sweep = cw ? a0 - a1 : a1 - a0;
      while (sweep <= 1e-12) sweep += 2 * std::numbers::pi;
      const double chord = r > 0.005 ? 2 * std::acos(1 - 0.005 / r) : std::numbers::pi / 8;
      const int n = std::max(4, static_cast<int>(std::ceil(sweep / std::min(chord, std::numbers::pi / 8))));
      for (int i = 1; i <= n; ++i) {
        const double a = a0 + (cw ? -1 : 1) * sweep * i / n;
        c.points.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
      }
    };
    HBlock b;
    for (std::size_t i = at->second + 1; i < prog().text.size();) {
      const std::size_t lines = read_block(i, b);
      const std::size_t index = i;
      i += lines;
      if (b.kind == Kind::Label) break;  // LBL 0, or the next label
      if (b.kind == Kind::Empty || b.kind == Kind::Comment) continue;
      if (b.kind != Kind::Path) fail_at(index, b.column, where + ": only contour blocks (L, C, CC, CR) belong here");
      const std::string& k = b.keyword;
      if (k != "L" && k != "C" && k != "CC" && k != "CR") {
        fail_at(index, b.column, where + ": " + k + " in an SL contour is not supported (L, C, CC, CR are)");
      }
      Point3 end = here;
      std::optional<double> radius;
      bool cw = false, dr = false;
      for (const HWord& w : b.words) {
        if (w.name == "RL") side = 41;
        else if (w.name == "RR") side = 42;
        else if (w.name == "DR") {
          dr = true;
          cw = w.sign == '-' || (w.value != kNoExpr && eval(b, w.value) < 0);
        } else if (w.value != kNoExpr) {
          const double val = eval(b, w.value);
          if (w.name == "X") end.x = val;
          else if (w.name == "Y") end.y = val;
          else if (w.name == "IX") end.x = here.x + val;
          else if (w.name == "IY") end.y = here.y + val;
          else if (w.name == "R" && k == "CR") radius = val;
        }
      }
      if (k == "CC") {
        pole_x = end.x;
        pole_y = end.y;
        have_pole = true;
        continue;
      }
      if (!started) {
        if (k != "L") fail_at(index, b.column, where + " must start with a straight line (L) to its first point");
        here = end;
        started = true;
        c.points.push_back({here.x, here.y});
        continue;
      }
      if (k == "L") {
        c.points.push_back({end.x, end.y});
      } else if (k == "C") {
        if (!have_pole || !dr) fail_at(index, b.column, where + ": C needs a CC before it and DR+ or DR-");
        arc_points(pole_x, pole_y, end, cw);
      } else {
        if (!radius || !dr) fail_at(index, b.column, where + ": CR needs R and DR+ or DR-");
        double cx = 0, cy = 0;
        if (!radius_arc_centre(here, end, *radius, cw, cx, cy)) fail_at(index, b.column, where + ": CR radius too small");
        arc_points(cx, cy, end, cw);
      }
      here = end;
    }
    // a closed contour: the last point is the first
    if (c.points.size() > 1 && std::hypot(c.points.back().x - c.points.front().x, c.points.back().y - c.points.front().y) < 1e-6) {
      c.points.pop_back();
    }
    if (c.points.size() < 3) m_.fail(column, where + " is not a closed contour");
    if (side == 0) m_.fail(column, where + " has no radius compensation (RL/RR): pocket or island cannot be told");
    double area = 0;
    for (std::size_t j = 0; j < c.points.size(); ++j) {
      const SlPoint& p = c.points[j];
      const SlPoint& q = c.points[(j + 1) % c.points.size()];
      area += p.x * q.y - q.x * p.y;
    }
    // the tool inside: RL counter-clockwise, RR clockwise
    c.pocket = (side == 41) == (area > 0);
    contours.push_back(std::move(c));
  }
  return contours;
}

void Runner::sl_cycle(std::map<std::string, double>& v, std::uint32_t column) {
  if (!sl_data_) m_.fail(column, "SL cycle " + cycle_ + " without its CONTOUR DATA (CYCL DEF 20)");
  const setup::Tool* tool = options_.tools.find(m_.state().tool_in_spindle);
  if (tool == nullptr) m_.fail(column, "SL cycle " + cycle_ + " needs the tool's diameter: the tool is not in the tool list");
  SlData d = *sl_data_;
  SlCall c;
  c.operation = cycle_ == "22" ? SlOperation::RoughOut : cycle_ == "23" ? SlOperation::FloorFinishing : SlOperation::SideFinishing;
  c.plunge_depth = v.count("plunge_depth") ? v["plunge_depth"] : 0.0;
  c.plunge_feed = feed(v.count("plunge_feed") ? v["plunge_feed"] : feed_);
  c.milling_feed = feed(v.count("milling_feed") ? v["milling_feed"] : feed_);
  c.finish_allowance = v.count("finish_allowance") ? v["finish_allowance"] : 0.0;
  c.tool_radius = tool->diameter / m_.state().mm_per_unit() / 2.0;
  if (cycle_ == "24" && v.count("direction") && v["direction"] != 0) d.direction = v["direction"] < 0 ? -1.0 : 1.0;
  if (cycle_ == "22" && v.count("coarse_tool") && v["coarse_tool"] != 0) {
    m_.comment("ncbridge: cycle 22 Q18 (coarse roughing tool " + std::to_string(std::lround(v["coarse_tool"])) +
               "): the whole area is cleared again, not only what that tool left");
  }
  sl_machine(m_, sl_contours(column), d, c, column);
}

// 251 RECTANGULAR POCKET, 252 CIRCULAR POCKET, 253 SLOT MILLING at the current position: the
// shape as one SL pocket contour, roughed out (Q215 0 or 1) from the inside out layer by layer of
// Q202, then (Q215 0 or 2) its walls finished in infeeds of Q338 and its floor, where the
// allowances Q368/Q369 leave something, at Q385; at the end up to the 2nd set-up clearance.
void Runner::pocket_cycle(std::map<std::string, double>& v, std::uint32_t column) {
  const setup::Tool* tool = options_.tools.find(m_.state().tool_in_spindle);
  if (tool == nullptr) m_.fail(column, "Cycle " + cycle_ + " needs the tool's diameter: the tool is not in the tool list");
  auto value = [&](const char* role, double fallback) { return v.count(role) ? v[role] : fallback; };
  const Point3 here = m_.position();
  SlContour c;
  c.pocket = true;
  auto circle = [&](double cx, double cy, double r, double from, double sweep) {
    const double chord = r > 0.005 ? 2 * std::acos(1 - 0.005 / r) : std::numbers::pi / 8;
    const int n = std::max(8, static_cast<int>(std::ceil(std::fabs(sweep) / std::min(chord, std::numbers::pi / 16))));
    for (int i = 0; i < n; ++i) {
      const double a = from + sweep * i / n;
      c.points.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
    }
  };
  const double rotation = value(cycle_ == "253" ? "rotation" : "rotation", 0.0) * kDeg;
  auto place = [&](double x, double y, double ox, double oy) -> SlPoint {
    // (x, y) relative to the shape's centre, turned, the centre at the reference point + (ox, oy)
    const double cr = std::cos(rotation), sr = std::sin(rotation);
    const double px = x + ox, py = y + oy;
    return {here.x + cr * px - sr * py, here.y + sr * px + cr * py};
  };
  if (cycle_ == "252") {
    const double d = value("diameter", 0.0);
    if (d <= 0) m_.fail(column, "Cycle 252 needs the circle diameter Q223");
    circle(here.x, here.y, d / 2.0, 0.0, 2 * std::numbers::pi);
  } else {
    const double l = value("first_side", 0.0), w = value("second_side", 0.0);
    if (l <= 0 || w <= 0) m_.fail(column, "Cycle " + cycle_ + " needs both side lengths Q218 and Q219");
    const int position = static_cast<int>(std::lround(value("position", 0.0)));
    double ox = 0, oy = 0;  // from the reference point to the centre, before turning
    if (cycle_ == "251") {
      const double rc = std::min(value("corner_radius", 0.0), std::min(l, w) / 2.0);
      switch (position) {
        case 0: break;
        case 1: ox = l / 2; oy = w / 2; break;
        case 2: ox = -l / 2; oy = w / 2; break;
        case 3: ox = -l / 2; oy = -w / 2; break;
        case 4: ox = l / 2; oy = -w / 2; break;
        default: m_.fail(column, "Cycle 251: Q367 must be 0-4");
      }
      const double hx = l / 2 - rc, hy = w / 2 - rc;
      const SlPoint corners[4] = {{hx, -hy}, {hx, hy}, {-hx, hy}, {-hx, -hy}};
      for (int k = 0; k < 4; ++k) {
        const double from = (k * 90.0 - 90.0) * kDeg;
        if (rc > 1e-9) {
          const int n = 8;
          for (int i = 0; i <= n; ++i) {
            const double a = from + (std::numbers::pi / 2) * i / n;
            c.points.push_back(place(corners[k].x + rc * std::cos(a), corners[k].y + rc * std::sin(a), ox, oy));
          }
        } else {
          c.points.push_back(place(corners[k].x, corners[k].y, ox, oy));
        }
      }
    } else {
      if (w >= l) m_.fail(column, "Cycle 253: the slot width Q219 must be less than its length Q218");
      const double half = l / 2 - w / 2;  // centre to the centre of each end circle
      switch (position) {
        case 0: break;
        case 1: ox = l / 2; break;
        case 2: ox = half; break;
        case 3: ox = -half; break;
        case 4: ox = -l / 2; break;
        default: m_.fail(column, "Cycle 253: Q367 must be 0-4");
      }
      for (int end = 0; end < 2; ++end) {
        const double cx = end == 0 ? half : -half;
        const double from = end == 0 ? -std::numbers::pi / 2 : std::numbers::pi / 2;
        const int n = 16;
        for (int i = 0; i <= n; ++i) {
          const double a = from + std::numbers::pi * i / n;
          c.points.push_back(place(cx + w / 2 * std::cos(a), w / 2 * std::sin(a), ox, oy));
        }
      }
    }
  }
  SlData d;
  d.depth = value("depth", 0.0);
  d.overlap = value("overlap", 1.0) > 0 ? value("overlap", 1.0) : 1.0;
  d.side_allowance = value("side_allowance", 0.0);
  d.floor_allowance = value("floor_allowance", 0.0);
  d.surface = value("surface", 0.0);
  d.setup = value("setup_clearance", 0.0);
  d.clearance = d.surface + std::max(std::fabs(d.setup), std::fabs(value("second_setup_clearance", 0.0)));
  d.direction = value("climb_or_up_cut", 1.0) < 0 ? -1.0 : 1.0;
  if (d.depth == 0) m_.fail(column, "Cycle " + cycle_ + " needs the depth Q201");
  const int operation = static_cast<int>(std::lround(value("operation", 0.0)));
  if (operation < 0 || operation > 2) m_.fail(column, "Cycle " + cycle_ + ": Q215 must be 0, 1 or 2");
  const std::vector<SlContour> contours = {c};
  SlCall call;
  call.tool_radius = tool->diameter / m_.state().mm_per_unit() / 2.0;
  call.plunge_feed = feed(value("plunge_feed", feed_));
  if (operation != 2) {
    call.operation = SlOperation::RoughOut;
    call.plunge_depth = value("plunge_depth", 0.0);
    call.milling_feed = feed(value("milling_feed", feed_));
    sl_machine(m_, contours, d, call, column);
  }
  if (operation != 1) {
    const double finishing = feed(value("finishing_feed", value("milling_feed", feed_)) > 0
                                      ? value("finishing_feed", value("milling_feed", feed_))
                                      : value("milling_feed", feed_));
    call.milling_feed = finishing;
    if (d.side_allowance > 0 || operation == 2) {
      call.operation = SlOperation::SideFinishing;
      call.plunge_depth = value("finishing_infeed", 0.0) != 0 ? value("finishing_infeed", 0.0) : std::fabs(d.depth);
      SlData walls = d;
      walls.side_allowance = 0;
      sl_machine(m_, contours, walls, call, column);
    }
    if (d.floor_allowance > 0 || operation == 2) {
      call.operation = SlOperation::FloorFinishing;
      SlData floor = d;
      floor.side_allowance = 0;
      sl_machine(m_, contours, floor, call, column);
    }
  }
}

// 220 POLAR PATTERN and 221 CARTESIAN PATTERN act at their definition: the cycle defined before
// them runs at each point, the tool moving between points at the 2nd set-up clearance (Q301 1)
// or the set-up clearance (Q301 0) above the surface; 221 runs line by line.
void Runner::point_pattern(const HBlock& b, const lowering::CycleEntry& pattern) {
  if (cycle_.empty()) m_.fail(b.column, "CYCL DEF " + b.keyword + " (" + pattern.name + ") with no cycle defined before it");
  for (const auto& [target, value] : b.parameters) {
    const ExprNode& t = b.exprs.nodes[target];
    m_.parameters().set_named(b.exprs.name(t.name_begin, t.name_length), eval(b, value));
  }
  std::map<std::string, double> p;
  for (const auto& [q, role] : pattern.roles) p[role] = m_.parameters().named("_q" + q.substr(1)).value_or(0.0);
  std::vector<std::pair<double, double>> points;
  if (b.keyword == "221") {
    const int columns = static_cast<int>(std::lround(p["columns"])), lines = static_cast<int>(std::lround(p["lines"]));
    if (columns < 1 || lines < 1) m_.fail(b.column, "CYCL DEF 221 needs at least one column (Q242) and line (Q243)");
    if (static_cast<std::uint64_t>(columns) * static_cast<std::uint64_t>(lines) > options_.max_loop_iterations) {
      m_.fail(b.column, "CYCL DEF 221: more points than the iteration limit");
    }
    const double a = p["rotation"] * kDeg;
    for (int line = 0; line < lines; ++line) {
      for (int col = 0; col < columns; ++col) {
        const double dx = col * p["spacing_1"], dy = line * p["spacing_2"];
        points.emplace_back(p["start_1"] + std::cos(a) * dx - std::sin(a) * dy, p["start_2"] + std::sin(a) * dx + std::cos(a) * dy);
      }
    }
  } else {
    const int count = static_cast<int>(std::lround(p["count"]));
    if (count < 1) m_.fail(b.column, "CYCL DEF 220 needs the number of points Q241");
    if (static_cast<std::uint64_t>(count) > options_.max_loop_iterations) m_.fail(b.column, "CYCL DEF 220: more points than the iteration limit");
    double step = p["angle_step"];
    if (step == 0 && count > 1) {
      const double span = p["stop_angle"] - p["start_angle"];
      step = std::fabs(span) >= 360.0 - 1e-9 || span == 0 ? 360.0 / count : span / (count - 1);
    }
    for (int i = 0; i < count; ++i) {
      const double a = (p["start_angle"] + i * step) * kDeg;
      points.emplace_back(p["centre_1"] + p["diameter"] / 2 * std::cos(a), p["centre_2"] + p["diameter"] / 2 * std::sin(a));
    }
  }
  const double travel = p["surface"] + (p["move_to_clearance"] != 0 ? std::max(std::fabs(p["setup_clearance"]), std::fabs(p["second_setup_clearance"]))
                                                                     : std::fabs(p["setup_clearance"]));
  for (const auto& [x, y] : points) {
    NeutralBlock nb;
    if (m_.position().z < travel - 1e-9) {
      nb.g(0, b.column);
      m_.put_axes(nb, std::nullopt, std::nullopt, travel, b.column);
      if (m_.execute(nb)) return;
      nb.clear();
    }
    nb.g(0, b.column);
    m_.put_axes(nb, x, y, std::nullopt, b.column);
    if (m_.execute(nb)) return;
    cycle_call(b.column);
  }
}

void Runner::cycle_call(std::uint32_t column) {
  if (cycle_.empty()) m_.fail(column, "Cycle call with no cycle defined");
  const lowering::CycleEntry& entry = table_.cycles.at(cycle_);
  for (const std::string& p : entry.required) {
    if (!defined_since_cycle_def_.count(p)) {
      m_.fail(column, "Cycle " + cycle_ + " (" + entry.name + ") called without " + p + " in its CYCL DEF (line " +
                          std::to_string(cycle_def_line_) + ")");
    }
  }
  std::map<std::string, double> v = cycle_values_;
  for (const auto& [q, role] : entry.roles) {
    if (q.empty() || q[0] != 'Q') continue;  // old cycles are defined by numbered lines, not Q parameters
    std::string name = "_q" + q.substr(1);
    v[role] = m_.parameters().named(name).value_or(0.0);
  }
  auto get = [&](const char* role) -> double {
    auto it = v.find(role);
    if (it == v.end()) m_.fail(column, "Cycle " + cycle_ + ": " + role + " is not set");
    return it->second;
  };
  Point3 here = m_.position();
  NeutralBlock nb;
  double r, bottom, clearance;
  int code = 81;
  double peck = 0, dwell = 0, feed_rate = 0;
  if (cycle_ == "251" || cycle_ == "252" || cycle_ == "253") {
    pocket_cycle(v, column);
    return;
  }
  if (cycle_ == "22" || cycle_ == "23" || cycle_ == "24") {
    sl_cycle(v, column);
    return;
  }
  if (cycle_ == "4") {
    // POCKET MILLING (old): the rectangle about the starting position, roughed out from the
    // inside out layer by layer below the surface, back to the starting position at the end
    const setup::Tool* tool = options_.tools.find(m_.state().tool_in_spindle);
    if (tool == nullptr) m_.fail(column, "Cycle 4 needs the tool's diameter: the tool is not in the tool list");
    const double l = std::fabs(get("first_side")), w = std::fabs(get("second_side"));
    const double rc = std::min(v.count("corner_radius") ? std::fabs(v["corner_radius"]) : 0.0, std::min(l, w) / 2.0);
    SlContour c;
    const double hx = l / 2 - rc, hy = w / 2 - rc;
    const double corners[4][2] = {{hx, -hy}, {hx, hy}, {-hx, hy}, {-hx, -hy}};
    for (int k = 0; k < 4; ++k) {
      const int n = rc > 1e-9 ? 8 : 0;
      for (int i = 0; i <= n; ++i) {
        const double a = (k * 90.0 - 90.0) * kDeg + (std::numbers::pi / 2) * (n == 0 ? 0 : i) / std::max(n, 1);
        c.points.push_back({here.x + corners[k][0] + rc * std::cos(a), here.y + corners[k][1] + rc * std::sin(a)});
      }
    }
    SlData d;
    d.setup = std::fabs(get("setup_clearance"));
    d.surface = here.z - d.setup;
    d.depth = -std::fabs(get("depth"));
    d.clearance = here.z;
    d.overlap = table_.setting("pocket_overlap_factor", 1.0);
    d.direction = v.count("direction") && v["direction"] < 0 ? -1.0 : 1.0;
    SlCall call;
    call.operation = SlOperation::RoughOut;
    call.plunge_depth = get("plunge_depth");
    call.plunge_feed = feed(v.count("plunge_feed") ? v["plunge_feed"] : feed_);
    call.milling_feed = feed(get("milling_feed"));
    call.tool_radius = tool->diameter / m_.state().mm_per_unit() / 2.0;
    sl_machine(m_, {c}, d, call, column);
    NeutralBlock back;
    back.g(0, column);
    m_.put_axes(back, here.x, here.y, std::nullopt, column);
    if (!m_.execute(back)) {
      back.clear();
      back.g(0, column);
      m_.put_axes(back, std::nullopt, std::nullopt, here.z, column);
      m_.execute(back);
    }
    return;
  }
  if (cycle_ == "5") {
    // CIRCULAR POCKET: the tool is at the pocket centre, at the set-up clearance
    const setup::Tool* tool = options_.tools.find(m_.state().tool_in_spindle);
    if (tool == nullptr) m_.fail(column, "Cycle 5 needs the tool's diameter: the tool is not in the tool list");
    CircularPocket p;
    p.cx = here.x;
    p.cy = here.y;
    p.start_z = here.z;
    p.surface_z = here.z - std::fabs(get("setup_clearance"));
    p.bottom_z = p.surface_z - std::fabs(get("depth"));
    p.plunge = std::fabs(get("plunge_depth"));
    p.plunge_feed = feed(v.count("plunge_feed") ? v["plunge_feed"] : feed_);
    p.radius = std::fabs(get("radius"));
    p.feed = feed(get("milling_feed"));
    p.clockwise = v.count("direction") && v["direction"] < 0;
    p.tool_radius = tool->diameter / m_.state().mm_per_unit() / 2.0;
    p.overlap = table_.setting("pocket_overlap_factor", 1.0);
    circular_pocket(m_, p, column);
    return;
  }
  if (cycle_ == "1") {
    double setup = get("setup_clearance"), depth = get("depth");
    // the tool starts at the set-up clearance above the surface; the cycle works towards -Z
    r = here.z;
    bottom = here.z - std::fabs(setup) - std::fabs(depth);
    peck = v.count("plunge_depth") ? std::fabs(v["plunge_depth"]) : 0.0;
    dwell = v.count("dwell_bottom") ? v["dwell_bottom"] : 0.0;
    feed_rate = get("plunge_feed");
    clearance = r;
    // a plunging depth of at least the depth is plain drilling (FreeCAD's post writes INCR = DEPTH)
    if (peck > 0 && peck < std::fabs(depth) - 1e-9) code = 83;
    else if (dwell > 0) code = 82;
    nb.g(98, column);
  } else {
    double surface = get("surface"), setup = std::fabs(get("setup_clearance"));
    double depth = get("depth");
    double second = v.count("second_setup_clearance") ? std::fabs(v["second_setup_clearance"]) : 0.0;
    r = surface + setup;
    bottom = surface - std::fabs(depth);
    clearance = surface + std::max(setup, second);
    feed_rate = v.count("plunge_feed") ? v["plunge_feed"] : feed_;
    dwell = v.count("dwell_bottom") ? v["dwell_bottom"] : 0.0;
    double plunge = v.count("plunge_depth") ? std::fabs(v["plunge_depth"]) : 0.0;
    if (cycle_ == "200" || cycle_ == "203" || cycle_ == "205") {
      if (plunge > 0 && plunge < std::fabs(depth) - 1e-9) {
        peck = plunge;
        code = (cycle_ == "203" && v.count("breaks") && v["breaks"] > 0) ? 73 : 83;
      } else {
        code = dwell > 0 ? 82 : 81;
      }
      if (v.count("decrement") && v["decrement"] != 0) {
        m_.comment("ncbridge: cycle " + cycle_ + " decrement Q212 is not applied (equal pecks used)");
      }
    } else if (cycle_ == "201") {
      code = dwell > 0 ? 89 : 85;
    } else if (cycle_ == "207") {
      code = 84;
      double pitch = get("pitch");
      feed_rate = std::fabs(pitch) * m_.state().speed;
      if (feed_rate <= 0) m_.fail(column, "Cycle 207 needs a spindle speed to feed the pitch");
      if (pitch < 0) code = 74;  // a left-hand thread: the spindle turns counter-clockwise going in
    } else if (cycle_ == "208") {
      bore_milling(v, r, bottom, clearance, column);
      return;
    } else {
      m_.fail(column, "Cycle " + cycle_ + " (" + entry.name + ") is read but its motion is not supported yet");
    }
    if (clearance > here.z + 1e-9) {
      NeutralBlock up;
      up.g(0, column);
      m_.put_axes(up, std::nullopt, std::nullopt, clearance, column);
      if (m_.execute(up)) return;
    }
    nb.g(second > setup ? 98 : 99, column);
  }
  double f = cycle_ == "207" ? feed_rate : feed(feed_rate);
  if (f <= 0) m_.fail(column, "Cycle " + cycle_ + " has no feed rate");
  nb.add('f', f, column);
  nb.g(code, column);
  Point3 e = m_.frame.to_executor({here.x, here.y, 0});
  nb.add('x', e.x, column);
  nb.add('y', e.y, column);
  nb.add('z', bottom + m_.frame.offset.z, column);
  nb.add('r', r + m_.frame.offset.z, column);
  if (code == 83 || code == 73) nb.add('q', peck, column);
  if (code == 82 || code == 89) nb.add('p', dwell, column);
  // left-hand tapping with the spindle programmed clockwise: reversed for the cycle, as the
  // control does, and back after it
  const bool reverse = code == 74 && m_.state().spindle == canonical::Direction::Clockwise;
  if (reverse) {
    NeutralBlock ccw;
    ccw.m(4, column);
    m_.execute(ccw);
  }
  m_.execute(nb);
  // the control's feed for following blocks is the last programmed F, not the cycle's
  NeutralBlock cancel;
  cancel.g(80, column);
  if (reverse) cancel.m(3, column);
  m_.execute(cancel);
}

}  // namespace

void run(ProgramText program, const Options& options, canonical::Sink& sink) {
  Runner runner(options, sink);
  runner.run(std::move(program));
}

}  // namespace ncbridge::interpreter::heidenhain
