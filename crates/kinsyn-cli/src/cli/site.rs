//! `kinsyn catalogue site --out DIR`: the catalogue as a static site (docs/catalogue-site.md).
//!
//! `index.html` holds every entry and the facts `kinsyn query` searches, as JSON in the page;
//! its script only filters those facts the way [`kinsyn::catalogue::Catalogue::query`] does,
//! with the pattern spellings and what each one covers decided here by the library
//! ([`PatternQuery`]'s parser and [`PatternQuery::covers`]). Each entry has a page
//! `entry/ID.html` with its facts, minimal lock sets, a schematic ([`kinsyn::schematic`]) and
//! a 3D view of its leg chain that animates each lock set's motion ([`kinsyn::view::chain_view`]);
//! three.js and the viewer script are written once, beside `index.html`, and every entry page
//! refers to them. Every file is written into DIR: no server, no network.

use super::CliError;
use super::args::Reading;
use super::output::OutputFolder;
use kinsyn::catalogue::{Catalogue, Entry, VERIFICATION_SEED};
use kinsyn::lockset::LockSet;
use kinsyn::markup::{escape, json_in_html};
use kinsyn::motion::{GroupKind, PatternName, PatternQuery};
use kinsyn::schematic;
use kinsyn::synthesis::tables;
use kinsyn::verification::Verification;
use kinsyn::view::{LEGEND, SCRIPT_FILES, Scripts, chain_view, parts};
use rayon::prelude::*;
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;
use std::path::Path;

/// The site's style sheet.
const CSS: &str = include_str!("site/site.css");
/// The index page's filter.
const JS: &str = include_str!("site/site.js");

/// Writes the site of the catalogue (in this reading) into the folder `out` (created if
/// missing), replacing existing files only when `force`: every file is checked before the
/// first is written, and each is written whole ([`super::output`]).
pub(super) fn site(out: &Path, force: bool, reading: &Reading) -> Result<String, CliError> {
    let cat = reading.catalogue()?;
    let seed = cat.verification.map_or(VERIFICATION_SEED, |(_, seed)| seed);
    let mut files: Vec<(String, String)> = vec![
        ("site.css".into(), CSS.to_string()),
        ("site.js".into(), JS.to_string()),
        ("index.html".into(), index(&cat)),
    ];
    files.extend(
        SCRIPT_FILES
            .iter()
            .map(|(name, text)| ((*name).to_string(), (*text).to_string())),
    );
    let pages = cat
        .entries
        .par_iter()
        .map(|e| Ok((format!("entry/{}.html", e.id), entry_page(e, seed)?)))
        .collect::<Result<Vec<_>, CliError>>()?;
    files.extend(pages);
    let folder = OutputFolder::check("--out", out, files.iter().map(|(name, _)| name), force)?;
    folder.create(&["entry"])?;
    // Each file is synced to the disk before its rename (a few ms each): written in
    // parallel, the waits overlap.
    files
        .par_iter()
        .try_for_each(|(name, text)| folder.write(name, text.as_bytes()).map(drop))?;
    Ok(format!(
        "wrote the catalogue site ({} entries) to {}; open {}\n",
        cat.entries.len(),
        out.display(),
        out.join("index.html").display()
    ))
}

/// How an entry's numerical check came out.
fn status(e: &Entry) -> &'static str {
    match &e.verification {
        None => "not verified",
        Some(v) if v.is_3t3r => "3T3R",
        Some(_) => "not 3T3R",
    }
}

/// Every spelling `kinsyn query --pattern` accepts without whitespace (groups with and without
/// a direction or plane, both orders of a plane's letters, `nTmR`), with the names of the
/// catalogue's patterns it covers.
fn query_spellings(names: &BTreeSet<PatternName>) -> BTreeMap<String, Vec<String>> {
    let mut candidates: Vec<String> = Vec::new();
    for kind in GroupKind::ALL {
        let symbol = kind.symbol();
        candidates.push(symbol.to_string());
        for p in ["x", "y", "z", "xy", "yx", "yz", "zy", "xz", "zx"] {
            candidates.push(format!("{symbol}({p})"));
        }
    }
    for t in 0..=3 {
        for r in 0..=3 {
            candidates.push(format!("{t}T{r}R"));
        }
    }
    candidates
        .into_iter()
        .filter_map(|text| {
            let q: PatternQuery = text.parse().ok()?;
            let covered = names
                .iter()
                .filter(|n| q.covers(n))
                .map(ToString::to_string)
                .collect();
            Some((text, covered))
        })
        .collect()
}

