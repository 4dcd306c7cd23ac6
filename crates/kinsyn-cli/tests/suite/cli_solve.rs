//! `kinsyn solve` (homotopy continuation on Bertini files) and `kinsyn analyze --all-assemblies`
//! from the command line: solution counts from the literature, solutions checked by evaluating
//! the file's equations here, assemblies checked against leg lengths computed here from the
//! description's geometry, and one-line refusals of bad input.

use crate::common;

use common::{assert_refused, kinsyn, stderr, stdout};
use kinsyn::poly::{C64, System, bertini};
use nalgebra::{Matrix3, Rotation3, Vector3};
use serde_json::Value;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// The repository root (the binary's working directory in [`kinsyn`]).
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// A successful run's standard output parsed as JSON.
fn json(args: &[&str]) -> Value {
    let o = kinsyn(args);
    assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
    serde_json::from_str(&stdout(&o)).unwrap()
}

fn write(dir: &Path, name: &str, bytes: &[u8]) -> String {
    let path = dir.join(name);
    std::fs::write(&path, bytes).unwrap();
    path.to_str().unwrap().to_string()
}

/// The system of a Bertini file, read here with the library's parser.
fn system_of(path: &str) -> System {
    let full = if Path::new(path).is_absolute() {
        PathBuf::from(path)
    } else {
        root().join(path)
    };
    bertini::parse(&std::fs::read_to_string(full).unwrap())
        .unwrap()
        .system
}

/// The solutions of a `kinsyn solve --json` output, as complex vectors.
fn solutions(v: &Value) -> Vec<Vec<C64>> {
    v["solutions"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| {
            s["x"]
                .as_array()
                .unwrap()
                .iter()
                .map(|c| C64::new(c[0].as_f64().unwrap(), c[1].as_f64().unwrap()))
                .collect()
        })
        .collect()
}

/// Every listed solution satisfies every equation of the file: `|f_i(x)|` at most `1e-10` of
/// the sum of its terms' moduli at `x` (the relative backward error), evaluated here.
fn assert_solutions_satisfy(file: &str, v: &Value) {
    let system = system_of(file);
    for x in solutions(v) {
        let values = system.evaluate(&x);
        for (p, f) in system.equations().iter().zip(values) {
            let scale: f64 = p
                .terms()
                .map(|(e, c)| {
                    c.norm()
                        * e.iter()
                            .zip(&x)
                            .map(|(k, xi)| xi.norm().powi(i32::try_from(*k).unwrap()))
                            .product::<f64>()
                })
                .sum();
            assert!(
                f.norm() <= 1e-10 * scale.max(1.0),
                "{file}: f = {f} at {x:?}"
            );
        }
    }
}

/// Whether two solution lists are the same set up to order (each point within `tol` of a
/// distinct point of the other).
fn same_set(a: &[Vec<C64>], b: &[Vec<C64>], tol: f64) -> bool {
    let near = |x: &[C64], y: &[C64]| x.iter().zip(y).all(|(p, q)| (p - q).norm() <= tol);
    let mut used = vec![false; b.len()];
    a.len() == b.len()
        && a.iter().all(|x| {
            (0..b.len())
                .find(|&j| !used[j] && near(x, &b[j]))
                .is_some_and(|j| {
                    used[j] = true;
                    true
                })
        })
}

fn count(v: &Value, key: &str) -> u64 {
    v[key].as_u64().unwrap_or_else(|| panic!("{key} in {v:#}"))
}

/// The unit circle met by the line x = y: x² + x² = 1, so x = y = ±1/√2 (by hand), both real
/// and regular (the Jacobian [[2x, 2y], [1, −1]] has determinant −4x ≠ 0), Bézout 2 = 2 roots.
#[test]
fn circle_line_has_the_two_real_roots_both_certified() {
    let file = "examples/systems/circle-line.bertini";
    let v = json(&["solve", file, "--json"]);
    assert_eq!(count(&v, "paths"), 2);
    assert_eq!(count(&v, "nonsingular"), 2);
    assert_eq!(count(&v, "real"), 2);
    assert_eq!(count(&v, "at_infinity"), 0);
    assert_eq!(count(&v, "certified"), 2);
    assert_eq!(count(&v, "certified_real"), 2);
    let r = std::f64::consts::FRAC_1_SQRT_2;
    let expected = vec![
        vec![C64::new(r, 0.0), C64::new(r, 0.0)],
        vec![C64::new(-r, 0.0), C64::new(-r, 0.0)],
    ];
    assert!(same_set(&solutions(&v), &expected, 1e-12), "{v:#}");
    for s in v["solutions"].as_array().unwrap() {
        assert_eq!(s["certified"], true);
        assert_eq!(s["reality"], "real");
        assert!(s["certificate_radius"].as_f64().unwrap() < 1e-6);
    }
    // The text lists them as real.
    let o = kinsyn(&["solve", file]);
    assert_eq!(o.status.code(), Some(0));
    let out = stdout(&o);
    assert!(out.contains("real solutions (2):"), "{out}");
    assert!(out.contains("x = 0.7071067812, y = 0.7071067812"), "{out}");
    assert!(
        out.contains("x = -0.7071067812, y = -0.7071067812"),
        "{out}"
    );
}

