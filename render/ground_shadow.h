// Shadows on the ground drawn as geometry, the cheap way for a directional light: every point of
// a caster slides along the light onto the ground plane (shaders::ground_shadow_vertex), and the
// ground's own shader, as if the sun were hidden, colours what it covers. A box or a cylinder is its
// own caster; a sphere's caster is its great disc facing the light, whose shadow is the sphere's
// (an ellipse).
// Only the ground receives shadows this way; the shadow map (shadow_map.h) also shades bodies.
#pragma once
#include "render/draw_list.h"
#include "render/instance.h"

namespace impulse::render {

// An instance of make_quad around the sphere's great disc facing the light (the shader keeps the
// disc). `towards_light` is unit.
Instance ground_shadow_disc(const SphereItem& sphere, const Vec3f& towards_light);

}  // namespace impulse::render
