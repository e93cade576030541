#include "render/shaders.h"

namespace impulse::render::shaders {
namespace {

constexpr const char* kVersion = "#version 450 core\n";

// Lighting shared by the mesh and ground programs. Colours come in sRGB; lighting happens in
// linear light and the result goes back to sRGB (the framebuffer is plain RGBA8).
constexpr const char* kLighting = R"(
uniform vec3 u_light_direction;      // unit vector towards the light
uniform vec3 u_camera_position;
uniform mat4 u_light_view_projection;
uniform sampler2DShadow u_shadow_map;
uniform int u_shadows_enabled;
uniform float u_shadow_texel_world; // size of one shadow-map texel in metres

vec3 to_linear(vec3 srgb) { return pow(srgb, vec3(2.2)); }
vec3 to_display(vec3 linear) { return pow(clamp(linear, 0.0, 1.0), vec3(1.0 / 2.2)); }

// 1 = fully lit, 0 = in shadow. Normal offset plus a small depth bias avoid acne; 3x3 taps of
// the hardware 2x2 filter give a soft edge.
float light_visibility(vec3 world, vec3 normal) {
  if (u_shadows_enabled == 0) return 1.0;
  float facing = dot(normal, u_light_direction);
  if (facing <= 0.0) return 0.0;
  vec3 offset_world = world + normal * (1.5 * u_shadow_texel_world);
  vec4 clip = u_light_view_projection * vec4(offset_world, 1.0);
  vec3 coords = clip.xyz / clip.w * 0.5 + 0.5;
  if (any(lessThan(coords.xy, vec2(0.0))) || any(greaterThan(coords.xy, vec2(1.0)))) return 1.0;
  float reference = min(coords.z, 1.0) - 0.0005;
  vec2 texel = 1.0 / vec2(textureSize(u_shadow_map, 0));
  float sum = 0.0;
  sum += texture(u_shadow_map, vec3(coords.xy + vec2(-0.5, -0.5) * texel, reference));
  sum += texture(u_shadow_map, vec3(coords.xy + vec2(0.5, -0.5) * texel, reference));
  sum += texture(u_shadow_map, vec3(coords.xy + vec2(-0.5, 0.5) * texel, reference));
  sum += texture(u_shadow_map, vec3(coords.xy + vec2(0.5, 0.5) * texel, reference));
  return sum / 4.0;
}

// Hemisphere ambient + Lambert + a little Blinn-Phong, in linear light.
vec3 shade(vec3 albedo, vec3 world, vec3 normal, float specular_strength) {
  float visibility = light_visibility(world, normal);
  float sky = 0.5 + 0.5 * normal.y;
  vec3 ambient = mix(vec3(0.24, 0.23, 0.22), vec3(0.38, 0.40, 0.44), sky);
  float diffuse = max(dot(normal, u_light_direction), 0.0);
  vec3 to_eye = normalize(u_camera_position - world);
  vec3 halfway = normalize(u_light_direction + to_eye);
  float specular = diffuse > 0.0 ? pow(max(dot(normal, halfway), 0.0), 60.0) * specular_strength : 0.0;
  vec3 sun = vec3(1.0, 0.98, 0.94) * 0.82;
  return albedo * (ambient + sun * diffuse * visibility) + sun * specular * visibility;
}
)";

}  // namespace

std::string lit_vertex() {
  return std::string(kVersion) + R"(
layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in mat4 in_model;
layout(location = 6) in mat3 in_normal_matrix;
layout(location = 9) in vec3 in_colour;
layout(location = 10) in float in_style;

uniform mat4 u_view_projection;

out vec3 v_world;
out vec3 v_normal;
out vec3 v_local;
out vec3 v_colour;
flat out int v_style;

void main() {
  vec4 world = in_model * vec4(in_position, 1.0);
  v_world = world.xyz;
  v_normal = in_normal_matrix * in_normal;
  v_local = in_position;
  v_colour = in_colour;
  v_style = int(in_style + 0.5);
  gl_Position = u_view_projection * world;
}
)";
}

