// The ProgramWriter: canonical calls in, a dialect's program out. State calls change the state
// asked for; each action first has the dialect writer bring the reader to that state (what the
// action depends on), then writes the action. Canned-cycle calls are gathered hole by hole.
#include "ncbridge/gcode_writer/program_writer.hpp"

#include <optional>
#include <type_traits>

#include "arc_turns.hpp"
#include "dialect_writer.hpp"
#include "ncbridge/common/error.hpp"

namespace ncbridge::gcode_writer {

using namespace canonical;

namespace {

bool reader_made(std::string_view text) {
  return text.rfind("interpreter: ", 0) == 0 || text.rfind("ncbridge: ", 0) == 0;
}

std::string base_name(std::string_view path) {
  const auto slash = path.find_last_of('/');
  return std::string(slash == std::string_view::npos ? path : path.substr(slash + 1));
}

std::string cycle_name(int g_code_x10) {
  switch (g_code_x10) {
    case 730: return "G73 (chip-breaking drilling)";
    case 740: return "G74 (left-hand tapping)";
    case 760: return "G76 (fine boring)";
    case 810: return "G81 (drilling)";
    case 820: return "G82 (drilling with dwell)";
    case 830: return "G83 (peck drilling)";
    case 840: return "G84 (tapping)";
    case 850: return "G85 (boring, feed out)";
    case 860: return "G86 (boring, spindle stop, rapid out)";
    case 870: return "G87 (back boring)";
    case 880: return "G88 (boring, manual out)";
    case 890: return "G89 (boring, dwell, feed out)";
    default: {
      std::string g(1, 'G');
      g += std::to_string(g_code_x10 / 10);
      return g;
    }
  }
}

std::unique_ptr<DialectWriter> make_writer(const Options& o, TextOutput& out, const WriterLocation& where) {
  switch (o.dialect) {
    case Dialect::Fanuc: return make_fanuc_writer(o, out, where);
    case Dialect::Mach3: return make_mach3_writer(o, out, where);
    case Dialect::Siemens840D: return make_siemens840d_writer(o, out, where);
    case Dialect::Heidenhain: return make_heidenhain_writer(o, out, where);
    case Dialect::Rs274Ngc: break;
  }
  return make_rs274ngc_writer(o, out, where);
}

}  // namespace

struct ProgramWriter::Impl {
  Impl(Options o, Output output) : options(std::move(o)), out(std::move(output)) {
    dialect = make_writer(options, out, where);
  }

  Options options;
  TextOutput out;
  WriterLocation where;
  std::unique_ptr<DialectWriter> dialect;
  MachineState desired;
  std::vector<std::string> files;
  bool started = false;
  bool ended = false;      // PROGRAM_END written
  bool finished = false;   // end() called
  bool pallet_pending = false;
  std::optional<Hole> hole;
  std::uint32_t announced_file = ~0u, announced_line = 0;
  bool in_repeat = false;
  std::vector<std::pair<std::string, bool>> early_comments;  // before the first action (text, message)

  [[noreturn]] void refuse(const std::string& message) const {
    throw InputError({where.file, where.line, 0}, message);
  }

  void locate(const Source& source) {
    if (source.file != located_file) {
      where.file = source.file < files.size() ? files[source.file] : std::string();
      located_file = source.file;
    }
    where.line = source.line;
  }
  std::uint32_t located_file = ~0u;

  void start() {
    if (started) return;
    started = true;
    dialect->begin_program(desired);
    for (const auto& [text, message] : early_comments) {
      if (message) dialect->message(text); else dialect->comment(text);
    }
    early_comments.clear();
  }

  // Comments::Source: a comment naming the source line before the blocks it made.
  void announce(const Source& source) {
    if (options.comments != Comments::Source || source.line == 0) return;
    if (source.file == announced_file && source.line == announced_line) return;
    announced_file = source.file;
    announced_line = source.line;
    start();
    dialect->comment(base_name(where.file) + ":" + std::to_string(source.line));
  }

  void sync(unsigned need) {
    start();
    dialect->sync(desired, need);
  }

  void call(const Call& c) {
    if (finished) refuse("call after the end of the program stream");
    if (c.cycle) {
      if (in_repeat) { locate(c.source); refuse("a canned cycle inside a repeated body (only moves, arcs and feeds repeat)"); }
      if (hole && hole->tag.cycle_id == c.cycle->cycle_id) {
        hole->calls.push_back(c);
        return;
      }
      flush_hole();
      hole = Hole{*c.cycle, {c}};
      return;
    }
    flush_hole();
    handle(c.data, c.source);
  }

