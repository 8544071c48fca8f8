// Compile-time checks that a HAL has what the core calls, without the hosted <type_traits>:
// HALOPLOT_HAL_MEMBER(Name, expression-using-H) defines Name<H>::value, true when the
// expression compiles for the HAL type H. Each interface header uses it to name its members,
// and its check_*() function static_asserts each one with a message that names the member
// and where it is specified, so a HAL that lacks one fails to build with that sentence
// instead of a page of template errors.
#pragma once

namespace haloplot::hal::detail {

template <typename...>
using void_t = void;
template <typename T>
T& object();  // never defined: for unevaluated expressions only
template <bool V>
struct constant {
  static constexpr bool value = V;
};

}  // namespace haloplot::hal::detail

#define HALOPLOT_HAL_MEMBER(Name, ...)                                   \
  template <typename H, typename = void>                                 \
  struct Name : ::haloplot::hal::detail::constant<false> {};             \
  template <typename H>                                                  \
  struct Name<H, ::haloplot::hal::detail::void_t<decltype(__VA_ARGS__)>> \
      : ::haloplot::hal::detail::constant<true> {};
