// The response methods' names, as scene files spell them (World answers its contacts with each in
// world_response.cpp).
#include "physics/response_method.h"

namespace impulse::physics {

namespace {
constexpr std::pair<ResponseMethod, std::string_view> kNames[] = {
    {ResponseMethod::impulse, "impulse"},
    {ResponseMethod::workshop, "workshop"},
    {ResponseMethod::projection, "projection"},
    {ResponseMethod::penalty, "penalty"},
};
}  // namespace

std::string_view method_name(ResponseMethod method) {
  for (const auto& [m, name] : kNames)
    if (m == method) return name;
  return "?";
}

static_assert(std::size(kNames) == 4, "method_names() lists every method");

const std::array<std::string_view, 4>& method_names() {
  static const std::array<std::string_view, 4> names = {kNames[0].second, kNames[1].second, kNames[2].second, kNames[3].second};
  return names;
}

std::optional<ResponseMethod> method_from_name(std::string_view name) {
  for (const auto& [m, n] : kNames)
    if (n == name) return m;
  return std::nullopt;
}

}  // namespace impulse::physics
