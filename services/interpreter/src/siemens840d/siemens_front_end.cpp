// SINUMERIK 840D: each block is read into items (address words with expression values, calls
// with argument lists, assignments, keywords), evaluated, then lowered onto neutral blocks.
#include "siemens840d/siemens_front_end.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numbers>
#include <optional>
#include <set>

#include "block_model.hpp"
#include "expression.hpp"
#include "lowering/dialect_machine.hpp"
#include "lowering/dialect_table.hpp"
#include "lowering/infix_expression.hpp"
#include "ncbridge/common/error.hpp"
#include "siemens840d/block_reader.hpp"
#include "siemens840d/pocket_milling.hpp"

namespace ncbridge::interpreter::siemens840d {

using lowering::DialectMachine;
using lowering::InfixParser;
using lowering::NeutralBlock;
using lowering::Point3;
using lowering::ProgramText;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct File {
  ProgramText text;
  std::map<std::string, std::vector<std::size_t>> labels;  // a label may be written again further on
};

// What a ShopMill step is, for the message that refuses it.
std::string shopmill_step_name(const std::string& step) {
  static const std::map<std::string, std::string> kNames = {
      {"E_MI_PL", "face milling"}, {"E_DR", "drilling"}, {"E_DR_BGF", "boring"}, {"E_DR_REA", "reaming"},
      {"E_DR_SIN", "centring"}, {"E_DR_TAP", "tapping"}, {"E_DR_O1", "deep hole drilling"},
      {"E_PS_XYZ", "positions"}, {"E_PS_POL", "positions on a circle"}, {"E_PS_CIR", "positions on a circle"},
      {"E_PS_MRX", "position matrix"}, {"E_PS_FRA", "position frame"}, {"E_PS_SEQ", "position row"},
      {"E_PS_ROW", "position row"}, {"E_PS_HIN", "obstacle"}, {"E_CON", "contour"}, {"E_MI_CON", "contour milling"},
      {"E_MI_TR", "path milling"}, {"E_PO_REC", "rectangular pocket"}, {"E_PO_CIR", "circular pocket"},
      {"E_SL_LON", "longitudinal slot"}, {"E_SL_CIR", "circumferential slot"}, {"E_CONFIG", "configuration"},
      {"E_TR_ORI", "zero offset"}, {"E_TR_OFF", "zero offset"}, {"E_MI_TXT", "engraving"}};
  auto it = kNames.find(step);
  return it == kNames.end() ? "a ShopMill step" : it->second;
}

class Runner {
 public:
  Runner(const Options& options, canonical::Sink& sink)
      : options_(options), table_(lowering::load_dialect_table("siemens840d")), m_(options, sink, table_), reader_(variables_) {}
  void run(ProgramText program);

 private:
  struct Call {
    std::size_t file, return_pc, start_pc;
    int remaining;
  };
  std::size_t add_file(ProgramText text);
  bool step();
  bool run_block(SBlock& b);
  double eval(const SBlock& b, ExprRef ref) {
    if (ref == kNoExpr) m_.fail(1, "A word of this block has no value");
    return evaluate(b.exprs, ref, m_.parameters(), m_.file_name());
  }
  void jump(const std::string& label, const std::string& how, std::uint32_t column);
  void call_subprogram(const std::string& name, int repeats, std::uint32_t column,
                       const std::vector<std::optional<double>>& arguments = {});
  std::optional<std::filesystem::path> subprogram_file(const std::string& name) const;
  void bind_parameters(std::size_t file, const std::vector<std::optional<double>>& arguments, std::uint32_t column);
  std::string message_text(const Item& msg, const SBlock& b);
  bool return_from_subprogram();
  void cycle(const Item& call, const SBlock& b, bool modal_call);
  void hole_pattern(const Item& call, const SBlock& b);
  void pocket(const Item& call, const SBlock& b);
  bool run_control(SBlock& b);
  std::string skip_structure(const std::vector<std::string>& opens, const std::vector<std::string>& ends,
                             std::uint32_t column);
  struct Structure {
    std::string kind;  // WHILE, REPEAT, LOOP, FOR
    std::size_t file, line;
    double to;
    std::string variable;
  };
  std::vector<Structure> structures_;
  void run_cycle_here(std::uint32_t column);
  void measure(const Item& word, const SBlock& b, NeutralBlock& nb, std::optional<double> x, std::optional<double> y,
               std::optional<double> z, bool arc);

  const Options& options_;
  lowering::DialectTable table_;
  DialectMachine m_;
  std::set<std::string> variables_;
  Reader reader_;
  std::vector<File> files_;
  std::size_t file_ = 0, pc_ = 0;
  std::vector<Call> calls_;
  std::uint64_t steps_ = 0;
  std::size_t last_index_ = 0;
  std::uint64_t backward_jumps_ = 0;

