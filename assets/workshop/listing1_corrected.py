"""Listing 1 of the workshop "Impulse Response", corrected as its errata say, in Python: the
same function as listing1_corrected.cpp, line for line, for `impulse.grade` and
`impulse.load(..., response=add_collision_impulse)` (docs/python.md).

The listing's members are snake_case numpy arrays (impulse.RigidBody); Transform(v, M) is v @ M,
and an inertia matrix is symmetric, so M @ v is the same.
"""

import numpy as np

import impulse


def add_collision_impulse(c0, c1, hit_point, normal, penetration):
    inv_mass0, inv_mass1 = c0.inv_mass, c1.inv_mass
    inertia0, inertia1 = c0.world_inv_inertia, c1.world_inv_inertia

    # Both objects are non movable
    if inv_mass0 + inv_mass1 == 0.0:
        return

    r0 = hit_point - c0.centre
    r1 = hit_point - c1.centre

    v0 = c0.lin_velocity + np.cross(c0.ang_velocity, r0)
    v1 = c1.lin_velocity + np.cross(c1.ang_velocity, r1)

    # Relative velocity (eq. 4 and 11, with the cross product)
    dv = v0 - v1

    # Moving apart: no impulse
    relative_movement = -np.dot(dv, normal)
    if relative_movement < -0.01:
        return

    # NORMAL impulse (eq. 13 with 1 + e; eq. 14 with - for body 1)
    e = c0.restitution if relative_movement >= 0.5 else 0.0  # none for a resting approach
    norm_div = np.dot(normal, normal) * (inv_mass0 + inv_mass1) + np.dot(
        normal, np.cross(np.cross(r0, normal) @ inertia0, r0) + np.cross(np.cross(r1, normal) @ inertia1, r1))
    jn = -(1 + e) * np.dot(dv, normal) / norm_div

    # Position correction: close half the depth beyond 5 mm in each step, as a speed
    beta, slop = 0.5, 0.005
    depth = penetration - slop
    if depth > 0.0:
        jn += beta / impulse.time_step() * depth / norm_div

    jn = max(jn, 0.0)  # a contact pushes, never pulls

    c0.lin_velocity = c0.lin_velocity + inv_mass0 * normal * jn
    c0.ang_velocity = c0.ang_velocity + np.cross(r0, normal * jn) @ inertia0
    c1.lin_velocity = c1.lin_velocity - inv_mass1 * normal * jn
    c1.ang_velocity = c1.ang_velocity - np.cross(r1, normal * jn) @ inertia1

    # TANGENT impulse: along the sliding, clamped to Coulomb's cone |jt| <= mu jn
    tangent = dv - np.dot(dv, normal) * normal
    length = np.linalg.norm(tangent)
    if length == 0.0:
        return  # nothing slides
    tangent = tangent / length
    tang_div = inv_mass0 + inv_mass1 + np.dot(
        tangent, np.cross(np.cross(r0, tangent) @ inertia0, r0) + np.cross(np.cross(r1, tangent) @ inertia1, r1))
    jt = -np.dot(dv, tangent) / tang_div
    mu = c0.friction
    jt = min(max(jt, -mu * jn), mu * jn)

    c0.lin_velocity = c0.lin_velocity + inv_mass0 * tangent * jt
    c0.ang_velocity = c0.ang_velocity + np.cross(r0, tangent * jt) @ inertia0
    c1.lin_velocity = c1.lin_velocity - inv_mass1 * tangent * jt
    c1.ang_velocity = c1.ang_velocity - np.cross(r1, tangent * jt) @ inertia1
