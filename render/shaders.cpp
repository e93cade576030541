// One file over 400 lines, on purpose: it is GLSL text, every program's stages built from the
// same pieces (kVersion, kLighting, kSurface) by concatenation, so that a change of lighting or
// of the sleeping bodies' hatching is made once and read beside every stage that uses it.
#include "render/shaders.h"

namespace impulse::render::shaders {
namespace {

constexpr const char* kVersion = "#version 450 core\n";

// Lighting shared by the mesh and ground programs. Colours come in sRGB; lighting happens in
// linear light and the result goes back to sRGB (the framebuffer is plain RGBA8).
constexpr const char* kLighting = R"(
uniform vec3 u_light_direction;      // unit vector towards the light
uniform vec3 u_camera_position;

vec3 to_linear(vec3 srgb) { return srgb * srgb; }  // gamma 2, close to sRGB and cheap on llvmpipe
vec3 to_display(vec3 linear) { return sqrt(clamp(linear, 0.0, 1.0)); }

#ifdef SHADOW_MAP
uniform mat4 u_light_view_projection;
uniform sampler2DShadow u_shadow_map;
uniform int u_shadows_enabled;
uniform float u_shadow_texel_world; // size of one shadow-map texel in metres

// 1 = fully lit, 0 = in shadow. Normal offset plus a small depth bias avoid acne; the hardware
// 2x2 filter of a linear shadow sampler softens the edge.
float light_visibility(vec3 world, vec3 normal) {
  if (u_shadows_enabled == 0) return 1.0;
  float facing = dot(normal, u_light_direction);
  if (facing <= 0.0) return 0.0;
  vec3 offset_world = world + normal * (1.5 * u_shadow_texel_world);
  vec4 clip = u_light_view_projection * vec4(offset_world, 1.0);
  vec3 coords = clip.xyz / clip.w * 0.5 + 0.5;
  if (any(lessThan(coords.xy, vec2(0.0))) || any(greaterThan(coords.xy, vec2(1.0)))) return 1.0;
  float reference = min(coords.z, 1.0) - 0.0005;
  return texture(u_shadow_map, vec3(coords.xy, reference));  // GL_LINEAR: a 2x2 percentage-closer filter
}
#else
// Without a shadow map only the ground receives shadows (drawn as geometry, see ground_shadow.h).
float light_visibility(vec3 world, vec3 normal) { return 1.0; }
#endif

// Hemisphere ambient + Lambert + a little Blinn-Phong, in linear light.
vec3 shade(vec3 albedo, vec3 world, vec3 normal, float specular_strength) {
  float visibility = light_visibility(world, normal);
  float sky = 0.5 + 0.5 * normal.y;
  vec3 ambient = mix(vec3(0.24, 0.23, 0.22), vec3(0.38, 0.40, 0.44), sky);
  float diffuse = max(dot(normal, u_light_direction), 0.0);
  vec3 to_eye = normalize(u_camera_position - world);
  vec3 halfway = normalize(u_light_direction + to_eye);
  // x^60 as x^32 x^16 x^8 x^4: eight products, where pow() costs llvmpipe a log and an exponential.
  float x = max(dot(normal, halfway), 0.0), x4 = (x * x) * (x * x), x8 = x4 * x4, x16 = x8 * x8;
  float specular = diffuse > 0.0 ? (x16 * x16) * x16 * x8 * x4 * specular_strength : 0.0;
  vec3 sun = vec3(1.0, 0.98, 0.94) * 0.82;
  return albedo * (ambient + sun * diffuse * visibility) + sun * specular * visibility;
}
)";

// Surface styles (InstanceStyle flags) and the final colour, shared by meshes and impostors.
constexpr const char* kSurface = R"(
uniform float u_alpha;
uniform float u_ambient_lift;  // arrows and points: flat, uniform colour

const int kStyleSpinMarks = 1;  // sphere, cylinder: alternate octants darker so rotation is visible
const int kStyleEdges = 2;      // box, flat mesh: thin dark outline along its faces' sides
const int kStyleSleeping = 4;   // pale and hatched: asleep, whatever the viewer's colour vision

float octant_shade(vec3 p) {
  float dark = step(0.0, p.x * p.y * p.z);
  vec3 pixels_to_boundary = abs(p) / max(fwidth(p), vec3(1e-6));
  float blend = clamp(min(min(pixels_to_boundary.x, pixels_to_boundary.y), pixels_to_boundary.z), 0.0, 1.0);
  return mix(1.0, 0.74, mix(0.5, dark, blend));
}

// Pixels from `p`, on a face of the unit cube, to that face's nearest side.
float box_pixels_to_edge(vec3 p) {
  vec3 pixels_to_edge = (1.0 - abs(p)) / max(fwidth(p), vec3(1e-6));
  // The smallest distance belongs to the face we are on; the next one is to the nearest edge.
  float smallest = min(min(pixels_to_edge.x, pixels_to_edge.y), pixels_to_edge.z);
  float largest = max(max(pixels_to_edge.x, pixels_to_edge.y), pixels_to_edge.z);
  return pixels_to_edge.x + pixels_to_edge.y + pixels_to_edge.z - smallest - largest;
}

// Pixels to the nearest side of a flat mesh's face, from its triangle's outline values (mesh.h's
// MeshVertex::outline: 0 on a side, affine across; a constant 1, no side, is a million pixels away).
float face_pixels_to_edge(vec3 outline) {
  vec3 pixels_to_edge = outline / max(fwidth(outline), vec3(1e-6));
  return min(min(pixels_to_edge.x, pixels_to_edge.y), pixels_to_edge.z);
}

float edge_shade(float pixels_to_edge) { return mix(0.55, 1.0, smoothstep(0.6, 1.6, pixels_to_edge)); }

// Diagonal stripes in screen space, 8 pixels apart.
float hatch_shade() {
  float stripe = mod(gl_FragCoord.x + gl_FragCoord.y, 8.0);
  return mix(1.0, 0.8, smoothstep(0.5, 1.5, stripe) * (1.0 - smoothstep(2.5, 3.5, stripe)));
}

// `pixels_to_edge`: with kStyleEdges, how far the nearest side of the face is (box_pixels_to_edge,
// face_pixels_to_edge).
vec4 surface_colour(vec3 srgb, int style, vec3 local, float pixels_to_edge, vec3 world, vec3 normal) {
  vec3 albedo = to_linear(srgb);
  float specular = 0.35;
  if ((style & kStyleSleeping) != 0) {
    float grey = dot(albedo, vec3(0.2126, 0.7152, 0.0722));
    albedo = mix(albedo, vec3(grey), 0.45) * 0.7 + 0.25;
    specular = 0.0;
  }
  if ((style & kStyleSpinMarks) != 0) albedo *= octant_shade(local);
  if ((style & kStyleEdges) != 0) albedo *= edge_shade(pixels_to_edge);
  if ((style & kStyleSleeping) != 0) albedo *= hatch_shade();
  vec3 lit = shade(albedo, world, normal, specular);
  lit = mix(lit, albedo, u_ambient_lift);
  return vec4(to_display(lit), u_alpha);
}
)";

