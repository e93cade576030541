// A response that crashes at its first call: an index far past the end of its array (a body
// "found" by a number computed from the depth), then a write through what it read there.
static void AddCollisionImpulse(RigidBody& c0, RigidBody& c1, const Vector3& hitPoint, const Vector3& normal, float penetration)
{
    RigidBody* bodies[2] = {&c0, &c1};
    const int which = 1 + int(penetration * 1e9f);
    bodies[which]->m_linVelocity += normal;
    c1.m_linVelocity -= normal + hitPoint * 0.0f;
}
