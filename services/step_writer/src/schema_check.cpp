#include <map>
#include <set>
#include <string>

#include "ncbridge/step_writer/schema_check.hpp"

namespace ncbridge::step_writer {
namespace {

using express::Type;
using part21::Instance;
using part21::Value;

// Entity names that real ISO 14649 files use but the 2002 draft schema does not declare, with the
// schema entity each stands for ("" when none: checked no further). Evidence in
// docs/formats/part21.md and /work/shared/notes/iso14649.md.
const std::map<std::string, std::string, std::less<>> kKnownVariants = {
    {"BIDIRECTIONAL_MILLING", "BIDIRECTIONAL"},        // NIST ex1.stp; 14649-11 draft vs IS
    {"CENTER_DRILL", "CENTERDRILL"},                   // UFSC / UnB files
    {"TOOL_DIMENSION", "MILLING_TOOL_DIMENSION"},      // UFSC files; 14649-111 draft vs IS
    {"HELIX", ""},                                     // ISO 10303-42 curve outside the subset (ex1E.stp)
};

constexpr int kMaxDepth = 64;

class Checker {
 public:
  Checker(const part21::Graph& graph, const express::Schema& schema, const CheckOptions& options)
      : graph_(graph), schema_(schema), options_(options) {}

  std::vector<Diagnostic> run() {
    for (const auto& instance : graph_.instances()) check_instance(instance);
    return std::move(out_);
  }

 private:
  struct Context {
    const Instance* instance;
    const std::string* entity;
    const std::string* attribute;
  };

  void report(Severity severity, const Context& at, std::string message) {
    Diagnostic d;
    d.severity = severity;
    d.where = SourceLocation{options_.file_name, at.instance->line, at.instance->column};
    d.instance = at.instance->id;
    d.entity = *at.entity;
    if (at.attribute) d.attribute = *at.attribute;
    d.message = std::move(message);
    out_.push_back(std::move(d));
  }

  // The schema entity a record name stands for, or "" when the check cannot follow it.
  std::string schema_name_of(const std::string& entity) const {
    if (schema_.entity(entity)) return entity;
    if (options_.known_variants_are_warnings)
      if (auto it = kKnownVariants.find(entity); it != kKnownVariants.end()) return it->second;
    return {};
  }

  void check_instance(const Instance& instance) {
    if (instance.records.empty()) return;
    bool complex = instance.records.size() > 1 || instance.complex;
    for (const auto& record : instance.records) {
      Context at{&instance, &record.entity, nullptr};
      std::string name = record.entity;
      if (!schema_.entity(name)) {
        auto variant = options_.known_variants_are_warnings ? kKnownVariants.find(name) : kKnownVariants.end();
        if (variant == kKnownVariants.end()) {
          report(Severity::Error, at, "entity " + name + " is not in schema " + schema_.name());
          continue;
        }
        if (variant->second.empty()) {
          report(Severity::Warning, at, "entity " + name + " is not in schema " + schema_.name() +
                                            " (a known entity of another STEP part); not checked");
          continue;
        }
        report(Severity::Warning, at, "entity " + name + " is not in schema " + schema_.name() +
                                          "; checked as " + variant->second + ", its name there");
        name = variant->second;
      }
      const express::Entity& entity = *schema_.entity(name);
      if (complex) {
        // A partial record carries its entity's own attributes; one that another partial entity
        // of the instance redeclares as DERIVE (SI_UNIT's NAMED_UNIT.dimensions) is written *.
        std::vector<express::InstanceAttribute> own;
        for (const auto& a : entity.attributes) own.push_back({&a, entity.name, redeclared_derived(instance, name, a.name)});
        check_attributes(at, record.attributes, own, name);
      } else {
        if (entity.abstract) report(Severity::Error, at, "entity " + name + " is ABSTRACT and cannot be instantiated");
        check_attributes(at, record.attributes, schema_.instance_attributes(name), name);
      }
    }
  }

  bool redeclared_derived(const Instance& instance, const std::string& owner, const std::string& attribute) const {
    for (const auto& other : instance.records) {
      std::string n = schema_name_of(other.entity);
      const express::Entity* e = n.empty() ? nullptr : schema_.entity(n);
      if (!e || n == owner || !schema_.is_subtype_of(n, owner)) continue;
      for (const auto& d : e->derived)
        if (upper(d) == upper(attribute)) return true;
    }
    return false;
  }

