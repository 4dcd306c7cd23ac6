//! The search of the verified catalogue for a motion pattern: the chains that give it with at
//! most so many joints locked, and their minimal lock sets.

use super::{Catalogue, Entry};
use crate::lockset::LockSet;
use crate::motion::{PatternName, PatternQuery};
use serde::Serialize;

/// A chain that gives the asked-for pattern, and how.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct QueryHit<'a> {
    /// The entry.
    pub entry: &'a Entry,
    /// The pattern as classified (with its direction): `X(z)` for a query `X`.
    pub pattern: PatternName,
    /// The joints to lock for it: its minimal lock sets with at most the asked number of
    /// joints (written `456`, `-` for none).
    pub lock_sets: Vec<LockSet>,
}

impl Catalogue {
    /// The verified chains that give `pattern`, directly or with at most `max_locks` joints
    /// locked, with their minimal lock sets; optionally only one family. A chain gives one hit
    /// per classified pattern the query covers ([`PatternQuery::covers`]: `X` finds `X(x)`,
    /// `X(y)` and `X(z)`), in catalogue order, patterns in the order of their names.
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
            for (name, locks) in v.patterns.iter().filter(|(name, _)| pattern.covers(name)) {
                let within: Vec<LockSet> = locks
                    .iter()
                    .copied()
                    .filter(|l| l.len() <= max_locks)
                    .collect();
                if !within.is_empty() {
                    hits.push(QueryHit {
                        entry: e,
                        pattern: *name,
                        lock_sets: within,
                    });
                }
            }
        }
        hits
    }
}
