//! Design rows read back: the JSON lines of a sweep's `designs.jsonl` and of a run's
//! checkpoint, each parsed and checked against the designs it may be, so that an edited or
//! damaged row is refused with its line instead of reaching a resumed run, a merge or a
//! ranking. Every reader of rows goes through [`Known::parse_rows`].
//!
//! A row is accepted when
//!
//! - it is a design of the sweep ([`Known::sweep`]: the same index, chain, notation, family,
//!   actuated joints and legs) or, read without its sweep's manifest ([`Known::catalogue`]),
//!   a design over a verified catalogue chain (its notation and family the catalogue's,
//!   actuated joints increasing within the leg's six, 3 to 6 legs);
//! - its fields agree: inputs = legs × actuated joints per leg (at most [`MAX_INPUTS`]); dof
//!   at most 6; every pattern a name kinsyn writes (`X(z)`, `T([0.485,-0.840,0.243])`,
//!   `2T1R`), a group in `groups` and a non-group in `non_groups`, each once with its
//!   parameters (parallel subgroups through other points share a name), its dof the
//!   pattern's dimension, parameters only for R, H, C, S and Y; `group_kinds` the kinds of
//!   `groups` in the order of the 12, `kinds` and `subgroups` their counts; every lock set `-`
//!   or labels of the design's inputs (`R1.3 P1.4`) in input order, at most as many as the
//!   subsets counted; the subsets of the patterns, the unsampled and the singular ones adding
//!   up to the 2^inputs lock subsets; a row with an `error` counting nothing.

use super::{Design, DesignRow, LEGS, Reached};
use crate::catalogue::{Catalogue, Entry};
use crate::manipulator::MAX_INPUTS;
use crate::motion::{GroupKind, PatternName};
use crate::notation::{Chain, MAX_PRIMITIVES};
use std::collections::{HashMap, HashSet};

/// Why a line is not a row of the designs known.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum RowFault {
    /// Not JSON, or JSON that is not a design row: a field missing, unknown or of the wrong type.
    #[error("not a design row of kinsyn sweep ({0})")]
    NotARow(String),
    /// The design of an earlier line.
    #[error("design {design} is already on line {first}")]
    Repeated {
        /// The design index.
        design: usize,
        /// The line that holds it first (1-based).
        first: usize,
    },
    /// A design that is not one of those known.
    #[error("design {design} ({chain:?} actuated {actuated:?}, {legs} legs) is not {known}: {why}")]
    Unknown {
        /// The design index.
        design: usize,
        /// The row's chain id.
        chain: String,
        /// The row's actuated joints.
        actuated: Vec<usize>,
        /// The row's legs.
        legs: usize,
        /// What the designs known are, in words.
        known: &'static str,
        /// What differs.
        why: String,
    },
    /// A field that is out of range or contradicts the others.
    #[error("design {design}: {field}: {why}")]
    Field {
        /// The design index.
        design: usize,
        /// The field, as a path (`groups[2].dof`).
        field: String,
        /// What is wrong with it.
        why: String,
    },
}

/// A refused line: its number (1-based) and why.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("line {line}: {fault}")]
pub struct RowError {
    /// The line (1-based).
    pub line: usize,
    /// Why it is refused.
    pub fault: RowFault,
}

/// The designs rows may be: those of one sweep, or any over the verified catalogue chains.
#[derive(Debug, Clone)]
pub struct Known<'a> {
    designs: Designs<'a>,
}

#[derive(Debug, Clone)]
enum Designs<'a> {
    Sweep { designs: &'a [Design], legs: usize },
    Catalogue(HashMap<&'a str, &'a Entry>),
}

impl<'a> Known<'a> {
    /// The designs of one sweep or shard, by increasing index (as [`super::designs`] lists
    /// them, or a shard of that list), each built with `legs` legs: a row must be one of them.
    #[must_use]
    pub fn sweep(designs: &'a [Design], legs: usize) -> Self {
        Known {
            designs: Designs::Sweep { designs, legs },
        }
    }

    /// Any design over a verified chain of `catalogue` with 3 to 6 legs: what a row read
    /// without its sweep's manifest can be checked against (its index is then its own).
    #[must_use]
    pub fn catalogue(catalogue: &'a Catalogue) -> Self {
        Known {
            designs: Designs::Catalogue(catalogue.verified().map(|e| (e.id.as_str(), e)).collect()),
        }
    }

