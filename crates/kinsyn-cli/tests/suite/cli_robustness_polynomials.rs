//! Polynomial systems that once crashed or ran without end, each now refused in one line with
//! exit 2 before the work, or read at a cost bounded by the text (docs/limits.md, "`kinsyn
//! solve` and `--all-assemblies`" and "Operation modes"): expressions nested thousands deep
//! (a stack overflow), expansions whose terms or work explode, decompositions of too many paths
//! or unknowns, and the option that raises each path limit.

use crate::common;

use common::{assert_refused, kinsyn, stderr, stdout};
use std::fmt::Write as _;
use std::path::Path;
use std::time::{Duration, Instant};

fn write(dir: &Path, name: &str, text: &str) -> String {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.to_str().unwrap().to_string()
}

/// A Bertini file of one equation `f = BODY` in the given variables (each its own function
/// when there are several: `f` then `g_k = x_k` for the others, so that the system is square).
fn one_equation(variables: &[&str], body: &str) -> String {
    let mut s = format!("INPUT\n  variable_group {};\n", variables.join(", "));
    let others: Vec<String> = (1..variables.len()).map(|k| format!("g{k}")).collect();
    let mut functions = vec!["f".to_string()];
    functions.extend(others.iter().cloned());
    let _ = writeln!(s, "  function {};", functions.join(", "));
    let _ = writeln!(s, "  f = {body};");
    for (k, g) in others.iter().enumerate() {
        let _ = writeln!(s, "  {g} = {} - 1;", variables[k + 1]);
    }
    s + "END;\n"
}

/// `n` equations in `n` unknowns `x0 … x(n−1)`, equation `i` given by `equation(i)`.
fn square_system(n: usize, equation: impl Fn(usize) -> String) -> String {
    let names: Vec<String> = (0..n).map(|i| format!("x{i}")).collect();
    let functions: Vec<String> = (0..n).map(|i| format!("f{i}")).collect();
    let mut s = format!(
        "INPUT\n  variable_group {};\n  function {};\n",
        names.join(", "),
        functions.join(", ")
    );
    for i in 0..n {
        let _ = writeln!(s, "  f{i} = {};", equation(i));
    }
    s + "END;\n"
}

/// Runs `kinsyn ARGS` and asserts the one-line refusal with every needle, within `seconds`.
fn refused_within(seconds: u64, args: &[&str], needles: &[&str]) {
    let clock = Instant::now();
    let o = kinsyn(args);
    let took = clock.elapsed();
    assert_refused(&o, &format!("{args:?}"), needles);
    assert!(
        took < Duration::from_secs(seconds),
        "{args:?} took {took:?}"
    );
}

/// The real solutions of `kinsyn solve FILE --json`, one coordinate vector each.
fn real_solutions(file: &str, extra: &[&str]) -> Vec<Vec<f64>> {
    let mut args = vec!["solve", file, "--json", "--show", "real"];
    args.extend(extra);
    let o = kinsyn(&args);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    v["solutions"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|s| s["real"] == true)
        .map(|s| {
            s["x"]
                .as_array()
                .unwrap()
                .iter()
                .map(|c| c[0].as_f64().unwrap())
                .collect()
        })
        .collect()
}

/// 7 000 nested parentheses, 400 000 minus signs and a chain of 400 000 `^1` once overflowed
/// the stack of both commands (an abort, exit 134). They nest far beyond 128 levels, the
/// documented limit, and are refused in one line; the files are under the 1 MiB file limit.
#[test]
fn deep_nesting_is_refused_in_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let cases = [
        (
            "parens.bertini",
            format!("{}x{}", "(".repeat(7000), ")".repeat(7000)),
        ),
        ("minus.bertini", format!("{}x", "- ".repeat(400_000))),
        ("power.bertini", format!("x{}", "^1".repeat(400_000))),
    ];
    for (name, body) in cases {
        let text = one_equation(&["x"], &body);
        assert!(text.len() < 1 << 20, "{name} is within the file limit");
        let file = write(d, name, &text);
        for command in ["solve", "components"] {
            refused_within(
                20,
                &[command, &file],
                &["line 4", "f nests", "more than 128 deep"],
            );
        }
    }
}

/// At the limit the nesting is read: 128 parentheses (or 64 signs inside 64 parentheses)
/// around `x − 1` leave the equation `x − 1 = 0` (an even number of signs), whose root 1 the
/// solver finds; one level more is refused.
#[test]
fn nesting_up_to_the_limit_is_read() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let parens = format!("{}x - 1{}", "(".repeat(128), ")".repeat(128));
    let signs = format!("{}x - 1{}", "-(".repeat(64), ")".repeat(64));
    for (name, body) in [("p128.bertini", parens), ("s128.bertini", signs)] {
        let file = write(d, name, &one_equation(&["x"], &body));
        let roots = real_solutions(&file, &[]);
        assert_eq!(roots.len(), 1, "{name}");
        assert!((roots[0][0] - 1.0).abs() < 1e-12, "{name}: {roots:?}");
    }
    let deeper = write(
        d,
        "p129.bertini",
        &one_equation(
            &["x"],
            &format!("{}x - 1{}", "(".repeat(129), ")".repeat(129)),
        ),
    );
    refused_within(20, &["solve", &deeper], &["more than 128 deep"]);
}