/// Katsura-5 has 2⁵ = 32 isolated solutions, all non-singular (S. Katsura 1990; the file's
/// header), equal to its Bézout number 2⁵·1: no path goes to infinity.
#[test]
fn katsura5_has_32_certified_roots() {
    let file = "examples/systems/katsura5.bertini";
    let v = json(&["solve", file, "--json", "--show", "all"]);
    assert_eq!(v["bezout_number"], "32");
    assert_eq!(count(&v, "paths"), 32);
    assert_eq!(count(&v, "nonsingular"), 32);
    assert_eq!(count(&v, "singular"), 0);
    assert_eq!(count(&v, "at_infinity"), 0);
    assert_eq!(count(&v, "failed"), 0);
    assert_eq!(count(&v, "certified"), 32);
    assert_solutions_satisfy(file, &v);
    // Real coefficients: the set is closed under complex conjugation.
    let xs = solutions(&v);
    let conjugates: Vec<Vec<C64>> = xs
        .iter()
        .map(|x| x.iter().map(C64::conj).collect())
        .collect();
    assert!(same_set(&xs, &conjugates, 1e-8));
}

/// Cyclic-5 has 70 isolated solutions (Björck & Fröberg 1991): of Bézout's 1·2·3·4·5 = 120
/// paths, 120 − 70 = 50 end at infinity. The equations are invariant under the cyclic shift
/// `x_i → x_{i+1}` and have real coefficients, so the solution set is closed under both. The
/// default start (auto) takes the polyhedral one: 70 paths, the mixed volume, none to spare.
#[test]
fn cyclic5_has_70_roots_and_50_at_infinity() {
    let file = "examples/systems/cyclic5.bertini";
    let auto = json(&["solve", file, "--json", "--show", "none"]);
    assert_eq!(auto["start"], "polyhedral");
    assert_eq!(auto["start_asked"], "auto");
    assert_eq!(count(&auto, "paths"), 70);
    assert_eq!(count(&auto, "nonsingular"), 70);
    assert_eq!(count(&auto, "at_infinity"), 0);
    assert_eq!(auto["complete"], true);
    let v = json(&[
        "solve",
        file,
        "--json",
        "--show",
        "none",
        "--start",
        "total-degree",
    ]);
    assert_eq!(v["bezout_number"], "120");
    assert_eq!(count(&v, "paths"), 120);
    assert_eq!(count(&v, "nonsingular"), 70);
    assert_eq!(count(&v, "singular"), 0);
    assert_eq!(count(&v, "at_infinity"), 50);
    assert_eq!(count(&v, "failed"), 0);
    assert_eq!(count(&v, "certified"), 70);
    assert_eq!(
        v["solutions"].as_array().unwrap().len(),
        70,
        "--json lists all"
    );
    assert_solutions_satisfy(file, &v);
    let xs = solutions(&v);
    let shifted: Vec<Vec<C64>> = xs
        .iter()
        .map(|x| (0..5).map(|i| x[(i + 1) % 5]).collect())
        .collect();
    assert!(same_set(&xs, &shifted, 1e-8), "not closed under the shift");
    let conjugates: Vec<Vec<C64>> = xs
        .iter()
        .map(|x| x.iter().map(C64::conj).collect())
        .collect();
    assert!(
        same_set(&xs, &conjugates, 1e-8),
        "not closed under conjugation"
    );
}

/// `--runs 4`: four runs with seeds seed … seed + 3, each finding the 32 roots of Katsura-5.
#[test]
fn four_runs_all_complete() {
    let v = json(&[
        "solve",
        "examples/systems/katsura5.bertini",
        "--runs",
        "4",
        "--seed",
        "5",
        "--json",
    ]);
    let runs = v["runs"].as_array().unwrap();
    assert_eq!(runs.len(), 4);
    let seeds: Vec<u64> = runs.iter().map(|r| r["seed"].as_u64().unwrap()).collect();
    assert_eq!(seeds, [5, 6, 7, 8]);
    for r in runs {
        assert_eq!(r["nonsingular"], 32);
        assert_eq!(r["complete"], true);
    }
    assert_eq!(v["complete_fraction"].as_f64(), Some(1.0));
    let o = kinsyn(&[
        "solve",
        "examples/systems/katsura5.bertini",
        "--runs",
        "4",
        "--show",
        "none",
    ]);
    assert!(
        stdout(&o).contains("4 independent runs (seeds 1–4) found 32 distinct non-singular solutions; 4 of 4 runs found all of them"),
        "{}",
        stdout(&o)
    );
}

