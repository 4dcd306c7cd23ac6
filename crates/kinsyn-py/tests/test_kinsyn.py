"""The Python package against the kinsyn command line's --json output (an independent path:
the CLI's own code over the same library) and against published values: paper 000 (the
3-UPS of §5, Table 1 of its Appendix), the 40 assemblies of a generic Gough–Stewart platform
(Faugère & Lazard 1995) and the 70 roots of cyclic-5 (Björck & Fröberg 1991).

The CLI is the binary named by $KINSYN_BIN, or `cargo run -q --locked --bin kinsyn --` run
from the workspace root.
"""

from __future__ import annotations

import json
import os
import subprocess
import threading
import time
from pathlib import Path

import numpy as np
import pytest

import kinsyn

ROOT = Path(__file__).resolve().parents[3]
UPS3 = ROOT / "mechanisms" / "3-ups.json"
UPS6 = ROOT / "mechanisms" / "6-ups.json"
CYCLIC5 = ROOT / "examples" / "systems" / "cyclic5.bertini"


def cli(*args: str) -> subprocess.CompletedProcess:
    binary = os.environ.get("KINSYN_BIN")
    command = [binary] if binary else ["cargo", "run", "-q", "--locked", "--bin", "kinsyn", "--"]
    return subprocess.run(
        command + list(args), cwd=ROOT, capture_output=True, text=True, check=False
    )


def cli_json(*args: str):
    done = cli(*args, "--json")
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def cli_error(*args: str) -> str:
    """The CLI's one-line message for a refused command, without its prefix."""
    done = cli(*args)
    assert done.returncode == 2, (done.returncode, done.stderr)
    lines = done.stderr.splitlines()
    assert len(lines) == 1, lines
    prefix = "kinsyn: error: "
    assert lines[0].startswith(prefix)
    return lines[0][len(prefix):]


# --- the catalogue --------------------------------------------------------------------------


def test_query_has_the_rows_of_the_cli():
    got = kinsyn.query("T3", max_locks=3)
    want = cli_json("query", "--pattern", "T3", "--max-locks", "3")
    assert len(got) == len(want) > 0
    assert got.to_dict("records") == [
        {k: row[k] for k in got.columns} for row in want
    ]


def test_query_with_a_family_is_the_cli_s():
    got = kinsyn.query("X(z)", max_locks=2, family="PPRRRR")
    want = cli_json("query", "--pattern", "X(z)", "--max-locks", "2", "--family", "PPRRRR")
    assert list(got["id"]) == [r["id"] for r in want]
    assert set(got["family"]) <= {"PPRRRR"}


def test_catalogue_has_the_cli_s_entries_and_table_1_of_paper_000():
    cat = kinsyn.catalogue()
    listed = cli_json("catalogue", "list")
    assert list(cat["id"]) == [e["id"] for e in listed]
    summary = cli_json("catalogue", "summary")
    assert len(cat) == summary["total_with_marks"]
    # Paper 000's Appendix, Table 1: 63 PPPRRR chains, all reproduced.
    assert (cat["table"] == 1).sum() == 63
    # The entries verified 3T3R, counted per table by the CLI's summary.
    assert cat["verified"].sum() == sum(t["verified_3t3r"] for t in summary["tables"])


def test_catalogue_patterns_filtered_in_pandas_agree_with_query():
    # Two ways to the same set: the library's query, and a pandas filter over every entry's
    # minimal lock sets.
    p = kinsyn.catalogue_patterns()
    by_filter = set(p[(p.pattern == "T3") & (p.locks <= 3)]["id"])
    by_query = set(kinsyn.query("T3", max_locks=3)["id"])
    assert by_filter == by_query and by_filter


# --- manipulators ---------------------------------------------------------------------------


def test_three_ups_has_six_dof_and_the_cli_s_jacobians():
    # Paper 000 §5.1: "The 3-UPS is a 6 dof parallel manipulator".
    a = kinsyn.Manipulator.from_file(UPS3).analyze()
    assert (a.mobility, a.dof, a.jd_rank) == (6, 6, 6)
    assert not a.singular
    want = cli_json("analyze", str(UPS3))
    assert a.J_D.shape == (6, 6) and a.J_I.shape == (6, 6)
    np.testing.assert_allclose(a.J_D, [r["jd"] for r in want["rows"]], rtol=0, atol=1e-12)
    # J_I: each row's entry in its own input's column (paper 000 eq. 12: 1 for a prismatic).
    np.testing.assert_allclose(np.diag(a.J_I), [r["ji"] for r in want["rows"]], atol=1e-12)
    np.testing.assert_allclose(a.J_I - np.diag(np.diag(a.J_I)), 0.0, atol=0)
    for label, entry in zip(a.inputs, np.diag(a.J_I)):
        if label.startswith("P"):
            assert entry == pytest.approx(1.0, abs=1e-12)
    np.testing.assert_allclose(a.singular_values, want["jd_rank"]["singular_values"], atol=1e-12)


