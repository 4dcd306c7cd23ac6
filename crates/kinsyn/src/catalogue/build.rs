//! The catalogue from enumerated candidates: the first occurrence of each chain (letters and
//! parallel marks) in the paper's table order becomes an entry with its provenance, and each
//! table counts what is new to it.

use super::{Catalogue, Composition, Entry, Provenance, Reading, TableCount};
use crate::published::PrintedTables;
use crate::synthesis::{Candidate, Options, TABLES, Table};
use std::collections::{BTreeMap, BTreeSet};

/// What earlier tables already hold: the first occurrence wins.
#[derive(Default)]
struct Seen {
    /// Canonical notations (letters and parallel marks): the catalogue's identity.
    marks: BTreeSet<String>,
    /// Letters only.
    letters: BTreeSet<String>,
    /// Printed letters.
    printed: BTreeSet<String>,
}

impl Seen {
    /// The new entries of one table and its counts, remembering what it adds.
    fn table(
        &mut self,
        table: &Table,
        candidates: &[Candidate],
        printed: &PrintedTables,
    ) -> (TableCount, Vec<Entry>) {
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
        let mut entries = Vec::new();
        for c in candidates.iter().filter(|c| c.table == table.number) {
            count.candidates += 1;
            let notation = c.chain.to_string();
            let letters = c.chain.letters();
            let first_with_letters = self.letters.insert(letters.clone());
            count.letters_only += usize::from(first_with_letters);
            if !self.marks.insert(notation.clone()) {
                continue;
            }
            count.with_marks += 1;
            let id = format!("T{}-{:03}", table.number, entries.len() + 1);
            entries.push(Entry {
                id,
                notation,
                parallel_groups: c.parallel_groups.clone(),
                composition: Composition::of(&c.chain),
                first_with_letters,
                printed_in_row: printed.printed_in(c.table, c.row, &letters),
                printed_in_appendix: printed.printed_anywhere(&letters),
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
                reading: 1,
                readings: vec![Reading::of(c)],
                verification: None,
            });
        }
        for p in printed.rows().iter().filter(|p| p.table == table.number) {
            for l in &p.chains {
                if self.printed.insert(l.clone()) {
                    count.printed_letters += 1;
                }
            }
        }
        (count, entries)
    }
}

/// Gives each entry every reading of its notation: the candidates that deduplication drops
/// (same letters and marks, another axis assignment, in this row or a later one) are kept as
/// the entry's further readings, in enumeration order, each axis assignment of a word once.
fn attach_readings(entries: &mut [Entry], candidates: &[Candidate]) {
    let by_notation: BTreeMap<String, usize> = entries
        .iter()
        .enumerate()
        .map(|(k, e)| (e.notation.clone(), k))
        .collect();
    for c in candidates {
        let Some(&k) = by_notation.get(&c.chain.to_string()) else {
            continue;
        };
        let readings = &mut entries[k].readings;
        if !readings
            .iter()
            .any(|r| r.word == c.word && r.axes == c.axes)
        {
            readings.push(Reading::of(c));
        }
    }
}

impl Catalogue {
    /// Builds the catalogue from enumerated candidates (first occurrence wins, in table order),
    /// each entry marked as printed in its row of `printed`, or elsewhere in it, or not; no
    /// numerical check. The row-by-row comparison with `printed` is
    /// [`crate::published::Comparison::new`] on the same candidates.
    #[must_use]
    pub fn from_candidates(
        options: Options,
        candidates: &[Candidate],
        printed: &PrintedTables,
    ) -> Self {
        let mut seen = Seen::default();
        let mut entries = Vec::new();
        let mut counts = Vec::new();
        for table in &TABLES {
            let (count, new) = seen.table(table, candidates, printed);
            counts.push(count);
            entries.extend(new);
        }
        attach_readings(&mut entries, candidates);
        Catalogue {
            options,
            entries,
            counts,
            verification: None,
        }
    }
}