  void check_attributes(Context at, const std::vector<Value>& values,
                        const std::vector<express::InstanceAttribute>& expected, const std::string& name) {
    if (values.size() != expected.size()) {
      std::string names;
      for (const auto& e : expected) names += (names.empty() ? "" : ", ") + e.attribute->name;
      report(Severity::Error, at,
             "has " + std::to_string(values.size()) + " attributes, " + name + " has " +
                 std::to_string(expected.size()) + " (" + names + ")");
      return;  // the values no longer line up with the attributes: checking them would mislead
    }
    std::size_t n = std::min(values.size(), expected.size());
    for (std::size_t k = 0; k < n; ++k) {
      const auto& ia = expected[k];
      at.attribute = &ia.attribute->name;
      const Value& v = values[k];
      if (ia.derived) {
        if (!v.is_derived()) report(Severity::Error, at, "is derived in " + name + " and must be written *");
        continue;
      }
      if (v.is_derived()) {
        report(Severity::Error, at, "* is only allowed for derived attributes");
        continue;
      }
      if (v.is_unset()) {
        if (!ia.attribute->optional)
          report(Severity::Error, at, "is not OPTIONAL but is $" +
                                          std::string(ia.attribute->type.kind == Type::Kind::Aggregate
                                                          ? " (an empty aggregate is written ())"
                                                          : ""));
        continue;
      }
      std::string problem = check_value(v, ia.attribute->type, 0);
      if (!problem.empty()) report(Severity::Error, at, problem);
    }
  }

  // "" when v fits type, else what is wrong.
  std::string check_value(const Value& v, const Type& type, int depth) {
    if (depth > kMaxDepth) return {};
    switch (type.kind) {
      case Type::Kind::Generic: return {};
      case Type::Kind::Named: return check_named(v, type.name, depth);
      case Type::Kind::Select: return check_select(v, type.items, depth);
      case Type::Kind::Enumeration: {
        const auto* e = v.enumeration_if();
        if (!e) return "expected an enumeration value, found " + kind_of(v);
        for (const auto& item : type.items)
          if (item == e->name) return {};
        std::string allowed;
        for (const auto& item : type.items) allowed += (allowed.empty() ? "." : ", .") + item + ".";
        return "." + e->name + ". is not one of " + allowed;
      }
      case Type::Kind::Boolean:
      case Type::Kind::Logical: {
        const auto* e = v.enumeration_if();
        bool ok = e && (e->name == "T" || e->name == "F" || (type.kind == Type::Kind::Logical && e->name == "U"));
        return ok ? std::string() : "expected " + type.to_string() + " (.T./.F." +
                                        (type.kind == Type::Kind::Logical ? "/.U." : "") + "), found " + kind_of(v);
      }
      case Type::Kind::Real:
      case Type::Kind::Number:
        return v.is_number() ? std::string() : "expected a real, found " + kind_of(v);
      case Type::Kind::Integer:
        return v.is_integer() ? std::string() : "expected an integer, found " + kind_of(v);
      case Type::Kind::String:
        return v.is_string() ? std::string() : "expected a string, found " + kind_of(v);
      case Type::Kind::Binary:
        return std::holds_alternative<part21::Binary>(v.data) ? std::string() : "expected a binary, found " + kind_of(v);
      case Type::Kind::Aggregate: {
        const auto* l = v.list_if();
        if (!l) return "expected " + type.to_string() + ", found " + kind_of(v);
        auto size = static_cast<std::int64_t>(l->items.size());
        if (size < type.lower || (type.upper && size > *type.upper))
          return "has " + std::to_string(size) + " elements, " + type.to_string() + " allows " +
                 std::to_string(type.lower) + " to " + (type.upper ? std::to_string(*type.upper) : "any number");
        for (std::size_t k = 0; k < l->items.size(); ++k) {
          const Value& item = l->items[k];
          std::string problem = item.is_unset() ? "$ is not allowed here"
                                                : check_value(item, type.element.front(), depth + 1);
          if (!problem.empty()) return "element " + std::to_string(k + 1) + ": " + problem;
        }
        return {};
      }
    }
    return {};
  }

