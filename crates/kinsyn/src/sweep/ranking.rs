//! Ranking the designs of a sweep by multioperation capacity (paper 000 §1: the more kinds of
//! displacement group the platform reaches by locking inputs, the more useful the manipulator)
//! against their cost in actuators.
//!
//! A design's **capacity** is the pair (group kinds reached, distinct subgroups reached),
//! compared lexicographically: kinds first, subgroups break ties. One design **dominates**
//! another when it has no more inputs and no less capacity, and is better in one of the two.
//! The **Pareto front** is the set of designs no other dominates: for each number of inputs,
//! the designs of the largest capacity there, kept only when that capacity beats every design
//! with fewer inputs.
//!
//! Designs that could not be built (a row with an `error`) take no part in the ranking and are
//! listed apart; designs with unsampled lock subsets are ranked on what was sampled (their
//! capacity is then a lower bound) and listed apart too. Every list is sorted with explicit
//! tie-breaks, so a ranking depends on the set of rows only, not on their order.

use super::DesignRow;
use serde::Serialize;
use std::cmp::Ordering;
use std::collections::BTreeMap;

/// A design's capacity as compared in the ranking: (group kinds, distinct subgroups).
#[must_use]
pub fn capacity(row: &DesignRow) -> (usize, usize) {
    (row.kinds, row.subgroups)
}

/// Whether design `a` dominates design `b`: no more inputs, no less capacity, and strictly
/// better in one of the two.
#[must_use]
pub fn dominates(a: &DesignRow, b: &DesignRow) -> bool {
    let (ca, cb) = (capacity(a), capacity(b));
    a.inputs <= b.inputs && ca >= cb && (a.inputs < b.inputs || ca > cb)
}

/// The order of the best designs: more kinds, then more subgroups, then fewer inputs, then the
/// lower design index.
fn best_first(a: &DesignRow, b: &DesignRow) -> Ordering {
    b.kinds
        .cmp(&a.kinds)
        .then(b.subgroups.cmp(&a.subgroups))
        .then(a.inputs.cmp(&b.inputs))
        .then(a.design.cmp(&b.design))
}

/// The designs of `rows` that were built (no `error`).
fn built(rows: &[DesignRow]) -> impl Iterator<Item = &DesignRow> {
    rows.iter().filter(|r| r.error.is_none())
}

/// The Pareto front of capacity against inputs among the built designs of `rows`: the designs
/// no other built design dominates, by increasing inputs, then as [`top_per_inputs`] orders
/// them. Designs of equal inputs and capacity are all kept.
#[must_use]
pub fn pareto_front(rows: &[DesignRow]) -> Vec<&DesignRow> {
    let mut best: BTreeMap<usize, (usize, usize)> = BTreeMap::new();
    for r in built(rows) {
        let entry = best.entry(r.inputs).or_insert((0, 0));
        *entry = (*entry).max(capacity(r));
    }
    // The inputs counts whose best capacity beats that of every smaller count.
    let mut front_capacity: BTreeMap<usize, (usize, usize)> = BTreeMap::new();
    let mut beaten: Option<(usize, usize)> = None;
    for (&inputs, &c) in &best {
        if beaten.is_none_or(|b| c > b) {
            front_capacity.insert(inputs, c);
            beaten = Some(c);
        }
    }
    let mut front: Vec<&DesignRow> = built(rows)
        .filter(|r| front_capacity.get(&r.inputs) == Some(&capacity(r)))
        .collect();
    front.sort_by(|a, b| a.inputs.cmp(&b.inputs).then(best_first(a, b)));
    front
}