/// `(x+1)^65535` has 65 536 terms and `(x+y+z+1)^50` has C(53, 3) = 53·52·51/6 = 23 426 (every
/// monomial of degree ≤ 50 in three variables): beyond the 10 000 terms of a polynomial, both
/// refused before they are expanded. `(x+1)^9999` has 10 000 terms, within the limit, but its
/// expansion takes 9999 · 10000 term products, beyond what a file in one variable may take.
/// Each once ran without end.
#[test]
fn explosive_expansions_are_refused_before_expanding() {
    assert_eq!(53 * 52 * 51 / 6, 23_426);
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let binomial = write(d, "binomial.bertini", &one_equation(&["x"], "(x+1)^65535"));
    let trinomial = write(
        d,
        "xyz.bertini",
        &one_equation(&["x", "y", "z"], "(x+y+z+1)^50"),
    );
    let work = write(d, "work.bertini", &one_equation(&["x"], "(x+1)^9999"));
    for command in ["solve", "components"] {
        refused_within(
            20,
            &[command, &binomial],
            &[
                "'(x+1)^65535' in f",
                "65536 terms",
                "beyond the limit of 10000",
            ],
        );
        refused_within(
            20,
            &[command, &trinomial],
            &["'(x+y+z+1)^50' in f", "23426 terms", "limit of 10000"],
        );
        refused_within(
            20,
            &[command, &work],
            &[
                "'(x+1)^9999' in f",
                "99990000 term products",
                "a file in 1 variable may take",
            ],
        );
    }
}

/// A long sum costs its terms, not their square: `x + x + … + x − 100000` with 100 000 terms
/// (about 400 kB) is read at once and is `100000·x − 100000`, whose root is 1.
#[test]
fn long_sums_are_read_in_linear_time() {
    let dir = tempfile::tempdir().unwrap();
    let body = format!("{}x - 100000", "x + ".repeat(99_999));
    let file = write(dir.path(), "sum.bertini", &one_equation(&["x"], &body));
    let clock = Instant::now();
    let roots = real_solutions(&file, &[]);
    assert!(
        clock.elapsed() < Duration::from_secs(20),
        "{:?}",
        clock.elapsed()
    );
    assert_eq!(roots.len(), 1);
    assert!((roots[0][0] - 1.0).abs() < 1e-12, "{roots:?}");
}

/// 21 equations `x_i² − 1`: the total-degree start system has 2²¹ = 2 097 152 paths, and the
/// decomposition by dimension solves one sliced system per dimension d = 20 … 0, of
/// 2^(21 − d) paths: 2 + 4 + … + 2²¹ = 2²² − 2 = 4 194 302 (regeneration:
/// 2 (2 + 4 + … + 2²¹) = 8 388 604). A path in 21 unknowns counts ⌈21³/12³⌉ = ⌈9261/1728⌉ = 6
/// times against `components`' limit: 25 165 812 in all. `components` once ran past 30 s; both
/// commands now refuse at once, naming `--max-paths`.
#[test]
fn too_many_paths_are_refused_at_once_naming_the_option() {
    let dir = tempfile::tempdir().unwrap();
    let file = write(
        dir.path(),
        "q21.bertini",
        &square_system(21, |i| format!("x{i}^2 - 1")),
    );
    refused_within(
        10,
        &["solve", &file],
        &[
            "2097152 paths",
            "more than --max-paths 65536",
            "at most 1048576",
        ],
    );
    refused_within(
        10,
        &["solve", &file, "--max-paths", "1048576"],
        &["2097152 paths", "the most --max-paths takes"],
    );
    refused_within(
        10,
        &["components", &file],
        &[
            "by-dimension is estimated at 4194302 paths",
            "in 21 unknowns, each counting 6 times",
            "25165812 in all",
            "more than --max-paths 65536",
            "at most 4194304",
        ],
    );
    refused_within(
        10,
        &["components", &file, "--method", "regeneration"],
        &["regeneration is estimated at 8388604 paths", "--max-paths"],
    );
}

