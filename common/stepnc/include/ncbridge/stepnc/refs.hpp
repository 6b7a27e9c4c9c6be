#pragma once
// Typed indices into the Project's tables: a workingstep names its feature and operation, an
// operation its tool, technology and machine functions. Several may share one (as in a file).
#include <cstdint>

namespace ncbridge::stepnc {

template <class Tag>
struct Ref {
  std::uint32_t index = 0;
  friend bool operator==(const Ref&, const Ref&) = default;
  friend auto operator<=>(const Ref&, const Ref&) = default;
};

using ToolRef = Ref<struct ToolTag>;
using TechnologyRef = Ref<struct TechnologyTag>;
using MachineFunctionsRef = Ref<struct MachineFunctionsTag>;
using FeatureRef = Ref<struct FeatureTag>;
using OperationRef = Ref<struct OperationTag>;

}  // namespace ncbridge::stepnc