/// The best `k` built designs for each number of inputs, by increasing inputs: most group
/// kinds, then most subgroups, then the lower design index.
#[must_use]
pub fn top_per_inputs(rows: &[DesignRow], k: usize) -> Vec<(usize, Vec<&DesignRow>)> {
    let mut by_inputs: BTreeMap<usize, Vec<&DesignRow>> = BTreeMap::new();
    for r in built(rows) {
        by_inputs.entry(r.inputs).or_default().push(r);
    }
    by_inputs
        .into_iter()
        .map(|(inputs, mut designs)| {
            designs.sort_by(|a, b| best_first(a, b));
            designs.truncate(k);
            (inputs, designs)
        })
        .collect()
}

/// A kind of displacement group a design reaches, with the subgroup of that kind reached with
/// the fewest locked inputs and that lock set.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct KindLock {
    /// The kind (`X`, `T3`, `S`, ...).
    pub kind: String,
    /// The subgroup reached (`X([0.447,-0.775,-0.447])`), with its parameters when it has any.
    pub pattern: String,
    /// The platform's degrees of freedom in it.
    pub dof: usize,
    /// A minimal lock set giving it (input labels, space separated; `-` for none): of all the
    /// minimal lock sets of the kind's subgroups, one with the fewest inputs, the first in text
    /// order among those.
    pub lock_set: String,
}

/// The kind of a subgroup's pattern name: the name without its parameters (`X(z)` → `X`).
#[must_use]
pub fn kind_of(pattern: &str) -> &str {
    pattern.split('(').next().unwrap_or(pattern)
}

/// The inputs a lock set names (`-` names none).
fn lock_count(set: &str) -> usize {
    if set == "-" {
        0
    } else {
        set.split_whitespace().count()
    }
}

/// For each group kind `row` reaches, in the row's order of kinds, a subgroup of that kind and a
/// minimal lock set that reaches it with the fewest inputs locked.
#[must_use]
pub fn kind_locks(row: &DesignRow) -> Vec<KindLock> {
    row.group_kinds
        .iter()
        .filter_map(|kind| {
            row.groups
                .iter()
                .filter(|g| kind_of(&g.pattern) == kind)
                .flat_map(|g| g.lock_sets.iter().map(move |s| (g, s)))
                .min_by(|(ga, a), (gb, b)| {
                    lock_count(a)
                        .cmp(&lock_count(b))
                        .then(a.cmp(b))
                        .then(ga.pattern.cmp(&gb.pattern))
                })
                .map(|(g, s)| KindLock {
                    kind: kind.clone(),
                    pattern: match &g.parameters {
                        Some(p) => format!("{} {p}", g.pattern),
                        None => g.pattern.clone(),
                    },
                    dof: g.dof,
                    lock_set: s.clone(),
                })
        })
        .collect()
}

/// A design as the ranking shows it.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct RankedDesign {
    /// The design's index in the sweep.
    pub design: usize,
    /// The leg chain's catalogue id.
    pub chain: String,
    /// The leg chain's notation.
    pub notation: String,
    /// The leg chain's family.
    pub family: String,
    /// Legs.
    pub legs: usize,
    /// The actuated primitive joints of each leg, 1-based.
    pub actuated: Vec<usize>,
    /// The manipulator's inputs.
    pub inputs: usize,
    /// The platform's degrees of freedom with no input locked.
    pub dof: usize,
    /// Group kinds reached.
    pub kinds: usize,
    /// Distinct subgroups reached.
    pub subgroups: usize,
    /// Each kind reached with a lock set giving it ([`kind_locks`]).
    pub kind_locks: Vec<KindLock>,
    /// Lock subsets that could not be sampled (the capacity is a lower bound when not 0).
    pub unsampled: usize,
}

impl From<&DesignRow> for RankedDesign {
    fn from(r: &DesignRow) -> Self {
        RankedDesign {
            design: r.design,
            chain: r.chain.clone(),
            notation: r.notation.clone(),
            family: r.family.clone(),
            legs: r.legs,
            actuated: r.actuated.clone(),
            inputs: r.inputs,
            dof: r.dof,
            kinds: r.kinds,
            subgroups: r.subgroups,
            kind_locks: kind_locks(r),
            unsampled: r.unsampled,
        }
    }
}