def test_locking_the_three_alphas_leaves_three_dof():
    # Paper 000 §5.2: blocking every α turns the 3-UPS into the 3-RPS, of three dof.
    a = kinsyn.Manipulator.from_file(UPS3).analyze(lock=["R1.1", "R2.1", "R3.1"])
    assert a.dof == 3
    want = cli_json("analyze", str(UPS3), "--lock", "R1.1,R2.1,R3.1")
    assert a.rows == [r["row"] for r in want["rows"]]
    assert a.J_I.shape == (6, 3)


def test_analyze_at_inputs_is_the_cli_s_configuration():
    m = kinsyn.Manipulator.from_file(UPS3)
    a = m.analyze(inputs={"P1.3": 0.05, "R2.1": 3.0})
    want = cli_json("analyze", str(UPS3), "--inputs", "P1.3=0.05,R2.1=3")
    np.testing.assert_allclose(a.joint_values, want["joint_values"], atol=1e-12)
    np.testing.assert_allclose(a.J_D, [r["jd"] for r in want["rows"]], atol=1e-12)


def test_three_ups_modes_are_the_cli_s_and_paper_000_s():
    df = kinsyn.Manipulator.from_file(UPS3).modes()
    assert len(df) == 64  # 2^6 lock subsets
    # Near the reference each locked input removes one dof (legs non-singular there).
    assert (df["dof"] == 6 - df["n_locked"]).all()
    # Paper 000 §5.2: 1T2R (the 3-RPS) exactly when the three α are locked.
    assert list(df[df.pattern == "1T2R"]["locked"]) == ["R1.1 R2.1 R3.1"]
    assert df.set_index("locked").loc["-", "pattern"] == "D"
    want = cli_json("modes", str(UPS3))
    assert list(zip(df["locked"], df["dof"], df["pattern"])) == [
        (m["lock_text"], m["dof"], m["pattern"]) for m in want["modes"]
    ]
    assert df.attrs["report"]["groups"] == want["groups"]
    # Every subset removes one dof per lock at the reference (above): no start is singular.
    assert not df["singular_start"].any()
    assert want["singular_starts"] == []


def test_modes_with_at_most_two_locks_are_the_cli_s():
    df = kinsyn.Manipulator.from_file(UPS6).modes(max_locks=2)
    want = cli_json("modes", str(UPS6), "--max-locks", "2")
    assert len(df) == 1 + 6 + 15
    assert list(df["pattern"]) == [m["pattern"] for m in want["modes"]]


def test_build_writes_what_kinsyn_build_writes():
    m = kinsyn.Manipulator.build(chain="UP!S", legs=6, twist=20.0, alternate=True)
    done = cli("build", "--chain", "UP!S", "--legs", "6", "--twist", "20", "--alternate")
    assert done.returncode == 0, done.stderr
    assert m.to_json() == done.stdout
    assert len(m.inputs) == 6


def _planar_six_ups() -> str:
    # The planar base and platform in general position of the CLI's test
    # a_generic_planar_six_ups_has_40_assemblies.
    base = [[1.03, 0.05], [0.46, 0.91], [-0.55, 0.80], [-0.97, -0.08], [-0.42, -0.90], [0.58, -0.83]]
    platform = [[0.41, 0.22], [0.33, 0.38], [-0.40, 0.27], [-0.52, 0.10], [-0.03, -0.55], [0.15, -0.45]]
    return json.dumps(
        {
            "format": "kinsyn-manipulator/1",
            "name": "planar 6-UPS",
            "units": {"length": "m", "angle": "deg"},
            "platform": {"position": [0, 0, 1.0], "orientation": [0, 0, 0], "point": [0, 0, 0]},
            "legs": [
                {"chain": "UP!S", "base": [b[0], b[1], 0.0], "platform": [p[0], p[1], 0.0]}
                for b, p in zip(base, platform)
            ],
        }
    )


