//! The chain notation (src/notation.rs) against paper 000 §2's own examples.

use kinsyn::notation::{Axis, AxisWord, Chain, NotationError, letters_fit_word};
use nalgebra::Vector3;
use proptest::prelude::*;

fn parse(s: &str) -> Chain {
    s.parse().unwrap_or_else(|e| panic!("{s}: {e}"))
}

#[test]
fn rule_4_example_three_parallel_then_two() {
    // Paper 000 §2 rule 4: "the chain RRRRRR ... The first three RRR pairs are parallel between
    // them ...; the next two RR (in italics) are parallel between them ...; the last R pair
    // forms 90° with respect to the previous set". Underline = group a, italics = group b.
    let c = parse("RaRaRaRbRbR");
    assert_eq!(c.letters(), "RRRRRR");
    assert_eq!(c.parallel_groups(), vec![vec![1, 2, 3], vec![4, 5]]);
    // Read with rule 3 (consecutive perpendicular R intersect): R R U(R3 R4) R5 R6 is one of
    // its readings; R4 ∥ R5 so they never share a U.
    let read = parse("RaRaU(a,b)U(b,-)");
    assert_eq!(read.primitive_word(), "RRRRRR");
    assert_eq!(read.parallel_groups(), c.parallel_groups());
}

#[test]
fn rule_4_example_three_groups() {
    // Rule 4: "In the case of having three groups of revolute joints ..., the third group will
    // be written in bold". Groups a, b, c = underline, italics, bold.
    let c = parse("RaU(a,b)U(b,c)Rc");
    assert_eq!(c.letters(), "RUUR");
    assert_eq!(
        c.parallel_groups(),
        vec![vec![1, 2], vec![3, 4], vec![5, 6]]
    );
    assert_eq!(c.to_string(), "RaU(a,b)U(b,c)Rc");
}

#[test]
fn section_2_2_uu_marking() {
    // §2.2: "UU ≡ RRRR symbolizes that the parallel axes are the ones associated with the last
    // R joint and the first R joint of the resulting universal joints": primitives 2 and 3.
    let c = parse("U(-,a)U(a,-)");
    assert_eq!(c.parallel_groups(), vec![vec![2, 3]]);
    assert_ne!(c, parse("UU"));
}

#[test]
fn actuation_marks_the_primitive() {
    // §5: the 3-UPS has two inputs per leg, the first R of the U (α) and the P (c).
    let c = parse("U(!,-)P!S");
    let actuated: Vec<usize> = c
        .primitives()
        .enumerate()
        .filter(|(_, (_, m))| m.actuated)
        .map(|(i, _)| i + 1)
        .collect();
    assert_eq!(actuated, vec![1, 3]);
    assert_eq!(c.to_string(), "U(!,-)P!S");
    assert_eq!(c.without_actuation().to_string(), "UPS");
    // A C's R in a group: the short form and the slot form are the same chain.
    assert_eq!(parse("CaRa"), parse("C(-,a)Ra"));
    assert_eq!(parse("C(!,a)Ra").to_string(), "C(!,a)Ra");
}

#[test]
fn groups_are_numbered_in_order_of_appearance() {
    // The paper's first marked group is the underline, whatever letter the user picked.
    assert_eq!(parse("RbRbRaRa"), parse("RaRaRbRb"));
    assert_eq!(parse("RbRbRaRa").to_string(), "RaRaRbRb");
    assert_eq!(parse(" P P S "), parse("PPS"));
}

#[test]
fn a_prismatic_does_not_break_a_group() {
    // Rule 5 of the reading: a P rotates nothing, so R P R with equal axes stay parallel.
    assert_eq!(parse("RaPRa").parallel_groups(), vec![vec![1, 3]]);
}

