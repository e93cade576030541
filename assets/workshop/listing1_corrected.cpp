// Listing 1 of the workshop "Impulse Response", corrected as its errata say (ERRATA.md in the
// workshop's notes; docs/students.md). What changed from listing1.cpp, line by line:
//   - the pair's coefficient of restitution instead of e = 0 (line 71), and none below a closing
//     speed of 0.5 m/s: e on every tiny approach makes a resting body jiggle;
//   - a position correction that grows with the mass it must hold up instead of the "hack fix"
//     jn += 1.5 * penetration (line 85), which adds a length to an impulse: Baumgarte's bias,
//     a closing speed of beta / dt times the depth beyond a slop, through eq. 13's denominator;
//   - friction clamped to Coulomb's cone, |jt| <= mu jn (the comment on line 119);
//   - the listing's signs are kept: they are right where the printed equations slip (eq. 8 and 13
//     print -(1 - e); eq. 7, 12 and 14 print + for body b).
// It needs impulse/workshop.h, which impulse includes first (RigidBody has m_restitution and
// m_friction there).

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

    // TANGENT Impulse Code
    {
        // Work out our tangent vector, with is perpendicular to our collision normal
        Vector3 tangent = dv - (Dot(dv, normal) * normal);
        tangent = Normalize(tangent);  // zero when nothing slides

        float tangDiv = invMass0 + invMass1 +
                        Dot(tangent, Cross((Cross(r0, tangent) * worldInvInertia0), r0) +
                                     Cross((Cross(r1, tangent) * worldInvInertia1), r1));

        float jt = -1 * Dot(dv, tangent) / tangDiv;

        // Clamp min/max tangential component: Coulomb's |jt| <= mu jn
        float mu = c0.m_friction;
        if (jt > mu * jn) jt = mu * jn;
        if (jt < -mu * jn) jt = -mu * jn;

        // Apply contact impulse
        c0.m_linVelocity += invMass0 * tangent * jt;
        c0.m_angVelocity += Transform(Cross(r0, tangent * jt), worldInvInertia0);

        c1.m_linVelocity -= invMass1 * tangent * jt;
        c1.m_angVelocity -= Transform(Cross(r1, tangent * jt), worldInvInertia1);
    }

    DBG_CHECKVECTOR( c0.m_linVelocity )
    DBG_CHECKVECTOR( c0.m_angVelocity )
    DBG_CHECKVECTOR( c1.m_linVelocity )
    DBG_CHECKVECTOR( c1.m_angVelocity )
}
