// A response that never returns: its loop's condition never changes.
static void AddCollisionImpulse(RigidBody& c0, RigidBody& c1, const Vector3& hitPoint, const Vector3& normal, float penetration)
{
    volatile bool searching = true;
    while (searching) {
    }
    c0.m_linVelocity += normal * penetration;
    c1.m_linVelocity -= normal * penetration + hitPoint * 0.0f;
}
