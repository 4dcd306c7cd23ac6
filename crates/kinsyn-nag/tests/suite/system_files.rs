//! System files: Bertini input files read and written (checked against polynomials built by
//! hand, every error class, exact round trips), and `PHCpack` run on systems whose solutions
//! are known from the literature or by hand. The `PHCpack` tests skip, with a notice, when
//! `phc` is not installed.

use kinsyn_nag::poly::bertini::{self, BertiniErrorKind};
use kinsyn_nag::poly::phc::{self, PhcClass, PhcError};
use kinsyn_nag::poly::{C64, Poly, System};
use proptest::prelude::*;
use std::path::PathBuf;
use std::time::Duration;

fn c(re: f64, im: f64) -> C64 {
    C64::new(re, im)
}

fn names(list: &[&str]) -> Vec<String> {
    list.iter().map(|s| (*s).to_string()).collect()
}

fn example(name: &str) -> String {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/systems/");
    std::fs::read_to_string(format!("{path}{name}")).expect("the sample file exists")
}

// ---------------------------------------------------------------------------------------
// Reading Bertini files

#[test]
fn a_hand_written_file_reads_as_the_polynomials_built_by_hand() {
    let text = "\
% a test file: every construct kinsyn reads
CONFIG
  MPType: 0;   % double precision
  FinalTol: 1e-11;
END;
INPUT
  variable_group x, y;
  variable_group z;
  function f, g, h;
  constant c, d;
  c = 2.5 + 3*I;
  d = .5e1;          % 5
  s = x*y;           % a subfunction
  f = c*s^2 - z/4 + 2E+3;
  g = -(x - 1.5e-3)*(y + 1) + d*z^3;
  h = Pi*x - (2 - I)*z/2 + s;
END;
";
    let input = bertini::parse(text).unwrap();
    let (x, y, z) = (
        Poly::variable(3, 0),
        Poly::variable(3, 1),
        Poly::variable(3, 2),
    );
    let s = &x * &y;
    let f =
        Poly::constant(3, c(2.5, 3.0)) * s.pow(2) - z.scale(c(0.25, 0.0)) + Poly::real(3, 2000.0);
    let g = -(&x - Poly::real(3, 0.0015)) * (&y + Poly::real(3, 1.0)) + z.pow(3) * 5.0;
    let h = x.scale(c(std::f64::consts::PI, 0.0)) - z.scale(c(1.0, -0.5)) + &s;
    let expected = System::new(names(&["x", "y", "z"]), vec![f, g, h])
        .unwrap()
        .with_groups(vec![vec![0, 1], vec![2]])
        .unwrap();
    assert_eq!(input.system, expected);
    assert_eq!(input.functions, names(&["f", "g", "h"]));
    assert_eq!(
        input.config,
        vec![
            ("MPType".to_string(), "0".to_string()),
            ("FinalTol".to_string(), "1e-11".to_string())
        ]
    );
    assert_eq!(
        input.constants,
        vec![
            ("c".to_string(), c(2.5, 3.0)),
            ("d".to_string(), c(5.0, 0.0))
        ]
    );
    assert!(!input.homogeneous);
    // The multi-homogeneous Bézout number of {x, y}{z} by hand: degrees (4,1), (2,3), (2,1);
    // the coefficient of a^2 b in (4a + b)(2a + 3b)(2a + b) is 4·2·1 + 4·3·2 + 1·2·2 = 36.
    assert_eq!(input.system.multihomogeneous_bezout(), Some(36));
}

#[test]
fn variable_and_hom_variable_group_declarations() {
    let text = "INPUT\n variable a;\n variable b, c;\n function f;\n f = a*b*c - 1;\nEND;\n";
    let input = bertini::parse(text).unwrap();
    assert_eq!(input.system.groups(), &[vec![0, 1, 2]]);
    let text = "INPUT\n hom_variable_group p, q;\n variable_group x;\n function f, g;\n \
                f = p*x - q;\n g = p^2 - q^2*x;\nEND;\n";
    let input = bertini::parse(text).unwrap();
    assert!(input.homogeneous);
    assert_eq!(input.homogeneous_groups, vec![0]);
    assert_eq!(input.system.groups(), &[vec![0, 1], vec![2]]);
}

