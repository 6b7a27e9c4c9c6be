#pragma once
// The toolpath generator (CC2 -> CC1): for every machining workingstep of an ISO 14649 CC2
// model, the explicit cutter-location toolpath its feature, operation, strategy, tool and
// technology call for. It is the inverse of the feature recogniser: what it generates, the
// recogniser reads back as the same features with the same operations and strategies.
//
// The result is the CC1 model the cc1_builder makes (docs/cc1.md): each milling workingstep a
// TOOLPATH_FEATURE with a FREEFORM_OPERATION holding the toolpath, each drilling-family
// workingstep its ROUND_HOLE with the drilling operation (its cutting depth and retract plane
// set; the writer turns it into a cycle), RAPID_MOVEMENTs between them through the security
// plane. Workingsteps that already are CC1 (TOOLPATH_FEATURE, FREEFORM_OPERATION with a
// toolpath) are kept as they are; toolpaths a CC2 file carries for other operations are
// replaced by generated ones, and its rapid movements by new ones.
//
// Strategies, their parameters and defaults: docs/toolpaths.md.
#include <optional>
#include <string>
#include <vector>

#include "ncbridge/setup/stock.hpp"
#include "ncbridge/stepnc/project.hpp"

namespace ncbridge::toolpath_generator {

// How the loops of a contour-parallel clearing are taken.
enum class ContourOrder : std::uint8_t {
  Automatic,  // closed areas from the inside out (entry in the middle, the walls last), open
              // areas from the outside in (entry from the open side)
  Inward,
  Outward
};

struct Options {
  // The stock when the model has no rawpiece (else the features' extent is taken, with a warning).
  std::optional<setup::Stock> stock;
  // mm above the highest material a rapid keeps (inside an operation) and where feeds start.
  double clearance = 2.0;
  // Radial depth (stepover) as a share of the cutter's diameter when the operation states none
  // (and its strategy no overlap).
  double stepover_ratio = 0.5;
  // Axial depth (step down) as a share of the cutter's diameter when the operation states none.
  double axial_depth_ratio = 1.0;
  // How far the cutter runs out past an open side (and the overlap beyond a face's edge when the
  // strategy gives none), mm.
  double run_out = 1.0;
  // Entries into material: ramps (along the cut, or a helix) descend at this angle, degrees.
  double ramp_angle_deg = 3.0;
  // Feed of entries, as a share of the operation's feed.
  double entry_feed_ratio = 0.5;
  // How far a through feature is cut below the part's bottom, mm (drills: beyond their point).
  double breakthrough = 1.0;
  ContourOrder contour_order = ContourOrder::Automatic;
  // Name used in error messages (the CC2 file).
  std::string source_name;
};

struct GeneratedToolpaths {
  stepnc::Project cc1;
  std::vector<std::string> warnings;  // what was chosen for the user (defaults, derived stock)
};

// Throws ncbridge::InputError naming the workingstep for what cannot be generated: a feature
// without usable geometry, a tool that does not fit the feature, a strategy that does not apply
// to it or has nonsense parameters, an operation of a kind not supported.
GeneratedToolpaths generate_toolpaths(const stepnc::Project& cc2, const Options& options = {});

}  // namespace ncbridge::toolpath_generator
