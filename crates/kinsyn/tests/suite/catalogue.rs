//! The catalogue files (src/catalogue.rs) and the invariants of their entries, built against no
//! printed table (the committed catalogue, marked against paper 000's Appendix, is checked by
//! the papers' tests/suite/appendix.rs).

use kinsyn::catalogue::{COMMITTED_JSON, Catalogue, FORMAT, LoadError};
use kinsyn::notation::{Chain, letters_fit_word};
use kinsyn::published::PrintedTables;
use kinsyn::synthesis::Options;
use kinsyn::synthesis::PrismaticReading;
use std::collections::BTreeSet;

#[test]
fn entries_are_unique_and_counted() {
    let cat = Catalogue::generate(&Options::default(), &PrintedTables::default());
    let ids: BTreeSet<&str> = cat.entries.iter().map(|e| e.id.as_str()).collect();
    let notations: BTreeSet<&str> = cat.entries.iter().map(|e| e.notation.as_str()).collect();
    let letters: BTreeSet<&str> = cat.entries.iter().map(|e| e.letters.as_str()).collect();
    assert_eq!(ids.len(), cat.entries.len());
    assert_eq!(notations.len(), cat.entries.len());
    let (by_letters, by_marks) = cat.totals();
    assert_eq!(by_marks, cat.entries.len());
    assert_eq!(by_letters, letters.len());
    assert_eq!(
        cat.entries.iter().filter(|e| e.first_with_letters).count(),
        by_letters
    );
    // Paper 000 §2.1: Table 1 holds 63 chains.
    assert_eq!(cat.counts[0].letters_only, 63);
}

#[test]
fn every_entry_round_trips_and_matches_its_axes() {
    let cat = Catalogue::generate(&Options::default(), &PrintedTables::default());
    for e in &cat.entries {
        let chain: Chain = e
            .notation
            .parse()
            .unwrap_or_else(|err| panic!("{}: {err}", e.notation));
        assert_eq!(chain.to_string(), e.notation);
        assert_eq!(chain.letters(), e.letters);
        assert_eq!(chain.parallel_groups().len(), e.parallel_groups.len());
        assert!(letters_fit_word(&e.letters, &e.word));
        // Independent check of the parallel groups from the axis word: two revolutes are in one
        // group exactly when they share a direction and no revolute between them turns away
        // (§2.3: RRR = RRR).
        let axes: Vec<char> = e.axes.chars().collect();
        let word: Vec<char> = e.word.chars().collect();
        let revolutes: Vec<usize> = (0..6).filter(|&i| word[i] == 'R').collect();
        for pair in revolutes.windows(2) {
            let (i, j) = (pair[0], pair[1]);
            let same_group = e
                .parallel_groups
                .iter()
                .any(|g| g.contains(&(i + 1)) && g.contains(&(j + 1)));
            assert_eq!(
                same_group,
                axes[i] == axes[j],
                "{} {} {}",
                e.id,
                e.notation,
                e.axes
            );
        }
        // Merged joints agree with the axes: C coaxial, U and S mutually perpendicular.
        let mut at = 0;
        for joint in chain.joints() {
            let n = joint.kind.primitives().len();
            let dirs: BTreeSet<char> = axes[at..at + n].iter().copied().collect();
            match joint.kind.letter() {
                'C' => assert_eq!(dirs.len(), 1, "{}", e.id),
                'U' | 'S' => assert_eq!(dirs.len(), n, "{}", e.id),
                _ => {}
            }
            at += n;
        }
    }
}

#[test]
fn find_by_id_and_by_notation() {
    let cat = Catalogue::generate(&Options::default(), &PrintedTables::default());
    let first = &cat.entries[0];
    assert_eq!(cat.find(&first.id).unwrap().id, first.id);
    assert_eq!(cat.find(&first.id.to_lowercase()).unwrap().id, first.id);
    assert_eq!(cat.find(&first.notation).unwrap().id, first.id);
    // The same marks spelt with other group letters find the same entry.
    let marked = cat
        .entries
        .iter()
        .find(|e| e.notation == "PPU(-,a)U(a,-)")
        .expect("PPUU with its middle pair parallel (Table 2 row 1)");
    assert_eq!(cat.find("PPU(-,b)U(b,-)").unwrap().id, marked.id);
    assert!(cat.find("T9-999").is_none());
    assert!(cat.find("SS").is_none());
}

/// A catalogue without the numerical check (another reading, §2's perpendicular guides) reads
/// back as written: entries without verification, counts without verified numbers.
#[test]
fn an_unverified_catalogue_round_trips_through_json() {
    let options = Options {
        prismatics: PrismaticReading::Perpendicular,
        ..Options::default()
    };
    let cat = Catalogue::synthesise(&options, &PrintedTables::default());
    let back = Catalogue::from_json(&cat.to_json()).unwrap();
    assert_eq!(back.options, options);
    assert_eq!(back.entries, cat.entries);
    assert_eq!(back.counts, cat.counts);
    assert!(back.verification.is_none());
    assert!(back.entries.iter().all(|e| e.verification.is_none()));
}

/// Another format version is refused by name; a damaged file is refused with the place of the
/// fault.
#[test]
fn from_json_checks_the_format_version() {
    let old = COMMITTED_JSON.replacen(FORMAT, "kinsyn-catalogue/1", 1);
    match Catalogue::from_json(&old) {
        Err(LoadError::Format { found }) => assert_eq!(found, "kinsyn-catalogue/1"),
        other => panic!("expected a format error, got {:?}", other.err()),
    }
    // Another version whose shape differs is still named as another version.
    let future = r#"{"format": "kinsyn-catalogue/4", "chains": []}"#;
    assert!(matches!(
        Catalogue::from_json(future),
        Err(LoadError::Format { .. })
    ));
    // No version at all, or a damaged entry: a parse error naming the field.
    let err = Catalogue::from_json(r#"{"entries": []}"#).unwrap_err();
    assert!(matches!(err, LoadError::Parse(_)), "{err}");
    let damaged = COMMITTED_JSON.replacen("\"rank\": 6", "\"rank\": \"six\"", 1);
    let err = Catalogue::from_json(&damaged).unwrap_err();
    assert!(matches!(err, LoadError::Parse(_)), "{err}");
    assert!(
        err.to_string()
            .contains("entries[0].readings[0].check.rank"),
        "{err}"
    );
    let err = Catalogue::from_json(&COMMITTED_JSON[..1000]).unwrap_err();
    assert!(matches!(err, LoadError::Parse(_)), "{err}");
    assert_eq!(err.to_string().lines().count(), 1, "{err}");
}
