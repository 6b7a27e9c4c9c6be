#pragma once
// The parts of an EXPRESS schema (ISO 10303-11) the instance check needs: ENTITY declarations
// (explicit attributes in order, SUBTYPE OF with several supertypes, ABSTRACT, OPTIONAL, DERIVE
// and INVERSE attributes, redeclarations through SELF\) and TYPE declarations (defined types,
// SELECT, ENUMERATION, aggregates LIST/SET/BAG/ARRAY with bounds). WHERE/UNIQUE rules, FUNCTIONs
// and RULEs are skipped. Names are kept upper case (EXPRESS is case-insensitive); attribute
// names keep the schema's spelling.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ncbridge::step_writer::express {

struct Type {
  enum class Kind {
    Named,         // an entity or a TYPE: `name`
    Real, Integer, Number, String, Boolean, Logical, Binary,
    Aggregate,     // `aggregate`, bounds, `element`
    Select,        // `items` (only as the underlying type of a TYPE)
    Enumeration,   // `items`, upper case (only as the underlying type of a TYPE)
    Generic,       // GENERIC / anything the checker does not interpret
  };
  enum class Aggregate { List, Set, Bag, Array };

  Kind kind = Kind::Generic;
  std::string name;
  Aggregate aggregate = Aggregate::List;
  std::int64_t lower = 0;
  std::optional<std::int64_t> upper;  // nullopt for `?`
  std::vector<Type> element;          // exactly one for aggregates
  std::vector<std::string> items;

  std::string to_string() const;      // EXPRESS-like, for messages: "LIST [2:?] OF CARTESIAN_POINT"
};

struct Attribute {
  std::string name;       // as declared, e.g. "its_secplane"
  Type type;
  bool optional = false;
};

struct Entity {
  std::string name;                      // upper case
  bool abstract = false;
  std::vector<std::string> supertypes;   // upper case, in declared order
  std::vector<Attribute> attributes;     // own explicit attributes, in order (not redeclarations)
  std::vector<std::string> derived;      // inherited attributes redeclared here as DERIVE (names)
  std::vector<Attribute> redeclared;     // inherited explicit attributes redeclared here (SELF\x.a)
  std::uint32_t line = 0;
};

struct DefinedType {
  std::string name;  // upper case
  Type underlying;
  std::uint32_t line = 0;
};

// One position of an instance's attribute list, with the entity that declared it.
struct InstanceAttribute {
  const Attribute* attribute = nullptr;  // the effective declaration (after redeclaration)
  std::string owner;                     // upper case name of the declaring entity
  bool derived = false;                  // redeclared as DERIVE: the instance writes `*`
};

class Schema {
 public:
  // Throws ncbridge::InputError (file, line, column) on text it cannot parse.
  static Schema parse(std::string_view text, const std::string& file_name);
  static Schema parse_file(const std::filesystem::path& path);

  const std::string& name() const { return name_; }
  const Entity* entity(std::string_view name) const;     // any case
  const DefinedType* type(std::string_view name) const;  // any case
  const std::map<std::string, Entity>& entities() const { return entities_; }
  const std::map<std::string, DefinedType>& types() const { return types_; }

  // The attribute list an instance of `entity` carries: every supertype's explicit attributes
  // first (depth first, in SUBTYPE OF order, each supertype once), then its own. Empty for
  // unknown entities.
  std::vector<InstanceAttribute> instance_attributes(std::string_view entity) const;
  bool is_subtype_of(std::string_view entity, std::string_view supertype) const;  // reflexive

 private:
  std::string name_;
  std::map<std::string, Entity> entities_;
  std::map<std::string, DefinedType> types_;
};

}  // namespace ncbridge::step_writer::express
