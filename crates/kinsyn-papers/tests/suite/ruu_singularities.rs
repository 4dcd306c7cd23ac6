//! Singular poses of paper 004's 4-RUU in its Schönflies modes (§5.1–5.2, eqs. 30–31), and
//! the angle form of the inputs (`InputMode::Angles`) that §5.2's θ = 180° needs.
//!
//! The mode `K1` is `x0 = x3 = 0` (platform upside down), `K2` is `x1 = x2 = 0`; in either, the
//! coplanarity equations g1–g4 vanish identically and the assemblies are the solutions of the
//! six equations g5–g8, g13, g14 in the six remaining Study parameters (a square system, §5:
//! "five constraint equations over five variables" after solving g13 for one of them). A pose
//! of the mode is singular when this 6×6 **mode Jacobian** drops below its generic rank 6
//! (the paper's 5×5 `det J1` / `det J2` are taken after solving g13 for one unknown, so they
//! may carry factors this determinant lacks). Two independent computations of where that happens: numerically with
//! kinsyn's derived equations (homotopy continuation, SVD), and exactly with Singular on the
//! printed equations (`data/paper004-constraints.txt`): eliminate the Study parameters from the
//! mode ideal plus the determinant's non-trivial factor. Both are compared with the printed
//! univariate polynomials of eqs. 30 and 31.

use kinsyn::homotopy::{SolveSettings, StartSystem, solve};
use kinsyn::poly::{C64, Poly, System};
use kinsyn::spatial::{Displacement, study};
use kinsyn_papers::ruu::{InputMode, Ruu};
use nalgebra::{DMatrix, Rotation3, Translation3, Unit, Vector3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::f64::consts::{FRAC_PI_2, PI};
use std::fmt::Write as _;

use crate::common::singular;

/// Eq. 30 as printed (§5.1, K1 at `t11 = −2, t12 = −1, t13 = 1/2`), coefficients of
/// `t14^14 … t14^0` (the paper writes `t4` for `t14`).
const EQ30: [i128; 15] = [
    2_028_993_300,
    -16_353_282_060,
    62_397_559_157,
    -149_262_975_886,
    248_592_910_386,
    -303_624_070_978,
    279_023_850_507,
    -193_904_900_892,
    100_410_321_408,
    -37_073_611_168,
    8_730_261_899,
    -928_156_246,
    -54_729_862,
    18_830_830,
    -1_000_395,
];

/// Eq. 31 (§5.2, K2 at `t11 = 0, t12 = 1, t13 = 0`), coefficients of `t14^18 … t14^0`, with two
/// repairs of the printed text: the leading term is printed `99544625 t14^8` (a degree-18
/// polynomial whose next term is `t14^17`: the exponent lost its `1`), and the coefficient of
/// `t14^13` is broken across two printed lines as `−175591` / `6864`, read as `−1755916864`
/// (as `9288810578` is, printed `92888105` / `78`). `eq31_reconstruction_has_exact_roots` checks
/// the repair.
const EQ31: [i128; 19] = [
    99_544_625,
    -1_042_686_200,
    4_293_155_895,
    -9_293_913_184,
    10_513_736_564,
    -1_755_916_864,
    -14_239_053_636,
    24_856_530_336,
    -20_314_694_418,
    4_683_758_224,
    9_288_810_578,
    -13_708_185_120,
    10_456_187_332,
    -5_370_369_152,
    1_960_220_428,
    -507_121_440,
    89_099_433,
    -9_580_248,
    476_847,
];

/// A Schönflies mode of §4.3 (eq. 23).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Mode {
    /// `x0 = x3 = 0`.
    K1,
    /// `x1 = x2 = 0`.
    K2,
}

impl Mode {
    /// The Study parameters (indices into x0 … y3) that vary in the mode.
    fn free(self) -> [usize; 6] {
        match self {
            Mode::K1 => [1, 2, 4, 5, 6, 7],
            Mode::K2 => [0, 3, 4, 5, 6, 7],
        }
    }

    /// The two Study parameters that vanish in the mode.
    fn zero(self) -> [usize; 2] {
        match self {
            Mode::K1 => [0, 3],
            Mode::K2 => [1, 2],
        }
    }

    fn names(self) -> Vec<String> {
        let all = ["x0", "x1", "x2", "x3", "y0", "y1", "y2", "y3"];
        self.free().iter().map(|i| all[*i].to_string()).collect()
    }

    /// The platform's height `z` over the base up to a non-zero factor, in the mode's
    /// coordinates (`M_T` of eq. 5): `x2 y1 − x1 y2` in K1, `x3 y0 − x0 y3` in K2 (the paper's
    /// factors `y2 = 0` and `y3 = 0` after solving g13).
    fn height(self, x: &[C64]) -> C64 {
        match self {
            Mode::K1 => x[1] * x[3] - x[0] * x[4],
            Mode::K2 => x[1] * x[2] - x[0] * x[5],
        }
    }
}

