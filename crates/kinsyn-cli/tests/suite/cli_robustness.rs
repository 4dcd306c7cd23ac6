//! The command line survives anything: a table of bad inputs, each of which must exit with code 2
//! and print exactly one line on stderr, and a regression test for each defect found and
//! reproduced (docs/limits.md lists the limits and error classes).

use crate::common;

use common::{assert_refused, kinsyn, stderr, stdout};
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

fn write(dir: &Path, name: &str, bytes: &[u8]) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, bytes).unwrap();
    path
}

/// The 3-UPS description with `edit` applied to its JSON.
fn edited(dir: &Path, name: &str, edit: impl FnOnce(&mut serde_json::Value)) -> PathBuf {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../mechanisms/3-ups.json"
    ))
    .unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    edit(&mut v);
    write(dir, name, serde_json::to_string(&v).unwrap().as_bytes())
}

/// More than fifty bad inputs across every command: each is refused with exit 2 and one line.
#[test]
#[expect(
    clippy::too_many_lines,
    reason = "one list of cases (arguments and the text the refusal must name), one per line"
)]
fn every_bad_input_is_one_line_and_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let s = |p: PathBuf| p.to_str().unwrap().to_string();
    let not_utf8 = s(write(d, "latin1.json", b"{\"format\": \"caf\xe9\"}"));
    let empty = s(write(d, "empty.json", b""));
    let array = s(write(d, "array.json", b"[1, 2, 3]"));
    let truncated = s(write(d, "truncated.json", b"{\"format\": \"kinsyn-manip"));
    let big = s(write(d, "big.json", &vec![b' '; (1 << 20) + 1]));
    let no_legs = s(edited(d, "nolegs.json", |v| {
        v["legs"] = serde_json::json!([]);
    }));
    let thirteen_legs = s(edited(d, "13legs.json", |v| {
        let leg = v["legs"][0].clone();
        v["legs"] = serde_json::Value::Array(vec![leg; 13]);
    }));
    let long_leg = s(edited(d, "longleg.json", |v| {
        v["legs"][0]["chain"] = "RRRRRRRRRRRRR".into();
    }));
    let four_coordinates = s(edited(d, "p4.json", |v| {
        v["legs"][0]["base"] = serde_json::json!([1, 0, 0, 5]);
    }));
    let huge_coordinate = s(edited(d, "huge.json", |v| {
        v["platform"]["position"] = serde_json::json!([0, 0, 1e300]);
    }));
    let bad_chain = s(edited(d, "badchain.json", |v| {
        v["legs"][1]["chain"] = "UP\u{1b}[31mS".into();
    }));
    let unknown_field = s(edited(d, "field.json", |v| v["colour"] = "red".into()));
    let ups = "mechanisms/3-ups.json".to_string();
    let bin = env!("CARGO_BIN_EXE_kinsyn").to_string();
    let o = |v: &[&str]| v.iter().map(|x| (*x).to_string()).collect::<Vec<String>>();
    let cases: Vec<(Vec<String>, &str)> = vec![
        // Missing or unknown arguments and subcommands.
        (o(&[]), "needs a subcommand: catalogue, query"),
        (o(&["catalogue"]), "needs a subcommand: generate, summary"),
        (o(&["frobnicate"]), "frobnicate"),
        (o(&["analyze"]), "<FILE>"),
        (o(&["modes"]), "<FILE>"),
        (o(&["notation"]), "<CHAIN>"),
        (o(&["query"]), "--pattern"),
        (o(&["build"]), "--chain"),
        (o(&["analyze", &ups, "--colour"]), "--colour"),
        (o(&["catalogue", "show"]), "<QUERY>"),
        // Chain strings.
        (o(&["notation", "PX\nR"]), "\"PX\\nR\""),
        (o(&["notation", "P\u{1b}[31mR"]), "\\u{1b}"),
        (o(&["notation", "PR\u{202e}S"]), "\\u{202e}"),
        (o(&["notation", ""]), ""),
        (o(&["notation", "U(a,-"]), ""),
        (o(&["notation", "RaRb"]), "group"),
        (o(&["notation", "!!!"]), ""),
        (o(&["notation", "U(-,-,-)"]), "slot"),
        (o(&["catalogue", "show", "T9-999"]), "no entry with id"),
        (o(&["catalogue", "show", "PPPPPP"]), "not in the catalogue"),
        (
            o(&["catalogue", "show", "T1-001", "--lock", "9"]),
            "not a joint",
        ),
        (
            o(&["catalogue", "show", "T1-001", "--lock", "11"]),
            "named twice",
        ),
        (o(&["catalogue", "list", "--family", "XYZ\n"]), "\"XYZ\\n\""),
        (
            o(&["catalogue", "list", "--table", "5"]),
            "no Appendix table 5",
        ),
        (
            o(&["catalogue", "summary", "--prismatics", "sideways"]),
            "sideways",
        ),
        // Patterns.
        (o(&["query", "--pattern", "Q"]), "not a motion pattern"),
        (o(&["query", "--pattern", "X(w)"]), "direction"),
        (o(&["query", "--pattern", "G(xz"]), "unclosed"),
        (o(&["query", "--pattern", "S(x)"]), "takes no direction"),
        (o(&["query", "--pattern", "4T1R"]), "at most 3"),
        (
            o(&["query", "--pattern", "T3", "--max-locks", "7"]),
            "six joints",
        ),
        (o(&["query", "--pattern", "T3", "--max-locks", "-1"]), "-1"),
        // Files that are not what they claim.
        (o(&["analyze", &not_utf8]), "not UTF-8"),
        (o(&["analyze", &bin]), "is not a kinsyn manipulator file"),
        (o(&["modes", "/dev/zero"]), "not a regular file"),
        (o(&["analyze", "/"]), "a directory"),
        (o(&["analyze", &empty]), "not JSON"),
        (o(&["analyze", &array]), "not an object"),
        (o(&["analyze", &truncated]), "not JSON"),
        (o(&["analyze", &big]), "at most 1048576 bytes"),
        (o(&["analyze", "no/such/file.json"]), "no/such/file.json"),
        // Descriptions with a faulty field, and the limits.
        (o(&["analyze", &no_legs]), "no leg"),
        (o(&["analyze", &thirteen_legs]), "13 legs: at most 12"),
        (o(&["analyze", &long_leg]), "a leg has at most 6"),
        (o(&["analyze", &four_coordinates]), "expected 3 coordinates"),
        (o(&["analyze", &huge_coordinate]), "platform.position"),
        (o(&["modes", &bad_chain]), "\\u{1b}"),
        (o(&["analyze", &unknown_field]), "colour"),
        // Poses, inputs and locks.
        (o(&["analyze", &ups, "--pose", "0,0,1"]), "six numbers"),
        (
            o(&["analyze", &ups, "--pose", "0,0,1,0,0,nan"]),
            "not a finite number",
        ),
        (o(&["analyze", &ups, "--pose", "w=1"]), "not a coordinate"),
        (o(&["analyze", &ups, "--pose", "z=1,z=2"]), "given twice"),
        (o(&["analyze", &ups, "--pose", "z=5"]), "degrees of freedom"),
        (
            o(&[
                "analyze",
                "mechanisms/3-rrr-planar.json",
                "--pose",
                "5,0,0,0,0,0",
            ]),
            "no assembly reached",
        ),
        (o(&["analyze", &ups, "--lock", "P1.2\n"]), "\"P1.2\\n\""),
        (o(&["analyze", &ups, "--lock", "R9.1"]), "not an actuator"),
        (o(&["analyze", &ups, "--inputs", "P1.3"]), "LABEL=VALUE"),
        (
            o(&["analyze", &ups, "--inputs", "P1.3=x"]),
            "not a finite number",
        ),
        (
            o(&["analyze", &ups, "--inputs", "P1.3=1,P1.3=2"]),
            "given twice",
        ),
        (
            o(&["analyze", &ups, "--inputs", "P1.3=50"]),
            "no assembly reached",
        ),
        (o(&["analyze", &ups, "--from", "1,2"]), "--from"),
        // Build.
        (
            o(&["build", "--chain", "UPS", "--platform-radius", "1e300"]),
            "--platform-radius",
        ),
        (o(&["build", "--chain", "UPS", "--height", "0"]), "positive"),
        (
            o(&["build", "--chain", "UPS", "--legs", "9"]),
            "three to six",
        ),
        (o(&["build", "--chain", "RP!S"]), "--axes"),
        (
            o(&["build", "--chain", "RP!S", "--axes", "xy\u{1b}"]),
            "\\u{1b}",
        ),
        (
            o(&["build", "--chain", "U(!,-)P!S", "--twist", "1e9"]),
            "--twist",
        ),
    ];
    assert!(cases.len() >= 50, "{} cases", cases.len());
    for (args, needle) in &cases {
        let refs: Vec<&str> = args.iter().map(String::as_str).collect();
        let out = kinsyn(&refs);
        assert_refused(&out, &format!("{args:?}"), &[needle]);
    }
}