/// Katsura-n from its definition (Katsura 1990, in the form of the `PoSSo` test suite): for
/// `m = 0..n-1`, `Σ_{l=-n..n} u_|l| u_|m-l| − u_m` (terms with an index above `n` vanish),
/// and `u_0 + 2 Σ_{l≥1} u_l − 1`.
fn katsura(n: usize) -> System {
    let v = n + 1;
    let u = |k: i64| -> Poly {
        let k = usize::try_from(k.unsigned_abs()).unwrap();
        if k > n {
            Poly::zero(v)
        } else {
            Poly::variable(v, k)
        }
    };
    let n_i = i64::try_from(n).unwrap();
    let mut equations = Vec::new();
    for m in 0..n_i {
        let mut p = -u(m);
        for l in -n_i..=n_i {
            p = p + u(l) * u(m - l);
        }
        equations.push(p);
    }
    let mut norm = u(0) - Poly::real(v, 1.0);
    for l in 1..=n_i {
        norm = norm + u(l) * 2.0;
    }
    equations.push(norm);
    System::new((0..v).map(|k| format!("u{k}")).collect(), equations).unwrap()
}

/// Cyclic-n from its definition: `Σ_i Π_{j<k} x_((i+j) mod n)` for `k = 1..n-1`, and
/// `x_1⋯x_n − 1`.
fn cyclic(n: usize) -> System {
    let mut equations = Vec::new();
    for k in 1..n {
        let mut p = Poly::zero(n);
        for i in 0..n {
            let mut m = Poly::real(n, 1.0);
            for j in 0..k {
                m = m * Poly::variable(n, (i + j) % n);
            }
            p = p + m;
        }
        equations.push(p);
    }
    let all = (0..n).fold(Poly::real(n, 1.0), |m, j| m * Poly::variable(n, j));
    equations.push(all - Poly::real(n, 1.0));
    System::new((1..=n).map(|k| format!("x{k}")).collect(), equations).unwrap()
}

#[test]
fn the_sample_files_are_the_systems_of_their_definitions() {
    let k5 = bertini::parse(&example("katsura5.bertini")).unwrap();
    assert_eq!(k5.system, katsura(5));
    assert_eq!(k5.system.bezout_number(), 32);
    let c5 = bertini::parse(&example("cyclic5.bertini")).unwrap();
    assert_eq!(c5.system, cyclic(5));
    let cl = bertini::parse(&example("circle-line.bertini")).unwrap();
    let (x, y) = (Poly::variable(2, 0), Poly::variable(2, 1));
    let circle = &x * &x + &y * &y - Poly::real(2, 1.0);
    assert_eq!(
        cl.system,
        System::new(names(&["x", "y"]), vec![circle, &x - &y]).unwrap()
    );
    assert_eq!(cl.config, vec![("TrackType".to_string(), "0".to_string())]);
}

// ---------------------------------------------------------------------------------------
// Errors: one line each, with the line number

fn error(text: &str) -> (usize, String) {
    let e = bertini::parse(text).expect_err("the file is invalid");
    let message = e.to_string();
    assert!(!message.contains('\n'), "one line: {message}");
    assert!(
        message.starts_with(&format!("line {}: ", e.line)),
        "{message}"
    );
    (e.line, message)
}

fn input(body: &str) -> String {
    format!("INPUT\n  variable_group x, y;\n  function f1, f2;\n{body}END;\n")
}

#[test]
fn an_unknown_name_is_named_with_its_line_and_function() {
    let text = "% line 1\n%\nINPUT\n  variable_group x, y;\n  function f1, f2;\n  \
                f1 = x + y;\n  f2 = x*z - 1;\nEND;\n";
    let e = bertini::parse(text).unwrap_err();
    assert_eq!(e.to_string(), "line 7: unknown name 'z' in f2");
    assert_eq!(
        e.kind,
        BertiniErrorKind::UnknownName {
            name: "z".into(),
            context: "f2".into()
        }
    );
}

