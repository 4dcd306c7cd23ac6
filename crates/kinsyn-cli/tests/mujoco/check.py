"""Drives a kinsyn MJCF export in MuJoCo to kinsyn's input values and compares the pose reached.

Usage: python3 check.py MODEL.xml EXPECTED.json

EXPECTED.json (written by tests/suite/mujoco_export.rs) holds:
  body        the MuJoCo body to compare (the end-effector, by its description name)
  ctrl        {actuator label: input value}  (kinsyn's input values at the displaced pose)
  position    [x, y, z]      the body frame's origin there (ground frame)
  quaternion  [w, x, y, z]   the body frame's orientation there
  joints      {joint label: value}  kinsyn's values of the joints MuJoCo has (a label's
              first letter, P or R, says whether it is a length or an angle)
  determined  whether the inputs determine every joint (false when legs have idle motions,
              e.g. a UPS leg spinning about its line: then only the inputs are compared)
  scale       the mechanism's characteristic length
  tolerance   {"length": relative to scale, "angle": rad}
  ramp, settle  seconds: the inputs move linearly from the reference over `ramp`, then are held

Two checks: (1) static: MuJoCo's joints set to kinsyn's values satisfy the equality constraints
and put the body at kinsyn's pose (to round-off: 1e-12 of the scale, 1e-12 rad); (2) dynamic: from
the reference, with the inputs ramped, the simulation settles at kinsyn's pose (the tolerance).
Prints one JSON line of measurements; exits 1 when a tolerance is exceeded, 2 on bad usage.
"""

import json
import sys

import mujoco
import numpy as np


def quaternion_angle(a, b):
    """The rotation angle (rad) between two unit quaternions [w, x, y, z]: that of a⁻¹ b, from
    its vector and scalar parts (accurate near zero, where an arccos of the dot product is not)."""
    relative = np.zeros(4)
    mujoco.mju_mulQuat(relative, np.array([a[0], -a[1], -a[2], -a[3]], dtype=float),
                       np.asarray(b, dtype=float))
    return 2.0 * float(np.arctan2(np.linalg.norm(relative[1:]), abs(relative[0])))


def equality_residual(model, data):
    """The largest violation of the equality constraints (length units: connect and weld
    positions; weld orientation rows are in radians)."""
    mujoco.mj_forward(model, data)
    rows = data.efc_type == mujoco.mjtConstraint.mjCNSTR_EQUALITY
    return float(np.abs(data.efc_pos[rows]).max()) if rows.any() else 0.0


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    model = mujoco.MjModel.from_xml_path(sys.argv[1])
    with open(sys.argv[2], encoding="utf-8") as f:
        expected = json.load(f)
    data = mujoco.MjData(model)
    scale = expected["scale"]

    # At the reference configuration (qpos0) every constraint holds by construction.
    reference_residual = equality_residual(model, data)

    tol = expected["tolerance"]
    tol_length = tol["length"] * scale
    body = model.body(expected["body"]).id
    kinsyn_position = np.array(expected["position"])
    kinsyn_quaternion = np.array(expected["quaternion"])

    # (1) Static: kinsyn's configuration in MuJoCo.
    static = mujoco.MjData(model)
    for label, value in expected["joints"].items():
        static.qpos[model.joint(label).qposadr[0]] = value
    static_residual = equality_residual(model, static)
    static_position_error = float(np.linalg.norm(static.xpos[body] - kinsyn_position))
    static_angle_error = quaternion_angle(static.xquat[body], kinsyn_quaternion)

    # (2) Dynamic: the inputs ramped from the reference, then held.
    target = np.zeros(model.nu)
    for label, value in expected["ctrl"].items():
        target[model.actuator(label).id] = value
    ramp, settle = expected["ramp"], expected["settle"]
    steps_ramp = int(round(ramp / model.opt.timestep))
    steps_settle = int(round(settle / model.opt.timestep))
    worst_during_ramp = 0.0
    for k in range(steps_ramp + steps_settle):
        data.ctrl[:] = target * min(1.0, (k + 1) / steps_ramp)
        mujoco.mj_step(model, data)
        if k < steps_ramp:
            rows = data.efc_type == mujoco.mjtConstraint.mjCNSTR_EQUALITY
            if rows.any():
                worst_during_ramp = max(worst_during_ramp, float(np.abs(data.efc_pos[rows]).max()))

    residual = equality_residual(model, data)
    position_error = float(np.linalg.norm(data.xpos[body] - np.array(expected["position"])))
    angle_error = quaternion_angle(data.xquat[body], np.array(expected["quaternion"]))
    # Each joint's error in tolerances: a slider's over the length one, a revolute's over the
    # angle one.
    worst_joint = 0.0
    worst_joint_in_tolerances = 0.0
    compared = {
        label: value
        for label, value in expected["joints"].items()
        if expected["determined"] or label in expected["ctrl"]
    }
    for label, value in compared.items():
        error = abs(float(data.qpos[model.joint(label).qposadr[0]] - value))
        unit = tol_length if label.upper().startswith("P") else tol["angle"]
        worst_joint = max(worst_joint, error)
        worst_joint_in_tolerances = max(worst_joint_in_tolerances, error / unit)
    servo_error = float(np.abs(data.actuator_length - target).max()) if model.nu else 0.0
    speed = float(np.abs(data.qvel).max())

    report = {
        "body": expected["body"],
        "static_equality_residual": static_residual,
        "static_position_error": static_position_error,
        "static_angle_error": static_angle_error,
        "position_error": position_error,
        "position_error_over_scale": position_error / scale,
        "angle_error": angle_error,
        "worst_joint_error": worst_joint,
        "joints_compared": len(compared),
        "servo_error": servo_error,
        "equality_residual": residual,
        "equality_residual_reference": reference_residual,
        "equality_residual_worst_during_ramp": worst_during_ramp,
        "final_speed": speed,
    }
    print(json.dumps(report))
    length = tol_length
    failures = []
    round_off = 1e-12
    if static_residual > round_off * scale:
        failures.append("kinsyn's configuration violates the constraints")
    if static_position_error > round_off * scale or static_angle_error > round_off:
        failures.append("kinsyn's configuration gives another pose")
    if reference_residual > length:
        failures.append("the constraints do not hold at qpos0")
    if position_error > length:
        failures.append("position")
    if angle_error > tol["angle"]:
        failures.append("orientation")
    if residual > length:
        failures.append("equality residual")
    if worst_joint_in_tolerances > 1.0:
        failures.append("joint values")
    if failures:
        print("FAILED: " + ", ".join(failures), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
