#include "ncbridge/step_writer/semantic_diff.hpp"

#include <algorithm>
#include <cmath>
#include <cctype>
#include <cstdio>
#include <map>
#include <unordered_map>
#include <unordered_set>

namespace ncbridge::step_writer {

using part21::Graph;
using part21::Instance;
using part21::InstanceId;
using part21::Value;

namespace {

constexpr std::uint64_t kSeed = 1469598103934665603ull;
std::uint64_t mix(std::uint64_t h, std::uint64_t v) {
  h ^= v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
  return h * 1099511628211ull;
}
std::uint64_t hash_text(std::string_view s) {
  std::uint64_t h = kSeed;
  for (char c : s) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  return h;
}

// Which attribute positions of which entity are ignored.
class IgnoreSet {
 public:
  IgnoreSet(const DiffOptions& options) : options_(options) {
    for (const std::string& spec : options.ignore) {
      auto dot = spec.find('.');
      std::string entity = spec.substr(0, dot);
      for (char& c : entity) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      rules_.push_back({entity, dot == std::string::npos ? "" : spec.substr(dot + 1)});
    }
  }
  // attribute `index` (0-based, over all records of the instance) of `entity`
  bool ignored(const std::string& entity, std::size_t index) const {
    for (const auto& [e, attr] : rules_) {
      if (e != "*" && e != entity) continue;
      if (attr.empty() || attr == "*") return true;
      if (std::all_of(attr.begin(), attr.end(), [](char c) { return c >= '0' && c <= '9'; })) {
        if (std::stoul(attr) == index + 1) return true;
        continue;
      }
      if (attribute_name(entity, index) == attr) return true;
    }
    return false;
  }
  std::string attribute_name(const std::string& entity, std::size_t index) const {
    if (options_.schema != nullptr) {
      auto key = entity + "#" + std::to_string(index);
      auto it = names_.find(key);
      if (it != names_.end()) return it->second;
      auto attrs = options_.schema->instance_attributes(entity);
      std::string name = index < attrs.size() && attrs[index].attribute ? attrs[index].attribute->name : "";
      names_[key] = name;
      return name;
    }
    return "";
  }

 private:
  const DiffOptions& options_;
  std::vector<std::pair<std::string, std::string>> rules_;
  mutable std::map<std::string, std::string> names_;
};

// One side: instances, their structural hashes, children-first order.
class Side {
 public:
  Side(const Graph& g, const IgnoreSet& ignore, double tolerance, const std::vector<std::string>& left_out)
      : g_(g), ignore_(ignore), tolerance_(tolerance) {
    for (const Instance& i : g.instances()) {
      for (const auto& r : i.records) {
        if (std::find(left_out.begin(), left_out.end(), r.entity) != left_out.end()) left_out_.insert(i.id);
      }
    }
    if (left_out_.empty()) {
      for (const Instance& i : g.instances()) visit(i.id);
      return;
    }
    // only what is reachable from the roots without passing through a left-out instance
    std::unordered_set<InstanceId> referenced;
    for (const Instance& i : g.instances()) {
      for (const auto& r : i.records) {
        for (const Value& v : r.attributes) collect_references(v, referenced);
      }
    }
    for (const Instance& i : g.instances()) {
      if (!referenced.count(i.id) && !left_out_.count(i.id)) visit(i.id);
    }
  }
  bool left_out(InstanceId id) const { return left_out_.count(id) != 0; }
  bool included(InstanceId id) const { return hashes_.count(id) != 0 && !left_out_.count(id); }
  const Graph& graph() const { return g_; }
  std::uint64_t hash(InstanceId id) const {
    if (left_out_.count(id)) return mix(kSeed, 0x1e770u);
    auto it = hashes_.find(id);
    return it == hashes_.end() ? 0 : it->second;
  }
  const std::vector<InstanceId>& order() const { return order_; }
  std::string entity(const Instance& i) const {
    std::string e;
    for (const auto& r : i.records) e += (e.empty() ? "" : "+") + r.entity;
    return e;
  }