#[test]
fn non_polynomial_expressions_are_refused() {
    // (body, line of the offence, words the message must contain)
    let cases: [(&str, usize, &str); 7] = [
        (
            "  f1 = sin(x);\n  f2 = y;\n",
            4,
            "'sin(…)' in f1 is not polynomial",
        ),
        ("  f1 = x;\n  f2 = exp(y) - 1;\n", 5, "'exp(…)' in f2"),
        (
            "  f1 = x;\n  f2 = 1/(x + 1);\n",
            5,
            "division by '(x+1)' in f2",
        ),
        ("  f1 = x/y;\n  f2 = y;\n", 4, "division by 'y'"),
        ("  f1 = x^0.5;\n  f2 = y;\n", 4, "the power '^0.5' in f1"),
        ("  f1 = x^(-1);\n  f2 = y;\n", 4, "the power '^(-1)'"),
        ("  f1 = x;\n  f2 = x^y;\n", 5, "the power '^y' in f2"),
    ];
    for (body, line, words) in cases {
        let (l, m) = error(&input(body));
        assert_eq!(l, line, "{m}");
        assert!(m.contains(words), "{m} lacks {words}");
        assert!(m.contains("not polynomial"), "{m}");
    }
}

#[test]
fn unsupported_constructs_say_why() {
    let (l, m) = error("INPUT\n  variable_group x;\n  pathvariable t;\n  function f;\nEND;\n");
    assert_eq!(l, 3);
    assert!(
        m.contains("'pathvariable'") && m.contains("parameter homotopy"),
        "{m}"
    );
    let (l, m) = error("INPUT\n  variable_group x;\n  parameter p;\n  function f;\nEND;\n");
    assert_eq!(l, 3);
    assert!(
        m.contains("'parameter'") && m.contains("parameter homotopy"),
        "{m}"
    );
    for word in ["random", "random_real"] {
        let (l, m) = error(&format!(
            "INPUT\n  variable_group x;\n  function f;\n  {word} r;\n  f = r*x;\nEND;\n"
        ));
        assert_eq!(l, 4);
        assert!(
            m.contains(&format!("'{word}'")) && m.contains("constant"),
            "{m}"
        );
    }
}

#[test]
fn declaration_and_syntax_errors_name_their_line() {
    let cases: [(String, usize, &str); 19] = [
        (
            input("  f1 = x;\n  f2 = 1e400*y;\n"),
            5,
            "'1e400' is beyond the range",
        ),
        (
            "INPUT\n  variable_group x;\n  s = x;\n  variable_group y;\n  function f;\n  \
             f = s + y;\nEND;\n"
                .into(),
            4,
            "variables must be declared before the first assignment",
        ),
        (input("  f1 = x;\n"), 3, "function 'f2' is never defined"),
        (
            "INPUT\n  variable_group x, y;\n  variable_group x;\n  function f;\n  f = x;\nEND;\n"
                .into(),
            3,
            "'x' is declared twice",
        ),
        (input("  f1 = x\n  f2 = y;\n"), 4, "missing ';'"),
        (
            input("  f1 = x;\n  f2 = y;\n").replace("END;\n", ""),
            5,
            "no 'END;'",
        ),
        ("CONFIG\n  MPType: 0;\nEND;\n".into(), 3, "no 'INPUT"),
        (
            input("  f1 = (x + y;\n  f2 = y;\n"),
            4,
            "'(' without its ')'",
        ),
        (
            input("  f1 = x;\n  f2 = 2y;\n"),
            5,
            "write products with '*'",
        ),
        (input("  f1 = x y;\n  f2 = y;\n"), 4, "unexpected 'y'"),
        (
            input("  f1 = x;\n  f2 = y # 1;\n"),
            5,
            "unexpected character '#'",
        ),
        (input("  f1 = x;\n  f2 = y/0;\n"), 5, "division by zero"),
        (
            input("  x = 1;\n  f1 = x;\n  f2 = y;\n"),
            4,
            "'x' is a variable",
        ),
        (
            input("  f1 = x;\n  f2 = y;\n  f1 = y;\n"),
            6,
            "'f1' is assigned twice",
        ),
        (
            input("  constant k;\n  k = x + 1;\n  f1 = x;\n  f2 = y;\n"),
            5,
            "constant 'k' is assigned an expression in the variables",
        ),
        (
            input("  constant k;\n  f1 = k*x;\n  f2 = y;\n  k = 2;\n"),
            5,
            "constant 'k' is used in f1 before it is assigned",
        ),
        (
            "CONFIG\n  MPType 0;\nEND;\nINPUT\n variable_group x;\n function f;\n f = x;\nEND;\n"
                .into(),
            2,
            "is not 'key: value;'",
        ),
        (
            "INPUT\n  variable x;\n  variable_group y;\n  function f;\n  f = x;\nEND;\n".into(),
            3,
            "'variable' and 'variable_group' cannot both",
        ),
        (
            format!("{}x = 1;\n", input("  f1 = x;\n  f2 = y;\n")),
            7,
            "after the INPUT section's END",
        ),
    ];
    for (text, line, words) in cases {
        let (l, m) = error(&text);
        assert_eq!(l, line, "{m}\nin\n{text}");
        assert!(m.contains(words), "{m} lacks {words}");
    }
}

