//! Paper 000's printed Appendix (`kinsyn_papers::appendix`, data/paper000-appendix.tsv): the
//! transcription, the row-by-row comparison with the enumeration against docs/deviations.md,
//! and the committed catalogue (`catalogue/`), which is marked against it.

use kinsyn::catalogue::{COMMITTED_JSON, Catalogue};
use kinsyn::published::{DifferenceKind, PrintedTables};
use kinsyn::synthesis::{Options, PrismaticReading, TABLES};
use kinsyn_papers::appendix;
use std::collections::BTreeSet;
use std::path::Path;
use std::sync::OnceLock;

/// The catalogue `kinsyn catalogue generate` writes, with its comparison (generated once).
fn generated() -> &'static (Catalogue, kinsyn::published::Comparison) {
    static C: OnceLock<(Catalogue, kinsyn::published::Comparison)> = OnceLock::new();
    C.get_or_init(|| appendix::generate(&Options::default()))
}

#[test]
fn the_appendix_is_a_printed_table_of_the_synthesis_tables() {
    // Every row is of a synthesis table, numbered from 1, with a P/R word: the checks that let
    // the comparison explain a printed chain by the rules.
    let printed = PrintedTables::new(appendix::NAME, appendix::appendix(), appendix::POOLED)
        .expect("the transcription is a printed table");
    assert_eq!(printed, appendix::printed());
    assert_eq!(printed.rows().len(), 201);
    assert!(printed.is_pooled(7) && printed.is_pooled(8) && !printed.is_pooled(4));
}

#[test]
fn the_transcription_has_every_printed_row() {
    let rows = appendix::appendix();
    let count = |t: u8| rows.iter().filter(|r| r.table == t).count();
    // Table 1: 20 permutations; Table 2: 15 permutations × 4 variant sub-rows; Table 3: six
    // permutations with 8 sub-rows each except row 2 (7 printed); Table 4: 6 × 8; Table 7: 10
    // rows (Table 5's 10 variants); Table 8: 16 rows (Table 6's 16 variants).
    assert_eq!(
        [count(1), count(2), count(3), count(4), count(7), count(8)],
        [20, 60, 47, 48, 10, 16]
    );
    for r in &rows {
        assert!(!r.chains.is_empty(), "table {} row {}", r.table, r.row);
        assert!(
            r.chains
                .iter()
                .all(|c| c.chars().all(|ch| "PRCUS".contains(ch))),
            "letters only in {:?}",
            r.chains
        );
    }
}

#[test]
fn each_row_holds_the_tables_word_in_order() {
    // The word a row holds, read from its chains, is the table's word at that position: this
    // pins the Appendix row order that "first occurrence wins" follows.
    for r in appendix::appendix().iter().filter(|r| r.table <= 4) {
        let table = TABLES.iter().find(|t| t.number == r.table).unwrap();
        assert_eq!(
            table.words[r.row - 1],
            r.word,
            "table {} row {}",
            r.table,
            r.row
        );
    }
}

#[test]
fn misprinted_words_of_table_1() {
    // docs/deviations.md: Table 1's 'Kinematic chain' column misprints rows 1, 6, 7, 8, 15,
    // 17, 18, 19; Tables 2–4 print every word correctly.
    let misprinted: BTreeSet<(u8, usize)> = appendix::appendix()
        .iter()
        .filter(|r| r.printed_word != r.word)
        .map(|r| (r.table, r.row))
        .collect();
    let expected: BTreeSet<(u8, usize)> = [1, 6, 7, 8, 15, 17, 18, 19]
        .into_iter()
        .map(|r| (1, r))
        .collect();
    assert_eq!(misprinted, expected);
}

#[test]
fn table_1_matches_row_by_row_except_misprints() {
    // Table 1 (63 chains, §2.1): every difference is a misprinted name or the omission that
    // misprint leaves, or a crossed-out repeat left out (docs/deviations.md).
    let (_, comparison) = appendix::synthesise(&Options::default());
    for d in comparison.differences.iter().filter(|d| d.key.table == 1) {
        assert!(
            matches!(
                d.kind,
                DifferenceKind::Misprint
                    | DifferenceKind::NotPrinted
                    | DifferenceKind::PrintedElsewhere
            ),
            "{d:?}"
        );
    }
}

/// The Markdown table between the markers of docs/deviations.md.
fn documented() -> Vec<String> {
    let doc = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../docs/deviations.md"
    ))
    .expect("docs/deviations.md");
    let begin = doc
        .find("<!-- differences:begin -->")
        .expect("begin marker");
    let end = doc.find("<!-- differences:end -->").expect("end marker");
    doc[begin..end]
        .lines()
        .filter(|l| l.starts_with("| ") && !l.starts_with("| table "))
        .map(str::to_string)
        .collect()
}