/// The same seed gives the same paths whatever the thread count: identical solutions, bit for
/// bit, with the same path numbers; another seed gives the same set in another order.
#[test]
fn threads_do_not_change_the_result_and_seeds_only_the_order() {
    let file = "examples/systems/cyclic5.bertini";
    let one = json(&["solve", file, "--threads", "1", "--json"]);
    let two = json(&["solve", file, "--threads", "2", "--json"]);
    assert_eq!(one["threads"], 1);
    assert_eq!(two["threads"], 2);
    assert_eq!(one["solutions"], two["solutions"]);
    assert_eq!(one["summary"], two["summary"]);
    let other = json(&["solve", file, "--seed", "77", "--json"]);
    assert_eq!(count(&other, "nonsingular"), 70);
    assert!(same_set(&solutions(&one), &solutions(&other), 1e-8));
}

/// x·y − 2x + 3y − 1 = 0 and 2xy + x − y − 4 = 0 in the groups {x}, {y}: each equation has
/// bidegree (1, 1), so the multi-homogeneous Bézout number is the coefficient of αβ in
/// (α + β)², 2, against the total degree 2·2 = 4. By hand: y = (2x + 1)/(x + 3) from the
/// first, y = (4 − x)/(2x − 1) from the second, so (2x + 1)(2x − 1) = (4 − x)(x + 3), i.e.
/// 5x² − x − 13 = 0, x = (1 ± √261)/10: two real roots, and the other two total-degree paths
/// go to infinity.
#[test]
fn multi_homogeneous_start_tracks_two_paths_for_two_bilinear_equations() {
    let dir = tempfile::tempdir().unwrap();
    let file = write(
        dir.path(),
        "bilinear.bertini",
        b"INPUT\n  variable_group x;\n  variable_group y;\n  function f, g;\n  f = x*y - 2*x + 3*y - 1;\n  g = 2*x*y + x - y - 4;\nEND;\n",
    );
    let root = |s: f64| {
        let x = (1.0 + s * 261f64.sqrt()) / 10.0;
        vec![C64::new(x, 0.0), C64::new((2.0 * x + 1.0) / (x + 3.0), 0.0)]
    };
    let expected = vec![root(1.0), root(-1.0)];
    let mh = json(&["solve", &file, "--start", "multi-homogeneous", "--json"]);
    assert_eq!(mh["multihomogeneous_bezout_number"], "2");
    assert_eq!(mh["start"], "multi-homogeneous");
    assert_eq!(count(&mh, "paths"), 2);
    assert_eq!(count(&mh, "at_infinity"), 0);
    assert_eq!(count(&mh, "certified_real"), 2);
    let td = json(&["solve", &file, "--json", "--start", "total-degree"]);
    assert_eq!(count(&td, "paths"), 4);
    // The linear-product start: each equation's terms pair x with y, so its slots are {x}{y};
    // one equation takes x, the other y: 2 paths, the same roots.
    let lp = json(&["solve", &file, "--json", "--start", "linear-product"]);
    assert_eq!(lp["linear_product_paths"], "2");
    assert_eq!(count(&lp, "paths"), 2);
    assert!(same_set(&solutions(&lp), &expected, 1e-10), "{lp:#}");
    // auto: the fewest paths, the multi-homogeneous start's 2 (the mixed volume is 2 too, and a
    // tie keeps the start without a first stage).
    let auto = json(&["solve", &file, "--json"]);
    assert_eq!(auto["start"], "multi-homogeneous");
    assert_eq!(count(&auto, "paths"), 2);
    assert_eq!(count(&td, "at_infinity"), 2);
    assert!(same_set(&solutions(&mh), &expected, 1e-10), "{mh:#}");
    assert!(same_set(&solutions(&td), &expected, 1e-10), "{td:#}");
    let o = kinsyn(&["solve", &file, "--start", "multi-homogeneous"]);
    assert!(
        stdout(&o).contains(
            "start system: multi-homogeneous, 2 paths (Bézout number 4, multi-homogeneous 2, linear-product 2 for 2 variable groups)"
        ),
        "{}",
        stdout(&o)
    );
}