/// `p` with the variables `subs` set to constants, in a ring whose variable `k` is `keep[k]`
/// of `p`'s ring (every other variable must have been substituted).
fn restrict(p: &Poly, subs: &[(usize, C64)], keep: &[usize]) -> Poly {
    let n = p.nvars();
    let mut q = p.clone();
    for (i, c) in subs {
        q = q.substitute(*i, &Poly::constant(n, *c));
    }
    let mut map = vec![0; n];
    for (k, i) in keep.iter().enumerate() {
        map[*i] = k;
    }
    for (e, _) in q.terms() {
        for (i, d) in e.iter().enumerate() {
            assert!(*d == 0 || keep.contains(&i), "variable {i} left over");
        }
    }
    q.relabel(keep.len(), &map)
}

/// The mode's equations g5–g8, g13, g14 (kinsyn's derivation, `InputMode::Free`) at the
/// inputs `t11, t12, t13` and `t14` (`None`: `t14` stays, as the seventh variable).
fn mode_equations(mode: Mode, t: [C64; 3], t14: Option<C64>) -> Vec<Poly> {
    let full = Ruu::paper004().constraints(InputMode::Free).unwrap();
    let zero = C64::new(0.0, 0.0);
    let mut subs: Vec<(usize, C64)> = mode.zero().iter().map(|i| (*i, zero)).collect();
    subs.extend((0..3).map(|i| (8 + i, t[i])));
    let mut keep = mode.free().to_vec();
    match t14 {
        Some(v) => subs.push((11, v)),
        None => keep.push(11),
    }
    [4, 5, 6, 7, 12, 13]
        .iter()
        .map(|k| restrict(&full.equations()[*k], &subs, &keep))
        .collect()
}

/// The same equations from `InputMode::Angles(theta)` (12 variables: Study, then `t2i`).
fn mode_equations_angles(mode: Mode, theta: [f64; 4]) -> Vec<Poly> {
    let full = Ruu::paper004()
        .constraints(InputMode::Angles(theta))
        .unwrap();
    let zero = C64::new(0.0, 0.0);
    let subs: Vec<(usize, C64)> = mode.zero().iter().map(|i| (*i, zero)).collect();
    [4, 5, 6, 7, 12, 13]
        .iter()
        .map(|k| restrict(&full.equations()[*k], &subs, &mode.free()))
        .collect()
}

/// The mode Jacobian: the derivatives of `eqs` by their first six variables at `x`.
fn jacobian(eqs: &[Poly], x: &[C64]) -> DMatrix<C64> {
    DMatrix::from_fn(eqs.len(), 6, |i, j| eqs[i].derivative(j).eval(x))
}

/// The singular values, largest first.
fn singular_values(m: &DMatrix<C64>) -> Vec<f64> {
    let mut s: Vec<f64> = m
        .clone()
        .svd(false, false)
        .singular_values
        .iter()
        .copied()
        .collect();
    s.sort_by(|a, b| b.total_cmp(a));
    s
}

/// `σ_min / σ_max` of the mode Jacobian at `x`.
fn sigma_ratio(eqs: &[Poly], x: &[C64]) -> f64 {
    let s = singular_values(&jacobian(eqs, x));
    s[s.len() - 1] / s[0]
}

/// All assemblies of the mode at the (complex) inputs: every finite endpoint of a total-degree
/// homotopy (64 paths), regular or not.
fn assemblies(mode: Mode, t: [C64; 4]) -> (Vec<Poly>, Vec<Vec<C64>>) {
    let eqs = mode_equations(mode, [t[0], t[1], t[2]], Some(t[3]));
    let system = System::new(mode.names(), eqs.clone()).unwrap();
    let report = solve(
        &system,
        &SolveSettings {
            certify: false,
            ..SolveSettings::default()
        },
    )
    .unwrap();
    let xs = report.solutions.iter().map(|s| s.x.clone()).collect();
    (eqs, xs)
}

/// The smallest `σ_min/σ_max` over the assemblies, and how many assemblies there are.
fn most_singular(mode: Mode, t: [C64; 4]) -> (f64, usize) {
    let (eqs, xs) = assemblies(mode, t);
    let worst = xs
        .iter()
        .map(|x| sigma_ratio(&eqs, x))
        .fold(f64::INFINITY, f64::min);
    (worst, xs.len())
}

fn real(v: f64) -> C64 {
    C64::new(v, 0.0)
}

/// The determinant of a square matrix of polynomials (Laplace expansion along the rows, the
/// minors of the lower rows memoised by their column set).
fn det_poly(m: &[Vec<Poly>]) -> Poly {
    let n = m.len();
    let nv = m[0][0].nvars();
    let mut minors: Vec<Option<Poly>> = vec![None; 1 << n];
    minors[0] = Some(Poly::real(nv, 1.0));
    for mask in 1usize..(1 << n) {
        let k = mask.count_ones() as usize;
        let row = n - k;
        let mut acc = Poly::zero(nv);
        let mut sign = 1.0;
        for col in 0..n {
            if mask & (1 << col) != 0 {
                let rest = minors[mask & !(1 << col)].as_ref().unwrap();
                acc = acc + (&m[row][col] * rest) * sign;
                sign = -sign;
            }
        }
        minors[mask] = Some(acc);
    }
    minors[(1 << n) - 1].take().unwrap()
}