  void flush_hole() {
    if (!hole) return;
    Hole h = std::move(*hole);
    hole.reset();
    locate(h.calls.front().source);
    announce(h.calls.front().source);
    if (pallet_pending) refuse_pallet();
    if (ended) refuse("motion after the program end (M2/M30)");
    // the path mode is the cycle's own business (the executor runs it in exact path mode, and an
    // L-repeated block switches it before its first hole and back after its last)
    sync((kFeedMotion & ~kPath) | kPlane);
    if (dialect->cycle(h, desired)) {
      for (const Call& c : h.calls) desired.apply(c.data);
      return;
    }
    if (options.comments != Comments::None) {
      dialect->comment("ncbridge: " + cycle_name(h.tag.g_code_x10) + " written as its moves");
    }
    try {
      for (const Call& c : h.calls) handle(c.data, c.source);
    } catch (const InputError& e) {
      // name the cycle: the moves are the writer's second choice
      const std::string& m = e.message();
      const std::string marker = " cannot express ";
      const auto at = m.find(marker);
      const std::string what = at == std::string::npos ? m : m.substr(at + marker.size());
      throw InputError(e.where(), std::string(dialect_name(options.dialect)) + " cannot express the " +
                                      cycle_name(h.tag.g_code_x10) + " cycle: it has no cycle making that motion, " +
                                      "and written as moves it needs " + what);
    }
  }

  [[noreturn]] void refuse_pallet() const {
    refuse("PALLET_SHUTTLE not followed by a program stop (M60) or end (M30): " +
           std::string(dialect_name(options.dialect)) + " has no pallet change on its own");
  }

  void handle(const Data& data, const Source& source) {
    locate(source);
    std::visit([&](const auto& d) { handle_one(d, data, source); }, data);
  }

  template <class T>
  void handle_one(const T& d, const Data& data, const Source& source) {
    constexpr bool is_state =
        std::is_same_v<T, UseLengthUnits> || std::is_same_v<T, SetG5xOffset> || std::is_same_v<T, SetG92Offset> ||
        std::is_same_v<T, SetXyRotation> || std::is_same_v<T, SelectPlane> || std::is_same_v<T, SetFeedRate> ||
        std::is_same_v<T, SetFeedReference> || std::is_same_v<T, SetFeedMode> ||
        std::is_same_v<T, SetMotionControlMode> || std::is_same_v<T, SetNaivecamTolerance> ||
        std::is_same_v<T, SetSpindleSpeed> || std::is_same_v<T, StartSpindleClockwise> ||
        std::is_same_v<T, StartSpindleCounterclockwise> || std::is_same_v<T, StopSpindleTurning> ||
        std::is_same_v<T, SetSpindleMode> || std::is_same_v<T, UseToolLengthOffset> || std::is_same_v<T, SelectTool> ||
        std::is_same_v<T, FloodOn> || std::is_same_v<T, FloodOff> || std::is_same_v<T, MistOn> ||
        std::is_same_v<T, MistOff> || std::is_same_v<T, EnableFeedOverride> || std::is_same_v<T, DisableFeedOverride> ||
        std::is_same_v<T, EnableSpeedOverride> || std::is_same_v<T, DisableSpeedOverride> ||
        std::is_same_v<T, EnableAdaptiveFeed> || std::is_same_v<T, DisableAdaptiveFeed> ||
        std::is_same_v<T, EnableFeedHold> || std::is_same_v<T, DisableFeedHold> ||
        std::is_same_v<T, StartSpeedFeedSynch> || std::is_same_v<T, StopSpeedFeedSynch>;
    if constexpr (is_state) {
      if (in_repeat && !std::is_same_v<T, SetFeedRate>) {
        refuse(std::string(name_of(data)) + " inside a repeated body (only moves, arcs and feeds repeat)");
      }
      desired.apply(data);
      return;
    } else if constexpr (std::is_same_v<T, Comment> || std::is_same_v<T, Message>) {
      if (options.comments == Comments::None || reader_made(d.text)) return;
      if (!started) {
        // the program's start waits for its first action (its units), the comments before it with it
        early_comments.emplace_back(d.text, std::is_same_v<T, Message>);
        return;
      }
      if constexpr (std::is_same_v<T, Comment>) dialect->comment(d.text); else dialect->message(d.text);
      return;
    } else if constexpr (std::is_same_v<T, OnReset> || std::is_same_v<T, StartChange>) {
      return;  // the reader's own start-up; the first call of M6 (CHANGE_TOOL writes M6)
    } else if constexpr (std::is_same_v<T, Finish>) {
      return;  // the closing % of a tape: end() ends the program
    } else {
      if (ended) refuse(std::string(name_of(data)) + " after the program end (M2/M30)");
      if (in_repeat && !std::is_same_v<T, StraightTraverse> && !std::is_same_v<T, StraightFeed> &&
          !std::is_same_v<T, ArcFeed>) {
        refuse(std::string(name_of(data)) + " inside a repeated body (only moves, arcs and feeds repeat)");
      }
      if constexpr (std::is_same_v<T, PalletShuttle>) {
        if (pallet_pending) refuse_pallet();
        pallet_pending = true;
        return;
      }
      if (pallet_pending && !std::is_same_v<T, ProgramStop> && !std::is_same_v<T, ProgramEnd>) refuse_pallet();
      announce(source);
      if constexpr (std::is_same_v<T, StraightTraverse>) {
        sync(kMotion);
        dialect->traverse(d.end);
      } else if constexpr (std::is_same_v<T, StraightFeed>) {
        if (desired.synch) {
          sync(kFeedMotion);
          dialect->action(Call{data, source, std::nullopt}, desired);
        } else {
          sync(kFeedMotion);
          dialect->feed(d.end);
        }
      } else if constexpr (std::is_same_v<T, ArcFeed>) {
        sync(kFeedMotion | kPlane);
        if ((d.rotation > 1 || d.rotation < -1) && !dialect->arcs_turn_more_than_once()) {
          if (d.rotation > 10000 || d.rotation < -10000) {
            refuse(std::string(dialect_name(options.dialect)) + " cannot express an arc of more than 10000 turns " +
                   "(its arcs turn at most once: one block a turn)");
          }
          if (options.comments != Comments::None) {
            dialect->comment("ncbridge: an arc of " + std::to_string(d.rotation < 0 ? -d.rotation : d.rotation) +
                             " turns, written one turn a block");
          }
          for (const ArcFeed& piece : split_turns(dialect->reader().position, d, desired.plane)) dialect->arc(piece);
        } else {
          dialect->arc(d);
        }
      } else if constexpr (std::is_same_v<T, Dwell>) {
        sync(kActuators | kUnits);
        dialect->dwell(d.seconds);
      } else if constexpr (std::is_same_v<T, ChangeTool>) {
        sync(kUnits);
        dialect->tool_change(desired.selected_tool < 0 ? desired.tool_in_spindle : desired.selected_tool);
      } else if constexpr (std::is_same_v<T, ProgramEnd>) {
        start();
        dialect->program_end(pallet_pending);
        pallet_pending = false;
        ended = true;
      } else if constexpr (std::is_same_v<T, ProgramStop>) {
        sync(kActuators);
        if (pallet_pending) {
          dialect->action(Call{PalletShuttle{}, source, std::nullopt}, desired);
          pallet_pending = false;
        } else {
          dialect->action(Call{data, source, std::nullopt}, desired);
        }
      } else if constexpr (std::is_same_v<T, OptionalProgramStop>) {
        sync(kActuators);
        dialect->action(Call{data, source, std::nullopt}, desired);
      } else if constexpr (std::is_same_v<T, StraightProbe> || std::is_same_v<T, RigidTap>) {
        sync(kFeedMotion);
        dialect->action(Call{data, source, std::nullopt}, desired);
      } else {
        sync(kUnits);
        dialect->action(Call{data, source, std::nullopt}, desired);
      }
      desired.apply(data);
    }
  }