/// x³ − 3x + 2 = (x − 1)²(x + 2): a simple root −2 (certified, real) and the double root 1
/// (singular, multiplicity 2, reached by two of the three paths, no certificate: Krawczyk
/// proves only regular roots).
#[test]
fn a_double_root_is_singular_with_multiplicity_2_and_no_certificate() {
    let dir = tempfile::tempdir().unwrap();
    let file = write(
        dir.path(),
        "double.bertini",
        b"INPUT\n  variable_group x;\n  function f;\n  f = x^3 - 3*x + 2;\nEND;\n",
    );
    let v = json(&["solve", &file, "--json"]);
    assert_eq!(count(&v, "paths"), 3);
    assert_eq!(count(&v, "nonsingular"), 1);
    assert_eq!(count(&v, "singular"), 1);
    assert_eq!(count(&v, "certified"), 1);
    let s = v["solutions"].as_array().unwrap();
    let regular = s.iter().find(|s| s["regular"] == true).unwrap();
    assert!((regular["x"][0][0].as_f64().unwrap() + 2.0).abs() < 1e-12);
    assert_eq!(regular["certified"], true);
    assert_eq!(regular["reality"], "real");
    let double = s.iter().find(|s| s["regular"] == false).unwrap();
    let x = C64::new(
        double["x"][0][0].as_f64().unwrap(),
        double["x"][0][1].as_f64().unwrap(),
    );
    // A double root is found to about half the digits (the endgame does better).
    assert!((x - C64::new(1.0, 0.0)).norm() < 1e-6, "{x}");
    assert_eq!(double["multiplicity"], 2);
    assert_eq!(double["paths"].as_array().unwrap().len(), 2);
    assert_eq!(double["certified"], false);
    assert_eq!(double["certificate_radius"], Value::Null);
    assert_eq!(double["reality"], "singular");
    let o = kinsyn(&["solve", &file, "--show", "all"]);
    assert!(
        stdout(&o).contains("singular, multiplicity 2"),
        "{}",
        stdout(&o)
    );
}

/// `x^16 − 1` has the 16 sixteenth roots of unity, all simple (the derivative `16x^15` does
/// not vanish on them), two of them real (±1): 16 non-singular, none singular, all certified.
/// (The solver once called two of them singular: its singular test was not scale-free.)
#[test]
fn the_sixteenth_roots_of_unity_are_sixteen_regular_certified_roots() {
    let dir = tempfile::tempdir().unwrap();
    let file = write(
        dir.path(),
        "unity16.bertini",
        b"INPUT\n  variable_group x;\n  function f;\n  f = x^16 - 1;\nEND;\n",
    );
    let v = json(&["solve", &file, "--json"]);
    assert_eq!(count(&v, "paths"), 16);
    assert_eq!(count(&v, "nonsingular"), 16);
    assert_eq!(count(&v, "singular"), 0);
    assert_eq!(count(&v, "real"), 2);
    assert_eq!(count(&v, "certified"), 16);
    assert_eq!(count(&v, "certified_real"), 2);
    let expected: Vec<Vec<C64>> = (0..16)
        .map(|k| {
            vec![C64::from_polar(
                1.0,
                std::f64::consts::TAU * f64::from(k) / 16.0,
            )]
        })
        .collect();
    assert!(same_set(&solutions(&v), &expected, 1e-12), "{v:#}");
}

/// A Bertini file with `n` equations `x_i^degree − 1` in `n` variables, in one group or one
/// group per variable.
fn power_system(n: usize, degree: u32, groups: bool) -> String {
    let names: Vec<String> = (0..n).map(|i| format!("x{i}")).collect();
    let mut s = String::from("INPUT\n");
    if groups {
        for v in &names {
            let _ = writeln!(s, "  variable_group {v};");
        }
    } else {
        let _ = writeln!(s, "  variable_group {};", names.join(", "));
    }
    let functions: Vec<String> = (0..n).map(|i| format!("f{i}")).collect();
    let _ = writeln!(s, "  function {};", functions.join(", "));
    for i in 0..n {
        let _ = writeln!(s, "  f{i} = x{i}^{degree} - 1;");
    }
    s + "END;\n"
}

/// A Bertini file in `d` with unknowns `x, y`, functions `f, g` and the given body.
fn two_unknowns(d: &Path, name: &str, body: &str) -> String {
    write(
        d,
        name,
        format!("INPUT\n  variable_group x, y;\n  function f, g;\n{body}END;\n").as_bytes(),
    )
}

