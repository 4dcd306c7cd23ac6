//! The rules of paper 000 §2, one function each, over a P/R word with an axis direction per
//! joint.
//!
//! Rule 1 puts every axis along one of three mutually perpendicular directions at the reference
//! configuration (`0`, `1`, `2`, printed `x`, `y`, `z`); consecutive axes are then parallel or
//! perpendicular by construction. The other rules decide which assignments are admissible and
//! how an admissible one is read in C/U/S letters.

use crate::notation::{Axis, AxisWord, Chain, Joint, JointKind, Mark, Primitive};

/// An axis direction at the reference configuration by its position 0, 1 or 2 in x, y, z
/// ([`Axis::index`]): the enumeration counts directions and relabels them, so it works on
/// positions, and [`axis_word`] names them.
pub type AxisIndex = u8;

/// The same directions relabelled so that the first joint lies along x and the next new
/// direction along y: relabelling the three directions changes no chain.
#[must_use]
pub fn canonical_axes(axes: &[AxisIndex]) -> Vec<AxisIndex> {
    let mut map = [u8::MAX; 3];
    let mut next = 0;
    axes.iter()
        .map(|&a| {
            if map[a as usize] == u8::MAX {
                map[a as usize] = next;
                next += 1;
            }
            map[a as usize]
        })
        .collect()
}

/// Names axis directions as a word such as `xyzxyz`.
///
/// # Panics
/// If a position is not 0, 1 or 2 (no rule produces one).
#[must_use]
pub fn axis_word(axes: &[AxisIndex]) -> AxisWord {
    axes.iter()
        .map(|&a| Axis::from_index(usize::from(a)).expect("directions are 0, 1 or 2"))
        .collect()
}

/// Every sequence of `n` revolute directions whose direction counts, largest first, are
/// `counts`, written canonically (the first direction used is x, the next new one y, then z),
/// in lexicographic order.
///
/// These are the permutations of §2.1–§2.4: "Any other combination with less number of R
/// joints with parallel axes is obtained by carrying out the permutations of the two cited
/// sequences". Relabelling the three directions changes no chain, so only canonical sequences
/// are kept.
#[must_use]
pub fn revolute_patterns(n: usize, counts: [u8; 3]) -> Vec<Vec<AxisIndex>> {
    fn rec(n: usize, counts: [u8; 3], seq: &mut Vec<AxisIndex>, out: &mut Vec<Vec<AxisIndex>>) {
        if seq.len() == n {
            let mut c = [0u8; 3];
            for &a in seq.iter() {
                c[a as usize] += 1;
            }
            c.sort_unstable_by(|a, b| b.cmp(a));
            if c == counts {
                out.push(seq.clone());
            }
            return;
        }
        let next_new = seq.iter().copied().max().map_or(0, |m| m + 1);
        for a in 0..=next_new.min(2) {
            seq.push(a);
            rec(n, counts, seq, out);
            seq.pop();
        }
    }
    let mut out = Vec::new();
    let mut seq = Vec::with_capacity(n);
    rec(n, counts, &mut seq, &mut out);
    out
}

/// The groups of parallel revolutes that stay parallel in motion, as lists of 0-based joint
/// positions, in order of first member.
///
/// Rule 4 marks "those set of R joints, in which their axes are parallel"; §2.3 adds that the
/// parallelism must survive motion: "the R joints will not maintain their parallelism when the
/// intermediate R starts to rotate, thus RRR = RRR". A prismatic joint rotates nothing, so two
/// revolutes with the same direction stay parallel exactly when every revolute between them
/// has that direction too: groups are the runs of equal direction in the sequence of revolutes.
#[must_use]
pub fn parallel_groups(word: &[Primitive], axes: &[AxisIndex]) -> Vec<Vec<usize>> {
    let revolutes: Vec<usize> = (0..word.len())
        .filter(|&i| word[i] == Primitive::R)
        .collect();
    let mut groups = Vec::new();
    let mut k = 0;
    while k < revolutes.len() {
        let mut end = k + 1;
        while end < revolutes.len() && axes[revolutes[end]] == axes[revolutes[k]] {
            end += 1;
        }
        if end - k >= 2 {
            groups.push(revolutes[k..end].to_vec());
        }
        k = end;
    }
    groups
}