/// `kinsyn catalogue list --json | head -c 10`: the reader goes away; kinsyn ends quietly
/// with exit 0 and no panic message (was exit 101, "failed printing to stdout").
#[test]
fn a_closed_pipe_ends_quietly() {
    for args in [
        &["catalogue", "list", "--json"][..],
        &["modes", "mechanisms/3-ups.json", "--json"][..],
    ] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_kinsyn"))
            .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
            .args(args)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let mut head = [0u8; 10];
        child.stdout.take().unwrap().read_exact(&mut head).unwrap();
        // The read end is dropped here: the rest of the output goes nowhere.
        let out = child.wait_with_output().unwrap();
        assert_eq!(out.status.code(), Some(0), "{args:?}: {}", stderr(&out));
        assert!(stderr(&out).is_empty(), "{args:?}: {}", stderr(&out));
    }
}

/// A non-UTF-8 argument is refused by the argument parser in one line.
#[test]
fn a_non_utf8_argument_is_one_line() {
    use std::os::unix::ffi::OsStrExt;
    let out = Command::new(env!("CARGO_BIN_EXE_kinsyn"))
        .arg("notation")
        .arg(std::ffi::OsStr::from_bytes(b"P\xffR"))
        .output()
        .unwrap();
    assert_refused(&out, "non-UTF-8 chain", &["UTF-8"]);
}