  std::string check_named(const Value& v, const std::string& name, int depth) {
    if (const express::DefinedType* t = schema_.type(name)) {
      if (const auto* typed = v.typed_if()) {
        // A typed value where a defined type is expected: the same type, or one built on it.
        if (typed->type == name && typed->value.size() == 1)
          return check_value(typed->value.front(), t->underlying, depth + 1);
        if (t->underlying.kind != Type::Kind::Select && !(t->underlying.kind == Type::Kind::Named && schema_.type(t->underlying.name)))
          return "typed value " + typed->type + "(...) where " + name + " is expected";
      }
      return check_value(v, t->underlying, depth + 1);
    }
    if (schema_.entity(name)) {
      const auto* r = v.reference_if();
      if (!r) return "expected a reference to " + name + ", found " + kind_of(v);
      const Instance* target = graph_.find(r->id);
      if (!target) return {};  // the reader rejects dangling references
      bool followable = false;
      for (const auto& record : target->records) {
        std::string n = schema_name_of(record.entity);
        if (n.empty()) continue;
        followable = true;
        if (schema_.is_subtype_of(n, name)) return {};
      }
      if (!followable) return {};  // an entity the schema does not know: reported on its own
      return "#" + std::to_string(r->id) + " is " + describe(*target) + ", not " + name + " (or a subtype)";
    }
    return {};  // undeclared type name in the schema itself: nothing to check against
  }

  // Collects the entity and defined-type names a SELECT admits, through nested SELECTs.
  void select_members(const std::vector<std::string>& items, std::set<std::string>& entities,
                      std::set<std::string>& types, int depth) {
    if (depth > kMaxDepth) return;
    for (const auto& raw : items) {
      std::string item = upper(raw);
      if (schema_.entity(item)) {
        entities.insert(item);
      } else if (const express::DefinedType* t = schema_.type(item)) {
        if (t->underlying.kind == Type::Kind::Select) select_members(t->underlying.items, entities, types, depth + 1);
        else types.insert(item);
      }
    }
  }

  std::string check_select(const Value& v, const std::vector<std::string>& items, int depth) {
    std::set<std::string> entities, types;
    select_members(items, entities, types, depth);
    if (const auto* r = v.reference_if()) {
      const Instance* target = graph_.find(r->id);
      if (!target) return {};
      bool followable = false;
      for (const auto& record : target->records) {
        std::string n = schema_name_of(record.entity);
        if (n.empty()) continue;
        followable = true;
        for (const auto& e : entities)
          if (schema_.is_subtype_of(n, e)) return {};
      }
      if (!followable) return {};
      return "#" + std::to_string(r->id) + " is " + describe(*target) + ", not one of the SELECT's entities";
    }
    if (const auto* typed = v.typed_if()) {
      if (!types.count(typed->type)) return "typed value " + typed->type + "(...) is not one of the SELECT's types";
      if (typed->value.size() != 1) return "typed value " + typed->type + " must hold exactly one value";
      return check_value(typed->value.front(), schema_.type(typed->type)->underlying, depth + 1);
    }
    // An untyped value: Part 21 wants it typed, but accept it when some member type fits it.
    for (const auto& t : types)
      if (check_value(v, schema_.type(t)->underlying, depth + 1).empty()) return {};
    std::string problem = kind_of(v);
    problem += " fits none of the SELECT's types";
    return problem;
  }

  std::string describe(const Instance& instance) const {
    std::string s = "a";
    for (const auto& r : instance.records) s += (s.size() == 1 ? " " : "+") + r.entity;
    return s;
  }

  static std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
  }

  static std::string kind_of(const Value& v) {
    struct Visitor {
      std::string operator()(const part21::Unset&) const { return "$"; }
      std::string operator()(const part21::Derived&) const { return "*"; }
      std::string operator()(std::int64_t) const { return "an integer"; }
      std::string operator()(double) const { return "a real"; }
      std::string operator()(const std::string&) const { return "a string"; }
      std::string operator()(const part21::Enumeration& e) const { return "." + e.name + "."; }
      std::string operator()(const part21::Binary&) const { return "a binary"; }
      std::string operator()(const part21::Reference& r) const { return "#" + std::to_string(r.id); }
      std::string operator()(const part21::List&) const { return "a list"; }
      std::string operator()(const part21::TypedParameter& t) const { return t.type + "(...)"; }
    };
    return std::visit(Visitor{}, v.data);
  }

  const part21::Graph& graph_;
  const express::Schema& schema_;
  const CheckOptions& options_;
  std::vector<Diagnostic> out_;
};

}  // namespace

std::vector<Diagnostic> check_instances(const part21::Graph& graph, const express::Schema& schema,
                                        const CheckOptions& options) {
  return Checker(graph, schema, options).run();
}

}  // namespace ncbridge::step_writer