/// Two prismatic joints whose guides stay parallel in motion: their translations are one and
/// the same, and the chain wastes a degree of freedom. Returns the first such pair.
///
/// §2: "the maximum number of translational joints in each chain will be three, so that
/// positioning them along the three directions in space the 3 translational dof can be
/// obtained"; §2.2: "the guides of the two prismatics have to be perpendicular". Two guides
/// stay parallel when they have the same direction and nothing between them turns one away
/// from the other, i.e. every revolute between them (if any) is parallel to them too.
/// With [`PrismaticReading::Perpendicular`] any two parallel guides are rejected.
#[must_use]
pub fn parallel_guides(
    word: &[Primitive],
    axes: &[AxisIndex],
    reading: PrismaticReading,
) -> Option<(usize, usize)> {
    let prismatics: Vec<usize> = (0..word.len())
        .filter(|&i| word[i] == Primitive::P)
        .collect();
    for (k, &i) in prismatics.iter().enumerate() {
        for &j in &prismatics[k + 1..] {
            if axes[i] != axes[j] {
                continue;
            }
            let turned = (i + 1..j).any(|m| word[m] == Primitive::R && axes[m] != axes[i]);
            if !turned || reading == PrismaticReading::Perpendicular {
                return Some((i, j));
            }
        }
    }
    None
}

/// How far apart two prismatic guides of one chain may be (§2 admits two readings).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize, serde::Deserialize)]
pub enum PrismaticReading {
    /// Default. Parallel guides are allowed when a revolute not parallel to them lies between
    /// them, so that they do not stay parallel in motion. Table 1 needs this reading: it prints
    /// CCPR for PRPRPR, whose third guide can only be parallel to the first.
    #[default]
    Separated,
    /// Every two guides perpendicular, as "positioning them along the three directions in
    /// space" suggests; Table 1 then loses CCPR and comes out below 63.
    Perpendicular,
}

/// A group of three parallel revolutes with no prismatic guide parallel to it.
///
/// §2.3, first bullet: "Three parallel revolute joints ... The combination of any of the
/// parallel R pairs with the prismatic will always yield a cylindrical joint. Otherwise, the
/// three translations would not be achieved." Three parallel revolutes translate only in the
/// plane normal to their axis, so the one guide must lie along the axis.
///
/// The bullet speaks of the PRRRRR family; a chain without prismatic joints (the 6R family of
/// §2.4, whose Table 6 pattern keeps three parallel R beside a parallel pair) is not subject
/// to it: its third translation comes from the other revolutes.
#[must_use]
pub fn triple_group_without_guide(word: &[Primitive], axes: &[AxisIndex]) -> bool {
    word.contains(&Primitive::P)
        && parallel_groups(word, axes)
            .iter()
            .filter(|g| g.len() >= 3)
            .any(|g| !(0..word.len()).any(|i| word[i] == Primitive::P && axes[i] == axes[g[0]]))
}

/// The options of the paper reading: where the text of §2 admits two readings.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Options {
    /// Whether non-consecutive prismatic guides may be parallel.
    pub prismatics: PrismaticReading,
    /// Whether the §2.3 rule "a group of three parallel R needs a parallel guide" is applied
    /// (default: yes, as the text states; the printed Table 3 breaks it, see docs/deviations.md).
    pub triple_group_needs_guide: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            prismatics: PrismaticReading::Separated,
            triple_group_needs_guide: true,
        }
    }
}

/// Which admissibility rule an axis assignment breaks, if any.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub enum Violation {
    /// Two guides stay parallel (see [`parallel_guides`]).
    ParallelGuides,
    /// A group of three parallel R without a guide along it (see [`triple_group_without_guide`]).
    TripleGroupWithoutGuide,
}

impl Violation {
    /// A short name that cites the rule.
    #[must_use]
    pub fn describe(self) -> &'static str {
        match self {
            Violation::ParallelGuides => {
                "two prismatic guides stay parallel (§2: three translations need three guide directions)"
            }
            Violation::TripleGroupWithoutGuide => {
                "three parallel R with no guide along them (§2.3, first bullet)"
            }
        }
    }
}

