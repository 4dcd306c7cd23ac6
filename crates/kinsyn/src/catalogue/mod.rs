//! The catalogue of 6-dof leg chains: candidates deduplicated, counted per table, marked as
//! printed or not in a published table ([`crate::published`]), and written as
//! `catalogue/chains.json`, `chains.csv` and `README.md`.
//!
//! Identity is "letters + parallel marks" (the canonical [`Chain`] text): two chains with the
//! same letters but different parallel groups move differently (§2.2: UU and UU). The first
//! occurrence in table order wins and keeps its provenance. "Letters only" counts are reported
//! beside it because they are what a plain-text printed table can be checked against.
//!
//! The module's files follow its jobs: this one holds the model (entries, counts, the
//! catalogue and its reading of the committed file); `build.rs` deduplicates the enumerated
//! candidates into entries and counts; `query.rs` searches the verified entries for a motion
//! pattern; `formats.rs` writes and reads `chains.json`, and writes `chains.csv` and the
//! Markdown tables of `README.md` and `docs/deviations.md`.
//!
//! The printed table the entries are marked against is an input ([`PrintedTables`]): paper
//! 000's Appendix is `kinsyn_papers::appendix`, which this crate never imports. The row-by-row
//! comparison with it ([`crate::published::Comparison`]) is a value of its own, not part of the catalogue or its
//! files: `README.md`'s table of differences takes it as an argument.

mod build;
mod formats;
mod query;

pub use query::QueryHit;

use crate::chain::{ChainError, SerialChain};
use crate::notation::{Axis, AxisWord, Chain, JointKind, Primitive};
use crate::published::PrintedTables;
use crate::synthesis::{self, Options};
use crate::verification::{self, RankCheck, Settings, Verification};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

/// How many joints of each letter a chain has.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub struct Composition {
    /// Prismatic joints.
    pub p: u8,
    /// Revolute joints.
    pub r: u8,
    /// Cylindrical joints.
    pub c: u8,
    /// Universal joints.
    pub u: u8,
    /// Spherical joints.
    pub s: u8,
}

impl Composition {
    /// Counts the letters of a chain.
    #[must_use]
    pub fn of(chain: &Chain) -> Self {
        let mut c = Composition::default();
        for j in chain.joints() {
            match j.kind {
                JointKind::P => c.p += 1,
                JointKind::R => c.r += 1,
                JointKind::C => c.c += 1,
                JointKind::U => c.u += 1,
                JointKind::S => c.s += 1,
            }
        }
        c
    }
}

/// Where an entry was first found.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Provenance {
    /// Appendix table.
    pub table: u8,
    /// Row of the table (the paper's numbering).
    pub row: usize,
    /// Variant sub-row within the row.
    pub variant: usize,
    /// The variant with its parallel marks, e.g. `PPRaRaRR`.
    pub variant_label: String,
}

/// One reading of an entry's notation: an axis assignment of a row's word that the rules of §2
/// admit and read as the entry's letters and parallel marks ([`crate::synthesis::Candidate`]).
///
/// The notation does not fix the directions: `RCRPP` in Table 1 row 16 (word RPRRPP) is read
/// from four assignments (the guides P5, P6 along x and y, x and z, y and x, or y and z once R1,
/// the C and R4 lie along x, y, z), and a C is the same joint whether its word holds PR or RP,
/// so other rows can read the same notation too. Deduplication keeps one entry per notation;
/// its readings are every such assignment, in enumeration order (the entry's own row first).
/// The numerical check runs on each, and the entry takes the first that is 3T3R
/// ([`Catalogue::verify`]).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Reading {
    /// Appendix table of the row the reading comes from.
    pub table: u8,
    /// Row of that table (the paper's numbering).
    pub row: usize,
    /// Variant sub-row within the row.
    pub variant: usize,
    /// The row's P/R word.
    pub word: String,
    /// Axis direction of each primitive joint at the reference configuration.
    pub axes: AxisWord,
    /// Parallel groups as 1-based positions in `word`.
    pub parallel_groups: Vec<Vec<usize>>,
    /// The rank check of this reading's chain ([`verification::rank_check`]), once
    /// [`Catalogue::verify`] ran.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub check: Option<ReadingCheck>,
}

