#pragma once
// The toolpath as the optimizer sees it: a stream of elements in program order. Motions are the
// only elements it rewrites; everything else (a printer's temperature or fan line, a comment, a
// CNC program's spindle or tool call) rides along in place as a text line (printer G-code) or a
// canonical call (CNC programs, from the interpreter), and ends any run of motions it sits in.
//
// Coordinates are program-frame positions in the program's units, as the front-end resolved
// them (absolute, incremental words applied). Extrusion is the filament length fed during a
// motion (relative, whatever E mode the file used).
#include <array>
#include <cstdint>
#include <string>
#include <vector>
#include <variant>

#include "ncbridge/canonical/call.hpp"

namespace ncbridge::toolpath_optimizer {

struct Vec3 {
  double x = 0, y = 0, z = 0;
  friend bool operator==(const Vec3&, const Vec3&) = default;
};

enum class MotionKind : std::uint8_t {
  Traverse,  // G0: straight, at the traverse rate (a printer moves it like G1)
  Line,      // G1
  Arc,       // G2/G3: circular in the plane, linear along its normal (helical when that moves)
};

// An arc's circle in one of the principal planes. The centre is in the plane's first and second
// axes as canonical ARC_FEED has them (XY: x,y; YZ: y,z; XZ: z,x); `ccw` is counter-clockwise in
// those two axes. The arc runs from the motion's start to its end, sweeping more than zero and at
// most one full turn (start = end in the plane: a full circle) plus `extra_turns` full turns.
struct ArcGeometry {
  canonical::Plane plane = canonical::Plane::XY;
  double first_centre = 0, second_centre = 0;
  bool ccw = true;
  std::uint32_t extra_turns = 0;
};

// How a printer file wrote a motion, so that an unchanged one is written back byte for byte and a
// made one in the file's own style.
struct PrinterSyntax {
  std::string text;             // the original line with its line ending; empty for a made motion
  double e_position = 0;        // the E axis after the motion (absolute E mode writes this)
  std::uint8_t xyz_decimals = 3;
  std::uint8_t e_decimals = 5;
  bool relative_e = false;      // E words are relative (M83, or G91 where the firmware says so)
  bool relative_xyz = false;    // G91 was in force
  bool has_e = false;           // the line had an E word
  bool has_f = false;           // the line had an F word (the feed changed or was restated here)
  bool crlf = false;            // the line ended with CR LF
};

struct Motion {
  MotionKind kind = MotionKind::Line;
  Vec3 start, end;
  ArcGeometry arc;                 // kind == Arc
  double feed = 0;                 // the F in force, units/min
  double extrusion = 0;            // filament fed during the motion (printer files), relative
  std::array<double, 6> rotary{};  // a b c u v w at the end (CNC); a motion that moves them is kept
  bool rotary_moves = false;
  bool start_known = true;         // false after homing: the start (or end) is not known
  bool keep = false;               // written as it came, never merged (a printer line with other
                                   // words, a checksum, G91; a canned cycle's move ...)
  canonical::Units units = canonical::Units::Millimeters;
  canonical::Source source;        // where it came from (line 0: made by the optimizer)
  std::uint32_t blocks = 1;        // input motion blocks this motion stands for
  PrinterSyntax printer;           // printer files only
};

// A printer line that is not a motion (or a motion the front-end keeps as written, see
// Motion::keep): written back exactly as it came, in place.
enum class LineRole : std::uint8_t {
  Blank,        // empty or white space only
  Comment,      // only a comment
  Setting,      // changes how later lines read: G90/G91, M82/M83, G92, G20/G21, G17-G19
  MotionMode,   // a G0..G3 word that moves nothing (`G1 F1800`): sets the mode and feed
  Homing,       // G28/G29 and friends: the position is not known after it
  ToolChange,   // T<n>
  Command,      // anything else (temperatures, fans, M117 ...)
};

struct TextLine {
  std::string text;  // with its line ending
  std::uint32_t line = 0;
  LineRole role = LineRole::Command;
};

struct Element;

// Layers that repeat up to a shift along Z, written once: the body runs `count` times, the i-th
// time (from 0) displaced by i * z_shift. The body's first run is the first layer as it was.
struct Loop {
  std::vector<Element> body;
  std::uint32_t count = 2;
  double z_shift = 0;
};

struct Element {
  std::variant<Motion, TextLine, canonical::Call, Loop> item;
};

// Receives an element stream; end() once after the last.
class ElementSink {
 public:
  virtual ~ElementSink() = default;
  virtual void element(Element&& element) = 0;
  virtual void end() {}
};

// Collects a stream (tests, the deviation checker).
class ElementCollector final : public ElementSink {
 public:
  void element(Element&& e) override { elements.push_back(std::move(e)); }
  std::vector<Element> elements;
};

}  // namespace ncbridge::toolpath_optimizer
