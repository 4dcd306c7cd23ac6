//! Which designs a sweep evaluates: the catalogue chains chosen (`--chains`, `--family`) and
//! this run's shard of them (`--shard K/N`).

use crate::Error;
use kinsyn::catalogue::Catalogue;
use kinsyn::sweep::{Design, SweepSettings, designs};
use kinsyn::synthesis::tables;
use serde::{Deserialize, Serialize};
use std::fmt;

/// The catalogue chains a sweep is restricted to; both `None`: every verified chain.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct SweepSelection {
    /// Only these chain ids, in catalogue order, each once (`--chains`).
    pub chains: Option<Vec<String>>,
    /// Only chains of this family, e.g. `PPRRRR` (`--family`).
    pub family: Option<String>,
}

impl SweepSelection {
    /// The selection of `--chains` (comma-separated ids, any case) and `--family`, checked
    /// against `catalogue`: the ids become the catalogue's spelling, in catalogue order.
    ///
    /// # Errors
    /// [`Error::Input`] naming an unknown id, an id whose chain is not verified (so not in
    /// the sweep), an empty list, or an unknown family.
    pub fn new(
        catalogue: &Catalogue,
        chains: Option<&str>,
        family: Option<&str>,
    ) -> Result<Self, Error> {
        if let Some(f) = family
            && !tables::families().contains(&f)
        {
            return Err(Error::Input(format!(
                "--family {f:?}: unknown family; the families are {}",
                tables::families().join(", ")
            )));
        }
        let chains = match chains {
            None => None,
            Some(text) => {
                let mut wanted = Vec::new();
                for id in text.split(',').map(str::trim) {
                    if id.is_empty() {
                        return Err(Error::Input(format!(
                            "--chains {text:?}: an empty id; give catalogue ids such as T1-001,T4-034"
                        )));
                    }
                    let Some(entry) = catalogue
                        .entries
                        .iter()
                        .find(|e| e.id.eq_ignore_ascii_case(id))
                    else {
                        return Err(Error::Input(format!(
                            "--chains: no catalogue entry {id:?} (ids look like T1-001; see kinsyn catalogue list)"
                        )));
                    };
                    if !catalogue.verified().any(|e| e.id == entry.id) {
                        return Err(Error::Input(format!(
                            "--chains: {} is not a verified chain (the numerical check rejects it), so it is in no sweep",
                            entry.id
                        )));
                    }
                    wanted.push(entry.id.clone());
                }
                let ordered: Vec<String> = catalogue
                    .entries
                    .iter()
                    .filter(|e| wanted.contains(&e.id))
                    .map(|e| e.id.clone())
                    .collect();
                Some(ordered)
            }
        };
        Ok(SweepSelection {
            chains,
            family: family.map(str::to_string),
        })
    }

    /// The sweep's designs: those of [`designs`] on the selected verified chains only,
    /// numbered from 0 in that order.
    ///
    /// # Errors
    /// [`Error::Input`] when the selection leaves no design (a family with none of the
    /// chosen chains).
    pub fn designs(
        &self,
        catalogue: &Catalogue,
        settings: &SweepSettings,
    ) -> Result<Vec<Design>, Error> {
        let mut chosen = catalogue.clone();
        chosen.entries.retain(|e| {
            self.chains.as_ref().is_none_or(|c| c.contains(&e.id))
                && self.family.as_ref().is_none_or(|f| &e.family == f)
        });
        let list = designs(&chosen, settings);
        if list.is_empty() {
            return Err(Error::Input(format!(
                "the selection ({self}) has no design; check --chains and --family"
            )));
        }
        Ok(list)
    }
}

impl fmt::Display for SweepSelection {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (&self.chains, &self.family) {
            (None, None) => write!(f, "every verified chain"),
            (Some(c), None) => write!(f, "chains {}", c.join(",")),
            (None, Some(fam)) => write!(f, "family {fam}"),
            (Some(c), Some(fam)) => write!(f, "chains {} of family {fam}", c.join(",")),
        }
    }
}

/// One of `count` parts of a sweep (`--shard K/N`): design `i` (0-based, in sweep order) is in
/// shard `(i mod count) + 1`, so that neighbouring designs, of similar cost, are spread over
/// the shards.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct Shard {
    /// K, 1-based.
    pub index: usize,
    /// N, the number of shards.
    pub count: usize,
}

impl Shard {
    /// The shard of `--shard K/N`.
    ///
    /// # Errors
    /// [`Error::Input`] when the text is not two whole numbers `K/N` with `1 ≤ K ≤ N`.
    pub fn parse(text: &str) -> Result<Self, Error> {
        let bad = |why: &str| {
            Error::Input(format!(
                "--shard {text:?}: {why}; give K/N with 1 <= K <= N, e.g. 2/3"
            ))
        };
        let (k, n) = text.split_once('/').ok_or_else(|| bad("no '/'"))?;
        let k: usize = k
            .trim()
            .parse()
            .map_err(|_| bad("K is not a whole number"))?;
        let n: usize = n
            .trim()
            .parse()
            .map_err(|_| bad("N is not a whole number"))?;
        if n == 0 {
            return Err(bad("N is 0"));
        }
        if k == 0 || k > n {
            return Err(bad(&format!("K is {k}, outside 1..={n}")));
        }
        Ok(Shard { index: k, count: n })
    }

    /// Whether design `index` of the sweep belongs to this shard.
    #[must_use]
    pub fn contains(&self, index: usize) -> bool {
        index % self.count + 1 == self.index
    }
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}
