//! Serial chains (src/chain.rs): the Jacobian against finite differences of the forward
//! kinematics, and the generic chain of paper 000 §3 against its own velocity equation.

use crate::common;

use common::finite_difference_column;
use kinsyn::chain::{GenericChain, GenericValues, SerialChain, random_unit};
use kinsyn::notation::Axis::{X, Y};
use kinsyn::notation::Primitive::{self, P, R};
use kinsyn::screw::Twist;
use nalgebra::Vector3;
use proptest::prelude::*;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

fn random_chain(rng: &mut ChaCha8Rng, n: usize) -> SerialChain {
    let joints: Vec<(Primitive, Vector3<f64>, Vector3<f64>)> = (0..n)
        .map(|_| {
            let kind = if rng.random_bool(0.5) { P } else { R };
            (
                kind,
                random_unit(rng),
                random_unit(rng) * rng.random_range(0.0..2.0),
            )
        })
        .collect();
    SerialChain::new(joints).unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    /// The Jacobian's columns are the derivatives of the forward kinematics (independent
    /// method: central differences, h = 1e-6, agreement to 1e-7).
    #[test]
    fn jacobian_matches_finite_differences(seed in 0u64..100_000, n in 1usize..8) {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let c = random_chain(&mut rng, n);
        let q: Vec<f64> = (0..n).map(|_| rng.random_range(-3.0..3.0)).collect();
        let j = c.jacobian(&q);
        for i in 0..n {
            let fd = finite_difference_column(&c, &q, i, 1e-6);
            let col = Twist::from_vector(&j.column(i).into_owned());
            prop_assert!((fd.w - col.w).norm() < 1e-7 && (fd.v - col.v).norm() < 1e-7, "joint {}: fd {:?} vs {:?}", i, fd, col);
        }
    }
}

fn random_generic(rng: &mut ChaCha8Rng) -> GenericChain {
    let mut directions = [Vector3::zeros(); 12];
    for d in &mut directions {
        *d = random_unit(rng);
    }
    GenericChain {
        base: random_unit(rng),
        directions,
        gp: random_unit(rng) * 0.7,
    }
}

#[test]
fn generic_chain_velocity_equation_matches_the_screw_jacobian() {
    // Paper 000 eqs. 3–4, evaluated directly, against the POE Jacobian of the same chain
    // (v_P = v + ω × r_P): two independent algorithms.
    let mut rng = ChaCha8Rng::seed_from_u64(3);
    for _ in 0..20 {
        let g = random_generic(&mut rng);
        let q: GenericValues = std::array::from_fn(|k| {
            if k % 2 == 0 {
                rng.random_range(0.2..1.5)
            } else {
                rng.random_range(-3.0..3.0)
            }
        });
        let rates: GenericValues = std::array::from_fn(|_| rng.random_range(-1.0..1.0));
        let (omega, v_p) = g.velocity(&q, &rates);
        let (chain, r_p) = g.particularise(&q, &[true; 12]);
        assert!((r_p - g.platform_point(&q)).norm() < 1e-12);
        let j = chain.jacobian(&[0.0; 12]);
        let t = Twist::from_vector(
            &(j * nalgebra::DVector::from_column_slice(&rates))
                .fixed_rows::<6>(0)
                .into_owned(),
        );
        assert!((t.w - omega).norm() < 1e-12, "{:?} vs {:?}", t.w, omega);
        assert!((t.velocity_at(&r_p) - v_p).norm() < 1e-12);
    }
}

#[test]
fn loop_equation_is_differentiated_by_the_velocity_equation() {
    // Eq. 2 differentiated numerically equals eq. 3.
    let mut rng = ChaCha8Rng::seed_from_u64(4);
    let g = random_generic(&mut rng);
    let q: GenericValues = std::array::from_fn(|k| if k % 2 == 0 { 0.8 } else { 0.3 * k as f64 });
    let rates: GenericValues = std::array::from_fn(|k| 0.1 * (k as f64 - 5.0));
    let h = 1e-6;
    let plus: GenericValues = std::array::from_fn(|k| q[k] + h * rates[k]);
    let minus: GenericValues = std::array::from_fn(|k| q[k] - h * rates[k]);
    let fd = (g.platform_point(&plus) - g.platform_point(&minus)) / (2.0 * h);
    assert!((fd - g.velocity(&q, &rates).1).norm() < 1e-8);
}

#[test]
fn ups_leg_from_eq_5_satisfies_eq_10() {
    // Eq. 5: a = b = d = e = f = 0, ψ = 0 turns the generic chain into the UPS leg (U = α, β;
    // P = c; S = γ, φ, θ). Eq. 10: u_c·v_P + (u_c × GP)·ω = ċ for every joint rate.
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let mut g = random_generic(&mut rng);
    // The U's axes perpendicular, the S's mutually perpendicular (Fig. 4).
    g.directions[1] = Vector3::x();
    g.directions[3] = Vector3::y();
    g.directions[5] = Vector3::x();
    g.directions[7] = Vector3::y();
    g.directions[9] = Vector3::z();
    let c_len = 1.3;
    let mut held = [0.0; 12];
    held[4] = c_len;
    let free = [
        false, true, false, true, true, true, false, true, false, true, false, false,
    ];
    let (ups, r_p) = g.particularise(&held, &free);
    assert_eq!(ups.len(), 6);
    let kinds: Vec<Primitive> = ups.joints().iter().map(|j| j.kind).collect();
    assert_eq!(kinds, vec![R, R, P, R, R, R]);
    let u_c = ups.joints()[2].axis;
    let g_point = ups.joints()[3].point; // the centre of the S, end of link c
    let gp = r_p - g_point;
    for _ in 0..10 {
        let rates: Vec<f64> = (0..6).map(|_| rng.random_range(-1.0..1.0)).collect();
        let t = Twist::from_vector(
            &(ups.jacobian(&[0.0; 6]) * nalgebra::DVector::from_vec(rates.clone()))
                .fixed_rows::<6>(0)
                .into_owned(),
        );
        let lhs = u_c.dot(&t.velocity_at(&r_p)) + u_c.cross(&gp).dot(&t.w);
        assert!(
            (lhs - rates[2]).abs() < 1e-12,
            "eq. 10: {lhs} vs ċ = {}",
            rates[2]
        );
    }
    // The joint screws are those of eq. 7: the S turns about G = r_A + c·u_c.
    assert!((g_point - (g.base + u_c * c_len)).norm() < 1e-12);
}

#[test]
fn bad_chain_descriptions_are_errors() {
    assert!(SerialChain::new(vec![(R, Vector3::zeros(), Vector3::zeros())]).is_err());
    assert!(SerialChain::new(vec![(R, Vector3::x(), Vector3::new(f64::NAN, 0.0, 0.0))]).is_err());
    let mut rng = ChaCha8Rng::seed_from_u64(1);
    assert!(SerialChain::from_layout(&[P, R], &[X], &[2], &mut rng).is_err());
    assert!(SerialChain::from_layout(&[P, R], &[X, Y], &[1], &mut rng).is_err());
}
