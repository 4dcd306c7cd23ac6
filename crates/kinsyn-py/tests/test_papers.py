"""One result of each seed paper from Python, against the kinsyn command line's --json output
(the CLI's own code over the same library) and the paper values the Rust tests use:

- 001 (HEXA with reconfigurable platforms): end-effector 2 has the Schönflies motion X(z),
  4 dof, with every input free;
- 002 (3-RPS-3-SPR): six dof at a general configuration; Table 1 row 1's Study parameters
  assemble, and kinsyn finds twist-system order 3 where the paper prints 5
  (docs/deviations.md, "Paper 002");
- 003 (configurable 4-RRR): at §5's inputs, 12 complex and 2 real assemblies, Table 1's pose
  C4 = (25.112, −147.043) mm, θ = 80°, φ = 105° among them;
- 004 (4-RUU): 32 isolated assemblies at generic inputs (docs/operation-modes.md: Singular's
  vdim 32).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import kinsyn
from test_kinsyn import cli_error, cli_json

ROOT = Path(__file__).resolve().parents[3]
HEXA = ROOT / "mechanisms" / "6-ruu-hexa.json"
SPM = ROOT / "mechanisms" / "multibody" / "3-rps-3-spr.json"
RRR4 = ROOT / "mechanisms" / "4-rrr-configurable.json"
RUU4 = ROOT / "mechanisms" / "4-ruu.json"
ROW1 = ["1:0:0:0:0:0:0:0.75", "1:0:0:0:0:0:0:0.8"]
Q_003 = "141.956,203.366,337.773,305.499"
GENERIC_004 = "R1.1=17,R2.1=-11,R3.1=14,R4.1=6"


def test_paper_001_end_effector_2_is_schoenflies():
    m = kinsyn.Manipulator.from_file(HEXA)
    df = m.modes(body="ee2", lock=[])
    want = cli_json("modes", str(HEXA), "--body", "ee2", "--lock", "")
    assert df.attrs["report"] == want
    assert list(df.dof) == [4]  # paper 001 §2: a Schönflies end-effector
    assert list(df.pattern) == ["X(z)"]
    assert want["end_effector"] == "ee2"


def test_modes_body_relative_to_and_legs_are_the_commands():
    m = kinsyn.Manipulator.from_file(RRR4)
    df = m.modes(body="m3", relative_to="m1", lock="-")
    want = cli_json("modes", str(RRR4), "--body", "m3", "--relative-to", "m1", "--lock", "-")
    assert df.attrs["report"] == want
    # README, "A configurable platform": opposite links keep the same angular velocity.
    assert list(df.pattern) == ["1T0R"]
    h = kinsyn.Manipulator.from_file(HEXA)
    # README, "limb 4 alone": X([0.5,-0.866,0]).
    df = h.modes(body="wrist4", legs=[13, 14, 15, 16], lock="-")
    want = cli_json("modes", str(HEXA), "--legs", "13-16", "--body", "wrist4", "--lock", "-")
    assert df.attrs["report"] == want
    assert df.pattern[0].startswith("X(") and df.dof[0] == 4


def test_analyze_relative_to_is_the_commands():
    m = kinsyn.Manipulator.from_file(RRR4)
    a = m.analyze(body="m3", relative_to="m1")
    want = cli_json("analyze", str(RRR4), "--body", "m3", "--relative-to", "m1")
    assert a.report["relative_motion"] == want["relative_motion"]
    assert a.report["relative_motion"]["dof"] == 1
    assert a.report["relative_motion"]["rotations"] == 0  # paper 003 eq. 27


def test_body_errors_are_the_commands():
    m = kinsyn.Manipulator.from_file(HEXA)
    with pytest.raises(kinsyn.InputError) as e:
        m.modes(body="nope", lock="-")
    assert str(e.value) == cli_error("modes", str(HEXA), "--body", "nope", "--lock", "-")
    with pytest.raises(kinsyn.InputError) as e:
        m.modes(legs="0", lock="-")
    assert str(e.value) == cli_error("modes", str(HEXA), "--legs", "0", "--lock", "-")
    with pytest.raises(kinsyn.InputError) as e:
        m.analyze(relative_to="nope")
    assert str(e.value) == cli_error("analyze", str(HEXA), "--relative-to", "nope")


def test_paper_002_study_parameters():
    m = kinsyn.Manipulator.from_file(SPM)
    assert m.analyze().dof == 6  # paper 002 §5: mobility six
    a = m.analyze(study=[ROW1[0], [1, 0, 0, 0, 0, 0, 0, 0.8]])
    want = cli_json("analyze", str(SPM), "--study", ROW1[0], "--study", ROW1[1])
    for key in ("study", "series_parallel", "platform_dof", "mobility", "joint_values"):
        assert a.report[key] == want[key], key
    # The paper prints 5; 3 by the loop closure, J_S-PM and the twist system (deviations.md).
    assert a.report["series_parallel"]["twist_system_order"]["rank"] == 3
    with pytest.raises(kinsyn.InputError) as e:
        m.analyze(study=[ROW1[0]])
    assert str(e.value) == cli_error("analyze", str(SPM), "--study", ROW1[0])


def test_paper_003_forward_inverse_velocity():
    f = kinsyn.configurable.forward([141.956, 203.366, 337.773, 305.499])
    assert f.report == cli_json("configurable", "forward", "--q", Q_003)
    assert (f.complex_solutions, f.real_solutions) == (12, 2)  # paper 003 §5
    # Table 1's pose (mm, degrees) is one of the two real assemblies.
    table1 = np.array([25.112, -147.043, 80.0, 105.0])
    got = f.assemblies[["c4_x", "c4_y", "theta_deg", "phi_deg"]].to_numpy()
    assert np.min(np.abs(got - table1).max(axis=1)) < 2e-3
    assert f.assemblies.certified.all()
    inv = kinsyn.configurable.inverse(theta=75, phi=100, centre=[20, -30])
    assert inv.attrs["report"] == cli_json(
        "configurable", "inverse", "--centre", "20,-30", "--theta", "75", "--phi", "100"
    )
    assert len(inv) == 16  # §5, Fig. 9
    published = np.array([141.956, 203.366, 337.773, 305.499])
    diff = (inv.to_numpy() - published + 180) % 360 - 180
    assert np.min(np.abs(diff).max(axis=1)) < 1e-3
    v = kinsyn.configurable.velocity(Q_003, [-1.5, -1.25, -2, 1.5])
    want = cli_json("configurable", "velocity", "--q", Q_003, "--qdot=-1.5,-1.25,-2,1.5")
    assert np.array_equal(v["corner_velocities"], np.array(want["corner_velocities"]))
    assert v["omega_m1"] == want["omega_m1"] == v["omega_m3"]  # eq. 27
    with pytest.raises(kinsyn.InputError) as e:
        kinsyn.configurable.forward("1,2,3")
    assert str(e.value) == cli_error("configurable", "forward", "--q", "1,2,3")
    with pytest.raises(kinsyn.InputError) as e:
        kinsyn.configurable.forward(Q_003, method=3)
    assert str(e.value) == cli_error("configurable", "forward", "--q", Q_003, "--method", "3")


def test_paper_004_components_at_generic_inputs():
    df = kinsyn.components(RUU4, inputs=GENERIC_004)
    want = cli_json("components", str(RUU4), "--inputs", GENERIC_004)
    got = dict(df.attrs["report"])
    for r in (got, want):
        r.pop("seconds")
    assert got == want
    assert len(df) == 32 and (df.dimension == 0).all()  # 32 isolated: Singular's vdim 32
    with pytest.raises(kinsyn.InputError) as e:
        kinsyn.components("nope.json")
    assert str(e.value) == cli_error("components", "nope.json")
    with pytest.raises(kinsyn.InputError):
        kinsyn.components(RUU4, method="nope")
    # The path count is decided from the degrees before any tracking: 10 paths are too few, and
    # the refusal is the CLI's line for --max-paths 10.
    with pytest.raises(kinsyn.InputError) as e:
        kinsyn.components(RUU4, inputs=GENERIC_004, max_paths=10)
    assert str(e.value) == cli_error(
        "components", str(RUU4), "--inputs", GENERIC_004, "--max-paths", "10"
    )


def test_components_with_some_inputs_free_and_another_body():
    # `free_inputs` as a list is `--free`; `body` is `--body`: the report is the CLI's, and on
    # each product of the 3-RPS-3-SPR's modes the coupler keeps its module's 3 dof.
    df = kinsyn.components(SPM, free_inputs=["P1.2", "P4.4"], body="coupler")
    want = cli_json(
        "components", str(SPM), "--free", "P1.2,P4.4", "--body", "coupler"
    )
    got = dict(df.attrs["report"])
    for r in (got, want):  # the wall times differ, the rest may not
        r.pop("seconds")
        for b in r["blocks"]:
            b.pop("seconds")
    assert got == want
    assert got["free_inputs"] == ["P1.2", "P4.4"]
    for m in df.mechanism:
        assert m["body"] == "coupler" and m["dof"] == 1
        assert m["moving_inputs"] == ["P1.2", "P4.4"]
