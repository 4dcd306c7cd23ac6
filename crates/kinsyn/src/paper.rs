//! The printed Appendix of paper 000 and its row-by-row comparison with the enumeration.
//!
//! The plain-text copy lost the parallel marks, so the comparison is on letters. A row of
//! Tables 1–4 is compared as a whole (its variant sub-rows pooled: which sub-row is which
//! depended on the lost marks); Tables 7 and 8 index their rows by lost marks alone, so each is
//! compared as one pool. Every difference is classified with the evidence the code can give.

use crate::notation::letters_fit_word;
use crate::synthesis::{self, Candidate, Options, Table, rules};
use serde::Serialize;
use std::collections::{BTreeMap, BTreeSet};

/// The transcription of the Appendix (see the header of the file for its columns).
pub const APPENDIX_TSV: &str = include_str!("../../../data/paper000-appendix.tsv");

/// One printed line of the Appendix.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct PrintedRow {
    /// Table number.
    pub table: u8,
    /// Row number as printed.
    pub row: usize,
    /// The 'Kinematic chain' column as printed (misprints kept).
    pub printed_word: String,
    /// The permutation the row really holds.
    pub word: String,
    /// Variant sub-row (Tables 2–4), 1-based.
    pub variant: Option<usize>,
    /// The 'Possible chains' column, letters as printed.
    pub chains: Vec<String>,
}

/// The printed Appendix, line by line.
///
/// # Panics
/// Never on the embedded file; a test parses it.
#[must_use]
pub fn appendix() -> Vec<PrintedRow> {
    APPENDIX_TSV
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("table\t") && !l.trim().is_empty())
        .map(|l| {
            let f: Vec<&str> = l.split('\t').collect();
            PrintedRow {
                table: f[0].parse().expect("table number"),
                row: f[1].parse().expect("row number"),
                printed_word: f[2].to_string(),
                word: f[3].to_string(),
                variant: f[4].parse().ok(),
                chains: f[5]
                    .split(',')
                    .filter(|s| !s.is_empty())
                    .map(str::to_string)
                    .collect(),
            }
        })
        .collect()
}

/// Where a comparison pools its chains: a row of Tables 1–4, or a whole Table 7 or 8 (row 0).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
pub struct RowKey {
    /// Table number.
    pub table: u8,
    /// Row number, 0 for a pooled table.
    pub row: usize,
}

/// Tables whose rows are told apart by lost marks only, so they are compared as one pool.
fn pooled(table: u8) -> bool {
    table >= 5
}

fn key(table: u8, row: usize) -> RowKey {
    RowKey {
        table,
        row: if pooled(table) { 0 } else { row },
    }
}

/// What kind of difference between the printed Appendix and the enumeration.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
pub enum DifferenceKind {
    /// Printed, but its letters cannot be read from the row's word at all.
    Misprint,
    /// Printed, not generated in this row, generated for the same word in another table: the
    /// paper repeats a chain of another pattern (crossed out in the original, or misfiled).
    CarriedOver,
    /// Printed; readable from the word only with an axis assignment that a rule of §2 rejects.
    RuleViolation,
    /// Printed; readable only with revolute directions outside the table's parallel pattern.
    OutsidePattern,
    /// Printed; the letters fit the word but no axis assignment reads that way under rules 2–3.
    NotReadable,
    /// Generated, not printed in this row, printed in another row or table.
    PrintedElsewhere,
    /// Generated, printed nowhere in the Appendix.
    NotPrinted,
}

impl DifferenceKind {
    /// The name used in docs/deviations.md.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            DifferenceKind::Misprint => "misprint",
            DifferenceKind::CarriedOver => "carried-over",
            DifferenceKind::RuleViolation => "rule-violation",
            DifferenceKind::OutsidePattern => "outside-pattern",
            DifferenceKind::NotReadable => "not-readable",
            DifferenceKind::PrintedElsewhere => "omission-printed-elsewhere",
            DifferenceKind::NotPrinted => "omission-not-printed",
        }
    }

    /// Parses [`DifferenceKind::name`].
    #[must_use]
    pub fn from_name(s: &str) -> Option<Self> {
        [
            DifferenceKind::Misprint,
            DifferenceKind::CarriedOver,
            DifferenceKind::RuleViolation,
            DifferenceKind::OutsidePattern,
            DifferenceKind::NotReadable,
            DifferenceKind::PrintedElsewhere,
            DifferenceKind::NotPrinted,
        ]
        .into_iter()
        .find(|k| k.name() == s)
    }
}

