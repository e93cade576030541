// Includes a file outside: its lines would be shown in the compiler's messages.
#include "/etc/passwd"
static void AddCollisionImpulse(RigidBody& c0, RigidBody& c1, const Vector3& hitPoint, const Vector3& normal, float penetration) {}
