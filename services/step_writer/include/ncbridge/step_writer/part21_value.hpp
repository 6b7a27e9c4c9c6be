#pragma once
// One attribute value of an ISO 10303-21 (Part 21) entity instance, as a value type.
//
//   $            Unset            *          Derived (redeclared as DERIVE in a subtype)
//   12 / -3      std::int64_t     5. 1.E-05  double
//   'text'       std::string      (decoded: '' -> ', \\ -> \, \X2\..\X0\ -> UTF-8)
//   .TCP.        Enumeration      (also .T. / .F. / .U. for BOOLEAN and LOGICAL)
//   "0F"         Binary           #12        Reference
//   (a, b, ...)  List             LENGTH_MEASURE(5.)  TypedParameter
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace ncbridge::step_writer::part21 {

using InstanceId = std::uint64_t;  // the n of #n; 0 is never a valid id

struct Value;

struct Unset {
  friend bool operator==(const Unset&, const Unset&) = default;
};
struct Derived {
  friend bool operator==(const Derived&, const Derived&) = default;
};
struct Enumeration {
  std::string name;  // upper case, without the dots: "TCP", "T"
  friend bool operator==(const Enumeration&, const Enumeration&) = default;
};
struct Binary {
  std::string digits;  // as written between the quotes: a leading 0..3 then hex digits
  friend bool operator==(const Binary&, const Binary&) = default;
};
struct Reference {
  InstanceId id = 0;
  friend bool operator==(const Reference&, const Reference&) = default;
};
struct List {
  std::vector<Value> items;
  friend bool operator==(const List&, const List&);
};
struct TypedParameter {
  std::string type;          // upper case defined-type name, e.g. "LENGTH_MEASURE"
  std::vector<Value> value;  // exactly one element (a vector only because Value is incomplete here)
  friend bool operator==(const TypedParameter&, const TypedParameter&);
};

struct Value {
  using Data = std::variant<Unset, Derived, std::int64_t, double, std::string, Enumeration, Binary,
                            Reference, List, TypedParameter>;
  Data data;

  bool is_unset() const { return std::holds_alternative<Unset>(data); }
  bool is_derived() const { return std::holds_alternative<Derived>(data); }
  bool is_integer() const { return std::holds_alternative<std::int64_t>(data); }
  bool is_real() const { return std::holds_alternative<double>(data); }
  bool is_number() const { return is_integer() || is_real(); }
  bool is_string() const { return std::holds_alternative<std::string>(data); }
  bool is_enumeration() const { return std::holds_alternative<Enumeration>(data); }
  bool is_reference() const { return std::holds_alternative<Reference>(data); }
  bool is_list() const { return std::holds_alternative<List>(data); }
  bool is_typed() const { return std::holds_alternative<TypedParameter>(data); }

  // Accessors return nullptr when the value holds something else.
  const std::int64_t* integer_if() const { return std::get_if<std::int64_t>(&data); }
  const double* real_if() const { return std::get_if<double>(&data); }
  const std::string* string_if() const { return std::get_if<std::string>(&data); }
  const Enumeration* enumeration_if() const { return std::get_if<Enumeration>(&data); }
  const Reference* reference_if() const { return std::get_if<Reference>(&data); }
  const List* list_if() const { return std::get_if<List>(&data); }
  const TypedParameter* typed_if() const { return std::get_if<TypedParameter>(&data); }

  // Convenience for readers of known shapes; throw std::logic_error on another kind.
  double as_number() const;              // integer or real (and a typed parameter around one)
  std::int64_t as_integer() const;
  const std::string& as_string() const;
  const std::string& as_enumeration() const;  // the name without dots
  InstanceId as_reference() const;
  const std::vector<Value>& as_list() const;

  friend bool operator==(const Value&, const Value&) = default;
};

inline bool operator==(const List& a, const List& b) { return a.items == b.items; }
inline bool operator==(const TypedParameter& a, const TypedParameter& b) {
  return a.type == b.type && a.value == b.value;
}

// ---- Builders, for writing code that reads like the file: add("CARTESIAN_POINT", {string(""), list({real(0), real(0), real(0)})})
inline Value unset() { return Value{Unset{}}; }
inline Value derived() { return Value{Derived{}}; }
inline Value integer(std::int64_t v) { return Value{v}; }
inline Value real(double v) { return Value{v}; }
inline Value string(std::string v) { return Value{std::move(v)}; }
Value enumeration(std::string_view name);  // upper-cased; dots are not part of the name
inline Value boolean(bool v) { return Value{Enumeration{v ? "T" : "F"}}; }
inline Value ref(InstanceId id) { return Value{Reference{id}}; }
inline Value list(std::vector<Value> items) { return Value{List{std::move(items)}}; }
Value list_of_reals(const std::vector<double>& values);
Value list_of_refs(const std::vector<InstanceId>& ids);
Value typed(std::string_view type, Value value);  // e.g. typed("LENGTH_MEASURE", real(5))
// An optional attribute: the value when present, else $.
template <class T, class Make>
Value optional(const T* present, Make make) { return present ? make(*present) : unset(); }

}  // namespace ncbridge::step_writer::part21
