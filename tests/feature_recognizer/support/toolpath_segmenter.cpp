#include "toolpath_segmenter.hpp"

#include <algorithm>
#include <type_traits>

#include "ncbridge/common/error.hpp"

namespace ncbridge::test_support {

namespace fr = feature_recognizer;

std::vector<fr::ToolpathWorkingstep> segment_workingsteps(const std::vector<canonical::Call>& calls,
                                                          const setup::ToolList& tools) {
  std::vector<fr::ToolpathWorkingstep> out;
  double scale = 1;  // to mm
  fr::Point3 at;
  setup::Tool tool;
  double feed = 0, rpm = 0;
  bool climbed_since_cut = true;  // a new workingstep starts at the next cutting move
  canonical::Plane plane = canonical::Plane::XY;
  fr::ToolpathWorkingstep current;
  std::vector<fr::Move> rapids_before;  // rapids since the last cut, carried into the next workingstep
  fr::Point3 rapids_start;
  bool cutting = false;

  auto close = [&] {
    if (cutting) out.push_back(std::move(current));
    current = {};
    cutting = false;
  };
  auto cut = [&](fr::Move move) {
    if (!cutting || climbed_since_cut) {
      close();
      current.tool = tool;
      current.spindle_rpm = rpm;
      current.start = rapids_start;
      current.moves = rapids_before;
      cutting = true;
    } else {
      current.moves.insert(current.moves.end(), rapids_before.begin(), rapids_before.end());
    }
    rapids_before.clear();
    current.feed = std::max(current.feed, feed);
    current.moves.push_back(move);
    climbed_since_cut = false;
    rapids_start = move.end;
  };

  for (const auto& call : calls) {
    std::visit(
        [&](const auto& d) {
          using T = std::decay_t<decltype(d)>;
          if constexpr (std::is_same_v<T, canonical::UseLengthUnits>) {
            scale = d.units == canonical::Units::Inches ? 25.4 : 1.0;
          } else if constexpr (std::is_same_v<T, canonical::SelectPlane>) {
            plane = d.plane;
          } else if constexpr (std::is_same_v<T, canonical::ChangeTool>) {
            close();
            climbed_since_cut = true;
            const auto* t = tools.find(d.slot);
            tool = t ? *t : setup::Tool{};
            tool.number = d.slot;
          } else if constexpr (std::is_same_v<T, canonical::SetSpindleSpeed>) {
            if (d.rpm != rpm) climbed_since_cut = true;
            rpm = d.rpm;
          } else if constexpr (std::is_same_v<T, canonical::SetFeedRate>) {
            feed = d.rate * scale;
          } else if constexpr (std::is_same_v<T, canonical::StraightTraverse>) {
            fr::Move m{fr::MoveKind::Rapid, {d.end.x * scale, d.end.y * scale, d.end.z * scale}};
            m.source_line = call.source.line;
            if (m.end.z > at.z + 1e-6) climbed_since_cut = true;
            if (rapids_before.empty() && !cutting) rapids_start = at;
            rapids_before.push_back(m);
            at = m.end;
          } else if constexpr (std::is_same_v<T, canonical::StraightFeed>) {
            fr::Move m{fr::MoveKind::Linear, {d.end.x * scale, d.end.y * scale, d.end.z * scale}};
            m.source_line = call.source.line;
            cut(m);
            at = m.end;
          } else if constexpr (std::is_same_v<T, canonical::ArcFeed>) {
            if (plane != canonical::Plane::XY) {
              throw InputError({"", call.source.line, 0}, "arcs outside the XY plane are not supported here");
            }
            fr::Move m{fr::MoveKind::Arc, {d.first_end * scale, d.second_end * scale, d.axis_end_point * scale}};
            m.center_x = d.first_axis * scale;
            m.center_y = d.second_axis * scale;
            m.clockwise = d.rotation < 0;
            m.turns = std::max(1, std::abs(d.rotation));
            m.source_line = call.source.line;
            cut(m);
            at = m.end;
          }
        },
        call.data);
  }
  close();
  return out;
}

}  // namespace ncbridge::test_support
