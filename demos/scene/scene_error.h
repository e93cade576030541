// The one error of the scene room: a scene file (or a --set argument, or --vary) that cannot be
// used. Its message names where: "FILE:LINE: FIELD: REASON", or "--set ARGUMENT: REASON"; its
// place says the same in parts, for a caller that shows them apart (Python's SceneError).
#pragma once
#include <stdexcept>
#include <string>

namespace impulse::demos {

struct ScenePlace {
  std::string file;     // the scene file ("" when the error is about no file)
  int line = 0;         // from 1; 0 when no line is at fault (or the tables were built in memory)
  std::string table;    // "[world]", "[[body]] 'ball'"; "" when no table is at fault
  std::string field;    // "friction"; "" when the table as a whole is at fault
  std::string setting;  // the --set argument at fault, "world.friction=2"; "" when the file is
};

class SceneError : public std::runtime_error {
 public:
  explicit SceneError(const std::string& message, ScenePlace place = {})
      : std::runtime_error(message), place_(std::move(place)) {}
  const ScenePlace& place() const { return place_; }

 private:
  ScenePlace place_;
};

}  // namespace impulse::demos
