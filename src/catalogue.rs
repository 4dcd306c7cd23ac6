//! The catalogue of 6-dof leg chains: candidates deduplicated, counted per table, compared with
//! the paper, and written as `catalogue/chains.json`, `chains.csv` and `README.md`.
//!
//! Identity is "letters + parallel marks" (the canonical [`Chain`] text): two chains with the
//! same letters but different parallel groups move differently (§2.2: UU and UU). The first
//! occurrence in table order wins and keeps its provenance. "Letters only" counts are reported
//! beside it because they are what the plain-text Appendix can be checked against.

use crate::chain::{ChainError, SerialChain};
use crate::motion::PatternQuery;
use crate::notation::{Axis, AxisWord, Chain, JointKind, Primitive};
use crate::paper::{self, Difference, DifferenceKind, RowComparison};
use crate::synthesis::{self, Candidate, Options, TABLES, tables};
use crate::verification::{self, Settings, Verification};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;
use std::path::Path;

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

/// The seed of the catalogue's numerical verification (geometry and configurations); each
/// entry derives its own from it and its notation ([`Entry::seed`]).
pub const VERIFICATION_SEED: u64 = 2026;

/// The version of `chains.json` that [`Catalogue::to_json`] writes and [`Catalogue::from_json`]
/// reads (the file's `format` field). Raise it when the file's shape or meaning changes, so
/// that a binary never reads a file it would misunderstand.
pub const FORMAT: &str = "kinsyn-catalogue/2";

/// The committed `catalogue/chains.json`, compiled in.
///
/// The committed catalogue is part of the source: it is what [`Catalogue::generate`] gives with
/// the default reading (`tests/catalogue.rs` checks it entry by entry, and byte for byte against
/// a fresh `kinsyn catalogue generate`). Compiling it in lets the binary read it from any
/// working directory, installed or not, with no path to find and no file that can go missing
/// or be swapped for another version after the build; its cost is 1.3 MB of read-only data.
pub const COMMITTED_JSON: &str = include_str!("../catalogue/chains.json");

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
}

/// A chain that gives the asked-for pattern, and how.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct QueryHit<'a> {
    /// The entry.
    pub entry: &'a Entry,
    /// The pattern as classified (with its direction).
    pub pattern: String,
    /// Its minimal lock sets within the limit (1-based joints, `-` for none).
    pub lock_sets: Vec<String>,
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
    /// The row-by-row comparison with the printed Appendix.
    #[serde(skip)]
    pub rows: Vec<RowComparison>,
    /// Every difference from the printed Appendix.
    #[serde(skip)]
    pub differences: Vec<Difference>,
    /// The settings and seed of the numerical check, once it ran.
    #[serde(skip)]
    pub verification: Option<(Settings, u64)>,
}

/// Parallel groups as text: `3 4; 5 6`.
fn groups_text(groups: &[Vec<usize>]) -> String {
    groups
        .iter()
        .map(|g| {
            g.iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join(" ")
        })
        .collect::<Vec<_>>()
        .join("; ")
}

/// Number of joints in a lock-set text (`-` for none).
fn lock_count(locks: &str) -> usize {
    if locks == "-" { 0 } else { locks.len() }
}

/// Whether a classified pattern's text form (parsed back as a query) is what `asked` wants: same
/// kind, and the same axis when the question names one.
fn pattern_query_covers(asked: &PatternQuery, classified: &PatternQuery) -> bool {
    if let (Some(kind), PatternQuery::Group { kind: k, .. }) = (asked.forced_group(), classified) {
        return kind == *k;
    }
    match (asked, classified) {
        (PatternQuery::Group { kind, axis }, PatternQuery::Group { kind: k, axis: a }) => {
            kind == k && (axis.is_none() || axis == a)
        }
        (a, c) => a == c,
    }
}

impl Catalogue {
    /// Enumerates, deduplicates, compares with the paper and verifies every entry
    /// numerically (default settings, [`VERIFICATION_SEED`]): the committed catalogue.
    #[must_use]
    pub fn generate(options: &Options) -> Self {
        let mut cat = Self::synthesise(options);
        cat.verify(&Settings::default(), VERIFICATION_SEED);
        cat
    }