// Edge anti-aliasing (edge_antialias.h): beside its colour a fragment writes how far its pixel's
// centre is from the nearest outline of what it draws towards +x, -x, +y and -y (pixels; an outline
// is where a value `inside`, > 0 inside and about linear across a pixel, is 0, and is counted along
// the axis it is more across). Stored as 1 - distance, so 0 is none within a pixel. Without
// EDGE_AA, nothing is written.
constexpr const char* kEdges = R"(
const vec4 kNoEdges = vec4(2.0);
#ifdef EDGE_AA
layout(location = 1) out vec4 out_edge;

// A zero gradient gives an infinite or undefined distance, which is dropped. (Selects, not
// branches or a computed index: llvmpipe runs 8 or 16 pixels in step.)
vec4 with_edge(vec4 edges, float inside) {
  vec2 gradient = vec2(dFdx(inside), dFdy(inside));
  bool along_x = abs(gradient.x) >= abs(gradient.y);
  // Towards the outline: where `inside` falls. A pixel drawn a little outside it (a mesh's facet
  // beyond the true sphere) is on it.
  float slope = along_x ? gradient.x : gradient.y;
  float offset = max(inside, 0.0) / abs(slope);
  bool forward = slope < 0.0;
  bvec4 slot = bvec4(along_x && forward, along_x && !forward, !along_x && forward, !along_x && !forward);
  return offset < 1.0 ? min(edges, mix(kNoEdges, vec4(offset), slot)) : edges;
}
void write_edges(vec4 edges) { out_edge = vec4(lessThan(edges, vec4(1.0))) * (1.0 - edges); }
#else
vec4 with_edge(vec4 edges, float inside) { return edges; }
void write_edges(vec4 edges) {}
#endif
// A box face (unit-cube coordinates `local`, face normal `local_normal`): its four sides.
vec4 with_box_face_edges(vec4 edges, vec3 local, vec3 local_normal) {
  for (int axis = 0; axis < 3; ++axis)
    if (abs(local_normal[axis]) < 0.5) edges = with_edge(with_edge(edges, 1.0 - local[axis]), 1.0 + local[axis]);
  return edges;
}
// How far inside its outline a ray from `origin` along `direction` passes the infinite cylinder of
// `radius` about the line through `centre` along unit `axis`: the sphere's discriminant, across the
// axis (along^2 - distance^2 + radius^2; 0 on the outline, about linear across it).
float cylinder_inside(vec3 origin, vec3 direction, vec3 centre, vec3 axis, float radius) {
  vec3 to_centre = centre - origin;
  vec3 across = to_centre - axis * dot(to_centre, axis);
  vec3 ray = direction - axis * dot(direction, axis);
  float along = dot(across, ray) * inversesqrt(max(dot(ray, ray), 1e-12));
  return along * along - dot(across, across) + radius * radius;
}
// A face of make_cylinder (unit coordinates `local`, normal `local_normal`): a cap's rim, or the
// side's rims and its outline (`side_inside`, cylinder_inside). Both are worked out and one is
// chosen, so the derivatives are taken in step.
vec4 with_cylinder_edges(vec4 edges, vec3 local, vec3 local_normal, float side_inside) {
  vec4 cap = with_edge(edges, 1.0 - dot(local.xz, local.xz));
  vec4 side = with_edge(with_edge(with_edge(edges, side_inside), 1.0 - local.y), 1.0 + local.y);
  return abs(local_normal.y) > 0.5 ? cap : side;
}
// A triangle of make_flat_mesh: those of its sides that outline its face (MeshVertex::outline; a
// side inside the face has a constant 1, no gradient, so no outline).
vec4 with_face_edges(vec4 edges, vec3 outline) {
  return with_edge(with_edge(with_edge(edges, outline.x), outline.y), outline.z);
}
)";

