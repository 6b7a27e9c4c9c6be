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
#include <deque>
#include <functional>
#include <map>
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

// The path of an element stream in mm, loops expanded, piece by piece to `each`; motions from an
// unknown position and motions that move nothing are skipped.
void path_pieces(const Element& e, const std::function<void(const PathPiece&)>& each);

// Collects the path of an element stream (path_pieces).
class PathRecorder final : public ElementSink {
 public:
  void element(Element&& e) override;
  std::vector<PathPiece> pieces;
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

// The checker fed as the two programs stream: input pieces as the input is read, output pieces
// as the written output is read back. Each output piece is checked as soon as the input up to
// its end has come, and the input before it is dropped: what is held is the input not yet
// matched by output (the optimizer's run and the writer's buffer, in a streaming pipeline), not
// the file.
class DeviationChecker {
 public:
  explicit DeviationChecker(const DeviationOptions& options) : options_(options) {}
  void input(const PathPiece& piece);
  void output(const PathPiece& piece);
  // Checks what is left; the report. Pieces after finish() are ignored.
  DeviationReport finish();
  // The most input and output pieces held at once so far.
  std::size_t most_held() const { return most_held_; }

 private:
  bool check_next(bool final);  // false: the front output piece needs input not come yet
  void drain(bool final);
  void consume(std::size_t input_pieces);
  bool stop();
  void problem(const std::string& text);
  static std::string where(const PathPiece& p);

  DeviationOptions options_;
  DeviationReport report_;
  std::deque<PathPiece> input_, output_;
  std::map<long long, LayerDeviation> layers_;
  std::size_t retry_at_ = 0, most_held_ = 0;
  bool stopped_ = false, finished_ = false;
};

// Sends an element stream's path pieces to the checker's input or output side.
class CheckerFeed final : public ElementSink {
 public:
  CheckerFeed(DeviationChecker& checker, bool output) : checker_(checker), output_(output) {}
  void element(Element&& e) override;

 private:
  DeviationChecker& checker_;
  bool output_;
};

// The whole of both paths at once.
DeviationReport check_deviation(const std::vector<PathPiece>& input, const std::vector<PathPiece>& output,
                                const DeviationOptions& options);

}  // namespace ncbridge::toolpath_optimizer
