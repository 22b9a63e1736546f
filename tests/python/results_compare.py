# Comparison of two limber.Results, bit for bit (the tests of runs that must give the same numbers).
import numpy as np


def same_bits(a, b):
    """Arrays of one dtype and shape holding the same bytes (NaN equal to NaN)."""
    a, b = np.asarray(a), np.asarray(b)
    return a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()


def assert_same_results(a, b):
    """Every series of two limber.Results equal bit for bit."""
    assert (a.status, a.message, a.title, a.integrator) == (b.status, b.message, b.title, b.integrator)
    assert a.accuracy == b.accuracy
    assert same_bits(a.time, b.time) and same_bits(a.steps, b.steps)
    assert a.bodies.keys() == b.bodies.keys() and a.joints.keys() == b.joints.keys()
    for name, body in a.bodies.items():
        other = b.bodies[name]
        for field in ("position", "orientation", "modal_coordinates", "modal_velocities", "frequencies_hz",
                      "deflection"):
            x, y = getattr(body, field), getattr(other, field)
            assert (x is None and y is None) or same_bits(x, y), f"{name}.{field}"
        assert (body.stress is None) == (other.stress is None)
        for key, values in (body.stress or {}).items():
            assert same_bits(values, other.stress[key]), f"{name}.stress.{key}"
    for name, joint in a.joints.items():
        other = b.joints[name]
        for field in ("position", "force_ground", "torque_ground", "force_joint", "torque_joint",
                      "indeterminate"):
            assert same_bits(getattr(joint, field), getattr(other, field)), f"{name}.{field}"
    for group in ("drivers", "energy", "acceleration_probes"):
        x, y = getattr(a, group), getattr(b, group)
        assert x.keys() == y.keys() and all(same_bits(x[k], y[k]) for k in x), group
    for key in ("position_violation", "velocity_violation"):
        assert same_bits(a.constraints[key], b.constraints[key]), key
    assert a.constraints["redundant"] == b.constraints["redundant"]
    assert a.hinge_limits.keys() == b.hinge_limits.keys()
    for name, limit in a.hinge_limits.items():
        for key in ("angle", "torque", "engaged"):
            assert same_bits(limit[key], b.hinge_limits[name][key]), f"{name}.{key}"
    assert a.events.keys() == b.events.keys()
    for key, values in a.events.items():
        assert values == b.events[key] if key == "limit" else same_bits(values, b.events[key]), f"events.{key}"
    assert (a.event_peaks is None) == (b.event_peaks is None)
    if a.event_peaks is not None:
        x, y = a.event_peaks, b.event_peaks
        assert (x["window"], x["joints"], len(x["windows"])) == (y["window"], y["joints"], len(y["windows"]))
        for u, v in zip(x["windows"], y["windows"]):
            assert (u["label"], u["start"], u["end"], u["states"]) == (v["label"], v["start"], v["end"], v["states"])
            for key in ("force", "force_time", "torque", "torque_time"):
                assert same_bits(u[key], v[key]), f"event_peaks.{key}"