std::string defines(bool shadow_map, bool edges) {
  return std::string(kVersion) + (shadow_map ? "#define SHADOW_MAP 1\n" : "") + (edges ? "#define EDGE_AA 1\n" : "");
}

}  // namespace

std::string lit_vertex() {
  return std::string(kVersion) + R"(
layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in mat4 in_model;
layout(location = 6) in mat3 in_normal_matrix;
layout(location = 9) in vec3 in_colour;
layout(location = 10) in float in_style;
layout(location = 11) in vec3 in_outline;

uniform mat4 u_view_projection;

out vec3 v_world;
out vec3 v_normal;
out vec3 v_local;
out vec3 v_local_normal;
out vec3 v_outline;
flat out vec4 v_sphere;  // centre and radius, for an icosphere or a cylinder
flat out vec3 v_axis;    // a cylinder's, unit
flat out vec3 v_colour;
flat out int v_style;

void main() {
  vec4 world = in_model * vec4(in_position, 1.0);
  v_sphere = vec4(in_model[3].xyz, length(in_model[0].xyz));
  v_axis = normalize(in_model[1].xyz);
  v_world = world.xyz;
  v_normal = in_normal_matrix * in_normal;
  v_local = in_position;
  v_local_normal = in_normal;
  v_outline = in_outline;
  v_colour = in_colour;
  v_style = int(in_style + 0.5);
  gl_Position = u_view_projection * world;
}
)";
}

