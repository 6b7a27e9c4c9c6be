#pragma once
// The material check: simulate a program's toolpaths on the stock (material_simulation.hpp)
// and compare what is left with the part the CC2 features describe. It reports figures; tests
// and callers decide what passes:
//   - per feature, the share of its floor (and walls, by probes just inside them) that was cut
//     down to the design within the tolerance plus what the feature's last operation may leave
//     (allowances, a ball or bull-nose cutter's scallop), and the largest leftover; areas no tool
//     of the feature can reach (a corner sharper than the cutter) are counted apart;
//   - gouges: anywhere cut deeper than the part (the deepest, its place, the area);
//   - rapid moves that would go through material, and plunges (steep feed descents cutting at
//     the cutter's centre) by tools other than drills;
//   - removed volume, feed length and the feed length that cut nothing.
#include <cstddef>
#include <string>
#include <vector>

#include "ncbridge/material_check/feature_region.hpp"
#include "ncbridge/material_check/material_simulation.hpp"
#include "ncbridge/material_check/toolpath_program.hpp"
#include "ncbridge/setup/stock.hpp"
#include "ncbridge/stepnc/project.hpp"

namespace ncbridge::material_check {

struct DesignedFeature {
  FeatureRegion region;
  // The reach of the smallest milling cutter of the feature's operations (its radius, and its
  // corner radius): where a circle of that radius cannot go, nothing is expected. 0 = drilled.
  double reach_radius = 0;
  double reach_corner_radius = 0;
  // What the feature's last operation may leave when it is a roughing: its side allowance (the
  // walls are expected where a cutter that much larger reaches) and bottom allowance; plus the
  // scallop a ball or bull-nose cutter leaves between passes.
  double allowance_side = 0;
  double allowed_leftover = 0;  // mm above the floor, beyond the tolerance
};

struct DesignedPart {
  setup::Stock stock;
  std::vector<DesignedFeature> features;
};

// The part a CC2 model describes: the features its machining workingsteps name (not
// TOOLPATH_FEATUREs) with what their operations' tools can reach.
DesignedPart designed_part(const stepnc::Project& cc2, const setup::Stock& stock, const std::string& source_name = "");

struct CheckOptions {
  double cell = 0;                // sample spacing, mm; 0 = automatic_cell(stock)
  double tolerance = 0.01;        // mm: the gouge and leftover allowed
  double probe_offset = 0.02;     // mm: probes on both sides of every feature wall
  double wall_band = 0.01;        // mm: grid samples this close to a wall count as on it
  double steep_descent_deg = 30;  // a feed descending steeper than this is a plunge
};

struct FeatureFigures {
  std::string id;
  double floor_z = 0;
  bool through = false;
  double area = 0;              // mm²: where this feature sets the design (grid samples)
  double unreachable_area = 0;  // mm² of that its tools cannot reach
  std::size_t samples = 0;      // reachable grid samples and inner wall probes checked
  double reached_fraction = 1;  // of them, the share cut to the design within the allowance
  double max_leftover = 0;      // mm above the design
  Point3 max_leftover_at;
  double allowed_leftover = 0;  // tolerance + the feature's own allowance
};

struct Finding {
  enum class Kind { RapidThroughMaterial, Plunge };
  Kind kind = Kind::RapidThroughMaterial;
  std::string workingstep;
  Point3 from, to;
  double depth = 0;
};

struct MaterialReport {
  double cell = 0;
  std::size_t samples = 0, probes = 0;
  std::vector<FeatureFigures> features;
  double max_gouge = 0;   // mm below the design
  Point3 max_gouge_at;
  double gouge_area = 0;  // mm² of grid samples gouged beyond the tolerance
  std::size_t rapid_collisions = 0;
  double max_rapid_depth = 0;
  std::size_t plunges = 0;
  double max_plunge_depth = 0;
  std::vector<Finding> findings;  // the first 50 rapids through material and plunges
  double removed_volume = 0;      // mm³
  double feed_length = 0, air_feed_length = 0;

  double max_leftover() const;        // over every feature
  double least_reached() const;       // the smallest reached_fraction
  // No gouge beyond `tolerance`, no rapid through material, no plunge, every feature fully
  // reached within its allowance.
  bool clean(double tolerance = 0.01) const;
};

MaterialReport check_material(const ToolpathProgram& program, const DesignedPart& part, const CheckOptions& options = {});

// What a program leaves of the stock, for comparing two programs' removal.
struct Simulated {
  HeightGrid grid;
  std::size_t rapid_collisions = 0;
  std::size_t plunges = 0;
  double removed_volume = 0;
};
Simulated simulate(const ToolpathProgram& program, const setup::Stock& stock, double cell);

struct MaterialDifference {
  double max_deeper = 0;      // mm: where `b` cut deeper than `a`, the most
  Point3 max_deeper_at;
  double max_shallower = 0;   // mm: where `b` left more than `a`, the most
  Point3 max_shallower_at;
  double differing_area = 0;  // mm² of samples differing by more than the tolerance
  double volume_a = 0, volume_b = 0;  // removed, mm³
};
// Both grids must come from the same stock and spacing.
MaterialDifference compare_material(const HeightGrid& a, const HeightGrid& b, double tolerance = 0.01);

}  // namespace ncbridge::material_check
