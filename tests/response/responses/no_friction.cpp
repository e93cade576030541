// Listing 1 corrected, but with no tangent impulse at all (its lines 102-130 left out): nothing
// holds a box on another, and the grade must say that friction is missing.

static void AddCollisionImpulse(RigidBody& c0, RigidBody& c1, const Vector3& hitPoint, const Vector3& normal, float penetration)
{
    float invMass0 = c0.m_invMass;
    float invMass1 = c1.m_invMass;

    const Matrix4& worldInvInertia0 = c0.m_worldInvInertia;
    const Matrix4& worldInvInertia1 = c1.m_worldInvInertia;

    // Both objects are non movable
    if ((invMass0 + invMass1) == 0.0) return;

    Vector3 r0 = hitPoint - c0.m_centre;
    Vector3 r1 = hitPoint - c1.m_centre;

    Vector3 v0 = c0.m_linVelocity + Cross(c0.m_angVelocity, r0);
    Vector3 v1 = c1.m_linVelocity + Cross(c1.m_angVelocity, r1);

    // Relative Velocity (eq. 4 and 11, with the cross product)
    Vector3 dv = v0 - v1;

    // If the objects are moving away from each other we dont need to apply an impulse
    float relativeMovement = -Dot(dv, normal);
    if (relativeMovement < -0.01f)
    {
        return;
    }

    // NORMAL Impulse (eq. 13 with 1 + e; eq. 14 with - for body 1)
    float jn = 0.0f;
    {
        // Coefficient of Restitution: the pair's, and none for a resting approach
        float e = c0.m_restitution;
        if (relativeMovement < 0.5f) e = 0.0f;

        float normDiv = Dot(normal, normal) * (invMass0 + invMass1) +
                        Dot(normal, Cross(Transform(Cross(r0, normal), worldInvInertia0), r0) +
                                    Cross(Transform(Cross(r1, normal), worldInvInertia1), r1));

        jn = -1 * (1 + e) * Dot(dv, normal) / normDiv;

        // Position correction: close half the depth beyond 5 mm in each step, as a speed
        const float beta = 0.5f, slop = 0.005f;
        float depth = penetration - slop;
        if (depth > 0.0f) jn = jn + beta / TimeStep() * depth / normDiv;

        if (jn < 0.0f) jn = 0.0f;  // a contact pushes, never pulls

        c0.m_linVelocity += invMass0 * normal * jn;
        c0.m_angVelocity += Transform(Cross(r0, normal * jn), worldInvInertia0);

        c1.m_linVelocity -= invMass1 * normal * jn;
        c1.m_angVelocity -= Transform(Cross(r1, normal * jn), worldInvInertia1);
    }

    DBG_CHECKVECTOR( c0.m_linVelocity )
    DBG_CHECKVECTOR( c0.m_angVelocity )
    DBG_CHECKVECTOR( c1.m_linVelocity )
    DBG_CHECKVECTOR( c1.m_angVelocity )

    DBG_CHECKVECTOR( c0.m_linVelocity )
    DBG_CHECKVECTOR( c0.m_angVelocity )
    DBG_CHECKVECTOR( c1.m_linVelocity )
    DBG_CHECKVECTOR( c1.m_angVelocity )
}