/// Every bad input to `kinsyn solve`: one line, exit 2, no panic.
#[test]
fn bad_solve_input_is_one_line_and_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let bertini = |name: &str, body: &str| two_unknowns(d, name, body);
    let latin1 = write(
        d,
        "latin1.bertini",
        b"INPUT\n  variable_group caf\xe9;\nEND;\n",
    );
    let syntax = bertini("syntax.bertini", "  f = x^2 +;\n  g = y;\n");
    let unknown = bertini("unknown.bertini", "  f = x^2 - z;\n  g = y;\n");
    let sine = bertini("sine.bertini", "  f = sin(x);\n  g = y;\n");
    let constant = bertini("constant.bertini", "  f = x^2 - 1;\n  g = 3;\n");
    let zero = bertini("zero.bertini", "  f = x^2 - 1;\n  g = y - y;\n");
    let overflow = bertini("overflow.bertini", "  f = 1e300*1e300*x^2 - 1;\n  g = y;\n");
    let fewer = write(
        d,
        "fewer.bertini",
        b"INPUT\n  variable_group x, y;\n  function f;\n  f = x^2 + y^2 - 1;\nEND;\n",
    );
    let more = write(
        d,
        "more.bertini",
        b"INPUT\n  variable_group x;\n  function f, g;\n  f = x^2 - 1;\n  g = x - 1;\nEND;\n",
    );
    // 2^65535·… : Bézout numbers beyond u128 must not overflow (65535 is the largest exponent).
    let huge = write(d, "huge.bertini", power_system(20, 65535, false).as_bytes());
    let huge_groups = write(
        d,
        "hugegroups.bertini",
        power_system(20, 65535, true).as_bytes(),
    );
    let dir_path = d.to_str().unwrap().to_string();
    let missing = d.join("missing.bertini").to_str().unwrap().to_string();
    let circle = "examples/systems/circle-line.bertini";
    let cases: Vec<(Vec<&str>, Vec<&str>)> = vec![
        (vec![&missing], vec!["missing.bertini", "No such file"]),
        (
            vec![&dir_path],
            vec!["not a Bertini input file (a directory)"],
        ),
        (vec!["/dev/zero"], vec!["not a regular file"]),
        (vec![&latin1], vec!["not UTF-8"]),
        (vec!["Cargo.toml"], vec!["Cargo.toml", "no INPUT section"]),
        (vec![&syntax], vec!["syntax.bertini", "line 4"]),
        (vec![&unknown], vec!["line 4", "unknown name 'z'"]),
        (vec![&sine], vec!["line 4", "sin", "not polynomial"]),
        (
            vec![&fewer],
            vec![
                "1 equation in 2 variables",
                "fewer equations than variables",
            ],
        ),
        (
            vec![&more],
            vec!["2 equations in 1 variable", "more equations than variables"],
        ),
        (
            vec![&constant],
            vec!["equation g is the non-zero constant 3"],
        ),
        (vec![&zero], vec!["equation g is identically zero"]),
        (
            vec![&overflow],
            vec![
                "line 4",
                "'1e300*1e300' in f",
                "not finite in double precision",
            ],
        ),
        (vec![&huge], vec!["more than 10^38 paths", "1048576"]),
        (
            vec![&huge_groups, "--start", "multi-homogeneous"],
            vec!["20 variable groups are too many to count"],
        ),
        (vec![circle, "--runs", "0"], vec!["--runs 0", "1 to 64"]),
        (vec![circle, "--runs", "65"], vec!["--runs 65", "1 to 64"]),
        (vec![circle, "--threads", "0"], vec!["--threads 0"]),
        (
            vec![circle, "--start", "random"],
            vec![
                "'random'",
                "--start",
                "auto, total-degree, multi-homogeneous, linear-product, polyhedral",
            ],
        ),
        (vec![circle, "--show", "some"], vec!["'some'"]),
    ];
    for (args, needles) in cases {
        let mut all = vec!["solve"];
        all.extend(&args);
        assert_refused(&kinsyn(&all), &format!("{args:?}"), &needles);
    }
}

/// Values that are not finite and degrees beyond `poly::MAX_DEGREE` (2^20) are refused where
/// they are written, in one line with exit 2: they once gave wrong certified answers.
#[test]
fn non_finite_values_and_degrees_beyond_the_limit_are_refused() {
    assert_eq!(kinsyn::poly::MAX_DEGREE, 1 << 20);
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let bertini = |name: &str, body: &str| two_unknowns(d, name, body);
    // inf·0 is NaN: once dropped as a zero coefficient, so that x − c gave x = 0.
    let nan = write(
        d,
        "nan.bertini",
        b"INPUT\n  variable_group x;\n  function f;\n  constant c;\n  c = (1e308*1e308)*0;\n  f = x - c;\nEND;\n",
    );
    let nan_difference = bertini(
        "nandiff.bertini",
        "  f = (1e200*1e200 - 1e200*1e200)*x;\n  g = y;\n",
    );
    // x^65536 raised to 65535 has degree 4294901760, and times x^65537 it wrapped round u32 to
    // degree 1 (a certified x = 2).
    let wrap = write(
        d,
        "wrap.bertini",
        b"INPUT\n  variable_group x;\n  function f;\n  s1 = x^65535*x;\n  s2 = s1^65535;\n  f = s2*s1*x - 2;\nEND;\n",
    );
    // Degree 2^20 + 1 by products within the exponent limit.
    let product = bertini(
        "product.bertini",
        "  s = x^65535*x;\n  f = s*s*s*s*s*s*s*s*s*s*s*s*s*s*s*s*x - 1;\n  g = y;\n",
    );
    let cases: Vec<(Vec<&str>, Vec<&str>)> = vec![
        (
            vec![&nan],
            vec!["line 5", "'1e308*1e308' in c", "not finite"],
        ),
        (
            vec![&nan_difference],
            vec!["line 4", "in f", "not finite", "NaN"],
        ),
        (
            vec![&wrap],
            vec![
                "line 5",
                "'s1^65535' in s2",
                "4294901760",
                "beyond the limit of 1048576 (2^20)",
            ],
        ),
        (
            vec![&product],
            vec!["line 5", "in f", "1048577", "limit of 1048576"],
        ),
    ];
    for (args, needles) in cases {
        let mut all = vec!["solve"];
        all.extend(&args);
        assert_refused(&kinsyn(&all), &format!("{args:?}"), &needles);
    }
}

