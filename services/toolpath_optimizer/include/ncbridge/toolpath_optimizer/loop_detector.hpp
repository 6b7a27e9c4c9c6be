#pragma once
// Repeated layers as loops (--loops): consecutive layers whose path is the same up to a shift
// along Z become one body and a Loop element (toolpath.hpp), for writers that have a loop
// construct (KRL FOR, the CNC dialects' repeats).
//
// A layer starts at each motion that changes Z (a Z hop makes a layer of its own), together
// with what came after the previous layer's last motion (its comments, a fan speed); a body is 1
// to max_period such layers, repeated at least twice with the same Z shift between repeats.
// Two layers match when they have the same elements in the same order: motions of the same
// kind, feed and plane, ends (and starts, except a first straight move, which names every axis)
// and arc centres equal in X and Y and shifted by the same amount in Z, extrusion equal to
// extrusion_match; text lines and canonical calls equal, comments apart (the body keeps the
// first layer's comments). Memory holds 2 * max_period layers besides the body.
#include <cstdint>
#include <deque>
#include <vector>

#include "ncbridge/toolpath_optimizer/toolpath.hpp"

namespace ncbridge::toolpath_optimizer {

struct LoopOptions {
  std::size_t max_period = 8;        // layers in one body
  double position_match = 1e-6;      // program units
  double extrusion_match = 5e-5;     // filament per motion
};

struct LoopStats {
  std::uint64_t loops = 0;
  std::uint64_t layers_in_loops = 0;   // layers written as repeats (not the bodies themselves)
};

class LoopDetector final : public ElementSink {
 public:
  LoopDetector(const LoopOptions& options, ElementSink& out);
  void element(Element&& e) override;
  void end() override;
  const LoopStats& stats() const { return stats_; }

 private:
  struct Layer {
    std::vector<Element> elements;
    double z = 0;
    bool has_motion = false;
  };
  void close_layer();
  void settle(bool at_end);
  bool same_layer(const Layer& a, const Layer& b, double shift) const;
  void emit_layer(Layer&& layer);
  void emit_loop();

  LoopOptions options_;
  ElementSink& out_;
  LoopStats stats_;
  Layer current_;
  std::size_t last_motion_ = 0;  // index of the current layer's last motion
  bool z_known_ = false;
  double z_ = 0;
  std::deque<Layer> pending_;
  // The loop being grown: body layers, repeats so far, shift between repeats.
  std::vector<Layer> body_;
  std::uint32_t count_ = 0;
  double shift_ = 0;
};

}  // namespace ncbridge::toolpath_optimizer