/// What the rank check found for one reading, in short: the full singular values are those of
/// the entry's `verification` for the reading kept.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ReadingCheck {
    /// Generic rank of the chain Jacobian (the largest over the samples).
    pub rank: usize,
    /// The smallest kept singular value over the largest, at the worst sample (σ6/σ1 for rank
    /// 6, σ5/σ1 for rank 5).
    pub gap: f64,
    /// The largest dropped singular value over the largest, over all samples (0: round-off).
    pub dropped: f64,
    /// Rank 6 at every sample and no idle joint.
    pub is_3t3r: bool,
}

impl From<&RankCheck> for ReadingCheck {
    fn from(c: &RankCheck) -> Self {
        ReadingCheck {
            rank: c.rank,
            gap: c.gap,
            dropped: c.dropped,
            is_3t3r: c.is_3t3r,
        }
    }
}

impl Reading {
    /// The reading of a candidate (its word, axes, groups and provenance).
    #[must_use]
    pub fn of(c: &synthesis::Candidate) -> Self {
        Reading {
            table: c.table,
            row: c.row,
            variant: c.variant,
            word: c.word.clone(),
            axes: c.axes.clone(),
            parallel_groups: c.parallel_groups.clone(),
            check: None,
        }
    }

    /// Whether the rank check found this reading 3T3R.
    #[must_use]
    pub fn is_3t3r(&self) -> bool {
        self.check.as_ref().is_some_and(|c| c.is_3t3r)
    }
}

/// The seed of the catalogue's numerical verification (geometry and configurations); each
/// entry derives its own from it and its notation ([`Entry::seed`]).
pub const VERIFICATION_SEED: u64 = 2026;

/// The version of `chains.json` that [`Catalogue::to_json`] writes and [`Catalogue::from_json`]
/// reads (the file's `format` field). Raise it when the file's shape or meaning changes, so
/// that a binary never reads a file it would misunderstand.
pub const FORMAT: &str = "kinsyn-catalogue/3";

/// The committed `catalogue/chains.json`, compiled in.
///
/// The committed catalogue is part of the source: it is what [`Catalogue::generate`] gives with
/// the default reading and paper 000's Appendix (`kinsyn_papers::appendix::generate`; the
/// papers' `tests/suite/appendix.rs` checks it entry by entry, and byte for byte against a
/// fresh `kinsyn catalogue generate`). Compiling it in lets the binary read it from any
/// working directory, installed or not, with no path to find and no file that can go missing
/// or be swapped for another version after the build; its cost is 1.3 MB of read-only data.
pub const COMMITTED_JSON: &str = include_str!("../../../../catalogue/chains.json");

/// Why a catalogue file cannot be read ([`Catalogue::from_json`]).
#[derive(Debug, thiserror::Error)]
pub enum LoadError {
    /// The text is not a catalogue of this format: not JSON, or a field missing or of the wrong
    /// type (the path names it, e.g. `entries[3].verification.rank`). Regenerate the file with
    /// `kinsyn catalogue generate`.
    #[error("not a {FORMAT} catalogue: {0}")]
    Parse(#[from] serde_path_to_error::Error<serde_json::Error>),
    /// The file says it is another version of the format (written by another kinsyn).
    /// Regenerate it with this kinsyn's `kinsyn catalogue generate`.
    #[error("catalogue format {found:?}, this kinsyn reads {FORMAT:?}")]
    Format {
        /// The file's `format` field.
        found: String,
    },
}

/// One chain of the catalogue.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Entry {
    /// Stable identifier: table and running number, e.g. `T2-017`.
    pub id: String,
    /// Canonical notation, letters and parallel marks (see docs/notation.md).
    pub notation: String,
    /// Letters only.
    pub letters: String,
    /// The family word (PPPRRR, PPRRRR, PRRRRR or RRRRRR).
    pub family: String,
    /// The P/R permutation it is read from.
    pub word: String,
    /// Axis direction of each primitive joint at the reference configuration (`xyzxyz`).
    pub axes: AxisWord,
    /// Parallel groups as 1-based positions in `word` (and `axes`).
    pub parallel_groups: Vec<Vec<usize>>,
    /// Joint letter counts.
    pub composition: Composition,
    /// Where it was first generated.
    pub provenance: Provenance,
    /// Whether it is the first entry with its letters (the "letters only" identity).
    pub first_with_letters: bool,
    /// Whether its letters are printed in the row it comes from.
    pub printed_in_row: bool,
    /// Whether its letters are printed anywhere in the Appendix.
    pub printed_in_appendix: bool,
    /// Which of `readings` (1-based) the entry's `word`, `axes`, `parallel_groups` and
    /// `verification` are of: the first reading that is 3T3R, or the first reading (the one
    /// `provenance` names) when none is.
    pub reading: usize,
    /// Every reading of the notation the rules admit, in enumeration order, each with its rank
    /// check once [`Catalogue::verify`] ran.
    pub readings: Vec<Reading>,
    /// The numerical check (rank, idle joints, lock patterns), once [`Catalogue::verify`] ran.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub verification: Option<Verification>,
}

