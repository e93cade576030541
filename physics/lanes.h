// Two manifolds solved side by side, one in each lane of an SSE register: the arithmetic of one,
// lane by lane, on GCC's vectors of two doubles (Box2D v3 solves its contacts four or eight wide
// the same way). Branches become lane-wise selections.
#pragma once
#include "physics/math.h"

#include <cmath>

namespace impulse::physics {

using Real2 = double __attribute__((vector_size(16)));
using Mask2 = long __attribute__((vector_size(16)));  // a comparison's result: all ones or zero per lane

#define IMPULSE_LANES [[gnu::always_inline]] inline

// A sweep's kernel built three times, for AVX2, for SSE4.2 and for baseline x86-64, and the one
// this CPU can run chosen when the program loads: SSE4.1 selects lanes by a mask in one instruction
// (blendvpd; SSE2 takes three) and compares 64-bit lanes in one (pcmpeqq); AVX2's encoding gives
// each instruction three operands, fewer copies. None of them fuses a multiply-add, and the
// arithmetic is the same instructions on the same 128-bit lanes (-mprefer-vector-width=128,
// CMakeLists.txt): the same bits on every machine. Clang 14 does not clone templates: its builds
// (the sanitizers') run the baseline code, so the test command checks the determinism constants on
// both, and on GCC's other clones under an emulated CPU (tests/physics/CMakeLists.txt). Other CPUs
// than x86-64 build it once.
#if defined(__x86_64__) && !defined(__clang__)
#define IMPULSE_LANES_KERNEL __attribute__((target_clones("avx2", "sse4.2", "default")))
#else
#define IMPULSE_LANES_KERNEL
#endif

IMPULSE_LANES Real2 splat(Real x) { return Real2{x, x}; }
IMPULSE_LANES bool any(Mask2 m) { return (m[0] | m[1]) != 0; }
IMPULSE_LANES Real2 select(Mask2 m, Real2 a, Real2 b) { return m ? a : b; }
// std::max(x, 0) and std::clamp(x, low, high), as the standard library computes them.
IMPULSE_LANES Real2 max0(Real2 x) { return select(x < 0, splat(0), x); }
IMPULSE_LANES Real2 clamp(Real2 x, Real2 low, Real2 high) { return select(x < low, low, select(high < x, high, x)); }
IMPULSE_LANES Real2 sqrt(Real2 x) { return Real2{std::sqrt(x[0]), std::sqrt(x[1])}; }
// The same for one lane, so that a function written once serves one pair (Real) and two (Real2).
IMPULSE_LANES bool any(bool m) { return m; }
IMPULSE_LANES Real select(bool m, Real a, Real b) { return m ? a : b; }
IMPULSE_LANES Real sqrt(Real x) { return std::sqrt(x); }

// A vector's components, each in two lanes.
struct V3 {
  Real2 x, y, z;
};
IMPULSE_LANES V3 operator+(const V3& a, const V3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
IMPULSE_LANES V3 operator-(const V3& a, const V3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
IMPULSE_LANES V3 operator*(Real2 s, const V3& a) { return {s * a.x, s * a.y, s * a.z}; }
IMPULSE_LANES Real2 dot(const V3& a, const V3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
IMPULSE_LANES V3 select(Mask2 m, const V3& a, const V3& b) { return {select(m, a.x, b.x), select(m, a.y, b.y), select(m, a.z, b.z)}; }

// A unit quaternion in two lanes: vector part u and scalar w.
struct Q4 {
  V3 u;
  Real2 w;
};
// q v q*, as rotate() in math.h: v + w t + u x t with t = 2 u x v.
IMPULSE_LANES V3 rotate(const Q4& q, const V3& v) {
  const V3& u = q.u;
  const V3 t{2 * (u.y * v.z - u.z * v.y), 2 * (u.z * v.x - u.x * v.z), 2 * (u.x * v.y - u.y * v.x)};
  return {v.x + q.w * t.x + (u.y * t.z - u.z * t.y), v.y + q.w * t.y + (u.z * t.x - u.x * t.z), v.z + q.w * t.z + (u.x * t.y - u.y * t.x)};
}
IMPULSE_LANES Q4 conjugate(const Q4& q) { return {{-q.u.x, -q.u.y, -q.u.z}, q.w}; }

// Two vectors or quaternions, one per lane; and one lane's vector back.
IMPULSE_LANES V3 lanes(const Vec3& a, const Vec3& b) { return {Real2{a.x(), b.x()}, Real2{a.y(), b.y()}, Real2{a.z(), b.z()}}; }
IMPULSE_LANES Q4 lanes(const Quat& a, const Quat& b) { return {{Real2{a.x(), b.x()}, Real2{a.y(), b.y()}, Real2{a.z(), b.z()}}, Real2{a.w(), b.w()}}; }
IMPULSE_LANES Vec3 lane(const V3& v, int l) { return Vec3(v.x[l], v.y[l], v.z[l]); }
IMPULSE_LANES void set_lane(V3& v, int l, const Vec3& value) {
  v.x[l] = value.x();
  v.y[l] = value.y();
  v.z[l] = value.z();
}

#undef IMPULSE_LANES

}  // namespace impulse::physics
