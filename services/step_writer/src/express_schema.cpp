#include <cctype>
#include <charconv>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

#include "express_lexer.hpp"
#include "ncbridge/step_writer/express_schema.hpp"

namespace ncbridge::step_writer::express {
namespace {

std::string upper(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

// Declarations the check does not need, each skipped up to its END_ keyword (which may nest).
const std::set<std::string, std::less<>> kSkippedBlocks = {"FUNCTION", "PROCEDURE", "RULE", "CONSTANT",
                                                           "SUBTYPE_CONSTRAINT"};

class Parser {
 public:
  Parser(std::string_view text, const std::string& file) : lexer_(text, file) { advance(); }

  void parse(std::string& schema_name, std::map<std::string, Entity>& entities,
             std::map<std::string, DefinedType>& types) {
    while (current_.kind != TokenKind::End) {
      if (current_.kind != TokenKind::Identifier) {
        skip_statement();
        continue;
      }
      std::string keyword = upper(current_.text);
      if (keyword == "SCHEMA") {
        advance();
        if (current_.kind == TokenKind::Identifier && schema_name.empty()) schema_name = upper(current_.text);
        skip_statement();
      } else if (keyword == "ENTITY") {
        Entity e = parse_entity();
        if (!entities.emplace(e.name, e).second) lexer_.fail(current_, "entity " + e.name + " is declared twice");
      } else if (keyword == "TYPE") {
        DefinedType t = parse_type_declaration();
        if (!types.emplace(t.name, t).second) lexer_.fail(current_, "type " + t.name + " is declared twice");
      } else if (kSkippedBlocks.count(keyword)) {
        skip_block(keyword);
      } else {
        skip_statement();  // SCHEMA/END_SCHEMA, USE FROM, REFERENCE FROM
      }
    }
  }

 private:
  void advance() { current_ = lexer_.next(); }
  bool at_symbol(std::string_view s) const { return current_.kind == TokenKind::Symbol && current_.text == s; }
  bool at_keyword(std::string_view k) const {
    return current_.kind == TokenKind::Identifier && upper(current_.text) == k;
  }
  void expect_symbol(std::string_view s, const std::string& context) {
    if (!at_symbol(s)) lexer_.fail(current_, "expected '" + std::string(s) + "' " + context + ", found '" + std::string(current_.text) + "'");
    advance();
  }
  std::string expect_identifier(const std::string& context) {
    if (current_.kind != TokenKind::Identifier)
      lexer_.fail(current_, "expected a name " + context + ", found '" + std::string(current_.text) + "'");
    std::string name(current_.text);
    advance();
    return name;
  }
  void fail_end() {
    if (current_.kind == TokenKind::End) lexer_.fail(current_, "unexpected end of the schema");
  }

  // Skips to the ';' that ends the current statement, over balanced brackets.
  void skip_statement() {
    int depth = 0;
    while (current_.kind != TokenKind::End) {
      if (at_symbol("(") || at_symbol("[")) ++depth;
      if (at_symbol(")") || at_symbol("]")) --depth;
      if (depth <= 0 && at_symbol(";")) {
        advance();
        return;
      }
      advance();
    }
  }

  void skip_block(const std::string& keyword) {
    std::string end = "END_" + keyword;
    int depth = 0;
    while (current_.kind != TokenKind::End) {
      if (at_keyword(keyword)) ++depth;
      if (at_keyword(end) && --depth == 0) {
        advance();
        if (at_symbol(";")) advance();
        return;
      }
      advance();
    }
    lexer_.fail(current_, keyword + " has no " + end);
  }

  std::int64_t bound() {
    if (at_symbol("?")) {
      advance();
      return -1;
    }
    std::int64_t value = -2;  // an expression: not interpreted
    if (current_.kind == TokenKind::Number) {
      auto [ptr, ec] = std::from_chars(current_.text.data(), current_.text.data() + current_.text.size(), value);
      if (ec != std::errc() || ptr != current_.text.data() + current_.text.size()) value = -2;
      advance();
    }
    while (!at_symbol(":") && !at_symbol("]")) {  // the rest of an expression bound
      fail_end();
      value = -2;
      advance();
    }
    return value;
  }

  Type parse_type() {
    Type type;
    std::string keyword = current_.kind == TokenKind::Identifier ? upper(current_.text) : std::string();
    if (keyword == "LIST" || keyword == "SET" || keyword == "BAG" || keyword == "ARRAY") {
      type.kind = Type::Kind::Aggregate;
      type.aggregate = keyword == "LIST"  ? Type::Aggregate::List
                       : keyword == "SET" ? Type::Aggregate::Set
                       : keyword == "BAG" ? Type::Aggregate::Bag
                                          : Type::Aggregate::Array;
      advance();
      type.lower = 0;
      if (at_symbol("[")) {
        advance();
        std::int64_t lo = bound();
        expect_symbol(":", "in aggregate bounds");
        std::int64_t hi = bound();
        expect_symbol("]", "closing aggregate bounds");
        type.lower = lo >= 0 ? lo : 0;
        if (hi >= 0) type.upper = hi;
      }
      if (!at_keyword("OF")) lexer_.fail(current_, "expected OF after " + keyword);
      advance();
      while (at_keyword("OPTIONAL") || at_keyword("UNIQUE")) advance();
      type.element.push_back(parse_type());
      return type;
    }
    if (keyword == "SELECT" || keyword == "EXTENSIBLE" || keyword == "GENERIC_ENTITY") {
      while (!at_keyword("SELECT")) {
        fail_end();
        advance();
      }
      advance();
      type.kind = Type::Kind::Select;
      if (at_symbol("(")) type.items = name_list();
      return type;
    }
    if (keyword == "ENUMERATION") {
      advance();
      if (!at_keyword("OF")) lexer_.fail(current_, "expected OF after ENUMERATION");
      advance();
      type.kind = Type::Kind::Enumeration;
      type.items = name_list();
      for (auto& item : type.items) item = upper(item);
      return type;
    }
    static const std::map<std::string, Type::Kind, std::less<>> simple = {
        {"REAL", Type::Kind::Real},       {"INTEGER", Type::Kind::Integer}, {"NUMBER", Type::Kind::Number},
        {"STRING", Type::Kind::String},   {"BOOLEAN", Type::Kind::Boolean}, {"LOGICAL", Type::Kind::Logical},
        {"BINARY", Type::Kind::Binary},   {"GENERIC", Type::Kind::Generic}};
    if (auto it = simple.find(keyword); it != simple.end()) {
      type.kind = it->second;
      advance();
      if (at_symbol("(")) skip_parenthesised();  // width / precision
      if (at_keyword("FIXED")) advance();
      if (type.kind == Type::Kind::Generic && at_symbol(":")) {
        advance();
        advance();
      }
      return type;
    }
    type.kind = Type::Kind::Named;
    type.name = upper(expect_identifier("for a type"));
    return type;
  }

  void skip_parenthesised() {
    int depth = 0;
    do {
      fail_end();
      if (at_symbol("(")) ++depth;
      if (at_symbol(")")) --depth;
      advance();
    } while (depth > 0);
  }

  std::vector<std::string> name_list() {
    std::vector<std::string> names;
    expect_symbol("(", "before a list of names");
    while (!at_symbol(")")) {
      names.push_back(expect_identifier("in a list of names"));
      if (at_symbol(",")) advance();
      else if (!at_symbol(")")) lexer_.fail(current_, "expected ',' or ')' in a list of names");
    }
    advance();
    return names;
  }

  DefinedType parse_type_declaration() {
    advance();  // TYPE
    DefinedType t;
    t.line = current_.line;
    t.name = upper(expect_identifier("after TYPE"));
    expect_symbol("=", "after TYPE " + t.name);
    t.underlying = parse_type();
    if (at_symbol(";")) advance();
    while (!at_keyword("END_TYPE")) {  // WHERE rules
      fail_end();
      advance();
    }
    advance();
    if (at_symbol(";")) advance();
    return t;
  }

  // SELF\supertype.attribute -> attribute name; a plain name -> itself. `redeclared` tells which.
  std::string attribute_name(bool& redeclared) {
    redeclared = false;
    if (at_keyword("SELF")) {
      advance();
      expect_symbol("\\", "after SELF");
      expect_identifier("after SELF\\");
      expect_symbol(".", "in SELF\\entity.attribute");
      redeclared = true;
    }
    std::string name = expect_identifier("of an attribute");
    if (at_keyword("RENAMED")) {
      advance();
      expect_identifier("after RENAMED");
    }
    return name;
  }

  Entity parse_entity() {
    advance();  // ENTITY
    Entity e;
    e.line = current_.line;
    e.name = upper(expect_identifier("after ENTITY"));
    // Supertype/subtype clauses, up to the ';' that ends the entity head.
    while (!at_symbol(";")) {
      fail_end();
      if (at_keyword("ABSTRACT")) {
        e.abstract = true;
        advance();
      } else if (at_keyword("SUPERTYPE")) {
        advance();
        if (at_keyword("OF")) {
          advance();
          skip_parenthesised();
        }
      } else if (at_keyword("SUBTYPE")) {
        advance();
        if (!at_keyword("OF")) lexer_.fail(current_, "expected OF after SUBTYPE");
        advance();
        for (auto& s : name_list()) e.supertypes.push_back(upper(s));
      } else {
        lexer_.fail(current_, "unexpected '" + std::string(current_.text) + "' in the head of ENTITY " + e.name);
      }
    }
    advance();

    enum class Section { Explicit, Derive, Inverse, Skip } section = Section::Explicit;
    while (!at_keyword("END_ENTITY")) {
      fail_end();
      if (at_keyword("DERIVE")) { section = Section::Derive; advance(); continue; }
      if (at_keyword("INVERSE")) { section = Section::Inverse; advance(); continue; }
      if (at_keyword("UNIQUE") || at_keyword("WHERE")) { section = Section::Skip; advance(); continue; }
      if (section == Section::Skip || section == Section::Inverse) {
        skip_statement();
        continue;
      }
      // One declaration: name {, name} : [OPTIONAL] type [:= expression] ;
      std::vector<std::pair<std::string, bool>> names;
      for (;;) {
        bool redeclared = false;
        std::string name = attribute_name(redeclared);
        names.emplace_back(name, redeclared);
        if (!at_symbol(",")) break;
        advance();
      }
      expect_symbol(":", "after attribute " + names.front().first + " of " + e.name);
      if (section == Section::Derive) {
        for (auto& [name, redeclared] : names)
          if (redeclared) e.derived.push_back(name);
        skip_statement();
        continue;
      }
      bool optional = false;
      if (at_keyword("OPTIONAL")) {
        optional = true;
        advance();
      }
      Type type = parse_type();
      expect_symbol(";", "after attribute " + names.front().first + " of " + e.name);
      for (auto& [name, redeclared] : names) {
        Attribute a{name, type, optional};
        (redeclared ? e.redeclared : e.attributes).push_back(std::move(a));
      }
    }
    advance();
    if (at_symbol(";")) advance();
    return e;
  }

  Lexer lexer_;
  Token current_;
};

}  // namespace

std::string Type::to_string() const {
  switch (kind) {
    case Kind::Named: return name;
    case Kind::Real: return "REAL";
    case Kind::Integer: return "INTEGER";
    case Kind::Number: return "NUMBER";
    case Kind::String: return "STRING";
    case Kind::Boolean: return "BOOLEAN";
    case Kind::Logical: return "LOGICAL";
    case Kind::Binary: return "BINARY";
    case Kind::Generic: return "GENERIC";
    case Kind::Select: return "SELECT";
    case Kind::Enumeration: return "ENUMERATION";
    case Kind::Aggregate: {
      static const char* names[] = {"LIST", "SET", "BAG", "ARRAY"};
      std::string s = names[static_cast<int>(aggregate)];
      s += " [" + std::to_string(lower) + ':' + (upper ? std::to_string(*upper) : std::string("?")) + "] OF ";
      s += element.empty() ? std::string("?") : element.front().to_string();
      return s;
    }
  }
  return "?";
}

Schema Schema::parse(std::string_view text, const std::string& file_name) {
  Schema schema;
  Parser parser(text, file_name);
  parser.parse(schema.name_, schema.entities_, schema.types_);
  return schema;
}

Schema Schema::parse_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(SourceLocation{path.string(), 0, 0}, "cannot open the EXPRESS schema");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return parse(buffer.str(), path.string());
}

const Entity* Schema::entity(std::string_view name) const {
  auto it = entities_.find(upper(name));
  return it == entities_.end() ? nullptr : &it->second;
}

const DefinedType* Schema::type(std::string_view name) const {
  auto it = types_.find(upper(name));
  return it == types_.end() ? nullptr : &it->second;
}

std::vector<InstanceAttribute> Schema::instance_attributes(std::string_view name) const {
  std::vector<InstanceAttribute> out;
  const Entity* leaf = entity(name);
  if (!leaf) return out;
  // Supertypes first, depth first in SUBTYPE OF order, each once; then the entity itself.
  std::vector<const Entity*> order;
  std::set<std::string> seen;
  std::function<void(const Entity&)> visit = [&](const Entity& e) {
    if (!seen.insert(e.name).second) return;
    for (const auto& s : e.supertypes)
      if (const Entity* super = entity(s)) visit(*super);
    order.push_back(&e);
  };
  visit(*leaf);
  for (const Entity* e : order)
    for (const auto& a : e->attributes) out.push_back({&a, e->name, false});
  // Redeclarations in subtypes (the order runs from the roots to the leaf: later ones win).
  for (const Entity* e : order) {
    for (const auto& r : e->redeclared)
      for (auto& ia : out)
        if (upper(ia.attribute->name) == upper(r.name) && e->name != ia.owner && is_subtype_of(e->name, ia.owner)) ia.attribute = &r;
    for (const auto& d : e->derived)
      for (auto& ia : out)
        if (upper(ia.attribute->name) == upper(d) && e->name != ia.owner && is_subtype_of(e->name, ia.owner)) ia.derived = true;
  }
  return out;
}

bool Schema::is_subtype_of(std::string_view name, std::string_view supertype) const {
  std::string sub = upper(name), super = upper(supertype);
  std::vector<std::string> pending{sub};
  std::set<std::string> seen;
  while (!pending.empty()) {
    std::string current = std::move(pending.back());
    pending.pop_back();
    if (current == super) return true;
    if (!seen.insert(current).second) continue;
    if (const Entity* e = entity(current))
      for (const auto& s : e->supertypes) pending.push_back(s);
  }
  return false;
}

}  // namespace ncbridge::step_writer::express