/// The complex roots of an integer polynomial (coefficients highest degree first): the
/// eigenvalues of its companion matrix.
fn roots(coefficients: &[i128]) -> Vec<C64> {
    let d = coefficients.len() - 1;
    let lead = coefficients[0] as f64;
    let companion = DMatrix::from_fn(d, d, |i, j| {
        if i == 0 {
            -(coefficients[j + 1] as f64) / lead
        } else if i == j + 1 {
            1.0
        } else {
            0.0
        }
    });
    companion.complex_eigenvalues().iter().copied().collect()
}

/// The distinct values among `v` (within `tolerance`), each the mean of its cluster, with its
/// cluster's size.
fn distinct(v: &[C64], tolerance: f64) -> Vec<(C64, usize)> {
    let mut out: Vec<(C64, usize)> = Vec::new();
    for z in v {
        if let Some(c) = out
            .iter_mut()
            .find(|(w, _)| (*w - z).norm() < tolerance * (1.0 + z.norm()))
        {
            c.0 = (c.0 * c.1 as f64 + z) / (c.1 as f64 + 1.0);
            c.1 += 1;
        } else {
            out.push((*z, 1));
        }
    }
    out
}

/// `p(z)` in floating point (Horner).
fn horner(coefficients: &[i128], z: C64) -> C64 {
    coefficients
        .iter()
        .fold(real(0.0), |acc, c| acc * z + real(*c as f64))
}

/// The distinct roots of an integer polynomial with their multiplicities: the companion
/// matrix's eigenvalues clustered (a root of multiplicity m comes out spread by about
/// ε^(1/m)), each cluster's mean then refined by Newton's method on the (m − 1)-th
/// derivative, of which it is a simple root.
fn printed_roots(coefficients: &[i128]) -> Vec<(C64, usize)> {
    distinct(&roots(coefficients), 1e-2)
        .into_iter()
        .map(|(mut z, m)| {
            let mut p = coefficients.to_vec();
            for _ in 1..m {
                p = derivative(&p);
            }
            let dp = derivative(&p);
            for _ in 0..20 {
                z -= horner(&p, z) / horner(&dp, z);
            }
            (z, m)
        })
        .collect()
}

/// `p(x)` exactly for a rational `x = num/den`, times `den^deg`.
fn eval_exact(coefficients: &[i128], num: i128, den: i128) -> i128 {
    let d = coefficients.len() - 1;
    coefficients
        .iter()
        .enumerate()
        .map(|(k, c)| {
            c * num.pow(u32::try_from(d - k).unwrap()) * den.pow(u32::try_from(k).unwrap())
        })
        .sum()
}

/// The derivative's coefficients.
fn derivative(coefficients: &[i128]) -> Vec<i128> {
    let d = coefficients.len() - 1;
    coefficients[..d]
        .iter()
        .enumerate()
        .map(|(k, c)| c * i128::try_from(d - k).unwrap())
        .collect()
}

/// The augmented system of a mode's singular inputs: the mode equations with `t14` free and
/// the determinant of the mode Jacobian, 7 equations in `(mode's Study parameters, t14)`.
fn singularity_system(mode: Mode, t: [C64; 3]) -> System {
    let mut eqs = mode_equations(mode, t, None);
    let m: Vec<Vec<Poly>> = eqs
        .iter()
        .map(|g| (0..6).map(|j| g.derivative(j)).collect())
        .collect();
    eqs.push(det_poly(&m));
    let mut names = mode.names();
    names.push("t14".into());
    System::new(names, eqs)
        .unwrap()
        .with_groups(vec![(0..6).collect(), vec![6]])
        .unwrap()
}

/// The distinct values of `t14` where the mode has a singular assembly off the base plane:
/// every finite endpoint of the augmented system ([`singularity_system`], multi-homogeneous
/// start, 512 paths) whose platform height is not zero, clustered.
fn singular_inputs_numerically(mode: Mode, t: [C64; 3]) -> Vec<(C64, usize)> {
    let report = solve(
        &singularity_system(mode, t),
        &SolveSettings {
            certify: false,
            start: StartSystem::MultiHomogeneous,
            ..SolveSettings::default()
        },
    )
    .unwrap();
    assert_eq!(report.failed(), 0, "{}", report.summary());
    let off_plane: Vec<C64> = report
        .solutions
        .iter()
        .filter(|s| {
            let scale: f64 = s.x[..6].iter().map(|v| v.norm()).sum();
            mode.height(&s.x).norm() > 1e-6 * scale * scale
        })
        .map(|s| s.x[6])
        .collect();
    distinct(&off_plane, 1e-6)
}

/// Distinct complex values with their multiplicities.
type Roots = Vec<(C64, usize)>;