/// One chain on which the printed row and the enumeration disagree.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Difference {
    /// Where.
    pub key: RowKey,
    /// The row's P/R word (`RRRRRR` for Tables 7, 8).
    pub word: String,
    /// The chain's letters.
    pub letters: String,
    /// The classification.
    pub kind: DifferenceKind,
    /// What the code established, in one line.
    pub evidence: String,
}

/// A row (or pooled table) compared.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct RowComparison {
    /// Where.
    pub key: RowKey,
    /// The row's word.
    pub word: String,
    /// Distinct letters generated for the row.
    pub generated: BTreeSet<String>,
    /// Distinct letters printed in the row.
    pub printed: BTreeSet<String>,
}

/// Compares the enumeration with the printed Appendix, row by row.
#[must_use]
pub fn compare(candidates: &[Candidate]) -> (Vec<RowComparison>, Vec<Difference>) {
    let printed_rows = appendix();
    let mut rows: BTreeMap<RowKey, RowComparison> = BTreeMap::new();
    for p in &printed_rows {
        let k = key(p.table, p.row);
        let entry = rows.entry(k).or_insert_with(|| RowComparison {
            key: k,
            word: p.word.clone(),
            generated: BTreeSet::new(),
            printed: BTreeSet::new(),
        });
        entry.printed.extend(p.chains.iter().cloned());
    }
    for c in candidates {
        let k = key(c.table, c.row);
        let entry = rows.entry(k).or_insert_with(|| RowComparison {
            key: k,
            word: c.word.clone(),
            generated: BTreeSet::new(),
            printed: BTreeSet::new(),
        });
        entry.generated.insert(c.chain.letters());
    }
    let mut printed_where: BTreeMap<&str, Vec<RowKey>> = BTreeMap::new();
    for r in rows.values() {
        for l in &r.printed {
            printed_where.entry(l.as_str()).or_default().push(r.key);
        }
    }
    let mut diffs = Vec::new();
    for r in rows.values() {
        for l in r.printed.difference(&r.generated) {
            let same_word: Vec<String> = rows
                .values()
                .filter(|o| o.key != r.key && o.word == r.word && o.generated.contains(l))
                .map(|o| describe_key(o.key))
                .collect();
            let (kind, evidence) = if !letters_fit_word(l, &r.word) || same_word.is_empty() {
                explain_missing(r.key.table, &r.word, l)
            } else {
                (
                    DifferenceKind::CarriedOver,
                    format!("generated for the same word in {}", same_word.join(", ")),
                )
            };
            diffs.push(Difference {
                key: r.key,
                word: r.word.clone(),
                letters: l.clone(),
                kind,
                evidence,
            });
        }
        for l in r.generated.difference(&r.printed) {
            let elsewhere = printed_where
                .get(l.as_str())
                .map(|v| {
                    v.iter()
                        .filter(|k| **k != r.key)
                        .copied()
                        .collect::<Vec<_>>()
                })
                .unwrap_or_default();
            let (kind, evidence) = if elsewhere.is_empty() {
                (
                    DifferenceKind::NotPrinted,
                    "the rules give it; no row of the Appendix prints it".to_string(),
                )
            } else {
                let places: Vec<String> = elsewhere.iter().map(|k| describe_key(*k)).collect();
                (
                    DifferenceKind::PrintedElsewhere,
                    format!("the rules give it here; printed in {}", places.join(", ")),
                )
            };
            diffs.push(Difference {
                key: r.key,
                word: r.word.clone(),
                letters: l.clone(),
                kind,
                evidence,
            });
        }
    }
    (rows.into_values().collect(), diffs)
}

/// "Table 2 row 5" or "Table 7".
#[must_use]
pub fn describe_key(k: RowKey) -> String {
    if k.row == 0 {
        format!("Table {}", k.table)
    } else {
        format!("Table {} row {}", k.table, k.row)
    }
}

/// One way a printed chain's letters can be read from its row's P/R word: the axes, the
/// admissibility rules they break, whether the revolute directions follow the table's pattern,
/// and whether the letters are rule 3's fewest joints for those axes.
struct Way {
    axes: Vec<rules::AxisIndex>,
    violations: Vec<rules::Violation>,
    in_pattern: bool,
    fewest: bool,
}

