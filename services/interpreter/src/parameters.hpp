#pragma once
// The parameter store: numbered parameters #1..#5601 (LinuxCNC numbering: #1-#30 are the
// subroutine arguments and local to each call, #5161.. hold homes, coordinate systems, G92),
// global named parameters `#<_name>`, and local named parameters `#<name>` (one scope per call).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace ncbridge::interpreter {

// Read-only named parameters computed from the machine state (#<_x>, #<_metric>, ...).
class ComputedParameters {
 public:
  virtual ~ComputedParameters() = default;
  virtual std::optional<double> computed(std::string_view name) const = 0;
};

class Parameters {
 public:
  static constexpr int kCount = 5602;
  static constexpr int kLocalCount = 30;  // #1..#30

  Parameters();

  void set_computed(const ComputedParameters* computed) { computed_ = computed; }

  static bool valid_number(double number);
  double numbered(int number) const { return numbered_[static_cast<std::size_t>(number)]; }
  void set_numbered(int number, double value) { numbered_[static_cast<std::size_t>(number)] = value; }

  // Named: `_name` is global, anything else local to the current call.
  std::optional<double> named(std::string_view name) const;
  void set_named(std::string_view name, double value);
  bool exists(std::string_view name) const { return named(name).has_value(); }

  // A subroutine call: saves #1..#30, opens a new local scope.
  void push_scope();
  void pop_scope();
  int depth() const { return static_cast<int>(frames_.size()); }

 private:
  struct Hash {
    using is_transparent = void;
    std::size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
  };
  using NameMap = std::unordered_map<std::string, double, Hash, std::equal_to<>>;
  struct Frame {
    std::array<double, kLocalCount> saved{};
    NameMap locals;
  };

  std::vector<double> numbered_;
  NameMap globals_;
  NameMap top_locals_;
  std::vector<Frame> frames_;
  const ComputedParameters* computed_ = nullptr;
};

}  // namespace ncbridge::interpreter
