//! The catalogue's files: `chains.json` (format [`FORMAT`], written and read back),
//! `chains.csv`, `README.md` (with the comparison's counts of differences), and the Markdown
//! tables kept in `docs/deviations.md`.

use super::{Catalogue, Entry, FORMAT, LoadError, TableCount};
use crate::output::{self, OutputError, Overwrite};
use crate::published::{Comparison, DifferenceKind};
use crate::synthesis::{Options, TABLES, tables};
use crate::verification::Settings;
use serde::{Deserialize, Serialize};
use std::fmt::Write as _;
use std::path::Path;

/// How many readings an entry has and how many of them the rank check finds 3T3R: `4, all
/// rank 5` for a rejected entry, `4, 3 are 3T3R`.
fn readings_text(readings: &[super::Reading]) -> String {
    let n = readings.len();
    let good = readings.iter().filter(|r| r.is_3t3r()).count();
    let ranks: std::collections::BTreeSet<usize> = readings
        .iter()
        .filter_map(|r| r.check.as_ref().map(|c| c.rank))
        .collect();
    if good == 0 {
        let ranks: Vec<String> = ranks.iter().map(ToString::to_string).collect();
        let all = if n == 1 { "" } else { "all " };
        format!("{n}, {all}rank {}", ranks.join("/"))
    } else {
        format!("{n}, {good} 3T3R")
    }
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

impl Catalogue {
    /// Reads a catalogue written by [`Catalogue::to_json`]: options, counts and entries with
    /// their verification, as the text holds them (no enumeration, no numerical check). The
    /// row-by-row comparison with a printed table, which the file does not hold, is
    /// [`Comparison::new`] on the enumeration in the catalogue's options.
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
        Ok(Catalogue {
            options: file.options,
            entries: file.entries,
            counts: file.counts,
            verification: file.verification.map(|v| (v.settings, v.seed)),
        })
    }

    /// `chains.json`: the entries with the generator's metadata.
    ///
    /// # Panics
    /// Never: the catalogue is plain data, and its only map keys (pattern names) are strings,
    /// so JSON can always represent it.
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
            "id,notation,letters,family,word,axes,parallel_groups,p,r,c,u,s,table,row,variant,variant_label,first_with_letters,printed_in_row,printed_in_appendix,rank,gap,idle_joints,is_3t3r,group_patterns,reading,readings,readings_3t3r\n",
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
                        .filter(|p| p.is_group())
                        .map(ToString::to_string)
                        .collect::<Vec<_>>()
                        .join(" "),
                ),
                None => Default::default(),
            };
            let _ = writeln!(
                s,
                "{},\"{}\",{},{},{},{},\"{}\",{},{},{},{},{},{},{},{},\"{}\",{},{},{},{},{},\"{}\",{},\"{}\",{},{},{}",
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
                groups,
                e.reading,
                e.readings.len(),
                e.readings.iter().filter(|r| r.is_3t3r()).count()
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

    /// The entries the numerical check rejects (not 3T3R), as the Markdown table kept in
    /// docs/deviations.md: rank, singular values, idle joints, and whether the paper prints the
    /// letters (and which entries with the same letters do pass).
    #[must_use]
    pub fn not_3t3r_markdown(&self) -> String {
        let mut s = String::from(
            "| id | chain | from | axes | rank | singular values | idle joints | readings | printed | same letters, 3T3R |\n|---|---|---|---|---:|---|---|---|---|---|\n",
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
                "| {} | {} | Table {} row {} | {} | {} | {} | {} | {} | {printed} | {} |",
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
                readings_text(&e.readings),
                if same.is_empty() {
                    "none".to_string()
                } else {
                    same.join(" ")
                }
            );
        }
        s
    }

    /// The entries verified with another reading than their first (the first is rank
    /// deficient, a later axis assignment of the same notation is 3T3R), as the Markdown table
    /// kept in docs/deviations.md: each reading's rank and smallest/largest singular value.
    #[must_use]
    pub fn other_reading_markdown(&self) -> String {
        let mut s = String::from(
            "| id | chain | from | reading kept | from | axes | σ6/σ1 | readings (axes: rank, smallest kept σ / largest) |\n|---|---|---|---|---|---|---:|---|\n",
        );
        for e in &self.entries {
            if e.reading <= 1 || e.verification.is_none() {
                continue;
            }
            let kept = &e.readings[e.reading - 1];
            let gap = kept.check.as_ref().map_or(0.0, |c| c.gap);
            let _ = writeln!(
                s,
                "| {} | {} | Table {} row {} | {} of {} | Table {} row {} | {} | {gap:.3e} | {} |",
                e.id,
                e.notation,
                e.provenance.table,
                e.provenance.row,
                e.reading,
                e.readings.len(),
                kept.table,
                kept.row,
                kept.axes,
                e.readings
                    .iter()
                    .map(|r| match &r.check {
                        Some(c) => format!("{}: {}, {:.2e}", r.axes, c.rank, c.gap),
                        None => format!("{}: —", r.axes),
                    })
                    .collect::<Vec<_>>()
                    .join("; ")
            );
        }
        s
    }

    /// `catalogue/README.md`, with the counts of `comparison`'s differences (the comparison
    /// of the same enumeration with the printed Appendix: `kinsyn_papers::appendix`).
    #[must_use]
    pub fn readme(&self, comparison: &Comparison) -> String {
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
            let other: Vec<String> = self
                .entries
                .iter()
                .filter(|e| e.reading > 1 && e.verification.is_some())
                .map(|e| format!("{} (reading {} of {})", e.id, e.reading, e.readings.len()))
                .collect();
            let readings: usize = self.entries.iter().map(|e| e.readings.len()).sum();
            let _ = write!(
                s,
                "\n## Numerical verification\n\nEvery entry's Jacobian was evaluated at {} random configurations (seed {seed}, rank tolerance {:e} of the\nlargest singular value) on a generic geometry (`docs/verification.md`), for every reading of its notation\n(every axis assignment the rules read as its letters and marks: {readings} readings of {} entries); an entry keeps\nits first 3T3R reading. {} entries are 3T3R with no idle joint (the verified catalogue, which `kinsyn query`\nsearches), {} of them with another reading than their first: {}. {} are not (no reading is 3T3R): {}.\n",
                settings.samples,
                settings.rank_tolerance,
                self.entries.len(),
                self.verified().count(),
                other.len(),
                other.join(", "),
                rejected.len(),
                rejected.join(", ")
            );
        }
        s.push_str("\n## Differences from the printed Appendix\n\n");
        s.push_str("Row by row, on letters (see `docs/deviations.md` for every difference with its evidence):\n\n");
        s.push_str("| table | misprint | carried over | rule violation | outside pattern | not readable | omission, printed elsewhere | omission, not printed |\n|---|---:|---:|---:|---:|---:|---:|---:|\n");
        let counts = comparison.counts();
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

    /// The files [`Catalogue::write`] writes, in its folder.
    pub const FILES: [&'static str; 3] = ["chains.json", "chains.csv", "README.md"];

    /// Writes `chains.json`, `chains.csv` and `README.md` (with `comparison`'s counts, as
    /// [`Catalogue::readme`]) into the folder `dir`, creating it if missing (only it: its
    /// parent must exist). All three are checked before any is written:
    /// with [`Overwrite::Refuse`] an existing one refuses them all. Each file is written whole
    /// or not at all ([`crate::output`]).
    ///
    /// # Errors
    /// The [`OutputError`] of the first file or folder that fails, with its path.
    pub fn write(
        &self,
        dir: &Path,
        comparison: &Comparison,
        overwrite: Overwrite,
    ) -> Result<(), OutputError> {
        output::check_folder(dir)?;
        for name in Self::FILES {
            output::check_file(&dir.join(name), overwrite)?;
        }
        let texts = [self.to_json(), self.to_csv(), self.readme(comparison)];
        output::create_folder(dir)?;
        for (name, text) in Self::FILES.into_iter().zip(texts) {
            output::write(&dir.join(name), text.as_bytes(), overwrite)?;
        }
        Ok(())
    }
}