// ---------------------------------------------------------------------------------------
// Round trips

fn round_trip(s: &System) {
    let text = bertini::write(s);
    let back = bertini::parse(&text).unwrap_or_else(|e| panic!("{e}\n{text}"));
    assert_eq!(&back.system, s, "\n{text}");
}

#[test]
fn written_files_read_back_exactly() {
    let (x, y) = (Poly::variable(2, 0), Poly::variable(2, 1));
    let awkward = Poly::from_terms(
        2,
        [
            (vec![3, 1], c(0.1, -1e-300)),
            (vec![0, 2], c(-f64::MIN_POSITIVE / 8.0, 0.0)),
            (vec![1, 0], c(-1.0, 0.0)),
            (vec![0, 1], c(1.0, 0.0)),
            (vec![0, 0], c(-7.25e15, 3.0e22)),
            (vec![2, 2], c(-0.0, -2.0)),
            (vec![1, 1], c(f64::MAX, f64::EPSILON)),
        ],
    );
    let systems = [
        bertini::parse(&example("circle-line.bertini"))
            .unwrap()
            .system,
        katsura(5),
        cyclic(5),
        System::new(names(&["x", "y"]), vec![awkward, &x * &y - x.pow(3)]).unwrap(),
        System::new(names(&["x", "y"]), vec![Poly::zero(2), Poly::real(2, -1.0)])
            .unwrap()
            .with_groups(vec![vec![0], vec![1]])
            .unwrap(),
        // a variable named like the written functions
        System::new(names(&["f1", "f2_"]), vec![x.clone(), y.clone()]).unwrap(),
    ];
    for s in &systems {
        round_trip(s);
    }
}

#[test]
fn names_bertini_cannot_read_are_renamed_and_groups_reordered() {
    let (x, y, z) = (
        Poly::variable(3, 0),
        Poly::variable(3, 1),
        Poly::variable(3, 2),
    );
    let eqs = vec![&x * &y - Poly::real(3, 2.0), &y + &z, &x - z.pow(2)];
    let s = System::new(names(&["θ", "I", "v1"]), eqs.clone()).unwrap();
    let back = bertini::parse(&bertini::write(&s)).unwrap().system;
    assert_eq!(back.variables(), &names(&["v1_", "v2", "v1"]));
    assert_eq!(back.equations(), s.equations());
    // Groups {z}{x, y}: the file declares z first, so the variables come back in the order
    // z, x, y — the same system with variable k renumbered by [1, 2, 0].
    let s = System::new(names(&["x", "y", "z"]), eqs.clone())
        .unwrap()
        .with_groups(vec![vec![2], vec![0, 1]])
        .unwrap();
    let back = bertini::parse(&bertini::write(&s)).unwrap().system;
    let map = [1, 2, 0];
    let expected = System::new(
        names(&["z", "x", "y"]),
        eqs.iter().map(|p| p.relabel(3, &map)).collect(),
    )
    .unwrap()
    .with_groups(vec![vec![0], vec![1, 2]])
    .unwrap();
    assert_eq!(back, expected);
}