/// The admissibility rules an axis assignment breaks under `options` (empty: admissible).
#[must_use]
pub fn violations(word: &[Primitive], axes: &[AxisIndex], options: &Options) -> Vec<Violation> {
    let mut v = Vec::new();
    if parallel_guides(word, axes, options.prismatics).is_some() {
        v.push(Violation::ParallelGuides);
    }
    if options.triple_group_needs_guide && triple_group_without_guide(word, axes) {
        v.push(Violation::TripleGroupWithoutGuide);
    }
    v
}

/// Every way of pairing consecutive parallel P and R joints into cylindrical joints: the
/// maximal sets of disjoint pairs, as (first, second) positions.
///
/// Rule 2: "In the case of a P joint and a R joint being parallel and consecutive (or a R and a
/// P), the distance between the axis of the revolute joint and the slider guide will be
/// considered null. Then, this PR (or RP) results in a cylindrical joint." A parallel pair is
/// always merged; when a joint has a parallel partner on both sides, either pairing is a
/// candidate.
#[must_use]
pub fn cylindrical_pairings(word: &[Primitive], axes: &[AxisIndex]) -> Vec<Vec<(usize, usize)>> {
    let edges: Vec<(usize, usize)> = (0..word.len().saturating_sub(1))
        .filter(|&i| word[i] != word[i + 1] && axes[i] == axes[i + 1])
        .map(|i| (i, i + 1))
        .collect();
    let mut out = Vec::new();
    for mask in 0u32..(1 << edges.len()) {
        let chosen: Vec<(usize, usize)> = (0..edges.len())
            .filter(|k| mask & (1 << k) != 0)
            .map(|k| edges[k])
            .collect();
        let used = |i: usize| chosen.iter().any(|&(a, b)| a == i || b == i);
        let disjoint = chosen.windows(2).all(|w| w[0].1 != w[1].0);
        let maximal = edges.iter().all(|&(a, b)| used(a) || used(b));
        if disjoint && maximal {
            out.push(chosen);
        }
    }
    out
}

/// The ways of reading a run of consecutive revolutes (not in a C) as R, U and S joints: block
/// sizes 1, 2 or 3, base to platform.
///
/// Rule 3: "If the axes of two R joints are consecutive and non-parallel, then the distance
/// must be null. For example, the sequence RR forms a universal joint and the sequence RRR a
/// spherical joint." A U needs two perpendicular axes, an S three mutually perpendicular ones;
/// the fewest joints are used, and every such reading is a candidate (RRRR → RS, SR or UU).
/// "Particular exceptions such as the SS kinematic chain, with 5 dof in the end-effector and
/// one idle dof, are solved by including a non-null distance resulting in chains SUR, URS,
/// RUS, ..., instead of SS chain": where the fewest would be SS, the readings with one joint
/// more are taken instead.
#[must_use]
pub fn revolute_groupings(axes: &[AxisIndex]) -> Vec<Vec<usize>> {
    let all = all_revolute_groupings(axes);
    let Some(fewest) = all.iter().map(Vec::len).min() else {
        return vec![Vec::new()];
    };
    let spherical_pair = |g: &Vec<usize>| g.len() == 2 && g.iter().all(|&s| s == 3);
    let target = if all.iter().any(|g| g.len() == fewest && spherical_pair(g)) {
        fewest + 1
    } else {
        fewest
    };
    all.into_iter()
        .filter(|g| g.len() == target && !spherical_pair(g))
        .collect()
}