/// `--max-paths` raises (or lowers) the limit, and the estimate is the one by hand. The circle
/// and the line have Bézout number 2·1 = 2. The twisted cubic and the line (four cubics in
/// three unknowns) slice to 1, 2 and 3 random cubics: 3 + 9 + 27 = 39 paths by dimension, and
/// regeneration estimates 2 (3 + 9 + 27 + 81) = 240.
#[test]
fn max_paths_raises_the_limit() {
    let circle = "examples/systems/circle-line.bertini";
    refused_within(
        10,
        &["solve", circle, "--max-paths", "1"],
        &["2 paths, more than --max-paths 1: raise it"],
    );
    let roots = real_solutions(circle, &["--max-paths", "2"]);
    assert_eq!(roots.len(), 2);
    let cubic = "examples/systems/twisted-cubic-and-line.bertini";
    refused_within(
        10,
        &["components", cubic, "--max-paths", "38"],
        &["by-dimension is estimated at 39 paths", "--max-paths 38"],
    );
    refused_within(
        10,
        &[
            "components",
            cubic,
            "--method",
            "regeneration",
            "--max-paths",
            "239",
        ],
        &["regeneration is estimated at 240 paths", "--max-paths 239"],
    );
    let o = kinsyn(&["components", cubic, "--max-paths", "100000", "--json"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_str(&stdout(&o)).unwrap();
    assert_eq!(v["estimated_paths"], "39");
    // Beyond the ceilings: refused by the argument parser.
    refused_within(
        10,
        &["solve", circle, "--max-paths", "1048577"],
        &["--max-paths"],
    );
    refused_within(
        10,
        &["components", cubic, "--max-paths", "0"],
        &["--max-paths"],
    );
    refused_within(
        10,
        &["components", cubic, "--max-paths", "4194305"],
        &["--max-paths"],
    );
}

/// A manipulator's constraints go through the same decomposition and its limit: the 4-RUU at
/// its reference inputs has ten quadrics in eight unknowns, so by dimension it slices to 1 … 8
/// random quadrics, 2 + 4 + … + 256 = 510 paths.
#[test]
fn a_manipulator_decomposition_has_the_same_limit() {
    refused_within(
        20,
        &["components", "mechanisms/4-ruu.json", "--max-paths", "509"],
        &[
            "mechanisms/4-ruu.json",
            "by-dimension is estimated at 510 paths",
            "more than --max-paths 509",
        ],
    );
}

/// 1 000 linear equations in 1 000 unknowns once failed to allocate within a second in
/// `components`, and 20 000 ran `solve` out of memory: the unknowns are bounded (100 for a
/// solve, 32 for a decomposition, 1 000 declared in a file), each refused before any work.
#[test]
fn too_many_unknowns_are_refused_before_any_work() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let linear = |n: usize| square_system(n, move |i| format!("x{i} + x{} - {i}", (i + 1) % n));
    let thousand = write(d, "lin1000.bertini", &linear(1000));
    let twenty_thousand = write(d, "lin20000.bertini", &linear(20_000));
    let hundred_one = write(d, "lin101.bertini", &linear(101));
    let thirty_three = write(d, "lin33.bertini", &linear(33));
    refused_within(10, &["solve", &thousand], &["1000 unknowns", "at most 100"]);
    refused_within(
        10,
        &["solve", &hundred_one],
        &["101 unknowns", "at most 100"],
    );
    refused_within(
        10,
        &["components", &thousand],
        &[
            "1000 equations in 1000 unknowns",
            "at most 128 equations in 32 unknowns",
        ],
    );
    refused_within(
        10,
        &["components", &thirty_three],
        &["33 equations in 33 unknowns", "32 unknowns"],
    );
    for command in ["solve", "components"] {
        refused_within(
            10,
            &[command, &twenty_thousand],
            &["line 2", "20000 variables declared", "limit of 1000"],
        );
    }
}

/// One variable group per unknown makes the multi-homogeneous count a permanent: 40 groups
/// are 2⁴⁰ states, beyond the 2¹⁶ counted. The total-degree solve of `x_i = i` (one path) still
/// runs and reports the count as not counted; the multi-homogeneous start is refused, naming
/// the way out.
#[test]
fn many_variable_groups_are_not_counted() {
    let dir = tempfile::tempdir().unwrap();
    let n = 40;
    let mut text = String::from("INPUT\n");
    for i in 0..n {
        let _ = writeln!(text, "  variable_group x{i};");
    }
    let functions: Vec<String> = (0..n).map(|i| format!("f{i}")).collect();
    let _ = writeln!(text, "  function {};", functions.join(", "));
    for i in 0..n {
        let _ = writeln!(text, "  f{i} = x{i} - {i};");
    }
    text.push_str("END;\n");
    let file = write(dir.path(), "groups40.bertini", &text);
    let roots = real_solutions(&file, &[]);
    assert_eq!(roots.len(), 1);
    for (i, x) in roots[0].iter().enumerate() {
        assert!((x - i as f64).abs() < 1e-9, "x{i} = {x}");
    }
    let o = kinsyn(&["solve", &file]);
    assert!(
        stdout(&o)
            .contains("multi-homogeneous not counted, linear-product 1 for 40 variable groups"),
        "{}",
        stdout(&o)
    );
    refused_within(
        10,
        &["solve", &file, "--start", "multi-homogeneous"],
        &["40 variable groups are too many", "--start total-degree"],
    );
}
