#pragma once
// Test helper: canonical calls with a distinct value in every field, and bit-exact comparison.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include "aggregate_fields.hpp"
#include "ncbridge/canonical/call.hpp"

namespace ncbridge::test {

// Fills every field of `t` with a value derived from `seed` and the field's position.
template <class T>
void fill(T& t, std::uint32_t seed) {
  if constexpr (std::is_same_v<T, std::string>) {
    t = "text " + std::to_string(seed) + " (\xff\xfe not UTF-8, \xc3\xbc is)";
  } else if constexpr (std::is_same_v<T, bool>) {
    t = (seed % 2) == 1;
  } else if constexpr (std::is_enum_v<T>) {
    t = static_cast<T>(seed % 2);  // every canonical enum has at least two values
  } else if constexpr (std::is_floating_point_v<T>) {
    t = static_cast<T>(seed) * 1.0625 + 0.1 / static_cast<T>(seed + 3);
  } else if constexpr (std::is_integral_v<T>) {
    t = static_cast<T>(seed * 7 + 3);
  } else if constexpr (requires { t.emplace_back(); }) {  // a vector: one to three elements
    t.resize(seed % 3 + 1);
    std::uint32_t i = 0;
    for (auto& e : t) fill(e, seed * 17 + ++i);
  } else {
    std::uint32_t i = 0;
    std::apply([&](auto&... f) { (fill(f, seed * 31 + ++i), ...); }, tie_fields(t));
  }
}

template <class T>
bool same_bits(const T& a, const T& b) {
  if constexpr (std::is_same_v<T, std::string>) {
    return a == b;
  } else if constexpr (std::is_arithmetic_v<T> || std::is_enum_v<T>) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
  } else if constexpr (requires { a.size(); a[0]; }) {
    if (a.size() != b.size()) return false;
    for (std::size_t k = 0; k < a.size(); ++k) {
      if (!same_bits(a[k], b[k])) return false;
    }
    return true;
  } else {
    auto fa = tie_fields(a);
    auto fb = tie_fields(b);
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
      return (same_bits(std::get<I>(fa), std::get<I>(fb)) && ...);
    }(std::make_index_sequence<std::tuple_size_v<decltype(fa)>>{});
  }
}

inline bool same_call(const canonical::Call& a, const canonical::Call& b) {
  if (a.data.index() != b.data.index()) return false;
  const bool data_same = std::visit(
      [&](const auto& da) { return same_bits(da, std::get<std::decay_t<decltype(da)>>(b.data)); }, a.data);
  if (!data_same || !same_bits(a.source, b.source)) return false;
  if (a.cycle.has_value() != b.cycle.has_value()) return false;
  return !a.cycle || same_bits(*a.cycle, *b.cycle);
}

// Call number `i` of a stream holding every alternative in turn, with every field set.
inline canonical::Call sample_call(std::size_t i) {
  constexpr std::size_t n = std::variant_size_v<canonical::Data>;
  canonical::Call call{canonical::Data{}, {}, std::nullopt};
  const auto seed = static_cast<std::uint32_t>(i);
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    ((i % n == I ? (call.data.emplace<I>(), fill(std::get<I>(call.data), seed + 1), 0) : 0), ...);
  }(std::make_index_sequence<n>{});
  fill(call.source, seed);
  if (i % 3 == 0) call.source.n_number = -1;  // a block without an N word
  if (i % 2 == 1) {
    canonical::CycleTag tag;
    fill(tag, seed);
    call.cycle = tag;
  }
  return call;
}

}  // namespace ncbridge::test