 private:
  std::uint64_t hash_value(const Value& v) {
    std::uint64_t h = mix(kSeed, v.data.index());
    if (auto* n = v.integer_if()) return mix(h, static_cast<std::uint64_t>(*n));
    if (auto* r = v.real_if()) return mix(h, static_cast<std::uint64_t>(std::llround(*r / tolerance_)));
    if (auto* s = v.string_if()) return mix(h, hash_text(*s));
    if (auto* e = v.enumeration_if()) return mix(h, hash_text(e->name));
    if (auto* ref = v.reference_if()) return mix(h, visit(ref->id));
    if (auto* l = v.list_if()) {
      for (const Value& item : l->items) h = mix(h, hash_value(item));
      return mix(h, l->items.size());
    }
    if (auto* t = v.typed_if()) {
      h = mix(h, hash_text(t->type));
      for (const Value& item : t->value) h = mix(h, hash_value(item));
      return h;
    }
    if (auto* b = std::get_if<part21::Binary>(&v.data)) return mix(h, hash_text(b->digits));
    return h;
  }

  static void collect_references(const Value& v, std::unordered_set<InstanceId>& out) {
    if (auto* ref = v.reference_if()) out.insert(ref->id);
    if (auto* l = v.list_if()) {
      for (const Value& item : l->items) collect_references(item, out);
    }
    if (auto* t = v.typed_if()) {
      for (const Value& item : t->value) collect_references(item, out);
    }
  }

  std::uint64_t visit(InstanceId id) {
    if (left_out_.count(id)) return mix(kSeed, 0x1e770u);  // every left-out instance alike
    auto it = hashes_.find(id);
    if (it != hashes_.end()) return it->second;
    const Instance* i = g_.find(id);
    if (i == nullptr) return hashes_[id] = mix(kSeed, 0xdeadull);
    hashes_[id] = mix(kSeed, 0xc1c1eull);  // a reference cycle hashes to a constant
    std::string e = entity(*i);
    std::uint64_t h = hash_text(e);
    std::size_t index = 0;
    for (const auto& r : i->records) {
      for (const Value& v : r.attributes) {
        if (!ignore_.ignored(e, index)) h = mix(h, hash_value(v));
        ++index;
      }
    }
    order_.push_back(id);  // after its children: children first
    return hashes_[id] = h;
  }