def test_a_generic_planar_gough_stewart_platform_has_40_assemblies():
    # Faugère & Lazard, Mech. Mach. Theory 30(6), 1995: the generic planar class keeps the
    # 40 complex assemblies of the general Gough–Stewart platform.
    s = kinsyn.Manipulator.from_json(_planar_six_ups()).assemblies(seed=2)
    assert s.nonsingular == 40
    assert len(s.real) + len(s.complex) == 40
    assert len(s.complex) % 2 == 0  # conjugate pairs
    assert (s.real["largest_leg_residual"] < 1e-8).all()


def test_six_ups_assemblies_are_the_cli_s():
    s = kinsyn.Manipulator.from_file(UPS6).assemblies(inputs={"P1.3": 0.1})
    want = cli_json("analyze", str(UPS6), "--inputs", "P1.3=0.1", "--all-assemblies")
    assert (s.paths, s.nonsingular, s.at_infinity) == (
        want["paths"], want["nonsingular"], want["at_infinity"]
    )
    assert list(s.real["pose"]) == [a["pose"] for a in want["real_assemblies"]]
    assert s.real["continued_from_reference"].sum() == 1
    np.testing.assert_allclose(
        s.complex,
        [[complex(*c) for c in x] for x in want["complex_assemblies"]],
        atol=1e-12,
    )


def test_a_stack_of_two_modules_has_the_products_of_their_assemblies():
    # Paper 002's 3-RPS-3-SPR: each module has the 3-RPS's 16 assemblies (Schadlbauer, Walter
    # & Husty 2014; the 3-SPR is its inversion), the stack their 16 × 16 pairs, each real one
    # with both bodies' poses; the end-effector's pose is that of the last body.
    f = UPS6.parent / "multibody" / "3-rps-3-spr.json"
    s = kinsyn.Manipulator.from_file(f).assemblies()
    blocks = s.report["blocks"]
    assert [b["nonsingular"] for b in blocks] == [16, 16]
    assert s.nonsingular == 256
    assert len(s.real) == blocks[0]["real"] * blocks[1]["real"]
    for a in s.report["real_assemblies"]:
        assert [b["body"] for b in a["bodies"]] == ["coupler", "end-effector"]
        assert a["bodies"][1]["pose"] == a["pose"]


# --- polynomial systems ---------------------------------------------------------------------


def test_cyclic5_has_70_roots():
    # Björck & Fröberg 1991: cyclic-5 has 70 isolated roots; of Bézout's 120 paths, 50 diverge.
    # The default start (auto) is the polyhedral one: 70 paths, the mixed volume.
    text = CYCLIC5.read_text()
    td = kinsyn.solve(text, start="total-degree")
    assert (td.paths, td.nonsingular, td.at_infinity, td.certified) == (120, 70, 50, 70)
    r = kinsyn.solve(text)
    assert (r.paths, r.nonsingular, r.at_infinity, r.certified) == (70, 70, 0, 70)
    assert (r.start, td.start, r.complete) == ("polyhedral", "total-degree", True)
    want = cli_json("solve", str(CYCLIC5))
    np.testing.assert_allclose(
        r.solutions, [[complex(*c) for c in s["x"]] for s in want["solutions"]], atol=1e-12
    )
    assert r.variables == want["variables"]
    # Each root satisfies the equations: z1 + … + z5 = 0 and z1⋯z5 = 1.
    np.testing.assert_allclose(r.solutions.sum(axis=1), 0, atol=1e-9)
    np.testing.assert_allclose(r.solutions.prod(axis=1), 1, atol=1e-9)
    assert len(r.real) == want["real"]


def test_solve_file_is_solve_of_its_text():
    a = kinsyn.solve_file(CYCLIC5, seed=3)
    b = kinsyn.solve(CYCLIC5.read_text(), seed=3)
    np.testing.assert_array_equal(a.solutions, b.solutions)


def test_the_gil_is_released_while_solving():
    # While another thread solves, this one keeps running Python: with the GIL held it would
    # stop for the whole solve.
    done = threading.Event()
    ticks = 0

    def work():
        kinsyn.solve_file(CYCLIC5, runs=4)
        done.set()

    t = threading.Thread(target=work)
    start = time.perf_counter()
    t.start()
    while not done.is_set():
        ticks += 1
        time.sleep(0.001)
    t.join()
    elapsed = time.perf_counter() - start
    assert elapsed > 0.05, "the solve was too short to tell"
    assert ticks > 0.25 * elapsed / 0.0011, (ticks, elapsed)


