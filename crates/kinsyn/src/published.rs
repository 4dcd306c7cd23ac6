//! A published table of chains, given as data, and its row-by-row comparison with the
//! enumeration: what a paper prints beside what the rules of [`crate::synthesis`] give.
//!
//! A printed table ([`PrintedTables`]) is rows of the synthesis tables, each with the P/R word
//! it holds and the chains it prints, by letters (a copy that lost the parallel marks can be
//! compared only on letters). A row is compared as a whole (its variant sub-rows pooled); a
//! table whose rows the copy cannot tell apart is named *pooled* and compared as one pool.
//! Every difference is classified with the evidence the code can give ([`DifferenceKind`]).
//!
//! The data of a particular paper is not here: paper 000's Appendix, transcribed, is
//! `kinsyn_papers::appendix`, which builds its [`PrintedTables`] and hands them to the
//! catalogue ([`crate::catalogue::Catalogue::from_candidates`]) and to [`Comparison::new`].

use crate::notation::letters_fit_word;
use crate::synthesis::{self, Candidate, Options, Table, rules};
use serde::Serialize;
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;

/// One printed line of a published table.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct PrintedRow {
    /// Table number (one of [`synthesis::TABLES`]).
    pub table: u8,
    /// Row number as printed (1-based).
    pub row: usize,
    /// The 'Kinematic chain' column as printed (misprints kept).
    pub printed_word: String,
    /// The P/R permutation the row really holds.
    pub word: String,
    /// Variant sub-row, 1-based, where the table prints them.
    pub variant: Option<usize>,
    /// The 'Possible chains' column, letters as printed.
    pub chains: Vec<String>,
}

/// Why rows cannot be a [`PrintedTables`].
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum PrintedError {
    /// A row of a table the synthesis does not have.
    #[error("table {table} row {row}: no such table among the synthesis tables")]
    UnknownTable {
        /// The row's table.
        table: u8,
        /// The row.
        row: usize,
    },
    /// A row numbered 0 (rows are 1-based; 0 stands for a pooled table).
    #[error("table {table}: row 0 (rows are numbered from 1)")]
    RowZero {
        /// The row's table.
        table: u8,
    },
    /// A row whose word is not made of P and R.
    #[error("table {table} row {row}: the word {word:?} is not a P/R word")]
    NotAWord {
        /// The row's table.
        table: u8,
        /// The row.
        row: usize,
        /// The word.
        word: String,
    },
}

/// A published table of chains as data: its printed rows, and the tables whose rows are told
/// apart by marks the copy lost, so that each is compared as one pool.
///
/// Every row belongs to a synthesis table and holds a P/R word ([`PrintedTables::new`] checks
/// it). The default is the empty table, "the printed table": nothing printed.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PrintedTables {
    name: String,
    rows: Vec<PrintedRow>,
    pooled: BTreeSet<u8>,
}

impl Default for PrintedTables {
    fn default() -> Self {
        PrintedTables {
            name: "the printed table".to_string(),
            rows: Vec::new(),
            pooled: BTreeSet::new(),
        }
    }
}

impl PrintedTables {
    /// The printed rows, with the tables compared as one pool each; `name` is how the
    /// evidence of a difference names the whole (`the Appendix`: "no row of the Appendix
    /// prints it").
    ///
    /// # Errors
    /// A row of a table that [`synthesis::TABLES`] does not have, a row numbered 0, or a word
    /// that is not made of P and R.
    pub fn new(
        name: &str,
        rows: Vec<PrintedRow>,
        pooled: impl IntoIterator<Item = u8>,
    ) -> Result<Self, PrintedError> {
        for r in &rows {
            if r.row == 0 {
                return Err(PrintedError::RowZero { table: r.table });
            }
            if synthesis::tables::table(r.table).is_none() {
                return Err(PrintedError::UnknownTable {
                    table: r.table,
                    row: r.row,
                });
            }
            if synthesis::parse_word(&r.word).is_none() {
                return Err(PrintedError::NotAWord {
                    table: r.table,
                    row: r.row,
                    word: r.word.clone(),
                });
            }
        }
        Ok(PrintedTables {
            name: name.to_string(),
            rows,
            pooled: pooled.into_iter().collect(),
        })
    }

    /// How the evidence names the whole table.
    #[must_use]
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The printed rows, in the order given.
    #[must_use]
    pub fn rows(&self) -> &[PrintedRow] {
        &self.rows
    }

