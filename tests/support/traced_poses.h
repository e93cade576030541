// The poses `impulse simulate --trace` wrote, by body and moment: what a test compares an export's
// poses with.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace impulse::testing {

// A body's pose at a moment: x y z and the quaternion w x y z.
using Pose = std::vector<double>;
using Poses = std::map<std::pair<std::string, long>, Pose>;  // (body, moment in ms) -> pose

// The trace's rows at the given moments (ms), by body name.
Poses traced_poses(const std::filesystem::path& csv, const std::vector<long>& moments);

}  // namespace impulse::testing