/// Pattern names nTmR that every motion with those numbers has as a group find that group
/// (were 0 hits); the others name the groups they leave out.
#[test]
fn group_names_written_as_ntmr_match_their_group() {
    let count = |pattern: &str| {
        let out = kinsyn(&["query", "--pattern", pattern]);
        assert!(out.status.success(), "{pattern}: {}", stderr(&out));
        stdout(&out)
            .lines()
            .last()
            .and_then(|l| l.split_whitespace().next())
            .and_then(|n| n.parse::<usize>().ok())
            .unwrap()
    };
    for (name, group) in [("3T3R", "D"), ("3T0R", "T3"), ("0T0R", "E")] {
        assert_eq!(count(name), count(group), "{name} vs {group}");
        assert!(count(name) > 0, "{name}");
    }
    let note = stdout(&kinsyn(&["query", "--pattern", "2T1R"]));
    assert!(note.contains("the groups of this type are G, Y"), "{note}");
}

/// `build --chain RRS --legs 6 --actuated 3,5 --axes xzyxz --twist 0` wrote a file that analyze
/// rejected and on which modes printed `?`: the built pose is a singular configuration of a
/// mechanism that is a structure elsewhere, where undamped Newton steps wandered off.
#[test]
fn a_file_build_writes_always_analyses() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("rrs.json");
    let f = file.to_str().unwrap();
    let out = kinsyn(&[
        "build",
        "--chain",
        "RRS",
        "--legs",
        "6",
        "--actuated",
        "3,5",
        "--axes",
        "xzyxz",
        "--twist",
        "0",
        "-o",
        f,
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let out = kinsyn(&["analyze", f]);
    assert!(out.status.success(), "{}", stderr(&out));
    // Its motion with no input locked, and with one, is sampled and classified.
    let m = kinsyn::manipulator::Manipulator::from_json(&std::fs::read_to_string(&file).unwrap())
        .unwrap();
    let settings = kinsyn::mechanism::SampleSettings::default();
    for locked in [vec![], vec![0], vec![1]] {
        let mode = m.mode(&locked, &settings);
        assert!(mode.error.is_none(), "{locked:?}: {:?}", mode.error);
        assert_ne!(mode.pattern_text(), "?", "{locked:?}");
    }
}

/// `--help` answers on stdout with exit 0, and `--version` ends with a newline.
#[test]
fn help_and_version_are_results() {
    let out = kinsyn(&["--version"]);
    assert_eq!(out.status.code(), Some(0));
    assert!(stdout(&out).ends_with('\n'), "{:?}", stdout(&out));
    let out = kinsyn(&["analyze", "--help"]);
    assert_eq!(out.status.code(), Some(0));
    assert!(stdout(&out).contains("--inputs"), "{}", stdout(&out));
}

/// `analyze --inputs` (forward kinematics) on the 6-UPS: from a displaced start (`--from`), the
/// reference's own leg lengths (all input values 0) bring the platform back to the file's
/// reference pose; and the input values printed at a pose lead back to that pose from the
/// reference (tests/suite/position.rs checks them against the closed-form leg lengths).
#[test]
fn analyze_inputs_is_forward_kinematics() {
    let json = |args: &[&str]| -> serde_json::Value {
        let out = kinsyn(args);
        assert!(out.status.success(), "{args:?}: {}", stderr(&out));
        serde_json::from_str(&stdout(&out)).unwrap()
    };
    let zeros = "P1.3=0,P2.3=0,P3.3=0,P4.3=0,P5.3=0,P6.3=0";
    let home = json(&[
        "analyze",
        "mechanisms/6-ups.json",
        "--from",
        "0.05,0,1.1,0,5,10",
        "--inputs",
        zeros,
        "--json",
    ]);
    let p = &home["platform_position"];
    for (k, expected) in [0.0, 0.0, 1.0].iter().enumerate() {
        assert!((p[k].as_f64().unwrap() - expected).abs() < 1e-9, "{p}");
    }
    let displaced = json(&[
        "analyze",
        "mechanisms/6-ups.json",
        "--pose",
        "0.05,0,1.1,0,5,10",
        "--json",
    ]);
    let inputs: Vec<String> = displaced["input_values"]
        .as_object()
        .unwrap()
        .iter()
        .map(|(label, v)| format!("{label}={:.15}", v.as_f64().unwrap()))
        .collect();
    let reached = json(&[
        "analyze",
        "mechanisms/6-ups.json",
        "--inputs",
        &inputs.join(","),
        "--json",
    ]);
    for k in 0..3 {
        let a = reached["platform_position"][k].as_f64().unwrap();
        let b = displaced["platform_position"][k].as_f64().unwrap();
        assert!((a - b).abs() < 1e-9, "{a} vs {b}");
        let a = reached["platform_rotation_vector_rad"][k].as_f64().unwrap();
        let b = displaced["platform_rotation_vector_rad"][k]
            .as_f64()
            .unwrap();
        assert!((a - b).abs() < 1e-9, "{a} vs {b}");
    }
    assert!(reached["continuation_steps"].as_u64().unwrap() >= 1);
}

/// `analyze --pose z=…,rx=…,ry=…` on the 3-RPS solves its parasitic motion: the given
/// coordinates are kept and the torsion is zero (tests/suite/position.rs checks the leg planes).
#[test]
fn analyze_a_partial_pose_of_the_three_rps() {
    let out = kinsyn(&[
        "analyze",
        "mechanisms/3-rps.json",
        "--pose",
        "z=1.1,rx=5,ry=-3",
        "--json",
    ]);
    assert!(out.status.success(), "{}", stderr(&out));
    let v: serde_json::Value = serde_json::from_str(&stdout(&out)).unwrap();
    let r = &v["platform_rotation_vector_rad"];
    assert!((v["platform_position"][2].as_f64().unwrap() - 1.1).abs() < 1e-9);
    assert!(
        (r[0].as_f64().unwrap() - 5f64.to_radians()).abs() < 1e-9,
        "{r}"
    );
    assert!(
        (r[1].as_f64().unwrap() + 3f64.to_radians()).abs() < 1e-9,
        "{r}"
    );
    assert!(r[2].as_f64().unwrap().abs() < 1e-9, "{r}");
    assert_eq!(v["platform_dof"], 3);
}