/// Paper 004 eqs. 30–31: the numerical singular inputs against the printed polynomial's
/// roots. Returns the printed roots (distinct, with multiplicity) that are not found.
fn compare_with_printed(mode: Mode, t: [f64; 3], printed: &[i128]) -> (Roots, Roots) {
    let t = t.map(real);
    let found = singular_inputs_numerically(mode, t);
    let printed = printed_roots(printed);
    for (v, n) in &found {
        assert!(
            printed
                .iter()
                .any(|(r, _)| (r - v).norm() < 1e-6 * (1.0 + v.norm())),
            "{mode:?}: singular input t14 = {v} ({n} endpoints) is not a root of the printed polynomial {printed:?}"
        );
    }
    let missing: Vec<(C64, usize)> = printed
        .iter()
        .filter(|(r, _)| {
            !found
                .iter()
                .any(|(v, _)| (r - v).norm() < 1e-6 * (1.0 + v.norm()))
        })
        .copied()
        .collect();
    // A second numerical look at every printed root: the assemblies there (64-path total-degree
    // homotopy, complex inputs) and their worst σ_min/σ_max. Generic assemblies of the mode have
    // full rank 6; a root of the singularity locus has an assembly of lower rank.
    for (r, m) in &printed {
        let (worst, count) = most_singular(mode, [t[0], t[1], t[2], *r]);
        let is_missing = missing.iter().any(|(v, _)| v == r);
        eprintln!(
            "{mode:?} printed root t14 = {r:.12} (x{m}): {count} assemblies, worst σ_min/σ_max = {worst:.3e}{}",
            if is_missing { " (not found)" } else { "" }
        );
        if is_missing {
            assert!(
                worst > 1e-4,
                "{mode:?}: printed root {r} not found, yet an assembly is singular: σ ratio {worst:e}"
            );
        } else {
            assert!(
                worst < 1e-7,
                "{mode:?}: singular input {r} but every assembly has σ ratio ≥ {worst:e}"
            );
        }
    }
    (found, missing)
}

fn is_near(z: C64, v: f64) -> bool {
    (z - real(v)).norm() < 1e-6
}

#[test]
fn angles_input_is_the_tangent_input_over_one_plus_t_squared() {
    // InputMode::Angles(θ) replaces ((1 − t²), 2t)/(1 + t²) by (cos θ, sin θ) (eq. 8), so each
    // g1..g12 of leg i is the InputMode::Given(tan(θ/2)) one divided by 1 + t1i², and g13, g14
    // are the same; at random complex points of the 12 unknowns (Study, passive t2i).
    let ruu = Ruu::paper004();
    let mut rng = ChaCha8Rng::seed_from_u64(14);
    for _ in 0..4 {
        let theta: [f64; 4] = std::array::from_fn(|_| rng.random_range(-3.0..3.0));
        let t = theta.map(|v| (v / 2.0).tan());
        let by_tangent = ruu.constraints(InputMode::Given(t)).unwrap();
        let by_angle = ruu.constraints(InputMode::Angles(theta)).unwrap();
        assert_eq!(by_tangent.variables(), by_angle.variables());
        for _ in 0..3 {
            let x: Vec<C64> = (0..12)
                .map(|_| C64::new(rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0)))
                .collect();
            for k in 0..14 {
                let w = if k < 12 {
                    1.0 + t[k % 4] * t[k % 4]
                } else {
                    1.0
                };
                let g = by_tangent.equations()[k].eval(&x) / w;
                let h = by_angle.equations()[k].eval(&x);
                assert!(
                    (g - h).norm() < 1e-12 * (1.0 + g.norm()),
                    "g{} at θ = {theta:?}: {g} vs {h}",
                    k + 1
                );
            }
        }
    }
    // θ11 = π (t11 = ∞): leg 1's g1, g5, g9 by angle are the limits of g/(1 + t11²) as
    // t11 → ∞, i.e. the coefficients of t11² in the InputMode::Free equations.
    let free = ruu.constraints(InputMode::Free).unwrap();
    let theta = [PI, 0.4, -1.2, 2.0];
    let by_angle = ruu.constraints(InputMode::Angles(theta)).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(15);
    let x: Vec<C64> = (0..12)
        .map(|_| C64::new(rng.random_range(-1.0..1.0), rng.random_range(-1.0..1.0)))
        .collect();
    for k in [0, 4, 8] {
        let leading = Poly::from_terms(
            16,
            free.equations()[k]
                .terms()
                .filter(|(e, _)| e[8] == 2)
                .map(|(e, c)| {
                    let mut e = e.to_vec();
                    e[8] = 0;
                    (e, c)
                }),
        );
        // Free's variables: Study 0..8, t11..t14 8..12, t21..t24 12..16.
        let mut point = x[..8].to_vec();
        point.extend([real(0.0); 4]);
        point.extend_from_slice(&x[8..]);
        let g = leading.eval(&point);
        let h = by_angle.equations()[k].eval(&x);
        assert!(
            (g - h).norm() < 1e-12 * (1.0 + g.norm()),
            "g{} at θ11 = π: limit {g} vs angle form {h}",
            k + 1
        );
    }
}

