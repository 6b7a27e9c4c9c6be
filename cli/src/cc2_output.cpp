#include "cc2_output.hpp"

#include <cmath>
#include <string>

#include "ncbridge/common/error.hpp"
#include "ncbridge/feature_recognizer/cc1_input.hpp"
#include "ncbridge/feature_recognizer/recognizer.hpp"
#include "ncbridge/feature_recognizer/to_stepnc.hpp"

namespace ncbridge::cli {

namespace fr = feature_recognizer;

namespace {

double tidy(double v) {
  const double r = std::round(v * 1e6) / 1e6;
  return r == 0 ? 0 : r;
}

nlohmann::ordered_json dimensions(const fr::RecognizedFeature& f) {
  nlohmann::ordered_json d = nlohmann::ordered_json::object();
  const auto& p = f.profile;
  switch (f.type) {
    case fr::FeatureType::RoundHole: d["diameter"] = tidy(f.diameter); break;
    case fr::FeatureType::Slot: {
      double course = 0;
      if (f.slot_course.size() >= 2) {
        course = std::hypot(f.slot_course.back().x - f.slot_course.front().x,
                            f.slot_course.back().y - f.slot_course.front().y);
      }
      const bool radiused = f.slot_ends[0] == fr::SlotEnd::Radiused || f.slot_ends[1] == fr::SlotEnd::Radiused;
      d["length"] = tidy(radiused ? course + f.slot_width : course);
      d["width"] = tidy(f.slot_width);
      d["angle_deg"] = tidy(p.angle_deg);
      break;
    }
    default:
      if (p.shape == fr::ProfileShape::Circular) {
        d["diameter"] = tidy(p.diameter);
        break;
      }
      d["length"] = tidy(p.length);
      d["width"] = tidy(p.width);
      if (p.shape == fr::ProfileShape::Rectangular) d["corner_radius"] = tidy(p.corner_radius);
      d["angle_deg"] = tidy(p.angle_deg);
  }
  return d;
}

}  // namespace

Cc2Output build_cc2(const stepnc::Project& cc1, const std::optional<setup::Stock>& stock, const std::string& source,
                    const std::function<void()>& checkpoint) {
  Cc2Output out;
  // The CC1 project's rawpiece first: a program converted directly and its CC1 file then give
  // the same stock, hence the same CC2 bytes.
  const auto rawpiece = fr::stock_from_cc1(cc1);
  if (rawpiece) out.stock = *rawpiece;
  else if (stock) out.stock = *stock;
  else throw InputError({source, 1, 1}, "no stock: the file has no rawpiece block; give --stock");
  try {
    fr::Options options;
    options.checkpoint = checkpoint;
    out.features = fr::recognize(fr::workingsteps_from_cc1(cc1), out.stock, options);
  } catch (const InputError& e) {
    // The recogniser knows the program lines of its moves, not the file: name it here.
    if (!e.where().file.empty()) throw;
    throw InputError({source, e.where().line == 0 ? 1 : e.where().line, e.where().column == 0 ? 1 : e.where().column},
                     e.message());
  }
  auto cc2 = fr::cc2_from_cc1(cc1, out.features);
  out.project = std::move(cc2.project);
  out.feature_ids = std::move(cc2.feature_ids);
  out.workingstep_ids = std::move(cc2.workingstep_ids);
  out.warnings = std::move(cc2.warnings);
  std::size_t approximate = 0;
  for (const auto& f : out.features) approximate += f.approximate ? 1 : 0;
  if (approximate > 0) {
    out.warnings.push_back(std::to_string(approximate) + " of " + std::to_string(out.features.size()) +
                           " features are approximate: the program's cuts overlap too densely to be analysed within "
                           "the recognition work limit (docs/recognition.md, \"Bounded cost\")");
  }
  return out;
}

nlohmann::ordered_json cc2_features_json(const Cc2Output& out) {
  using json = nlohmann::ordered_json;
  json features = json::array();
  for (std::size_t i = 0; i < out.features.size(); ++i) {
    const auto& f = out.features[i];
    json j;
    j["id"] = out.feature_ids.at(i);
    j["type"] = fr::to_string(f.type);
    j["center_xy"] = {tidy(f.x), tidy(f.y)};
    j["top_z"] = tidy(f.top_z);
    j["bottom_z"] = tidy(f.bottom_z);
    j["depth"] = tidy(f.depth());
    j["dimensions"] = dimensions(f);
    j["bottom_condition"] = fr::to_string(f.bottom);
    if (f.bottom == fr::BottomCondition::Conical) j["bottom_angle_deg"] = tidy(f.bottom_angle_deg);
    json sides = json::array();
    for (auto s : f.open_sides) sides.push_back(fr::to_string(s));
    j["open_sides"] = sides;
    if (f.approximate) j["approximate"] = true;
    if (f.type == fr::FeatureType::Slot) {
      json ends = json::array();
      for (auto e : f.slot_ends) ends.push_back(e == fr::SlotEnd::Open ? "open" : e == fr::SlotEnd::Flat ? "flat" : "radiused");
      j["end_conditions"] = ends;
    }
    json ops = json::array();
    for (std::size_t k = 0; k < f.operations.size(); ++k) {
      const auto& op = f.operations[k];
      json o;
      o["type"] = fr::to_string(op.type);
      o["tool_number"] = op.tool_number;
      o["strategy"] = fr::to_string(op.strategy);
      o["layers"] = op.layers;
      if (op.axial_depth > 0) o["axial_depth"] = tidy(op.axial_depth);
      if (op.radial_depth > 0) o["radial_depth"] = tidy(op.radial_depth);
      if (op.side_allowance > 0) o["side_allowance"] = tidy(op.side_allowance);
      if (op.bottom_allowance > 0) o["bottom_allowance"] = tidy(op.bottom_allowance);
      const auto& ws = out.workingstep_ids.at(i).at(k);
      if (!ws.empty()) o["workingstep"] = ws;
      ops.push_back(std::move(o));
    }
    j["operations"] = ops;
    features.push_back(std::move(j));
  }
  return features;
}

}  // namespace ncbridge::cli
