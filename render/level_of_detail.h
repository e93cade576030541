// How finely to tessellate round things so that their outline is within a fraction of a pixel
// of the true curve, and no finer (llvmpipe pays for every triangle, most for tiny ones).
#pragma once

namespace impulse::render {

inline constexpr int kMaxSphereLevel = 5;   // icosphere subdivisions 0..5 (20 .. 20480 triangles)
// Sides of every cylinder: its outline strays radius * (1 - cos(pi / 64)) = 0.0012 radius from the
// circle, a quarter pixel up to a radius of 200 pixels (a body filling a 720-line frame). One mesh
// for all sizes: 256 triangles an instance.
inline constexpr int kCylinderSegments = 64;

// The icosphere subdivision whose outline strays at most `tolerance` from a sphere of `radius`
// (both in pixels): the largest face's circumradius is about 0.64 / 2^n rad, so the error is
// about radius * 0.204 / 4^n.
int sphere_level(float radius, float tolerance);

}  // namespace impulse::render