  void end() {
    if (finished) return;
    flush_hole();
    if (in_repeat) refuse("the stream ended inside a repeated body (begin_repeat without end_repeat)");
    if (pallet_pending) refuse_pallet();
    start();
    dialect->end_program(ended);
    finished = true;
    out.flush();
  }
};

ProgramWriter::ProgramWriter(Options options, Output output)
    : impl_(std::make_unique<Impl>(std::move(options), std::move(output))) {}

ProgramWriter::~ProgramWriter() = default;

void ProgramWriter::source_file(std::uint32_t index, std::string_view path) {
  if (impl_->files.size() <= index) impl_->files.resize(index + 1);
  impl_->files[index] = std::string(path);
  impl_->located_file = ~0u;
}

void ProgramWriter::call(const Call& call) { impl_->call(call); }

void ProgramWriter::end() { impl_->end(); }

void ProgramWriter::begin_repeat(std::uint32_t count, double z_shift) {
  Impl& m = *impl_;
  m.flush_hole();
  if (m.in_repeat) m.refuse("a repeated body inside another one");
  if (m.ended) m.refuse("a repeated body after the program end (M2/M30)");
  if (count < 1) m.refuse("a repeated body must run at least once");
  m.sync(kMotion);
  m.dialect->begin_repeat(count, z_shift);
  m.in_repeat = true;
}

void ProgramWriter::end_repeat() {
  Impl& m = *impl_;
  if (!m.in_repeat) m.refuse("end_repeat without begin_repeat");
  m.flush_hole();
  m.dialect->end_repeat();
  m.in_repeat = false;
  // the copies after the first: the tool ends where the reader's last copy ends
  m.desired.position = m.dialect->reader().position;
}

std::string write_program(std::span<const Call> calls, const Options& options) {
  std::string text;
  ProgramWriter writer(options, [&](std::string_view piece) { text.append(piece); });
  for (const Call& c : calls) writer.call(c);
  writer.end();
  return text;
}

}  // namespace ncbridge::gcode_writer
