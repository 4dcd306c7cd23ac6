//! The manipulator commands of the `kinsyn` binary (`modes`, `analyze`, `build`): output on the
//! committed files of mechanisms/, and one-line errors naming the field with exit code 2 for every
//! kind of bad input (exit 1 for a missing file).

use crate::common;
use serde_json::Value;
use std::path::{Path, PathBuf};

use common::{kinsyn, stderr, stdout};
use std::process::Output;

/// Runs kinsyn, asserts success and returns its standard output.
fn succeed(args: &[&str]) -> String {
    let o = kinsyn(args);
    assert_eq!(o.status.code(), Some(0), "kinsyn {args:?}: {}", stderr(&o));
    stdout(&o)
}

/// The committed 3-UPS description as a JSON value, to be broken one field at a time.
fn three_ups() -> Value {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join("mechanisms/3-ups.json");
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

/// Writes `text` as `name` in `dir` and returns the path.
fn write(dir: &tempfile::TempDir, name: &str, text: &str) -> PathBuf {
    let path = dir.path().join(name);
    std::fs::write(&path, text).unwrap();
    path
}

/// The 3-UPS with `edit` applied, written to a file in `dir`.
fn broken(dir: &tempfile::TempDir, name: &str, edit: impl FnOnce(&mut Value)) -> PathBuf {
    let mut v = three_ups();
    edit(&mut v);
    write(dir, name, &serde_json::to_string_pretty(&v).unwrap())
}

/// A 6-UPS with both U revolutes and the slider of every leg actuated (18 inputs: 2^18 lock
/// subsets), written by `kinsyn build` into `dir`.
fn eighteen_inputs(dir: &tempfile::TempDir) -> PathBuf {
    let file = dir.path().join("18.json");
    succeed(&[
        "build",
        "--legs",
        "6",
        "--chain",
        "U(!,!)P!S",
        "--twist",
        "20",
        "--alternate",
        "-o",
        file.to_str().unwrap(),
    ]);
    file
}

/// Asserts exit code 2, nothing on stdout, and exactly one stderr line that starts with
/// `kinsyn: error:` and contains every one of `needles`.
fn assert_input_error(o: &Output, what: &str, needles: &[&str]) {
    let err = stderr(o);
    assert_eq!(o.status.code(), Some(2), "{what}: {err}");
    assert!(stdout(o).is_empty(), "{what}: {}", stdout(o));
    assert_eq!(err.lines().count(), 1, "{what}: {err}");
    assert!(err.starts_with("kinsyn: error: "), "{what}: {err}");
    for needle in needles {
        assert!(err.contains(needle), "{what}: '{needle}' not in {err}");
    }
}

/// One section of `modes`' compact text: `dof K: N subsets, P patterns` and its pattern lines,
/// each split into words.
struct DofSection {
    dof: usize,
    subsets: usize,
    lines: Vec<String>,
}

/// The `dof K` sections of `modes`' text output, from the most dof to none.
fn dof_sections(out: &str) -> Vec<DofSection> {
    let mut sections: Vec<DofSection> = Vec::new();
    let mut inside = false;
    for line in out.lines() {
        if let Some(rest) = line.strip_prefix("dof ") {
            let (dof, rest) = rest.split_once(": ").expect("dof K: N subsets");
            let subsets = rest.split_whitespace().next().unwrap();
            sections.push(DofSection {
                dof: dof.parse().unwrap(),
                subsets: subsets.parse().unwrap(),
                lines: Vec::new(),
            });
            inside = true;
        } else if inside && line.starts_with("  ") {
            sections.last_mut().unwrap().lines.push(line.trim().into());
        } else {
            inside = false;
        }
    }
    sections
}

/// Words of a line, for comparisons that ignore the column padding.
fn words(line: &str) -> Vec<&str> {
    line.split_whitespace().collect()
}

#[test]
fn modes_of_the_three_ups_list_64_subsets_and_the_three_rps() {
    let out = succeed(&["modes", "mechanisms/3-ups.json"]);
    assert!(
        out.starts_with("3-UPS: 6 inputs (R1.1 P1.3 R2.1 P2.3 R3.1 P3.3), 64 lock subsets;"),
        "{out}"
    );
    // The patterns by dof account for every one of the 64 subsets: near the reference each
    // locked input removes one dof (the legs are not singular there), so dof 6 − k is reached by
    // the C(6, k) subsets of k locks.
    let sections = dof_sections(&out);
    assert_eq!(
        sections.iter().map(|s| s.dof).collect::<Vec<_>>(),
        [6, 5, 4, 3, 2, 1, 0],
        "{out}"
    );
    let binomial = [1, 6, 15, 20, 15, 6, 1];
    for s in &sections {
        assert_eq!(s.subsets, binomial[6 - s.dof], "dof {}: {out}", s.dof);
    }
    // Paper 000 §5–5.2: holding α̇ = 0 in every leg (the U's first revolute, R_i.1) turns the
    // 3-UPS into the 3-RPS, whose platform keeps three dof (§5, eqs. 20–22). Those three dof are
    // the 3-RPS's known 1T2R motion (one translation, two rotations, with parasitic motion of the
    // other three coordinates), not one of the 12 displacement groups; no other subset gives it.
    let dof3 = &sections[3];
    assert!(
        dof3.lines
            .iter()
            .any(|l| words(l) == ["1T2R", "1", "subset", "lock", "R1.1", "R2.1", "R3.1"]),
        "{out}"
    );
    // Nothing locked: the full 6 dof, the displacement group D; everything locked: E.
    assert_eq!(
        sections[0]
            .lines
            .iter()
            .map(|l| words(l))
            .collect::<Vec<_>>(),
        [["D", "group", "1", "subset", "lock", "-"]],
        "{out}"
    );
    assert_eq!(
        words(&sections[6].lines[0]),
        [
            "E", "group", "1", "subset", "lock", "R1.1", "P1.3", "R2.1", "P2.3", "R3.1", "P3.3"
        ],
        "{out}"
    );
    assert!(
        out.lines()
            .any(|l| l.trim() == "1T2R     lock R1.1 R2.1 R3.1"),
        "{out}"
    );
}

#[test]
fn modes_json_has_64_modes() {
    let o = kinsyn(&["modes", "mechanisms/3-ups.json", "--json"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: Value = serde_json::from_str(&stdout(&o)).expect("modes --json is JSON");
    assert_eq!(v["manipulator"], "3-UPS");
    let modes = v["modes"].as_array().unwrap();
    assert_eq!(modes.len(), 64);
    assert_eq!(v["actuators"].as_array().unwrap().len(), 6);
    let rps = modes
        .iter()
        .find(|m| m["lock_text"] == "R1.1 R2.1 R3.1")
        .unwrap();
    assert_eq!(rps["dof"], 3);
    assert_eq!(rps["pattern"], "1T2R");
    assert_eq!(rps["group"], false);
    // Each locked input removes one dof near the reference configuration.
    for m in modes {
        let locked = m["locked"].as_array().unwrap().len() as u64;
        assert_eq!(m["dof"].as_u64(), Some(6 - locked), "{m}");
    }
}

#[test]
fn analyze_the_three_rps_has_mobility_3() {
    let out = succeed(&["analyze", "mechanisms/3-rps.json"]);
    assert!(
        out.starts_with("3-RPS: P = [0.000000, 0.000000, 1.000000] m;"),
        "{out}"
    );
    assert!(
        out.lines()
            .any(|l| l.starts_with("mobility 3 (joint rates closing the loops), platform dof 3")),
        "{out}"
    );
    // Three actuation rows (the prismatic inputs, J_I entry 1 as in eq. 21) and three leg
    // constraint rows (eq. 22).
    assert_eq!(
        out.lines()
            .filter(|l| l.trim().starts_with("input P"))
            .count(),
        3
    );
    assert_eq!(
        out.lines()
            .filter(|l| l.trim().starts_with("constraint leg"))
            .count(),
        3
    );
    assert!(out.contains("no singularity"), "{out}");
    let o = kinsyn(&["analyze", "mechanisms/3-rps.json", "--json"]);
    let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["mobility"], 3);
    assert_eq!(v["platform_dof"], 3);
    assert_eq!(v["rows"].as_array().unwrap().len(), 6);
}

#[test]
fn analyze_at_a_pose_and_with_locks() {
    // Locking every α of the 3-UPS leaves three dof, as the 3-RPS (paper 000 §5.2).
    let out = succeed(&[
        "analyze",
        "mechanisms/3-ups.json",
        "--lock",
        "R1.1,R2.1,R3.1",
    ]);
    assert!(out.contains("locked: R1.1 R2.1 R3.1"), "{out}");
    assert!(
        out.contains("mobility 3 (joint rates closing the loops)"),
        "{out}"
    );
    assert_eq!(
        out.lines()
            .filter(|l| l.trim().starts_with("locked R"))
            .count(),
        3
    );
    // A displaced pose of the 6-UPS: the platform frame (= P here) goes where asked.
    let v: Value = serde_json::from_str(&succeed(&[
        "analyze",
        "mechanisms/6-ups.json",
        "--pose",
        "0.1,0.05,1.1,5,-3,10",
        "--json",
    ]))
    .unwrap();
    let p: Vec<f64> = v["point"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    for (got, want) in p.iter().zip([0.1, 0.05, 1.1]) {
        assert!((got - want).abs() < 1e-9, "{p:?}");
    }
    let r: Vec<f64> = v["platform_rotation_vector_rad"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    for (got, want) in r.iter().zip([5.0_f64, -3.0, 10.0]) {
        assert!((got - want.to_radians()).abs() < 1e-9, "{r:?}");
    }
    assert_eq!(v["mobility"], 6);
    // The 3-RPS's one translation is along z: raising the platform to z = 5 without tilt only
    // lengthens the legs (the sliders have no stroke limit), so that pose does assemble.
    let out = succeed(&["analyze", "mechanisms/3-rps.json", "--pose", "0,0,5,0,0,0"]);
    assert!(out.contains(", 5.000000] m;"), "{out}");
    assert!(
        out.contains("mobility 3 (joint rates closing the loops)"),
        "{out}"
    );
}

#[test]
fn bad_description_files_are_one_line_naming_the_field_and_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    let cases: Vec<(&str, PathBuf, Vec<&str>)> = vec![
        (
            "not JSON",
            write(
                &dir,
                "notjson.json",
                "{\"format\": \"kinsyn-manipulator/1\", ",
            ),
            vec!["is not a kinsyn manipulator file (not JSON"],
        ),
        (
            "no format",
            broken(&dir, "noformat.json", |v| {
                v.as_object_mut().unwrap().remove("format");
            }),
            vec![
                "is not a kinsyn manipulator file (no \"format\"",
                "kinsyn-manipulator/1",
            ],
        ),
        (
            "wrong format",
            broken(&dir, "wrongformat.json", |v| {
                v["format"] = "kinsyn-manipulator/2".into();
            }),
            vec![
                "(\"format\" is \"kinsyn-manipulator/2\"",
                "expected \"kinsyn-manipulator/1\"",
            ],
        ),
        (
            "unknown chain letter",
            broken(&dir, "letter.json", |v| {
                v["legs"][1]["chain"] = "UXS".into();
            }),
            vec!["legs[1].chain", "'X' is not a joint letter"],
        ),
        (
            "wrong number of axes",
            broken(&dir, "axes.json", |v| {
                v["legs"][2]["axes"].as_array_mut().unwrap().pop();
            }),
            vec!["legs[2].axes:", "5 axes for the 6 primitive joints of UPS"],
        ),
        (
            "zero axis",
            broken(&dir, "zero.json", |v| {
                v["legs"][0]["axes"][4] = serde_json::json!([0.0, 0.0, 0.0]);
            }),
            vec!["legs[0].axes[4]", "no length"],
        ),
        (
            "U with parallel axes",
            broken(&dir, "u.json", |v| {
                // The U's second axis made parallel to its first, [-2, 0, -1]/√5.
                v["legs"][0]["axes"][1] = serde_json::json!([2.0, 0.0, 1.0]);
            }),
            vec!["legs[0].axes[1]", "U joint", "parallel"],
        ),
        (
            "actuated position out of range",
            broken(&dir, "actuated.json", |v| {
                v["legs"][0]["actuated"] = serde_json::json!([1, 7]);
            }),
            vec![
                "legs[0].actuated",
                "7 is not a joint of UPS (joints 1 to 6)",
            ],
        ),
    ];
    // The file name leads the message, so the user knows which file is at fault.
    for (what, path, needles) in &cases {
        let name = path.file_name().unwrap().to_str().unwrap();
        for command in ["modes", "analyze"] {
            let o = kinsyn(&[command, path.to_str().unwrap()]);
            let mut all: Vec<&str> = needles.clone();
            all.push(name);
            assert_input_error(&o, &format!("{command} {what}"), &all);
        }
    }
}

#[test]
fn the_committed_file_is_accepted_when_rewritten() {
    // The breaking above starts from a file the binary accepts: the same JSON, re-serialised.
    let dir = tempfile::tempdir().unwrap();
    let path = broken(&dir, "same.json", |_| {});
    let o = kinsyn(&["modes", path.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).contains("64 lock subsets"));
}

#[test]
fn bad_poses_locks_and_builds_are_one_line_and_exit_2() {
    // The 3-RPS platform's x translation is parasitic (fixed by z and the two tilts): with no
    // tilt it stays at 0, so a pose 0.3 off to the side cannot be reached.
    let o = kinsyn(&[
        "analyze",
        "mechanisms/3-rps.json",
        "--pose",
        "0.3,0,1,0,0,0",
    ]);
    assert_input_error(
        &o,
        "unreachable pose",
        &["--pose \"0.3,0,1,0,0,0\"", "no assembly reached"],
    );
    let o = kinsyn(&["analyze", "mechanisms/3-rps.json", "--pose", "0,0,1"]);
    assert_input_error(&o, "short pose", &["--pose \"0,0,1\"", "six numbers"]);
    // R1.1 is an input of the 3-UPS, not of the 3-RPS (whose inputs are the prismatic joints).
    let o = kinsyn(&["analyze", "mechanisms/3-rps.json", "--lock", "R1.1"]);
    assert_input_error(
        &o,
        "unknown lock label",
        &["\"R1.1\" is not an actuator of 3-RPS", "P1.2 P2.2 P3.2"],
    );
    let o = kinsyn(&["build", "--legs", "2", "--chain", "U(!,-)P!S"]);
    assert_input_error(&o, "build --legs 2", &["--legs 2", "three to six legs"]);
    // RPS has five primitive joints: no 6-dof catalogue entry gives its axes.
    let o = kinsyn(&["build", "--chain", "RP!S"]);
    assert_input_error(
        &o,
        "build without catalogue axes",
        &["RP!S is not a catalogue chain", "--axes"],
    );
}

/// A missing input file is a mistake in the arguments: exit 2 (docs/limits.md).
#[test]
fn a_missing_file_is_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("missing.json");
    for command in ["modes", "analyze"] {
        let o = kinsyn(&[command, missing.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(2), "{command}: {}", stderr(&o));
        let err = stderr(&o);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.starts_with("kinsyn: error: "), "{err}");
        assert!(err.contains("missing.json"), "{err}");
    }
}

#[test]
fn build_writes_a_file_that_modes_and_analyze_read() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("3-ups.json");
    let o = kinsyn(&[
        "build",
        "--legs",
        "3",
        "--chain",
        "U(!,-)P!S",
        "--name",
        "My 3-UPS",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(
        stdout(&o).contains("My 3-UPS: 3 legs, 6 inputs; mobility 6, platform dof 6"),
        "{}",
        stdout(&o)
    );
    let v: Value = serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    assert_eq!(v["format"], "kinsyn-manipulator/1");
    assert_eq!(v["name"], "My 3-UPS");
    let legs = v["legs"].as_array().unwrap();
    assert_eq!(legs.len(), 3);
    for leg in legs {
        // The '!' marks are written as 1-based positions: α (1) and c (3), paper 000 §5.1.
        assert_eq!(leg["chain"], "UPS");
        assert_eq!(leg["actuated"], serde_json::json!([1, 3]));
        assert_eq!(leg["axes"].as_array().unwrap().len(), 6);
    }
    let o = kinsyn(&["modes", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(
        stdout(&o)
            .starts_with("My 3-UPS: 6 inputs (R1.1 P1.3 R2.1 P2.3 R3.1 P3.3), 64 lock subsets"),
        "{}",
        stdout(&o)
    );
    // Without -o the description goes to stdout.
    let v: Value = serde_json::from_str(&succeed(&["build", "--chain", "U(!,-)P!S"])).unwrap();
    assert_eq!(v["name"], "3-UPS");
}

#[test]
fn review_findings_stay_fixed() {
    // Found in review: each of these once gave a misleading message or a wrong number.
    let dir = tempfile::tempdir().unwrap();
    // A format that is not a string is named as such, not as missing.
    let p = broken(&dir, "format-number.json", |v| v["format"] = Value::from(1));
    assert_input_error(
        &kinsyn(&["analyze", p.to_str().unwrap()]),
        "format 1",
        &["is not a kinsyn manipulator file (\"format\" is 1, expected"],
    );
    // A missing nested field is named by its whole path.
    let p = broken(&dir, "no-position.json", |v| {
        v["platform"].as_object_mut().unwrap().remove("position");
    });
    assert_input_error(
        &kinsyn(&["analyze", p.to_str().unwrap()]),
        "position",
        &["platform: missing field `position`"],
    );
    // An axis of the wrong type says what an axis is.
    let p = broken(&dir, "bad-axis.json", |v| {
        v["legs"][1]["axes"][0] = Value::from("up");
    });
    let o = kinsyn(&["analyze", p.to_str().unwrap()]);
    assert_input_error(&o, "axis 'up'", &["legs[1].axes[0]"]);
    // Coordinates so large that products of lengths overflow are refused, not computed with.
    let p = broken(&dir, "huge.json", |v| {
        v["legs"][0]["base"] = serde_json::json!([1e300, 0.0, 0.0]);
    });
    assert_input_error(
        &kinsyn(&["modes", p.to_str().unwrap()]),
        "1e300",
        &["legs[0].base", "beyond"],
    );
    // build names its own options, not fields of a file the user never wrote.
    assert_input_error(
        &kinsyn(&[
            "build",
            "--chain",
            "UPS",
            "--actuated",
            "3",
            "--axes",
            "xxzxyz",
        ]),
        "U with parallel axes",
        &["--axes \"xxzxyz\"", "the U at joints 1–2"],
    );
    assert_input_error(
        &kinsyn(&["build", "--chain", "UPS", "--actuated", "9"]),
        "--actuated 9",
        &["--actuated: 9"],
    );
    assert_input_error(
        &kinsyn(&["build", "--chain", "U(!,-)P!S", "--actuated", "2"]),
        "marks disagree",
        &["disagrees with the '!' marks"],
    );
    assert_input_error(
        &kinsyn(&[
            "build",
            "--chain",
            "UPS",
            "--actuated",
            "3",
            "--height",
            "-1",
        ]),
        "height",
        &["--height -1"],
    );
    // A platform turned by exactly half a turn about z prints that rotation, and a platform
    // below the base (legs of negative length are still a pose of the sliders) prints no NaN.
    let o = kinsyn(&[
        "analyze",
        "mechanisms/3-rps.json",
        "--pose",
        "0,0,1,0,0,180",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(
        stdout(&o).contains("rotation vector [0.000000, 0.000000, -180.000000] deg")
            || stdout(&o).contains("rotation vector [0.000000, 0.000000, 180.000000] deg"),
        "{}",
        stdout(&o)
    );
    let v: Value = serde_json::from_str(&succeed(&[
        "analyze",
        "mechanisms/3-rps.json",
        "--pose",
        "0,0,-1,0,0,0",
        "--json",
    ]))
    .unwrap();
    let rv = v["platform_rotation_vector_rad"].as_array().unwrap();
    assert!(
        rv.iter()
            .all(|x| x.as_f64().is_some_and(|x| x.abs() < 1e-12)),
        "{rv:?}"
    );
}

/// The committed file `name` of mechanisms/ with `edit` applied, written to a file in `dir`.
fn edited(dir: &tempfile::TempDir, name: &str, edit: impl FnOnce(&mut Value)) -> PathBuf {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(format!("mechanisms/{name}.json"));
    let mut v: Value = serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    edit(&mut v);
    write(dir, &format!("{name}-edited.json"), &v.to_string())
}

#[test]
fn committed_files_analyse_without_leg_warnings() {
    // Every committed file is meant to be generic, so its legs pass the leg check.
    for name in [
        "3-ups",
        "3-rps",
        "6-ups",
        "3-prrr",
        "3-rrr-spherical",
        "3-rrr-planar",
    ] {
        let file = format!("mechanisms/{name}.json");
        let o = kinsyn(&["analyze", &file, "--json"]);
        assert_eq!(o.status.code(), Some(0), "{name}: {}", stderr(&o));
        assert_eq!(stderr(&o), "", "{name}");
        let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
        assert_eq!(v["warnings"], serde_json::json!([]), "{name}");
    }
}

#[test]
fn a_singular_leg_is_warned_on_stderr_and_in_json() {
    // Hand-written files get a leg-rank check. Leg 1 of the planar 3-RRR with its middle joint at
    // the midpoint of its base and platform points: three z revolutes through collinear points,
    // twists (z; p × z) linear in p, rank 2 there and 3 at generic joint values
    // (tests/suite/manipulator.rs derives it). The analysis still runs; stdout is the analysis
    // only, and each warning is one stderr line.
    let dir = tempfile::tempdir().unwrap();
    let path = edited(&dir, "3-rrr-planar", |v| {
        let leg = &mut v["legs"][0];
        let mid: Vec<f64> = (0..3)
            .map(|i| {
                f64::midpoint(
                    leg["base"][i].as_f64().unwrap(),
                    leg["platform"][i].as_f64().unwrap(),
                )
            })
            .collect();
        leg["points"] = serde_json::json!([mid]);
    });
    let file = path.to_str().unwrap();
    let message = "leg 1 (RaRaRa) is singular at the reference configuration: its 3 joint twists have rank 2 there, 3 at generic joint values; joints 1, 2 and 3 dependent";
    for command in ["analyze", "modes"] {
        let o = kinsyn(&[command, file]);
        assert_eq!(o.status.code(), Some(0), "{command}: {}", stderr(&o));
        assert_eq!(
            stderr(&o),
            format!("warning: {file}: {message}\n"),
            "{command}"
        );
        assert!(!stdout(&o).contains("warning"), "{command}: {}", stdout(&o));
    }
    for command in ["analyze", "modes"] {
        let o = kinsyn(&[command, file, "--json"]);
        let v: Value = serde_json::from_str(&stdout(&o)).unwrap();
        assert_eq!(v["warnings"], serde_json::json!([message]), "{command}");
        assert_eq!(stderr(&o), format!("warning: {file}: {message}\n"));
    }
    // A command that fails still prints its error as the only stderr line.
    let o = kinsyn(&["analyze", file, "--lock", "P9.9"]);
    assert_input_error(
        &o,
        "bad lock on a warned file",
        &["\"P9.9\" is not an actuator"],
    );
}

#[test]
fn parallel_marks_that_contradict_the_axes_are_one_line_exit_2() {
    // `RaRaRa` marks three parallel revolutes; an x axis among z axes is refused, naming the field.
    let dir = tempfile::tempdir().unwrap();
    let path = edited(&dir, "3-rrr-planar", |v| {
        v["legs"][2]["axes"][1] = serde_json::json!([1.0, 0.0, 0.0]);
    });
    let o = kinsyn(&["analyze", path.to_str().unwrap()]);
    assert_input_error(
        &o,
        "parallel marks",
        &[
            "legs[2].axes[1]: marked 'a' in RaRaRa like axes[0], so the two must be parallel",
            "90.000° apart",
        ],
    );
    let o = kinsyn(&[
        "build",
        "--chain",
        "RaRaRa",
        "--axes",
        "xyx",
        "--actuated",
        "1",
    ]);
    assert_input_error(
        &o,
        "build parallel marks",
        &["--axes \"xyx\": joints 1 and 2 of RaRaRa are in parallel group 'a' but get 'x' and 'y'"],
    );
}

#[test]
fn build_fails_on_a_leg_that_is_singular_at_the_built_geometry() {
    // The C's revolute and the last R of CRR with axes zzzz both lie on the leg line (z), so joints
    // 2 and 4 have equal twists at the reference (rank 3, 4 at generic joint values), and turning
    // revolutes about z keeps every axis z. Once this wrote a file whose source claimed turned
    // axes; now nothing is written.
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("crr.json");
    let o = kinsyn(&[
        "build",
        "--chain",
        "CRR",
        "--axes",
        "zzzz",
        "--actuated",
        "1",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_input_error(
        &o,
        "CRR zzzz",
        &[
            "leg 1 (CRR) is singular at the reference configuration",
            "rank 3 there, 4 at generic joint values",
            "joints 2 and 4 dependent",
            "leaves these axis directions unchanged, so no file is written",
        ],
    );
    assert!(!out.exists());
    // Four parallel revolutes are dependent at every configuration.
    let o = kinsyn(&[
        "build",
        "--chain",
        "RRRR",
        "--axes",
        "zzzz",
        "--actuated",
        "1",
    ]);
    assert_input_error(
        &o,
        "RRRR zzzz",
        &[
            "has joints dependent at every configuration",
            "rank 3 at generic joint values",
        ],
    );
}

#[test]
fn a_structure_is_called_one() {
    // A 4-leg PPR built with `build`. Hand derivation: each PPR leg (sliders along its leg frame's
    // x and y, revolute along z, the leg's direction) allows the planar motions G of the plane
    // normal to its leg; two planar groups with non-parallel normals share no rotation and only the
    // translations along the line where the planes meet, and three independent normals leave none.
    // Four inclined legs: dof 0 everywhere, one answer from mobility and wrenches, and `analyze`
    // says it is a structure.
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("ppr.json");
    let file = file.to_str().unwrap();
    succeed(&[
        "build",
        "--legs",
        "4",
        "--chain",
        "PPR",
        "--axes",
        "xyz",
        "--actuated",
        "1",
        "-o",
        file,
    ]);
    let out = succeed(&["analyze", file]);
    assert!(
        out.contains("mobility 0 (joint rates closing the loops), platform dof 0"),
        "{out}"
    );
    assert!(out.contains("a structure, not a manipulator"), "{out}");
}

#[test]
fn modes_print_the_parameters_of_the_groups() {
    // A group's parameters in the text output. Hand derivation for the 3-UPS of mechanisms/
    // (platform radius 0.5 at height 1, legs at 0°, 120°, 240°): with legs 2 and 3 fully locked and
    // leg 1's α locked, the platform turns about the line through the S centres
    // G2 = (−0.25, 0.433, 1) and G3 = (−0.25, −0.433, 1), along y; its point nearest the origin is
    // (−0.25, 0, 1). The spherical 3-RRR's axes all pass through (0, 0, 0.5) (its source).
    let out = succeed(&["modes", "mechanisms/3-ups.json"]);
    let dof1 = dof_sections(&out).into_iter().find(|s| s.dof == 1).unwrap();
    assert!(
        dof1.lines.iter().any(|l| l
            == "R(y)     group     1 subset   lock R1.1 R2.1 P2.3 R3.1 P3.3 (axis through [-0.25, 0, 1] m)"),
        "{out}"
    );
    assert!(
        out.lines()
            .any(|l| l.trim()
                == "R(y)     lock R1.1 R2.1 P2.3 R3.1 P3.3 (axis through [-0.25, 0, 1] m)"),
        "{out}"
    );
    let out = succeed(&["modes", "mechanisms/3-rrr-spherical.json"]);
    assert!(
        out.lines()
            .any(|l| l.trim() == "S        lock - (centre [0, 0, 0.5] m)"),
        "{out}"
    );
}

// ---- `kinsyn modes` for analysts (--lock, --max-locks, --pose, limits, compact text) ----

/// `modes ARGS --json` as a JSON value (asserting success).
fn modes_json(args: &[&str]) -> Value {
    let mut all = vec!["modes"];
    all.extend_from_slice(args);
    all.push("--json");
    serde_json::from_str(&succeed(&all)).expect("modes --json is JSON")
}

/// The value of a `key: value` line of `modes --lock`'s detail.
fn detail<'a>(out: &'a str, key: &str) -> &'a str {
    out.lines()
        .find_map(|l| l.strip_prefix(&format!("{key}: ")))
        .unwrap_or_else(|| panic!("no '{key}:' line in {out}"))
}

#[test]
fn modes_lock_of_the_three_alphas_is_the_three_rps_in_detail() {
    // Paper 000 §5.2: locking α in every leg of the 3-UPS gives the 3-RPS, three dof, the
    // non-group 1T2R (as modes_of_the_three_ups_list_64_subsets_and_the_three_rps and
    // tests/suite/manipulator.rs locking_every_alpha_gives_three_dof_1t2r_and_the_constraints_of_eq_22
    // find in the full run).
    let out = succeed(&["modes", "mechanisms/3-ups.json", "--lock", "R1.1,R2.1,R3.1"]);
    assert!(
        out.starts_with(
            "3-UPS: 6 inputs (R1.1 P1.3 R2.1 P2.3 R3.1 P3.3), 1 lock subset (R1.1 R2.1 R3.1);"
        ),
        "{out}"
    );
    assert_eq!(detail(&out, "locked"), "R1.1 R2.1 R3.1");
    assert_eq!(detail(&out, "dof"), "3");
    assert_eq!(detail(&out, "pattern"), "1T2R (not a displacement group)");
    // The evidence behind it: a clear rank gap, and samples far enough apart to tell a group.
    assert!(
        detail(&out, "rank gap").starts_with("smallest kept singular value "),
        "{out}"
    );
    let separation: f64 = detail(&out, "min separation")
        .split_whitespace()
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!(separation >= 1e-3, "{out}");
    // The same subset with the same seed in the full run: the same mode, field by field.
    let one = modes_json(&["mechanisms/3-ups.json", "--lock", "R1.1,R2.1,R3.1"]);
    assert_eq!(one["lock"], "R1.1 R2.1 R3.1");
    assert_eq!(one["max_locks"], Value::Null);
    assert_eq!(one["modes"].as_array().unwrap().len(), 1);
    let all = modes_json(&["mechanisms/3-ups.json"]);
    let same = all["modes"]
        .as_array()
        .unwrap()
        .iter()
        .find(|m| m["lock_text"] == "R1.1 R2.1 R3.1")
        .unwrap();
    assert_eq!(&one["modes"][0], same);
    // A group in detail: with legs 2 and 3 locked and leg 1's α, R(y) about the line through
    // the S centres of legs 2 and 3 (modes_print_the_parameters_of_the_groups).
    let out = succeed(&[
        "modes",
        "mechanisms/3-ups.json",
        "--lock",
        "R1.1,R2.1,P2.3,R3.1,P3.3",
    ]);
    assert_eq!(detail(&out, "dof"), "1");
    assert_eq!(
        detail(&out, "pattern"),
        "R(y) (one of the 12 displacement groups; axis through [-0.25, 0, 1] m)"
    );
}

#[test]
fn modes_max_locks_1_agrees_with_the_full_run_subset_by_subset() {
    // Σ_{k≤1} C(n, k) = 1 + n subsets; each subset's walks are seeded from the subset alone, so
    // the short run must give exactly the full run's mode for each of them.
    for (file, n) in [("mechanisms/3-ups.json", 6), ("mechanisms/3-prrr.json", 3)] {
        let short = modes_json(&[file, "--max-locks", "1"]);
        assert_eq!(short["max_locks"], 1, "{file}");
        let modes = short["modes"].as_array().unwrap();
        assert_eq!(modes.len(), 1 + n, "{file}");
        let full = modes_json(&[file]);
        let full_modes = full["modes"].as_array().unwrap();
        assert_eq!(full_modes.len(), 1 << n, "{file}");
        for m in modes {
            assert!(m["locked"].as_array().unwrap().len() <= 1, "{file}: {m}");
            let same = full_modes
                .iter()
                .find(|f| f["lock_text"] == m["lock_text"])
                .unwrap();
            assert_eq!(m, same, "{file}");
        }
        // The text says how many subsets and how they were chosen.
        let out = succeed(&["modes", file, "--max-locks", "1"]);
        assert!(
            out.lines()
                .next()
                .unwrap()
                .contains(&format!(", {} lock subsets with at most 1 locked;", 1 + n)),
            "{out}"
        );
    }
}

#[test]
fn modes_at_a_displaced_pose_hold_the_locks_there() {
    // The 6-UPS at the displaced pose of analyze_at_a_pose_and_with_locks: the platform frame
    // at (0.1, 0.05, 1.1) m turned by (5°, −3°, 10°). Locking all six legs there leaves nothing
    // (dof 0, E); locking none leaves the whole of D (dof 6): a Gough–Stewart platform away
    // from singularities.
    let pose = "0.1,0.05,1.1,5,-3,10";
    let file = "mechanisms/6-ups.json";
    let all = modes_json(&[
        file,
        "--pose",
        pose,
        "--lock",
        "P1.3,P2.3,P3.3,P4.3,P5.3,P6.3",
    ]);
    assert_eq!(all["pose"], pose);
    for (got, want) in all["start_position"]
        .as_array()
        .unwrap()
        .iter()
        .zip([0.1, 0.05, 1.1])
    {
        assert!((got.as_f64().unwrap() - want).abs() < 1e-9, "{all}");
    }
    for (got, want) in all["start_rotation_vector_rad"]
        .as_array()
        .unwrap()
        .iter()
        .zip([5.0_f64, -3.0, 10.0])
    {
        assert!(
            (got.as_f64().unwrap() - want.to_radians()).abs() < 1e-9,
            "{all}"
        );
    }
    assert_eq!(all["modes"][0]["dof"], 0);
    assert_eq!(all["modes"][0]["pattern"], "E");
    let none = modes_json(&[file, "--pose", pose, "--lock", "-"]);
    assert_eq!(none["modes"][0]["dof"], 6);
    assert_eq!(none["modes"][0]["pattern"], "D");
    // The same start configuration in both runs (assembled with every input free).
    assert_eq!(all["start_joint_values"], none["start_joint_values"]);

    // The 3-UPS raised to z = 1.1 m without turning: every leg stays in its radial plane, so the
    // α (R_i.1) keep their reference values and `analyze --pose --lock`, which holds the locked
    // inputs at their reference values, reaches the same configuration. Its platform dof (six
    // minus the rank of the constraint wrenches) must be the dof of the motion `modes` samples
    // with the locks held there (loop closure: a second method).
    let pose = "0,0,1.1,0,0,0";
    let file = "mechanisms/3-ups.json";
    for (lock, pattern) in [
        ("-", "D"),
        ("R1.1", "2T3R"),
        ("R1.1,R2.1", "1T3R"),
        ("R1.1,R2.1,R3.1", "1T2R"),
    ] {
        let modes = modes_json(&[file, "--pose", pose, "--lock", lock]);
        let analysis: Value = serde_json::from_str(&succeed(&[
            "analyze", file, "--pose", pose, "--lock", lock, "--json",
        ]))
        .unwrap();
        let q_modes = modes["start_joint_values"].as_array().unwrap();
        let q_analyze = analysis["joint_values"].as_array().unwrap();
        assert_eq!(q_modes.len(), q_analyze.len());
        for (a, b) in q_modes.iter().zip(q_analyze) {
            assert!(
                (a.as_f64().unwrap() - b.as_f64().unwrap()).abs() < 1e-9,
                "{lock}: {q_modes:?} vs {q_analyze:?}"
            );
        }
        let mode = &modes["modes"][0];
        assert_eq!(mode["dof"], analysis["platform_dof"], "{lock}");
        assert_eq!(mode["pattern"], pattern, "{lock}");
    }
}

#[test]
fn modes_limits_are_one_line_and_exit_2() {
    // 64 subsets of the 3-UPS against a limit of 10: refused before any sampling, naming the
    // ways out (--max-locks 1 gives 1 + 6 = 7 subsets, within 10).
    let o = kinsyn(&["modes", "mechanisms/3-ups.json", "--max-subsets", "10"]);
    assert_input_error(
        &o,
        "more subsets than --max-subsets",
        &[
            "mechanisms/3-ups.json: 6 inputs give 64 lock subsets (all 2^6), more than --max-subsets 10",
            "--max-locks 1 (7 subsets)",
            "--lock SET",
        ],
    );
    let o = kinsyn(&[
        "modes",
        "mechanisms/3-ups.json",
        "--max-locks",
        "2",
        "--max-subsets",
        "21",
    ]);
    assert_input_error(
        &o,
        "--max-locks over the limit",
        &["22 lock subsets with at most 2 locked", "--max-locks 1"],
    );
    // Eighteen inputs (every joint of a UPS leg but the S, six legs): 2^18 = 262144 subsets
    // against the default 4096; Σ_{k≤4} C(18, k) = 1 + 18 + 153 + 816 + 3060 = 4048 fit.
    let dir = tempfile::tempdir().unwrap();
    let file = eighteen_inputs(&dir);
    let file = file.to_str().unwrap();
    let o = kinsyn(&["modes", file]);
    assert_input_error(
        &o,
        "2^18 subsets",
        &[
            "18 inputs give 262144 lock subsets (all 2^18), more than --max-subsets 4096",
            "--max-locks 4 (4048 subsets)",
        ],
    );
    for (args, needles) in [
        (vec!["--samples", "65"], vec!["'65'", "--samples", "2..=64"]),
        (vec!["--max-subsets", "65537"], vec!["'65537'", "1..=65536"]),
        (vec!["--max-subsets", "0"], vec!["'0'", "--max-subsets"]),
        (
            vec!["--lock", "R1.1", "--max-locks", "1"],
            vec!["--lock", "cannot be used with", "--max-locks"],
        ),
        (
            vec!["--lock", "P9.9"],
            vec!["--lock \"P9.9\"", "\"P9.9\" is not an actuator of 3-UPS"],
        ),
        (
            vec!["--pose", "0,0,1"],
            vec!["--pose \"0,0,1\"", "six numbers"],
        ),
    ] {
        let mut all = vec!["modes", "mechanisms/3-ups.json"];
        all.extend(args.iter().copied());
        assert_input_error(&kinsyn(&all), &format!("{args:?}"), &needles);
    }
}

#[test]
fn modes_text_is_bounded_whatever_the_number_of_subsets() {
    // The compact text has a header (2 lines), at most seven dof sections (dof 6 to 0: a blank,
    // a heading, at most 12 pattern lines and one "… more" line), one line for the subsets that
    // could not be sampled (and its blank), and the summary (blank, heading, at most 12 + 1
    // group lines, the non-group heading and at most 12 + 1 lines): at most
    // 2 + 7 · 15 + 2 + 2 + 13 + 1 + 13 = 138 lines, however many subsets. Each pattern line shows
    // at most six lock sets and says how many more --json lists.
    const BOUND: usize = 138;
    let dir = tempfile::tempdir().unwrap();
    let file = eighteen_inputs(&dir);
    let file = file.to_str().unwrap();
    // 1 + 18 + 153 = 172 subsets.
    let out = succeed(&["modes", file, "--max-locks", "2"]);
    assert!(
        out.contains(", 172 lock subsets with at most 2 locked;"),
        "{out}"
    );
    let lines = out.lines().count();
    assert!(lines <= BOUND, "{lines} lines: {out}");
    let v = modes_json(&[file, "--max-locks", "2"]);
    assert_eq!(v["modes"].as_array().unwrap().len(), 172);
    // Every pattern line against --json: its subset count, and its lock sets shown or counted.
    let sections = dof_sections(&out);
    let patterns: Vec<&Value> = v["groups"]
        .as_array()
        .unwrap()
        .iter()
        .chain(v["non_groups"].as_array().unwrap())
        .collect();
    for s in &sections {
        for line in &s.lines {
            if line.starts_with('…') {
                continue;
            }
            let w = words(line);
            let shown: Vec<&str> = line
                .split(" lock ")
                .nth(1)
                .unwrap()
                .split(" … ")
                .next()
                .unwrap()
                .split(" (")
                .next()
                .unwrap()
                .split(" | ")
                .collect();
            let p = patterns
                .iter()
                .find(|p| {
                    p["pattern"] == w[0] && p["dof"] == s.dof && p["lock_sets"][0] == shown[0]
                })
                .unwrap_or_else(|| panic!("{line}"));
            let sets = p["lock_sets"].as_array().unwrap().len();
            assert_eq!(shown.len(), sets.min(6), "{line}");
            if sets > 6 {
                assert!(
                    line.contains(&format!(" … and {} more (see --json)", sets - 6)),
                    "{line}"
                );
            }
            assert!(w.contains(&p["subsets"].to_string().as_str()), "{line}");
        }
    }
    // The sections account for every subset.
    assert_eq!(sections.iter().map(|s| s.subsets).sum::<usize>(), 172);
}