impl Entry {
    /// The chain's primitive joints, axis directions and joint blocks (primitives per letter),
    /// in the order of `word`.
    #[must_use]
    pub fn layout(&self) -> (Vec<Primitive>, Vec<Axis>, Vec<usize>) {
        let word = synthesis::parse_word(&self.word).unwrap_or_default();
        let axes = self.axes.axes().collect();
        let blocks = self
            .notation
            .parse::<Chain>()
            .map(|c| {
                c.joints()
                    .iter()
                    .map(|j| j.kind.primitives().len())
                    .collect()
            })
            .unwrap_or_default();
        (word, axes, blocks)
    }

    /// The entry's own seed: the catalogue seed mixed with a hash (FNV-1a) of its notation, so
    /// that an entry's geometry does not depend on which other entries exist.
    #[must_use]
    pub fn seed(&self, base: u64) -> u64 {
        let mut h: u64 = 0xcbf2_9ce4_8422_2325;
        for b in self.notation.bytes() {
            h ^= u64::from(b);
            h = h.wrapping_mul(0x0100_0000_01b3);
        }
        base ^ h
    }

    /// The seed of the configurations sampled for this entry's verification.
    #[must_use]
    pub fn sample_seed(&self, base: u64) -> u64 {
        self.seed(base).wrapping_add(1)
    }

    /// A concrete chain with the entry's layout and seeded generic offsets
    /// ([`SerialChain::from_layout`]).
    ///
    /// # Errors
    /// If the entry's word, axes and notation disagree (a corrupted entry).
    pub fn serial_chain(&self, base_seed: u64) -> Result<SerialChain, ChainError> {
        let (word, axes, blocks) = self.layout();
        let mut rng = ChaCha8Rng::seed_from_u64(self.seed(base_seed));
        SerialChain::from_layout(&word, &axes, &blocks, &mut rng)
    }

    /// The concrete chain of one of the entry's readings: its word and axes, the entry's joint
    /// blocks, and the same seeded offsets as [`Entry::serial_chain`] (the seed depends on the
    /// notation only), so that readings differ in their directions alone.
    ///
    /// # Errors
    /// If the reading's word and axes do not fit the entry's notation (a corrupted entry).
    pub fn reading_chain(
        &self,
        reading: &Reading,
        base_seed: u64,
    ) -> Result<SerialChain, ChainError> {
        let (_, _, blocks) = self.layout();
        let word = synthesis::parse_word(&reading.word).unwrap_or_default();
        let axes: Vec<Axis> = reading.axes.axes().collect();
        let mut rng = ChaCha8Rng::seed_from_u64(self.seed(base_seed));
        SerialChain::from_layout(&word, &axes, &blocks, &mut rng)
    }

    /// Makes reading `k` (0-based) the entry's: its word, axes and parallel groups.
    fn adopt_reading(&mut self, k: usize) {
        if let Some(r) = self.readings.get(k) {
            self.word.clone_from(&r.word);
            self.axes = r.axes.clone();
            self.parallel_groups.clone_from(&r.parallel_groups);
            self.reading = k + 1;
        }
    }

