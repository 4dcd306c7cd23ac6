"""Reads a kinsyn export (MJCF or URDF) in Pinocchio and compares its forward kinematics with
kinsyn's.

Usage: python3 check.py MODEL EXPECTED.json

EXPECTED.json (written by tests/suite/pinocchio_export.rs) holds:
  format      "mjcf" or "urdf"
  nq, nv      the sizes Pinocchio's model must have (one coordinate per joint: every joint
              of both files is bounded)
  joints      {joint label: value}  kinsyn's joint values at an assembled configuration away
              from the reference (every joint; the model must have exactly `model_joints`)
  model_joints  the labels of the joints the model must have
  bodies      {body name: 4x4}  each body's displacement from the reference configuration
              (ground frame), kinsyn's product of exponentials
  end_effector  {"name": body name, "frame": 4x4}  the end-effector frame there
  scale       the mechanism's characteristic length
  tolerance   relative to scale for lengths, rad for angles

Pinocchio's tree is set to the joint values; each body's frame there, composed with the inverse
of its frame at the neutral configuration (the reference), is compared with kinsyn's
displacement, and the end-effector frame with kinsyn's. Prints one JSON line of measurements;
exits 1 when a check fails, 2 on bad usage.
"""

import json
import sys

import numpy as np
import pinocchio as pin


def se3(matrix):
    m = np.asarray(matrix, dtype=float)
    return pin.SE3(m[:3, :3], m[:3, 3])


def errors(a, b):
    """Position distance and rotation angle (rad) between two placements."""
    position = float(np.linalg.norm(a.translation - b.translation))
    angle = float(np.linalg.norm(pin.log3(a.rotation.T @ b.rotation)))
    return position, angle


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    path = sys.argv[1]
    with open(sys.argv[2], encoding="utf-8") as f:
        expected = json.load(f)
    if expected["format"] == "mjcf":
        model = pin.buildModelFromMJCF(path)
    else:
        model = pin.buildModelFromUrdf(path)
    data = model.createData()
    failures = []

    names = [model.names[i] for i in range(1, model.njoints)]
    if sorted(names) != sorted(expected["model_joints"]):
        missing = sorted(set(expected["model_joints"]) - set(names))
        extra = sorted(set(names) - set(expected["model_joints"]))
        failures.append(f"joints: missing {missing}, unexpected {extra}")
    if model.nq != expected["nq"] or model.nv != expected["nv"]:
        failures.append(f"nq {model.nq} nv {model.nv}, expected {expected['nq']} {expected['nv']}")
    missing_bodies = [b for b in expected["bodies"] if not model.existFrame(b)]
    if missing_bodies:
        failures.append(f"bodies missing: {missing_bodies}")
    if failures:
        print(json.dumps({"failures": failures}))
        return 1

    q0 = pin.neutral(model)
    q = pin.neutral(model)
    for i in range(1, model.njoints):
        joint = model.joints[i]
        value = expected["joints"][model.names[i]]
        if joint.nq == 1:
            q[joint.idx_q] = value
        elif joint.nq == 2:  # an unbounded revolute: cos and sin of its angle
            q[joint.idx_q:joint.idx_q + 2] = [np.cos(value), np.sin(value)]
        else:
            failures.append(f"joint {model.names[i]} has {joint.nq} coordinates")

    pin.framesForwardKinematics(model, data, q0)
    reference = {b: data.oMf[model.getFrameId(b)].copy() for b in expected["bodies"]}
    end = expected["end_effector"]["name"]
    pin.framesForwardKinematics(model, data, q)

    scale = expected["scale"]
    tol = expected["tolerance"]
    worst_body = [0.0, 0.0]
    for body, matrix in expected["bodies"].items():
        moved = data.oMf[model.getFrameId(body)] * reference[body].inverse()
        position, angle = errors(moved, se3(matrix))
        worst_body = [max(worst_body[0], position / scale), max(worst_body[1], angle)]
        if position > tol["length"] * scale or angle > tol["angle"]:
            failures.append(f"body {body}: displacement off by {position:.3e}, {angle:.3e} rad")
    position, angle = errors(data.oMf[model.getFrameId(end)], se3(expected["end_effector"]["frame"]))
    if position > tol["length"] * scale or angle > tol["angle"]:
        failures.append(f"end-effector {end}: off by {position:.3e}, {angle:.3e} rad")

    print(json.dumps({
        "nq": model.nq,
        "nv": model.nv,
        "bodies": len(expected["bodies"]),
        "body_error": {"length": worst_body[0], "angle": worst_body[1]},
        "end_effector_error": {"length": position / scale, "angle": angle},
        "failures": failures,
    }))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