#[test]
fn k1_singular_inputs_numerically_eq30() {
    // Paper 004 §5.1, eq. 30 (t11 = −2, t12 = −1, t13 = 1/2): every singular input found
    // numerically is a printed root; of the printed roots, only t14 = 1/2 (a double root as
    // printed) is not: there every K1 assembly has full rank.
    let (found, missing) = compare_with_printed(Mode::K1, [-2.0, -1.0, 0.5], &EQ30);
    eprintln!("K1 singular t14 (numerical): {found:?}");
    assert_eq!(
        found.len(),
        10,
        "8 of the degree-8 factor, 1/9 and 1: {found:?}"
    );
    assert!(found.iter().any(|(v, _)| is_near(*v, 1.0)));
    assert!(found.iter().any(|(v, _)| is_near(*v, 1.0 / 9.0)));
    assert_eq!(missing.len(), 1, "{missing:?}");
    assert!(
        is_near(missing[0].0, 0.5) && missing[0].1 == 2,
        "{missing:?}"
    );
}

#[test]
fn k2_singular_inputs_numerically_eq31() {
    // Paper 004 §5.2, eq. 31 (t11 = 0, t12 = 1, t13 = 0, reconstructed, see EQ31): every
    // singular input found numerically is a printed root; the printed triple roots t14 = 1 and
    // t14 = 3/5 are not singular inputs.
    let (found, missing) = compare_with_printed(Mode::K2, [0.0, 1.0, 0.0], &EQ31);
    eprintln!("K2 singular t14 (numerical): {found:?}");
    assert_eq!(found.len(), 12, "the degree-12 factor: {found:?}");
    assert_eq!(missing.len(), 2, "{missing:?}");
    assert!(
        missing
            .iter()
            .all(|(v, m)| (is_near(*v, 1.0) || is_near(*v, 0.6)) && *m == 3),
        "{missing:?}"
    );
}

#[test]
fn eq31_reconstruction_has_exact_roots() {
    // With the coefficient −1755916864 (printed "−175591 / 6864" across a line break) and the
    // leading t14^18, eq. 31 has the rational triple roots 1 and 3/5 exactly (integer
    // arithmetic): p, p′, p″ vanish there. A wrong digit in any coefficient would break this.
    let d1 = derivative(&EQ31);
    let d2 = derivative(&d1);
    for (num, den) in [(1, 1), (3, 5)] {
        for p in [&EQ31[..], &d1, &d2] {
            assert_eq!(eval_exact(p, num, den), 0, "at {num}/{den}");
        }
        assert_ne!(eval_exact(&derivative(&d2), num, den), 0);
    }
    // Likewise eq. 30 has the double roots 1, 1/2, 1/9 exactly.
    let e1 = derivative(&EQ30);
    for (num, den) in [(1, 1), (1, 2), (1, 9)] {
        assert_eq!(eval_exact(&EQ30, num, den), 0, "at {num}/{den}");
        assert_eq!(eval_exact(&e1, num, den), 0, "at {num}/{den}");
        assert_ne!(eval_exact(&derivative(&e1), num, den), 0);
    }
}

/// The Singular script: the mode ideal of the printed g5–g8 with g13, g14 at the inputs, the
/// mode Jacobian's determinant factored, the Study parameters eliminated from the ideal plus
/// the factor that is not the height, the eliminant and the printed polynomial factored.
fn singular_script(mode: Mode, inputs: &str, printed: &[i128]) -> String {
    let (ring, zero, rest) = match mode {
        Mode::K1 => (
            "x1,x2,y0,y1,y2,y3,t14,x0,x3",
            ["x0", "x3"],
            "x1*x2*y0*y1*y2*y3",
        ),
        Mode::K2 => (
            "x0,x3,y0,y1,y2,y3,t14,x1,x2",
            ["x1", "x2"],
            "x0*x3*y0*y1*y2*y3",
        ),
    };
    let mut s = format!(
        "LIB \"elim.lib\";\nring R = 0,({ring}),dp;\nnumber a=2; number b=1; number l=1; number r=2;\n{inputs}\n"
    );
    s += &singular::printed_paper004(&["g5", "g6", "g7", "g8"]);
    let d = printed.len() - 1;
    let p: Vec<String> = printed
        .iter()
        .enumerate()
        .map(|(k, c)| format!("({c})*t14^{}", d - k))
        .collect();
    write!(
        s,
        "ideal G = g5,g6,g7,g8,x0*y0+x1*y1+x2*y2+x3*y3,x0^2+x1^2+x2^2+x3^2-1;\n\
         G = subst(G,{z0},0); G = subst(G,{z1},0);\n\
         matrix J = jacob(G); matrix C[6][6]; int i,j;\n\
         for(i=1;i<=6;i++){{for(j=1;j<=6;j++){{C[i,j]=J[i,j];}}}}\n\
         list L = factorize(det(C),2); int k;\n\
         for(k=1;k<=size(L[1]);k++){{print(\"DET \" + string(L[1][k]));}}\n\
         poly F = L[1][2]; if (deg(L[1][1]) > 2) {{ F = L[1][1]; }}\n\
         ideal E = eliminate(G + F, {rest});\n\
         print(\"GENERATORS \" + string(size(E)));\n\
         list M = factorize(E[1],2);\n\
         for(k=1;k<=size(M[1]);k++){{print(\"ELIM \" + string(M[1][k]));}}\n\
         poly P = {p};\n\
         list N = factorize(P,2);\n\
         for(k=1;k<=size(N[1]);k++){{print(\"PRINTED \" + string(N[1][k]) + \" ^\" + string(N[2][k]));}}\n\
         quit;\n",
        z0 = zero[0],
        z1 = zero[1],
        p = p.join("+")
    )
    .unwrap();
    s
}

