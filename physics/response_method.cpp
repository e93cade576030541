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

std::optional<ResponseMethod> method_from_name(std::string_view name) {
  for (const auto& [m, n] : kNames)
    if (n == name) return m;
  return std::nullopt;
}

}  // namespace impulse::physics
