#pragma once
// Visitor from lambdas for std::visit: std::visit(Overloaded{[](A) {...}, [](B) {...}}, v).

namespace deploydyn {

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
// Needed by clang 14, which does not deduce aggregate template arguments (P1816) yet.
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

}  // namespace deploydyn