fn coefficient() -> impl Strategy<Value = C64> {
    let real = prop::num::f64::NORMAL | prop::num::f64::SUBNORMAL | prop::num::f64::ZERO;
    let small = (-1000i32..1000).prop_map(|k| f64::from(k) / 8.0);
    let part = prop_oneof![real, small];
    (part.clone(), prop_oneof![Just(0.0), part]).prop_map(|(a, b)| C64::new(a, b))
}

fn random_system() -> impl Strategy<Value = System> {
    (1usize..=4, 1usize..=4).prop_flat_map(|(n, m)| {
        let term = (prop::collection::vec(0u32..4, n), coefficient());
        let poly =
            prop::collection::vec(term, 0..6).prop_map(move |terms| Poly::from_terms(n, terms));
        // Contiguous groups: cut points between the variables.
        let cuts = prop::collection::vec(any::<bool>(), n - 1);
        (prop::collection::vec(poly, m), cuts).prop_map(move |(equations, cuts)| {
            let mut groups = vec![vec![0]];
            for (k, cut) in cuts.iter().enumerate() {
                if *cut {
                    groups.push(Vec::new());
                }
                groups.last_mut().unwrap().push(k + 1);
            }
            System::new((0..n).map(|k| format!("x{k}")).collect(), equations)
                .unwrap()
                .with_groups(groups)
                .unwrap()
        })
    })
}

proptest! {
    #[test]
    fn random_systems_round_trip_exactly(s in random_system()) {
        let text = bertini::write(&s);
        let back = bertini::parse(&text).map_err(|e| TestCaseError::fail(format!("{e}\n{text}")))?;
        prop_assert_eq!(back.system, s);
    }
}

// ---------------------------------------------------------------------------------------
// `PHCpack`: the input format

#[test]
fn phcpack_names_avoid_its_reserved_letters() {
    for bad in ["e", "E1", "eta", "i", "Ix", "I", "x[1]", "", "_x"] {
        assert!(!phc::is_valid_name(bad), "{bad}");
    }
    for good in ["x", "x1e2", "xi", "theta", "a_b", "u0"] {
        assert!(phc::is_valid_name(good), "{good}");
    }
    let s = System::new(
        names(&["e", "i", "x1", "y"]),
        (0..4).map(|k| Poly::variable(4, k)).collect(),
    )
    .unwrap();
    assert_eq!(phc::phc_names(&s), names(&["x1_", "x2", "x1", "y"]));
    // Non-square: the header gives equations and variables.
    let t = System::new(names(&["x", "y"]), vec![Poly::variable(2, 0)]).unwrap();
    assert!(phc::write(&t).starts_with("1 2\n"));
    assert!(phc::write(&s).starts_with("4\n"));
}

/// `PHCpack` 2.4.86's output for x² = 0, y − 1 = 0 (trimmed to its last solution list): the
/// double root (0, 1), which `PHCpack` reports with m = 2 and as singular.
const SINGULAR_OUTPUT: &str = "\
 2
x^2;
y-1;

ROOT COUNTS :

total degree : 2
1-homogeneous Bezout number : 2
  with partition : { y }
general linear-product Bezout number : 2
  based on the set structure :
     { x }{ x }
     { y }
mixed volume : 0
stable mixed volume : 2

TIMING INFORMATION for Root Counting

THE SOLUTIONS :

1 2
===========================================================================
solution 1 :    start residual :  0.000E+00   #deflations : 1   success
t :  1.00000000000000E+00   0.00000000000000E+00
m : 2
the solution for t :
 x :  0.00000000000000E+00   0.00000000000000E+00
 y :  1.00000000000000E+00   0.00000000000000E+00