    /// The rows of `text`, one JSON object per line (blank lines skipped), each a design
    /// known here, each design once, in the order of the lines.
    ///
    /// # Errors
    /// The first line that is not such a row, with its number and why ([`RowFault`]).
    pub fn parse_rows(&self, text: &str) -> Result<Vec<DesignRow>, RowError> {
        let mut rows = Vec::new();
        let mut line_of: HashMap<usize, usize> = HashMap::new();
        for (i, line) in text.lines().enumerate() {
            let refuse = |fault| RowError { line: i + 1, fault };
            if line.trim().is_empty() {
                continue;
            }
            let row: DesignRow =
                serde_json::from_str(line).map_err(|e| refuse(RowFault::NotARow(e.to_string())))?;
            if let Some(&first) = line_of.get(&row.design) {
                return Err(refuse(RowFault::Repeated {
                    design: row.design,
                    first,
                }));
            }
            self.check(&row).map_err(refuse)?;
            line_of.insert(row.design, i + 1);
            rows.push(row);
        }
        Ok(rows)
    }

    /// Checks that `row` is a design known here and that its fields agree (module
    /// documentation).
    ///
    /// # Errors
    /// The first fault found.
    pub fn check(&self, row: &DesignRow) -> Result<(), RowFault> {
        self.identify(row)?;
        let field = |field: &str, why: String| RowFault::Field {
            design: row.design,
            field: field.to_string(),
            why,
        };
        if row.inputs != row.legs * row.actuated.len() {
            return Err(field(
                "inputs",
                format!(
                    "{} is not legs × actuated joints per leg ({} × {})",
                    row.inputs,
                    row.legs,
                    row.actuated.len()
                ),
            ));
        }
        if row.inputs > MAX_INPUTS {
            return Err(field(
                "inputs",
                format!("{} is more than {MAX_INPUTS}", row.inputs),
            ));
        }
        if row.dof > 6 {
            return Err(field("dof", format!("{} is more than 6", row.dof)));
        }
        let inputs = input_labels(row).map_err(|why| field("notation", why))?;
        if let Some(error) = &row.error {
            return check_failed(row, error).map_err(|(f, why)| field(f, why));
        }
        check_patterns(row, &inputs).map_err(|(f, why)| field(&f, why))
    }

    /// Checks that `row` names a design known here.
    fn identify(&self, row: &DesignRow) -> Result<(), RowFault> {
        let unknown = |known: &'static str, why: String| RowFault::Unknown {
            design: row.design,
            chain: row.chain.clone(),
            actuated: row.actuated.clone(),
            legs: row.legs,
            known,
            why,
        };
        match &self.designs {
            Designs::Sweep { designs, legs } => {
                const KNOWN: &str = "one of this sweep's designs";
                let Ok(at) = designs.binary_search_by_key(&row.design, |d| d.index) else {
                    return Err(unknown(
                        KNOWN,
                        "no design of the sweep has this index".into(),
                    ));
                };
                let d = &designs[at];
                let differs = [
                    ("chain", d.chain != row.chain, format!("{:?}", d.chain)),
                    (
                        "notation",
                        d.notation != row.notation,
                        format!("{:?}", d.notation),
                    ),
                    ("family", d.family != row.family, format!("{:?}", d.family)),
                    (
                        "actuated",
                        d.actuated != row.actuated,
                        format!("{:?}", d.actuated),
                    ),
                    ("legs", *legs != row.legs, legs.to_string()),
                ];
                match differs.into_iter().find(|(_, differ, _)| *differ) {
                    Some((name, _, wanted)) => Err(unknown(
                        KNOWN,
                        format!("design {} has {name} {wanted}", row.design),
                    )),
                    None => Ok(()),
                }
            }
            Designs::Catalogue(entries) => {
                const KNOWN: &str = "a design of the catalogue";
                let Some(entry) = entries.get(row.chain.as_str()) else {
                    return Err(unknown(
                        KNOWN,
                        "no verified catalogue chain has this id".into(),
                    ));
                };
                if entry.notation != row.notation || entry.family != row.family {
                    return Err(unknown(
                        KNOWN,
                        format!(
                            "{} is {:?} of family {}",
                            entry.id, entry.notation, entry.family
                        ),
                    ));
                }
                let joints = entry.family.len().min(MAX_PRIMITIVES);
                let increasing = row.actuated.windows(2).all(|w| w[0] < w[1]);
                if row.actuated.is_empty()
                    || !increasing
                    || row.actuated.iter().any(|&j| j == 0 || j > joints)
                {
                    return Err(unknown(
                        KNOWN,
                        format!("the actuated joints are not increasing joints 1 to {joints}"),
                    ));
                }
                if !LEGS.contains(&row.legs) {
                    return Err(unknown(
                        KNOWN,
                        format!("a sweep builds {} to {} legs", LEGS.start(), LEGS.end()),
                    ));
                }
                Ok(())
            }
        }
    }
}

