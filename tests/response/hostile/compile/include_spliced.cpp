// Includes a file outside on two lines joined by a backslash, which the preprocessor reads as one.
#inc\
lude "/etc/passwd"
static void AddCollisionImpulse(RigidBody& c0, RigidBody& c1, const Vector3& hitPoint, const Vector3& normal, float penetration) {}