== err :  0.000E+00 = rco :  0.000E+00 = res :  0.000E+00 = real singular ==
===========================================================================
A list of 1 solutions has been refined :
Seed used in random number generators : 11404.
";

fn singular_system() -> System {
    let (x, y) = (Poly::variable(2, 0), Poly::variable(2, 1));
    System::new(names(&["x", "y"]), vec![x.pow(2), y - Poly::real(2, 1.0)]).unwrap()
}

#[test]
fn phcpack_output_is_read() {
    let s = singular_system();
    let out = phc::parse_output(SINGULAR_OUTPUT, &s).unwrap();
    assert_eq!(out.solutions.len(), 1);
    let sol = &out.solutions[0];
    assert_eq!(sol.point, vec![c(0.0, 0.0), c(1.0, 0.0)]);
    assert_eq!(sol.multiplicity, 2);
    assert_eq!(sol.class, Some(PhcClass::RealSingular));
    assert!(!sol.is_regular());
    // By hand: total degree 2 · 1; x² is a single monomial, so no root has both coordinates
    // non-zero (mixed volume 0), while the stable mixed volume counts the double root (0, 1)
    // twice.
    assert_eq!(out.root_counts.total_degree, Some(s.bezout_number()));
    assert_eq!(s.bezout_number(), 2);
    assert_eq!(out.root_counts.multihomogeneous, Some((1, 2)));
    assert_eq!(out.root_counts.linear_product, Some(2));
    assert_eq!(out.root_counts.mixed_volume, Some(0));
    assert_eq!(out.root_counts.stable_mixed_volume, Some(2));
    assert_eq!(out.seed, Some(11404));
    // A list naming a variable the system does not have is an error.
    let other = System::new(names(&["x", "z"]), s.equations().to_vec()).unwrap();
    let e = phc::parse_output(SINGULAR_OUTPUT, &other).unwrap_err();
    assert!(e.to_string().contains("unknown variable 'y'"), "{e}");
}

// ---------------------------------------------------------------------------------------
// `PHCpack`: runs on systems with known solutions

fn phc_program() -> Option<PathBuf> {
    let found = phc::find_phc();
    if found.is_none() {
        eprintln!("notice: phc (PHCpack) is not on PATH; the PHCpack test is skipped");
    }
    found
}

/// The largest equation value at `x`, by kinsyn's own evaluation.
fn residual(s: &System, x: &[C64]) -> f64 {
    s.evaluate(x).iter().map(|v| v.norm()).fold(0.0, f64::max)
}

#[test]
fn phcpack_solves_the_circle_and_the_line() {
    let Some(program) = phc_program() else { return };
    let s = bertini::parse(&example("circle-line.bertini"))
        .unwrap()
        .system;
    let result = phc::solve(&s, &program).unwrap();
    let out = &result.output;
    assert_eq!(out.root_counts.total_degree, Some(s.bezout_number()));
    let mut real = out.real_solutions(1e-10);
    assert_eq!(real.len(), 2);
    real.sort_by(|a, b| a[0].total_cmp(&b[0]));
    let h = std::f64::consts::FRAC_1_SQRT_2;
    for (sol, sign) in real.iter().zip([-1.0, 1.0]) {
        assert!((sol[0] - sign * h).abs() < 1e-12 && (sol[1] - sign * h).abs() < 1e-12);
    }
    assert!(
        out.solutions
            .iter()
            .all(|s| s.class == Some(PhcClass::RealRegular))
    );
    assert!(result.wall_time > Duration::ZERO);
}

#[test]
fn phcpack_finds_the_roots_of_a_univariate_cubic() {
    let Some(program) = phc_program() else { return };
    let x = Poly::variable(1, 0);
    let p = (&x - Poly::real(1, 1.0)) * (&x - Poly::real(1, 2.0)) * (&x - Poly::real(1, 3.0));
    let s = System::new(names(&["x"]), vec![p]).unwrap();
    let out = phc::solve(&s, &program).unwrap().output;
    let mut roots: Vec<f64> = out.real_solutions(1e-10).iter().map(|r| r[0]).collect();
    roots.sort_by(f64::total_cmp);
    assert_eq!(roots.len(), 3);
    for (r, k) in roots.iter().zip([1.0, 2.0, 3.0]) {
        assert!((r - k).abs() < 1e-12, "{roots:?}");
    }
}

