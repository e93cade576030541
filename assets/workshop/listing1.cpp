// First ..
// Recap of common Rigid Body information...
class RigidBody
{
public:
// ***** LINEAR *****
Vector3 m_centre; // Center Of Rigid Body
float m_invMass;
Vector3 m_linVelocity;
Vector3 m_forces;

// ***** ANGULAR *****
Matrix4 m_invInertia;
Vector3 m_angVelocity;
Quaternion m_orientation;
Vector3 m_torques;

// ***** COMBINED *****
Matrix4 m_matWorld;
Matrix4 m_worldInvInertia;
//...
// Common functions, such as AddForce(), Integrate(), GetPosition()..
};

// Second..
// Actual collision impulse implementation method
//-----

//
//                               -(1+e)(relv.norm)
// j = -----
//   norm.norm(1/Mass0 + 1/Mass1) + (sqr(r0 x norm) / Inertia0) + (sqr(r1 x norm) / Inertia1)
//
//-----
static
void AddCollisionImpulse( RigidBody&   c0,
                         RigidBody&   c1,
                         const Vector3& hitPoint,
                         const Vector3& normal,
                         float   penetration)
{
// Some simple check code.
float invMass0 = c0.m_invMass;
float invMass1 = c1.m_invMass;

const Matrix4& worldInvInertia0 = c0.m_worldInvInertia;
const Matrix4& worldInvInertia1 = c1.m_worldInvInertia;

// Both objects are non movable
if ( (invMass0+invMass1)==0.0 ) return;

Vector3 r0 = hitPoint - c0.m_centre;
Vector3 r1 = hitPoint - c1.m_centre;

Vector3 v0 = c0.m_linVelocity + Cross(c0.m_angVelocity, r0);
Vector3 v1 = c1.m_linVelocity + Cross(c1.m_angVelocity, r1);

// Relative Velocity
Vector3 dv = v0 - v1;

// If the objects are moving away from each other we dont need to apply an impulse
float relativeMovement = -Dot(dv, normal);
if (relativeMovement < -0.01f)
{
    return;
}

// NORMAL Impulse
{
// Coefficient of Restitution
float e = 0.0f;

float normDiv = Dot(normal, normal) *
(invMass0 + invMass1) +
Dot( normal,
Cross( Transform( Cross(r0, normal), worldInvInertia0), r0) +
Cross( Transform( Cross(r1, normal), worldInvInertia1), r1) );

float jn = -1*(1+e)*Dot(dv, normal) / normDiv;

// Hack fix to stop sinking – bias impulse proportional to penetration distance
jn = jn + (penetration*1.5f);

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
#if 1
{
// Work out our tangent vector, with is perpendicular
// to our collision normal
Vector3 tangent(0,0,0);
tangent = dv - (Dot(dv, normal) * normal);
tangent = Normalize(tangent);

float tangDiv = invMass0 + invMass1+
Dot( tangent,
Cross((Cross(r0, tangent) * worldInvInertia0), r0) +
Cross((Cross(r1, tangent) * worldInvInertia1), r1) );

float jt = -1 * Dot(dv, tangent) / tangDiv;
// Clamp min/max tangential component

// Apply contact impulse
c0.m_linVelocity += invMass0 * tangent * jt;
c0.m_angVelocity += Transform(Cross(r0, tangent * jt), worldInvInertia0);

c1.m_linVelocity -= invMass1 * tangent * jt;
c1.m_angVelocity -= Transform(Cross(r1, tangent * jt), worldInvInertia1);

}
#endif
// TANGENT

DBG_CHECKVECTOR( c0.m_linVelocity )
DBG_CHECKVECTOR( c0.m_angVelocity )
DBG_CHECKVECTOR( c1.m_linVelocity )
DBG_CHECKVECTOR( c1.m_angVelocity )
} // End AddCollisionImpulse(..)
