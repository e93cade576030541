// impulse/workshop.h: what listing 1 of the workshop "Impulse Response" needs to compile as it is
// printed, so that a student's own AddCollisionImpulse can drive the impulse engine.
//
//   impulse render scene.toml --response mine.cpp    # mine.cpp defines AddCollisionImpulse
//   impulse grade mine.cpp                           # a battery of small scenes, each against a law
//   impulse response --include-dir                   # where this file is, for your editor
//
// impulse compiles your file inside a translation unit of its own that includes this header first,
// so you need not include it (an #include "impulse/workshop.h" of your own does no harm). Define
//
//   static void AddCollisionImpulse(RigidBody& c0, RigidBody& c1, const Vector3& hitPoint,
//                                   const Vector3& normal, float penetration);
//
// as the listing does. It is called once per touching contact per step: c0 is pushed along
// `normal`, c1 the other way; `penetration` > 0 is how deep they overlap (m). Change the two
// bodies' m_linVelocity and m_angVelocity; the engine reads nothing else back. A body that cannot
// move has m_invMass == 0 and a zero m_worldInvInertia.
//
// RigidBody is below, with the listing's members and two more: m_restitution and m_friction, the
// pair's coefficient of restitution e and of friction mu (the listing hard-codes e = 0, line 71).
// You may also keep the listing's own `class RigidBody { ... };` (lines 3-23): yours is used then,
// and any of m_restitution, m_friction you add to it are filled in too.
//
// Conventions: row vectors, as the listing's `Vector3 * Matrix4` reads: Transform(v, M) = v M,
// with a translation in M's fourth row. Units SI. Types float, as printed.
#ifndef IMPULSE_WORKSHOP_H
#define IMPULSE_WORKSHOP_H

// Included here, before your file, so that your own includes of them cost nothing.
#include <algorithm>
#include <cassert>
#include <cfloat>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "impulse/workshop_abi.h"

// ***** Vector3 *****
struct Vector3 {
  float x, y, z;
  Vector3() : x(0), y(0), z(0) {}
  Vector3(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}
  float& operator[](int i) { return i == 0 ? x : i == 1 ? y : z; }
  float operator[](int i) const { return i == 0 ? x : i == 1 ? y : z; }
  Vector3& operator+=(const Vector3& v) { x += v.x; y += v.y; z += v.z; return *this; }
  Vector3& operator-=(const Vector3& v) { x -= v.x; y -= v.y; z -= v.z; return *this; }
  Vector3& operator*=(float s) { x *= s; y *= s; z *= s; return *this; }
  Vector3& operator/=(float s) { x /= s; y /= s; z /= s; return *this; }
  float LengthSq() const { return x * x + y * y + z * z; }
  float Length() const { return std::sqrt(LengthSq()); }
};
inline Vector3 operator+(const Vector3& a, const Vector3& b) { return Vector3(a.x + b.x, a.y + b.y, a.z + b.z); }
inline Vector3 operator-(const Vector3& a, const Vector3& b) { return Vector3(a.x - b.x, a.y - b.y, a.z - b.z); }
inline Vector3 operator-(const Vector3& a) { return Vector3(-a.x, -a.y, -a.z); }
inline Vector3 operator*(const Vector3& a, float s) { return Vector3(a.x * s, a.y * s, a.z * s); }
inline Vector3 operator*(float s, const Vector3& a) { return a * s; }
inline Vector3 operator/(const Vector3& a, float s) { return Vector3(a.x / s, a.y / s, a.z / s); }
inline bool operator==(const Vector3& a, const Vector3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
inline bool operator!=(const Vector3& a, const Vector3& b) { return !(a == b); }

inline float Dot(const Vector3& a, const Vector3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vector3 Cross(const Vector3& a, const Vector3& b) {
  return Vector3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
inline float LengthSq(const Vector3& v) { return Dot(v, v); }
inline float Length(const Vector3& v) { return std::sqrt(Dot(v, v)); }
// The unit vector along v; the zero vector stays zero (the listing normalises its tangent, which is
// zero in a head-on hit: no NaN).
inline Vector3 Normalize(const Vector3& v) {
  const float length = Length(v);
  return length > 0 ? v / length : Vector3();
}

// ***** Matrix4 *****: m[row][column]; a default one is the identity.
struct Matrix4 {
  float m[4][4];
  Matrix4() {
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) m[r][c] = r == c ? 1.0f : 0.0f;
  }
  float* operator[](int row) { return m[row]; }
  const float* operator[](int row) const { return m[row]; }
};
inline Matrix4 operator*(const Matrix4& a, const Matrix4& b) {
  Matrix4 p;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      p.m[r][c] = 0;
      for (int k = 0; k < 4; ++k) p.m[r][c] += a.m[r][k] * b.m[k][c];
    }
  return p;
}
inline Matrix4 Transpose(const Matrix4& a) {
  Matrix4 t;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) t.m[r][c] = a.m[c][r];
  return t;
}
// v M as a row vector with w = 1: the upper 3x3 turns, the fourth row moves. An inertia tensor has
// no fourth row, so Transform(Cross(r, n), m_worldInvInertia) is I^-1 (r x n) (it is symmetric).
inline Vector3 Transform(const Vector3& v, const Matrix4& M) {
  return Vector3(v.x * M.m[0][0] + v.y * M.m[1][0] + v.z * M.m[2][0] + M.m[3][0],
                 v.x * M.m[0][1] + v.y * M.m[1][1] + v.z * M.m[2][1] + M.m[3][1],
                 v.x * M.m[0][2] + v.y * M.m[1][2] + v.z * M.m[2][2] + M.m[3][2]);
}
// As the listing's tangent code writes it (lines 113-115): the same as Transform(v, M).
inline Vector3 operator*(const Vector3& v, const Matrix4& M) { return Transform(v, M); }