std::string lit_fragment(bool shadow_map, bool edges) {
  return defines(shadow_map, edges) + kLighting + kSurface + kEdges + R"(
in vec3 v_world;
in vec3 v_normal;
in vec3 v_local;
in vec3 v_local_normal;
in vec3 v_outline;
flat in vec4 v_sphere;
flat in vec3 v_axis;
flat in vec3 v_colour;
flat in int v_style;

// The mesh drawn, for its outlines: boxes (their faces' sides), icospheres and cylinders (the true
// sphere's or side's outline, as an impostor's, and a cylinder's rims), flat meshes (their faces'
// sides, from v_outline).
const int kBoxMesh = 0;
const int kSphereMesh = 1;
const int kCylinderMesh = 2;
const int kFaceMesh = 3;
uniform int u_mesh;

out vec4 out_colour;

void main() {
  vec3 normal = normalize(v_normal);
  if (!gl_FrontFacing) normal = -normal;
  vec3 ray = normalize(v_world - u_camera_position);
  vec4 edges;
  if (u_mesh == kSphereMesh) {  // a uniform: the derivatives stay in step
    vec3 eye_to_centre = v_sphere.xyz - u_camera_position;
    float along = dot(eye_to_centre, ray);
    float inside = along * along - dot(eye_to_centre, eye_to_centre) + v_sphere.w * v_sphere.w;  // the ray meets it
    edges = with_edge(kNoEdges, inside);
  } else if (u_mesh == kCylinderMesh) {
    float inside = cylinder_inside(u_camera_position, ray, v_sphere.xyz, v_axis, v_sphere.w);
    edges = with_cylinder_edges(kNoEdges, v_local, v_local_normal, inside);
  } else if (u_mesh == kFaceMesh) {
    edges = with_face_edges(kNoEdges, v_outline);
  } else {  // kBoxMesh
    edges = with_box_face_edges(kNoEdges, v_local, v_local_normal);
  }
  write_edges(edges);
  float pixels_to_edge = 0.0;
  if ((v_style & kStyleEdges) != 0)
    pixels_to_edge = u_mesh == kFaceMesh ? face_pixels_to_edge(v_outline) : box_pixels_to_edge(v_local);
  out_colour = surface_colour(v_colour, v_style, v_local, pixels_to_edge, v_world, normal);
}
)";
}

// A sphere impostor: a quad facing the eye through the sphere's centre, just large enough to hold
// its outline (the tangent cone's circle: r d / sqrt(d^2 - r^2)). The fragment stage casts a ray
// per multisample and keeps the samples that hit, so edges are as smooth as a mesh's under MSAA.
std::string impostor_vertex() {
  return std::string(kVersion) + R"(
layout(location = 0) in vec3 in_position;  // unit quad: x, z in [-1, 1]
layout(location = 2) in mat4 in_model;
layout(location = 9) in vec3 in_colour;
layout(location = 10) in float in_style;

uniform mat4 u_view_projection;
uniform vec3 u_camera_position;

out vec3 v_world;
flat out vec3 v_centre;
flat out float v_radius;
flat out vec3 v_to_local_0;
flat out vec3 v_to_local_1;
flat out vec3 v_to_local_2;
flat out vec3 v_colour;
flat out int v_style;

void main() {
  vec3 centre = in_model[3].xyz;
  float radius = length(in_model[0].xyz);
  vec3 to_centre = centre - u_camera_position;
  float distance = length(to_centre);
  vec3 forward = to_centre / distance;
  vec3 helper = abs(forward.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
  vec3 right = normalize(cross(forward, helper));
  vec3 up = cross(right, forward);
  // The eye inside (or on) the sphere: nothing sensible to draw, collapse the quad.
  float half_size = distance > 1.0001 * radius ? 1.01 * radius * distance / sqrt(distance * distance - radius * radius) : 0.0;
  v_world = centre + (right * in_position.x + up * in_position.z) * half_size;
  v_centre = centre;
  v_radius = radius;
  mat3 to_local = transpose(mat3(in_model)) / (radius * radius);  // R^T, from R * radius
  v_to_local_0 = to_local[0];
  v_to_local_1 = to_local[1];
  v_to_local_2 = to_local[2];
  v_colour = in_colour;
  v_style = int(in_style + 0.5);
  gl_Position = u_view_projection * vec4(v_world, 1.0);
}
)";
}

