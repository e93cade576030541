// GLSL 450 core sources of the renderer's programs.
//
// Vertex inputs shared by every mesh program (see instance.h):
//   0 position, 1 normal, 11 outline       per vertex (mesh.h's MeshVertex)
//   2..5 model matrix, 6..8 normal matrix,  per instance
//   9 colour (sRGB), 10 style (InstanceStyle flags)
#pragma once
#include <string>

namespace impulse::render::shaders {

// `shadow_map`: the fragment stages look up the shadow map (else only the ground gets shadows,
// drawn by ground_shadow_vertex + ground_fragment(false, true, ...)). `edges`: they also write, at
// location 1, where the nearest outline is (edge_antialias.h).
std::string lit_vertex();       // tessellated spheres, boxes, cylinders, flat meshes
std::string lit_fragment(bool shadow_map, bool edges);
std::string impostor_vertex();  // spheres as ray-cast quads (the unit quad of make_quad)
std::string impostor_fragment(bool shadow_map, bool edges);
std::string flat_vertex();      // flat-coloured triangles (arrows): 0 position, 1 colour
std::string flat_fragment(bool edges);
std::string ground_vertex();    // one quad, placed by uniforms
std::string ground_fragment(bool shadow_map, bool in_shadow, bool edges);  // in_shadow: as if the sun were hidden
std::string ground_shadow_vertex();  // spheres' discs, boxes, cylinders and flat meshes, slid along the light onto the ground
std::string shadow_vertex();    // depth only; no fragment stage
std::string impostor_shadow_vertex();  // sphere impostors into the shadow map
std::string impostor_shadow_fragment();

}  // namespace impulse::render::shaders