/// The facts the index filters, as JSON safe inside a `<script>` element
/// ([`json_in_html`]: no `</script>` or `<!--` can be made up of the text).
fn data_json(cat: &Catalogue) -> String {
    let names: BTreeSet<PatternName> = cat
        .entries
        .iter()
        .filter_map(|e| e.verification.as_ref())
        .flat_map(|v| v.patterns.keys().copied())
        .collect();
    let entries: Vec<serde_json::Value> = cat
        .entries
        .iter()
        .map(|e| {
            let patterns: Vec<serde_json::Value> = e
                .verification
                .iter()
                .flat_map(|v| &v.patterns)
                .map(|(name, sets)| {
                    let sets: Vec<serde_json::Value> = sets
                        .iter()
                        .map(|l| serde_json::json!([l.to_string(), l.len()]))
                        .collect();
                    serde_json::json!([name.to_string(), name.is_group(), sets])
                })
                .collect();
            serde_json::json!({
                "id": e.id,
                "family": e.family,
                "notation": e.notation,
                "status": status(e),
                "queried": e.verification.as_ref().is_some_and(|v| v.is_3t3r),
                "patterns": patterns,
            })
        })
        .collect();
    let data = serde_json::json!({
        "families": tables::families(),
        "queries": query_spellings(&names),
        "entries": entries,
    });
    json_in_html(&serde_json::to_string(&data).expect("serialisable"))
}

