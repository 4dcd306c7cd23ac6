//! Every file kinsyn writes (docs/limits.md, "Output files"): written whole or not at all, a
//! full disk leaving the old file or none; an existing file refused unless `--force`, checked
//! for every file before any is written; a symbolic link replaced, never written through; a
//! path that is the wrong kind or whose parent is missing refused with exit 2; a folder that
//! cannot be written named with exit 1. Each command that writes is run through each case.

use crate::common;

use common::{assert_refused, kinsyn, stderr, stdout};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const HEXA: &str = "mechanisms/6-ruu-hexa.json";
const SMALL: [&str; 4] = ["--chains", "T1-001,T1-002", "--actuated", "1"];

/// What a command writes: one file named by its option, or files in a folder named by `--out`.
#[derive(Clone, Copy)]
enum Target {
    /// A file (`-o`, `--mjcf`).
    File,
    /// A folder, and one of the files the command writes in it.
    Folder(&'static str),
}

/// A command that writes, its arguments with `OUT` for the output path.
struct Case {
    name: &'static str,
    args: Vec<String>,
    target: Target,
}

impl Case {
    /// The arguments with `out` in place of `OUT`, and `extra` after them.
    fn args(&self, out: &Path, extra: &[&str]) -> Vec<String> {
        self.args
            .iter()
            .map(|a| {
                if a == "OUT" {
                    out.to_str().unwrap().to_string()
                } else {
                    a.clone()
                }
            })
            .chain(extra.iter().map(|s| (*s).to_string()))
            .collect()
    }

    /// The file whose content the tests follow: the output file, or the named one of the folder.
    fn probe(&self, out: &Path) -> PathBuf {
        match self.target {
            Target::File => out.to_path_buf(),
            Target::Folder(name) => out.join(name),
        }
    }

    fn run(&self, out: &Path, extra: &[&str]) -> Output {
        let args = self.args(out, extra);
        kinsyn(&args.iter().map(String::as_str).collect::<Vec<_>>())
    }

    /// Runs under a file-size limit of one block (`ulimit -f 1`: 512 bytes in a POSIX shell),
    /// which every output here exceeds.
    fn run_limited(&self, out: &Path, extra: &[&str]) -> Output {
        Command::new("sh")
            .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
            .arg("-c")
            .arg("ulimit -f 1; exec \"$0\" \"$@\"")
            .arg(env!("CARGO_BIN_EXE_kinsyn"))
            .args(self.args(out, extra))
            .output()
            .expect("run kinsyn under ulimit")
    }
}

/// Sweep directories the cases read: two complete shards of the small sweep.
struct Fixtures {
    _dir: tempfile::TempDir,
    shards: [PathBuf; 2],
}

fn fixtures() -> Fixtures {
    let dir = tempfile::tempdir().unwrap();
    let shards = [1, 2].map(|k| {
        let d = dir.path().join(format!("shard{k}"));
        let shard = format!("{k}/2");
        let args = [
            &["sweep", "--out", d.to_str().unwrap()][..],
            &SMALL,
            &["--shard", &shard],
        ]
        .concat();
        let o = kinsyn(&args);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
        d
    });
    Fixtures { _dir: dir, shards }
}

/// Every command that writes a file or folder.
fn cases(f: &Fixtures) -> Vec<Case> {
    let v = |args: &[&str]| args.iter().map(|s| (*s).to_string()).collect::<Vec<_>>();
    let shard = |k: usize| f.shards[k].to_str().unwrap();
    vec![
        Case {
            name: "build -o",
            args: v(&["build", "--legs", "3", "--chain", "U(!,-)P!S", "-o", "OUT"]),
            target: Target::File,
        },
        Case {
            name: "stack -o",
            args: v(&[
                "stack",
                "--modules",
                "RPS,SPR",
                "--radii",
                "2,1,2",
                "--heights=-1.5,-1.6",
                "-o",
                "OUT",
            ]),
            target: Target::File,
        },
        Case {
            name: "export --mjcf",
            args: v(&["export", "mechanisms/3-ups.json", "--mjcf", "OUT"]),
            target: Target::File,
        },
        Case {
            name: "view --out",
            args: v(&[
                "view",
                "mechanisms/3-rrr-planar.json",
                "--steps",
                "1",
                "--no-assemblies",
                "--out",
                "OUT",
            ]),
            target: Target::File,
        },
        Case {
            name: "catalogue generate",
            args: v(&["catalogue", "generate", "--out", "OUT"]),
            target: Target::Folder("chains.json"),
        },
        Case {
            name: "catalogue site",
            args: v(&["catalogue", "site", "--out", "OUT"]),
            target: Target::Folder("index.html"),
        },
        Case {
            name: "plot inverse",
            args: v(&["plot", "inverse", "--out", "OUT"]),
            target: Target::Folder("inverse-configurations.svg"),
        },
        Case {
            name: "plot trajectory",
            args: v(&["plot", "trajectory", "--steps", "50", "--out", "OUT"]),
            target: Target::Folder("trajectory-velocities.svg"),
        },
        Case {
            name: "plot workspace",
            args: v(&["plot", "workspace", HEXA, "--step", "40", "--out", "OUT"]),
            target: Target::Folder("hexa-four-bar.png"),
        },
        Case {
            name: "plot indices",
            args: v(&[
                "plot",
                "indices",
                HEXA,
                "--step",
                "40",
                "--workspace-step",
                "40",
                "--out",
                "OUT",
            ]),
            target: Target::Folder("hexa-indices.svg"),
        },
        Case {
            name: "sweep report",
            args: v(&["sweep", "report", shard(0), "--out", "OUT"]),
            target: Target::Folder("report.md"),
        },
        Case {
            name: "sweep",
            args: v(&[&["sweep", "--out", "OUT"][..], &SMALL].concat()),
            target: Target::Folder("designs.jsonl"),
        },
        Case {
            name: "sweep merge",
            args: v(&["sweep", "merge", shard(0), shard(1), "--out", "OUT"]),
            target: Target::Folder("designs.parquet"),
        },
    ]
}

/// The files under `dir` (relative paths) with their bytes; none for a missing folder.
fn tree(dir: &Path) -> BTreeMap<PathBuf, Vec<u8>> {
    let mut files = BTreeMap::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&d) else {
            continue;
        };
        for e in entries {
            let path = e.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else {
                let bytes = std::fs::read(&path).unwrap();
                files.insert(path.strip_prefix(dir).unwrap().to_path_buf(), bytes);
            }
        }
    }
    files
}

