#include <string_view>

#include "ncbridge/part_reader/part.hpp"

namespace ncbridge::part_reader {

std::string_view to_string(FeatureKind kind) {
  switch (kind) {
    case FeatureKind::PlanarFace: return "planar_face";
    case FeatureKind::RoundHole: return "round_hole";
    case FeatureKind::ClosedPocket: return "closed_pocket";
    case FeatureKind::OpenPocket: return "open_pocket";
    case FeatureKind::Slot: return "slot";
    case FeatureKind::Step: return "step";
    case FeatureKind::GeneralOutsideProfile: return "general_outside_profile";
  }
  return "round_hole";
}

std::string_view to_string(HoleBottom bottom) {
  switch (bottom) {
    case HoleBottom::Through: return "through";
    case HoleBottom::Flat: return "flat";
    case HoleBottom::Conical: return "conical";
    case HoleBottom::FlatWithRadius: return "flat with radius";
    case HoleBottom::Spherical: return "spherical";
  }
  return "flat";
}

std::string_view to_string(SlotEnd end) {
  switch (end) {
    case SlotEnd::Open: return "open";
    case SlotEnd::Radiused: return "radiused";
    case SlotEnd::Flat: return "flat";
  }
  return "open";
}

std::string_view to_string(Side side) {
  switch (side) {
    case Side::XMinus: return "x-";
    case Side::XPlus: return "x+";
    case Side::YMinus: return "y-";
    case Side::YPlus: return "y+";
  }
  return "x-";
}

std::string_view to_string(SetupUp up) {
  switch (up) {
    case SetupUp::PlusZ: return "+z";
    case SetupUp::MinusZ: return "-z";
    case SetupUp::PlusX: return "+x";
    case SetupUp::MinusX: return "-x";
    case SetupUp::PlusY: return "+y";
    case SetupUp::MinusY: return "-y";
  }
  return "+z";
}

std::optional<SetupUp> setup_up_from_string(std::string_view text) {
  for (SetupUp up : {SetupUp::PlusZ, SetupUp::MinusZ, SetupUp::PlusX, SetupUp::MinusX, SetupUp::PlusY, SetupUp::MinusY}) {
    if (text == to_string(up) || (text.size() == 1 && text[0] == to_string(up)[1] && to_string(up)[0] == '+')) return up;
  }
  return std::nullopt;
}

std::string_view to_string(CompoundKind kind) {
  return kind == CompoundKind::Counterbore ? "counterbore" : "countersink";
}

}  // namespace ncbridge::part_reader
