//! `kinsyn catalogue …` and `kinsyn query`: the committed catalogue (or another reading of
//! paper 000, enumerated and verified), its entries, differences and queries, as text or JSON.

use super::args::{CatalogueCommand, PrismaticsArg, Reading};
use super::{CliError, json, list_or_none, terminal};
use kinsyn::catalogue::{Catalogue, Entry, VERIFICATION_SEED};
use kinsyn::lockset::LockSet;
use kinsyn::motion::{PatternName, PatternQuery};
use kinsyn::notation::Chain;
use kinsyn::published::Comparison;
use kinsyn::synthesis::{Options, PrismaticReading, tables};
use kinsyn::verification::{self, Settings};
use kinsyn_papers::appendix;
use std::fmt::Write as _;
use std::path::Path;

impl Reading {
    /// The catalogue in this reading. The default reading is the committed catalogue, compiled
    /// into the binary ([`Catalogue::committed`]: read, not re-verified, in milliseconds); any
    /// other reading is enumerated and verified ([`Reading::generated`]).
    pub(super) fn catalogue(&self) -> Result<Catalogue, CliError> {
        let options = self.options();
        if options != Options::default() {
            return Ok(self.generated().0);
        }
        Catalogue::committed().map_err(|e| {
            CliError::Internal(format!(
                "the catalogue compiled into kinsyn cannot be read: {e} (a damaged build: regenerate catalogue/chains.json with `kinsyn catalogue generate` and rebuild)"
            ))
        })
    }

    /// The catalogue in this reading, enumerated, marked against paper 000's Appendix and
    /// verified (about a second: a spinner shows on a terminal), with its comparison with the
    /// Appendix.
    pub(super) fn generated(&self) -> (Catalogue, Comparison) {
        terminal::working("enumerating and verifying the catalogue", || {
            appendix::generate(&self.options())
        })
    }

    /// The catalogue in this reading ([`Reading::catalogue`]) and its row-by-row comparison
    /// with paper 000's Appendix (the enumeration in its options compared: about 15 ms).
    pub(super) fn compared(&self) -> Result<(Catalogue, Comparison), CliError> {
        if self.options() != Options::default() {
            return Ok(self.generated());
        }
        let cat = self.catalogue()?;
        let comparison = appendix::comparison(&cat.options);
        Ok((cat, comparison))
    }

    pub(super) fn options(&self) -> Options {
        Options {
            prismatics: match self.prismatics {
                PrismaticsArg::Separated => PrismaticReading::Separated,
                PrismaticsArg::Perpendicular => PrismaticReading::Perpendicular,
            },
            triple_group_needs_guide: !self.no_triple_guide,
        }
    }
}

fn check_family(family: Option<&str>) -> Result<(), CliError> {
    match family {
        Some(f) if !tables::families().contains(&f) => Err(CliError::Input(format!(
            "unknown family {f:?}; the families are {}",
            tables::families().join(", ")
        ))),
        _ => Ok(()),
    }
}

pub(super) fn query(
    pattern: &str,
    max_locks: usize,
    family: Option<&str>,
    as_json: bool,
    reading: &Reading,
) -> Result<String, CliError> {
    let q: PatternQuery = pattern
        .parse()
        .map_err(|e| CliError::Input(format!("{e}")))?;
    check_family(family)?;
    if max_locks > 6 {
        return Err(CliError::Input(format!(
            "--max-locks {max_locks}: a leg has six joints"
        )));
    }
    let cat = reading.catalogue()?;
    let hits = cat.query(&q, max_locks, family);
    if as_json {
        let rows: Vec<serde_json::Value> = hits
            .iter()
            .map(|h| serde_json::json!({"id": h.entry.id, "notation": h.entry.notation, "family": h.entry.family, "word": h.entry.word, "axes": h.entry.axes, "pattern": h.pattern, "lock_sets": h.lock_sets}))
            .collect();
        return Ok(json(&rows));
    }
    let mut s = String::new();
    for h in &hits {
        let _ = writeln!(
            s,
            "{:<8} {:<22} {} {} {:<7} lock {}",
            h.entry.id,
            h.entry.notation,
            h.entry.word,
            h.entry.axes,
            h.pattern,
            lock_sets_text(&h.lock_sets)
        );
    }
    let chains: std::collections::BTreeSet<&str> =
        hits.iter().map(|h| h.entry.id.as_str()).collect();
    let _ = writeln!(
        s,
        "{} verified chains give {q} with at most {max_locks} locked joints{}",
        chains.len(),
        pattern_note(&q)
    );
    Ok(s)
}