std::string impostor_fragment(bool shadow_map, bool edges) {
  return defines(shadow_map, edges) + kLighting + kSurface + kEdges + R"(
in vec3 v_world;
flat in vec3 v_centre;
flat in float v_radius;
flat in vec3 v_to_local_0;
flat in vec3 v_to_local_1;
flat in vec3 v_to_local_2;
flat in vec3 v_colour;
flat in int v_style;

uniform mat4 u_view_projection;
uniform vec2 u_sample_offsets[16];  // multisample positions relative to the pixel centre
uniform int u_sample_count;

layout(depth_less) out float gl_FragDepth;
out vec4 out_colour;

void main() {
  vec3 eye_to_centre = v_centre - u_camera_position;
  float centre_distance_squared = dot(eye_to_centre, eye_to_centre);
  float radius_squared = v_radius * v_radius;
  // The pixel centre's ray: how far inside the outline it passes (the discriminant).
  vec3 direction = normalize(v_world - u_camera_position);
  float along = dot(eye_to_centre, direction);
  float inside = along * along - centre_distance_squared + radius_squared;
  float per_pixel = fwidth(inside);
  vec4 edges = with_edge(kNoEdges, inside);
  if (inside < -1.5 * per_pixel) discard;
  gl_SampleMask[0] = -1;  // well inside: every sample (a shader that writes the mask must always)
  if (u_sample_count == 1) {
    // One sample, at the pixel centre (edges or no anti-aliasing): its ray is the one above.
    if (inside < 0.0) discard;
  } else if (inside < 1.5 * per_pixel) {
    // Near the outline: one ray per sample, through the quad's plane (linear, so derivatives
    // are exact).
    vec3 step_x = dFdx(v_world);
    vec3 step_y = dFdy(v_world);
    int mask = 0;
    for (int i = 0; i < u_sample_count; ++i) {
      vec3 sample_direction = normalize(v_world + step_x * u_sample_offsets[i].x + step_y * u_sample_offsets[i].y - u_camera_position);
      float sample_along = dot(eye_to_centre, sample_direction);
      if (sample_along * sample_along - centre_distance_squared + radius_squared >= 0.0) mask |= 1 << i;
    }
    if (mask == 0) discard;
    gl_SampleMask[0] = mask;
  }

  // Shade where the pixel centre's ray meets the sphere (on a partly covered pixel whose centre
  // misses, the nearest point of the outline).
  float discriminant = max(inside, 0.0);
  vec3 hit = u_camera_position + direction * (along - sqrt(discriminant));
  vec3 normal = normalize(hit - v_centre);
  vec4 clip = u_view_projection * vec4(hit, 1.0);
  gl_FragDepth = clamp(clip.z / clip.w * 0.5 + 0.5, 0.0, 1.0);
  write_edges(edges);
  vec3 local = mat3(v_to_local_0, v_to_local_1, v_to_local_2) * (hit - v_centre);
  out_colour = surface_colour(v_colour, v_style, local, 0.0, hit, normal);  // 0.0: never kStyleEdges
}
)";
}

// The outline values (FlatVertex::outline) are interpolated with perspective: affine on the flat
// shape, so they are 0 exactly along its sides, whichever of its triangles a pixel is in.
std::string flat_vertex() {
  return std::string(kVersion) + R"(
layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_colour;
layout(location = 2) in vec4 in_outline;
uniform mat4 u_view_projection;
flat out vec3 v_colour;
out vec4 v_outline;
void main() {
  v_colour = in_colour;
  v_outline = in_outline;
  gl_Position = u_view_projection * vec4(in_position, 1.0);
}
)";
}

