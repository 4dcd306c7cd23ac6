//! The real-branch follower (`homotopy::follow_real`, `real_newton`, `real_rates`) against
//! closed forms derived by hand.

use kinsyn_nag::homotopy::{BranchEnd, ParametrizedSystem, follow_real, real_newton, real_rates};
use kinsyn_nag::poly::{Poly, System};

/// `F(x; p) = x² − p`: one unknown `x`, one parameter `p`. Its real solutions are `±√p` for
/// `p ≥ 0`, none for `p < 0`; `F_x = 2x`, `F_p = −1`, so `ẋ = ṗ/(2x)`.
fn square_root_family() -> ParametrizedSystem {
    let (x, p) = (Poly::variable(2, 0), Poly::variable(2, 1));
    let system = System::new(vec!["x".into(), "p".into()], vec![&x * &x - p]).unwrap();
    ParametrizedSystem::new(system, 1).unwrap()
}

#[test]
fn the_branch_of_a_square_root_is_followed_to_its_turning_point_and_no_further() {
    // p(t) = 1 − t: the branch x = √(1 − t) is real for t < 1 and meets −√(1 − t) at t = 1
    // (a turning point), after which both are imaginary. ṗ = −1, so ẋ = −1/(2√(1 − t)).
    let family = square_root_family();
    let times: Vec<f64> = (0..=20).map(|k| f64::from(k) * 0.1).collect();
    let branch = follow_real(&family, &[1.0], |t| vec![1.0 - t], |_| vec![-1.0], &times);
    assert_eq!(
        branch.points.len(),
        10,
        "t = 0, 0.1, …, 0.9 reached, not 1.0 onwards"
    );
    for point in &branch.points {
        let root = (1.0 - point.t).sqrt();
        assert!(
            (point.x[0] - root).abs() < 1e-9,
            "x({}) = {}",
            point.t,
            point.x[0]
        );
        let rate = -1.0 / (2.0 * root);
        assert!(
            (point.rates[0] - rate).abs() < 1e-8 * rate.abs(),
            "ẋ({})",
            point.t
        );
        // A 1×1 Jacobian is perfectly conditioned wherever it is not zero.
        assert!((point.inverse_condition - 1.0).abs() < 1e-12);
    }
    let BranchEnd::Ceased { last, next, .. } = branch.end else {
        panic!("the branch cannot be real past t = 1: {:?}", branch.end);
    };
    assert!(
        last < next,
        "the bracket is ordered in the direction of travel"
    );
    assert!(
        (0.9..=1.0 + 1e-9).contains(&last),
        "last real instant {last}"
    );
    assert!(
        (next - 1.0).abs() < 1e-3,
        "the turning point is t = 1, bracketed at {last}..{next}"
    );
}

#[test]
fn followed_back_in_time_the_branch_ends_at_the_same_turning_point() {
    // The same family with p(t) = t − 1 followed from t = 2 down: real for t > 1.
    let family = square_root_family();
    let times: Vec<f64> = (0..=20).map(|k| 2.0 - f64::from(k) * 0.1).collect();
    let branch = follow_real(&family, &[1.0], |t| vec![t - 1.0], |_| vec![1.0], &times);
    assert_eq!(branch.points.len(), 10, "t = 2.0, 1.9, …, 1.1 reached");
    let BranchEnd::Ceased { last, next, .. } = branch.end else {
        panic!("the branch cannot be real below t = 1: {:?}", branch.end);
    };
    assert!(next < last);
    assert!(
        (next - 1.0).abs() < 1e-3 && last >= 1.0 - 1e-9,
        "{last}..{next}"
    );
}

#[test]
fn a_circle_cut_by_a_moving_line_is_followed_whole_with_its_implicit_rates() {
    // F = (x² + y² − 1, y − p): the line y = p cuts the unit circle at x = ±√(1 − p²). With
    // p(t) = 0.6 sin t the right point is x = √(1 − p²) throughout (|p| ≤ 0.6 < 1), and
    // ẋ = −p ṗ / x, ẏ = ṗ = 0.6 cos t. The Jacobian in (x, y) is [[2x, 2y], [0, 1]].
    let (x, y, p) = (
        Poly::variable(3, 0),
        Poly::variable(3, 1),
        Poly::variable(3, 2),
    );
    let equations = vec![&x * &x + &y * &y - Poly::real(3, 1.0), &y - &p];
    let names = vec!["x".into(), "y".into(), "p".into()];
    let family = ParametrizedSystem::new(System::new(names, equations).unwrap(), 1).unwrap();
    let times: Vec<f64> = (0..=40)
        .map(|k| f64::from(k) * std::f64::consts::TAU / 40.0)
        .collect();
    let branch = follow_real(
        &family,
        &[1.0, 0.0],
        |t| vec![0.6 * t.sin()],
        |t| vec![0.6 * t.cos()],
        &times,
    );
    assert_eq!(branch.end, BranchEnd::Completed);
    assert_eq!(branch.points.len(), times.len());
    for point in &branch.points {
        let (pv, dp) = (0.6 * point.t.sin(), 0.6 * point.t.cos());
        let xv = (1.0 - pv * pv).sqrt();
        assert!((point.x[0] - xv).abs() < 1e-9 && (point.x[1] - pv).abs() < 1e-9);
        assert!((point.rates[0] + pv * dp / xv).abs() < 1e-9);
        assert!((point.rates[1] - dp).abs() < 1e-9);
    }
    // Newton from a rough guess lands on the nearer intersection; the rates at p = 0.6, ṗ = 1
    // are ẋ = −0.6/0.8 = −0.75, ẏ = 1.
    let root = real_newton(&family, &[0.7, 0.5], &[0.6]).unwrap();
    assert!((root[0] - 0.8).abs() < 1e-12 && (root[1] - 0.6).abs() < 1e-12);
    let (rates, _) = real_rates(&family, &root, &[0.6], &[1.0]).unwrap();
    assert!((rates[0] + 0.75).abs() < 1e-12 && (rates[1] - 1.0).abs() < 1e-12);
    let left = real_newton(&family, &[-0.7, 0.5], &[0.6]).unwrap();
    assert!((left[0] + 0.8).abs() < 1e-12);
}
