//! The four families of paper 000 §2 and the Appendix tables that hold them.

use serde::Serialize;

/// One Appendix table of paper 000: a family of P/R words and the parallel-axis pattern of
/// its revolutes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct Table {
    /// The paper's table number (1–4, 7, 8; Tables 5 and 6 list the 6R variants that 7 and 8 use).
    pub number: u8,
    /// The family word (§2: PPPRRR, PPRRRR, PRRRRR, RRRRRR).
    pub family: &'static str,
    /// How many revolute axes lie along each of the three directions, largest first: the
    /// parallel-axis pattern the section prescribes before permuting (see [`Table::axis_counts`]).
    pub axis_counts: [u8; 3],
    /// The permutations of the family, in the order the Appendix prints its rows.
    pub words: &'static [&'static str],
    /// The number of chains the paper announces for this table (Tables 7 and 8 are announced
    /// together, [`PUBLISHED_6R`]).
    pub published: Option<usize>,
}

/// The Appendix tables in the paper's order. First occurrence wins in this order.
///
/// * Table 1 (§2.1): "To get three rotational dof in the chain, the axes of the three R pairs
///   will form 90°" — one R along each direction.
/// * Table 2 (§2.2): four R, two of them parallel ("three consecutive R pairs, two of them
///   being parallel") and the others perpendicular — counts 2, 1, 1.
/// * Table 3 (§2.3): "three parallel revolute joints and the remaining two forming 90°" —
///   counts 3, 1, 1.
/// * Table 4 (§2.3): "two groups formed by two R joints ... the remaining R perpendicular" —
///   counts 2, 2, 1.
/// * Table 7 (§2.4, Table 5): "three groups of parallel joints" — counts 2, 2, 2.
/// * Table 8 (§2.4, Table 6): "one group having three R joints with parallel axes, another group
///   with two parallel R ..., and finally, the remaining R joint" — counts 3, 2, 1.
///
/// Every permutation of the axes over the revolutes is then taken ("Any other combination with
/// less number of R joints with parallel axes is obtained by carrying out the permutations").
/// The row order of Table 1 is the printed one: rows 8–10 hold RPPPRR, RPPRPR, RPPRRP before
/// PRRPPR, PRRPRP, PRRRPP in rows 11–13.
pub const TABLES: [Table; 6] = [
    Table {
        number: 1,
        family: "PPPRRR",
        axis_counts: [1, 1, 1],
        words: &[
            "PPPRRR", "PPRPRR", "PPRRPR", "PPRRRP", "PRPPRR", "PRPRPR", "PRPRRP", "RPPPRR",
            "RPPRPR", "RPPRRP", "PRRPPR", "PRRPRP", "PRRRPP", "RPRPPR", "RPRPRP", "RPRRPP",
            "RRPPPR", "RRPPRP", "RRPRPP", "RRRPPP",
        ],
        published: Some(63),
    },
    Table {
        number: 2,
        family: "PPRRRR",
        axis_counts: [2, 1, 1],
        words: &[
            "PPRRRR", "PRPRRR", "RPPRRR", "PRRPRR", "PRRRPR", "PRRRRP", "RPRRPR", "RRPPRR",
            "RPRPRR", "RRRRPP", "RRRPRP", "RRRPPR", "RRPRRP", "RPRRRP", "RRPRPR",
        ],
        published: Some(151),
    },
    Table {
        number: 3,
        family: "PRRRRR",
        axis_counts: [3, 1, 1],
        words: &["PRRRRR", "RPRRRR", "RRPRRR", "RRRPRR", "RRRRPR", "RRRRRP"],
        published: Some(69),
    },
    Table {
        number: 4,
        family: "PRRRRR",
        axis_counts: [2, 2, 1],
        words: &["PRRRRR", "RPRRRR", "RRPRRR", "RRRPRR", "RRRRPR", "RRRRRP"],
        published: Some(40),
    },
    Table {
        number: 7,
        family: "RRRRRR",
        axis_counts: [2, 2, 2],
        words: &["RRRRRR"],
        published: None,
    },
    Table {
        number: 8,
        family: "RRRRRR",
        axis_counts: [3, 2, 1],
        words: &["RRRRRR"],
        published: None,
    },
];

/// The paper's count for Tables 7 and 8 together (§2.4: "24 possible combinations").
pub const PUBLISHED_6R: usize = 24;

/// The paper's grand total (§2.4: "In total, the number of obtained kinematic chains is 347").
pub const PUBLISHED_TOTAL: usize = 347;

/// The table with the given number.
#[must_use]
pub fn table(number: u8) -> Option<&'static Table> {
    TABLES.iter().find(|t| t.number == number)
}

/// The family words, each once, in table order.
#[must_use]
pub fn families() -> Vec<&'static str> {
    let mut f: Vec<&'static str> = Vec::new();
    for t in &TABLES {
        if !f.contains(&t.family) {
            f.push(t.family);
        }
    }
    f
}