/// 21 equations of degree 2: Bézout 2²¹ = 2097152 paths, over `MAX_PATHS` = 2²⁰ (the most
/// `--max-paths` takes): refused at once, before any path is tracked.
#[test]
fn too_many_paths_are_refused_at_once() {
    assert_eq!(kinsyn::homotopy::MAX_PATHS, 1 << 20);
    let dir = tempfile::tempdir().unwrap();
    let file = write(
        dir.path(),
        "q21.bertini",
        power_system(21, 2, false).as_bytes(),
    );
    let clock = std::time::Instant::now();
    let o = kinsyn(&["solve", &file]);
    assert!(clock.elapsed().as_secs_f64() < 5.0, "{:?}", clock.elapsed());
    assert_refused(
        &o,
        "21 quadrics",
        &["2097152 paths", "--max-paths", "1048576 = 2^20"],
    );
}

/// A rotation from its rotation vector (nalgebra's exponential, not kinsyn's).
fn rotation(v: &Value) -> Matrix3<f64> {
    let r = &v["rotation_vector_rad"];
    Rotation3::new(Vector3::new(
        r[0].as_f64().unwrap(),
        r[1].as_f64().unwrap(),
        r[2].as_f64().unwrap(),
    ))
    .into_inner()
}

fn position(v: &Value) -> Vector3<f64> {
    let t = &v["position"];
    Vector3::new(
        t[0].as_f64().unwrap(),
        t[1].as_f64().unwrap(),
        t[2].as_f64().unwrap(),
    )
}

fn point(v: &Value) -> Vector3<f64> {
    Vector3::new(
        v[0].as_f64().unwrap(),
        v[1].as_f64().unwrap(),
        v[2].as_f64().unwrap(),
    )
}

/// One leg of a description: base point, platform point (platform frame), first joint axis.
type Leg = (Vector3<f64>, Vector3<f64>, Option<Vector3<f64>>);

/// The legs of a description.
fn legs(file: &Path) -> Vec<Leg> {
    let m: Value = serde_json::from_str(&std::fs::read_to_string(file).unwrap()).unwrap();
    assert_eq!(
        m["platform"]["position"],
        serde_json::json!([0.0, 0.0, 1.0])
    );
    assert_eq!(
        m["platform"]["orientation"],
        serde_json::json!([0.0, 0.0, 0.0])
    );
    assert_eq!(m["platform"]["point"], serde_json::json!([0.0, 0.0, 0.0]));
    m["legs"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| {
            (
                point(&l["base"]),
                point(&l["platform"]),
                l.get("axes").map(|a| point(&a[0])),
            )
        })
        .collect()
}

/// Reflection through the plane z = 0. Base points at z = 0 and platform points at z = 0 of
/// the platform frame: if (R, t) puts platform point p at R p + t, then (M R M, M t) puts it at
/// M R M p + M t = M (R p + t) (M p = p), the mirror image, at the same distance from the base
/// point b = M b; M R M is a rotation (det 1). A horizontal R axis keeps its plane through b
/// mirror-symmetric too. So the real assemblies come in pairs z ↔ −z.
fn assert_mirror_pairs(assemblies: &[Value]) {
    let m = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, -1.0));
    for a in assemblies {
        let (r, t) = (m * rotation(a) * m, m * position(a));
        assert!(
            assemblies
                .iter()
                .any(|b| (rotation(b) - r).amax() < 1e-8 && (position(b) - t).amax() < 1e-8),
            "no mirror image of {a}"
        );
    }
}

/// The 3-RPS direct kinematics has 16 complex solutions (J. Schadlbauer, D. R. Walter,
/// M. L. Husty, "The 3-RPS parallel manipulator from an algebraic viewpoint", Mech. Mach.
/// Theory 75, 2014). Each real assembly is checked here from the file: every platform point at
/// its reference leg length from its base point (the P joints at their reference value 0), and
/// in the plane through the base point normal to its R axis.
#[test]
fn three_rps_has_16_assemblies_8_real_with_the_reference() {
    let file = "mechanisms/3-rps.json";
    let v = json(&["analyze", file, "--all-assemblies", "--json"]);
    assert_eq!(count(&v, "nonsingular"), 16);
    assert_eq!(count(&v, "certified"), 16);
    assert_eq!(count(&v, "real"), 8);
    let real = v["real_assemblies"].as_array().unwrap();
    assert_eq!(real.len(), 8);
    assert_eq!(v["complex_assemblies"].as_array().unwrap().len(), 8);
    let legs = legs(&root().join(file));
    let reference = Vector3::new(0.0, 0.0, 1.0);
    for a in real {
        assert_eq!(a["certified"], true, "{a}");
        let (r, t) = (rotation(a), position(a));
        for (b, p, axis) in &legs {
            let length = (reference + p - b).norm();
            let leg = r * p + t - b;
            assert!(
                (leg.norm() - length).abs() < 1e-9,
                "{a}: {} ≠ {length}",
                leg.norm()
            );
            assert!(leg.dot(&axis.unwrap()).abs() < 1e-9, "{a}: off the R plane");
        }
    }
    let marked: Vec<&Value> = real
        .iter()
        .filter(|a| a["continued_from_reference"] == true)
        .collect();
    assert_eq!(marked.len(), 1);
    assert!((position(marked[0]) - reference).amax() < 1e-9);
    assert!((rotation(marked[0]) - Matrix3::identity()).amax() < 1e-9);
    // The pose text in full, as --pose takes it (the reference: the file's platform frame).
    assert_eq!(marked[0]["pose"], "0,0,1,0,0,0");
    assert_mirror_pairs(real);
}

