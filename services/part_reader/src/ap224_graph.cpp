#include "ap224_graph.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ncbridge::part_reader::ap224 {

namespace {

void collect_references(const p21::Value& value, std::vector<InstanceId>& out) {
  if (const auto* r = value.reference_if()) {
    out.push_back(r->id);
  } else if (const auto* l = value.list_if()) {
    for (const auto& item : l->items) collect_references(item, out);
  } else if (const auto* t = value.typed_if()) {
    for (const auto& item : t->value) collect_references(item, out);
  }
}

bool is_relationship(const p21::Instance& instance) {
  for (const auto& r : instance.records) {
    if (r.entity == "SHAPE_ASPECT_RELATIONSHIP" || r.entity == "SHAPE_DEFINING_RELATIONSHIP" ||
        r.entity == "FEATURE_COMPONENT_RELATIONSHIP") {
      return true;
    }
  }
  return false;
}

// The record of a relationship instance holding (name, description, relating, related).
const p21::Record* relationship_record(const p21::Instance& instance) {
  for (const char* e : {"SHAPE_ASPECT_RELATIONSHIP", "FEATURE_COMPONENT_RELATIONSHIP", "SHAPE_DEFINING_RELATIONSHIP"}) {
    if (const auto* r = instance.record(e); r && r->attributes.size() >= 4) return r;
  }
  return nullptr;
}

double si_prefix(const std::string& prefix) {
  if (prefix == "MILLI") return 1e-3;
  if (prefix == "CENTI") return 1e-2;
  if (prefix == "DECI") return 1e-1;
  if (prefix == "KILO") return 1e3;
  if (prefix == "MICRO") return 1e-6;
  if (prefix == "NANO") return 1e-9;
  if (prefix == "DECA") return 1e1;
  if (prefix == "HECTO") return 1e2;
  return 1;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

Graph::Graph(const p21::Graph& graph, std::string file) : graph_(graph), file_(std::move(file)) {
  std::vector<InstanceId> refs;
  for (const auto& instance : graph_.instances()) {
    refs.clear();
    for (const auto& record : instance.records) {
      for (const auto& v : record.attributes) collect_references(v, refs);
    }
    std::sort(refs.begin(), refs.end());
    refs.erase(std::unique(refs.begin(), refs.end()), refs.end());
    for (InstanceId r : refs) users_[r].push_back(instance.id);
  }
}

const p21::Instance& Graph::at(InstanceId id) const {
  const p21::Instance* instance = graph_.find(id);
  if (!instance) throw InputError({file_, 0, 0}, "#" + std::to_string(id) + " does not exist");
  if (instance->records.empty()) fail(id, "instance without an entity");
  return *instance;
}

SourceLocation Graph::where(InstanceId id) const {
  const p21::Instance* instance = graph_.find(id);
  return {file_, instance ? instance->line : 0, instance ? instance->column : 0};
}

void Graph::fail(InstanceId id, const std::string& message) const {
  const p21::Instance* instance = graph_.find(id);
  std::string entity;
  if (instance && !instance->records.empty()) {
    entity = " " + instance->records.front().entity;
    if (instance->complex) {
      for (const auto& r : instance->records) {
        if (r.entity != "CHARACTERIZED_OBJECT" && r.entity != "FEATURE_DEFINITION" && r.entity != "INSTANCED_FEATURE" &&
            r.entity != "MACHINING_FEATURE" && r.entity != "SHAPE_ASPECT") {
          entity = " " + r.entity;
        }
      }
    }
  }
  throw InputError(where(id), "#" + std::to_string(id) + entity + ": " + message);
}

const std::vector<InstanceId>& Graph::users(InstanceId id) const {
  auto it = users_.find(id);
  return it == users_.end() ? none_ : it->second;
}

bool Graph::is(const p21::Instance& instance, std::string_view entity) { return instance.record(entity) != nullptr; }

const p21::Value& Graph::attribute(const p21::Instance& instance, const p21::Record& record, std::size_t index) const {
  if (index >= record.attributes.size()) {
    fail(instance.id, record.entity + " has " + std::to_string(record.attributes.size()) + " attributes, expected more than " +
                          std::to_string(index));
  }
  return record.attributes[index];
}

std::string Graph::text(const p21::Instance& instance, const p21::Record& record, std::size_t index) const {
  const p21::Value& v = attribute(instance, record, index);
  if (const auto* s = v.string_if()) return *s;
  if (v.is_unset() || v.is_derived()) return "";
  fail(instance.id, record.entity + " attribute " + std::to_string(index + 1) + " is not a string");
}

double Graph::number(const p21::Instance& instance, const p21::Value& value) const {
  if (const auto* r = value.real_if()) return *r;
  if (const auto* i = value.integer_if()) return static_cast<double>(*i);
  if (const auto* t = value.typed_if(); t && t->value.size() == 1) return number(instance, t->value.front());
  fail(instance.id, "a number was expected");
}

InstanceId Graph::reference(const p21::Instance& instance, const p21::Value& value) const {
  if (const auto* r = value.reference_if()) {
    at(r->id);
    return r->id;
  }
  fail(instance.id, "a reference was expected");
}

const std::vector<p21::Value>& Graph::list(const p21::Instance& instance, const p21::Value& value) const {
  if (const auto* l = value.list_if()) return l->items;
  fail(instance.id, "a list was expected");
}

std::optional<std::pair<std::string, std::string>> Graph::aspect_text(const p21::Instance& instance) const {
  const p21::Record* record = instance.record("SHAPE_ASPECT");
  if (!record && !instance.complex) record = &instance.records.front();
  if (!record || record->attributes.size() < 4) return std::nullopt;
  const auto& a = record->attributes;
  const std::size_t n = a.size();
  if (!a[n - 2].is_reference() || !a[n - 1].is_enumeration()) return std::nullopt;
  auto str = [](const p21::Value& v) { return v.string_if() ? *v.string_if() : std::string(); };
  return std::make_pair(str(a[n - 4]), str(a[n - 3]));
}

std::optional<InstanceId> Graph::aspect_of_shape(const p21::Instance& instance) const {
  const p21::Record* record = instance.record("SHAPE_ASPECT");
  if (!record && !instance.complex) record = &instance.records.front();
  if (!record || record->attributes.size() < 4) return std::nullopt;
  const auto& a = record->attributes;
  if (!a[a.size() - 1].is_enumeration()) return std::nullopt;
  if (const auto* r = a[a.size() - 2].reference_if()) return r->id;
  return std::nullopt;
}

std::string Graph::description_of(const p21::Instance& instance) const {
  if (const auto* co = instance.record("CHARACTERIZED_OBJECT"); co && co->attributes.size() >= 2) {
    if (const auto* s = co->attributes[1].string_if(); s && !s->empty()) return *s;
    if (const auto* s = co->attributes[0].string_if(); s && !s->empty()) return *s;
  }
  if (auto t = aspect_text(instance)) return t->second.empty() ? t->first : t->second;
  return "";
}

stepnc::CartesianPoint Graph::point(InstanceId id, double scale) const {
  const auto& instance = at(id);
  const auto* record = instance.record("CARTESIAN_POINT");
  if (!record) fail(id, "a CARTESIAN_POINT was expected");
  const auto& c = list(instance, attribute(instance, *record, 1));
  if (c.empty() || c.size() > 3) fail(id, "a point has 1 to 3 coordinates");
  stepnc::CartesianPoint p;
  p.x = number(instance, c[0]) * scale;
  if (c.size() > 1) p.y = number(instance, c[1]) * scale;
  if (c.size() > 2) p.z = number(instance, c[2]) * scale;
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) fail(id, "a coordinate is not finite");
  return p;
}

stepnc::Direction Graph::direction(InstanceId id) const {
  const auto& instance = at(id);
  const auto* record = instance.record("DIRECTION");
  if (!record) fail(id, "a DIRECTION was expected");
  const auto& c = list(instance, attribute(instance, *record, 1));
  if (c.size() != 3) fail(id, "a direction needs 3 ratios");
  double x = number(instance, c[0]), y = number(instance, c[1]), z = number(instance, c[2]);
  const double n = std::sqrt(x * x + y * y + z * z);
  if (!(n > 1e-12) || !std::isfinite(n)) fail(id, "a direction of length 0");
  x /= n, y /= n, z /= n;
  auto snap = [](double v) { return std::abs(v) < 1e-12 ? 0.0 : v; };
  return {snap(x), snap(y), snap(z)};
}

stepnc::Axis2Placement3d Graph::placement(InstanceId id, double scale) const {
  const auto& instance = at(id);
  stepnc::Axis2Placement3d p;
  if (const auto* a2 = instance.record("AXIS2_PLACEMENT_3D")) {
    p.location = point(reference(instance, attribute(instance, *a2, 1)), scale);
    const auto& axis = attribute(instance, *a2, 2);
    const auto& ref = attribute(instance, *a2, 3);
    if (!axis.is_unset()) p.axis = direction(reference(instance, axis));
    if (!ref.is_unset()) {
      p.ref_direction = direction(reference(instance, ref));
    } else {  // any direction normal to the axis
      p.ref_direction = std::abs(p.axis.x) < 0.9 ? stepnc::Direction{1, 0, 0} : stepnc::Direction{0, 1, 0};
    }
    // The ref direction as Part 42 uses it: its part normal to the axis.
    const double d = p.ref_direction.x * p.axis.x + p.ref_direction.y * p.axis.y + p.ref_direction.z * p.axis.z;
    stepnc::Direction r{p.ref_direction.x - d * p.axis.x, p.ref_direction.y - d * p.axis.y, p.ref_direction.z - d * p.axis.z};
    const double n = std::sqrt(r.x * r.x + r.y * r.y + r.z * r.z);
    if (!(n > 1e-9)) fail(id, "the reference direction is parallel to the axis");
    p.ref_direction = {r.x / n, r.y / n, r.z / n};
    return p;
  }
  if (const auto* a1 = instance.record("AXIS1_PLACEMENT")) {
    p.location = point(reference(instance, attribute(instance, *a1, 1)), scale);
    const auto& axis = attribute(instance, *a1, 2);
    if (!axis.is_unset()) p.axis = direction(reference(instance, axis));
    p.ref_direction = std::abs(p.axis.x) < 0.9 ? stepnc::Direction{1, 0, 0} : stepnc::Direction{0, 1, 0};
    const double d = p.ref_direction.x * p.axis.x + p.ref_direction.y * p.axis.y + p.ref_direction.z * p.axis.z;
    stepnc::Direction r{p.ref_direction.x - d * p.axis.x, p.ref_direction.y - d * p.axis.y, p.ref_direction.z - d * p.axis.z};
    const double n = std::sqrt(r.x * r.x + r.y * r.y + r.z * r.z);
    p.ref_direction = {r.x / n, r.y / n, r.z / n};
    return p;
  }
  fail(id, "a placement (AXIS2_PLACEMENT_3D) was expected");
}

double Graph::unit_scale(InstanceId unit, bool angle, int depth) const {
  if (depth > 8) fail(unit, "unit definitions refer to each other in a loop");
  const auto& instance = at(unit);
  if (const auto* si = instance.record("SI_UNIT")) {
    const auto& prefix = attribute(instance, *si, si->attributes.size() - 2);
    const auto& name = attribute(instance, *si, si->attributes.size() - 1);
    const double factor = prefix.is_enumeration() ? si_prefix(prefix.as_enumeration()) : 1.0;
    if (!name.is_enumeration()) fail(unit, "SI_UNIT without a unit name");
    const std::string& n = name.as_enumeration();
    if (n == "METRE") return factor * 1000.0;
    if (n == "RADIAN") return factor * 180.0 / std::numbers::pi;
    if (angle) fail(unit, "an angle unit was expected, not " + n);
    fail(unit, "a length unit was expected, not " + n);
  }
  if (const auto* cb = instance.record("CONVERSION_BASED_UNIT")) {
    const InstanceId factor_id = reference(instance, attribute(instance, *cb, 1));
    const auto& factor = at(factor_id);
    const p21::Record* mwu = factor.record("MEASURE_WITH_UNIT");
    for (const char* e : {"LENGTH_MEASURE_WITH_UNIT", "PLANE_ANGLE_MEASURE_WITH_UNIT"}) {
      if (!mwu && !factor.complex) mwu = factor.record(e);
    }
    if (!mwu || mwu->attributes.size() < 2) fail(factor_id, "a measure with unit was expected");
    return number(factor, mwu->attributes[0]) * unit_scale(reference(factor, mwu->attributes[1]), angle, depth + 1);
  }
  fail(unit, "an SI or conversion-based unit was expected");
}

double Graph::length_unit_mm(InstanceId unit) const {
  const double s = unit_scale(unit, false, 0);
  if (!(s > 0) || !std::isfinite(s)) fail(unit, "a length unit must be positive");
  return s;
}

double Graph::angle_unit_degrees(InstanceId unit) const {
  const double s = unit_scale(unit, true, 0);
  if (!(s > 0) || !std::isfinite(s)) fail(unit, "an angle unit must be positive");
  return s;
}

namespace {
std::optional<InstanceId> context_length_unit(const Graph& g, InstanceId context) {
  const auto& instance = g.at(context);
  const auto* guac = instance.record("GLOBAL_UNIT_ASSIGNED_CONTEXT");
  if (!guac || guac->attributes.empty() || !guac->attributes[0].is_list()) return std::nullopt;
  for (const auto& u : guac->attributes[0].as_list()) {
    const auto* r = u.reference_if();
    if (!r) continue;
    if (Graph::is(g.at(r->id), "LENGTH_UNIT")) return r->id;
  }
  return std::nullopt;
}
}  // namespace

double Graph::context_length_mm(InstanceId context) const {
  const auto unit = context_length_unit(*this, context);
  return unit ? length_unit_mm(*unit) : 1.0;
}

std::string Graph::context_length_name(InstanceId context) const {
  const auto unit = context_length_unit(*this, context);
  if (!unit) return "mm";
  const auto& instance = at(*unit);
  if (const auto* cb = instance.record("CONVERSION_BASED_UNIT"); cb && !cb->attributes.empty() && cb->attributes[0].is_string()) {
    return lower(cb->attributes[0].as_string());
  }
  const double mm = length_unit_mm(*unit);
  if (std::abs(mm - 1) < 1e-12) return "mm";
  if (std::abs(mm - 1000) < 1e-9) return "m";
  if (std::abs(mm - 10) < 1e-12) return "cm";
  return std::to_string(mm) + " mm";
}

void Graph::read_item(InstanceId id, double length_scale, Parameters& out) const {
  const auto& instance = at(id);
  auto name_of = [&](const p21::Record& r) { return text(instance, r, 0); };
  if (const auto* a2 = instance.record("AXIS2_PLACEMENT_3D")) {
    out.placements[name_of(*a2)] = placement(id, length_scale);
    return;
  }
  if (const auto* a1 = instance.record("AXIS1_PLACEMENT")) {
    out.placements[name_of(*a1)] = placement(id, length_scale);
    return;
  }
  if (const auto* d = instance.record("DIRECTION")) {
    out.directions[name_of(*d)] = direction(id);
    return;
  }
  if (const auto* dri = instance.record("DESCRIPTIVE_REPRESENTATION_ITEM")) {
    const std::string n = name_of(*dri);
    out.texts[n] = text(instance, *dri, 1);
    out.listing.emplace_back(n, out.texts[n]);
    return;
  }
  // A measure: complex (..MEASURE_WITH_UNIT(value, unit)..REPRESENTATION_ITEM(name)) or a simple
  // MEASURE_REPRESENTATION_ITEM(name, value, unit).
  const p21::Value* value = nullptr;
  const p21::Value* unit = nullptr;
  std::string name;
  if (instance.complex) {
    const auto* mwu = instance.record("MEASURE_WITH_UNIT");
    const auto* ri = instance.record("REPRESENTATION_ITEM");
    if (!mwu || !ri) return;  // not a parameter (geometry, topology...)
    value = &attribute(instance, *mwu, 0);
    unit = &attribute(instance, *mwu, 1);
    name = name_of(*ri);
  } else if (const auto* mri = instance.record("MEASURE_REPRESENTATION_ITEM")) {
    name = name_of(*mri);
    value = &attribute(instance, *mri, 1);
    unit = &attribute(instance, *mri, 2);
  } else {
    return;
  }
  const double raw = number(instance, *value);
  const auto* typed = value->typed_if();
  const std::string type = typed ? typed->type : "";
  const bool is_length = type.find("LENGTH_MEASURE") != std::string::npos || Graph::is(instance, "LENGTH_MEASURE_WITH_UNIT");
  const bool is_angle = type.find("PLANE_ANGLE_MEASURE") != std::string::npos || Graph::is(instance, "PLANE_ANGLE_MEASURE_WITH_UNIT");
  char buf[64];
  // Plus/minus deviations of a qualified item, in the measure's own unit.
  std::optional<std::pair<double, double>> deviations;
  if (const auto* q = instance.record("QUALIFIED_REPRESENTATION_ITEM"); q && !q->attributes.empty() && q->attributes[0].is_list()) {
    for (const auto& v : q->attributes[0].as_list()) {
      const auto* r = v.reference_if();
      if (!r) continue;
      const auto& qi = at(r->id);
      const auto* su = qi.record("STANDARD_UNCERTAINTY");
      if (!su || su->attributes.size() < 3) continue;
      const std::string which = text(qi, *su, 0);
      const double amount = number(qi, su->attributes[2]);
      if (!deviations) deviations.emplace(0.0, 0.0);
      if (which == "upper limit") deviations->first = amount;
      else if (which == "lower limit") deviations->second = amount;
    }
  }
  if (is_length) {
    const double scale = unit->is_unset() ? length_scale : length_unit_mm(reference(instance, *unit));
    const double mm = raw * scale;
    if (!std::isfinite(mm)) fail(id, "a length that is not finite");
    out.lengths[name] = mm;
    if (deviations) out.tolerances[name] = {deviations->first * scale, deviations->second * scale};
    std::snprintf(buf, sizeof buf, "%.10g mm", mm);
  } else if (is_angle) {
    const double deg = raw * (unit->is_unset() ? 1.0 : angle_unit_degrees(reference(instance, *unit)));
    if (!std::isfinite(deg)) fail(id, "an angle that is not finite");
    out.angles[name] = deg;
    std::snprintf(buf, sizeof buf, "%.10g deg", deg);
  } else {
    if (!std::isfinite(raw)) fail(id, "a measure that is not finite");
    out.counts[name] = raw;
    std::snprintf(buf, sizeof buf, "%.10g", raw);
  }
  out.listing.emplace_back(name, buf);
}

void Graph::read_representation(InstanceId rep_id, Parameters& out) const {
  const auto& rep = at(rep_id);
  const p21::Record* record = nullptr;
  for (const auto& r : rep.records) {
    if (r.entity.find("REPRESENTATION") != std::string::npos && r.attributes.size() >= 3 && r.attributes[1].is_list()) record = &r;
  }
  if (!record) return;
  double scale = 1.0;
  if (const auto* ctx = record->attributes[2].reference_if()) scale = context_length_mm(ctx->id);
  const bool directions = Graph::is(rep, "DIRECTION_SHAPE_REPRESENTATION");
  const std::string rep_name = text(rep, *record, 0);
  for (const auto& item : record->attributes[1].as_list()) {
    const auto* r = item.reference_if();
    if (!r) fail(rep_id, "a representation item is not a reference");
    if (directions && Graph::is(at(r->id), "DIRECTION")) {
      out.directions[rep_name] = direction(r->id);
      continue;
    }
    read_item(r->id, scale, out);
  }
}

Parameters Graph::representation(InstanceId rep) const {
  Parameters out;
  read_representation(rep, out);
  return out;
}

Parameters Graph::parameters(InstanceId id) const {
  Parameters out;
  for (InstanceId pd : users(id)) {
    const auto& pdi = at(pd);
    const auto* pdr = pdi.record("PROPERTY_DEFINITION");
    if (!pdr || pdr->attributes.size() < 3) continue;
    const auto* def = pdr->attributes[2].reference_if();
    if (!def || def->id != id) continue;
    for (InstanceId sdr : users(pd)) {
      const auto& sdri = at(sdr);
      const p21::Record* rec = sdri.record("SHAPE_DEFINITION_REPRESENTATION");
      if (!rec) rec = sdri.record("PROPERTY_DEFINITION_REPRESENTATION");
      if (!rec || rec->attributes.size() < 2) continue;
      const auto* d = rec->attributes[0].reference_if();
      const auto* used = rec->attributes[1].reference_if();
      if (!d || d->id != pd || !used) continue;
      read_representation(used->id, out);
    }
  }
  return out;
}

std::vector<Component> Graph::components(InstanceId feature) const {
  std::vector<Component> out;
  // `direct`: the feature itself relates (a composite hole to its holes, a chamfer to its offsets).
  auto add_relations = [&](InstanceId aspect, const std::string& aspect_description, bool direct) {
    for (InstanceId rel : users(aspect)) {
      const auto& ri = at(rel);
      if (!is_relationship(ri)) continue;
      const auto* r = relationship_record(ri);
      if (!r) continue;
      const auto* relating = r->attributes[2].reference_if();
      const auto* related = r->attributes[3].reference_if();
      if (!relating || !related) continue;
      if (!direct && related->id == aspect && relating->id != aspect) {
        out.push_back({aspect_description, text(ri, *r, 0), text(ri, *r, 1), relating->id});
      } else if (direct && relating->id == aspect && related->id != aspect) {
        out.push_back({"", text(ri, *r, 0), text(ri, *r, 1), related->id});
      }
    }
  };
  for (InstanceId pds : users(feature)) {
    const auto& pi = at(pds);
    const auto* pr = pi.record("PRODUCT_DEFINITION_SHAPE");
    if (!pr || pr->attributes.size() < 3) continue;
    const auto* def = pr->attributes[2].reference_if();
    if (!def || def->id != feature) continue;
    for (InstanceId aspect : users(pds)) {
      const auto& ai = at(aspect);
      if (aspect_of_shape(ai) != pds) continue;
      const auto t = aspect_text(ai);
      add_relations(aspect, t ? t->second : "", false);
    }
  }
  add_relations(feature, "", true);
  return out;
}

}  // namespace ncbridge::part_reader::ap224