std::string lit_fragment() {
  return std::string(kVersion) + kLighting + R"(
in vec3 v_world;
in vec3 v_normal;
in vec3 v_local;
in vec3 v_colour;
flat in int v_style;

uniform float u_alpha;
uniform float u_ambient_lift;  // arrows: flatter, more uniform colour

out vec4 out_colour;

const int kStylePlain = 0;
const int kStyleSpinMarks = 1;  // sphere: alternate octants darker so rotation is visible
const int kStyleEdges = 2;      // box: thin dark outline along the edges

float octant_shade(vec3 p) {
  float dark = step(0.0, p.x * p.y * p.z);
  vec3 pixels_to_boundary = abs(p) / max(fwidth(p), vec3(1e-6));
  float blend = clamp(min(min(pixels_to_boundary.x, pixels_to_boundary.y), pixels_to_boundary.z), 0.0, 1.0);
  return mix(1.0, 0.74, mix(0.5, dark, blend));
}

float edge_shade(vec3 p) {
  vec3 pixels_to_edge = (1.0 - abs(p)) / max(fwidth(p), vec3(1e-6));
  // The smallest distance belongs to the face we are on; the next one is to the nearest edge.
  float smallest = min(min(pixels_to_edge.x, pixels_to_edge.y), pixels_to_edge.z);
  float largest = max(max(pixels_to_edge.x, pixels_to_edge.y), pixels_to_edge.z);
  float to_edge = pixels_to_edge.x + pixels_to_edge.y + pixels_to_edge.z - smallest - largest;
  return mix(0.55, 1.0, smoothstep(0.6, 1.6, to_edge));
}

void main() {
  vec3 normal = normalize(v_normal);
  if (!gl_FrontFacing) normal = -normal;
  vec3 albedo = to_linear(v_colour);
  if (v_style == kStyleSpinMarks) albedo *= octant_shade(v_local);
  if (v_style == kStyleEdges) albedo *= edge_shade(v_local);
  vec3 lit = shade(albedo, v_world, normal, 0.35);
  lit = mix(lit, albedo, u_ambient_lift);
  out_colour = vec4(to_display(lit), u_alpha);
}
)";
}

std::string ground_vertex() {
  return std::string(kVersion) + R"(
layout(location = 0) in vec3 in_position;  // unit quad in x, z

uniform mat4 u_view_projection;
uniform vec3 u_ground_centre;
uniform float u_ground_half_size;

out vec3 v_world;

void main() {
  v_world = u_ground_centre + vec3(in_position.x, 0.0, in_position.z) * u_ground_half_size;
  gl_Position = u_view_projection * vec4(v_world, 1.0);
}
)";
}

std::string ground_fragment() {
  return std::string(kVersion) + kLighting + R"(
in vec3 v_world;

uniform vec3 u_background;  // sRGB
uniform vec3 u_ground_colour;  // sRGB
uniform float u_fog_start;
uniform float u_fog_end;

out vec4 out_colour;

// 1 on a line of a grid with `spacing` metres, fading out where cells shrink below a few pixels.
float grid_line(vec2 coord, float spacing) {
  vec2 cell = coord / spacing;
  vec2 derivative = max(fwidth(cell), vec2(1e-6));
  vec2 pixels_to_line = abs(fract(cell - 0.5) - 0.5) / derivative;
  float line = 1.0 - clamp(min(pixels_to_line.x, pixels_to_line.y) - 0.25, 0.0, 1.0);
  float fade = 1.0 - smoothstep(0.04, 0.14, max(derivative.x, derivative.y));
  return line * fade;
}

void main() {
  vec3 normal = vec3(0.0, 1.0, 0.0);
  float minor = grid_line(v_world.xz, 1.0);
  float major = grid_line(v_world.xz, 5.0);
  float darken = max(minor * 0.06, major * 0.12);
  vec3 albedo = to_linear(u_ground_colour * (1.0 - darken));
  vec3 lit = shade(albedo, v_world, normal, 0.0);
  float distance_to_eye = length(v_world - u_camera_position);
  float fog = smoothstep(u_fog_start, u_fog_end, distance_to_eye);
  out_colour = vec4(mix(to_display(lit), u_background, fog), 1.0);
}
)";
}

std::string shadow_vertex() {
  return std::string(kVersion) + R"(
layout(location = 0) in vec3 in_position;
layout(location = 2) in mat4 in_model;

uniform mat4 u_view_projection;

void main() { gl_Position = u_view_projection * in_model * vec4(in_position, 1.0); }
)";
}

}  // namespace impulse::render::shaders
