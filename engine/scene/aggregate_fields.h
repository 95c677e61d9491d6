// aggregateFieldCount<T>(): how many direct fields the aggregate T has, at compile time.
//
// Code that must visit every field of a scene struct (the scene hash, its test) asserts the
// count it was written for, so that adding a field stops the build there instead of being left
// out silently. It counts the largest N for which T{x1, ..., xN} compiles with each xi
// convertible to anything; a field of aggregate type would be counted by its own fields (brace
// elision), so it holds for structs whose fields are scalars, enums, glm types and std classes.
#pragma once

#include <cstddef>
#include <type_traits>
#include <utility>

namespace bounce {
namespace aggregate_fields_detail {

struct AnyField {
  template <class T>
  operator T() const;  // declared only: used in unevaluated operands
};

template <class T, std::size_t... I>
constexpr bool bracedFrom(std::index_sequence<I...>) {
  return requires {
    T{(void(I), AnyField{})...};
  };
}

template <class T, std::size_t N>
constexpr std::size_t countFrom() {
  if constexpr (bracedFrom<T>(std::make_index_sequence<N + 1>{}))
    return countFrom<T, N + 1>();
  else
    return N;
}

}  // namespace aggregate_fields_detail

template <class T>
requires std::is_aggregate_v<T>
constexpr std::size_t aggregateFieldCount() {
  return aggregate_fields_detail::countFrom<T, 0>();
}

}  // namespace bounce
