//! Paper 003's planar 4-RRR with a configurable platform: the paper's parametrisations checked
//! against each other and against its printed numbers.

use kinsyn_papers::configurable::{CentrePose, Configurable, CornerPose};
use nalgebra::Vector2;

#[test]
fn the_two_parametrisations_describe_the_same_platform() {
    // Paper 003 §5: the inverse example θ = 75°, φ = 100°, C = (20, −30) mm (eq. 11's sense)
    // and Table 1's converged pose θ = 80°, φ = 105°, C4 = (25.112, −147.043) (eq. 13's sense).
    let m = Configurable::paper003();
    let centre = CentrePose {
        centre: Vector2::new(20.0, -30.0),
        theta: 75f64.to_radians(),
        phi: 100f64.to_radians(),
    };
    let corner = centre.to_corner_pose(m.c);
    assert!((corner.theta.to_degrees() - 80.0).abs() < 1e-12);
    assert!((corner.phi.to_degrees() - 105.0).abs() < 1e-12);
    let (a, b) = (centre.corners(m.c), corner.corners(m.c));
    for i in 0..4 {
        assert!(
            (a[i] - b[i]).norm() < 1e-12,
            "corner {}: {a:?} vs {b:?}",
            i + 1
        );
        // A rhombus of side c (eq. 9).
        assert!(((a[i] - a[(i + 1) % 4]).norm() - m.c).abs() < 1e-12);
    }
    // Table 2's corners, printed to 3 decimals.
    let table2 = [
        (45.949, -28.866),
        (14.889, 87.042),
        (-5.947, -31.133),
        (25.112, -147.043),
    ];
    for (i, (x, y)) in table2.iter().enumerate() {
        assert!(
            (a[i] - Vector2::new(*x, *y)).amax() < 5e-3,
            "C{}: {:?}",
            i + 1,
            a[i]
        );
    }
    // Table 1's pose directly (C4 printed to 3 decimals, angles to 3).
    let table1 = CornerPose {
        c4: Vector2::new(25.112, -147.043),
        theta: 79.999f64.to_radians(),
        phi: 105.0f64.to_radians(),
    };
    for (i, p) in table1.corners(m.c).iter().enumerate() {
        assert!((p - a[i]).amax() < 5e-3, "C{}", i + 1);
    }
}