/// What an `nTmR` query means when groups have the same numbers: the group it always is, or
/// the groups it leaves out (it matches non-group motions only).
fn pattern_note(q: &PatternQuery) -> String {
    if let Some(kind) = q.forced_group() {
        return format!(" ({q} is always the group {})", kind.symbol());
    }
    let groups: Vec<&str> = q
        .groups_of_the_same_type()
        .iter()
        .map(|k| k.symbol())
        .collect();
    if groups.is_empty() {
        String::new()
    } else {
        format!(
            " ({q} counts non-group motions only; the groups of this type are {}: query them by name)",
            groups.join(", ")
        )
    }
}

/// `kinsyn catalogue SUBCOMMAND`.
pub(super) fn catalogue(command: CatalogueCommand) -> Result<String, CliError> {
    match command {
        CatalogueCommand::Generate {
            out,
            force,
            reading,
        } => generate(&out, force.force, &reading),
        CatalogueCommand::Summary {
            json: as_json,
            reading,
        } => summary(&reading, as_json),
        CatalogueCommand::List {
            family,
            table,
            json: as_json,
            reading,
        } => list(family.as_deref(), table, &reading, as_json),
        CatalogueCommand::Site {
            out,
            force,
            reading,
        } => super::site::site(&out, force.force, &reading),
        CatalogueCommand::Rejected { reading } => rejected(&reading),
        CatalogueCommand::Show {
            query,
            lock,
            json: as_json,
            reading,
        } => show(&query, lock.as_deref(), &reading, as_json),
        CatalogueCommand::Compare {
            json: as_json,
            reading,
        } => compare(&reading, as_json),
    }
}

/// `catalogue rejected`: the entries no reading of which is 3T3R, then the entries verified
/// with another reading than their first (the two tables kept in docs/deviations.md).
fn rejected(reading: &Reading) -> Result<String, CliError> {
    let cat = reading.catalogue()?;
    Ok(format!(
        "{}\nVerified with another reading than their first (the first axis assignment is rank deficient):\n\n{}",
        cat.not_3t3r_markdown(),
        cat.other_reading_markdown()
    ))
}

/// `catalogue generate`: the catalogue files written to `out` (replacing existing ones only
/// when `force`).
fn generate(out: &Path, force: bool, reading: &Reading) -> Result<String, CliError> {
    super::output::OutputFolder::check("--out", out, Catalogue::FILES, force)?;
    let (cat, comparison) = reading.generated();
    cat.write(
        out,
        &comparison,
        kinsyn::output::Overwrite::from_force(force),
    )
    .map_err(|e| super::output::error("--out", out, e))?;
    let (letters, marks) = cat.totals();
    Ok(format!(
        "wrote {} entries ({letters} distinct by letters) to {}\n",
        marks,
        out.display()
    ))
}

/// `catalogue summary`: the counts per Appendix table against the paper's.
fn summary(reading: &Reading, as_json: bool) -> Result<String, CliError> {
    let (cat, comparison) = reading.compared()?;
    if as_json {
        let diffs: Vec<serde_json::Value> = comparison
            .counts()
            .iter()
            .map(|((t, k), n)| serde_json::json!({"table": t, "kind": k.name(), "count": n}))
            .collect();
        let (letters, marks) = cat.totals();
        return Ok(json(&serde_json::json!({
            "options": cat.options,
            "tables": cat.counts,
            "published_6r": tables::PUBLISHED_6R,
            "published_total": tables::PUBLISHED_TOTAL,
            "total_letters_only": letters,
            "total_with_marks": marks,
            "differences": diffs,
        })));
    }
    let readme = cat.readme(&comparison);
    let body = readme
        .split_once("## Counts per table")
        .map_or(readme.as_str(), |(_, b)| b);
    Ok(format!(
        "kinsyn catalogue: paper 000 §2 structural synthesis{body}"
    ))
}

