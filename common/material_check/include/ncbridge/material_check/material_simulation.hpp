#pragma once
// A 2.5D material simulation: the stock as heights sampled on a regular XY grid (cell centres)
// plus any extra sample points (probes along feature walls); each feed move lowers every
// sample its cutter sweeps to the cutter's lowest surface over the move, computed exactly for
// straight moves and XY arcs (helical arcs as chords within 0.0005 mm). Rapids remove nothing:
// they report how deep they would have gone into the material.
#include <cstddef>
#include <vector>

#include "ncbridge/material_check/cutter_shape.hpp"
#include "ncbridge/material_check/toolpath_program.hpp"
#include "ncbridge/setup/stock.hpp"

namespace ncbridge::material_check {

class HeightGrid {
 public:
  HeightGrid() = default;
  // Samples at the centres of `cell`-sized cells covering the stock's XY box, at its top.
  HeightGrid(const setup::Stock& stock, double cell);

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  double cell() const { return cell_; }
  double x(int i) const { return x0_ + (i + 0.5) * cell_; }
  double y(int j) const { return y0_ + (j + 0.5) * cell_; }
  float height(int i, int j) const { return heights_[static_cast<std::size_t>(j) * nx_ + i]; }
  float& height(int i, int j) { return heights_[static_cast<std::size_t>(j) * nx_ + i]; }
  std::size_t size() const { return heights_.size(); }
  const std::vector<float>& heights() const { return heights_; }
  // Index ranges of the cells whose centres lie within [lo, hi] (empty when first > last).
  int first_column(double x_lo) const;
  int last_column(double x_hi) const;
  int first_row(double y_lo) const;
  int last_row(double y_hi) const;

 private:
  double x0_ = 0, y0_ = 0, cell_ = 1;
  int nx_ = 0, ny_ = 0;
  std::vector<float> heights_;
};

// The outcome of one feed move.
struct CutResult {
  bool removed = false;        // some sample got lower
  double removed_volume = 0;   // mm³ on the grid (cell area x height drop)
  double centre_depth = 0;     // deepest cut within half the cutter's radius of its axis
};

class MaterialSimulation {
 public:
  // `cell` = sample spacing (mm); `probes` = extra sample points (those outside the stock are
  // kept but never hold material).
  MaterialSimulation(const setup::Stock& stock, double cell, std::vector<Point2> probes = {});

  CutResult feed(const Point3& from, const Motion& motion, const CutterShape& cutter);
  // How deep (mm) the cutter would go into the material along the move; 0 when clear.
  double penetration(const Point3& from, const Motion& motion, const CutterShape& cutter) const;

  const HeightGrid& grid() const { return grid_; }
  const std::vector<Point2>& probes() const { return probes_; }
  const std::vector<float>& probe_heights() const { return probe_heights_; }
  const setup::Stock& stock() const { return stock_; }

 private:
  template <class Visit>
  void sweep(const Point3& from, const Motion& motion, const CutterShape& cutter, Visit&& visit) const;

  setup::Stock stock_;
  HeightGrid grid_;
  std::vector<Point2> probes_;
  std::vector<float> probe_heights_;
  // Probes bucketed by a coarse grid for lookup by box.
  double bucket_ = 1;
  int bx_ = 0, by_ = 0;
  std::vector<std::vector<std::size_t>> buckets_;
};

// The sample spacing used when none is given: 0.1 mm, coarser for large stocks so that the
// grid stays within about 4 million samples.
double automatic_cell(const setup::Stock& stock);

}  // namespace ncbridge::material_check