/// Every way `letters` can be read from `word` (any axis assignment whose readings, fewest
/// joints or any grouping, include those letters), one per distinct combination of broken
/// rules, pattern and fewest, in assignment order.
fn ways_to_read(word: &[crate::notation::Primitive], letters: &str, spec: &Table) -> Vec<Way> {
    let mut ways: Vec<Way> = Vec::new();
    for axes in synthesis::all_assignments(word) {
        let fewest = rules::readings(word, &axes)
            .iter()
            .any(|c| c.letters() == letters);
        if !fewest
            && !rules::readings_with(word, &axes, rules::Grouping::Any)
                .iter()
                .any(|c| c.letters() == letters)
        {
            continue;
        }
        let in_pattern = revolute_counts(word, &axes) == spec.axis_counts;
        let violations = rules::violations(word, &axes, &Options::default());
        if !ways
            .iter()
            .any(|w| w.violations == violations && w.in_pattern == in_pattern && w.fewest == fewest)
        {
            ways.push(Way {
                axes,
                violations,
                in_pattern,
                fewest,
            });
        }
    }
    ways
}

/// Why a printed chain is not generated from the row's word: the least-violating axis
/// assignment that reads as those letters, and what it breaks.
fn explain_missing(table: u8, word_text: &str, letters: &str) -> (DifferenceKind, String) {
    if !letters_fit_word(letters, word_text) {
        return (
            DifferenceKind::Misprint,
            format!(
                "{letters} cannot be read from the word {word_text} (P→P, R→R, C→PR/RP, U→RR, S→RRR)"
            ),
        );
    }
    let word = synthesis::parse_word(word_text).expect("appendix words are P/R words");
    let spec: &Table = synthesis::tables::table(table).expect("appendix tables exist");
    // The undominated ways are the evidence (a way is dominated when another breaks a subset
    // of its rules).
    let ways = ways_to_read(&word, letters, spec);
    if ways.is_empty() {
        return (
            DifferenceKind::NotReadable,
            format!(
                "no axis assignment of {word_text} reads as {letters} under rules 2–3 (parallel P–R pairs always merged into C)"
            ),
        );
    }
    let in_pattern: Vec<&Way> = ways.iter().filter(|w| w.in_pattern).collect();
    if in_pattern.is_empty() {
        let axes = &ways[0].axes;
        let counts = revolute_counts(&word, axes);
        let owner = synthesis::TABLES
            .iter()
            .filter(|t| t.axis_counts == counts && t.family == word_text_family(word_text))
            .map(|t| format!("Table {}'s", t.number))
            .next()
            .unwrap_or_else(|| "no table's".to_string());
        return (
            DifferenceKind::OutsidePattern,
            format!(
                "needs axes {}: revolutes per direction {:?}, {owner} pattern, not Table {table}'s {:?}",
                rules::axis_word(axes),
                counts,
                spec.axis_counts
            ),
        );
    }
    let dominated = |w: &Way| {
        in_pattern.iter().any(|o| {
            !std::ptr::eq(*o, w)
                && o.violations.iter().all(|v| w.violations.contains(v))
                && (o.fewest || !w.fewest)
                && (o.violations.len() < w.violations.len() || (o.fewest && !w.fewest))
        })
    };
    let alternatives: Vec<String> = in_pattern
        .iter()
        .filter(|w| !dominated(w))
        .map(|w| {
            let mut why: Vec<String> = w
                .violations
                .iter()
                .map(|x| x.describe().to_string())
                .collect();
            if !w.fewest {
                let usual: Vec<String> = rules::readings(&word, &w.axes)
                    .iter()
                    .map(super::notation::Chain::letters)
                    .collect();
                why.push(format!(
                    "more U/S/R joints than rule 3's fewest (the fewest reading is {})",
                    usual.join(" or ")
                ));
            }
            format!(
                "with axes {}: {}",
                rules::axis_word(&w.axes),
                why.join("; ")
            )
        })
        .collect();
    (
        DifferenceKind::RuleViolation,
        format!("only {}", alternatives.join("; or ")),
    )
}

/// How many revolutes lie along each direction, largest first.
fn revolute_counts(word: &[crate::notation::Primitive], axes: &[rules::AxisIndex]) -> [u8; 3] {
    let mut counts = [0u8; 3];
    for (i, p) in word.iter().enumerate() {
        if *p == crate::notation::Primitive::R {
            counts[axes[i] as usize] += 1;
        }
    }
    counts.sort_unstable_by(|a, b| b.cmp(a));
    counts
}

/// The family a word belongs to: its letters sorted P first.
fn word_text_family(word: &str) -> String {
    let p = word.chars().filter(|&c| c == 'P').count();
    format!("{}{}", "P".repeat(p), "R".repeat(word.len() - p))
}