/// `catalogue list`: the entries, optionally of one family or first found in one table.
fn list(
    family: Option<&str>,
    table: Option<u8>,
    reading: &Reading,
    as_json: bool,
) -> Result<String, CliError> {
    if let Some(f) = family
        && !tables::families().contains(&f)
    {
        return Err(CliError::Input(format!(
            "unknown family {f:?}; the families are {}",
            tables::families().join(", ")
        )));
    }
    if let Some(t) = table
        && tables::table(t).is_none()
    {
        return Err(CliError::Input(format!(
            "no Appendix table {t}; the tables with chains are 1, 2, 3, 4, 7, 8"
        )));
    }
    let cat = reading.catalogue()?;
    let entries: Vec<&Entry> = cat
        .entries
        .iter()
        .filter(|e| {
            family.is_none_or(|f| e.family == f) && table.is_none_or(|t| e.provenance.table == t)
        })
        .collect();
    if as_json {
        return Ok(json(&entries));
    }
    let mut s = String::new();
    for e in entries {
        let _ = writeln!(
            s,
            "{:<8} {:<22} {} {} table {} row {} variant {}",
            e.id,
            e.notation,
            e.word,
            e.axes,
            e.provenance.table,
            e.provenance.row,
            e.provenance.variant
        );
    }
    Ok(s)
}

/// `catalogue show`: one entry (by id or notation), or every entry with the letters asked for,
/// optionally with the motion left when some joints are locked.
fn show(
    query: &str,
    lock: Option<&str>,
    reading: &Reading,
    as_json: bool,
) -> Result<String, CliError> {
    let cat = reading.catalogue()?;
    let entry = match cat.find(query) {
        Some(e) => e,
        None if query
            .parse::<Chain>()
            .is_ok_and(|c| c.parallel_groups().is_empty()) =>
        {
            return same_letters(&cat, query, as_json);
        }
        None => return Err(CliError::Input(not_found(&cat, query))),
    };
    let locked = match &lock {
        None => None,
        Some(text) => Some(locked_pattern(entry, text)?),
    };
    if as_json {
        let mut v = serde_json::to_value(entry).expect("serialisable");
        if let Some((set, pattern)) = locked {
            v["locked"] = serde_json::json!({"lock_set": set, "pattern": pattern});
        }
        return Ok(json(&v));
    }
    let mut s = describe(&cat, entry);
    if let Some((set, pattern)) = locked {
        let _ = writeln!(s, "locked {set:<6} {pattern}");
    }
    Ok(s)
}

/// `catalogue show LETTERS` for letters without parallel marks that are not an entry: every
/// entry with these letters.
fn same_letters(cat: &Catalogue, query: &str, as_json: bool) -> Result<String, CliError> {
    // Letters only: show every entry with these letters, if any.
    let letters = query
        .parse::<Chain>()
        .map(|c| c.letters())
        .unwrap_or_default();
    let same: Vec<&Entry> = cat
        .entries
        .iter()
        .filter(|e| e.letters == letters)
        .collect();
    if same.is_empty() {
        return Err(CliError::Input(format!(
            "{letters:?} is not in the catalogue: the rules of paper 000 §2 do not give it"
        )));
    }
    if as_json {
        return Ok(json(&same));
    }
    let mut s = format!(
        "no entry {letters} without parallel marks; {} entr{} with these letters:\n\n",
        same.len(),
        if same.len() == 1 { "y" } else { "ies" }
    );
    s.push_str(
        &same
            .iter()
            .map(|e| describe(cat, e))
            .collect::<Vec<_>>()
            .join("\n"),
    );
    Ok(s)
}

/// Why `query` names no entry: an unknown id, not a chain, or a chain the rules do not give
/// (with the entries that have its letters).
fn not_found(cat: &Catalogue, query: &str) -> String {
    let looks_like_id = query.trim().starts_with(['T', 't'])
        && query.contains('-')
        && query.chars().any(|c| c.is_ascii_digit());
    match query.parse::<Chain>() {
        Err(_) if looks_like_id => {
            format!("no entry with id {query:?} (ids look like T2-017; see kinsyn catalogue list)")
        }
        Err(e) => {
            format!("{query:?} is neither an entry id nor a valid chain: {e}")
        }
        Ok(chain) => {
            let same: Vec<&str> = cat
                .entries
                .iter()
                .filter(|e| e.letters == chain.letters())
                .map(|e| e.notation.as_str())
                .collect();
            if same.is_empty() {
                format!(
                    "'{chain}' is not in the catalogue: the rules of paper 000 §2 do not give it"
                )
            } else {
                format!(
                    "'{chain}' is not in the catalogue; entries with letters {}: {}",
                    chain.letters(),
                    same.join(", ")
                )
            }
        }
    }
}