/// The lines of `out` after `tag `, without it.
fn tagged<'a>(out: &'a str, tag: &str) -> Vec<&'a str> {
    out.lines()
        .filter_map(|l| l.strip_prefix(tag).and_then(|r| r.strip_prefix(' ')))
        .collect()
}

/// Paper 004 eqs. 30–31 against Singular: the determinant is the height times one other
/// factor; that factor's eliminant has each irreducible factor among the printed polynomial's;
/// returns the printed factors (with exponents) that the eliminant lacks.
fn exact_comparison(
    mode: Mode,
    inputs: &str,
    printed: &[i128],
    height: &str,
) -> Option<Vec<String>> {
    let out = singular::run(
        &singular_script(mode, inputs, printed),
        "the exact singular inputs of the 4-RUU",
    )?;
    let det = tagged(&out, "DET");
    assert_eq!(det.len(), 2, "{mode:?}: det factors {det:?}");
    assert!(
        det.contains(&height),
        "{mode:?}: no height factor in {det:?}"
    );
    assert_eq!(tagged(&out, "GENERATORS"), vec!["1"], "{out}");
    let elim = tagged(&out, "ELIM");
    let printed = tagged(&out, "PRINTED");
    eprintln!(
        "{mode:?}: det factors {det:?}\neliminant factors {elim:?}\nprinted factors {printed:?}"
    );
    for f in &elim {
        assert!(
            printed.iter().any(|p| p.split(" ^").next() == Some(*f)),
            "{mode:?}: eliminant factor {f} is not a factor of the printed polynomial {printed:?}"
        );
    }
    Some(
        printed
            .iter()
            .filter(|p| !elim.contains(&p.split(" ^").next().unwrap()))
            .map(|p| (*p).to_string())
            .collect(),
    )
}

#[test]
fn k1_singular_inputs_exactly_eq30() {
    // Paper 004 eq. 30 as printed = (degree-8 factor)·(t14 − 1)²(2 t14 − 1)²(9 t14 − 1)²; the
    // exact eliminant of K1 plus the non-height factor of det(J) has the factors degree-8,
    // t14 − 1, 9 t14 − 1, but not 2 t14 − 1.
    let Some(extra) = exact_comparison(
        Mode::K1,
        "number t11=-2; number t12=-1; number t13=1/2;",
        &EQ30,
        "-x2*y1+x1*y2",
    ) else {
        return;
    };
    assert_eq!(extra, vec!["2*t14-1 ^2"]);
}

#[test]
fn k2_singular_inputs_exactly_eq31() {
    // Paper 004 eq. 31 (reconstructed) = (degree-12 factor)·(t14 − 1)³(5 t14 − 3)³; the exact
    // eliminant is the degree-12 factor alone.
    let Some(mut extra) = exact_comparison(
        Mode::K2,
        "number t11=0; number t12=1; number t13=0;",
        &EQ31,
        "-x3*y0+x0*y3",
    ) else {
        return;
    };
    extra.sort();
    assert_eq!(extra, vec!["5*t14-3 ^3", "t14-1 ^3"]);
}

/// The mode coordinates of a displacement's Study parameters (`study::from_displacement`), and
/// the largest absolute value of the two that must vanish in the mode.
fn mode_point(mode: Mode, g: &Displacement) -> (Vec<C64>, f64) {
    let s = study::from_displacement(g);
    let off = mode.zero().iter().map(|i| s[*i].abs()).fold(0.0, f64::max);
    (mode.free().iter().map(|i| real(s[*i])).collect(), off)
}

/// The largest residual of the mode equations at `x`.
fn residual(eqs: &[Poly], x: &[C64]) -> f64 {
    eqs.iter().map(|g| g.eval(x).norm()).fold(0.0, f64::max)
}

/// The number of singular values of the mode Jacobian below `1e-9 σ_max`, and the ratio of
/// the smallest singular value above to `σ_max` (the gap).
fn nullity(eqs: &[Poly], x: &[C64]) -> (usize, f64, f64) {
    let s = singular_values(&jacobian(eqs, x));
    let small = s.iter().filter(|v| **v < 1e-9 * s[0]).count();
    (small, s[s.len() - 1] / s[0], s[s.len() - 1 - small] / s[0])
}