// ***** Quaternion *****: w + xi + yj + zk; a default one is no turn.
struct Quaternion {
  float x, y, z, w;
  Quaternion() : x(0), y(0), z(0), w(1) {}
  Quaternion(float x_, float y_, float z_, float w_) : x(x_), y(y_), z(z_), w(w_) {}
};
inline Quaternion operator*(const Quaternion& a, const Quaternion& b) {
  return Quaternion(a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y, a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
                    a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w, a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z);
}

// ***** RigidBody *****: listing 1's (lines 3-23), with the pair's e and mu.
class RigidBody {
 public:
  // ***** LINEAR *****
  Vector3 m_centre;  // Center Of Rigid Body
  float m_invMass = 0;
  Vector3 m_linVelocity;
  Vector3 m_forces;  // gravity's m g

  // ***** ANGULAR *****
  Matrix4 m_invInertia;  // in the body's own frame
  Vector3 m_angVelocity;
  Quaternion m_orientation;
  Vector3 m_torques;

  // ***** COMBINED *****
  Matrix4 m_matWorld;         // body to world: Transform(local point, m_matWorld) is the world point
  Matrix4 m_worldInvInertia;  // the inverse inertia in the world's frame, this step's (symmetric)

  // ***** MATERIAL *****: the pair's, as the engine mixes the two bodies' (or a scene's pair says)
  float m_restitution = 0;  // e
  float m_friction = 0;     // mu; 0 when the scene turns friction off

  Vector3 GetPosition() const { return m_centre; }
};

// The length of the step this call belongs to, in seconds (for a position correction of your own).
namespace impulse_workshop {
inline float time_step = 1.0f / 60;

// DBG_CHECKVECTOR's test: a vector that is not finite ends the run here, naming the line.
struct NotFinite : std::runtime_error {
  using std::runtime_error::runtime_error;
};
inline void check_vector(const Vector3& v, const char* expression, const char* file, int line) {
  if (std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)) return;
  char text[512];
  std::snprintf(text, sizeof text, "%s:%d: DBG_CHECKVECTOR( %s ) found (%g, %g, %g): not a number", file, line, expression,
                double(v.x), double(v.y), double(v.z));
  throw NotFinite(text);
}
}  // namespace impulse_workshop
inline float TimeStep() { return impulse_workshop::time_step; }

#define DBG_CHECKVECTOR(v) { ::impulse_workshop::check_vector((v), #v, __FILE__, __LINE__); }

#endif  // IMPULSE_WORKSHOP_H
