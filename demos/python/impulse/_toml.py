"""Python values as TOML text, for the scene's settings (``set={"world.friction": False}``)."""

import json
import math
import numbers


def toml_value(value):
    """One value written as a scene file writes it: ``false``, ``0.2``, ``"text"``, ``[0, 1, 0]``."""
    if hasattr(value, "tolist") and not isinstance(value, str):
        value = value.tolist()  # numpy arrays and numbers
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        value = float(value)
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, str):
        return json.dumps(value)  # a TOML basic string: the same escapes
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(toml_value(item) for item in value) + "]"
    if isinstance(value, dict):
        return "{" + ", ".join(f"{json.dumps(str(k))} = {toml_value(v)}" for k, v in value.items()) + "}"
    raise TypeError(f"{type(value).__name__} is not a scene value (give a bool, number, string, list or dict)")


def settings(values):
    """``{"world.friction": False}`` (or a list of ``"KEY=VALUE"`` strings) as --set's arguments."""
    if values is None:
        return []
    if isinstance(values, dict):
        return [f"{key}={toml_value(value)}" for key, value in values.items()]
    if isinstance(values, str):
        return [values]
    return list(values)