#[test]
fn printed_k1_singular_pose() {
    // Paper 004 §5.1: "solving Eq. (30) for t14 = 1 … θ = (126.934°, −90°, 53.157°, 90°)".
    // t14 = 1 is a (double) root of eq. 30 as printed, exactly.
    assert_eq!(eval_exact(&EQ30, 1, 1), 0);
    // The printed degrees are 2 atan(t) of t = 2, −1, 1/2 converted with π ≈ 3.14
    // (2 atan 2 = 126.870°, 2 atan ½ = 53.130°), and θ11 has lost the sign of t11 = −2.
    let rounded_pi = 314.0 / 100.0;
    let deg = |t: f64| 2.0 * t.atan() * 180.0 / rounded_pi;
    assert!((deg(2.0) - 126.934).abs() < 5e-4 && (deg(0.5) - 53.157).abs() < 5e-4);
    assert!((2.0 * 2f64.atan()).to_degrees() - 126.934 < -0.06);
    // At the stated inputs t11 = −2 (θ11 = −126.87°), t14 = 1 the K1 assemblies contain a
    // 1-dof self-motion (hand derivation): with the platform turned by π about
    // u = (2, 1, 0)/√5, B_i − R C_i = ±d for all four legs (d = B_1 − R C_1 = (0.8, −1.6, 0)),
    // so |T ∓ d| = r for T ⊥ d with |T|² = r² − |d|²: a circle of translations. Every pose of
    // it is singular (rank 5).
    let ruu = Ruu::paper004();
    let theta = [-2.0f64, -1.0, 0.5, 1.0].map(|t| 2.0 * t.atan());
    let u = Unit::new_normalize(Vector3::new(2.0, 1.0, 0.0));
    let rot = Rotation3::from_axis_angle(&u, PI);
    let d = ruu.crank_joint(0, theta[0]) - rot * ruu.platform_joint(0);
    for (i, th) in theta.iter().enumerate() {
        let di = ruu.crank_joint(i, *th) - rot * ruu.platform_joint(i);
        assert!(
            (di - d).norm() < 1e-12 || (di + d).norm() < 1e-12,
            "leg {i}: {di}"
        );
    }
    let radius = (ruu.r * ruu.r - d.norm_squared()).sqrt();
    let across = Vector3::z().cross(&d).normalize();
    let eqs = mode_equations(Mode::K1, [-2.0, -1.0, 0.5].map(real), Some(real(1.0)));
    for alpha in [0.3, 1.4, 2.9] {
        let t = radius * (across * f64::cos(alpha) + Vector3::z() * f64::sin(alpha));
        let g = Displacement::from_parts(Translation3::from(t), rot);
        let (x, off) = mode_point(Mode::K1, &g);
        assert!(off < 1e-12 && residual(&eqs, &x) < 1e-12, "α = {alpha}");
        let (small, ratio, gap) = nullity(&eqs, &x);
        eprintln!(
            "K1 self-motion at t11 = −2, α = {alpha}: σ_min/σ_max = {ratio:.3e}, next {gap:.3e}"
        );
        assert_eq!(
            small, 1,
            "rank 5 on the self-motion: σ ratio {ratio:e}, next {gap:e}"
        );
        assert!(gap > 1e-3, "one small singular value, then {gap:e}");
    }
    // At the printed angles' sign, t11 = +2, t14 = 1: no real K1 assembly at all (16 complex
    // solutions counted with multiplicity; the singular ones among them are complex, with the
    // platform in the base plane).
    let (eqs, xs) = assemblies(Mode::K1, [2.0, -1.0, 0.5, 1.0].map(real));
    let real_count = xs
        .iter()
        .filter(|x| x.iter().all(|v| v.im.abs() < 1e-8 * (1.0 + v.norm())))
        .count();
    let worst = xs
        .iter()
        .map(|x| sigma_ratio(&eqs, x))
        .fold(f64::INFINITY, f64::min);
    eprintln!(
        "K1 at t11 = +2, t14 = 1: {} assemblies, {real_count} real, worst σ_min/σ_max = {worst:.3e}",
        xs.len()
    );
    assert_eq!(real_count, 0);
}

#[test]
fn printed_k2_singular_pose_is_regular() {
    // Paper 004 §5.2: "solving Eq. (31), for example t14 = 1 … θ = (0°, 90°, 0°, 90°)". t14 = 1
    // is a (triple) root of eq. 31 as reconstructed, but every K2 assembly at t = (0, 1, 0, 1)
    // has a full-rank mode Jacobian: 16 regular assemblies (4 real); compare with generic
    // inputs.
    assert_eq!(eval_exact(&EQ31, 1, 1), 0);
    let (eqs, xs) = assemblies(Mode::K2, [0.0, 1.0, 0.0, 1.0].map(real));
    let ratios: Vec<f64> = xs.iter().map(|x| sigma_ratio(&eqs, x)).collect();
    let worst = ratios.iter().copied().fold(f64::INFINITY, f64::min);
    let real_count = xs
        .iter()
        .filter(|x| x.iter().all(|v| v.im.abs() < 1e-8 * (1.0 + v.norm())))
        .count();
    let (generic, n) = most_singular(Mode::K2, [0.3, -0.7, 1.1, 0.45].map(real));
    eprintln!(
        "K2 at (0, 1, 0, 1): {} assemblies, {real_count} real, worst σ_min/σ_max = {worst:.3e}; generic inputs: {n} assemblies, worst {generic:.3e}",
        xs.len()
    );
    assert_eq!((xs.len(), real_count), (16, 4));
    assert!(worst > 1e-4, "a singular assembly: σ ratio {worst:e}");
}