/// Checks that the finite solutions are `count` distinct regular roots of `s`.
fn check_roots(s: &System, out: &phc::PhcOutput, count: usize) {
    let finite = out.finite();
    assert_eq!(finite.len(), count);
    for sol in &finite {
        assert!(sol.is_regular(), "{sol:?}");
        assert!(residual(s, &sol.point) < 1e-10, "{sol:?}");
    }
    for (a, sa) in finite.iter().enumerate() {
        for sb in &finite[a + 1..] {
            let d = sa
                .point
                .iter()
                .zip(&sb.point)
                .map(|(u, v)| (u - v).norm())
                .fold(0.0, f64::max);
            assert!(d > 1e-6, "two equal roots {sa:?} {sb:?}");
        }
    }
}

#[test]
fn phcpack_finds_the_70_cyclic_5_roots_and_the_32_katsura_5_roots() {
    let Some(program) = phc_program() else { return };
    // Björck & Fröberg (1991): 70 isolated cyclic 5-roots; total degree 5! = 120.
    let c5 = bertini::parse(&example("cyclic5.bertini")).unwrap().system;
    let out = phc::solve(&c5, &program).unwrap().output;
    check_roots(&c5, &out, 70);
    assert_eq!(out.root_counts.total_degree, Some(120));
    assert_eq!(out.root_counts.mixed_volume, Some(70));
    // Katsura (1990): Katsura-n has 2^n solutions.
    let k5 = bertini::parse(&example("katsura5.bertini")).unwrap().system;
    let out = phc::solve(&k5, &program).unwrap().output;
    check_roots(&k5, &out, 32);
    assert_eq!(out.root_counts.total_degree, Some(k5.bezout_number()));
}

#[test]
fn phcpack_results_come_back_under_the_systems_own_names() {
    let Some(program) = phc_program() else { return };
    // e² = 1, i = 2e: (e, i) = (1, 2) and (−1, −2); `PHCpack` sees x1, x2.
    let (e, i) = (Poly::variable(2, 0), Poly::variable(2, 1));
    let s = System::new(
        names(&["e", "i"]),
        vec![e.pow(2) - Poly::real(2, 1.0), i - e * 2.0],
    )
    .unwrap();
    let mut real = phc::solve(&s, &program)
        .unwrap()
        .output
        .real_solutions(1e-10);
    real.sort_by(|a, b| a[0].total_cmp(&b[0]));
    assert_eq!(real.len(), 2);
    for (sol, sign) in real.iter().zip([-1.0, 1.0]) {
        assert!((sol[0] - sign).abs() < 1e-12 && (sol[1] - 2.0 * sign).abs() < 1e-12);
    }
}

#[test]
fn phcpack_reports_singular_roots_and_roots_at_infinity() {
    let Some(program) = phc_program() else { return };
    let out = phc::solve(&singular_system(), &program).unwrap().output;
    let finite = out.finite();
    assert_eq!(finite.len(), 1);
    assert!(!finite[0].is_regular());
    assert!(residual(&singular_system(), &finite[0].point) < 1e-10);
    // x² − y = 0 and x² − y = 1 have no common root: nothing finite may come back.
    let (x, y) = (Poly::variable(2, 0), Poly::variable(2, 1));
    let q = x.pow(2) - y;
    let s = System::new(names(&["x", "y"]), vec![q.clone(), q - Poly::real(2, 1.0)]).unwrap();
    let out = phc::solve(&s, &program).unwrap().output;
    assert!(out.finite().is_empty(), "{:?}", out.solutions);
}

