//! The HEXA of paper 001 on kinsyn's general mechanism graph: its `kinsyn-manipulator/2`
//! description (`mechanisms/6-ruu-hexa.json`), written from the paper's dimensions at a
//! reference pose, and read back into those dimensions.
//!
//! # The model (paper 001 §2, Figs. 1–2)
//! Limb `i` is eq. 1's bond `R(A_i) R(B_i) T(n_i) R(C_i)`: the active
//! link turns about `u_i` at `A_i` (the actuated joint) and carries the parallelogram's upper
//! bar `upper{i}` by a revolute about `u_i` at `B_i`; two rods, hinged about
//! `n_i = u_i × w_i / |u_i × w_i|` at `B_i ± h u_i` and `C_i ± h u_i`, make the lower bar
//! `lower{i}` translate on a circle relative to the upper one (`T(n_i)`); the lower bar joins
//! the platform by a revolute about `u_i` at `C_i`: onto the sub-platform `sub16` (limbs 1, 6)
//! or `sub23` (limbs 2, 3), or onto a wrist `wrist{i}` (limbs 4, 5) that end-effector 2 `ee2`
//! turns on about `k` at `C_i` (the two revolutes at `C_i` are a universal joint; the wrist is
//! named so that each limb's bond, the motion of the body after `R(C_i)`, can be asked for). End-effector 1 `ee1` (the bar `C2C1`, frame at
//! `P1`, `x` along `C2 → C1`) turns about `k` on both sub-platforms at `C1` and `C2` (eq. 2's
//! `R(N, k)`). The four-bar of eqs. 7–8: cranks `crank3`, `crank6` about `k` at `C3` (on
//! `sub23`) and `C6` (on `sub16`), the coupler `coupler` (`D3`–`D6`, frame at its middle `P2`,
//! `x` along `D3 → D6`), and `ee2` (frame at `P2`, `x` along `C4 → C5`) turning about `k` on it.
//!
//! Legs, in order: for limb `i`, legs `4i − 3 … 4i` (1-based) are `ground → upper{i}` (`R!R`),
//! the two rods `upper{i} → lower{i}` (`RR`), and `lower{i} →` its sub-platform or wrist (`R`);
//! then legs 25–33: `sub16 → ee1`, `sub23 → ee1`, `sub23 → crank3`, `crank3 → coupler`,
//! `sub16 → crank6`, `crank6 → coupler`, `coupler → ee2`, `wrist4 → ee2`, `wrist5 → ee2`.
//! Twenty-one moving bodies, 33 legs, 51 primitive joints. Lengths in mm, angles in degrees.
//! The actuated joint's file axis is `+u_i`: a positive joint value turns the active link about
//! `u_i`, that is by `+Δθ_i` in the sense of [`Hexa::link_direction`].

use super::{Configuration, FourBarPose, Hexa, Pose, mu, rz};
use kinsyn::manipulator::file::{
    AngleUnit, AxisSpec, BodySpec, FORMAT_2, LegBetween, MultibodyDescription, Units,
};
use nalgebra::Vector3;

/// The ground's name in a HEXA description.
pub const GROUND: &str = "base";

/// The tolerance (in the file's units, mm and degrees) within which a number of a file must
/// equal the regenerated HEXA's for [`Hexa::from_description`] to recognise it.
pub const FILE_TOLERANCE: f64 = 1e-6;

/// Why a description is not paper 001's HEXA, or the HEXA cannot be written at a pose.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum HexaFileError {
    /// The description is not one [`Hexa::description`] writes; the message names the field.
    #[error("not a 6-RUU HEXA description (mechanisms/6-ruu-hexa.json): {0}")]
    NotAHexa(String),
    /// The reference pose cannot be assembled: a limb out of reach, or `P2` off the four-bar.
    #[error("the HEXA cannot be assembled at its reference pose: {0}")]
    Reference(String),
}

/// What a HEXA description holds ([`Hexa::read_description`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HexaFile {
    /// The dimensions (`R, a, b, l, r1 … r5, γ`).
    pub hexa: Hexa,
    /// The reference pose.
    pub reference: Pose,
    /// The half-width `h` of the parallelograms (mm): the rods at `B_i ± h u_i`, `C_i ± h u_i`.
    pub half_width: f64,
}

/// The body frame of a description: origin and turn about `k` (radians).
#[derive(Clone, Copy)]
struct Frame {
    origin: Vector3<f64>,
    turn: f64,
}

impl Frame {
    fn at(origin: Vector3<f64>, turn: f64) -> Self {
        Frame { origin, turn }
    }

    /// A ground-frame point in this frame.
    fn local(&self, p: &Vector3<f64>) -> [f64; 3] {
        let x = rz(-self.turn) * (p - self.origin);
        [x.x, x.y, x.z]
    }