#[test]
fn k2_rank_drops_in_the_two_particular_conditions() {
    // Paper 004 §5.2: det J2 vanishes (a) when all inputs are equal — a 1-dof self-motion, the
    // platform turning about Z with the cranks fixed — and (b) at θ = (180°, −90°, 0°, 90°),
    // the cranks pointing inward — a self-motion with translations. Poses derived by hand:
    // (a) B_i = a e_i + l(cos θ, sin θ, 0); T = l(cos θ, sin θ, 0) + Z e_z, R = Rot(Z, φ):
    //     |b R e_i − a e_i + Z e_z|² = a² + b² − 2ab cos φ + Z² = r² for every leg.
    // (b) B_i = (a − l) e_i = b e_i: R = I, any T with |T| = r.
    let ruu = Ruu::paper004();
    for theta in [0.0, 0.9, -2.2] {
        let eqs = mode_equations_angles(Mode::K2, [theta; 4]);
        for phi in [0.2, -0.6] {
            let z2 =
                ruu.r * ruu.r - ruu.a * ruu.a - ruu.b * ruu.b + 2.0 * ruu.a * ruu.b * f64::cos(phi);
            let t = Vector3::new(ruu.l * theta.cos(), ruu.l * theta.sin(), z2.sqrt());
            let g = Displacement::from_parts(
                Translation3::from(t),
                Rotation3::from_axis_angle(&Vector3::z_axis(), phi),
            );
            let (x, off) = mode_point(Mode::K2, &g);
            assert!(
                off < 1e-12 && residual(&eqs, &x) < 1e-12,
                "θ = {theta}, φ = {phi}"
            );
            let (small, ratio, gap) = nullity(&eqs, &x);
            eprintln!(
                "K2 all inputs {theta}, φ = {phi}: σ_min/σ_max = {ratio:.3e}, next {gap:.3e}"
            );
            assert_eq!(small, 1, "σ ratio {ratio:e}, next {gap:e}");
            assert!(gap > 1e-3, "next {gap:e}");
        }
    }
    let eqs = mode_equations_angles(Mode::K2, [PI, -FRAC_PI_2, 0.0, FRAC_PI_2]);
    for (alpha, beta) in [(0.4, 1.1), (1.2, -2.5)] {
        let t = ruu.r
            * Vector3::new(
                f64::sin(alpha) * f64::cos(beta),
                f64::sin(alpha) * f64::sin(beta),
                f64::cos(alpha),
            );
        let g = Displacement::from_parts(Translation3::from(t), Rotation3::identity());
        let (x, off) = mode_point(Mode::K2, &g);
        assert!(
            off < 1e-12 && residual(&eqs, &x) < 1e-12,
            "α = {alpha}, β = {beta}"
        );
        let (small, ratio, gap) = nullity(&eqs, &x);
        eprintln!(
            "K2 inward cranks, α = {alpha}, β = {beta}: nullity {small}, σ_min/σ_max = {ratio:.3e}, next {gap:.3e}"
        );
        assert_eq!(
            small, 2,
            "a 2-sphere of translations: σ ratio {ratio:e}, next {gap:e}"
        );
        assert!(gap > 1e-3, "next {gap:e}");
    }
    // The rotation of (b) is another branch: R = Rot(Z, φ), T = Z e_z with
    // |(R − I) b e_i + Z e_z|² = 2b²(1 − cos φ) + Z² = r²; rank 5 there.
    let phi: f64 = 0.7;
    let z = (ruu.r * ruu.r - 2.0 * ruu.b * ruu.b * (1.0 - phi.cos())).sqrt();
    let g = Displacement::from_parts(
        Translation3::new(0.0, 0.0, z),
        Rotation3::from_axis_angle(&Vector3::z_axis(), phi),
    );
    let (x, off) = mode_point(Mode::K2, &g);
    assert!(off < 1e-12 && residual(&eqs, &x) < 1e-12);
    let (small, ratio, gap) = nullity(&eqs, &x);
    eprintln!(
        "K2 inward cranks, rotation φ = {phi}: nullity {small}, σ_min/σ_max = {ratio:.3e}, next {gap:.3e}"
    );
    assert_eq!(small, 1, "σ ratio {ratio:e}, next {gap:e}");
    assert!(gap > 1e-3, "next {gap:e}");
}
