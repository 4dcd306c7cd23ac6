//! Paper 000's printed Appendix (Tables 1–4, 7 and 8), transcribed, and the catalogue compared
//! with it.
//!
//! The plain-text copy lost the parallel marks, so the comparison is on letters. A row of
//! Tables 1–4 is compared as a whole (its variant sub-rows pooled: which sub-row is which
//! depended on the lost marks); Tables 7 and 8 index their rows by lost marks alone, so each is
//! compared as one pool ([`POOLED`]). The comparison itself is the engine's
//! ([`kinsyn::published`]); this module gives it the data, and builds the committed catalogue
//! (`catalogue/`) with it: [`generate`] with the default options.

use kinsyn::catalogue::Catalogue;
use kinsyn::published::{Comparison, PrintedRow, PrintedTables};
use kinsyn::synthesis::{self, Candidate, Options};

/// The transcription of the Appendix (see the header of the file for its columns).
pub const APPENDIX_TSV: &str = include_str!("../../../data/paper000-appendix.tsv");

/// The tables whose rows the plain-text copy cannot tell apart (their rows are indexed by lost
/// marks alone): each is compared as one pool.
pub const POOLED: [u8; 2] = [7, 8];

/// How the evidence of a difference names the whole: "no row of the Appendix prints it".
pub const NAME: &str = "the Appendix";

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

/// The Appendix as the printed table the catalogue is marked against and compared with.
///
/// # Panics
/// Never on the embedded file (every row is of a synthesis table and holds a P/R word); a test
/// checks it.
#[must_use]
pub fn printed() -> PrintedTables {
    PrintedTables::new(NAME, appendix(), POOLED).expect("the Appendix's rows are checked")
}

/// Compares enumerated candidates with the Appendix, row by row.
#[must_use]
pub fn compare(candidates: &[Candidate]) -> Comparison {
    Comparison::new(&printed(), candidates)
}

/// The comparison of the enumeration in `options` with the Appendix (about 15 ms): what a
/// catalogue read from its file ([`Catalogue::committed`], [`Catalogue::from_json`]) is
/// compared with.
#[must_use]
pub fn comparison(options: &Options) -> Comparison {
    compare(&synthesis::enumerate(options))
}

/// The catalogue in `options`, its entries marked against the Appendix, and its comparison
/// with it; no numerical check.
#[must_use]
pub fn synthesise(options: &Options) -> (Catalogue, Comparison) {
    let candidates = synthesis::enumerate(options);
    let printed = printed();
    (
        Catalogue::from_candidates(*options, &candidates, &printed),
        Comparison::new(&printed, &candidates),
    )
}

/// [`synthesise`], then every entry verified numerically ([`Catalogue::verify`] with the
/// default settings and [`kinsyn::catalogue::VERIFICATION_SEED`]): with the default options,
/// the committed catalogue and its comparison (`kinsyn catalogue generate`).
#[must_use]
pub fn generate(options: &Options) -> (Catalogue, Comparison) {
    let (mut catalogue, comparison) = synthesise(options);
    catalogue.verify(
        &kinsyn::verification::Settings::default(),
        kinsyn::catalogue::VERIFICATION_SEED,
    );
    (catalogue, comparison)
}
