//! Structural synthesis of 6-dof P/R chains (paper 000 §2 and its Appendix).
//!
//! For each Appendix table, in the paper's row order: every P/R word of the family, every
//! assignment of axis directions the rules allow (the revolutes' directions follow the table's
//! parallel-axis pattern, [`rules::revolute_patterns`]; the guides take any direction the rules
//! in [`rules::violations`] admit), and every C/U/S reading of it ([`rules::readings`]). Each
//! reading is a [`Candidate`] with its provenance. [`crate::catalogue`] deduplicates them.
//!
//! ```
//! use kinsyn::synthesis::{enumerate, Options};
//! let candidates = enumerate(&Options::default());
//! let table1: std::collections::BTreeSet<String> =
//!     candidates.iter().filter(|c| c.table == 1).map(|c| c.chain.letters()).collect();
//! assert_eq!(table1.len(), 63); // paper 000 §2.1: "the possible 63 chains"
//! ```

pub mod rules;
pub mod tables;

pub use rules::{AxisIndex, Options, PrismaticReading, Violation};
pub use tables::{TABLES, Table};

use crate::notation::{AxisWord, Chain, Joint, JointKind, Mark, Primitive};
use itertools::Itertools;

/// One C/U/S reading of one admissible axis assignment, with where it comes from.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Candidate {
    /// Appendix table number.
    pub table: u8,
    /// The paper's row number within the table (1-based).
    pub row: usize,
    /// The P/R word of the row.
    pub word: String,
    /// Variant number within the row (1-based): which revolutes stay parallel.
    pub variant: usize,
    /// The variant as the paper's 'Variants' column would print it, marks kept (e.g. `PPRaRaRR`).
    pub variant_label: String,
    /// Axis direction of each primitive joint at the reference configuration, canonical (the
    /// first joint along x, the next new direction y), e.g. `xyyxzz`.
    pub axes: AxisWord,
    /// The parallel groups, as 1-based positions in `word`.
    pub parallel_groups: Vec<Vec<usize>>,
    /// The chain in C/U/S letters with its parallel groups.
    pub chain: Chain,
}

/// Parses a P/R word into primitives; `None` if it holds another letter.
#[must_use]
pub fn parse_word(word: &str) -> Option<Vec<Primitive>> {
    word.chars()
        .map(|c| match c {
            'P' => Some(Primitive::P),
            'R' => Some(Primitive::R),
            _ => None,
        })
        .collect()
}

/// The word with each revolute marked by its parallel group, e.g. `PPRaRaRR`.
#[must_use]
#[expect(
    clippy::cast_possible_truncation,
    reason = "a parallel group holds at least two of the word's revolutes, so a six-joint word \
              of the tables has at most three (the notation's a, b, c)"
)]
pub fn variant_label(word: &[Primitive], groups: &[Vec<usize>]) -> String {
    let joints = word
        .iter()
        .enumerate()
        .map(|(i, &p)| {
            let kind = if p == Primitive::P {
                JointKind::P
            } else {
                JointKind::R
            };
            Joint {
                kind,
                marks: vec![Mark {
                    group: groups.iter().position(|g| g.contains(&i)).map(|g| g as u8),
                    actuated: false,
                }],
            }
        })
        .collect();
    Chain::from_joints(joints).to_string()
}

/// One variant of a row: the parallel groups its revolute patterns keep (0-based positions in
/// the word) and those patterns.
struct Variant {
    groups: Vec<Vec<usize>>,
    patterns: Vec<Vec<AxisIndex>>,
}