#[test]
fn phcpack_runs_are_limited_and_bad_input_is_refused() {
    let square = bertini::parse(&example("cyclic5.bertini")).unwrap().system;
    let t = System::new(names(&["x", "y"]), vec![Poly::variable(2, 0)]).unwrap();
    let e = phc::solve(&t, std::path::Path::new("phc")).unwrap_err();
    assert!(
        matches!(
            e,
            PhcError::NotSquare {
                equations: 1,
                variables: 2
            }
        ),
        "{e}"
    );
    let e = phc::solve(&square, std::path::Path::new("/nonexistent/phc")).unwrap_err();
    assert!(matches!(e, PhcError::Io { .. }), "{e}");
    let Some(program) = phc_program() else { return };
    // Cyclic-5 takes `PHCpack` about 0.2 s: 1 ms is not enough.
    let e = phc::solve_within(&square, &program, Duration::from_millis(1)).unwrap_err();
    assert_eq!(e, PhcError::Timeout(Duration::from_millis(1)));
}

#[test]
fn phcpack_reads_complex_coefficients_as_written() {
    let Some(program) = phc_program() else { return };
    // x² = 2i·y, y = 1: x = ±(1 + i), since (1 + i)² = 2i. The coefficient −2i is written
    // `(0.0 - 2.0*i)`.
    let (x, y) = (Poly::variable(2, 0), Poly::variable(2, 1));
    let s = System::new(
        names(&["x", "y"]),
        vec![x.pow(2) + y.scale(c(0.0, -2.0)), y - Poly::real(2, 1.0)],
    )
    .unwrap();
    assert!(
        phc::write(&s).contains("(0.0 - 2.0*i)"),
        "{}",
        phc::write(&s)
    );
    let out = phc::solve(&s, &program).unwrap().output;
    let mut roots: Vec<C64> = out.finite().iter().map(|s| s.point[0]).collect();
    roots.sort_by(|a, b| a.re.total_cmp(&b.re));
    assert_eq!(roots.len(), 2);
    for (r, sign) in roots.iter().zip([-1.0, 1.0]) {
        assert!((r - c(sign, sign)).norm() < 1e-12, "{roots:?}");
    }
    assert!(
        out.solutions
            .iter()
            .all(|s| s.class == Some(PhcClass::ComplexRegular))
    );
}

proptest! {
    /// Whatever the text, reading gives a system or a one-line error, never a panic: random
    /// strings over Bertini's alphabet, and the sample file with a stretch cut out.
    #[test]
    fn reading_never_panics(
        text in "[ -~\n%;θ]{0,200}",
        cut in (0usize..1500, 0usize..60),
    ) {
        for t in [text.clone(), format!("INPUT\n{text}\nEND;\n")] {
            if let Err(e) = bertini::parse(&t) {
                prop_assert!(!e.to_string().contains('\n'));
            }
        }
        let sample = example("katsura5.bertini");
        let start = cut.0.min(sample.len());
        let end = (start + cut.1).min(sample.len());
        if sample.is_char_boundary(start) && sample.is_char_boundary(end) {
            let mutilated = format!("{}{}", &sample[..start], &sample[end..]);
            if let Err(e) = bertini::parse(&mutilated) {
                prop_assert!(!e.to_string().contains('\n'));
            }
        }
    }
}

proptest! {
    /// Random statements from Bertini's vocabulary, in an INPUT section: an error or a
    /// system, never a panic.
    #[test]
    fn random_statements_never_panic(words in prop::collection::vec(prop::sample::select(vec![
        "x", "y", "f", "g", "s", "c", "=", "+", "-", "*", "/", "^", "(", ")", "2", ".5", "0",
        "1e400", "I", "Pi", ";", ";", ";", "variable_group", "variable", "hom_variable_group",
        "function", "constant", "z", ",", "sin", "END", "INPUT", "CONFIG", ":",
    ]), 0..40)) {
        let text = format!(
            "INPUT\n variable_group x, y;\n function f;\n{}\n f = x;\nEND;\n",
            words.join(" ")
        );
        if let Err(e) = bertini::parse(&text) {
            prop_assert!(!e.to_string().contains('\n'));
        }
    }
}