/// Asserts an environment failure: exit 1, nothing on stdout, one stderr line starting with
/// `kinsyn: error:` that contains every needle.
fn assert_environment_failure(o: &Output, what: &str, needles: &[&str]) {
    let err = stderr(o);
    assert_eq!(o.status.code(), Some(1), "{what}: {err}");
    assert!(stdout(o).is_empty(), "{what}: stdout {}", stdout(o));
    assert_eq!(err.lines().count(), 1, "{what}: {err:?}");
    assert!(err.starts_with("kinsyn: error: "), "{what}: {err}");
    for needle in needles {
        assert!(err.contains(needle), "{what}: {needle:?} not in {err}");
    }
    assert!(
        !err.contains(".tmp\""),
        "{what}: a temporary file named: {err}"
    );
}

fn succeeds(o: &Output, what: &str) {
    assert_eq!(o.status.code(), Some(0), "{what}: {}", stderr(o));
}

/// A second run refuses to replace what the first wrote, naming the file and `--force`, and
/// writes nothing (every file is checked before the first is written); `--force` replaces it
/// with the same bytes a fresh run writes.
#[test]
fn an_existing_output_is_refused_unless_force() {
    let f = fixtures();
    let dir = tempfile::tempdir().unwrap();
    for (i, case) in cases(&f).iter().enumerate() {
        let out = dir.path().join(format!("case{i}"));
        let probe = case.probe(&out);
        succeeds(&case.run(&out, &[]), case.name);
        let fresh = std::fs::read(&probe).unwrap();
        // Only the probe is left, with other bytes: a refused run must add no file.
        if let Target::Folder(_) = case.target {
            std::fs::remove_dir_all(&out).unwrap();
            std::fs::create_dir(&out).unwrap();
        }
        std::fs::write(&probe, b"old").unwrap();
        let o = case.run(&out, &[]);
        assert_refused(
            &o,
            case.name,
            &[probe.to_str().unwrap(), "exists", "--force"],
        );
        assert_eq!(std::fs::read(&probe).unwrap(), b"old", "{}", case.name);
        if let Target::Folder(name) = case.target {
            let left: Vec<PathBuf> = tree(&out).into_keys().collect();
            assert_eq!(
                left,
                [PathBuf::from(name)],
                "{}: a refused run wrote",
                case.name
            );
        }
        succeeds(&case.run(&out, &["--force"]), case.name);
        assert!(
            std::fs::read(&probe).unwrap() == fresh,
            "{}: --force did not write what a fresh run writes",
            case.name
        );
    }
}

