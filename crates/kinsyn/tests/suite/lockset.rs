//! Lock sets (src/lockset.rs): the catalogue's text form (`-`, `456`) kept byte for byte, and an
//! unambiguous form for joints 10 and beyond (`1,10,12`), which the earlier `lock_text` printed
//! as `?`.

use kinsyn::lockset::{LockSet, LockSetError};
use proptest::prelude::*;

fn set(joints: &[usize]) -> LockSet {
    joints.iter().copied().collect()
}

#[test]
fn catalogue_lock_sets_keep_their_text() {
    // The forms of catalogue/chains.json: none, one joint, PPPS's spherical joint (T3 with
    // joints 4, 5, 6 locked, Table 1 row 1), every joint of a 6-joint leg.
    for (joints, text) in [
        (&[][..], "-"),
        (&[2][..], "2"),
        (&[4, 5, 6][..], "456"),
        (&[1, 2, 4][..], "124"),
        (&[1, 2, 3, 4, 5, 6][..], "123456"),
        (&[9][..], "9"),
    ] {
        let s = set(joints);
        assert_eq!(s.to_string(), text);
        assert_eq!(text.parse::<LockSet>(), Ok(s));
        assert_eq!(s.joints().collect::<Vec<_>>(), joints);
        assert_eq!(s.len(), joints.len());
        assert_eq!(serde_json::to_string(&s).unwrap(), format!("\"{text}\""));
        assert_eq!(
            serde_json::from_str::<LockSet>(&format!("\"{text}\"")).unwrap(),
            s
        );
    }
}

#[test]
fn joints_ten_and_beyond_are_numbers_with_commas() {
    // The old lock_text wrote joint 10 of a longer chain as '?': "1?" for joints 1 and 10,
    // which reads back as nothing. Now any joint of 10 or more switches the whole set to
    // comma-separated numbers, and a lone such joint keeps a trailing comma ("12" would be
    // joints 1 and 2).
    for (joints, text) in [
        (&[1, 10][..], "1,10"),
        (&[1, 10, 12][..], "1,10,12"),
        (&[10][..], "10,"),
        (&[12][..], "12,"),
        (&[3, 31][..], "3,31"),
        (&[32][..], "32,"),
        (
            &[1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11][..],
            "1,2,3,4,5,6,7,8,9,10,11",
        ),
    ] {
        let s = set(joints);
        assert_eq!(s.to_string(), text, "{joints:?}");
        assert_eq!(text.parse::<LockSet>(), Ok(s), "{text}");
        assert_eq!(LockSet::parse_for(text, 32), Ok(s), "{text}");
    }
    assert!(!set(&[1, 10]).to_string().contains('?'));
    assert_eq!("12".parse::<LockSet>(), Ok(set(&[1, 2])));
    assert_eq!("12,".parse::<LockSet>(), Ok(set(&[12])));
}

#[test]
fn user_spellings_read_as_the_catalogue_form() {
    // `kinsyn catalogue show T1-001 --lock 4,5` and its other spellings.
    for text in ["45", "4,5", "4, 5", "4 5", " 45 ", "5,4"] {
        assert_eq!(LockSet::parse_for(text, 6), Ok(set(&[4, 5])), "{text:?}");
    }
    assert_eq!(LockSet::parse_for("-", 6), Ok(LockSet::NONE));
    assert_eq!(LockSet::parse_for("", 6), Ok(LockSet::NONE));
}

#[test]
fn bad_lock_sets_are_typed_errors() {
    assert_eq!(
        LockSet::parse_for("9", 6),
        Err(LockSetError::NotAJoint {
            text: "9".into(),
            joint: 9,
            joints: 6
        })
    );
    assert_eq!(
        LockSet::parse_for("11", 6),
        Err(LockSetError::Repeated {
            text: "11".into(),
            joint: 1
        })
    );
    assert_eq!(
        LockSet::parse_for("0", 6),
        Err(LockSetError::NotAJoint {
            text: "0".into(),
            joint: 0,
            joints: 6
        })
    );
    assert_eq!(
        LockSet::parse_for("1,11", 10),
        Err(LockSetError::NotAJoint {
            text: "1,11".into(),
            joint: 11,
            joints: 10
        })
    );
    assert_eq!(
        LockSet::parse_for("4a", 6),
        Err(LockSetError::NotANumber {
            text: "4a".into(),
            found: "a".into()
        })
    );
    assert!("33,".parse::<LockSet>().is_err());
    assert!("+4,5".parse::<LockSet>().is_err());
    assert_eq!(
        LockSet::parse_for("9", 6).unwrap_err().to_string(),
        "lock set \"9\": joint 9 is not a joint of this chain (joints 1 to 6)"
    );
}

proptest! {
    /// Every set of joints 1 to 32 prints to a text that reads back to it, and its text has
    /// digits only exactly when no joint is 10 or more.
    #[test]
    fn every_set_round_trips(mask in any::<u32>()) {
        let s = LockSet::from_mask(mask);
        let text = s.to_string();
        prop_assert_eq!(text.parse::<LockSet>(), Ok(s));
        let small = s.joints().all(|j| j <= 9);
        prop_assert_eq!(!text.contains(','), small);
        prop_assert_eq!(s.mask(), mask);
    }
}
