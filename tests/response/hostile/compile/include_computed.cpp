// Includes a file outside through a macro, which no scan of the text alone can follow.
#define SECRET "/etc/passwd"
#include SECRET
static void AddCollisionImpulse(RigidBody& c0, RigidBody& c1, const Vector3& hitPoint, const Vector3& normal, float penetration) {}
