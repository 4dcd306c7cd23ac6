//! A solve's paths shared among processes. Every path of a homotopy is tracked on its own from
//! its start point, and the start points, γ and the patches come from the seed alone, so a
//! solve splits into **shards** — shard `K` of `N` tracks the paths `k` with `k mod N = K − 1`
//! ([`solve_shard`]) — run anywhere, and [`merge_shards`] puts their ends back in path order
//! and finishes as one process does: the suspect paths tracked again round by round, the
//! distinct solutions, the certificates. The answer is the one-process answer, path for path
//! (the tests compare every endpoint's bits).
//!
//! Neighbouring paths (of the same start cell or the same roots of unity) go to different
//! shards, so shards cost about the same. The re-tracking is the merge's: it needs every
//! path's end (two paths at one regular endpoint are a jump, whichever shards they came
//! from), and it tracks few paths (those that failed or jumped).

use super::{
    HomotopyError, PathEnd, SolveReport, SolveSettings, StartSystem, check, finish_solve,
    first_ends, start_paths,
};
use crate::poly::System;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// Shard `index` (1-based) of `count`: the paths `k` with `k mod count = index − 1`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    /// Which shard, `1 ≤ index ≤ count`.
    pub index: usize,
    /// How many shards.
    pub count: usize,
}

impl Shard {
    /// Shard `index` of `count`; `None` unless `1 ≤ index ≤ count`.
    #[must_use]
    pub fn new(index: usize, count: usize) -> Option<Self> {
        (index >= 1 && index <= count).then_some(Self { index, count })
    }

    /// Whether path `k` is this shard's.
    #[must_use]
    pub fn holds(&self, k: usize) -> bool {
        k % self.count == self.index - 1
    }
}

/// The paths of one shard, tracked once: what [`merge_shards`] combines.
#[derive(Debug, Clone, PartialEq)]
pub struct ShardEnds {
    /// The shard.
    pub shard: Shard,
    /// The start system tracked (resolved: never [`StartSystem::Auto`]).
    pub start: StartSystem,
    /// The seed.
    pub seed: u64,
    /// The paths of the whole solve.
    pub paths: usize,
    /// The ends of the shard's paths, in path order.
    pub ends: Vec<PathEnd>,
    /// Wall seconds of the shard.
    pub seconds: f64,
}

/// Tracks the paths of `shard` of the solve of `system` with `settings` ([`super::solve`]), once
/// each: the limit of paths ([`SolveSettings::max_paths`]) applies to the shard's share.
///
/// # Errors
/// As [`super::solve`] before it tracks (the start system resolved the same way in every
/// shard: from the system and the seed alone).
pub fn solve_shard(
    system: &System,
    settings: &SolveSettings,
    shard: Shard,
    progress: &(dyn Fn() + Sync),
) -> Result<ShardEnds, HomotopyError> {
    let clock = std::time::Instant::now();
    let count = u128::try_from(shard.count).unwrap_or(u128::MAX);
    let (start, _) = check(system, settings, count)?;
    let settings = &SolveSettings {
        start,
        ..settings.clone()
    };
    let mut rng = ChaCha8Rng::seed_from_u64(settings.seed);
    let (homotopy, starts, _) = start_paths(system, settings, &mut rng)?;
    let ends = first_ends(&homotopy, &starts, settings, |k| shard.holds(k), progress);
    Ok(ShardEnds {
        shard,
        start,
        seed: settings.seed,
        paths: starts.len(),
        ends,
        seconds: clock.elapsed().as_secs_f64(),
    })
}

/// The solve of `system` with `settings` from the first ends of its shards (any order; each
/// shard `1 … N` once): the ends put in path order, then the re-tracking, the distinct
/// solutions and the certificates as in [`super::solve`] — the same report as one process.
/// [`SolveReport::seconds`] is the merge's time plus the slowest shard's.
///
/// # Errors
/// [`HomotopyError::Shards`] when the shards do not make one solve of this system (another
/// count, start system, seed or number of paths; a shard missing or repeated; a path missing,
/// repeated or in the wrong shard); else as [`super::solve`] before it tracks.
pub fn merge_shards(
    system: &System,
    settings: &SolveSettings,
    shards: &[ShardEnds],
) -> Result<SolveReport, HomotopyError> {
    let clock = std::time::Instant::now();
    let first = shards
        .first()
        .ok_or_else(|| HomotopyError::Shards("no shard given".into()))?;
    let count = first.shard.count;
    let (start, _) = check(system, settings, u128::try_from(count).unwrap_or(u128::MAX))?;
    let refuse = |why: String| Err(HomotopyError::Shards(why));
    let mut seen = vec![false; count];
    for s in shards {
        if s.shard.count != count {
            return refuse(format!(
                "shard {}/{} beside shards of {count}",
                s.shard.index, s.shard.count
            ));
        }
        if s.start != start || s.seed != settings.seed {
            return refuse(format!(
                "shard {}/{count} was run with the {} start system and seed {}, this solve has the {} start system and seed {}",
                s.shard.index,
                s.start.name(),
                s.seed,
                start.name(),
                settings.seed
            ));
        }
        if std::mem::replace(&mut seen[s.shard.index - 1], true) {
            return refuse(format!("shard {}/{count} given twice", s.shard.index));
        }
    }
    let missing: Vec<String> = (1..=count)
        .filter(|k| !seen[k - 1])
        .map(|k| format!("{k}/{count}"))
        .collect();
    if !missing.is_empty() {
        return refuse(format!("missing shard {}", missing.join(", ")));
    }
    let settings = &SolveSettings {
        start,
        ..settings.clone()
    };
    let mut rng = ChaCha8Rng::seed_from_u64(settings.seed);
    let (homotopy, starts, _) = start_paths(system, settings, &mut rng)?;
    let mut ends: Vec<Option<PathEnd>> = vec![None; starts.len()];
    for s in shards {
        if s.paths != starts.len() {
            return refuse(format!(
                "shard {}/{count} has {} paths, this solve {}",
                s.shard.index,
                s.paths,
                starts.len()
            ));
        }
        for e in &s.ends {
            let k = e.path;
            if k >= starts.len() || !s.shard.holds(k) || ends[k].is_some() {
                return refuse(format!(
                    "path {k} does not belong to shard {}/{count} or is repeated",
                    s.shard.index
                ));
            }
            ends[k] = Some(e.clone());
        }
    }
    let ends: Vec<PathEnd> = match ends.into_iter().collect::<Option<Vec<_>>>() {
        Some(ends) => ends,
        None => return refuse("a shard lacks some of its paths".into()),
    };
    let slowest = shards.iter().map(|s| s.seconds).fold(0.0, f64::max);
    Ok(finish_solve(
        system,
        settings,
        (&homotopy, &starts),
        ends,
        slowest + clock.elapsed().as_secs_f64(),
    ))
}