/// The 6-UPS at the brief's inputs: every real assembly puts each platform point at the leg
/// length reference + input from its base point, computed here from the file.
#[test]
fn six_ups_assemblies_have_the_leg_lengths_and_come_in_mirror_pairs() {
    let file = "mechanisms/6-ups.json";
    let inputs = [0.05, -0.03, 0.02, 0.04, -0.01, 0.03];
    let text: Vec<String> = inputs
        .iter()
        .enumerate()
        .map(|(i, x)| format!("P{}.3={x}", i + 1))
        .collect();
    let v = json(&[
        "analyze",
        file,
        "--inputs",
        &text.join(","),
        "--all-assemblies",
        "--json",
    ]);
    let real = v["real_assemblies"].as_array().unwrap();
    assert!(!real.is_empty());
    assert_eq!(count(&v, "real"), real.len() as u64);
    assert_eq!(real.len() % 2, 0, "mirror pairs");
    let legs = legs(&root().join(file));
    let reference = Vector3::new(0.0, 0.0, 1.0);
    for a in real {
        assert_eq!(a["certified"], true, "{a}");
        let (r, t) = (rotation(a), position(a));
        for ((b, p, _), input) in legs.iter().zip(inputs) {
            let length = (reference + p - b).norm() + input;
            let leg = (r * p + t - b).norm();
            assert!((leg - length).abs() < 1e-9, "{a}: {leg} ≠ {length}");
        }
    }
    assert_mirror_pairs(real);
    // The assembly continued from the reference is one of them, near the reference pose.
    let marked: Vec<&Value> = real
        .iter()
        .filter(|a| a["continued_from_reference"] == true)
        .collect();
    assert_eq!(marked.len(), 1);
    assert!((position(marked[0]) - reference).norm() < 0.2);
}

/// A Gough–Stewart platform with planar base and platform in general position has 40 complex
/// assemblies (J.-C. Faugère, D. Lazard, "Combinatorial classes of parallel manipulators",
/// Mech. Mach. Theory 30(6), 1995: the generic planar class keeps the 40 of the general
/// platform), in mirror pairs (an even count).
#[test]
fn a_generic_planar_six_ups_has_40_assemblies() {
    let dir = tempfile::tempdir().unwrap();
    let base = [
        [1.03, 0.05],
        [0.46, 0.91],
        [-0.55, 0.80],
        [-0.97, -0.08],
        [-0.42, -0.90],
        [0.58, -0.83],
    ];
    let platform = [
        [0.41, 0.22],
        [0.33, 0.38],
        [-0.40, 0.27],
        [-0.52, 0.10],
        [-0.03, -0.55],
        [0.15, -0.45],
    ];
    let legs: Vec<Value> = base
        .iter()
        .zip(&platform)
        .map(|(b, p)| {
            serde_json::json!({"chain": "UP!S", "base": [b[0], b[1], 0.0], "platform": [p[0], p[1], 0.0]})
        })
        .collect();
    let m = serde_json::json!({
        "format": "kinsyn-manipulator/1",
        "name": "planar 6-UPS",
        "units": {"length": "m", "angle": "deg"},
        "platform": {"position": [0.0, 0.0, 1.0], "orientation": [0.0, 0.0, 0.0], "point": [0.0, 0.0, 0.0]},
        "legs": legs,
    });
    let file = write(dir.path(), "planar.json", m.to_string().as_bytes());
    for seed in ["1", "2", "2026"] {
        let v = json(&[
            "analyze",
            &file,
            "--all-assemblies",
            "--seed",
            seed,
            "--json",
        ]);
        assert_eq!(
            count(&v, "nonsingular"),
            40,
            "seed {seed}: {}",
            v["summary"]
        );
    }
}

