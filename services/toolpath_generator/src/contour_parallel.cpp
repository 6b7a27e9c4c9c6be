// CONTOUR_PARALLEL: loops at successive offsets of the clearing area's centres, as many as the
// material left needs (each loop kept only when it cuts some of it), from the outside in or
// the inside out.
#include <algorithm>
#include <cmath>

#include "clearing.hpp"

namespace ncbridge::toolpath_generator {

namespace {

constexpr double kNothing = 1e-3;  // mm²: less left than this is nothing

bool nothing_left(const PolygonSet& left) { return without_slivers(left, 0.004).area() < kNothing; }

}  // namespace

std::vector<Cut> contour_parallel_cuts(const ClearingArea& c, const PolygonSet& left_in, double stepover, bool outward,
                                       const LoopSense& sense) {
  struct Loop {
    PlanarCurve curve;
    bool hole = false;
    double depth = 0;  // how far inside the area's boundary its offset runs (< 0: outside it)
    PolygonSet swept;
  };
  std::vector<Loop> loops;
  PolygonSet left = left_in;
  // The passes last: where the stock about a part is narrower than the cutter, only their
  // band holds the loop along the part.
  const std::pair<const PolygonSet*, double> bases[] = {
      {&c.tight, c.radius - c.run_out}, {&c.loose, c.run_out - c.radius}, {&c.passes, -(c.radius + c.run_out)}};
  for (const auto& [base, base_depth] : bases) {
    if (nothing_left(left)) break;
    if (base->empty()) continue;
    for (int i = 0; i < 100000; ++i) {
      PolygonSet region = i == 0 ? *base : base->offset(-i * stepover, kArcTolerance);
      bool last = false;
      if (region.empty()) {
        if (i == 0) break;
        // A last loop half a step in: with a stepover up to the cutter's diameter, the offsets
        // then leave nothing along the middle.
        region = base->offset(-(i - 0.5) * stepover, kArcTolerance);
        last = true;
        if (region.empty()) break;
      }
      struct Candidate {
        Loop loop;
        PolygonSet swept;
        double gain;
      };
      std::vector<Candidate> candidates;
      for (const auto& ring : region.rings()) {
        Candidate k;
        k.loop.curve = curve_from_ring(ring);
        k.loop.hole = material_check::signed_area(ring) < 0;
        k.loop.depth = base_depth + (last ? i - 0.5 : i) * stepover;
        k.swept = swept_by({k.loop.curve}, c.radius);
        k.gain = k.swept.intersected(left).area();
        candidates.push_back(std::move(k));
      }
      std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) { return a.gain > b.gain; });
      for (auto& k : candidates) {
        if (k.swept.intersected(left).area() < kNothing) continue;
        left = left.minus(k.swept);
        k.loop.swept = std::move(k.swept);
        loops.push_back(std::move(k.loop));
      }
      if (last || nothing_left(left)) break;
    }
  }
  // The bases' loops interleave in depth (a face's tight loops lie inside its passes' loops):
  // one monotonic order, or the recogniser reads the jumps between them as another strategy.
  std::stable_sort(loops.begin(), loops.end(), [](const Loop& a, const Loop& b) { return a.depth < b.depth; });
  if (outward) {
    std::reverse(loops.begin(), loops.end());
    // Enter on a loop with room to ramp round (not a sliver about the middle).
    auto roomy = std::find_if(loops.begin(), loops.end(), [&](const Loop& l) { return l.curve.length() >= 2 * c.radius; });
    if (roomy != loops.end()) std::rotate(loops.begin(), roomy, roomy + 1);
  }
  // In that order a loop may find nothing left that the loops before it do not cut (an outside
  // profile's corner loops, before the one loop round the part that cuts them too): dropped.
  left = left_in;
  std::erase_if(loops, [&](const Loop& l) {
    if (l.swept.intersected(left).area() < kNothing) return true;
    left = left.minus(l.swept);
    return false;
  });
  std::vector<Cut> out;
  for (auto& l : loops) {
    const bool ccw = l.curve.signed_area() > 0;
    if (ccw != counter_clockwise_for(sense, l.hole)) l.curve = l.curve.reversed();
    out.push_back({std::move(l.curve), false});
  }
  return out;
}

}  // namespace ncbridge::toolpath_generator
