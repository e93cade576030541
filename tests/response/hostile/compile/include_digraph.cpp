// Includes a file outside with the digraph %: for #, after a comment.
/* a comment */ %:include "/etc/passwd"
static void AddCollisionImpulse(RigidBody& c0, RigidBody& c1, const Vector3& hitPoint, const Vector3& normal, float penetration) {}