/// A symbolic link where kinsyn writes is refused like a file, and with `--force` replaced by
/// the new file: the file it points to is never written.
#[cfg(unix)]
#[test]
fn a_symbolic_link_is_replaced_never_written_through() {
    let f = fixtures();
    let dir = tempfile::tempdir().unwrap();
    for (i, case) in cases(&f).iter().enumerate() {
        if !matches!(
            case.name,
            "build -o" | "export --mjcf" | "plot inverse" | "sweep merge"
        ) {
            continue;
        }
        let out = dir.path().join(format!("case{i}"));
        let probe = case.probe(&out);
        if let Target::Folder(_) = case.target {
            std::fs::create_dir(&out).unwrap();
        }
        let victim = dir.path().join(format!("victim{i}"));
        std::fs::write(&victim, b"keep").unwrap();
        std::os::unix::fs::symlink(&victim, &probe).unwrap();
        assert_refused(
            &case.run(&out, &[]),
            case.name,
            &[probe.to_str().unwrap(), "--force"],
        );
        succeeds(&case.run(&out, &["--force"]), case.name);
        assert_eq!(std::fs::read(&victim).unwrap(), b"keep", "{}", case.name);
        let kind = std::fs::symlink_metadata(&probe).unwrap().file_type();
        assert!(kind.is_file(), "{}: {kind:?}", case.name);
        assert!(std::fs::read(&probe).unwrap().len() > 4, "{}", case.name);
    }
}

/// A full disk (a file-size limit of 512 bytes, `ulimit -f 1`) is one line naming the file and
/// exit 1; every file left is whole (the bytes a run without the limit writes) or the old one,
/// and no temporary file is left behind.
#[cfg(unix)]
#[test]
fn a_full_disk_leaves_the_old_file_or_none_never_a_truncated_one() {
    let f = fixtures();
    let dir = tempfile::tempdir().unwrap();
    for (i, case) in cases(&f).iter().enumerate() {
        let whole = dir.path().join(format!("whole{i}"));
        succeeds(&case.run(&whole, &[]), case.name);
        let (whole_files, probe_bytes) = match case.target {
            Target::File => {
                let bytes = std::fs::read(&whole).unwrap();
                (BTreeMap::new(), bytes)
            }
            Target::Folder(name) => {
                let files = tree(&whole);
                let bytes = files[Path::new(name)].clone();
                (files, bytes)
            }
        };
        assert!(probe_bytes.len() > 1024, "{}: too small to test", case.name);
        let out = dir.path().join(format!("case{i}"));
        let o = case.run_limited(&out, &[]);
        assert_environment_failure(&o, case.name, &[out.to_str().unwrap(), "File too large"]);
        match case.target {
            Target::File => assert!(!out.exists(), "{}: a partial file", case.name),
            Target::Folder(_) => {
                for (name, bytes) in tree(&out) {
                    let hidden = name.to_str().unwrap().starts_with('.');
                    assert!(!hidden, "{}: {} left behind", case.name, name.display());
                    // The sweep's manifest records completeness and its checkpoint is a
                    // journal that drops a torn last line (docs/sweep.md); the rest is whole.
                    if case.name == "sweep" && name == Path::new("sweep.json") {
                        serde_json::from_slice::<serde_json::Value>(&bytes).unwrap();
                    } else if case.name != "sweep" || name != Path::new("checkpoint.jsonl") {
                        assert!(
                            whole_files.get(&name) == Some(&bytes),
                            "{}: {} is not whole",
                            case.name,
                            name.display()
                        );
                    }
                }
            }
        }
        // With --force over an old file: the old file stays.
        let probe = case.probe(&out);
        if let Target::Folder(_) = case.target {
            std::fs::create_dir_all(&out).unwrap();
        }
        std::fs::write(&probe, b"old").unwrap();
        let o = case.run_limited(&out, &["--force"]);
        assert_environment_failure(&o, case.name, &["File too large"]);
        assert_eq!(std::fs::read(&probe).unwrap(), b"old", "{}", case.name);
    }
}

