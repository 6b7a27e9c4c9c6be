#include <cctype>
#include <stdexcept>

#include "ncbridge/step_writer/part21_value.hpp"

namespace ncbridge::step_writer::part21 {
namespace {

const Value& unwrap_typed(const Value& value) {
  const Value* v = &value;
  while (const auto* t = v->typed_if()) {
    if (t->value.size() != 1) break;
    v = &t->value.front();
  }
  return *v;
}

[[noreturn]] void wrong_kind(const char* wanted) {
  throw std::logic_error(std::string("Part 21 value is not ") + wanted);
}

}  // namespace

double Value::as_number() const {
  const Value& v = unwrap_typed(*this);
  if (const auto* r = v.real_if()) return *r;
  if (const auto* i = v.integer_if()) return static_cast<double>(*i);
  wrong_kind("a number");
}

std::int64_t Value::as_integer() const {
  const Value& v = unwrap_typed(*this);
  if (const auto* i = v.integer_if()) return *i;
  wrong_kind("an integer");
}

const std::string& Value::as_string() const {
  const Value& v = unwrap_typed(*this);
  if (const auto* s = v.string_if()) return *s;
  wrong_kind("a string");
}

const std::string& Value::as_enumeration() const {
  const Value& v = unwrap_typed(*this);
  if (const auto* e = v.enumeration_if()) return e->name;
  wrong_kind("an enumeration");
}

InstanceId Value::as_reference() const {
  if (const auto* r = reference_if()) return r->id;
  wrong_kind("a reference");
}

const std::vector<Value>& Value::as_list() const {
  if (const auto* l = list_if()) return l->items;
  wrong_kind("a list");
}

Value enumeration(std::string_view name) {
  std::string upper(name);
  for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return Value{Enumeration{std::move(upper)}};
}

Value list_of_reals(const std::vector<double>& values) {
  List l;
  l.items.reserve(values.size());
  for (double v : values) l.items.push_back(real(v));
  return Value{std::move(l)};
}

Value list_of_refs(const std::vector<InstanceId>& ids) {
  List l;
  l.items.reserve(ids.size());
  for (InstanceId id : ids) l.items.push_back(ref(id));
  return Value{std::move(l)};
}

Value typed(std::string_view type, Value value) {
  std::string upper(type);
  for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  TypedParameter t{std::move(upper), {}};
  t.value.push_back(std::move(value));
  return Value{std::move(t)};
}

}  // namespace ncbridge::step_writer::part21
