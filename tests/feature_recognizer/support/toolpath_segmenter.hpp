#pragma once
// Test support: cuts a canonical call stream into toolpath workingsteps, as the cc1_builder
// does: a new workingstep at a tool change, a spindle speed change, and the first cutting move
// after a rapid that climbed (a retract between cuts). Feed changes do not split (plunge and
// cutting feeds alternate inside one operation).
#include <vector>

#include "ncbridge/canonical/call.hpp"
#include "ncbridge/feature_recognizer/toolpath.hpp"
#include "ncbridge/setup/tool_list.hpp"

namespace ncbridge::test_support {

std::vector<feature_recognizer::ToolpathWorkingstep> segment_workingsteps(const std::vector<canonical::Call>& calls,
                                                                          const setup::ToolList& tools);

}  // namespace ncbridge::test_support