#[test]
fn errors_name_the_position() {
    use NotationError as E;
    let cases: Vec<(&str, E)> = vec![
        ("", E::Empty),
        ("   ", E::Empty),
        (
            "PXR",
            E::UnknownCharacter {
                column: 2,
                found: 'X',
            },
        ),
        (
            "aPR",
            E::DanglingMark {
                column: 1,
                found: 'a',
            },
        ),
        (
            "(a)",
            E::DanglingMark {
                column: 1,
                found: '(',
            },
        ),
        ("PPPRRRR", E::TooManyPrimitives { count: 7 }),
        ("SSR", E::TooManyPrimitives { count: 7 }),
        ("PaRR", E::GroupOnPrismatic { column: 2 }),
        ("C(a,-)R", E::GroupOnPrismatic { column: 3 }),
        (
            "RaR",
            E::LoneGroup {
                column: 2,
                group: 'a',
            },
        ),
        (
            "U(a,a)",
            E::GroupInsideJoint {
                column: 1,
                letter: 'U',
                group: 'a',
            },
        ),
        (
            "PS(a,-,a)",
            E::GroupInsideJoint {
                column: 2,
                letter: 'S',
                group: 'a',
            },
        ),
        (
            "RaRRa",
            E::BrokenGroup {
                column: 3,
                group: 'a',
            },
        ),
        (
            "U(a)",
            E::SlotCount {
                column: 1,
                letter: 'U',
                expected: 2,
                found: 1,
            },
        ),
        (
            "U(x,-)",
            E::BadSlot {
                column: 3,
                slot: "x".into(),
            },
        ),
        ("U(a,-", E::Unclosed { column: 2 }),
        (
            "Ua",
            E::NeedsSlots {
                column: 2,
                letter: 'U',
            },
        ),
        (
            "C!",
            E::NeedsSlots {
                column: 2,
                letter: 'C',
            },
        ),
    ];
    for (input, expected) in cases {
        let got = input.parse::<Chain>().expect_err(input);
        assert_eq!(got, expected, "input {input:?}");
        assert!(
            !got.to_string().contains('\n'),
            "one-line message for {input:?}"
        );
    }
}

#[test]
fn letters_fit_word_reads_merged_joints() {
    // C = PR or RP (rule 2), U = RR, S = RRR (rule 3).
    assert!(letters_fit_word("PPCU", "PPPRRR"));
    assert!(letters_fit_word("CRRC", "RPRRPR"));
    assert!(letters_fit_word("CRRC", "PRRRRP"));
    assert!(!letters_fit_word("CRC", "PRRRRP")); // Table 2 row 6 prints CRC: five primitives
    assert!(!letters_fit_word("PPRRPR", "PPRRP"));
}

#[test]
fn axis_directions_read_and_print_as_x_y_z() {
    // Rule 1 of paper 000 §2: three mutually perpendicular directions, written x, y, z in the
    // catalogue's axis words; each is the unit vector of its frame axis.
    for (text, axis, unit) in [
        ("x", Axis::X, Vector3::new(1.0, 0.0, 0.0)),
        ("y", Axis::Y, Vector3::new(0.0, 1.0, 0.0)),
        ("z", Axis::Z, Vector3::new(0.0, 0.0, 1.0)),
    ] {
        assert_eq!(text.parse::<Axis>(), Ok(axis));
        assert_eq!(axis.to_string(), text);
        assert_eq!(axis.unit(), unit);
        assert_eq!(Axis::from_index(axis.index()), Some(axis));
    }
    for bad in ["", "X", "w", "xy", " x"] {
        assert!(bad.parse::<Axis>().is_err(), "{bad:?}");
    }
    // PPPS (Table 1 row 1): three perpendicular guides, then the S's three revolutes.
    let word: AxisWord = "xyzxyz".parse().unwrap();
    assert_eq!(
        word.axes().collect::<Vec<_>>(),
        [Axis::X, Axis::Y, Axis::Z, Axis::X, Axis::Y, Axis::Z]
    );
    assert_eq!(word.to_string(), "xyzxyz");
    assert_eq!(serde_json::to_string(&word).unwrap(), "\"xyzxyz\"");
    assert_eq!(
        serde_json::from_str::<AxisWord>("\"zzx\"")
            .unwrap()
            .as_str(),
        "zzx"
    );
    assert!(serde_json::from_str::<AxisWord>("\"xyq\"").is_err());
    let e = "xyq".parse::<AxisWord>().unwrap_err().to_string();
    assert_eq!(e, r#""xyq": "q" is not an axis direction; write x, y or z"#);
}

proptest! {
    /// Any string over the notation's alphabet either parses or is rejected with an error, never
    /// a panic; what parses prints to a canonical text that parses back to the same chain.
    #[test]
    fn parse_never_panics_and_round_trips(s in "[PRCUSabc!(),\\- x]{0,16}") {
        if let Ok(chain) = s.parse::<Chain>() {
            let text = chain.to_string();
            let again: Chain = text.parse().expect("canonical text parses");
            prop_assert_eq!(&again, &chain);
            prop_assert_eq!(again.to_string(), text);
        }
    }
}
