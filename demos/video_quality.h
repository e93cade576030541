// Quality presets in the spirit of Manim's -ql / -qm / -qh. A preset sets size, frame rate and
// CRF together; explicit values (scene file, then command line) override each.
#pragma once
#include "render/video_encoder.h"

#include <optional>
#include <string>
#include <string_view>

namespace impulse::demos {

inline constexpr std::string_view kQualityNames = "low, medium, high";

// low: 854x480, 15 fps, CRF 23; medium (the default): 1280x720, 30 fps, CRF 20;
// high: 1920x1080, 60 fps, CRF 18. nullopt for an unknown name.
std::optional<render::VideoSettings> quality_preset(std::string_view name);

}  // namespace impulse::demos