    /// Which reading the entry keeps and why, in words (empty before verification): "reading 2
    /// of 4 (Table 1 row 16, axes xyyzxz), the first 3T3R one: reading 1 (xyyzxy) has rank 5".
    #[must_use]
    pub fn reading_note(&self) -> String {
        let Some(kept) = self.readings.get(self.reading.saturating_sub(1)) else {
            return String::new();
        };
        if kept.check.is_none() {
            return String::new();
        }
        let n = self.readings.len();
        let at = |r: &Reading| format!("Table {} row {}, axes {}", r.table, r.row, r.axes);
        let rank = |r: &Reading| {
            r.check.as_ref().map_or_else(String::new, |c| {
                if c.is_3t3r {
                    "3T3R".to_string()
                } else if c.rank < 6 {
                    format!("rank {}", c.rank)
                } else {
                    "an idle joint".to_string()
                }
            })
        };
        if !kept.is_3t3r() {
            return format!(
                "none of the {n} reading{} is 3T3R ({})",
                if n == 1 { "" } else { "s" },
                self.readings
                    .iter()
                    .map(|r| format!("{}: {}", r.axes, rank(r)))
                    .collect::<Vec<_>>()
                    .join("; ")
            );
        }
        if self.reading == 1 {
            return format!("reading 1 of {n} ({}), 3T3R", at(kept));
        }
        format!(
            "reading {} of {n} ({}), the first 3T3R one: {}",
            self.reading,
            at(kept),
            self.readings[..self.reading - 1]
                .iter()
                .enumerate()
                .map(|(k, r)| format!("reading {} ({}) has {}", k + 1, r.axes, rank(r)))
                .collect::<Vec<_>>()
                .join(", ")
        )
    }
}

/// The counts of one table, each "new": not already found in an earlier table.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct TableCount {
    /// Table number.
    pub table: u8,
    /// Family word.
    pub family: String,
    /// The paper's count (none for Tables 7 and 8, which the paper counts together).
    pub published: Option<usize>,
    /// Candidates generated (readings, repeats included).
    pub candidates: usize,
    /// New distinct chains by letters only.
    pub letters_only: usize,
    /// New distinct chains by letters and parallel marks.
    pub with_marks: usize,
    /// New distinct letters printed in the table's rows (misprints included).
    pub printed_letters: usize,
    /// Of the new entries (letters + marks), how many the numerical check finds 3T3R.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub verified_3t3r: Option<usize>,
}

/// The whole catalogue.
#[derive(Debug, Clone, Serialize)]
pub struct Catalogue {
    /// The options of the paper reading used.
    pub options: Options,
    /// The entries, in table order.
    pub entries: Vec<Entry>,
    /// Per-table counts.
    pub counts: Vec<TableCount>,
    /// The settings and seed of the numerical check, once it ran.
    #[serde(skip)]
    pub verification: Option<(Settings, u64)>,
}

impl Catalogue {
    /// Enumerates, deduplicates, marks what `printed` prints and verifies every entry
    /// numerically (default settings, [`VERIFICATION_SEED`]). With paper 000's Appendix and
    /// the default options this is the committed catalogue (`kinsyn_papers::appendix::generate`).
    #[must_use]
    pub fn generate(options: &Options, printed: &PrintedTables) -> Self {
        let mut cat = Self::synthesise(options, printed);
        cat.verify(&Settings::default(), VERIFICATION_SEED);
        cat
    }

    /// Enumerates, deduplicates and marks what `printed` prints, without the numerical check.
    #[must_use]
    pub fn synthesise(options: &Options, printed: &PrintedTables) -> Self {
        let candidates = synthesis::enumerate(options);
        Self::from_candidates(*options, &candidates, printed)
    }

