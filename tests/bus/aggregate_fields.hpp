#pragma once
// Test helper: visit the fields of a plain aggregate (the canonical call structs) without naming
// them, so tests cover every field of every call type, including ones added later.
#include <cstddef>
#include <tuple>
#include <utility>

namespace ncbridge::test {

struct AnyField {
  template <class T>
  operator T() const;  // never defined: only used in unevaluated brace-init checks
};

template <class T, std::size_t... I>
constexpr bool brace_initializable(std::index_sequence<I...>) {
  return requires { T{(void(I), AnyField{})...}; };
}

template <class T, std::size_t N = 16>
constexpr std::size_t field_count() {
  if constexpr (N == 0) {
    return 0;
  } else if constexpr (brace_initializable<T>(std::make_index_sequence<N>{})) {
    return N;
  } else {
    return field_count<T, N - 1>();
  }
}

// std::tie of every field of t, in declaration order (up to 13 fields).
template <class T>
auto tie_fields(T& t) {
  constexpr std::size_t n = field_count<T>();
  static_assert(n <= 13, "extend tie_fields");
  if constexpr (n == 0) {
    return std::tie();
  } else if constexpr (n == 1) {
    auto& [a] = t; return std::tie(a);
  } else if constexpr (n == 2) {
    auto& [a, b] = t; return std::tie(a, b);
  } else if constexpr (n == 3) {
    auto& [a, b, c] = t; return std::tie(a, b, c);
  } else if constexpr (n == 4) {
    auto& [a, b, c, d] = t; return std::tie(a, b, c, d);
  } else if constexpr (n == 5) {
    auto& [a, b, c, d, e] = t; return std::tie(a, b, c, d, e);
  } else if constexpr (n == 6) {
    auto& [a, b, c, d, e, f] = t; return std::tie(a, b, c, d, e, f);
  } else if constexpr (n == 7) {
    auto& [a, b, c, d, e, f, g] = t; return std::tie(a, b, c, d, e, f, g);
  } else if constexpr (n == 8) {
    auto& [a, b, c, d, e, f, g, h] = t; return std::tie(a, b, c, d, e, f, g, h);
  } else if constexpr (n == 9) {
    auto& [a, b, c, d, e, f, g, h, i] = t; return std::tie(a, b, c, d, e, f, g, h, i);
  } else if constexpr (n == 10) {
    auto& [a, b, c, d, e, f, g, h, i, j] = t; return std::tie(a, b, c, d, e, f, g, h, i, j);
  } else if constexpr (n == 11) {
    auto& [a, b, c, d, e, f, g, h, i, j, k] = t; return std::tie(a, b, c, d, e, f, g, h, i, j, k);
  } else if constexpr (n == 12) {
    auto& [a, b, c, d, e, f, g, h, i, j, k, l] = t; return std::tie(a, b, c, d, e, f, g, h, i, j, k, l);
  } else {
    auto& [a, b, c, d, e, f, g, h, i, j, k, l, m] = t; return std::tie(a, b, c, d, e, f, g, h, i, j, k, l, m);
  }
}

}  // namespace ncbridge::test