/// The labels of the design's inputs in input order, leg by leg (`R1.3 P1.4 R2.3 …`), as
/// [`crate::manipulator::Actuator::label`] writes them.
fn input_labels(row: &DesignRow) -> Result<Vec<String>, String> {
    let chain: Chain = row
        .notation
        .parse()
        .map_err(|_| format!("{:?} is not a chain", row.notation))?;
    let word: Vec<char> = chain.primitive_word().chars().collect();
    let mut labels = Vec::with_capacity(row.inputs);
    for leg in 1..=row.legs {
        for &joint in &row.actuated {
            let letter = word
                .get(joint.wrapping_sub(1))
                .ok_or_else(|| format!("actuated joint {joint} is not a joint of the chain"))?;
            labels.push(format!("{letter}{leg}.{joint}"));
        }
    }
    Ok(labels)
}

/// A fault of one field: its path and why.
type FieldFault = (String, String);

/// Checks a row whose design could not be built: nothing counted.
fn check_failed(row: &DesignRow, error: &str) -> Result<(), (&'static str, String)> {
    if error.trim().is_empty() {
        return Err(("error", "empty".into()));
    }
    let counted = [
        ("dof", row.dof),
        ("subgroups", row.subgroups),
        ("kinds", row.kinds),
        ("group_kinds", row.group_kinds.len()),
        ("groups", row.groups.len()),
        ("non_groups", row.non_groups.len()),
        ("unsampled", row.unsampled),
        ("singular", row.singular),
        ("singular_lock_sets", row.singular_lock_sets.len()),
    ];
    match counted.into_iter().find(|&(_, n)| n != 0) {
        Some((name, n)) => Err((
            name,
            format!("{n} in a row with an error (a design not built counts nothing)"),
        )),
        None => Ok(()),
    }
}

/// Checks the patterns, kinds, counts and lock sets of a built design's row.
fn check_patterns(row: &DesignRow, inputs: &[String]) -> Result<(), FieldFault> {
    let mut kinds: Vec<GroupKind> = Vec::new();
    let mut subsets: u128 = 0;
    for (list, reached, groups) in [
        ("groups", &row.groups, true),
        ("non_groups", &row.non_groups, false),
    ] {
        // Subgroups of one name may differ in their parameters (parallel axes through other
        // points): a pattern with its parameters is listed once.
        let mut seen: HashSet<(&str, Option<&str>)> = HashSet::with_capacity(reached.len());
        for (i, r) in reached.iter().enumerate() {
            let at = |f: &str| format!("{list}[{i}].{f}");
            let name = check_reached(r, groups, inputs).map_err(|(f, why)| (at(&f), why))?;
            if !seen.insert((r.pattern.as_str(), r.parameters.as_deref())) {
                return Err((
                    at("pattern"),
                    format!(
                        "{:?}{} is listed twice",
                        r.pattern,
                        r.parameters
                            .as_ref()
                            .map_or_else(String::new, |p| format!(" ({p})"))
                    ),
                ));
            }
            if let PatternName::Group { kind, .. } = name
                && !kinds.contains(&kind)
            {
                kinds.push(kind);
            }
            subsets += r.subsets as u128;
        }
    }
    let expected: Vec<&str> = GroupKind::ALL
        .into_iter()
        .filter(|k| kinds.contains(k))
        .map(GroupKind::symbol)
        .collect();
    if row.group_kinds != expected {
        return Err((
            "group_kinds".into(),
            format!(
                "{:?} is not the kinds of the groups reached, in the order of the 12 ({expected:?})",
                row.group_kinds
            ),
        ));
    }
    if row.kinds != expected.len() {
        return Err((
            "kinds".into(),
            format!(
                "{} is not the number of group kinds ({})",
                row.kinds,
                expected.len()
            ),
        ));
    }
    if row.subgroups != row.groups.len() {
        return Err((
            "subgroups".into(),
            format!(
                "{} is not the number of groups reached ({})",
                row.subgroups,
                row.groups.len()
            ),
        ));
    }
    check_lock_sets("singular_lock_sets", &row.singular_lock_sets, inputs)?;
    if row.singular_lock_sets.len() > row.singular
        || (row.singular > 0 && row.singular_lock_sets.is_empty())
    {
        return Err((
            "singular_lock_sets".into(),
            format!(
                "{} minimal lock sets for {} singular subsets",
                row.singular_lock_sets.len(),
                row.singular
            ),
        ));
    }
    let all = 1u128 << row.inputs;
    let counted = subsets + row.unsampled as u128 + row.singular as u128;
    if counted != all {
        return Err((
            "groups".into(),
            format!(
                "the lock subsets of the patterns ({subsets}), unsampled ({}) and singular ({}) add up to {counted}, not the 2^{} = {all} lock subsets of the inputs",
                row.unsampled, row.singular, row.inputs
            ),
        ));
    }
    Ok(())
}