# --- errors ---------------------------------------------------------------------------------


def test_a_missing_file_is_the_cli_s_message():
    with pytest.raises(kinsyn.InputError) as e:
        kinsyn.Manipulator.from_file("mechanisms/no-such.json")
    assert str(e.value) == cli_error("analyze", "mechanisms/no-such.json")
    assert isinstance(e.value, kinsyn.KinsynError)


def test_a_malformed_chain_is_the_cli_s_message():
    with pytest.raises(kinsyn.InputError) as e:
        kinsyn.Manipulator.build(chain="UPX")
    assert str(e.value) == cli_error("build", "--chain", "UPX")


def test_a_file_that_is_not_a_description_is_the_cli_s_message():
    with pytest.raises(kinsyn.InputError) as e:
        kinsyn.Manipulator.from_file(CYCLIC5)
    assert str(e.value) == cli_error("analyze", str(CYCLIC5))


def test_bad_patterns_inputs_and_systems_are_the_cli_s_messages():
    with pytest.raises(kinsyn.InputError) as e:
        kinsyn.query("Q3")
    assert str(e.value) == cli_error("query", "--pattern", "Q3")
    with pytest.raises(kinsyn.InputError) as e:
        kinsyn.Manipulator.from_file(UPS3).analyze(inputs="Q9=1")
    assert str(e.value) == cli_error("analyze", str(UPS3), "--inputs", "Q9=1")
    with pytest.raises(kinsyn.InputError) as e:
        kinsyn.solve_file(UPS3)
    assert str(e.value) == cli_error("solve", str(UPS3))
    with pytest.raises(kinsyn.InputError) as e:
        kinsyn.Manipulator.from_file(UPS6).modes(max_locks=6, max_subsets=10)
    assert str(e.value) == cli_error("modes", str(UPS6), "--max-locks", "6", "--max-subsets", "10")


def test_a_bad_system_text_names_the_line():
    with pytest.raises(kinsyn.InputError, match=r"^<string>: line 4: "):
        kinsyn.solve("INPUT\nvariable_group x;\nfunction f;\nf = x^2 +;\nEND;\n")


def test_control_characters_in_messages_are_escaped_as_on_the_cli():
    with pytest.raises(kinsyn.InputError) as e:
        kinsyn.query("T3\n\x1b[31m")
    assert "\n" not in str(e.value) and "\x1b" not in str(e.value)
    assert str(e.value) == cli_error("query", "--pattern", "T3\n\x1b[31m")


# --- the 3D view ----------------------------------------------------------------------------


def _view_data(html: str):
    start = html.index('<script type="application/json" id="kinsyn-data">')
    start = html.index(">", start) + 1
    return json.loads(html[start : html.index("</script>", start)])


def test_view_holds_the_data_of_the_cli(tmp_path):
    m = kinsyn.Manipulator.from_file(UPS3)
    view = m.view(inputs={"P1.3": 0.02}, steps=3, assemblies=False, seed=4)
    page = tmp_path / "cli.html"
    want = cli_json(
        "view", str(UPS3), "--out", str(page), "--inputs", "P1.3=0.02", "--steps", "3", "--no-assemblies", "--seed", "4"
    )
    assert _view_data(view.html) == want
    assert _view_data(page.read_text("utf-8")) == want
    # Inline in Jupyter: the page in a sandboxed frame, its text escaped.
    frame = view._repr_html_()
    assert frame.startswith("<iframe srcdoc=") and "&lt;script" in frame and "<script" not in frame
    view.save(tmp_path / "saved.html")
    assert (tmp_path / "saved.html").read_text("utf-8") == view.html
    assert m.show(steps=1, assemblies=False).html.startswith("<!DOCTYPE html>")


def test_view_refuses_what_the_cli_refuses(tmp_path):
    m = kinsyn.Manipulator.from_file(UPS3)
    with pytest.raises(kinsyn.InputError) as e:
        m.view(steps=0)
    assert str(e.value) == cli_error("view", str(UPS3), "--out", str(tmp_path / "v.html"), "--steps", "0")
