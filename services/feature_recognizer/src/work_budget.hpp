#pragma once
// The bound on exact geometric work (docs/recognition.md, "Bounded cost"). Each stage that makes
// or compares regions (swept areas, grouping, classification, the material model) may spend
// up to a limit proportional to the program's toolpath points, in units of region_work() (one
// vertex handed to or made by a Boolean operation). What a stage meets after its limit is treated
// coarsely, so that the whole recognition is linear in the program's size on any input; real
// parts stay far inside it.
#include <cstddef>
#include <cstdint>
#include <limits>

#include "region.hpp"

namespace ncbridge::feature_recognizer {

class WorkBudget {
 public:
  WorkBudget() = default;  // unlimited
  explicit WorkBudget(double limit) : limit_(limit) {}
  bool available() const { return spent_ < limit_; }
  void spend(double units) { spent_ += units; }
  double spent() const { return spent_; }

 private:
  double limit_ = std::numeric_limits<double>::infinity();
  double spent_ = 0;
};

// Charges a budget with the region work done while it lives.
class WorkCharge {
 public:
  explicit WorkCharge(WorkBudget& budget) : budget_(budget), start_(region_work()) {}
  ~WorkCharge() { budget_.spend(static_cast<double>(region_work() - start_)); }
  WorkCharge(const WorkCharge&) = delete;
  WorkCharge& operator=(const WorkCharge&) = delete;

 private:
  WorkBudget& budget_;
  std::uint64_t start_;
};

}  // namespace ncbridge::feature_recognizer
