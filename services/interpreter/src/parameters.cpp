#include "parameters.hpp"

#include <cmath>

namespace ncbridge::interpreter {

Parameters::Parameters() : numbered_(kCount, 0.0) {
  numbered_[5599] = 1.0;  // LinuxCNC: (DEBUG,...) messages are shown while #5599 is not 0
}

bool Parameters::valid_number(double number) {
  return number >= 1 && number < kCount && std::fabs(number - std::round(number)) < 1e-4;
}

std::optional<double> Parameters::named(std::string_view name) const {
  if (!name.empty() && name.front() == '_') {
    if (computed_ != nullptr) {
      if (auto v = computed_->computed(name)) return v;
    }
    auto it = globals_.find(name);
    if (it != globals_.end()) return it->second;
    return std::nullopt;
  }
  const NameMap& locals = frames_.empty() ? top_locals_ : frames_.back().locals;
  auto it = locals.find(name);
  if (it != locals.end()) return it->second;
  return std::nullopt;
}

void Parameters::set_named(std::string_view name, double value) {
  NameMap& map = (!name.empty() && name.front() == '_') ? globals_
                 : frames_.empty()                       ? top_locals_
                                                         : frames_.back().locals;
  auto it = map.find(name);
  if (it != map.end()) {
    it->second = value;
  } else {
    map.emplace(std::string(name), value);
  }
}

void Parameters::push_scope() {
  Frame frame;
  for (int i = 0; i < kLocalCount; ++i) frame.saved[static_cast<std::size_t>(i)] = numbered_[static_cast<std::size_t>(i + 1)];
  frames_.push_back(std::move(frame));
}

void Parameters::pop_scope() {
  if (frames_.empty()) return;
  const Frame& frame = frames_.back();
  for (int i = 0; i < kLocalCount; ++i) numbered_[static_cast<std::size_t>(i + 1)] = frame.saved[static_cast<std::size_t>(i)];
  frames_.pop_back();
}

}  // namespace ncbridge::interpreter