/// `index.html`.
fn index(cat: &Catalogue) -> String {
    let mut families = String::new();
    for f in tables::families() {
        let _ = write!(families, r#"<option value="{0}">{0}</option>"#, escape(f));
    }
    let mut locks = String::new();
    for k in 0..=6 {
        let _ = write!(locks, r#"<option value="{k}">{k}</option>"#);
    }
    let verified = cat.verified().count();
    format!(
        r#"<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>kinsyn catalogue of 6-dof leg chains</title>
<link rel="stylesheet" href="site.css">
</head>
<body>
<header>
<h1>kinsyn catalogue of 6-dof leg chains</h1>
<p>{total} chains of paper 000's structural synthesis, {verified} verified 3T3R. Filter by the motion a chain gives with some joints locked (the rows of <code>kinsyn query</code>); open an entry for its lock table and schematic.</p>
</header>
<main>
<form id="filters" method="get" action="index.html">
<label>pattern <input id="pattern" name="pattern" size="10" placeholder="T3, X(z), 2T1R" autocomplete="off"></label>
<label>family <select id="family" name="family"><option value="">any</option>{families}</select></label>
<label>at most <select id="max-locks" name="max-locks">{locks}</select> locked joints</label>
<button type="submit">filter</button> <a href="index.html">clear</a>
</form>
<p id="error" class="error" role="alert" hidden></p>
<p id="count" aria-live="polite"></p>
<table id="entries">
<thead><tr><th>id</th><th>family</th><th>notation</th><th>status</th><th id="patterns-head">patterns reached (minimal lock sets)</th></tr></thead>
<tbody id="rows"></tbody>
</table>
<noscript><p>The table is drawn by the page's script; the entries are in the folder <a href="entry/">entry/</a>.</p></noscript>
</main>
<script type="application/json" id="catalogue-data">{data}</script>
<script src="site.js"></script>
</body>
</html>
"#,
        total = cat.entries.len(),
        data = data_json(cat)
    )
}

/// `entry/ID.html`; `seed` is the catalogue's verification seed (the chain's geometry).
#[allow(
    clippy::too_many_lines,
    reason = "a page template: one line or three per fact, then the page's text"
)]
fn entry_page(e: &Entry, seed: u64) -> Result<String, CliError> {
    let picture = schematic::entry(e)
        .map_err(|err| CliError::Internal(format!("{}: cannot draw: {err}", e.id)))?;
    let mut facts = String::new();
    let mut fact = |k: &str, v: &str| {
        let _ = write!(facts, "<tr><th>{k}</th><td>{v}</td></tr>");
    };
    fact("notation", &format!("<code>{}</code>", escape(&e.notation)));
    fact("letters", &escape(&e.letters));
    fact(
        "family",
        &format!(
            "{} (Appendix Table {})",
            escape(&e.family),
            e.provenance.table
        ),
    );
    fact(
        "word",
        &format!(
            "<code>{}</code> (primitive joints, base to end)",
            escape(&e.word)
        ),
    );
    fact(
        "axes",
        &format!(
            "<code>{}</code> (each primitive joint's direction at the reference configuration)",
            escape(e.axes.as_str())
        ),
    );
    let groups: Vec<String> = e
        .parallel_groups
        .iter()
        .zip('a'..)
        .map(|(g, letter)| {
            let members: Vec<String> = g.iter().map(ToString::to_string).collect();
            format!("{letter}: joints {}", members.join(", "))
        })
        .collect();
    fact(
        "parallel groups",
        &escape(&if groups.is_empty() {
            "none".to_string()
        } else {
            groups.join("; ")
        }),
    );
    let c = e.composition;
    fact(
        "composition",
        &format!("P {} R {} C {} U {} S {}", c.p, c.r, c.c, c.u, c.s),
    );
    fact(
        "provenance",
        &format!(
            "Table {} row {} variant {} (<code>{}</code>); {}",
            e.provenance.table,
            e.provenance.row,
            e.provenance.variant,
            escape(&e.provenance.variant_label),
            match (e.printed_in_row, e.printed_in_appendix) {
                (true, _) => "printed in this row of the Appendix",
                (false, true) => "printed in another row of the Appendix",
                (false, false) => "not printed in the Appendix",
            }
        ),
    );
    let note = e.reading_note();
    if !note.is_empty() {
        fact("reading", &escape(&note));
    }
    let mut locks = String::new();
    let rows = e.verification.as_ref().map(lock_rows).unwrap_or_default();
    let view = chain_view(e, seed, &rows)
        .map_err(|err| CliError::Internal(format!("cannot draw in 3D: {err}")))?;
    let view = parts(&view, Scripts::Linked("../"));
    if let Some(v) = &e.verification {
        fact(
            "verification",
            &format!(
                "<span class=\"status\">{}</span>: {}",
                status(e),
                escape(&v.summary())
            ),
        );
        locks = lock_table(&rows);
    } else {
        fact("verification", "not verified");
    }
    Ok(format!(
        r#"<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{id} {notation} · kinsyn catalogue</title>
<link rel="stylesheet" href="../site.css">
</head>
<body>
<header>
<p><a href="../index.html">← catalogue</a></p>
<h1>{id} <code>{notation}</code></h1>
</header>
<main>
<figure class="view">
<div id="kinsyn-canvas"></div>
<div class="view-controls">
<p class="legend">{LEGEND}</p>
{controls}</div>
<div hidden="hidden">
{lists}</div>
<figcaption>The chain in 3D: the leg chain of the numerical verification (the axes below at the reference configuration, a C, U or S on one point, generic offsets between joint letters) at a generic configuration. Drag to orbit, scroll to zoom, right-drag to pan. <em>animate</em> in the lock table moves the free joints with that lock set's joints held at their reference values.</figcaption>
</figure>
<figure class="schematic">
{picture}
<figcaption>Base on the left, end link on the right; seen along y (x to the right, z up). P: a box on its guide (■ with a dot: along y). R: a circle when its axis is along y, two bars across its axis otherwise. C, U, S: their primitive joints on a shaded band, S as a ball. Numbers: positions in the word (the lock sets' numbers) and axes; colours and letters a, b, c: parallel groups; hatched and !: actuated.</figcaption>
</figure>
<table class="facts">{facts}</table>
<h2>Lock table</h2>
<p>Each minimal lock set (joint positions in the word; - for none): the motion left with these joints locked, and its dof. Minimal sets only: no smaller set gives the same pattern; <code>kinsyn catalogue show {id} --lock SET</code> classifies any other set.</p>
<table class="locks"><thead><tr><th>lock set</th><th>locked</th><th>dof</th><th>pattern</th><th>motion</th></tr></thead><tbody>{locks}</tbody></table>
</main>
{scripts}</body>
</html>
"#,
        id = escape(&e.id),
        notation = escape(&e.notation),
        controls = view.controls,
        lists = view.lists,
        scripts = view.scripts,
    ))
}

/// An entry's minimal lock sets with the pattern each leaves, in the lock table's order:
/// fewest locks first, then by the set's text and the pattern. The 3D view's mode `k` is row
/// `k`.
fn lock_rows(v: &Verification) -> Vec<(LockSet, PatternName)> {
    let mut rows: Vec<(LockSet, PatternName)> = v
        .patterns
        .iter()
        .flat_map(|(name, sets)| sets.iter().map(move |l| (*l, *name)))
        .collect();
    rows.sort_by_cached_key(|(l, name)| (l.len(), l.to_string(), *name));
    rows
}

/// The rows of an entry's lock table: each minimal lock set with its size, the dof and the
/// pattern it leaves, and a link that animates its motion in the 3D view (mode `k` of row `k`).
fn lock_table(rows: &[(LockSet, PatternName)]) -> String {
    let mut locks = String::new();
    for (k, (set, name)) in rows.iter().enumerate() {
        let _ = write!(
            locks,
            r##"<tr class="{}"><td><code>{}</code></td><td>{}</td><td>{}</td><td>{}</td><td><a class="play" href="#play={k}" onclick="if (location.hash === this.hash) window.dispatchEvent(new HashChangeEvent('hashchange'))">{}</a></td></tr>"##,
            if name.is_group() { "group" } else { "nongroup" },
            escape(&set.to_string()),
            set.len(),
            name.dof(),
            escape(&name.to_string()),
            if name.dof() == 0 { "show" } else { "animate" }
        );
    }
    locks
}