/// `--out FILE` where a folder is wanted, `-o FOLDER` where a file is: exit 2, the option and
/// the path named (docs/limits.md's promise for `plot inverse --out README.md`).
#[test]
fn the_wrong_kind_of_path_is_exit_2_naming_it() {
    let f = fixtures();
    for case in cases(&f) {
        let (path, needle) = match case.target {
            Target::Folder(_) => ("README.md", "--out README.md: is a file, give a folder"),
            Target::File => ("crates", "crates: is a folder, give a file"),
        };
        assert_refused(&case.run(Path::new(path), &[]), case.name, &[needle]);
        assert_refused(
            &case.run(Path::new(path), &["--force"]),
            case.name,
            &[needle],
        );
    }
}

/// Only the folder named is created: a missing parent is exit 2 naming it, and nothing is made.
#[test]
fn a_missing_parent_is_exit_2_and_no_folder_is_made() {
    let f = fixtures();
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("missing");
    for case in cases(&f) {
        let out = missing.join("out");
        let needle = format!("{} does not exist", missing.display());
        assert_refused(&case.run(&out, &[]), case.name, &[&needle]);
        assert!(
            !missing.exists(),
            "{}: created {}",
            case.name,
            missing.display()
        );
    }
}

/// A folder that cannot be written (here /proc/self, which not even root can add files to):
/// exit 1 naming the file, for the commands that once gave the operating system's message
/// alone.
#[cfg(target_os = "linux")]
#[test]
fn a_folder_that_cannot_be_written_is_named() {
    let f = fixtures();
    let unwritable = Path::new("/proc/self");
    for case in cases(&f) {
        let (out, file) = match case.target {
            Target::File => (unwritable.join("x"), unwritable.join("x")),
            Target::Folder(_) if case.name.starts_with("plot") || case.name == "sweep report" => {
                (unwritable.to_path_buf(), unwritable.to_path_buf())
            }
            Target::Folder(_) => continue,
        };
        let o = case.run(&out, &[]);
        assert_environment_failure(
            &o,
            case.name,
            &["cannot write", &format!("{}", file.display())],
        );
    }
}

/// Standard output that cannot be written (a full device) is exit 1, named.
#[cfg(target_os = "linux")]
#[test]
fn a_full_standard_output_is_named() {
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_kinsyn"))
        .args(["catalogue", "list"])
        .stdout(full)
        .output()
        .unwrap();
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.starts_with("kinsyn: error: cannot write standard output: No space left on device"),
        "{err}"
    );
}

/// `kinsyn sweep --out DIR` into its own interrupted run resumes without `--force`; another
/// sweep there, or a manifest that does not read, is refused unless `--force`, which starts
/// afresh and writes what a fresh directory gets.
#[test]
fn a_sweep_resumes_without_force_and_replaces_another_only_with_it() {
    let dir = tempfile::tempdir().unwrap();
    let run = |out: &Path, extra: &[&str]| {
        let args = [
            &["sweep", "--out", out.to_str().unwrap()][..],
            &SMALL,
            extra,
        ]
        .concat();
        kinsyn(&args)
    };
    let cut = dir.path().join("cut");
    succeeds(&run(&cut, &["--stop-after", "3"]), "interrupted");
    assert!(cut.join("checkpoint.jsonl").exists());
    let o = run(&cut, &["--json"]);
    succeeds(&o, "resumed");
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(
        (v["resumed"].as_u64(), v["complete"].as_bool()),
        (Some(3), Some(true))
    );
    // The same complete sweep with --force: left as it is, not recomputed.
    let o = run(&cut, &["--force"]);
    succeeds(&o, "complete");
    assert!(stdout(&o).contains("already complete"), "{}", stdout(&o));
    // Another seed: refused, then replaced.
    assert_refused(
        &run(&cut, &["--seed", "7"]),
        "another sweep",
        &["holds another sweep", "--force"],
    );
    succeeds(&run(&cut, &["--seed", "7", "--force"]), "replaced");
    let fresh = dir.path().join("fresh");
    succeeds(&run(&fresh, &["--seed", "7"]), "fresh");
    assert!(
        tree(&cut) == tree(&fresh),
        "a replaced sweep differs from a fresh one"
    );
    // A manifest that does not read: refused, and replaced with --force.
    let damaged = dir.path().join("damaged");
    std::fs::create_dir(&damaged).unwrap();
    std::fs::write(damaged.join("sweep.json"), b"{").unwrap();
    assert_refused(&run(&damaged, &["--seed", "7"]), "damaged", &["sweep.json"]);
    succeeds(
        &run(&damaged, &["--seed", "7", "--force"]),
        "damaged, replaced",
    );
    assert!(
        tree(&damaged) == tree(&fresh),
        "a replaced sweep differs from a fresh one"
    );
}