/// The best designs for one number of inputs.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct InputsTop {
    /// The number of inputs.
    pub inputs: usize,
    /// How many built designs have that many inputs.
    pub designs: usize,
    /// The best of them, best first ([`top_per_inputs`]).
    pub top: Vec<RankedDesign>,
}

/// A leg chain used by the designs of the front or of the top lists.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct LegUse {
    /// The chain's catalogue id.
    pub chain: String,
    /// Its notation.
    pub notation: String,
    /// Its family.
    pub family: String,
    /// How many designs of the top lists use it.
    pub top_designs: usize,
    /// How many designs of the Pareto front use it.
    pub front_designs: usize,
}

/// The capacity of the built designs of one family.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FamilyCapacity {
    /// The family (the chain's primitive joints in order, `PPRRPR`).
    pub family: String,
    /// Built designs of the family.
    pub designs: usize,
    /// Mean group kinds over them.
    pub mean_kinds: f64,
    /// Most group kinds among them.
    pub max_kinds: usize,
}

/// A design that could not be built.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Failed {
    /// The design's index.
    pub design: usize,
    /// The leg chain's catalogue id.
    pub chain: String,
    /// The actuated joints of each leg.
    pub actuated: Vec<usize>,
    /// Why it could not be built.
    pub error: String,
}

/// A design some of whose lock subsets could not be sampled.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Unsampled {
    /// The design's index.
    pub design: usize,
    /// The leg chain's catalogue id.
    pub chain: String,
    /// The actuated joints of each leg.
    pub actuated: Vec<usize>,
    /// How many lock subsets were not sampled.
    pub unsampled: usize,
}

/// The ranking of a sweep's rows.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Ranking {
    /// Rows ranked (designs read).
    pub designs: usize,
    /// Of them, designs built (ranked).
    pub built: usize,
    /// The number of best designs kept per number of inputs.
    pub top_k: usize,
    /// The Pareto front ([`pareto_front`]).
    pub front: Vec<RankedDesign>,
    /// The best designs per number of inputs ([`top_per_inputs`]).
    pub top: Vec<InputsTop>,
    /// The leg chains of the front and the top lists: most top designs first, then most front
    /// designs, then by catalogue id.
    pub legs: Vec<LegUse>,
    /// Capacity per family, by family name.
    pub families: Vec<FamilyCapacity>,
    /// `histogram[k]`: built designs reaching exactly `k` group kinds, `k` from 0 to the most.
    pub histogram: Vec<usize>,
    /// Designs that could not be built, by index.
    pub failed: Vec<Failed>,
    /// Designs with unsampled lock subsets, by index.
    pub unsampled: Vec<Unsampled>,
    /// Built designs with lock subsets that start at a singular configuration
    /// ([`crate::motion::SingularStart`]), and those subsets in all: not counted in any
    /// capacity, so these designs' capacity is what their regular starts reach.
    pub singular: (usize, usize),
}