  bool incremental_ = false;
  int motion_ = 0;  // 0, 1, 2, 3
  Point3 pole_;                  // G110/G111/G112 (the workpiece origin until one is set)
  double polar_radius_ = 0, polar_angle_ = 0;  // RP=, AP= (modal)
  int plane_ = 17;
  Point3 tangent_{1, 0, 0};
  bool have_tangent_ = false;
  int measured_probe_ = 0;  // MEAS/MEAW in the block being run: its probe
  std::optional<std::string> modal_cycle_;  // MCALL
  std::map<std::string, double> modal_cycle_args_;
  std::string cycle_name_;
  std::map<std::string, double> cycle_args_;
};

std::size_t Runner::add_file(ProgramText text) {
  File f;
  f.text = std::move(text);
  for (std::size_t i = 0; i < f.text.size(); ++i) {
    std::string_view l = f.text.line(i);
    std::size_t colon = l.find(':');
    if (colon == std::string_view::npos) continue;
    std::size_t p = 0;
    while (p < l.size() && (l[p] == ' ' || l[p] == '\t')) ++p;
    if (p + 1 < l.size() && lowering::upper(l[p]) == 'N' && lowering::is_digit(l[p + 1])) {
      ++p;
      while (p < l.size() && lowering::is_digit(l[p])) ++p;
      while (p < l.size() && l[p] == ' ') ++p;
    }
    std::size_t q = p;
    while (q < l.size() && ident_char(l[q])) ++q;
    if (q > p && q == colon && lowering::is_alpha(l[p])) f.labels[up(l.substr(p, q - p))].push_back(i);
  }
  files_.push_back(std::move(f));
  std::size_t index = files_.size() - 1;
  m_.announce_file(static_cast<std::uint32_t>(index), files_[index].text.name);
  return index;
}

void Runner::run(ProgramText program) {
  // R parameters exist from the start, at 0 (as on the control)
  for (int i = 0; i < 1000; ++i) m_.parameters().set_named("_r" + std::to_string(i), 0.0);
  for (int probe = 1; probe <= 2; ++probe) m_.parameters().set_named(Reader::measured_key(probe), 0.0);
  add_file(std::move(program));
  m_.at(0, files_[0].text.name, 0);
  m_.start();
  while (step()) {
  }
}

bool Runner::step() {
  const File& f = files_[file_];
  if (pc_ >= f.text.size()) {
    m_.at(static_cast<std::uint32_t>(file_), f.text.name, static_cast<std::uint32_t>(f.text.size()));
    if (!calls_.empty()) {
      // a subprogram file may end without M17/RET
      return return_from_subprogram();
    }
    if (!structures_.empty()) {
      const Structure& open = structures_.back();
      const char* end = open.kind == "WHILE" ? "ENDWHILE" : open.kind == "REPEAT" ? "UNTIL" : open.kind == "LOOP" ? "ENDLOOP" : "ENDFOR";
      throw InputError({files_[open.file].text.name, static_cast<std::uint32_t>(open.line + 1), 1},
                       open.kind + " without its " + end);
    }
    if (options_.require_program_end) m_.fail(1, "File ended with no program end (M30/M2)");
    m_.warn(1, "File ended with no program end (M30/M2): the program ends here");
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
  SBlock b;
  reader_.declared_.clear();
  reader_.read(f.text.line(index), static_cast<std::uint32_t>(index + 1), f.text.name, b);
  m_.at(static_cast<std::uint32_t>(file_), f.text.name, static_cast<std::uint32_t>(index + 1), b.n);
  for (const std::string& name : reader_.declared_) variables_.insert(name);
  return run_block(b);
}

// GOTOF searches forward from the block for the label, GOTOB backward, GOTO (and GOTOC) forward
// and then backward: a label written in several sections is the nearest one that way.
void Runner::jump(const std::string& label, const std::string& how, std::uint32_t column) {
  const File& f = files_[file_];
  auto it = f.labels.find(label);
  if (it == f.labels.end()) m_.fail(column, how + " " + label + ": no label " + label + ": in this program");
  const std::size_t here = pc_ - 1;
  std::optional<std::size_t> forward, backward;
  for (std::size_t line : it->second) {
    if (line > here && !forward) forward = line;
    if (line < here) backward = line;
  }
  if (how == "GOTOF" && !forward) m_.fail(column, "GOTOF " + label + ": the label is not after this block");
  if (how == "GOTOB" && !backward) m_.fail(column, "GOTOB " + label + ": the label is not before this block");
  if (how == "GOTOB") pc_ = *backward;
  else if (forward) pc_ = *forward;
  else if (backward) pc_ = *backward;
  else m_.fail(column, how + " " + label + ": the label is this block");
}

std::optional<std::filesystem::path> Runner::subprogram_file(const std::string& name) const {
  std::vector<std::filesystem::path> dirs = options_.subroutine_path;
  dirs.push_back(std::filesystem::path(files_[file_].text.name).parent_path());
  dirs.push_back(std::filesystem::path(files_[0].text.name).parent_path());
  for (const auto& dir : dirs) {
    for (const char* ext : {".SPF", ".spf", ".MPF", ".mpf", ""}) {
      std::filesystem::path candidate = (dir.empty() ? std::filesystem::path(".") : dir) / (name + ext);
      std::error_code ec;
      if (std::filesystem::is_regular_file(candidate, ec)) return candidate;
    }
  }
  return std::nullopt;
}

void Runner::call_subprogram(const std::string& name, int repeats, std::uint32_t column,
                             const std::vector<std::optional<double>>& arguments) {
  if (calls_.size() >= 16) m_.fail(column, "Too many nested subprogram calls");
  const auto candidate = subprogram_file(name);
  if (!candidate) {
    m_.fail(column, "Subprogram " + name + " not found (" + name + ".SPF in the subroutine path or beside the program)");
  }
  std::size_t index = files_.size();
  for (std::size_t i = 0; i < files_.size(); ++i) {
    if (files_[i].text.name == candidate->string()) index = i;
  }
  if (index == files_.size()) index = add_file(ProgramText::from_file(*candidate));
  bind_parameters(index, arguments, column);
  calls_.push_back(Call{file_, pc_, 0, repeats - 1});
  file_ = index;
  pc_ = 0;
}

// The called program's PROC NAME(INT A, REAL B) takes the call's arguments in order; an argument
// left out keeps the parameter at 0 (the control's default for an unassigned value).
void Runner::bind_parameters(std::size_t file, const std::vector<std::optional<double>>& arguments,
                             std::uint32_t column) {
  const ProgramText& text = files_[file].text;
  std::vector<std::string> names;
  for (std::size_t i = 0; i < text.size() && i < 64; ++i) {
    std::string_view l = text.line(i);
    std::size_t p = 0;
    while (p < l.size() && (l[p] == ' ' || l[p] == '\t')) ++p;
    if (p >= l.size() || l[p] == ';') continue;
    SBlock proc;
    reader_.declared_.clear();
    reader_.read(l, static_cast<std::uint32_t>(i + 1), text.name, proc);
    if (proc.control == "PROC") names = proc.proc_parameters;
    break;
  }
  if (arguments.size() > names.size()) {
    m_.fail(column, "Call with " + std::to_string(arguments.size()) + " arguments: " + text.name + " declares " +
                        std::to_string(names.size()) + " (PROC)");
  }
  for (std::size_t i = 0; i < names.size(); ++i) {
    variables_.insert(names[i]);
    const double v = i < arguments.size() && arguments[i] ? *arguments[i] : 0.0;
    m_.parameters().set_named(Reader::variable_key(names[i]), v);
  }
}

std::string Runner::message_text(const Item& msg, const SBlock& b) {
  if (msg.message.empty()) return msg.text;
  std::string text;
  for (const auto& [part, value] : msg.message) {
    if (value == kNoExpr) {
      text += part;
      continue;
    }
    const double v = eval(b, value);
    char number[64];
    std::snprintf(number, sizeof number, "%.6g", v);
    text += number;
  }
  return text;
}

bool Runner::return_from_subprogram() {
  if (calls_.empty()) return false;  // M17/RET in the main program ends it
  Call& c = calls_.back();
  if (c.remaining > 0) {
    --c.remaining;
    pc_ = c.start_pc;
    return true;
  }
  file_ = c.file;
  pc_ = c.return_pc;
  calls_.pop_back();
  return true;
}

bool Runner::run_block(SBlock& b) {
  if (b.control == "IF") {
    bool taken = eval(b, b.condition) != 0.0;
    for (const Item& it : b.items) {
      // IF condition GOTOx label: the jump is the only statement the condition guards
      if (it.kind == Item::Kind::Keyword && it.name.rfind("GOTO", 0) == 0) {
        if (taken) jump(it.text, it.name, it.column);
        return true;
      }
    }
    if (!taken) {
      // on to the block after the matching ELSE, or after the matching ENDIF
      skip_structure({"IF"}, {"ELSE", "ENDIF"}, b.control_column);
    }
    return true;
  }
  if (!b.control.empty()) return run_control(b);
  NeutralBlock nb;
  if (b.has_comment) {
    nb.comment = b.comment;
    nb.has_comment = true;
  }
  std::map<std::string, const Item*> words;
  std::vector<const Item*> gs, ms;
  bool supa = false, g53 = false, cip = false, ct = false;
  std::optional<std::string> frame_op;
  std::uint32_t frame_column = 1;
  const Item* cycle_call = nullptr;
  const Item* pattern_call = nullptr;
  const Item* milling_call = nullptr;
  bool mcall = false, program_return = false;
  std::string subprogram;
  std::vector<std::optional<double>> sub_arguments;
  bool shopmill_end = false;
  std::optional<std::string> goto_label, goto_how;
  std::uint32_t goto_column = 0, sub_column = 0;
  for (const Item& it : b.items) {
    switch (it.kind) {
      case Item::Kind::Assign:
        m_.parameters().set_named(it.name.size() > 1 && it.name[0] == 'R' &&
                                          std::all_of(it.name.begin() + 1, it.name.end(), lowering::is_digit)
                                      ? "_r" + it.name.substr(1)
                                      : Reader::variable_key(it.name),
                                  eval(b, it.value));
        break;
      case Item::Kind::Word:
        if (it.name == "G") gs.push_back(&it);
        else if (it.name == "M") ms.push_back(&it);
        else {
          if (words.count(it.name)) m_.fail(it.column, "Address " + it.name + " programmed twice");
          words[it.name] = &it;
        }
        break;
      case Item::Kind::Call: {
        const std::string& n = it.name;
        if (n == "MSG") {
          const std::string text = message_text(it, b);
          if (!text.empty()) m_.message(text);
        } else if (n == "E_HEAD") {
          // the ShopMill step program's header (blank, retraction plane, safety clearance):
          // it moves nothing; the steps that would use it are refused below
          m_.comment("ncbridge: ShopMill program header E_HEAD read (no motion)");
        } else if (n == "E_END") {
          shopmill_end = true;
        } else if ((n.rfind("E_", 0) == 0 || n.rfind("F_", 0) == 0) && n.size() > 2) {
          m_.fail(it.column, "ShopMill step " + n + " (" + shopmill_step_name(n) +
                                 "): the positional parameters of ShopMill's steps are not published, and "
                                 "ncbridge does not guess them (save the program as G code from ShopMill, or "
                                 "post it with CYCLE61/CYCLE81-89/POCKET3/4 and explicit moves)");
        } else if (n == "CYCLE832") {
          // high speed settings: the first parameter is the contour tolerance (0: deselect)
          const double tolerance = !it.arguments.empty() && it.arguments[0] != kNoExpr ? eval(b, it.arguments[0]) : 0.0;
          nb.g(64, it.column);
          if (tolerance > 0) nb.add('p', tolerance, it.column);
        } else if (table_.cycles.count(n)) {
          cycle_call = &it;
        } else if (table_.patterns.count(n)) {
          pattern_call = &it;
        } else if (table_.milling_cycles.count(n)) {
          milling_call = &it;
        } else if (std::find(table_.unsupported_cycles.begin(), table_.unsupported_cycles.end(), n) != table_.unsupported_cycles.end()) {
          m_.fail(it.column, n + " is recognised but not supported: ncbridge does not invent its motion "
                                 "(post the program with explicit moves, or use CYCLE81-CYCLE89)");
        } else if (n == "CYCLE800") {
          // CYCLE800(_FR, _TC, _ST, _MODE, _X0, _Y0, _Z0, _A, _B, _C, _X1, _Y1, _Z1, _DIR, ...): a
          // swivel of the working plane (5-axis) unless every offset and angle (positions 5-13) is 0
          for (std::size_t i = 4; i < it.arguments.size() && i < 13; ++i) {
            if (it.arguments[i] != kNoExpr && eval(b, it.arguments[i]) != 0.0) {
              static const char* const kNames[] = {"_X0", "_Y0", "_Z0", "_A", "_B", "_C", "_X1", "_Y1", "_Z1"};
              m_.fail(it.column, std::string("CYCLE800 swivels the working plane (") + kNames[i - 4] + " is not 0): "
                                 "5-axis swivelling is not supported; only CYCLE800 without rotation or offset");
            }
          }
        } else if (std::find(table_.ignored_calls.begin(), table_.ignored_calls.end(), n) != table_.ignored_calls.end()) {
          // no effect on the canonical toolpath
        } else if (subprogram_file(n)) {
          // NAME(3600, 600), L140(2): a subprogram with PROC parameters
          subprogram = n;
          sub_column = it.column;
          for (ExprRef a : it.arguments) {
            sub_arguments.push_back(a == kNoExpr ? std::nullopt : std::optional<double>(eval(b, a)));
          }
        } else {
          m_.fail(it.column, n + "(...) is neither a cycle ncbridge supports nor a subprogram file " + n +
                                 ".SPF in the subroutine path or beside the program");
        }
        break;
      }
      case Item::Kind::Keyword: {
        const std::string& n = it.name;
        if (n == "SUPA") supa = true;
        else if (n == "CIP") cip = true;
        else if (n == "CT") ct = true;
        else if (n == "TRANS" || n == "ATRANS" || n == "ROT" || n == "AROT") {
          frame_op = n;
          frame_column = it.column;
        }
        else if (n == "MCALL") mcall = true;
        else if (n == "RET") program_return = true;
        else if (n == "GOTOF" || n == "GOTOB" || n == "GOTO" || n == "GOTOC") {
          goto_label = it.text;
          goto_how = n == "GOTOC" ? "GOTO" : n;
          goto_column = it.column;
        } else if (n == "G90" || n == "G91") {
          incremental_ = n == "G91";
        } else if (std::find(table_.ignored_calls.begin(), table_.ignored_calls.end(), n) != table_.ignored_calls.end()) {
        } else if (n == "DEF") {
        } else if (n == "CALL") {
          if (it.text.empty()) m_.fail(it.column, "CALL needs a program name");
          subprogram = it.text;
          sub_column = it.column;
        } else if (n == "BSPLINE" || n == "ASPLINE" || n == "CSPLINE") {
          m_.fail(it.column, "not supported: spline interpolation " + n + " (a subprogram of that name is not called)");
        } else if (subprogram.empty() && n.size() > 0) {
          subprogram = n;  // a named subprogram call: PART1
          sub_column = it.column;
        } else {
          m_.fail(it.column, "Unknown word " + n);
        }
        break;
      }
    }
  }
  static const std::set<std::string> kWords = {"X", "Y", "Z", "A", "B", "C", "I", "J", "K", "I1", "J1", "K1", "CR",
                                                "AR", "F", "S", "T", "D", "L", "P", "TURN", "RPL", "AP", "RP",
                                                "MEAS", "MEAW"};
  for (const auto& [name, item] : words) {
    if (!kWords.count(name)) m_.fail(item->column, "Address " + name + " is not supported");
  }
  // L-subprogram call: L10 (P repeats)
  if (words.count("L")) {
    subprogram = "L" + std::to_string(std::lround(eval(b, words["L"]->value)));
    sub_column = words["L"]->column;
    words.erase("L");
  }

  // G codes
  int g4 = 0;
  std::string pole_how;
  std::uint32_t pole_column = 0;
  for (const Item* g : gs) {
    double code = eval(b, g->value);
    const lowering::CodeEntry* e = table_.g(code);
    if (e == nullptr) m_.fail(g->column, "G" + lowering::code_key(code) + " is not a SINUMERIK G code ncbridge supports");
    const std::string& meta = e->meta;
    if (meta == "rapid" || meta == "linear" || meta == "circular_cw" || meta == "circular_ccw") {
      motion_ = static_cast<int>(*e->rs274);
    } else if (meta == "absolute" || meta == "incremental") {
      incremental_ = meta == "incremental";
    } else if (meta == "dwell") {
      g4 = static_cast<int>(g->column);
    } else if (meta == "pole_incremental" || meta == "pole_absolute" || meta == "pole_relative") {
      pole_how = meta;
      pole_column = g->column;
    } else if (meta == "suppress_frames_block") {
      g53 = true;
    } else if (meta == "work_offset_off") {
      m_.comment("ncbridge: G500: no settable work offset; coordinate system 1 (G54, offsets from the setup) used");
      nb.g(54, g->column);
    } else if (meta == "exact_stop_block" || meta == "exact_stop_fine" || meta == "exact_stop_coarse") {
    } else if (e->rs274) {
      if (meta == "plane_xy") plane_ = 17;
      if (meta == "plane_xz") plane_ = 18;
      if (meta == "plane_yz") plane_ = 19;
      nb.g(*e->rs274, g->column);
    } else {
      m_.fail(g->column, "G" + lowering::code_key(code) + " (" + meta + ") is not supported yet");
    }
  }
  for (const Item* mi : ms) {
    double code = eval(b, mi->value);
    const lowering::CodeEntry* e = table_.m(code);
    if (e == nullptr) {
      if (m_.machine_function(code, mi->column)) continue;
      m_.fail(mi->column, "M" + lowering::code_key(code) + " is not a SINUMERIK M code ncbridge supports");
    }
    if (e->meta == "subprogram_return") program_return = true;
    else if (e->rs274) nb.m(static_cast<int>(*e->rs274), mi->column);
  }

  // technology words
  auto value_of = [&](const char* name) -> std::optional<double> {
    auto it = words.find(name);
    if (it == words.end()) return std::nullopt;
    return eval(b, it->second->value);
  };
  if (auto f = value_of("F"); f && !g4) nb.add('f', *f, words["F"]->column);
  if (auto s = value_of("S"); s && !g4) nb.add('s', *s, words["S"]->column);
  if (words.count("T")) {
    const Item* t = words["T"];
    int tool = t->text.empty() ? static_cast<int>(std::lround(eval(b, t->value))) : m_.tool_number_for_name(t->text, t->column);
    nb.add('t', tool, t->column);
  }
  if (auto d = value_of("D")) {
    // D0: no tool offset; D1..: the offsets of the active tool
    if (*d == 0) nb.g(49, words["D"]->column);
    else nb.g(43, words["D"]->column);  // the length of the tool in the spindle (after this block's M6)
  }
  if (g4) {
    double seconds = 0;
    if (auto f = value_of("F")) seconds = *f;
    else if (auto s = value_of("S")) {
      if (m_.state().speed <= 0) m_.fail(static_cast<std::uint32_t>(g4), "G4 S (revolutions) with no spindle speed");
      seconds = *s * 60.0 / m_.state().speed;
    } else {
      m_.fail(static_cast<std::uint32_t>(g4), "G4 needs F (seconds) or S (revolutions)");
    }
    nb.g(4, static_cast<std::uint32_t>(g4));
    nb.add('p', seconds, static_cast<std::uint32_t>(g4));
  }

  // frames: TRANS/ATRANS X Y Z, ROT/AROT RPL= or Z=
  if (frame_op) {
    auto v = [&](const char* n) { return value_of(n); };
    if (*frame_op == "TRANS") {
      m_.frame = lowering::Frame{{v("X").value_or(0), v("Y").value_or(0), v("Z").value_or(0)}, 0};
    } else if (*frame_op == "ATRANS") {
      m_.frame.shift_within({v("X").value_or(0), v("Y").value_or(0), 0});
      m_.frame.offset.z += v("Z").value_or(0);
    } else {
      std::optional<double> angle = v("RPL");
      if (!angle) angle = v("Z");
      for (const char* axis : {"X", "Y"}) {
        if (auto a = v(axis); a && *a != 0) {
          m_.fail(frame_column, *frame_op + " " + axis + ": the working plane turned about " + axis +
                                    " (an angle head or a swivelled spindle) is not supported: ncbridge converts "
                                    "three-axis machining with the tool along Z");
        }
      }
      if (*frame_op == "ROT") m_.frame = lowering::Frame{{0, 0, 0}, angle.value_or(0)};
      else m_.frame.rotation_deg += angle.value_or(0);
    }
    return !m_.execute(nb);
  }

  // motion
  Point3 here = m_.position();
  auto axis = [&](const char* n, double current) -> std::optional<double> {
    auto it = words.find(n);
    if (it == words.end()) return std::nullopt;
    double v = eval(b, it->second->value);
    char mode = it->second->mode;
    bool inc = mode == 'I' || (mode != 'A' && incremental_);
    return inc ? current + v : v;
  };
  // G110/G111/G112 X Y: the pole of polar coordinates (no motion)
  if (!pole_how.empty()) {
    if (words.count("AP") || words.count("RP")) m_.fail(pole_column, "A pole given in polar coordinates (AP=/RP= with G110-G112) is not supported");
    Point3 base = pole_how == "pole_absolute" ? Point3{0, 0, 0} : pole_how == "pole_incremental" ? here : pole_;
    auto pole_axis = [&](const char* n, double from) {
      auto it = words.find(n);
      if (it == words.end()) return pole_how == "pole_absolute" ? 0.0 : from;
      const double v = eval(b, it->second->value);
      // G111 is absolute (unless =IC()); G110 and G112 add to their reference point
      const bool inc = pole_how != "pole_absolute" ? it->second->mode != 'A' : it->second->mode == 'I';
      return inc ? from + v : v;
    };
    pole_ = {pole_axis("X", base.x), pole_axis("Y", base.y), 0};
    polar_radius_ = std::hypot(here.x - pole_.x, here.y - pole_.y);
    polar_angle_ = std::atan2(here.y - pole_.y, here.x - pole_.x) / kDeg;
    words.erase("X");
    words.erase("Y");
    if (words.count("Z")) m_.fail(words["Z"]->column, "Z in a pole block (G110-G112) is not supported");
  }
  // AP= (angle, degrees) and RP= (radius) about the pole: both modal
  std::optional<double> polar_x, polar_y;
  if (words.count("AP") || words.count("RP")) {
    if (plane_ != 17) m_.fail(words.count("AP") ? words["AP"]->column : words["RP"]->column, "Polar coordinates outside G17 are not supported");
    if (words.count("X") || words.count("Y")) m_.fail(words.count("X") ? words["X"]->column : words["Y"]->column, "X/Y and AP=/RP= in one block");
    if (auto ap = axis("AP", polar_angle_)) polar_angle_ = *ap;
    if (auto rp = axis("RP", polar_radius_)) polar_radius_ = *rp;
    if (polar_radius_ < 0) m_.fail(words.count("RP") ? words["RP"]->column : words["AP"]->column, "Negative polar radius RP");
    polar_x = pole_.x + polar_radius_ * std::cos(polar_angle_ * kDeg);
    polar_y = pole_.y + polar_radius_ * std::sin(polar_angle_ * kDeg);
  }
  std::optional<double> x = polar_x ? polar_x : axis("X", here.x), y = polar_y ? polar_y : axis("Y", here.y),
                        z = axis("Z", here.z);
  bool has_axes = x || y || z || words.count("A") || words.count("B") || words.count("C");
  const std::uint32_t col = b.items.empty() ? 1 : b.items.front().column;
  if (supa || g53) {
    // SUPA/G53/G153: machine coordinates for this block
    for (const char* n : {"X", "Y", "Z", "A", "B", "C"}) {
      if (auto v = value_of(n)) nb.add(static_cast<char>(n[0] - 'A' + 'a'), *v, words[n]->column);
    }
    if (has_axes) {
      nb.g(53, col);
      nb.g(motion_ == 1 ? 1 : 0, col);
    }
  } else if (words.count("MEAS") || words.count("MEAW")) {
    measure(words.count("MEAS") ? *words["MEAS"] : *words["MEAW"], b, nb, x, y, z, cip || ct || motion_ == 2 || motion_ == 3);
  } else if (has_axes || polar_x || ((cip || ct || motion_ == 2 || motion_ == 3) &&
                              (words.count("I") || words.count("J") || words.count("AR") || words.count("CR")))) {
    for (const char* n : {"A", "B", "C"}) {
      if (auto v = value_of(n)) {
        const canonical::Pose& p = m_.state().position;
        double current = n[0] == 'A' ? p.a : n[0] == 'B' ? p.b : p.c;
        nb.add(static_cast<char>(n[0] - 'A' + 'a'), incremental_ ? current + *v : *v, words[n]->column);
      }
    }
    bool arc_word = cip || ct || motion_ == 2 || motion_ == 3;
    if (!arc_word) {
      nb.g(motion_, col);
      m_.put_axes(nb, x, y, z, col);
      double dx = x.value_or(here.x) - here.x, dy = y.value_or(here.y) - here.y, l = std::hypot(dx, dy);
      if (l > 1e-12) { tangent_ = {dx / l, dy / l, 0}; have_tangent_ = true; }
    } else {
      if (plane_ != 17) {
        if (m_.frame.rotation_deg != 0 || cip || ct || words.count("AR")) {
          m_.fail(col, "Arcs outside G17 support only I/J/K and CR= without frame rotation");
        }
        nb.g(motion_, col);
        m_.put_axes(nb, x, y, z, col);
        for (const char* n : {"I", "J", "K"}) {
          if (auto v = value_of(n)) nb.add(static_cast<char>(n[0] - 'A' + 'a'), *v, words[n]->column);
        }
        if (auto cr = value_of("CR")) nb.add('r', *cr, words["CR"]->column);
      } else {
        Point3 end{x.value_or(here.x), y.value_or(here.y), z.value_or(here.z)};
        bool cw = motion_ == 2;
        double cx = 0, cy = 0;
        bool have_centre = false;
        if (cip) {
          auto i1 = axis("I1", here.x), j1 = axis("J1", here.y);
          if (!i1 || !j1) m_.fail(col, "CIP needs the intermediate point I1= and J1=");
          // the circle through start, intermediate and end point
          double ax = here.x, ay = here.y, bx = *i1, by = *j1, ex = end.x, ey = end.y;
          double d = 2 * (ax * (by - ey) + bx * (ey - ay) + ex * (ay - by));
          if (std::fabs(d) < 1e-12) m_.fail(col, "CIP points lie on a straight line");
          double a2 = ax * ax + ay * ay, b2 = bx * bx + by * by, e2 = ex * ex + ey * ey;
          cx = (a2 * (by - ey) + b2 * (ey - ay) + e2 * (ay - by)) / d;
          cy = (a2 * (ex - bx) + b2 * (ax - ex) + e2 * (bx - ax)) / d;
          cw = ((bx - ax) * (ey - ay) - (by - ay) * (ex - ax)) < 0;
          have_centre = true;
        } else if (ct) {
          if (!have_tangent_) m_.fail(col, "CT needs a preceding contour element to be tangent to");
          double dx = end.x - here.x, dy = end.y - here.y;
          double nx = -tangent_.y, ny = tangent_.x;
          double nd = nx * dx + ny * dy;
          if (std::fabs(nd) < 1e-9) m_.fail(col, "CT end point lies on the tangent: program G1");
          double k = (dx * dx + dy * dy) / (2 * nd);
          cx = here.x + nx * k;
          cy = here.y + ny * k;
          cw = k < 0;
          have_centre = true;
        } else if (polar_x) {
          // G2/G3 AP= (RP=): about the pole
          cx = pole_.x;
          cy = pole_.y;
          have_centre = true;
        } else if (words.count("I") || words.count("J")) {
          auto centre = [&](const char* n, double current) {
            auto it = words.find(n);
            if (it == words.end()) return current;
            double v = eval(b, it->second->value);
            return it->second->mode == 'A' ? v : current + v;
          };
          cx = centre("I", here.x);
          cy = centre("J", here.y);
          have_centre = true;
          if (auto ar = value_of("AR"); ar && !x && !y) {
            double r0 = std::hypot(here.x - cx, here.y - cy);
            double a0 = std::atan2(here.y - cy, here.x - cx) + (cw ? -*ar : *ar) * kDeg;
            end.x = cx + r0 * std::cos(a0);
            end.y = cy + r0 * std::sin(a0);
          }
        } else if (auto ar = value_of("AR")) {
          // end point and opening angle: the centre lies on the chord's bisector
          double dx = end.x - here.x, dy = end.y - here.y, chord = std::hypot(dx, dy);
          if (chord < 1e-9 || *ar <= 0 || *ar >= 360) m_.fail(words["AR"]->column, "AR= needs an angle between 0 and 360 and a distinct end point");
          double half = *ar * kDeg / 2;
          double h = chord / 2 / std::tan(half);  // distance of the centre from the chord middle (signed)
          double nx = -dy / chord, ny = dx / chord;  // left normal
          double side = cw ? -1.0 : 1.0;
          cx = (here.x + end.x) / 2 + side * nx * h;
          cy = (here.y + end.y) / 2 + side * ny * h;
          have_centre = true;
        } else if (auto cr = value_of("CR")) {
          nb.g(motion_, col);
          m_.put_axes(nb, end.x, end.y, z, col);
          nb.add('r', *cr, words["CR"]->column);
        } else {
          m_.fail(col, "Circle needs I/J, CR=, AR=, CIP or CT");
        }
        if (have_centre) {
          m_.put_xy_arc(nb, cw, end.x, end.y, z, cx, cy, col);
          if (auto turn = value_of("TURN"); turn && *turn > 0) nb.add('p', std::lround(*turn) + 1, words["TURN"]->column);
          double rx = end.x - cx, ry = end.y - cy, l = std::hypot(rx, ry);
          if (l > 0) { tangent_ = cw ? Point3{ry / l, -rx / l, 0} : Point3{-ry / l, rx / l, 0}; have_tangent_ = true; }
        }
      }
    }
  }
  if (m_.execute(nb)) return false;
  if (measured_probe_ != 0) {
    m_.parameters().set_named(Reader::measured_key(measured_probe_), 1.0);
    measured_probe_ = 0;
  }

  if (milling_call) {
    if (mcall) m_.fail(milling_call->column, "MCALL " + milling_call->name + ": a modal pocket cycle is not supported");
    pocket(*milling_call, b);
  }
  if (pattern_call) hole_pattern(*pattern_call, b);
  if (cycle_call) cycle(*cycle_call, b, mcall);
  else if (mcall) modal_cycle_.reset();
  if (modal_cycle_ && !cycle_call && has_axes && !supa) run_cycle_here(col);
  if (goto_label) {
    jump(*goto_label, *goto_how, goto_column);
    return true;
  }
  if (!subprogram.empty()) {
    int repeats = 1;
    if (auto p = value_of("P")) repeats = static_cast<int>(std::lround(*p));
    call_subprogram(subprogram, repeats, sub_column, sub_arguments);
    return true;
  }
  if (shopmill_end) {
    // E_END: the end of the ShopMill step program
    NeutralBlock end;
    end.m(30, col);
    return !m_.execute(end);
  }
  if (program_return) return return_from_subprogram();
  return true;
}

// MEAS=n / MEAW=n with a straight move: measuring with probe n (1 or 2), on its rising edge
// (contact) when n > 0, its falling edge (contact lost) when n < 0. MEAS stops the axes at the
// trigger, MEAW lets them reach the end point; both are read as a probe move (LinuxCNC's G38.3,
// G38.5 for a falling edge) whose trigger position, taken as the end point, is what
// $AA_MW[axis] reads afterwards (#5061..), with $AC_MEA[n] = 1.
void Runner::measure(const Item& word, const SBlock& b, NeutralBlock& nb, std::optional<double> x,
                     std::optional<double> y, std::optional<double> z, bool arc) {
  const double n = eval(b, word.value);
  const int probe = static_cast<int>(std::lround(std::fabs(n)));
  if (probe < 1 || probe > 2 || std::fabs(std::fabs(n) - probe) > 1e-9) {
    m_.fail(word.column, word.name + "=" + lowering::code_key(n) + ": the probe is 1 or 2 (-1, -2: falling edge)");
  }
  if (arc) m_.fail(word.column, "not supported: measuring (" + word.name + "=) on a circle");
  if (!x && !y && !z) m_.fail(word.column, word.name + "= needs an X, Y or Z end point");
  nb.g(n > 0 ? 38.3 : 38.5, word.column);
  m_.put_axes(nb, x, y, z, word.column);
  measured_probe_ = probe;
}

// Skips forward from the current block to the first of `ends` at the same nesting depth
// (blocks in `opens` nest); the next block to run is the one after it. Returns which was found.
std::string Runner::skip_structure(const std::vector<std::string>& opens, const std::vector<std::string>& ends,
                                   std::uint32_t column) {
  const File& f = files_[file_];
  const std::string opener = opens.front();
  const std::uint32_t from_line = m_.line();
  int depth = 0;
  SBlock scan;
  for (std::size_t i = pc_; i < f.text.size(); ++i) {
    reader_.declared_.clear();
    reader_.read(f.text.line(i), static_cast<std::uint32_t>(i + 1), f.text.name, scan);
    const std::string& c = scan.control;
    if (c.empty()) continue;
    bool is_goto_if = false;
    for (const Item& it : scan.items) {
      if (it.kind == Item::Kind::Keyword && it.name.rfind("GOTO", 0) == 0) is_goto_if = true;
    }
    if (std::find(opens.begin(), opens.end(), c) != opens.end() && !(c == "IF" && is_goto_if)) {
      ++depth;
      continue;
    }
    if (std::find(ends.begin(), ends.end(), c) != ends.end()) {
      if (depth == 0) {
        pc_ = i + 1;
        return c;
      }
      if (c != "ELSE") --depth;
    }
  }
  throw InputError({f.text.name, from_line, column}, opener + " without its " + ends.back());
}

bool Runner::run_control(SBlock& b) {
  const std::string& c = b.control;
  const std::size_t here = pc_ - 1;
  const std::uint32_t col = b.control_column;
  auto top_is = [&](const char* kind) {
    return !structures_.empty() && structures_.back().kind == kind && structures_.back().file == file_;
  };
  if (c == "PROC" || c == "EXTERN") {
    // PROC: the parameters were bound by the call; EXTERN declares a called program's signature
  } else if (c == "ELSE") {
    // the IF branch ran to here: on after the ENDIF
    skip_structure({"IF"}, {"ENDIF"}, col);
  } else if (c == "ENDIF") {
  } else if (c == "WHILE") {
    bool again = top_is("WHILE") && structures_.back().line == here;
    if (eval(b, b.condition) != 0.0) {
      if (!again) structures_.push_back({"WHILE", file_, here, 0, ""});
    } else {
      if (again) structures_.pop_back();
      skip_structure({"WHILE"}, {"ENDWHILE"}, col);
    }
  } else if (c == "ENDWHILE") {
    if (!top_is("WHILE")) m_.fail(col, "ENDWHILE without WHILE");
    pc_ = structures_.back().line;
  } else if (c == "REPEAT" || c == "LOOP") {
    if (!(top_is(c.c_str()) && structures_.back().line == here)) structures_.push_back({c, file_, here, 0, ""});
  } else if (c == "UNTIL") {
    if (!top_is("REPEAT")) m_.fail(col, "UNTIL without REPEAT");
    if (eval(b, b.condition) != 0.0) structures_.pop_back();
    else pc_ = structures_.back().line + 1;
  } else if (c == "ENDLOOP") {
    if (!top_is("LOOP")) m_.fail(col, "ENDLOOP without LOOP");
    pc_ = structures_.back().line + 1;
  } else if (c == "FOR") {
    double from = eval(b, b.for_from), to = eval(b, b.for_to);
    m_.parameters().set_named(b.for_variable, from);
    if (from > to) {
      skip_structure({"FOR"}, {"ENDFOR"}, col);
    } else {
      structures_.push_back({"FOR", file_, here, to, b.for_variable});
    }
  } else if (c == "ENDFOR") {
    if (!top_is("FOR")) m_.fail(col, "ENDFOR without FOR");
    Structure& s = structures_.back();
    double next = m_.parameters().named(s.variable).value_or(0.0) + 1.0;
    m_.parameters().set_named(s.variable, next);
    if (next <= s.to) pc_ = s.line + 1;
    else structures_.pop_back();
  }
  return true;
}

// HOLES1 (a row) and HOLES2 (a circle): rapid to each hole at the current height, where the
// modally called cycle (MCALL) drills; without one the pattern only positions, as on the control.
void Runner::hole_pattern(const Item& call, const SBlock& b) {
  const lowering::CycleEntry& entry = table_.patterns.at(call.name);
  std::map<std::string, double> a;
  if (call.arguments.size() > entry.positional.size()) {
    m_.fail(call.column, call.name + " takes at most " + std::to_string(entry.positional.size()) + " parameters");
  }
  for (std::size_t i = 0; i < call.arguments.size(); ++i) {
    if (call.arguments[i] != kNoExpr) a[entry.positional[i]] = eval(b, call.arguments[i]);
  }
  auto get = [&](const char* p) {
    auto it = a.find(p);
    if (it == a.end()) m_.fail(call.column, call.name + ": parameter " + std::string(p) + " missing");
    return it->second;
  };
  const int count = static_cast<int>(std::lround(get("NUM")));
  if (count < 1) m_.fail(call.column, call.name + ": NUM must be at least 1");
  std::vector<std::pair<double, double>> holes;
  if (entry.meta == "hole_row") {
    const double x0 = get("SPCA"), y0 = get("SPCO"), angle = a.count("STA1") ? a["STA1"] * kDeg : 0.0;
    const double first = get("FDIS"), spacing = get("DBH");
    for (int k = 0; k < count; ++k) {
      double d = first + k * spacing;
      holes.emplace_back(x0 + d * std::cos(angle), y0 + d * std::sin(angle));
    }
  } else {
    const double cx = get("CPA"), cy = get("CPO"), radius = get("RAD");
    const double start = a.count("STA1") ? a["STA1"] : 0.0;
    const double step = a.count("INDA") && a["INDA"] != 0 ? a["INDA"] : 360.0 / count;
    for (int k = 0; k < count; ++k) {
      double angle = (start + k * step) * kDeg;
      holes.emplace_back(cx + radius * std::cos(angle), cy + radius * std::sin(angle));
    }
  }
  for (const auto& [x, y] : holes) {
    NeutralBlock nb;
    nb.g(0, call.column);
    m_.put_axes(nb, x, y, std::nullopt, call.column);
    if (m_.execute(nb)) return;
    if (modal_cycle_) run_cycle_here(call.column);
  }
}

void Runner::pocket(const Item& call, const SBlock& b) {
  const lowering::CycleEntry& entry = table_.milling_cycles.at(call.name);
  if (call.arguments.size() > entry.positional.size()) {
    m_.fail(call.column, call.name + " takes at most " + std::to_string(entry.positional.size()) + " parameters");
  }
  std::map<std::string, double> args;
  for (std::size_t i = 0; i < call.arguments.size(); ++i) {
    if (call.arguments[i] != kNoExpr) args[entry.positional[i]] = eval(b, call.arguments[i]);
  }
  const setup::Tool* tool = options_.tools.find(m_.state().tool_in_spindle);
  const double radius = tool ? tool->diameter / m_.state().mm_per_unit() / 2.0 : 0.0;
  if (entry.meta == "rectangular_pocket") rectangular_pocket(m_, call.name, args, radius, call.column);
  else circular_pocket(m_, call.name, args, radius, call.column);
}

void Runner::cycle(const Item& call, const SBlock& b, bool modal_call) {
  const lowering::CycleEntry& entry = table_.cycles.at(call.name);
  std::map<std::string, double> args;
  if (call.arguments.size() > entry.positional.size()) {
    m_.fail(call.column, call.name + " takes at most " + std::to_string(entry.positional.size()) + " parameters");
  }
  for (std::size_t i = 0; i < call.arguments.size(); ++i) {
    if (call.arguments[i] != kNoExpr) args[entry.positional[i]] = eval(b, call.arguments[i]);
  }
  cycle_name_ = call.name;
  cycle_args_ = args;
  if (modal_call) {
    modal_cycle_ = call.name;
    modal_cycle_args_ = args;
    return;  // MCALL: the cycle runs at the positions programmed next
  }
  run_cycle_here(call.column);
}

void Runner::run_cycle_here(std::uint32_t column) {
  const std::string name = modal_cycle_ ? *modal_cycle_ : cycle_name_;
  const std::map<std::string, double>& a = modal_cycle_ ? modal_cycle_args_ : cycle_args_;
  auto get = [&](const char* p, std::optional<double> fallback = std::nullopt) -> double {
    auto it = a.find(p);
    if (it != a.end()) return it->second;
    if (fallback) return *fallback;
    m_.fail(column, name + ": parameter " + p + " missing");
  };
  double rtp = get("RTP"), rfp = get("RFP", 0.0), sdis = std::fabs(get("SDIS", 0.0));
  double dpr = a.count("DPR") ? a.at("DPR") : 0.0;
  double bottom = dpr != 0.0 ? rfp - std::fabs(dpr) : get("DP");
  double r = rfp + sdis;
  if (bottom >= r) m_.fail(column, name + ": the final drilling depth is not below the reference plane");
  int code = 81;
  double q = 0, p = 0;
  if (name == "CYCLE82") { code = 82; p = get("DTB", 0.0); }
  else if (name == "CYCLE83") {
    double first = a.count("FDPR") && a.at("FDPR") != 0 ? std::fabs(a.at("FDPR"))
                   : a.count("FDEP") ? rfp - a.at("FDEP") : 0.0;
    if (first <= 0) m_.fail(column, "CYCLE83 needs the first drilling depth FDEP or FDPR");
    if (a.count("DAM") && a.at("DAM") != 0) m_.comment("ncbridge: CYCLE83 degression DAM is not applied (equal pecks used)");
    q = first;
    code = a.count("VARI") && a.at("VARI") == 0 ? 73 : 83;
  } else if (name == "CYCLE84") {
    double pitch = a.count("PIT") ? a.at("PIT") : 0.0;
    if (pitch == 0) m_.fail(column, "CYCLE84 needs the thread pitch PIT");
    if (m_.state().speed <= 0) m_.fail(column, "CYCLE84 needs a spindle speed to feed the pitch");
    NeutralBlock f;
    f.add('f', std::fabs(pitch) * m_.state().speed, column);
    m_.execute(f);
    code = 84;
  } else if (name == "CYCLE85") code = 85;
  else if (name == "CYCLE86") { code = 86; p = get("DTB", 0.0); }
  else if (name == "CYCLE87") { code = 88; p = 0; }
  else if (name == "CYCLE88") { code = 88; p = get("DTB", 0.0); }
  else if (name == "CYCLE89") { code = 89; p = get("DTB", 0.0); }
  Point3 here = m_.position();
  if (std::fabs(here.z - rtp) > 1e-9) {
    NeutralBlock up;
    up.g(0, column);
    m_.put_axes(up, std::nullopt, std::nullopt, rtp, column);
    if (m_.execute(up)) return;
  }
  NeutralBlock nb;
  nb.g(98, column);
  nb.g(code, column);
  Point3 e = m_.frame.to_executor({here.x, here.y, 0});
  nb.add('x', e.x, column);
  nb.add('y', e.y, column);
  nb.add('z', bottom + m_.frame.offset.z, column);
  nb.add('r', r + m_.frame.offset.z, column);
  if (code == 83 || code == 73) nb.add('q', q, column);
  if (code == 82 || code == 86 || code == 88 || code == 89) nb.add('p', p, column);
  m_.execute(nb);
  NeutralBlock cancel;
  cancel.g(80, column);
  m_.execute(cancel);
}

}  // namespace

void run(ProgramText program, const Options& options, canonical::Sink& sink) {
  Runner runner(options, sink);
  runner.run(std::move(program));
}

}  // namespace ncbridge::interpreter::siemens840d
