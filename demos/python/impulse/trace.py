"""A scene's numbers over time (``Scene.simulate``): what ``impulse simulate`` writes, as arrays."""

import numpy as np


class Contacts:
    """Every contact of the kept steps, one row each (the columns of ``--contacts``).

    row (m,)               the trace's row (index into ``trace.time``) the contact belongs to
    time, step (m,)        its step's time (s) and number
    body_a, body_b (m,)    the bodies' names ("world" for none)
    point, normal (m, 3)   where it touches and the normal (body a is pushed along it)
    penetration (m,)       how deep they overlap, m
    normal_impulse (m,)    N s, along the normal
    friction_impulse (m, 3)  N s, in the contact's plane
    """

    def __init__(self, trace, row, a, b, values):
        names = np.array(list(trace.bodies) + ["world"], dtype=object)
        self.row = row
        self.time = trace.time[row]
        self.step = trace.step[row]
        self.body_a = names[a]  # -1 (none) picks "world", the last name
        self.body_b = names[b]
        self.point = values[:, 0:3]
        self.normal = values[:, 3:6]
        self.penetration = values[:, 6]
        self.normal_impulse = values[:, 7]
        self.friction_impulse = values[:, 8:11]

    def __len__(self):
        return len(self.row)

    def __repr__(self):
        return f"<impulse.Contacts: {len(self)} contacts>"


class Trace:
    """The world at the start and after every ``every``th step (and the last).

    time, step (n,)        s and the step's number
    bodies                 the bodies' names, in the scene's order
    position(b), velocity(b), angular_velocity(b) (n, 3); orientation(b) (n, 4), w x y z: a body
                           by name or index
    kinetic_energy, potential_energy (n,)  J
    momentum, angular_momentum (n, 3)      kg m/s, kg m²/s (about the origin)
    contacts               Contacts
    checks                 the scene's [[check]]s: dicts of check, passed, measured

    The numbers are the doubles ``impulse simulate`` prints with %.9g.
    """

    def __init__(self, scene, arrays):
        self.scene = scene
        self.bodies = list(scene.bodies)
        self.time = arrays["time"]
        self.step = arrays["step"]
        self._bodies = arrays["bodies"]
        world = arrays["world"]
        self.kinetic_energy = world[:, 0]
        self.potential_energy = world[:, 1]
        self.momentum = world[:, 2:5]
        self.angular_momentum = world[:, 5:8]
        self.contacts = Contacts(self, arrays["contact_row"], arrays["contact_a"], arrays["contact_b"],
                                 arrays["contact_values"])
        self.checks = list(arrays["checks"])

    def __len__(self):
        return len(self.time)

    def __repr__(self):
        return (f"<impulse.Trace of {self.scene.name}: {len(self)} rows, {len(self.bodies)} bodies, "
                f"t = {self.time[0]:g} .. {self.time[-1]:g} s, {len(self.contacts)} contacts>")

    def view(self, path=None):
        """The interactive page of the scene this trace ran (Scene.view): the same run, as the
        engine gives the same scene the same steps, sampled at the video's frames."""
        return self.scene.view(path)

    def index(self, body):
        """A body's index: by name (the first of that name) or by index."""
        if isinstance(body, str):
            try:
                return self.bodies.index(body)
            except ValueError:
                raise KeyError(f"no body is named {body!r}; the bodies: {', '.join(self.bodies)}") from None
        index = int(body)
        if not -len(self.bodies) <= index < len(self.bodies):
            raise IndexError(f"body {index}: the scene has {len(self.bodies)} bodies")
        return index

    def position(self, body):
        return self._bodies[:, self.index(body), 0:3]

    def orientation(self, body):
        return self._bodies[:, self.index(body), 3:7]

    def velocity(self, body):
        return self._bodies[:, self.index(body), 7:10]

    def angular_velocity(self, body):
        return self._bodies[:, self.index(body), 10:13]

    def to_pandas(self, table="bodies"):
        """A DataFrame of "bodies" (one row per body per kept step), "contacts" or "world", with
        the columns and units of ``impulse simulate``'s CSV files. Needs pandas."""
        try:
            import pandas
        except ImportError:
            raise ImportError("to_pandas needs pandas: apt-get install python3-pandas") from None
        if table == "bodies":
            rows, count = len(self.time), len(self.bodies)
            frame = pandas.DataFrame(self._bodies.reshape(rows * count, 13), columns=[
                "x_m", "y_m", "z_m", "qw", "qx", "qy", "qz", "vx_m_per_s", "vy_m_per_s", "vz_m_per_s",
                "wx_rad_per_s", "wy_rad_per_s", "wz_rad_per_s"])
            frame.insert(0, "body", np.tile(np.array(self.bodies, dtype=object), rows))
            frame.insert(0, "step", np.repeat(self.step, count))
            frame.insert(0, "time_s", np.repeat(self.time, count))
            return frame
        if table == "contacts":
            c = self.contacts
            return pandas.DataFrame({
                "time_s": c.time, "step": c.step, "body_a": c.body_a, "body_b": c.body_b,
                "x_m": c.point[:, 0], "y_m": c.point[:, 1], "z_m": c.point[:, 2],
                "nx": c.normal[:, 0], "ny": c.normal[:, 1], "nz": c.normal[:, 2], "penetration_m": c.penetration,
                "normal_impulse_N_s": c.normal_impulse, "friction_x_N_s": c.friction_impulse[:, 0],
                "friction_y_N_s": c.friction_impulse[:, 1], "friction_z_N_s": c.friction_impulse[:, 2]})
        if table == "world":
            return pandas.DataFrame({
                "time_s": self.time, "step": self.step, "kinetic_energy_J": self.kinetic_energy,
                "potential_energy_J": self.potential_energy, "px_kg_m_per_s": self.momentum[:, 0],
                "py_kg_m_per_s": self.momentum[:, 1], "pz_kg_m_per_s": self.momentum[:, 2],
                "Lx_kg_m2_per_s": self.angular_momentum[:, 0], "Ly_kg_m2_per_s": self.angular_momentum[:, 1],
                "Lz_kg_m2_per_s": self.angular_momentum[:, 2]})
        raise ValueError(f"table must be 'bodies', 'contacts' or 'world', got {table!r}")
