"""Listing 1 in Python: a student's ``AddCollisionImpulse`` as the world's response.

Write it as the workshop prints it, with the listing's members in snake_case::

    import numpy as np
    import impulse

    def add_collision_impulse(c0, c1, hit_point, normal, penetration):
        r0 = hit_point - c0.centre
        ...
        c0.lin_velocity = c0.lin_velocity + c0.inv_mass * normal * jn

    impulse.grade(add_collision_impulse)            # the battery of `impulse grade`
    scene = impulse.load("assets/scenes/bounce.toml", response=add_collision_impulse)

It is called once per touching contact per step: ``c0`` is pushed along ``normal``, ``c1`` the
other way; ``penetration`` > 0 is how deep they overlap (m). Change ``lin_velocity`` and
``ang_velocity`` of the two bodies; nothing else is read back. An exception it raises stops the
run with its message (in a grade, fails the case); it never takes the program down.
"""

import numpy as np

from . import _impulse


class RigidBody:
    """Listing 1's RigidBody (lines 3-23): numpy arrays of float64, SI units.

    centre (3,)               m_centre: the centre of mass, where the step began
    inv_mass                  m_invMass; 0: does not move (static or asleep)
    lin_velocity (3,)         m_linVelocity
    forces (3,)               m_forces: gravity's m g
    inv_inertia (3, 3)        m_invInertia, in the body's frame
    ang_velocity (3,)         m_angVelocity, in the world's frame
    orientation (4,)          m_orientation: w, x, y, z
    torques (3,)              m_torques: none
    world_inv_inertia (3, 3)  m_worldInvInertia = R I^-1 R^T (symmetric: @ from either side)
    restitution, friction     the pair's e and mu (m_restitution, m_friction)
    """

    __slots__ = ("centre", "inv_mass", "lin_velocity", "forces", "inv_inertia", "ang_velocity", "orientation",
                 "torques", "world_inv_inertia", "restitution", "friction")

    def __init__(self, **members):
        for name in self.__slots__:
            setattr(self, name, members[name])

    def __repr__(self):
        return (f"RigidBody(inv_mass={self.inv_mass:g}, centre={np.round(self.centre, 4).tolist()}, "
                f"lin_velocity={np.round(self.lin_velocity, 4).tolist()}, "
                f"ang_velocity={np.round(self.ang_velocity, 4).tolist()})")


def time_step():
    """The step's length in s during a call of the response (listing 1's TimeStep())."""
    return _impulse.time_step()


def case_names():
    """The grade's cases, in the order they run."""
    return list(_impulse.case_names())


class Grade:
    """What ``impulse.grade`` found: a case per law, as ``impulse grade`` reports them.

    ``passed`` and ``failed`` count the cases; ``cases`` are dicts (name, title, law, expected,
    measured, passed, hint, failure); ``str()`` is the command's table, ``json()`` its --json.
    """

    def __init__(self, name, function, cases):
        self.name = name
        self.function = function
        self.cases = cases
        self.passed = sum(1 for case in cases if case["passed"])
        self.failed = len(cases) - self.passed

    def __bool__(self):
        return self.failed == 0

    def __str__(self):
        return _impulse.grade_table(self.name, self.cases)

    def __repr__(self):
        return f"<impulse.Grade {self.name}: {self.passed} of {len(self.cases)} cases pass>"

    def _repr_pretty_(self, printer, cycle):
        printer.text(str(self))

    def json(self):
        return _impulse.grade_json(self.name, self.cases)

    def videos(self, directory):
        """Each failed case as a video, the function's run beside the reference's: the paths."""
        return list(_impulse.failure_videos(str(directory), self.name, self.function, self.cases))
