// Includes a device that never ends: the compiler would read it for ever.
#include </dev/urandom>
static void AddCollisionImpulse(RigidBody& c0, RigidBody& c1, const Vector3& hitPoint, const Vector3& normal, float penetration) {}
