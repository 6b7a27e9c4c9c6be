#include "ncbridge/process_planner/planner.hpp"

#include <algorithm>

#include "feature_entities.hpp"
#include "ncbridge/common/error.hpp"
#include "operation_plan.hpp"
#include "tool_choice.hpp"
#include "workplan.hpp"

namespace ncbridge::process_planner {

namespace pr = part_reader;

std::optional<Material> material_from_string(std::string_view name) {
  for (Material m : {Material::Steel, Material::Aluminium, Material::StainlessSteel, Material::CastIron, Material::Brass, Material::Plastic}) {
    if (name == to_string(m)) return m;
  }
  if (name == "aluminum") return Material::Aluminium;
  return std::nullopt;
}

std::string_view to_string(Material material) {
  switch (material) {
    case Material::Steel: return "steel";
    case Material::Aluminium: return "aluminium";
    case Material::StainlessSteel: return "stainless";
    case Material::CastIron: return "cast_iron";
    case Material::Brass: return "brass";
    case Material::Plastic: return "plastic";
  }
  return "steel";
}

Plan plan(const pr::Part& part, const setup::Stock& stock, const setup::ToolList& tools, const Options& options) {
  Plan out;
  const PlanContext context{tools, stock, options, part, out.warnings};
  std::vector<const pr::Feature*> planned;
  std::vector<std::size_t> index;
  for (std::size_t i = 0; i < part.features.size(); ++i) {
    if (!part.features[i].accessible) continue;
    planned.push_back(&part.features[i]);
    index.push_back(i);
  }
  const auto ids = feature_ids(planned);
  std::vector<FeaturePlan> features;
  for (std::size_t k = 0; k < planned.size(); ++k) {
    const pr::Feature& f = *planned[k];
    FeaturePlan fp;
    fp.part_feature = index[k];
    fp.id = ids[k];
    fp.feature = to_stepnc(f, ids[k]);
    switch (f.kind) {
      case pr::FeatureKind::PlanarFace: fp.operations = plan_face(f, ids[k], context); break;
      case pr::FeatureKind::ClosedPocket:
      case pr::FeatureKind::OpenPocket: fp.operations = plan_pocket(f, ids[k], context); break;
      case pr::FeatureKind::Slot: fp.operations = plan_slot(f, ids[k], context); break;
      case pr::FeatureKind::Step: fp.operations = plan_step(f, ids[k], context); break;
      case pr::FeatureKind::GeneralOutsideProfile: fp.operations = plan_outside_profile(f, ids[k], context); break;
      case pr::FeatureKind::RoundHole: {
        bool counterbore = false, countersink = false;
        if (f.compound >= 0 && static_cast<std::size_t>(f.compound) < part.compounds.size()) {
          const auto& c = part.compounds[static_cast<std::size_t>(f.compound)];
          // Every step of a counterbore but the innermost is milled flat; a countersink's cone is sunk.
          counterbore = c.kind == pr::CompoundKind::Counterbore && c.elements.size() >= 2 && c.elements.back() != index[k];
          countersink = c.kind == pr::CompoundKind::Countersink && c.elements.front() == index[k];
        }
        fp.operations = countersink ? plan_countersink(f, ids[k], context) : plan_hole(f, ids[k], counterbore, context);
        break;
      }
    }
    features.push_back(std::move(fp));
  }
  build_workplan(features, stock, part, options, out);
  return out;
}

}  // namespace ncbridge::process_planner