    fn body(&self, name: &str) -> BodySpec {
        BodySpec {
            name: name.into(),
            position: [self.origin.x, self.origin.y, self.origin.z],
            orientation: [0.0, 0.0, self.turn.to_degrees()],
            point: [0.0; 3],
        }
    }
}

fn axis(v: &Vector3<f64>) -> AxisSpec {
    AxisSpec::Vector([v.x, v.y, v.z])
}

/// The body after limb `i`'s `R(C_i)` (0-based): `sub16`, `sub23` or its wrist.
fn platform_of(i: usize) -> &'static str {
    match i {
        0 | 5 => "sub16",
        1 | 2 => "sub23",
        3 => "wrist4",
        _ => "wrist5",
    }
}

impl Hexa {
    /// The HEXA as a `kinsyn-manipulator/2` description (module documentation) at the
    /// reference `pose`, the parallelogram's rods `2 half_width` apart (mm). The limbs are in
    /// the working mode ([`Hexa::inverse`]); the four-bar in its assembly through `P2` nearest
    /// the nominal one ([`Hexa::nominal_four_bar`]) by the position of `D3`.
    ///
    /// # Errors
    /// [`HexaFileError::Reference`] when a limb cannot reach its platform joint, `P2` is off the
    /// four-bar's coupler curve (by more than `1e-9 l`), a limb is stretched along its axis
    /// (`u_i × w_i = 0`: no parallelogram plane), or `half_width` is not a positive length.
    pub fn description(
        &self,
        reference: &Pose,
        half_width: f64,
    ) -> Result<MultibodyDescription, HexaFileError> {
        let bad = |why: String| Err(HexaFileError::Reference(why));
        if !(half_width.is_finite() && half_width > 0.0) {
            return bad(format!(
                "half-width {half_width}: the rods need a positive distance"
            ));
        }
        let Some(conf) = self.inverse(reference) else {
            return bad("a limb cannot reach its platform joint (eq. 5 has no real root)".into());
        };
        let p2 = reference.p2();
        let Some(fb) = &conf.four_bar else {
            return bad(format!(
                "P2 = ({}, {}, {}) is off the four-bar's coupler curve (eqs. 7–8)",
                p2.x, p2.y, p2.z
            ));
        };
        let frames = Self::frames(&conf, fb, reference);
        let legs = self.legs(&conf, fb, &frames, half_width)?;
        Ok(MultibodyDescription {
            format: FORMAT_2.into(),
            name: "6-RUU HEXA with reconfigurable platforms".into(),
            source: Some(self.source(reference, half_width)),
            units: Units {
                length: "mm".into(),
                angle: AngleUnit::Deg,
            },
            ground: GROUND.into(),
            bodies: frames.iter().map(|(name, f)| f.body(name)).collect(),
            end_effector: Some("ee1".into()),
            legs,
        })
    }

    /// The twenty-one bodies' names and frames at a configuration and a four-bar assembly.
    fn frames(conf: &Configuration, fb: &FourBarPose, pose: &Pose) -> Vec<(String, Frame)> {
        let c = &conf.joints;
        let angle = |d: Vector3<f64>| d.y.atan2(d.x);
        let mut frames = Vec::new();
        for (i, (limb, ci)) in conf.limbs.iter().zip(c).enumerate() {
            frames.push((format!("upper{}", i + 1), Frame::at(limb.b, mu(i))));
            frames.push((format!("lower{}", i + 1), Frame::at(*ci, mu(i))));
        }
        frames.extend([
            ("sub16".to_string(), Frame::at(c[0], 0.0)),
            ("sub23".into(), Frame::at(c[1], 0.0)),
            ("ee1".into(), Frame::at(pose.p1(), pose.phi1())),
            ("wrist4".into(), Frame::at(c[3], mu(3))),
            ("wrist5".into(), Frame::at(c[4], mu(4))),
            ("crank3".into(), Frame::at(c[2], angle(fb.d3 - c[2]))),
            ("crank6".into(), Frame::at(c[5], angle(fb.d6 - c[5]))),
            ("coupler".into(), Frame::at(fb.p2, angle(fb.d6 - fb.d3))),
            ("ee2".into(), Frame::at(pose.p2(), pose.phi2())),
        ]);
        frames
    }

