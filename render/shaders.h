// GLSL 450 core sources of the renderer's programs.
//
// Vertex inputs shared by every mesh program (see instance_data.h):
//   0 position, 1 normal                    per vertex
//   2..5 model matrix, 6..8 normal matrix,  per instance
//   9 colour (sRGB), 10 style
#pragma once
#include <string>

namespace impulse::render::shaders {

std::string lit_vertex();       // spheres, boxes, arrows
std::string lit_fragment();
std::string ground_vertex();    // one quad, placed by uniforms
std::string ground_fragment();
std::string shadow_vertex();    // depth only; no fragment stage

}  // namespace impulse::render::shaders
