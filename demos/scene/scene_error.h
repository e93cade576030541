// The one error of the scene room: a scene file (or a --set argument, or --vary) that cannot be
// used. Its message names where: "FILE:LINE: FIELD: REASON", or "--set ARGUMENT: REASON".
#pragma once
#include <stdexcept>

namespace impulse::demos {

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace impulse::demos