impl Ranking {
    /// The ranking of `rows` with the best `top_k` designs per number of inputs.
    #[must_use]
    pub fn new(rows: &[DesignRow], top_k: usize) -> Self {
        let front: Vec<RankedDesign> = pareto_front(rows)
            .into_iter()
            .map(RankedDesign::from)
            .collect();
        let mut count_per_inputs: BTreeMap<usize, usize> = BTreeMap::new();
        for r in built(rows) {
            *count_per_inputs.entry(r.inputs).or_default() += 1;
        }
        let top: Vec<InputsTop> = top_per_inputs(rows, top_k)
            .into_iter()
            .map(|(inputs, designs)| InputsTop {
                inputs,
                designs: count_per_inputs[&inputs],
                top: designs.into_iter().map(RankedDesign::from).collect(),
            })
            .collect();
        Ranking {
            designs: rows.len(),
            built: built(rows).count(),
            top_k,
            legs: leg_uses(&front, &top),
            front,
            top,
            families: families(rows),
            histogram: histogram(rows),
            failed: rows
                .iter()
                .filter_map(|r| {
                    r.error.as_ref().map(|e| Failed {
                        design: r.design,
                        chain: r.chain.clone(),
                        actuated: r.actuated.clone(),
                        error: e.clone(),
                    })
                })
                .sorted_by_design(),
            unsampled: built(rows)
                .filter(|r| r.unsampled > 0)
                .map(|r| Unsampled {
                    design: r.design,
                    chain: r.chain.clone(),
                    actuated: r.actuated.clone(),
                    unsampled: r.unsampled,
                })
                .sorted_by_design(),
            singular: (
                built(rows).filter(|r| r.singular > 0).count(),
                built(rows).map(|r| r.singular).sum(),
            ),
        }
    }
}

/// Collecting into a list sorted by design index.
trait SortedByDesign<T> {
    fn sorted_by_design(self) -> Vec<T>;
}

impl<I: Iterator<Item = Failed>> SortedByDesign<Failed> for I {
    fn sorted_by_design(self) -> Vec<Failed> {
        let mut v: Vec<Failed> = self.collect();
        v.sort_by_key(|f| f.design);
        v
    }
}

impl<I: Iterator<Item = Unsampled>> SortedByDesign<Unsampled> for I {
    fn sorted_by_design(self) -> Vec<Unsampled> {
        let mut v: Vec<Unsampled> = self.collect();
        v.sort_by_key(|f| f.design);
        v
    }
}

/// The leg chains of the front and top lists with how often each is used.
fn leg_uses(front: &[RankedDesign], top: &[InputsTop]) -> Vec<LegUse> {
    let mut uses: BTreeMap<String, LegUse> = BTreeMap::new();
    let designs = top
        .iter()
        .flat_map(|t| &t.top)
        .map(|d| (d, true))
        .chain(front.iter().map(|d| (d, false)));
    for (d, in_top) in designs {
        let e = uses.entry(d.chain.clone()).or_insert_with(|| LegUse {
            chain: d.chain.clone(),
            notation: d.notation.clone(),
            family: d.family.clone(),
            top_designs: 0,
            front_designs: 0,
        });
        if in_top {
            e.top_designs += 1;
        } else {
            e.front_designs += 1;
        }
    }
    let mut out: Vec<LegUse> = uses.into_values().collect();
    out.sort_by(|a, b| {
        b.top_designs
            .cmp(&a.top_designs)
            .then(b.front_designs.cmp(&a.front_designs))
            .then(a.chain.cmp(&b.chain))
    });
    out
}

/// Mean and most group kinds of the built designs of each family, by family name.
fn families(rows: &[DesignRow]) -> Vec<FamilyCapacity> {
    let mut by_family: BTreeMap<&str, (usize, usize, usize)> = BTreeMap::new();
    for r in built(rows) {
        let e = by_family.entry(r.family.as_str()).or_insert((0, 0, 0));
        e.0 += 1;
        e.1 += r.kinds;
        e.2 = e.2.max(r.kinds);
    }
    by_family
        .into_iter()
        .map(|(family, (designs, sum, max))| FamilyCapacity {
            family: family.to_string(),
            designs,
            #[allow(
                clippy::cast_precision_loss,
                reason = "counts of designs and kinds, far below 2^52"
            )]
            mean_kinds: sum as f64 / designs as f64,
            max_kinds: max,
        })
        .collect()
}

/// Built designs per number of group kinds reached, from 0 to the most.
fn histogram(rows: &[DesignRow]) -> Vec<usize> {
    let most = built(rows).map(|r| r.kinds).max();
    let mut h = vec![0; most.map_or(0, |m| m + 1)];
    for r in built(rows) {
        h[r.kinds] += 1;
    }
    h
}