  const Graph& g_;
  const IgnoreSet& ignore_;
  double tolerance_;
  std::unordered_map<InstanceId, std::uint64_t> hashes_;
  std::vector<InstanceId> order_;
  std::unordered_set<InstanceId> left_out_;
};

std::string format_real(double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string show(const Value& v, const Graph& g, int depth = 0) {
  if (v.is_unset()) return "$";
  if (v.is_derived()) return "*";
  if (auto* n = v.integer_if()) return std::to_string(*n);
  if (auto* r = v.real_if()) return format_real(*r);
  if (auto* s = v.string_if()) return "'" + *s + "'";
  if (auto* e = v.enumeration_if()) return "." + e->name + ".";
  if (auto* ref = v.reference_if()) {
    const Instance* i = g.find(ref->id);
    return "#" + std::to_string(ref->id) + (i ? " " + i->entity() : "");
  }
  if (auto* l = v.list_if()) {
    std::string out = "(";
    for (std::size_t k = 0; k < l->items.size(); ++k) {
      if (k == 6 || depth > 1) {
        out += "... " + std::to_string(l->items.size()) + " items";
        break;
      }
      out += (k ? ", " : "") + show(l->items[k], g, depth + 1);
    }
    return out + ")";
  }
  if (auto* t = v.typed_if()) return t->type + "(" + (t->value.empty() ? "" : show(t->value.front(), g, depth)) + ")";
  if (auto* b = std::get_if<part21::Binary>(&v.data)) return "\"" + b->digits + "\"";
  return "?";
}

std::vector<const Value*> flat_attributes(const Instance& i) {
  std::vector<const Value*> out;
  for (const auto& r : i.records) {
    for (const Value& v : r.attributes) out.push_back(&v);
  }
  return out;
}

class Differ {
 public:
  Differ(const Side& a, const Side& b, const IgnoreSet& ignore, const DiffOptions& options)
      : a_(a), b_(b), ignore_(ignore), options_(options) {}

  DiffResult run() {
    DiffResult result;
    result.instances_a = a_.graph().size();
    result.instances_b = b_.graph().size();
    // 1. equal content
    std::unordered_multimap<std::uint64_t, InstanceId> by_hash;
    for (InstanceId id : b_.order()) by_hash.emplace(b_.hash(id), id);
    for (InstanceId id : a_.order()) {
      auto [first, last] = by_hash.equal_range(a_.hash(id));
      if (first == last) continue;
      pair(id, first->second, true);
      by_hash.erase(first);
      ++result.matched;
    }
    // 2. the rest, paired within each entity type, children first
    std::map<std::string, std::vector<InstanceId>> unpaired_b;
    for (InstanceId id : b_.order()) {
      if (!b_to_a_.count(id)) unpaired_b[b_.entity(b_.graph().at(id))].push_back(id);
    }
    for (InstanceId id : a_.order()) {
      if (a_to_b_.count(id)) continue;
      const Instance& ia = a_.graph().at(id);
      auto& candidates = unpaired_b[a_.entity(ia)];
      if (candidates.empty()) continue;
      std::size_t best = 0;
      int best_score = -1;
      if (candidates.size() <= 400) {
        for (std::size_t k = 0; k < candidates.size(); ++k) {
          int score = similarity(ia, b_.graph().at(candidates[k]));
          if (score > best_score) {
            best_score = score;
            best = k;
          }
        }
      }
      InstanceId bid = candidates[best];
      candidates.erase(candidates.begin() + static_cast<std::ptrdiff_t>(best));
      std::vector<AttributeDifference> diffs;
      bool through_parts = false;
      compare(ia, b_.graph().at(bid), diffs, through_parts);
      bool same = diffs.empty() && !through_parts;
      pair(id, bid, same);
      if (same) {
        ++result.matched;
      } else if (diffs.empty()) {
        ++result.changed_through_parts;
      } else {
        result.differences.insert(result.differences.end(), diffs.begin(), diffs.end());
      }
    }
    for (const Instance& i : a_.graph().instances()) {
      if (a_.included(i.id) && !a_to_b_.count(i.id)) result.only_a.push_back(unpaired(a_, i));
    }
    for (const Instance& i : b_.graph().instances()) {
      if (b_.included(i.id) && !b_to_a_.count(i.id)) result.only_b.push_back(unpaired(b_, i));
    }
    result.instances_a = count_included(a_);
    result.instances_b = count_included(b_);
    return result;
  }

 private:
  void pair(InstanceId a, InstanceId b, bool equivalent) {
    a_to_b_[a] = b;
    b_to_a_[b] = a;
    if (equivalent) equivalent_.insert({a, b});
  }

  static std::size_t count_included(const Side& side) {
    std::size_t n = 0;
    for (const Instance& i : side.graph().instances()) n += side.included(i.id) ? 1 : 0;
    return n;
  }

  UnpairedInstance unpaired(const Side& side, const Instance& i) const {
    std::string text = side.entity(i) + "(";
    auto attrs = flat_attributes(i);
    for (std::size_t k = 0; k < attrs.size(); ++k) text += (k ? ", " : "") + show(*attrs[k], side.graph(), 1);
    text += ")";
    if (text.size() > 160) text = text.substr(0, 157) + "...";
    return {side.entity(i), i.id, text};
  }

  // Equal attributes: references equal when they lead to equivalent instances.
  bool equal(const Value& x, const Value& y, bool& through_parts) const {
    if (x.data.index() != y.data.index()) {
      // an integer written where the other file writes a real
      if ((x.is_integer() || x.real_if()) && (y.is_integer() || y.real_if())) {
        return std::fabs(x.as_number() - y.as_number()) <= options_.tolerance;
      }
      return false;
    }
    if (auto* r = x.real_if()) return std::fabs(*r - *y.real_if()) <= options_.tolerance;
    if (auto* ra = x.reference_if()) {
      InstanceId rb = y.reference_if()->id;
      if (a_.hash(ra->id) == b_.hash(rb)) return true;  // same content (or both left out)
      auto it = a_to_b_.find(ra->id);
      if (it == a_to_b_.end() || it->second != rb) return false;
      if (!equivalent_.count({ra->id, rb})) through_parts = true;
      return true;
    }
    if (auto* la = x.list_if()) {
      const auto& lb = *y.list_if();
      if (la->items.size() != lb.items.size()) return false;
      for (std::size_t k = 0; k < la->items.size(); ++k) {
        if (!equal(la->items[k], lb.items[k], through_parts)) return false;
      }
      return true;
    }
    if (auto* ta = x.typed_if()) {
      const auto& tb = *y.typed_if();
      return ta->type == tb.type && ta->value.size() == tb.value.size() &&
             (ta->value.empty() || equal(ta->value.front(), tb.value.front(), through_parts));
    }
    return x == y;
  }

  int similarity(const Instance& x, const Instance& y) const {
    auto ax = flat_attributes(x), ay = flat_attributes(y);
    int score = 0;
    bool unused = false;
    for (std::size_t k = 0; k < std::min(ax.size(), ay.size()); ++k) {
      if (equal(*ax[k], *ay[k], unused)) ++score;
    }
    return score;
  }

  void compare(const Instance& x, const Instance& y, std::vector<AttributeDifference>& out, bool& through_parts) const {
    std::string entity = a_.entity(x);
    auto ax = flat_attributes(x), ay = flat_attributes(y);
    std::size_t n = std::max(ax.size(), ay.size());
    for (std::size_t k = 0; k < n; ++k) {
      if (ignore_.ignored(entity, k)) continue;
      if (k < ax.size() && k < ay.size() && equal(*ax[k], *ay[k], through_parts)) continue;
      std::string name = ignore_.attribute_name(entity, k);
      out.push_back({entity, x.id, y.id, name.empty() ? "#" + std::to_string(k + 1) : name,
                     k < ax.size() ? show(*ax[k], a_.graph()) : "(none)", k < ay.size() ? show(*ay[k], b_.graph()) : "(none)"});
    }
  }

  struct PairHash {
    std::size_t operator()(const std::pair<InstanceId, InstanceId>& p) const { return std::hash<InstanceId>{}(p.first * 31 + p.second); }
  };

  const Side& a_;
  const Side& b_;
  const IgnoreSet& ignore_;
  const DiffOptions& options_;
  std::unordered_map<InstanceId, InstanceId> a_to_b_, b_to_a_;
  std::unordered_set<std::pair<InstanceId, InstanceId>, PairHash> equivalent_;
};

}  // namespace

DiffResult semantic_diff(const Graph& a, const Graph& b, const DiffOptions& options) {
  IgnoreSet ignore(options);
  double grid = options.tolerance > 0 ? options.tolerance : 1e-12;
  Side sa(a, ignore, grid, options.ignore_entities), sb(b, ignore, grid, options.ignore_entities);
  return Differ(sa, sb, ignore, options).run();
}

std::string format_diff(const DiffResult& r, const std::string& name_a, const std::string& name_b) {
  std::string out;
  char line[512];
  std::snprintf(line, sizeof line, "A: %s (%zu instances)\nB: %s (%zu instances)\n", name_a.c_str(), r.instances_a,
                name_b.c_str(), r.instances_b);
  out += line;
  std::snprintf(line, sizeof line, "%zu instances match by content; %zu attribute differences; %zu only in A; %zu only in B",
                r.matched, r.differences.size(), r.only_a.size(), r.only_b.size());
  out += line;
  if (r.changed_through_parts) out += "; " + std::to_string(r.changed_through_parts) + " differ only through the instances they refer to";
  out += "\n";
  if (r.identical()) return out + "identical\n";
  std::map<std::string, std::vector<const AttributeDifference*>> by_entity;
  for (const auto& d : r.differences) by_entity[d.entity].push_back(&d);
  for (const auto& [entity, diffs] : by_entity) {
    out += "\n" + entity + "\n";
    std::size_t width = 9;
    for (const auto* d : diffs) width = std::max(width, d->attribute.size());
    std::snprintf(line, sizeof line, "  %-14s %-*s  %-28s  %s\n", "instance A/B", static_cast<int>(width), "attribute", "value A", "value B");
    out += line;
    for (const auto* d : diffs) {
      std::string ids = "#" + std::to_string(d->a) + "/#" + std::to_string(d->b);
      std::snprintf(line, sizeof line, "  %-14s %-*s  %-28s  %s\n", ids.c_str(), static_cast<int>(width), d->attribute.c_str(),
                    d->value_a.c_str(), d->value_b.c_str());
      out += line;
    }
  }
  auto unpaired = [&](const std::vector<UnpairedInstance>& list, const char* which) {
    if (list.empty()) return;
    out += std::string("\nonly in ") + which + "\n";
    std::size_t shown = 0;
    for (const auto& u : list) {
      if (++shown > 50) {
        out += "  ... " + std::to_string(list.size() - 50) + " more\n";
        break;
      }
      out += "  #" + std::to_string(u.id) + " " + u.text + "\n";
    }
  };
  unpaired(r.only_a, "A");
  unpaired(r.only_b, "B");
  return out;
}

}  // namespace ncbridge::step_writer