    /// The 33 legs (module documentation), their points in the frames of their bodies.
    fn legs(
        &self,
        conf: &Configuration,
        fb: &FourBarPose,
        frames: &[(String, Frame)],
        half_width: f64,
    ) -> Result<Vec<LegBetween>, HexaFileError> {
        let c = &conf.joints;
        let k = Vector3::z();
        let mut legs = Vec::new();
        let mut leg = |chain: &str,
                       (from, to): (&str, &str),
                       (first, last): (Vector3<f64>, Vector3<f64>),
                       axes: Vec<Vector3<f64>>| {
            let local = |name: &str, p: &Vector3<f64>| {
                frames
                    .iter()
                    .find(|(n, _)| n == name)
                    .map_or([p.x, p.y, p.z], |(_, f)| f.local(p))
            };
            legs.push(LegBetween {
                chain: chain.into(),
                from: from.into(),
                to: to.into(),
                first: local(from, &first),
                last: local(to, &last),
                points: None,
                axes: Some(axes.iter().map(axis).collect()),
                actuated: None,
            });
        };
        for (i, (limb, ci)) in conf.limbs.iter().zip(c).enumerate() {
            let u = self.axis(i);
            let n = u.cross(&limb.w);
            if n.norm() <= 1e-12 * limb.w.norm() {
                return Err(HexaFileError::Reference(format!(
                    "limb {}'s parallelogram lies along its axis u_{} (u × w = 0)",
                    i + 1,
                    i + 1
                )));
            }
            let n = n.normalize();
            let (upper, lower) = (format!("upper{}", i + 1), format!("lower{}", i + 1));
            leg(
                "R!R",
                (GROUND, &upper),
                (self.base_joint(i), limb.b),
                vec![u, u],
            );
            for side in [1.0, -1.0] {
                let offset = u * (side * half_width);
                leg(
                    "RR",
                    (&upper, &lower),
                    (limb.b + offset, ci + offset),
                    vec![n, n],
                );
            }
            leg("R", (&lower, platform_of(i)), (*ci, *ci), vec![u]);
        }
        for (from, to, p) in [
            ("sub16", "ee1", c[0]),
            ("sub23", "ee1", c[1]),
            ("sub23", "crank3", c[2]),
            ("crank3", "coupler", fb.d3),
            ("sub16", "crank6", c[5]),
            ("crank6", "coupler", fb.d6),
            ("coupler", "ee2", fb.p2),
            ("wrist4", "ee2", c[3]),
            ("wrist5", "ee2", c[4]),
        ] {
            leg("R", (from, to), (p, p), vec![k]);
        }
        Ok(legs)
    }

    /// The `source` field: the paper, the dimensions, the choices the paper leaves open.
    fn source(&self, reference: &Pose, half_width: f64) -> String {
        let [r1, r2, r3, r4, r5] = self.r;
        let (p1, p2) = (reference.p1(), reference.p2());
        format!(
            "paper 001 (Wu & Dong, Kinematics of a 6-RUU parallel robot with reconfigurable platforms) §2–4: R = {}, a = {}, b = {}, l = {}, r1..r5 = {r1}, {r2}, {r3}, {r4}, {r5} mm; gamma = {} deg (eq. 6b's direction of the sub-platforms' arms C2C3, C1C6, unstated in the paper); parallelogram rods at B_i ± h u_i, C_i ± h u_i with h = {half_width} mm (a modelling choice: any h > 0 gives the same motion). Reference: P1 = ({}, {}, {}), phi1 = {} deg, P2 = ({}, {}, {}), phi2 = {} deg, limbs in the working mode (elbow out), the four-bar's assembly through P2 nearest the nominal one. Bodies: upper{{i}}, lower{{i}} the parallelogram's bars of limb i; sub16, sub23 the sub-platforms; wrist4, wrist5 the wrists of limbs 4, 5; ee1, ee2 the end-effectors (frames at P1, P2); crank3, crank6, coupler the four-bar of eqs. 7–8. Legs 4i-3..4i: limb i (R!R to upper{{i}}, two RR rods, R onto a sub-platform or a wrist); legs 25-33: the platform linkage. Written by Hexa::description (crates/kinsyn-papers/src/hexa/mechanism.rs); regenerate with KINSYN_BLESS=1 cargo test -p kinsyn-papers --test suite hexa_mechanism::",
            self.big_r,
            self.a,
            self.b,
            self.l,
            (self.gamma.to_degrees() * 1e9).round() / 1e9,
            p1.x,
            p1.y,
            p1.z,
            reference.phi1().to_degrees(),
            p2.x,
            p2.y,
            p2.z,
            reference.phi2().to_degrees(),
        )
    }

    /// The HEXA a description was written from ([`Hexa::description`]), with its reference pose
    /// and the rods' half-width: `R`, `a` from `A_1`; `b`, `l` from `B_1`, `C_1`; `r1` from
    /// `C1` on `ee1`; `r2` and `γ` from `C3 − C2` on `sub23`; `r3`, `r4` from `D3` on `crank3`
    /// and the coupler; `r5` from `C5` on `ee2`. The description is then written again from
    /// these and compared, field by field, to [`FILE_TOLERANCE`] (`name` and `source` aside).
    ///
    /// # Errors
    /// [`HexaFileError::NotAHexa`] naming the first field that differs from the regenerated
    /// HEXA (or the bodies and legs that are missing), [`HexaFileError::Reference`] when the
    /// dimensions read cannot be assembled at the file's reference.
    pub fn from_description(d: &MultibodyDescription) -> Result<Hexa, HexaFileError> {
        Self::read_description(d).map(|f| f.hexa)
    }

