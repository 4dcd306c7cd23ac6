//! The comparison with a printed table given as data (src/published.rs), on a small table made
//! up here: what is printed and generated, misprinted, printed elsewhere or not at all, pooled
//! tables, and the rows refused. Paper 000's Appendix itself is the papers' tests/suite/appendix.rs.

use kinsyn::catalogue::Catalogue;
use kinsyn::notation::letters_fit_word;
use kinsyn::published::{
    Comparison, DifferenceKind, PrintedError, PrintedRow, PrintedTables, RowKey,
};
use kinsyn::synthesis::{Candidate, Options, TABLES, enumerate};
use std::collections::BTreeSet;

fn row(table: u8, row: usize, word: &str, chains: &[&str]) -> PrintedRow {
    PrintedRow {
        table,
        row,
        printed_word: word.to_string(),
        word: word.to_string(),
        variant: None,
        chains: chains.iter().map(|c| (*c).to_string()).collect(),
    }
}

/// The distinct letters generated for Table 1's row `r`, in order.
fn generated(candidates: &[Candidate], r: usize) -> Vec<String> {
    candidates
        .iter()
        .filter(|c| c.table == 1 && c.row == r)
        .map(|c| c.chain.letters())
        .collect::<BTreeSet<_>>()
        .into_iter()
        .collect()
}

#[test]
fn each_difference_is_classified_with_its_evidence() {
    let candidates = enumerate(&Options::default());
    let words = TABLES[0].words;
    // The row of Table 1 with the most chains, and another row.
    let r = (1..=words.len())
        .max_by_key(|&r| generated(&candidates, r).len())
        .unwrap();
    let other = if r == 1 { 2 } else { 1 };
    let row_r = generated(&candidates, r);
    assert!(row_r.len() >= 3, "{row_r:?}");
    let (kept, moved) = (row_r[0].as_str(), row_r[1].as_str());
    // Row r prints one of its chains and a name no reading of its word gives (two S need six
    // revolutes); the other row prints another chain of row r.
    let printed = PrintedTables::new(
        "the test table",
        vec![
            row(1, r, words[r - 1], &[kept, "SS"]),
            row(1, other, words[other - 1], &[moved]),
        ],
        [],
    )
    .unwrap();
    let comparison = Comparison::new(&printed, &candidates);
    let key = RowKey { table: 1, row: r };
    let of_row_r: Vec<_> = comparison
        .differences
        .iter()
        .filter(|d| d.key == key)
        .collect();
    let kind_of = |letters: &str| {
        of_row_r
            .iter()
            .find(|d| d.letters == letters)
            .map(|d| (d.kind, d.evidence.clone()))
    };
    assert_eq!(kind_of(kept), None);
    assert_eq!(kind_of("SS").unwrap().0, DifferenceKind::Misprint);
    assert_eq!(
        kind_of(moved).unwrap(),
        (
            DifferenceKind::PrintedElsewhere,
            format!("the rules give it here; printed in Table 1 row {other}")
        )
    );
    for letters in &row_r[2..] {
        assert_eq!(
            kind_of(letters).unwrap(),
            (
                DifferenceKind::NotPrinted,
                "the rules give it; no row of the test table prints it".to_string()
            ),
            "{letters}"
        );
    }
    // Every generated chain but the one printed, and the misprint.
    assert_eq!(of_row_r.len(), row_r.len());
    // Counted by table and kind (the other row's print may be a misprint there too).
    let counts = comparison.counts();
    assert_eq!(counts.values().sum::<usize>(), comparison.differences.len());
    assert_eq!(
        counts[&(1, DifferenceKind::Misprint)],
        1 + usize::from(!letters_fit_word(moved, words[other - 1]))
    );
    assert!(
        comparison
            .markdown()
            .contains(&format!("| 1 | {r} | {} | SS | misprint |", words[r - 1]))
    );
    // The catalogue marks its entries against the same table.
    let catalogue = Catalogue::from_candidates(Options::default(), &candidates, &printed);
    let entry = |letters: &str| {
        catalogue
            .entries
            .iter()
            .find(|e| e.letters == letters)
            .unwrap()
    };
    // An entry is printed "in its row" when its provenance (its first occurrence) is that row.
    let kept_entry = entry(kept);
    assert_eq!(
        (kept_entry.printed_in_row, kept_entry.printed_in_appendix),
        (kept_entry.provenance.row == r, true)
    );
    let moved_entry = entry(moved);
    assert_eq!(
        (moved_entry.printed_in_row, moved_entry.printed_in_appendix),
        (moved_entry.provenance.row == other, true)
    );
    assert_eq!(catalogue.counts[0].printed_letters, 3);
    assert!(catalogue.counts[1..].iter().all(|c| c.printed_letters == 0));
}

#[test]
fn a_pooled_table_is_compared_as_one_row() {
    let candidates = enumerate(&Options::default());
    let words = TABLES[0].words;
    let row_2 = generated(&candidates, 2);
    // Printed in row 1 of a pooled Table 1: printed "in its row" for row 2's chains too.
    let printed = PrintedTables::new(
        "the test table",
        vec![row(1, 1, words[0], &[row_2[0].as_str()])],
        [1],
    )
    .unwrap();
    assert_eq!(printed.key(1, 5), RowKey { table: 1, row: 0 });
    assert_eq!(printed.key(2, 5), RowKey { table: 2, row: 5 });
    assert!(printed.printed_in(1, 2, &row_2[0]));
    let comparison = Comparison::new(&printed, &candidates);
    assert!(
        comparison
            .rows
            .iter()
            .all(|r| r.key.table != 1 || r.key.row == 0)
    );
    assert!(
        comparison
            .differences
            .iter()
            .all(|d| !(d.key.table == 1 && d.letters == row_2[0]))
    );
}

#[test]
fn rows_outside_the_synthesis_tables_are_refused() {
    let refused = |r: PrintedRow| PrintedTables::new("t", vec![r], []).unwrap_err();
    assert_eq!(
        refused(row(5, 1, "RRRRRR", &["UUU"])),
        PrintedError::UnknownTable { table: 5, row: 1 }
    );
    assert_eq!(
        refused(row(1, 0, "PPPRRR", &["PPPS"])),
        PrintedError::RowZero { table: 1 }
    );
    assert_eq!(
        refused(row(1, 3, "PPPRRU", &["PPPS"])),
        PrintedError::NotAWord {
            table: 1,
            row: 3,
            word: "PPPRRU".to_string()
        }
    );
    let empty = PrintedTables::default();
    assert!(empty.rows().is_empty() && !empty.printed_anywhere("PPPS"));
}