/// Bad input to `--all-assemblies`: one line, exit 2.
#[test]
fn bad_all_assemblies_input_is_one_line_and_exit_2() {
    let ups = "mechanisms/6-ups.json";
    assert_refused(
        &kinsyn(&["analyze", ups, "--all-assemblies", "--pose", "0,0,1,0,0,0"]),
        "with --pose",
        &["'--all-assemblies' cannot be used with '--pose"],
    );
    // The HEXA's unknowns by hand: the platform linkage's 15 bodies joined by 15 revolutes
    // (one loop, the four-bar's) are one block, the root's 8 Study parameters and 14 hinge
    // tangents; the six upper bars join it, each through its crank leg R!R whose second
    // revolute is an unknown: 8 + 14 + 6 = 28.
    assert_refused(
        &kinsyn(&["analyze", "mechanisms/6-ruu-hexa.json", "--all-assemblies"]),
        "the HEXA (its platform linkage held by six crank-and-bar limbs: 28 unknowns)",
        &[
            "--all-assemblies: the total-degree start system has",
            "paths in 28 unknowns",
            "more than the limit",
        ],
    );
    assert_refused(
        &kinsyn(&["analyze", ups, "--all-assemblies", "--inputs", "P7.3=0.1"]),
        "unknown actuator",
        &["\"P7.3\" is not an actuator of 6-UPS"],
    );
    assert_refused(
        &kinsyn(&["analyze", ups, "--all-assemblies", "--inputs", "P1.3=nan"]),
        "NaN input",
        &["not a finite number"],
    );
}

/// Shard files 1/3, 2/3, 3/3 of cyclic-5 with seed 4 in `dir`, written by three processes,
/// listed 3, 1, 2.
fn cyclic5_parts(dir: &Path) -> Vec<String> {
    let part = |k: usize| dir.join(format!("part{k}.json"));
    for k in 1..=3 {
        let o = kinsyn(&[
            "solve",
            "examples/systems/cyclic5.bertini",
            "--seed",
            "4",
            "--shard",
            &format!("{k}/3"),
            "--out",
            part(k).to_str().unwrap(),
        ]);
        assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
        assert!(
            stdout(&o).contains(&format!("shard {k}/3")),
            "{}",
            stdout(&o)
        );
    }
    [3, 1, 2]
        .iter()
        .map(|k| part(*k).to_str().unwrap().to_string())
        .collect()
}

/// `kinsyn solve --shard K/N --out PART` in three processes and `--merge` of the parts (in
/// another order) print the report of one process: every solution's coordinates to the bit,
/// the counts, the start.
#[test]
fn shards_merged_print_the_one_process_report() {
    let dir = tempfile::tempdir().unwrap();
    let file = "examples/systems/cyclic5.bertini";
    let parts = cyclic5_parts(dir.path());
    let mut args = vec!["solve", file, "--seed", "4", "--json", "--merge"];
    args.extend(parts.iter().map(String::as_str));
    let merged = json(&args);
    let one = json(&["solve", file, "--seed", "4", "--json"]);
    for key in [
        "start",
        "paths",
        "nonsingular",
        "singular",
        "at_infinity",
        "failed",
        "complete",
        "certified",
        "retracked",
    ] {
        assert_eq!(merged[key], one[key], "{key}");
    }
    assert_eq!(merged["solutions"], one["solutions"]);
    // Cyclic-5's 70 roots (Björck & Fröberg 1991).
    assert_eq!(solutions(&merged).len(), 70);
}

/// A part missing, given twice, of another seed or system, a file that is no shard, a bad K/N
/// or --runs with --shard are refused in one line, and nothing is written.
#[test]
fn shards_that_make_no_solve_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let file = "examples/systems/cyclic5.bertini";
    let parts = cyclic5_parts(dir.path());
    let refused = |args: &[&str], needles: &[&str]| {
        assert_refused(&kinsyn(args), &format!("{args:?}"), needles);
    };
    refused(
        &[
            "solve", file, "--seed", "4", "--merge", &parts[0], &parts[1],
        ],
        &["missing shard 2/3"],
    );
    refused(
        &[
            "solve", file, "--seed", "4", "--merge", &parts[0], &parts[0], &parts[1], &parts[2],
        ],
        &["given twice"],
    );
    refused(
        &[
            "solve", file, "--seed", "5", "--merge", &parts[0], &parts[1], &parts[2],
        ],
        &["shard of another solve"],
    );
    refused(
        &[
            "solve",
            "examples/systems/katsura5.bertini",
            "--seed",
            "4",
            "--merge",
            &parts[0],
        ],
        &["shard of another solve"],
    );
    let junk = write(dir.path(), "junk.json", b"{\"kind\": 3");
    refused(
        &["solve", file, "--merge", &junk],
        &["not a kinsyn solve shard file"],
    );
    let out = dir.path().join("x.json");
    for bad in ["0/3", "4/3", "3", "a/b", "1/0"] {
        refused(
            &[
                "solve",
                file,
                "--shard",
                bad,
                "--out",
                out.to_str().unwrap(),
            ],
            &["--shard", "1-based"],
        );
    }
    refused(
        &[
            "solve",
            file,
            "--runs",
            "2",
            "--shard",
            "1/2",
            "--out",
            out.to_str().unwrap(),
        ],
        &["a sharded solve is one run"],
    );
    assert!(!out.exists(), "nothing written by a refused shard");
}
