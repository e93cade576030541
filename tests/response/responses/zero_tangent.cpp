// A response that normalises the tangent by hand: in a head-on hit the tangent is zero, and it
// divides by a zero length (a NaN, caught by DBG_CHECKVECTOR).
static void AddCollisionImpulse(RigidBody& c0, RigidBody& c1, const Vector3& hitPoint, const Vector3& normal, float penetration)
{
    Vector3 dv = c0.m_linVelocity - c1.m_linVelocity;
    Vector3 tangent = dv - Dot(dv, normal) * normal;
    tangent = tangent / tangent.Length();
    c0.m_linVelocity += c0.m_invMass * tangent * 0.01f;
    c1.m_linVelocity -= c1.m_invMass * tangent * 0.01f + hitPoint * 0.0f * penetration;
    DBG_CHECKVECTOR( c0.m_linVelocity )
}
