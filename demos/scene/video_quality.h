// Quality presets in the spirit of Manim's -ql / -qm / -qh. A preset sets size, frame rate and
// CRF together; explicit values (scene file, then command line) override each.
#pragma once
#include "demos/scene/view_options.h"

#include <optional>
#include <string>
#include <string_view>

namespace impulse::demos {

// low: 854x480, 15 fps, CRF 23; medium (the default): 1280x720, 30 fps, CRF 20;
// high: 1920x1080, 60 fps, CRF 18. nullopt for an unknown name.
std::optional<VideoSetting> quality_preset(std::string_view name);

}  // namespace impulse::demos