#[test]
fn every_difference_from_the_appendix_is_documented() {
    let (_, comparison) = appendix::synthesise(&Options::default());
    let generated: Vec<String> = comparison
        .markdown()
        .lines()
        .filter(|l| l.starts_with("| ") && !l.starts_with("| table "))
        .map(str::to_string)
        .collect();
    let documented = documented();
    let undocumented: Vec<&String> = generated
        .iter()
        .filter(|l| !documented.contains(l))
        .collect();
    let stale: Vec<&String> = documented
        .iter()
        .filter(|l| !generated.contains(l))
        .collect();
    assert!(
        undocumented.is_empty() && stale.is_empty(),
        "docs/deviations.md is out of date (regenerate with `kinsyn catalogue compare` and explain).\nundocumented:\n{}\nstale:\n{}",
        undocumented
            .iter()
            .map(|l| l.as_str())
            .collect::<Vec<_>>()
            .join("\n"),
        stale
            .iter()
            .map(|l| l.as_str())
            .collect::<Vec<_>>()
            .join("\n")
    );
    // Every kind name in the document is one the code knows.
    for l in &documented {
        let kind = l.split('|').nth(5).unwrap().trim();
        assert!(DifferenceKind::from_name(kind).is_some(), "{kind}");
    }
}

#[test]
fn committed_catalogue_is_reproduced_byte_for_byte() {
    let dir = tempfile::tempdir().unwrap();
    let (catalogue, comparison) = generated();
    catalogue
        .write(dir.path(), comparison, kinsyn::output::Overwrite::Refuse)
        .unwrap();
    let committed = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join("catalogue");
    for name in ["chains.json", "chains.csv", "README.md"] {
        let fresh = std::fs::read(dir.path().join(name)).unwrap();
        let old =
            std::fs::read(committed.join(name)).unwrap_or_else(|e| panic!("catalogue/{name}: {e}"));
        assert!(
            fresh == old,
            "catalogue/{name} differs from a fresh `kinsyn catalogue generate`"
        );
    }
}

/// The catalogue the binary reads ([`Catalogue::committed`], `catalogue/chains.json` compiled
/// in) is the one the code generates with the default reading, entry by entry, verification
/// results included; so the CLI's answers never drift from the code.
#[test]
fn embedded_catalogue_equals_the_generated_one() {
    let loaded = Catalogue::committed().expect("the compiled-in catalogue reads");
    let (fresh, comparison) = generated();
    assert_eq!(loaded.options, fresh.options);
    assert_eq!(loaded.verification, fresh.verification);
    assert_eq!(loaded.counts, fresh.counts);
    assert_eq!(loaded.entries.len(), fresh.entries.len());
    for (l, f) in loaded.entries.iter().zip(&fresh.entries) {
        assert_eq!(l, f, "entry {} of the committed catalogue", f.id);
    }
    // Its comparison with the Appendix, recomputed from the file's options, is the fresh one.
    let recompared = appendix::comparison(&loaded.options);
    assert_eq!(recompared.rows, comparison.rows);
    assert_eq!(recompared.differences, comparison.differences);
    // What the files are made of agrees too.
    assert_eq!(loaded.to_json(), COMMITTED_JSON);
    assert_eq!(loaded.readme(&recompared), fresh.readme(comparison));
}

/// A catalogue without the numerical check (another reading, §2's perpendicular guides), marked
/// against the Appendix, reads back as written: entries without verification, counts without verified numbers.
#[test]
fn an_unverified_catalogue_round_trips_through_json() {
    let options = Options {
        prismatics: PrismaticReading::Perpendicular,
        ..Options::default()
    };
    let (cat, comparison) = appendix::synthesise(&options);
    let back = Catalogue::from_json(&cat.to_json()).unwrap();
    assert_eq!(back.options, options);
    assert_eq!(back.entries, cat.entries);
    assert_eq!(back.counts, cat.counts);
    assert_eq!(
        appendix::comparison(&back.options).differences,
        comparison.differences
    );
    assert!(back.verification.is_none());
    assert!(back.entries.iter().all(|e| e.verification.is_none()));
}

#[test]
fn every_rejected_entry_is_documented() {
    let doc = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../docs/deviations.md"
    ))
    .unwrap();
    let begin = doc.find("<!-- not-3t3r:begin -->").expect("begin marker");
    let end = doc.find("<!-- not-3t3r:end -->").expect("end marker");
    let documented: Vec<&str> = doc[begin..end]
        .lines()
        .filter(|l| l.starts_with("| T"))
        .collect();
    let generated = generated().0.not_3t3r_markdown();
    let generated: Vec<&str> = generated.lines().filter(|l| l.starts_with("| T")).collect();
    assert_eq!(
        documented, generated,
        "docs/deviations.md is out of date: regenerate with `kinsyn catalogue rejected`"
    );
}