    /// Enumerates, deduplicates and compares with the paper, without the numerical check.
    #[must_use]
    pub fn synthesise(options: &Options) -> Self {
        let candidates = synthesis::enumerate(options);
        Self::from_candidates(*options, &candidates)
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

    /// Reads a catalogue written by [`Catalogue::to_json`]: options, counts and entries with
    /// their verification come from the text; the row-by-row comparison with the printed
    /// Appendix (`rows`, `differences`), which the file does not hold, is recomputed from the
    /// enumeration (no numerical check: about 15 ms).
    ///
    /// # Errors
    /// [`LoadError::Format`] if the text's `format` is not [`FORMAT`], [`LoadError::Parse`] if it
    /// is not a catalogue.
    pub fn from_json(text: &str) -> Result<Self, LoadError> {
        /// The parts of `chains.json` that a catalogue is rebuilt from; the prose fields
        /// (`source`, `identity`, the verification's `geometry` and `locks`) are ignored.
        #[derive(Deserialize)]
        struct File {
            format: String,
            options: Options,
            verification: Option<VerificationMeta>,
            counts: Vec<TableCount>,
            entries: Vec<Entry>,
        }
        #[derive(Deserialize)]
        struct VerificationMeta {
            seed: u64,
            settings: Settings,
        }
        /// Only the version, to tell another format from a damaged file.
        #[derive(Deserialize)]
        struct Header {
            format: String,
        }
        let wrong_format = |found: String| (found != FORMAT).then_some(LoadError::Format { found });
        let file: File =
            serde_path_to_error::deserialize(&mut serde_json::Deserializer::from_str(text))
                .map_err(|e| {
                    serde_json::from_str::<Header>(text)
                        .ok()
                        .and_then(|h| wrong_format(h.format))
                        .unwrap_or(LoadError::Parse(e))
                })?;
        if let Some(e) = wrong_format(file.format) {
            return Err(e);
        }
        let (rows, differences) = paper::compare(&synthesis::enumerate(&file.options));
        Ok(Catalogue {
            options: file.options,
            entries: file.entries,
            counts: file.counts,
            rows,
            differences,
            verification: file.verification.map(|v| (v.settings, v.seed)),
        })
    }

    /// Verifies every entry numerically (in parallel): rank, idle joints and the patterns of
    /// all lock subsets ([`verification::verify`]), and counts the 3T3R entries per table.
    pub fn verify(&mut self, settings: &Settings, seed: u64) {
        self.entries.par_iter_mut().for_each(|e| {
            e.verification = e
                .serial_chain(seed)
                .ok()
                .map(|chain| verification::verify(&chain, settings, e.sample_seed(seed)));
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

    /// The verified chains that give `pattern`, directly or with at most `max_locks` joints
    /// locked, with their minimal lock sets; optionally only one family.
    #[must_use]
    pub fn query(
        &self,
        pattern: &PatternQuery,
        max_locks: usize,
        family: Option<&str>,
    ) -> Vec<QueryHit<'_>> {
        let mut hits = Vec::new();
        for e in self
            .verified()
            .filter(|e| family.is_none_or(|f| e.family == f))
        {
            let Some(v) = &e.verification else { continue };
            for (text, locks) in &v.patterns {
                let Ok(classified) = text.parse::<PatternQuery>() else {
                    continue;
                };
                if !pattern_query_covers(pattern, &classified) {
                    continue;
                }
                let within: Vec<String> = locks
                    .iter()
                    .filter(|l| lock_count(l) <= max_locks)
                    .cloned()
                    .collect();
                if !within.is_empty() {
                    hits.push(QueryHit {
                        entry: e,
                        pattern: text.clone(),
                        lock_sets: within,
                    });
                }
            }
        }
        hits
    }

    /// Builds the catalogue from enumerated candidates (first occurrence wins).
    #[must_use]
    pub fn from_candidates(options: Options, candidates: &[Candidate]) -> Self {
        let (rows, differences) = paper::compare(candidates);
        let printed_in_row: BTreeSet<(u8, usize, String)> = paper::appendix()
            .into_iter()
            .flat_map(|p| p.chains.into_iter().map(move |c| (p.table, p.row, c)))
            .collect();
        let printed_anywhere: BTreeSet<&str> =
            printed_in_row.iter().map(|(_, _, c)| c.as_str()).collect();
        let mut seen_marks = BTreeSet::new();
        let mut seen_letters = BTreeSet::new();
        let mut seen_printed: BTreeSet<String> = BTreeSet::new();
        let mut entries = Vec::new();
        let mut counts = Vec::new();
        for table in &TABLES {
            let mut count = TableCount {
                table: table.number,
                family: table.family.to_string(),
                published: table.published,
                candidates: 0,
                letters_only: 0,
                with_marks: 0,
                printed_letters: 0,
                verified_3t3r: None,
            };
            let mut n = 0;
            for c in candidates.iter().filter(|c| c.table == table.number) {
                count.candidates += 1;
                let notation = c.chain.to_string();
                let letters = c.chain.letters();
                let first_with_letters = seen_letters.insert(letters.clone());
                count.letters_only += usize::from(first_with_letters);
                if !seen_marks.insert(notation.clone()) {
                    continue;
                }
                count.with_marks += 1;
                n += 1;
                let in_row = printed_in_row.iter().any(|(t, r, l)| {
                    *t == c.table && (*r == c.row || c.table >= 5) && *l == letters
                });
                entries.push(Entry {
                    id: format!("T{}-{n:03}", table.number),
                    notation,
                    parallel_groups: c.parallel_groups.clone(),
                    composition: Composition::of(&c.chain),
                    first_with_letters,
                    printed_in_row: in_row,
                    printed_in_appendix: printed_anywhere.contains(letters.as_str()),
                    letters,
                    family: table.family.to_string(),
                    word: c.word.clone(),
                    axes: c.axes.clone(),
                    provenance: Provenance {
                        table: c.table,
                        row: c.row,
                        variant: c.variant,
                        variant_label: c.variant_label.clone(),
                    },
                    verification: None,
                });
            }
            for (t, _, l) in &printed_in_row {
                if *t == table.number && seen_printed.insert(l.clone()) {
                    count.printed_letters += 1;
                }
            }
            counts.push(count);
        }
        Catalogue {
            options,
            entries,
            counts,
            rows,
            differences,
            verification: None,
        }
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

    /// How many differences of each kind each table has.
    #[must_use]
    pub fn difference_counts(&self) -> BTreeMap<(u8, DifferenceKind), usize> {
        let mut m = BTreeMap::new();
        for d in &self.differences {
            *m.entry((d.key.table, d.kind)).or_insert(0) += 1;
        }
        m
    }

    /// `chains.json`: the entries with the generator's metadata.
    #[must_use]
    pub fn to_json(&self) -> String {
        #[derive(Serialize)]
        struct VerificationMeta {
            seed: u64,
            settings: Settings,
            geometry: &'static str,
            locks: &'static str,
        }
        #[derive(Serialize)]
        struct File<'a> {
            format: &'static str,
            source: &'static str,
            identity: &'static str,
            options: &'a Options,
            #[serde(skip_serializing_if = "Option::is_none")]
            verification: Option<VerificationMeta>,
            counts: &'a [TableCount],
            entries: &'a [Entry],
        }
        let file = File {
            verification: self.verification.map(|(settings, seed)| VerificationMeta {
                seed,
                settings,
                geometry: "axes along the entry's directions; joints of one C/U/S share a point; other consecutive joints offset by seeded generic vectors (length 0.5-1.5)",
                locks: "locked joints held at their reference values; lock sets are 1-based joint positions in the entry's word, '-' for none",
            }),
            format: FORMAT,
            source: "paper 000 §2 and Appendix (Ibarreche et al., Multioperation capacity of parallel manipulators basing on generic kinematic chain approach)",
            identity: "letters + parallel marks, first occurrence in table order",
            options: &self.options,
            counts: &self.counts,
            entries: &self.entries,
        };
        let mut s = serde_json::to_string_pretty(&file).expect("catalogue serialises");
        s.push('\n');
        s
    }

    /// `chains.csv`: one flat line per entry.
    #[must_use]
    pub fn to_csv(&self) -> String {
        let mut s = String::from(
            "id,notation,letters,family,word,axes,parallel_groups,p,r,c,u,s,table,row,variant,variant_label,first_with_letters,printed_in_row,printed_in_appendix,rank,gap,idle_joints,is_3t3r,group_patterns\n",
        );
        for e in &self.entries {
            let c = e.composition;
            let (rank, gap, idle, is_3t3r, groups) = match &e.verification {
                Some(v) => (
                    v.rank.to_string(),
                    v.gap.to_string(),
                    v.idle_joints
                        .iter()
                        .map(ToString::to_string)
                        .collect::<Vec<_>>()
                        .join(" "),
                    v.is_3t3r.to_string(),
                    v.patterns
                        .keys()
                        .filter(|p| {
                            p.parse::<PatternQuery>()
                                .is_ok_and(|q| matches!(q, PatternQuery::Group { .. }))
                        })
                        .cloned()
                        .collect::<Vec<_>>()
                        .join(" "),
                ),
                None => Default::default(),
            };
            let _ = writeln!(
                s,
                "{},\"{}\",{},{},{},{},\"{}\",{},{},{},{},{},{},{},{},\"{}\",{},{},{},{},{},\"{}\",{},\"{}\"",
                e.id,
                e.notation,
                e.letters,
                e.family,
                e.word,
                e.axes,
                groups_text(&e.parallel_groups),
                c.p,
                c.r,
                c.c,
                c.u,
                c.s,
                e.provenance.table,
                e.provenance.row,
                e.provenance.variant,
                e.provenance.variant_label,
                e.first_with_letters,
                e.printed_in_row,
                e.printed_in_appendix,
                rank,
                gap,
                idle,
                is_3t3r,
                groups
            );
        }
        s
    }

    /// The per-table counts as a Markdown table, published numbers beside the generated and
    /// verified ones.
    #[must_use]
    pub fn counts_markdown(&self) -> String {
        let mut s = String::from(
            "| table | family | published | printed letters (new) | generated, letters only (new) | generated, letters + marks (new) | verified 3T3R (new) | candidates |\n|---|---|---:|---:|---:|---:|---:|---:|\n",
        );
        let row = |s: &mut String,
                   table: &str,
                   family: &str,
                   published: Option<usize>,
                   counts: &[&TableCount]| {
            let sum = |f: &dyn Fn(&TableCount) -> usize| counts.iter().map(|c| f(c)).sum::<usize>();
            let verified = if counts.iter().all(|c| c.verified_3t3r.is_some()) {
                sum(&|c| c.verified_3t3r.unwrap_or(0)).to_string()
            } else {
                "—".to_string()
            };
            let _ = writeln!(
                s,
                "| {table} | {family} | {} | {} | {} | {} | {verified} | {} |",
                published.map_or_else(|| "—".to_string(), |n| n.to_string()),
                sum(&|c| c.printed_letters),
                sum(&|c| c.letters_only),
                sum(&|c| c.with_marks),
                sum(&|c| c.candidates)
            );
        };
        for c in &self.counts {
            row(&mut s, &c.table.to_string(), &c.family, c.published, &[c]);
        }
        let six_r: Vec<&TableCount> = self.counts.iter().filter(|c| c.table >= 5).collect();
        row(
            &mut s,
            "7 + 8",
            "RRRRRR",
            Some(tables::PUBLISHED_6R),
            &six_r,
        );
        let all: Vec<&TableCount> = self.counts.iter().collect();
        row(&mut s, "all", "", Some(tables::PUBLISHED_TOTAL), &all);
        s
    }

    /// The differences from the printed Appendix as the Markdown table kept in
    /// docs/deviations.md (one line per difference).
    #[must_use]
    pub fn differences_markdown(&self) -> String {
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

    /// The entries the numerical check rejects (not 3T3R), as the Markdown table kept in
    /// docs/deviations.md: rank, singular values, idle joints, and whether the paper prints the
    /// letters (and which entries with the same letters do pass).
    #[must_use]
    pub fn not_3t3r_markdown(&self) -> String {
        let mut s = String::from(
            "| id | chain | from | axes | rank | singular values | idle joints | printed | same letters, 3T3R |\n|---|---|---|---|---:|---|---|---|---|\n",
        );
        for e in &self.entries {
            let Some(v) = e.verification.as_ref().filter(|v| !v.is_3t3r) else {
                continue;
            };
            let sv: Vec<String> = v
                .singular_values
                .iter()
                .map(|x| format!("{x:.3e}"))
                .collect();
            let same: Vec<&str> = self
                .verified()
                .filter(|o| o.letters == e.letters)
                .map(|o| o.id.as_str())
                .collect();
            let printed = if e.printed_in_row {
                "in its row"
            } else if e.printed_in_appendix {
                "elsewhere"
            } else {
                "no"
            };
            let _ = writeln!(
                s,
                "| {} | {} | Table {} row {} | {} | {} | {} | {} | {printed} | {} |",
                e.id,
                e.notation,
                e.provenance.table,
                e.provenance.row,
                e.axes,
                v.rank,
                sv.join(" "),
                v.idle_joints
                    .iter()
                    .map(ToString::to_string)
                    .collect::<Vec<_>>()
                    .join(" "),
                if same.is_empty() {
                    "none".to_string()
                } else {
                    same.join(" ")
                }
            );
        }
        s
    }

    /// `catalogue/README.md`.
    #[must_use]
    pub fn readme(&self) -> String {
        let mut s = String::new();
        s.push_str("# The kinsyn catalogue of 6-dof P/R leg chains\n\n");
        s.push_str("Generated by `kinsyn catalogue generate`; do not edit by hand (a test regenerates these files and\n");
        s.push_str("compares them byte for byte). Source: paper 000 §2 and its Appendix, read as `docs/synthesis.md`\n");
        s.push_str("describes. Notation: `docs/notation.md`.\n\n");
        s.push_str("## Files\n\n");
        s.push_str("- `chains.json`: every entry (id, notation, letters, family, P/R word, axis directions, parallel\n");
        s.push_str("  groups, C/U/S composition, provenance, whether the paper prints it), with the counts below.\n");
        s.push_str("- `chains.csv`: the same entries, one flat line each.\n\n");
        s.push_str("## Counts per table\n\n");
        s.push_str("Each count is of chains new to that table (first occurrence wins, in the paper's table order).\n");
        s.push_str("\"Printed letters\" counts the distinct names the plain-text Appendix prints, misprints included;\n");
        s.push_str("the published numbers count the paper's own identity, which rests on typographic marks this\n");
        s.push_str("copy lost. The catalogue's entries are the \"letters + marks\" column.\n\n");
        s.push_str(&self.counts_markdown());
        if let Some((settings, seed)) = self.verification {
            let rejected: Vec<&str> = self
                .entries
                .iter()
                .filter(|e| e.verification.as_ref().is_some_and(|v| !v.is_3t3r))
                .map(|e| e.id.as_str())
                .collect();
            let _ = write!(
                s,
                "\n## Numerical verification\n\nEvery entry's Jacobian was evaluated at {} random configurations (seed {seed}, rank tolerance {:e} of the\nlargest singular value) on a generic geometry (`docs/verification.md`). {} entries are 3T3R with no idle joint\n(the verified catalogue, which `kinsyn query` searches); {} are not: {}.\n",
                settings.samples,
                settings.rank_tolerance,
                self.verified().count(),
                rejected.len(),
                rejected.join(", ")
            );
        }
        s.push_str("\n## Differences from the printed Appendix\n\n");
        s.push_str("Row by row, on letters (see `docs/deviations.md` for every difference with its evidence):\n\n");
        s.push_str("| table | misprint | carried over | rule violation | outside pattern | not readable | omission, printed elsewhere | omission, not printed |\n|---|---:|---:|---:|---:|---:|---:|---:|\n");
        let counts = self.difference_counts();
        for t in &TABLES {
            let get = |k| counts.get(&(t.number, k)).copied().unwrap_or(0);
            let _ = writeln!(
                s,
                "| {} | {} | {} | {} | {} | {} | {} | {} |",
                t.number,
                get(DifferenceKind::Misprint),
                get(DifferenceKind::CarriedOver),
                get(DifferenceKind::RuleViolation),
                get(DifferenceKind::OutsidePattern),
                get(DifferenceKind::NotReadable),
                get(DifferenceKind::PrintedElsewhere),
                get(DifferenceKind::NotPrinted)
            );
        }
        s
    }

    /// Writes `chains.json`, `chains.csv` and `README.md` into `dir`, creating it.
    ///
    /// # Errors
    /// Any I/O error, with the path that failed.
    pub fn write(&self, dir: &Path) -> Result<(), std::io::Error> {
        std::fs::create_dir_all(dir)
            .map_err(|e| std::io::Error::new(e.kind(), format!("{}: {e}", dir.display())))?;
        for (name, text) in [
            ("chains.json", self.to_json()),
            ("chains.csv", self.to_csv()),
            ("README.md", self.readme()),
        ] {
            let path = dir.join(name);
            std::fs::write(&path, text)
                .map_err(|e| std::io::Error::new(e.kind(), format!("{}: {e}", path.display())))?;
        }
        Ok(())
    }
}