/// `catalogue compare`: every difference from the printed Appendix.
fn compare(reading: &Reading, as_json: bool) -> Result<String, CliError> {
    let (_, comparison) = reading.compared()?;
    if as_json {
        return Ok(json(&comparison.differences));
    }
    Ok(comparison.markdown())
}

/// The motion of an entry's chain with the joints of `text` locked (its verification's
/// geometry and sample configurations).
fn locked_pattern(entry: &Entry, text: &str) -> Result<(LockSet, PatternName), CliError> {
    let chain = entry
        .serial_chain(VERIFICATION_SEED)
        .map_err(|e| CliError::Input(format!("{}: {e}", entry.id)))?;
    let locks = LockSet::parse_for(text, chain.len())
        .map_err(|e| CliError::Input(format!("{}: {e}", entry.id)))?;
    let settings = Settings::default();
    let configurations =
        verification::configurations(&chain, &settings, entry.sample_seed(VERIFICATION_SEED));
    let c = verification::locked_motion(&chain, locks.mask(), &configurations, &settings);
    Ok((locks, c.pattern.name()))
}

/// Lock sets as the text commands print them: `45 | 46`.
fn lock_sets_text(sets: &[LockSet]) -> String {
    sets.iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join(" | ")
}

fn describe(cat: &Catalogue, e: &Entry) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{}  {}", e.id, e.notation);
    let _ = writeln!(s, "letters      {}", e.letters);
    let _ = writeln!(
        s,
        "family       {} (Table {})",
        e.family, e.provenance.table
    );
    let _ = writeln!(s, "word         {}", e.word);
    let _ = writeln!(
        s,
        "axes         {} (direction of each primitive joint at the reference configuration)",
        e.axes
    );
    let groups: Vec<String> = e.parallel_groups.iter().map(|g| format!("{g:?}")).collect();
    let _ = writeln!(s, "parallel     {}", list_or_none(&groups));
    let c = e.composition;
    let _ = writeln!(
        s,
        "composition  P {} R {} C {} U {} S {}",
        c.p, c.r, c.c, c.u, c.s
    );
    let _ = writeln!(
        s,
        "provenance   Table {} row {} variant {} ({})",
        e.provenance.table, e.provenance.row, e.provenance.variant, e.provenance.variant_label
    );
    let _ = writeln!(
        s,
        "paper        {}",
        match (e.printed_in_row, e.printed_in_appendix) {
            (true, _) => "printed in this row of the Appendix",
            (false, true) => "printed in another row of the Appendix",
            (false, false) => "not printed in the Appendix",
        }
    );
    let note = e.reading_note();
    if !note.is_empty() {
        let _ = writeln!(s, "reading      {note}");
    }
    if let Some(v) = &e.verification {
        let _ = writeln!(
            s,
            "verified     {} ({})",
            if v.is_3t3r { "3T3R" } else { "NOT 3T3R" },
            v.summary()
        );
        let sv: Vec<String> = v
            .singular_values
            .iter()
            .map(|x| format!("{x:.4}"))
            .collect();
        let _ = writeln!(s, "singular     {}", sv.join(" "));
        let _ = writeln!(
            s,
            "patterns     (lock sets: joint positions in the word; minimal sets only)"
        );
        // Groups by the fewest joints that lock them, then by name.
        let mut groups: Vec<(&PatternName, &Vec<LockSet>)> =
            v.patterns.iter().filter(|(p, _)| p.is_group()).collect();
        groups.sort_by_key(|(p, locks)| (locks.iter().map(|l| l.len()).min(), **p));
        for (p, locks) in groups {
            let _ = writeln!(s, "  {p:<8} {}", lock_sets_text(locks));
        }
        let others: Vec<String> = v
            .patterns
            .keys()
            .filter(|p| !p.is_group())
            .map(ToString::to_string)
            .collect();
        let _ = writeln!(s, "  non-group: {}", others.join(" "));
    }
    let others: Vec<String> = cat
        .entries
        .iter()
        .filter(|o| o.letters == e.letters && o.id != e.id)
        .map(|o| format!("{} {}", o.id, o.notation))
        .collect();
    if !others.is_empty() {
        let _ = writeln!(s, "same letters {}", others.join(", "));
    }
    s
}
