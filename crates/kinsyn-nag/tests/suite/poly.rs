//! The polynomial layer: arithmetic against hand expansions, derivatives against finite
//! differences, the straight-line program against term-by-term evaluation, Bézout numbers
//! against hand counts.

use kinsyn_nag::poly::{C64, Poly, System};

fn c(re: f64, im: f64) -> C64 {
    C64::new(re, im)
}

#[test]
fn binomial_expansion_by_hand() {
    // (x + 2y)^3 = x^3 + 6x^2y + 12xy^2 + 8y^3.
    let x = Poly::variable(2, 0);
    let y = Poly::variable(2, 1);
    let p = (&x + &(y.clone() * 2.0)).pow(3);
    let expected = Poly::from_terms(
        2,
        [
            (vec![3, 0], c(1.0, 0.0)),
            (vec![2, 1], c(6.0, 0.0)),
            (vec![1, 2], c(12.0, 0.0)),
            (vec![0, 3], c(8.0, 0.0)),
        ],
    );
    assert_eq!(p, expected);
    assert_eq!(p.total_degree(), 3);
    assert_eq!(p.degree_in(&[1]), 3);
    assert!((&p - &p).is_empty(), "p − p cancels to the zero polynomial");
}

#[test]
fn substitution_and_derivative() {
    // p = x^2 y + i y, x := y + 1 gives y^3 + 2y^2 + (1 + i) y.
    let x = Poly::variable(2, 0);
    let y = Poly::variable(2, 1);
    let p = &(&x * &x) * &y + y.scale(c(0.0, 1.0));
    let q = p.substitute(0, &(&y + &Poly::real(2, 1.0)));
    let expected = Poly::from_terms(
        2,
        [
            (vec![0, 3], c(1.0, 0.0)),
            (vec![0, 2], c(2.0, 0.0)),
            (vec![0, 1], c(1.0, 1.0)),
        ],
    );
    assert_eq!(q, expected);
    // Derivatives against central differences at a complex point.
    let at = [c(0.3, -0.7), c(1.1, 0.4)];
    for i in 0..2 {
        let h = 1e-6;
        let mut plus = at;
        let mut minus = at;
        plus[i] += h;
        minus[i] -= h;
        let fd = (p.eval(&plus) - p.eval(&minus)) / (2.0 * h);
        assert!((fd - p.derivative(i).eval(&at)).norm() < 1e-8);
    }
}

#[test]
fn program_matches_term_by_term_evaluation() {
    // Cyclic-3 with a complex coefficient added, evaluated both ways.
    let v: Vec<Poly> = (0..3).map(|i| Poly::variable(3, i)).collect();
    let f1 = &v[0] + &v[1] + &v[2];
    let f2 = &v[0] * &v[1] + &v[1] * &v[2] + &v[2] * &v[0] + Poly::constant(3, c(0.5, -2.0));
    let f3 = &(&v[0] * &v[1]) * &v[2] - Poly::real(3, 1.0) + v[0].pow(4);
    let system = System::new(vec!["x".into(), "y".into(), "z".into()], vec![f1, f2, f3]).unwrap();
    let program = system.program();
    let mut ws = program.workspace::<C64>();
    let x = [c(0.2, 0.9), c(-1.3, 0.1), c(0.7, -0.4)];
    let mut values = [C64::default(); 3];
    let mut jac = [C64::default(); 9];
    program.evaluate_with_jacobian(&x, &mut values, &mut jac, &mut ws);
    for (i, p) in system.equations().iter().enumerate() {
        assert!((values[i] - p.eval(&x)).norm() < 1e-14);
        for j in 0..3 {
            assert!((jac[3 * i + j] - p.derivative(j).eval(&x)).norm() < 1e-13);
        }
    }
}

#[test]
fn bezout_numbers_by_hand() {
    // Two bilinear equations in groups {x}, {y}: total degree 2·2 = 4, but the
    // two-homogeneous count is 2 (α β coefficient of (α + β)²).
    let x = Poly::variable(2, 0);
    let y = Poly::variable(2, 1);
    let f1 = &x * &y - Poly::real(2, 1.0);
    let f2 = &(&x * &y) + &(x.clone() * 3.0) - Poly::real(2, 2.0);
    let system = System::new(vec!["x".into(), "y".into()], vec![f1, f2]).unwrap();
    assert_eq!(system.bezout_number(), 4);
    let grouped = system.with_groups(vec![vec![0], vec![1]]).unwrap();
    assert_eq!(
        grouped.multihomogeneous_degrees(),
        vec![vec![1, 1], vec![1, 1]]
    );
    assert_eq!(grouped.multihomogeneous_bezout(), Some(2));
    assert!(
        grouped.clone().with_groups(vec![vec![0]]).is_err(),
        "every variable in a group"
    );
}

#[test]
fn homogenisation_per_group() {
    // x^2 y + x in groups {x}, {y}: degrees 2 and 1; x^2 y + x h0 h1.
    let x = Poly::variable(2, 0);
    let y = Poly::variable(2, 1);
    let p = &(&x * &x) * &y + &x;
    let h = p.homogenize(&[vec![0], vec![1]]);
    let expected = Poly::from_terms(
        4,
        [
            (vec![2, 1, 0, 0], c(1.0, 0.0)),
            (vec![1, 0, 1, 1], c(1.0, 0.0)),
        ],
    );
    assert_eq!(h, expected);
}

/// `System::subsystem`: the equations x·z − 1 and y + 2 of a system in (x, y, z, w), kept in
/// (z, x) and in (x, y, z): by hand, the first becomes z·x − 1 in (z, x) — its value at
/// (z, x) = (2, 3) is 5 — and the second cannot drop y.
#[test]
fn a_subsystem_keeps_the_equations_in_the_variables_named() {
    let v = |i| Poly::variable(4, i);
    let names = ["x", "y", "z", "w"].map(String::from).to_vec();
    let s = System::new(
        names,
        vec![
            &(&v(0) * &v(2)) - &Poly::real(4, 1.0),
            &v(1) + &Poly::real(4, 2.0),
        ],
    )
    .unwrap();
    let sub = s.subsystem(&[0], &[2, 0]).unwrap();
    assert_eq!(sub.variables(), ["z".to_string(), "x".to_string()]);
    assert_eq!(
        sub.evaluate(&[C64::from(2.0), C64::from(3.0)])[0],
        C64::from(5.0)
    );
    assert!(s.subsystem(&[1], &[0, 2]).is_err(), "y left out");
    assert!(s.subsystem(&[2], &[0]).is_err(), "no equation 2");
    let both = s.subsystem(&[0, 1], &[0, 1, 2]).unwrap();
    assert_eq!(both.len(), 2);
}