std::string flat_fragment(bool edges) {
  return defines(false, edges) + kEdges + R"(
flat in vec3 v_colour;
in vec4 v_outline;
uniform float u_alpha;
out vec4 out_colour;
void main() {
  write_edges(with_edge(with_edge(with_edge(with_edge(kNoEdges, v_outline.x), v_outline.y), v_outline.z), v_outline.w));
  out_colour = vec4(v_colour, u_alpha);
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

std::string ground_fragment(bool shadow_map, bool in_shadow, bool edges) {
  return defines(shadow_map, edges) + (in_shadow ? "#define IN_SHADOW 1\n" : "") + kLighting + kEdges + R"(
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

#ifdef IN_SHADOW
in vec2 v_disc;
in vec3 v_local;         // a box's or cylinder's shadow: the unit mesh's coordinates and face normal
in vec3 v_local_normal;
in vec3 v_outline;       // a flat mesh's (MeshVertex::outline)
flat in vec3 v_centre;   // a cylinder's
flat in vec3 v_axis;
flat in float v_radius;
const int kBoxCaster = 0;
const int kDiscCaster = 1;      // keep the samples inside the disc of the quad
const int kCylinderCaster = 2;
const int kFaceCaster = 3;      // a flat mesh
uniform int u_caster;
uniform vec2 u_sample_offsets[16];  // multisample positions relative to the pixel centre
uniform int u_sample_count;
#endif

void main() {
#ifdef IN_SHADOW
  vec4 edges;
  if (u_caster == kDiscCaster) {  // a uniform: the derivatives stay in step
    edges = with_edge(kNoEdges, 1.0 - dot(v_disc, v_disc));
  } else if (u_caster == kCylinderCaster) {
    // The side's shadow ends where the line along which this point slid (ground_shadow_vertex)
    // grazes the cylinder.
    vec3 slide = vec3(u_light_direction.x, max(u_light_direction.y, 0.05), u_light_direction.z);
    edges = with_cylinder_edges(kNoEdges, v_local, v_local_normal, cylinder_inside(v_world, slide, v_centre, v_axis, v_radius));
  } else if (u_caster == kFaceCaster) {
    edges = with_face_edges(kNoEdges, v_outline);  // slid along the light, the values stay affine
  } else {  // kBoxCaster
    edges = with_box_face_edges(kNoEdges, v_local, v_local_normal);
  }
  write_edges(edges);
  gl_SampleMask[0] = -1;  // every sample, unless the disc says otherwise (a shader that writes the mask must always)
  if (u_caster == kDiscCaster) {
    // Per multisample, as the impostors: a quad is two large triangles, where a fan of thin ones
    // would cost llvmpipe far more.
    vec2 step_x = dFdx(v_disc), step_y = dFdy(v_disc);
    float reach = length(abs(step_x) + abs(step_y));  // about a pixel, in disc units
    float radius = length(v_disc);
    if (radius > 1.0 + reach) discard;
    if (u_sample_count == 1) {  // one sample, at the pixel centre
      if (dot(v_disc, v_disc) > 1.0) discard;
    } else if (radius > 1.0 - reach) {  // near the edge: test each sample
      int mask = 0;
      for (int i = 0; i < u_sample_count; ++i) {
        vec2 p = v_disc + step_x * u_sample_offsets[i].x + step_y * u_sample_offsets[i].y;
        if (dot(p, p) <= 1.0) mask |= 1 << i;
      }
      if (mask == 0) discard;
      gl_SampleMask[0] = mask;
    }
  }
#endif
#ifndef IN_SHADOW
  write_edges(kNoEdges);  // the ground: no outline on screen worth the name
#endif
  float minor = grid_line(v_world.xz, 1.0);
  float major = grid_line(v_world.xz, 5.0);
  float darken = max(minor * 0.06, major * 0.12);
  vec3 albedo = to_linear(u_ground_colour * (1.0 - darken));
  // The ground is flat and rough: ambient from the sky plus the sun, where it reaches.
  float sun = max(u_light_direction.y, 0.0) * 0.82;
#ifdef IN_SHADOW
  float visibility = 0.0;
#else
  float visibility = light_visibility(v_world, vec3(0.0, 1.0, 0.0));
#endif
  vec3 lit = albedo * (vec3(0.38, 0.40, 0.44) + vec3(1.0, 0.98, 0.94) * sun * visibility);
  float distance_to_eye = length(v_world - u_camera_position);
  float fog = smoothstep(u_fog_start, u_fog_end, distance_to_eye);
  out_colour = vec4(mix(to_display(lit), u_background, fog), 1.0);
}
)";
}

// Shadows cast on the ground by geometry: each vertex slides along the light onto the plane
// y = u_ground_height (a sphere's great disc, as the quad around it, or a box's, cylinder's or flat
// mesh's own vertices).
std::string ground_shadow_vertex() {
  return std::string(kVersion) + R"(
layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in mat4 in_model;
layout(location = 11) in vec3 in_outline;

uniform mat4 u_view_projection;
uniform vec3 u_light_direction;
uniform float u_ground_height;

out vec3 v_world;
out vec2 v_disc;  // a disc's quad: the disc is where |v_disc| <= 1 (projection keeps this linear)
out vec3 v_local;
out vec3 v_local_normal;
out vec3 v_outline;
flat out vec3 v_centre;  // a cylinder's centre, unit axis and radius
flat out vec3 v_axis;
flat out float v_radius;

void main() {
  v_disc = in_position.xz;
  v_local = in_position;
  v_local_normal = in_normal;
  v_outline = in_outline;
  v_centre = in_model[3].xyz;
  v_axis = normalize(in_model[1].xyz);
  v_radius = length(in_model[0].xyz);
  vec3 world = (in_model * vec4(in_position, 1.0)).xyz;
  world -= u_light_direction * (max(world.y - u_ground_height, 0.0) / max(u_light_direction.y, 0.05));
  world.y = u_ground_height;
  v_world = world;
  gl_Position = u_view_projection * vec4(world, 1.0);
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

// The light is directional and its projection orthographic: the quad faces the light through
// the centre with the sphere's radius, and the depth is that of the near surface.
std::string impostor_shadow_vertex() {
  return std::string(kVersion) + R"(
layout(location = 0) in vec3 in_position;
layout(location = 2) in mat4 in_model;

uniform mat4 u_view_projection;
uniform vec3 u_light_direction;

out vec2 v_offset;  // in the quad's plane, metres from the centre
out vec3 v_world;
flat out float v_radius;

void main() {
  vec3 centre = in_model[3].xyz;
  float radius = length(in_model[0].xyz);
  vec3 helper = abs(u_light_direction.y) < 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
  vec3 right = normalize(cross(u_light_direction, helper));
  vec3 up = cross(right, u_light_direction);
  v_offset = in_position.xz * (1.01 * radius);
  v_world = centre + right * v_offset.x + up * v_offset.y;
  v_radius = radius;
  gl_Position = u_view_projection * vec4(v_world, 1.0);
}
)";
}

std::string impostor_shadow_fragment() {
  return std::string(kVersion) + R"(
in vec2 v_offset;
in vec3 v_world;
flat in float v_radius;

uniform mat4 u_view_projection;
uniform vec3 u_light_direction;

layout(depth_less) out float gl_FragDepth;

void main() {
  float height_squared = v_radius * v_radius - dot(v_offset, v_offset);
  if (height_squared < 0.0) discard;
  vec4 clip = u_view_projection * vec4(v_world + u_light_direction * sqrt(height_squared), 1.0);
  gl_FragDepth = clamp(clip.z * 0.5 + 0.5, 0.0, 1.0);
}
)";
}

}  // namespace impulse::render::shaders