/// Checks one pattern reached and returns its name.
fn check_reached(r: &Reached, group: bool, inputs: &[String]) -> Result<PatternName, FieldFault> {
    let fault = |field: &str, why: String| (field.to_string(), why);
    let name: PatternName = r
        .pattern
        .parse()
        .map_err(|_| fault("pattern", format!("{:?} is not a pattern name", r.pattern)))?;
    if name.to_string() != r.pattern {
        return Err(fault(
            "pattern",
            format!(
                "{:?} is not written as kinsyn writes it ({name})",
                r.pattern
            ),
        ));
    }
    let (dimension, has_parameters) = match name {
        PatternName::Group { kind, .. } if group => (
            kind.dimension(),
            matches!(
                kind,
                GroupKind::R | GroupKind::H | GroupKind::C | GroupKind::S | GroupKind::Y
            ),
        ),
        PatternName::NonGroup {
            translations,
            rotations,
        } if !group => (translations + rotations, false),
        _ => {
            return Err(fault(
                "pattern",
                format!(
                    "{:?} is {} pattern",
                    r.pattern,
                    if group { "a non-group" } else { "a group" }
                ),
            ));
        }
    };
    if r.dof != dimension {
        return Err(fault(
            "dof",
            format!("{} is not the dimension of {name} ({dimension})", r.dof),
        ));
    }
    if let Some(p) = &r.parameters
        && (!has_parameters || p.trim().is_empty() || p.chars().any(crate::markup::is_hidden))
    {
        return Err(fault(
            "parameters",
            if has_parameters {
                format!("{p:?} is not one line of text")
            } else {
                format!("{name} has no parameters")
            },
        ));
    }
    if r.lock_sets.is_empty() || r.lock_sets.len() > r.subsets {
        return Err(fault(
            "lock_sets",
            format!(
                "{} minimal lock sets for {} lock subsets",
                r.lock_sets.len(),
                r.subsets
            ),
        ));
    }
    check_lock_sets("lock_sets", &r.lock_sets, inputs)?;
    Ok(name)
}

/// Checks the lock sets `sets` of the field `field`: each once, each a lock set of `inputs`.
fn check_lock_sets(field: &str, sets: &[String], inputs: &[String]) -> Result<(), FieldFault> {
    for (k, set) in sets.iter().enumerate() {
        let at = || format!("{field}[{k}]");
        check_lock_set(set, inputs).map_err(|why| (at(), why))?;
        if sets[..k].contains(set) {
            return Err((at(), format!("{set:?} is listed twice")));
        }
    }
    Ok(())
}

/// Checks that `set` is `-` or labels of `inputs`, space separated, in input order.
fn check_lock_set(set: &str, inputs: &[String]) -> Result<(), String> {
    if set == "-" {
        return Ok(());
    }
    let mut last: Option<usize> = None;
    for label in set.split(' ') {
        let at = inputs.iter().position(|l| l == label);
        match at {
            Some(i) if last.is_none_or(|j| j < i) => last = Some(i),
            _ => {
                return Err(format!(
                    "{set:?} is not '-' or labels of the inputs ({}) in that order",
                    inputs.join(" ")
                ));
            }
        }
    }
    Ok(())
}
