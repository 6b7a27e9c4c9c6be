#pragma once
// KUKA KRL out (.src and .dat) and the reader of what it writes (docs/krl.md).
//
// The .src holds one DEF with the motions: the BASE and TOOL frames, PTP to the home position,
// LIN for straight moves, CIRC with an auxiliary point for arcs (a full circle as CIRC with CA
// 360), $VEL.CP from the feed (m/s), C_DIS approximation at $APO.CDIS, repeated layers as a FOR
// loop that shifts the base frame by NCB_ZOFF (a FRAME whose Z grows by the layer height each
// time round). A printer's extruder follows two global variables declared in the .dat:
// NCB_EXTRUDE, filament mm per mm of path, set path-synchronously by TRIGGER WHEN DISTANCE=0
// before the motions it applies to; and NCB_FILAMENT(LENGTH, FEED), a local subprogram for a
// filament-only move (retraction, prime) that hands LENGTH (mm) and FEED (mm/min) to the
// extruder's control through NCB_FILAMENT_MOVE/NCB_FILAMENT_FEED and waits while it sets
// NCB_FILAMENT_BUSY. Other printer or CNC commands are written as comments. Lengths are mm.
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

#include "ncbridge/toolpath_optimizer/toolpath.hpp"

namespace ncbridge::toolpath_optimizer {

struct KrlOptions {
  std::string name = "NCBRIDGE";            // the module: DEF name, DEFDAT name (krl_module_name)
  std::string source;                       // the input file, for the header comment
  int base = 1;                             // BASE_DATA[base]: the part's frame
  int tool = 1;                             // TOOL_DATA[tool]: the nozzle or spindle tip
  std::array<double, 3> orientation{0, 90, 0};                // A B C of the tool, degrees
  std::array<double, 6> home{0, -90, 90, 0, 0, 0};            // A1..A6, degrees
  double approximation_mm = 0.025;          // $APO.CDIS
  double rapid_m_per_s = 0.5;               // $VEL.CP of traverse moves that carry no feed
  bool extruder = false;                    // write NCB_EXTRUDE / NCB_FILAMENT (printer input)
  int decimals = 4;
};

// A KRL name from a file stem: letters, digits and _, starting with a letter, at most 24
// characters, upper case ("cylinder-v2" -> "CYLINDER_V2", "3dp" -> "P3DP").
std::string krl_module_name(std::string_view stem);

class KrlWriter final : public ElementSink {
 public:
  KrlWriter(const KrlOptions& options, std::function<void(std::string_view)> src,
            std::function<void(std::string_view)> dat);
  void element(Element&& e) override;
  void end() override;  // writes the .src's end and the whole .dat

  std::uint64_t motion_statements() const { return motions_; }  // PTP, LIN, CIRC written
  std::uint64_t lines() const { return lines_; }
  std::uint64_t commands() const { return commands_; }          // statements (comments aside)

 private:
  void write(const Element& e, int depth);
  void motion(const Motion& m, int depth);
  void line(int depth, std::string_view text, bool statement = true);
  void position(std::string& out, const Vec3& p, double scale, bool full);
  void flush();

  KrlOptions o_;
  std::function<void(std::string_view)> src_, dat_;
  std::string buffer_;
  bool known_ = false;     // the robot's Cartesian position is known (after a Cartesian PTP)
  double feed_ = -1;       // the $VEL.CP written last, mm/min; -1: none
  double rate_ = -1;       // the NCB_EXTRUDE written last
  std::uint64_t motions_ = 0, lines_ = 0, commands_ = 0;
};

struct KrlCounts {
  std::uint64_t lines = 0;
  std::uint64_t motion_statements = 0;  // PTP, LIN, CIRC as written (a loop's body once)
  std::uint64_t loops = 0;
};

// Reads the KRL a KrlWriter writes (.src text; `name` for messages) and streams its motions,
// loops run out, into `sink`: LIN and CIRC as lines and arcs from the position before them,
// PTP as a move from an unknown position, the extruder's variables as extrusion. Anything
// outside that subset is an InputError with line and column.
KrlCounts read_krl_text(std::string_view src, const std::string& name, ElementSink& sink);

}  // namespace ncbridge::toolpath_optimizer