    /// Whether the rows of `table` are compared as one pool.
    #[must_use]
    pub fn is_pooled(&self, table: u8) -> bool {
        self.pooled.contains(&table)
    }

    /// Where a chain of `table`, `row` is compared: its row, or its whole table if pooled.
    #[must_use]
    pub fn key(&self, table: u8, row: usize) -> RowKey {
        RowKey {
            table,
            row: if self.is_pooled(table) { 0 } else { row },
        }
    }

    /// Whether `letters` are printed in `table`, `row` (anywhere in the table if pooled).
    #[must_use]
    pub fn printed_in(&self, table: u8, row: usize, letters: &str) -> bool {
        self.rows.iter().any(|p| {
            p.table == table
                && (p.row == row || self.is_pooled(table))
                && p.chains.iter().any(|l| l == letters)
        })
    }

    /// Whether `letters` are printed anywhere.
    #[must_use]
    pub fn printed_anywhere(&self, letters: &str) -> bool {
        self.rows
            .iter()
            .any(|p| p.chains.iter().any(|l| l == letters))
    }
}

/// Where a comparison pools its chains: a row, or a whole pooled table (row 0).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
pub struct RowKey {
    /// Table number.
    pub table: u8,
    /// Row number, 0 for a pooled table.
    pub row: usize,
}

/// What kind of difference between a printed table and the enumeration.
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
    /// Generated, printed nowhere in the table.
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
    /// The row's P/R word.
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

/// The row-by-row comparison of the enumeration with a printed table.
#[derive(Debug, Clone, PartialEq, Eq, Default, Serialize)]
pub struct Comparison {
    /// Every row (or pooled table) printed or generated, in key order.
    pub rows: Vec<RowComparison>,
    /// Every difference between them.
    pub differences: Vec<Difference>,
}

impl Comparison {
    /// Compares the enumeration with the printed table, row by row.
    ///
    /// # Panics
    /// Never: [`PrintedTables::new`] checked the printed rows' tables and words, and the
    /// enumeration gives only the synthesis tables' rows.
    #[must_use]
    pub fn new(printed: &PrintedTables, candidates: &[Candidate]) -> Self {
        let mut rows: BTreeMap<RowKey, RowComparison> = BTreeMap::new();
        for p in printed.rows() {
            row(&mut rows, printed.key(p.table, p.row), &p.word)
                .printed
                .extend(p.chains.iter().cloned());
        }
        for c in candidates {
            row(&mut rows, printed.key(c.table, c.row), &c.word)
                .generated
                .insert(c.chain.letters());
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
                        format!("the rules give it; no row of {} prints it", printed.name()),
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
        Comparison {
            rows: rows.into_values().collect(),
            differences: diffs,
        }
    }

    /// How many differences of each kind each table has.
    #[must_use]
    pub fn counts(&self) -> BTreeMap<(u8, DifferenceKind), usize> {
        let mut m = BTreeMap::new();
        for d in &self.differences {
            *m.entry((d.key.table, d.kind)).or_insert(0) += 1;
        }
        m
    }

    /// The differences as a Markdown table, one line per difference (the table kept in
    /// docs/deviations.md for paper 000's Appendix).
    #[must_use]
    pub fn markdown(&self) -> String {
        let mut s = String::from(
            "| table | row | word | chain | kind | evidence |\n|---|---|---|---|---|---|\n",
        );
        for d in &self.differences {
            let row = if d.key.row == 0 {
                "all".to_string()
            } else {
                d.key.row.to_string()
            };
            let _ = writeln!(
                s,
                "| {} | {row} | {} | {} | {} | {} |",
                d.key.table,
                d.word,
                d.letters,
                d.kind.name(),
                d.evidence
            );
        }
        s
    }
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
    let word = synthesis::parse_word(word_text).expect("printed words are P/R words (checked)");
    let spec: &Table = synthesis::tables::table(table).expect("printed tables exist (checked)");
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
                    .map(crate::notation::Chain::letters)
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

/// The comparison of row `key` in `rows`, created empty with the row's `word` the first time
/// the row is met (by a printed row or a generated chain).
fn row<'a>(
    rows: &'a mut BTreeMap<RowKey, RowComparison>,
    key: RowKey,
    word: &str,
) -> &'a mut RowComparison {
    rows.entry(key).or_insert_with(|| RowComparison {
        key,
        word: word.to_string(),
        generated: BTreeSet::new(),
        printed: BTreeSet::new(),
    })
}
