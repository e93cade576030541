// Includes another file beside it (another student's, in a class's folder).
#include "../run/read_file.cpp"
static void AddCollisionImpulse(RigidBody& c0, RigidBody& c1, const Vector3& hitPoint, const Vector3& normal, float penetration) {}