/// The variants of a row: revolute direction patterns grouped by the parallel groups they
/// keep, ordered as the Appendix orders its sub-rows (most revolutes in groups first, then by
/// the position of the groups; "no group kept" last).
fn variants(word: &[Primitive], table: &Table) -> Vec<Variant> {
    let revolutes: Vec<usize> = (0..word.len())
        .filter(|&i| word[i] == Primitive::R)
        .collect();
    let mut found: Vec<Variant> = Vec::new();
    for pattern in rules::revolute_patterns(revolutes.len(), table.axis_counts) {
        let mut axes = vec![0; word.len()];
        for (k, &i) in revolutes.iter().enumerate() {
            axes[i] = pattern[k];
        }
        let groups = rules::parallel_groups(word, &axes);
        match found.iter_mut().find(|v| v.groups == groups) {
            Some(v) => v.patterns.push(pattern),
            None => found.push(Variant {
                groups,
                patterns: vec![pattern],
            }),
        }
    }
    found.sort_by_key(|v| {
        (
            std::cmp::Reverse(v.groups.iter().map(Vec::len).sum::<usize>()),
            v.groups.is_empty(),
            v.groups.clone(),
        )
    });
    found
}

/// Every admissible axis assignment of a row's word in one variant: the revolutes follow the
/// pattern, the guides take every direction, in lexicographic order.
fn assignments<'a>(
    word: &'a [Primitive],
    patterns: &'a [Vec<AxisIndex>],
    options: &'a Options,
) -> impl Iterator<Item = Vec<AxisIndex>> + 'a {
    let prismatics: Vec<usize> = (0..word.len())
        .filter(|&i| word[i] == Primitive::P)
        .collect();
    let revolutes: Vec<usize> = (0..word.len())
        .filter(|&i| word[i] == Primitive::R)
        .collect();
    patterns.iter().flat_map(move |pattern| {
        let (prismatics, revolutes) = (prismatics.clone(), revolutes.clone());
        std::iter::repeat_n(0..3u8, prismatics.len())
            .multi_cartesian_product()
            .filter_map(move |guides| {
                let mut axes = vec![0; word.len()];
                for (k, &i) in revolutes.iter().enumerate() {
                    axes[i] = pattern[k];
                }
                for (k, &i) in prismatics.iter().enumerate() {
                    axes[i] = guides[k];
                }
                rules::violations(word, &axes, options)
                    .is_empty()
                    .then_some(axes)
            })
    })
}

/// All candidates of all Appendix tables, in table, row, variant and assignment order.
///
/// # Complexity
/// Exponential in the length of the words: for each P/R word of a table, every pattern of
/// revolute directions the table allows ([`rules::revolute_patterns`], a multinomial count in
/// the r revolutes) is combined with every assignment of the 3 directions to the p prismatic
/// joints (3^p), each combination is checked against the rules of §2
/// ([`rules::violations`]), and each admissible one is read in C/U/S letters
/// ([`rules::readings`]). The tables are fixed (six-joint words, at most three P), so the
/// whole enumeration takes about 3–6 ms (`cargo bench -p kinsyn-bench --bench synthesis`).
///
/// # Panics
/// Never: every word of the built-in Appendix tables is a P/R word.
#[must_use]
pub fn enumerate(options: &Options) -> Vec<Candidate> {
    let mut out = Vec::new();
    for table in &TABLES {
        for (r, word_text) in table.words.iter().enumerate() {
            let word = parse_word(word_text).expect("table words are P/R words");
            for (v, variant) in variants(&word, table).iter().enumerate() {
                let label = variant_label(&word, &variant.groups);
                for axes in assignments(&word, &variant.patterns, options) {
                    for chain in rules::readings(&word, &axes) {
                        out.push(Candidate {
                            table: table.number,
                            row: r + 1,
                            word: (*word_text).to_string(),
                            variant: v + 1,
                            variant_label: label.clone(),
                            axes: rules::axis_word(&rules::canonical_axes(&axes)),
                            parallel_groups: rules::parallel_groups(&word, &axes)
                                .iter()
                                .map(|g| g.iter().map(|i| i + 1).collect())
                                .collect(),
                            chain,
                        });
                    }
                }
            }
        }
    }
    out
}

/// Every axis assignment of a word, whatever the table's pattern, written canonically (the
/// first joint along x, the next new direction y). Used to explain why a printed chain is not
/// generated.
#[must_use]
pub fn all_assignments(word: &[Primitive]) -> Vec<Vec<AxisIndex>> {
    std::iter::repeat_n(0..3u8, word.len())
        .multi_cartesian_product()
        .filter(|axes| rules::canonical_axes(axes) == *axes)
        .collect()
}