    /// The committed catalogue ([`COMMITTED_JSON`]): the entries, counts and verification
    /// results of `catalogue/chains.json`, without re-running the numerical check.
    ///
    /// # Errors
    /// If the compiled-in file does not parse or has another [`FORMAT`] (a build from a broken
    /// tree: the test `embedded_catalogue_equals_the_generated_one` guards against it).
    ///
    /// # Example
    /// Table 1 of paper 000's Appendix prints 63 PPPRRR chains, which the catalogue reproduces
    /// exactly; and PPPS (`T1-001`) translates (T3) with its spherical joint's three revolutes
    /// (joints 4, 5, 6) locked, since what is left is three prismatic joints.
    ///
    /// ```
    /// use kinsyn::catalogue::Catalogue;
    ///
    /// let catalogue = Catalogue::committed()?;
    /// let table_1 = catalogue.entries.iter().filter(|e| e.provenance.table == 1);
    /// assert_eq!(table_1.count(), 63);
    ///
    /// let hits = catalogue.query(&"T3".parse()?, 3, None);
    /// let ppps = hits.iter().find(|h| h.entry.notation == "PPPS").unwrap();
    /// assert_eq!(ppps.lock_sets, ["456"]);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn committed() -> Result<Self, LoadError> {
        Self::from_json(COMMITTED_JSON)
    }

    /// Verifies every entry numerically (in parallel): rank, idle joints and the patterns of
    /// all lock subsets ([`verification::verify`]), and counts the 3T3R entries per table.
    ///
    /// Every reading of an entry is rank-checked first ([`verification::rank_check`], same
    /// geometry seed, same sample seed): the entry keeps the first reading that is 3T3R, in
    /// enumeration order, or its first reading when none is, and the full verification (lock
    /// patterns) runs on the reading kept. A chain is rejected only when no reading of its
    /// notation is 3T3R.
    pub fn verify(&mut self, settings: &Settings, seed: u64) {
        self.entries.par_iter_mut().for_each(|e| {
            let sample_seed = e.sample_seed(seed);
            let checks: Vec<Option<ReadingCheck>> = e
                .readings
                .iter()
                .map(|r| {
                    e.reading_chain(r, seed).ok().map(|chain| {
                        ReadingCheck::from(&verification::rank_check(&chain, settings, sample_seed))
                    })
                })
                .collect();
            for (r, check) in e.readings.iter_mut().zip(checks) {
                r.check = check;
            }
            let kept = e.readings.iter().position(Reading::is_3t3r).unwrap_or(0);
            e.adopt_reading(kept);
            e.verification = e
                .serial_chain(seed)
                .ok()
                .map(|chain| verification::verify(&chain, settings, sample_seed));
        });
        for count in &mut self.counts {
            count.verified_3t3r = Some(
                self.entries
                    .iter()
                    .filter(|e| {
                        e.provenance.table == count.table
                            && e.verification.as_ref().is_some_and(|v| v.is_3t3r)
                    })
                    .count(),
            );
        }
        self.verification = Some((*settings, seed));
    }

    /// The entries the numerical check confirms as 3T3R with no idle joint: the verified
    /// catalogue that queries run on.
    pub fn verified(&self) -> impl Iterator<Item = &Entry> {
        self.entries
            .iter()
            .filter(|e| e.verification.as_ref().is_some_and(|v| v.is_3t3r))
    }

    /// Finds an entry by id (case-insensitive) or by notation (parsed, so any spelling of the
    /// same marks matches).
    #[must_use]
    pub fn find(&self, query: &str) -> Option<&Entry> {
        if let Some(e) = self
            .entries
            .iter()
            .find(|e| e.id.eq_ignore_ascii_case(query.trim()))
        {
            return Some(e);
        }
        let chain: Chain = query.parse().ok()?;
        let text = chain.without_actuation().to_string();
        self.entries.iter().find(|e| e.notation == text)
    }

    /// The entries of one family.
    pub fn family<'a>(&'a self, family: &'a str) -> impl Iterator<Item = &'a Entry> + 'a {
        self.entries.iter().filter(move |e| e.family == family)
    }

    /// Totals: (letters only, letters + marks).
    #[must_use]
    pub fn totals(&self) -> (usize, usize) {
        (
            self.counts.iter().map(|c| c.letters_only).sum(),
            self.counts.iter().map(|c| c.with_marks).sum(),
        )
    }
}
