#pragma once
// The deviation checker: how far an optimized program strays from its input, measured on the
// two programs as their front-ends read them (loops expanded), independently of how the
// optimizer built the output.
//
// Both paths are walked in order. Every output motion must start and end at a point where the
// input path is at that moment (the optimizer keeps the input's vertices at the ends of what it
// writes); the input motions in between are the output motion's span. For each span:
// - input to output: every input vertex, and points along input arcs, to the output motion;
// - output to input: points along the output motion, at most tolerance/20 apart where the
//   distance comes near the band, to the span's input path; between two samples d1, d2 at h
//   apart no point is farther than (d1 + d2 + h) / 2, and an interval where that exceeds the
//   band is halved until it does not (to the band plus 1e-6: floating point);
// - extrusion: the output motion's filament length against the span's sum.
// Filament-only moves (retractions, primes) must pair up one to one. The distance of a point to
// a helix is taken to the helix point at the query's angle (exact for plane arcs, an upper
// bound otherwise). The figures reported are the largest sampled distances.
// Deviations are collected per layer (the output motion's end Z, in 0.01 steps).
#include <cstdint>
#include <string>
#include <vector>

#include "ncbridge/toolpath_optimizer/toolpath.hpp"

namespace ncbridge::toolpath_optimizer {

// One motion as the checker needs it.
struct PathPiece {
  MotionKind kind = MotionKind::Line;
  Vec3 start, end;
  ArcGeometry arc;
  double extrusion = 0;
  std::uint32_t line = 0;
};

// Collects the path of an element stream in mm, loops expanded; skips motions from an unknown
// position and motions that move nothing.
class PathRecorder final : public ElementSink {
 public:
  void element(Element&& e) override;
  std::vector<PathPiece> pieces;

 private:
  void add(const Element& e, double z_shift);
};

struct DeviationOptions {
  double tolerance = 0.025;             // the band being checked, mm
  double extrusion_tolerance = 1e-4;    // filament per motion, absolute (plus 1e-6 relative)
  double vertex_match = 2e-4;           // an output end is an input vertex this close (rounding)
  std::size_t max_problems = 20;        // problems listed in the report
};

struct LayerDeviation {
  double z = 0;
  double input_to_output = 0;
  double output_to_input = 0;
  std::uint32_t output_motions = 0;
};

struct DeviationReport {
  double input_to_output = 0;     // largest distance of the input path from the output path
  double output_to_input = 0;     // and the other way
  double extrusion_error = 0;     // largest filament difference of one output motion
  std::uint32_t worst_output_line = 0;  // the output line with the largest deviation
  std::uint64_t input_motions = 0, output_motions = 0, spans = 0;
  std::size_t layer_count = 0;
  std::vector<LayerDeviation> worst_layers;  // up to 20, largest deviation first
  std::vector<std::string> problems;         // what does not match, in order (first max_problems)
  std::uint64_t problem_count = 0;

  double largest() const { return input_to_output > output_to_input ? input_to_output : output_to_input; }
  // Within the band (plus 1e-6 for floating point), with nothing unmatched.
  bool passed(double tolerance) const { return problem_count == 0 && largest() <= tolerance + 1e-6; }
};

DeviationReport check_deviation(const std::vector<PathPiece>& input, const std::vector<PathPiece>& output,
                                const DeviationOptions& options);

}  // namespace ncbridge::toolpath_optimizer