/// Every way of reading a run of revolutes as R, U and S joints (perpendicular axes in a U,
/// mutually perpendicular in an S), not only the fewest: what rule 3 chooses from.
#[must_use]
pub fn all_revolute_groupings(axes: &[AxisIndex]) -> Vec<Vec<usize>> {
    fn rec(axes: &[AxisIndex], at: usize, cur: &mut Vec<usize>, out: &mut Vec<Vec<usize>>) {
        if at == axes.len() {
            out.push(cur.clone());
            return;
        }
        for size in 1..=3 {
            if at + size > axes.len() {
                break;
            }
            let block = &axes[at..at + size];
            let ok = match size {
                1 => true,
                2 => block[0] != block[1],
                _ => block[0] != block[1] && block[1] != block[2] && block[0] != block[2],
            };
            if ok {
                cur.push(size);
                rec(axes, at + size, cur, out);
                cur.pop();
            }
        }
    }
    let mut all = Vec::new();
    rec(axes, 0, &mut Vec::new(), &mut all);
    all
}

/// Which U/S readings of a run of revolutes [`readings`] takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Grouping {
    /// Rule 3: the fewest joints, with the SS exception ([`revolute_groupings`]).
    Fewest,
    /// Every reading ([`all_revolute_groupings`]); used to explain printed chains.
    Any,
}

/// Every C/U/S reading of an axis assignment under rules 2 and 3, with the parallel groups
/// marked.
#[must_use]
pub fn readings(word: &[Primitive], axes: &[AxisIndex]) -> Vec<Chain> {
    readings_with(word, axes, Grouping::Fewest)
}

/// Every C/U/S reading of an axis assignment, the revolutes grouped as `grouping` says.
#[must_use]
pub fn readings_with(word: &[Primitive], axes: &[AxisIndex], grouping: Grouping) -> Vec<Chain> {
    let groups = parallel_groups(word, axes);
    #[expect(
        clippy::cast_possible_truncation,
        reason = "a parallel group holds at least two of the word's revolutes, so a six-joint \
                  word of the tables has at most three (the notation's a, b, c)"
    )]
    let mark = |i: usize| Mark {
        group: groups.iter().position(|g| g.contains(&i)).map(|g| g as u8),
        actuated: false,
    };
    let mut out = Vec::new();
    for pairing in cylindrical_pairings(word, axes) {
        let paired = |i: usize| pairing.iter().any(|&(a, b)| a == i || b == i);
        // Pieces: Err(run of free revolutes) or Ok(a finished joint).
        let mut pieces: Vec<Result<Joint, Vec<usize>>> = Vec::new();
        let mut i = 0;
        while i < word.len() {
            if let Some(&(a, b)) = pairing.iter().find(|&&(a, _)| a == i) {
                let (p, r) = if word[a] == Primitive::P {
                    (a, b)
                } else {
                    (b, a)
                };
                pieces.push(Ok(Joint {
                    kind: JointKind::C,
                    marks: vec![mark(p), mark(r)],
                }));
                i = b + 1;
            } else if word[i] == Primitive::P {
                pieces.push(Ok(Joint {
                    kind: JointKind::P,
                    marks: vec![mark(i)],
                }));
                i += 1;
            } else {
                let start = i;
                while i < word.len() && word[i] == Primitive::R && !paired(i) {
                    i += 1;
                }
                pieces.push(Err((start..i).collect()));
            }
        }
        let mut partial: Vec<Vec<Joint>> = vec![Vec::new()];
        for piece in pieces {
            match piece {
                Ok(joint) => partial.iter_mut().for_each(|p| p.push(joint.clone())),
                Err(run) => {
                    let run_axes: Vec<AxisIndex> = run.iter().map(|&k| axes[k]).collect();
                    let mut next = Vec::new();
                    for prefix in &partial {
                        let blocks_list = match grouping {
                            Grouping::Fewest => revolute_groupings(&run_axes),
                            Grouping::Any => all_revolute_groupings(&run_axes),
                        };
                        for blocks in blocks_list {
                            let mut p = prefix.clone();
                            let mut at = 0;
                            for size in blocks {
                                let kind = [JointKind::R, JointKind::U, JointKind::S][size - 1];
                                p.push(Joint {
                                    kind,
                                    marks: run[at..at + size].iter().map(|&k| mark(k)).collect(),
                                });
                                at += size;
                            }
                            next.push(p);
                        }
                    }
                    partial = next;
                }
            }
        }
        out.extend(partial.into_iter().map(Chain::from_joints));
    }
    out
}