    /// [`Hexa::from_description`] with the file's reference pose and the rods' half-width.
    ///
    /// # Errors
    /// See [`Hexa::from_description`].
    pub fn read_description(d: &MultibodyDescription) -> Result<HexaFile, HexaFileError> {
        let not = |why: String| HexaFileError::NotAHexa(why);
        if d.bodies.len() != 21 || d.legs.len() != 33 {
            return Err(not(format!(
                "{} moving bodies and {} legs, where the HEXA has 21 and 33",
                d.bodies.len(),
                d.legs.len()
            )));
        }
        let angle = |a: f64| d.units.angle.to_radians(a);
        let body = |name: &str| {
            d.bodies
                .iter()
                .find(|b| b.name == name)
                .ok_or_else(|| not(format!("no body named {name:?}")))
        };
        let v = |p: &[f64; 3]| Vector3::from(*p);
        let a1 = v(&d.legs[0].first);
        let b1 = v(&body("upper1")?.position);
        let c1 = v(&body("lower1")?.position);
        let arm = v(&d.legs[26].first);
        let (ee1, ee2) = (body("ee1")?, body("ee2")?);
        let hexa = Hexa {
            big_r: a1.y,
            a: a1.x,
            b: (b1 - a1).norm(),
            l: (c1 - b1).norm(),
            r: [
                v(&d.legs[24].last).norm(),
                arm.norm(),
                v(&d.legs[27].first).norm(),
                v(&d.legs[27].last).norm(),
                v(&d.legs[32].last).norm(),
            ],
            gamma: (-arm.y).atan2(-arm.x),
        };
        let pose = Pose::new(
            &v(&ee1.position),
            angle(ee1.orientation[2]),
            &v(&ee2.position),
            angle(ee2.orientation[2]),
        );
        let half_width = v(&d.legs[1].first).norm();
        let mut again = hexa.description(&pose, half_width)?;
        if d.units.angle == AngleUnit::Rad {
            for b in &mut again.bodies {
                b.orientation = b.orientation.map(f64::to_radians);
            }
        }
        again.units.angle = d.units.angle;
        again.name.clone_from(&d.name);
        again.source.clone_from(&d.source);
        let (ours, theirs) = (
            serde_json::to_value(&again).unwrap_or_default(),
            serde_json::to_value(d).unwrap_or_default(),
        );
        if let Some(path) = first_difference(&theirs, &ours, "") {
            return Err(not(format!(
                "{path} differs from the HEXA with R = {}, a = {}, b = {}, l = {}, r = {:?}, gamma = {} deg read from it",
                hexa.big_r,
                hexa.a,
                hexa.b,
                hexa.l,
                hexa.r,
                hexa.gamma.to_degrees()
            )));
        }
        Ok(HexaFile {
            hexa,
            reference: pose,
            half_width,
        })
    }
}

/// The path of the first place where two JSON values differ (numbers by more than
/// [`FILE_TOLERANCE`]), or `None`.
fn first_difference(a: &serde_json::Value, b: &serde_json::Value, path: &str) -> Option<String> {
    use serde_json::Value;
    let here = || {
        if path.is_empty() {
            "file".to_string()
        } else {
            path.to_string()
        }
    };
    match (a, b) {
        (Value::Number(x), Value::Number(y)) => {
            let (x, y) = (x.as_f64()?, y.as_f64()?);
            ((x - y).abs() > FILE_TOLERANCE).then(|| format!("{} ({x} ≠ {y})", here()))
        }
        (Value::Array(x), Value::Array(y)) => {
            if x.len() != y.len() {
                return Some(format!("{} (length {} ≠ {})", here(), x.len(), y.len()));
            }
            x.iter()
                .zip(y)
                .enumerate()
                .find_map(|(i, (x, y))| first_difference(x, y, &format!("{path}[{i}]")))
        }
        (Value::Object(x), Value::Object(y)) => {
            let keys: std::collections::BTreeSet<&String> = x.keys().chain(y.keys()).collect();
            keys.into_iter().find_map(|k| {
                let sub = if path.is_empty() {
                    k.clone()
                } else {
                    format!("{path}.{k}")
                };
                match (x.get(k), y.get(k)) {
                    (Some(x), Some(y)) => first_difference(x, y, &sub),
                    _ => Some(format!("{sub} (present in one only)")),
                }
            })
        }
        _ => (a != b).then(|| format!("{} ({a} ≠ {b})", here())),
    }
}
