//! Catalogue chains named in a description: a leg's `chain` may be a catalogue id (`T4-034`) or
//! a catalogue chain's notation whose axes are left out, and both are resolved through a
//! [`ChainLookup`] before the manipulator is built.
//!
//! The default lookup, [`CommittedChains`], reads the ids, notations and axis words of the
//! committed `catalogue/chains.json` compiled into the crate ([`catalogue::COMMITTED_JSON`]),
//! once per process, without synthesising or verifying anything; a [`Catalogue`] (for instance
//! one synthesised with other options) is a lookup as well.

use crate::catalogue::{self, Catalogue};
use crate::notation::Chain;
use serde::Deserialize;
use std::sync::OnceLock;

/// A catalogue chain as a lookup gives it: what a leg needs to be built from it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CatalogueChain<'a> {
    /// The entry's id, e.g. `T4-034`.
    pub id: &'a str,
    /// Its canonical notation (letters and parallel marks).
    pub notation: &'a str,
    /// The axis direction (`x`, `y`, `z`) of each primitive joint at the reference
    /// configuration, in the leg frame ([`super::build::leg_frame`]).
    pub axes: &'a str,
}

/// Resolves the chains of a description against a catalogue.
pub trait ChainLookup {
    /// The catalogue chain whose id is `query` (ignoring case and surrounding blanks), or else
    /// whose notation is that of the chain `query` parses to (any spelling of the same marks,
    /// actuation ignored); `None` when there is none.
    fn chain(&self, query: &str) -> Option<CatalogueChain<'_>>;
}

impl ChainLookup for Catalogue {
    fn chain(&self, query: &str) -> Option<CatalogueChain<'_>> {
        self.find(query).map(|e| CatalogueChain {
            id: &e.id,
            notation: &e.notation,
            axes: &e.axes,
        })
    }
}

/// One row of the committed catalogue as the lookup reads it.
#[derive(Debug, Deserialize)]
struct Row {
    id: String,
    notation: String,
    axes: String,
}

/// The ids, notations and axis words of the committed catalogue (`catalogue/chains.json`,
/// compiled in): the default [`ChainLookup`] of [`super::Manipulator::new`]. It is the same
/// data as [`Catalogue::committed`] and [`Catalogue::synthesise`] with the default options give
/// (`tests/suite/manipulator.rs` checks every entry), read without the enumeration, the comparison
/// with the paper or the numerical check.
#[derive(Debug)]
pub struct CommittedChains {
    entries: Vec<Row>,
}

impl CommittedChains {
    /// The committed catalogue's chains, read on first use and kept for the process.
    ///
    /// # Panics
    /// If the compiled-in `chains.json` does not read or has another [`catalogue::FORMAT`]: a
    /// damaged build, which the test `embedded_catalogue_equals_the_generated_one` rules out.
    #[must_use]
    pub fn get() -> &'static Self {
        /// The parts of `chains.json` the lookup needs.
        #[derive(Deserialize)]
        struct File {
            format: String,
            entries: Vec<Row>,
        }
        static CHAINS: OnceLock<CommittedChains> = OnceLock::new();
        CHAINS.get_or_init(|| {
            let file: File = serde_json::from_str(catalogue::COMMITTED_JSON)
                .unwrap_or_else(|e| panic!("the compiled-in catalogue does not read: {e}"));
            assert!(
                file.format == catalogue::FORMAT,
                "the compiled-in catalogue is {:?}, this kinsyn reads {:?}",
                file.format,
                catalogue::FORMAT
            );
            CommittedChains {
                entries: file.entries,
            }
        })
    }
}

impl ChainLookup for CommittedChains {
    fn chain(&self, query: &str) -> Option<CatalogueChain<'_>> {
        let by_id = self
            .entries
            .iter()
            .find(|e| e.id.eq_ignore_ascii_case(query.trim()));
        let row = if let Some(row) = by_id {
            row
        } else {
            let chain: Chain = query.parse().ok()?;
            let text = chain.without_actuation().to_string();
            self.entries.iter().find(|e| e.notation == text)?
        };
        Some(CatalogueChain {
            id: &row.id,
            notation: &row.notation,
            axes: &row.axes,
        })
    }
}
