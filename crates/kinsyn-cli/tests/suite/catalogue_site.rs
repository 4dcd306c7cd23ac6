//! `kinsyn catalogue site`: the static site loaded in headless Chromium. The rows its index
//! shows for a filter in the address are the rows of `kinsyn query` with the same options (an
//! independent path: the query command against the page's script), and every entry page's
//! schematic is well-formed XML (Chromium's XML parser) with one symbol per joint letter. An
//! entry page's 3D view draws the entry's chain where kinsyn's forward kinematics
//! (`SerialChain::forward`, Rust) puts it, along the animation of a lock set of its lock table.
//!
//! Chromium is required in CI (`CI` set; `.ci/run` sets it and installs Chromium): without it
//! the test fails there. Elsewhere a missing Chromium prints a notice and the test passes, like
//! the other external tools' checks (Singular, PHCpack). Debian: `apt-get install chromium`.

use crate::common;

use common::browser::{Screenshot, chromium, dump_dom, numbers, screenshot, url, view_states};
use common::{kinsyn, stdout};
use kinsyn::catalogue::{Catalogue, VERIFICATION_SEED};
use kinsyn::chain::SerialChain;
use kinsyn::lockset::LockSet;
use serde_json::Value;
use std::path::Path;

/// The site, built by the binary into a temporary folder.
fn build_site() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    let out = kinsyn(&["catalogue", "site", "--out", dir.path().to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    dir
}

/// The text between `start` and the next `end` after each occurrence of `start` in `s`.
fn between<'a>(s: &'a str, start: &str, end: &str) -> Vec<&'a str> {
    s.match_indices(start)
        .map(|(i, _)| {
            let rest = &s[i + start.len()..];
            &rest[..rest.find(end).unwrap()]
        })
        .collect()
}

/// The rows the index shows: (id, pattern, lock sets as "456 | 356").
fn rows_shown(dom: &str) -> Vec<(String, String, String)> {
    let body = between(dom, "<tbody id=\"rows\">", "</tbody>");
    assert_eq!(body.len(), 1, "no table body in the page");
    body[0]
        .split("<tr ")
        .skip(1)
        .map(|tr| {
            let id = between(tr, "data-id=\"", "\"")[0].to_string();
            let pattern = between(tr, "data-pattern=\"", "\"")[0].to_string();
            let sets = between(tr, "<span class=\"sets\">", "</span>")[0].to_string();
            (id, pattern, sets)
        })
        .collect()
}

/// The rows of `kinsyn query … --json`, in the same form.
fn query_rows(args: &[&str]) -> Vec<(String, String, String)> {
    let mut all = vec!["query", "--json"];
    all.extend_from_slice(args);
    let out = kinsyn(&all);
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    let rows: Vec<serde_json::Value> = serde_json::from_str(&stdout(&out)).unwrap();
    rows.iter()
        .map(|r| {
            let sets: Vec<&str> = r["lock_sets"]
                .as_array()
                .unwrap()
                .iter()
                .map(|s| s.as_str().unwrap())
                .collect();
            (
                r["id"].as_str().unwrap().to_string(),
                r["pattern"].as_str().unwrap().to_string(),
                sets.join(" | "),
            )
        })
        .collect()
}

#[test]
fn the_index_filtered_in_its_address_shows_the_rows_of_kinsyn_query() {
    let Some(chromium) = chromium("the catalogue site test") else {
        return;
    };
    let site = build_site();
    let cases: [(&str, &[&str]); 3] = [
        (
            "pattern=T3&max-locks=3",
            &["--pattern", "T3", "--max-locks", "3"],
        ),
        // Every X along z in one family, any number of locks (the default 6).
        (
            "pattern=X(z)&family=PPRRRR",
            &["--pattern", "X(z)", "--family", "PPRRRR"],
        ),
        // A non-group name, written with spaces (which the query ignores).
        (
            "pattern=1T%202R&family=RRRRRR&max-locks=3",
            &[
                "--pattern",
                "1T 2R",
                "--family",
                "RRRRRR",
                "--max-locks",
                "3",
            ],
        ),
    ];
    let mut first = None;
    for (filter, args) in cases {
        let dom = dump_dom(
            &chromium,
            &url(site.path(), &format!("index.html?{filter}")),
        );
        let shown = rows_shown(&dom);
        let expected = query_rows(args);
        assert!(!expected.is_empty(), "{filter}: the query finds nothing");
        assert_eq!(shown, expected, "{filter}");
        first.get_or_insert(shown);
    }
    // The first case by hand: T1-002 (PPCU, axes xyzzxy) is a translator with its U and the
    // C's R locked (three locked revolutes remove the three rotations), so the page shows it.
    let shown = first.expect("three cases");
    assert!(shown.contains(&("T1-002".into(), "T3".into(), "456".into())));
    // A plane written backwards.
    let dom = dump_dom(
        &chromium,
        &url(site.path(), "index.html?pattern=G(yx)&max-locks=2"),
    );
    assert_eq!(
        rows_shown(&dom),
        query_rows(&["--pattern", "G(xy)", "--max-locks", "2"])
    );
    // No filter: every entry of the catalogue, in its order.
    let dom = dump_dom(&chromium, &url(site.path(), "index.html"));
    let ids: Vec<String> = rows_shown_ids(&dom);
    let list: Vec<serde_json::Value> =
        serde_json::from_str(&stdout(&kinsyn(&["catalogue", "list", "--json"]))).unwrap();
    let listed: Vec<String> = list
        .iter()
        .map(|e| e["id"].as_str().unwrap().to_string())
        .collect();
    assert_eq!(ids, listed);
    // A pattern the query refuses: an error and no row.
    let dom = dump_dom(&chromium, &url(site.path(), "index.html?pattern=T4"));
    assert!(rows_shown_ids(&dom).is_empty());
    assert!(dom.contains("\"T4\" is not a motion pattern"), "{dom}");
    let refused = kinsyn(&["query", "--pattern", "T4"]);
    assert_eq!(refused.status.code(), Some(2));
}

/// The ids of the rows shown, without a pattern filter.
fn rows_shown_ids(dom: &str) -> Vec<String> {
    let body = between(dom, "<tbody id=\"rows\">", "</tbody>");
    between(body[0], "<tr data-id=\"", "\"")
        .into_iter()
        .map(String::from)
        .collect()
}

#[test]
fn every_schematic_is_well_formed_xml_with_one_symbol_per_joint_letter() {
    let Some(chromium) = chromium("the catalogue site test") else {
        return;
    };
    let site = build_site();
    let list: Vec<serde_json::Value> =
        serde_json::from_str(&stdout(&kinsyn(&["catalogue", "list", "--json"]))).unwrap();
    // Every entry page's <svg>, in one XHTML document: Chromium parses it as XML.
    let mut doc = String::from(
        r#"<?xml version="1.0" encoding="utf-8"?><html xmlns="http://www.w3.org/1999/xhtml"><head><title>schematics</title></head><body>"#,
    );
    let mut letters = 0;
    for e in &list {
        let id = e["id"].as_str().unwrap();
        letters += e["letters"].as_str().unwrap().len();
        let page = std::fs::read_to_string(site.path().join(format!("entry/{id}.html"))).unwrap();
        let start = page.find("<svg ").unwrap();
        let end = page.find("</svg>").unwrap() + "</svg>".len();
        doc.push_str(&["<div id=\"", id, "\">", &page[start..end], "</div>"].concat());
    }
    doc.push_str("</body></html>");
    let file = site.path().join("schematics.xhtml");
    std::fs::write(&file, &doc).unwrap();
    let dom = dump_dom(&chromium, &url(site.path(), "schematics.xhtml"));
    assert!(!dom.contains("parsererror"), "not well-formed XML");
    assert_eq!(dom.matches("<svg ").count(), list.len());
    assert_eq!(dom.matches("data-letter=").count(), letters);
    // Each entry's letters, in order, from its own drawing.
    for e in &list {
        let id = e["id"].as_str().unwrap();
        let part = between(&dom, &format!("<div id=\"{id}\">"), "</svg>")[0];
        assert_eq!(
            between(part, "data-letter=\"", "\"").concat(),
            e["letters"].as_str().unwrap(),
            "{id}"
        );
    }
    // The check can fail: a document with an unclosed element is reported.
    let broken = site.path().join("broken.xhtml");
    std::fs::write(&broken, doc.replacen("</g>", "", 1)).unwrap();
    let dom = dump_dom(&chromium, &url(site.path(), "broken.xhtml"));
    assert!(dom.contains("parsererror"));
}

/// The data of the 3D view an entry page carries.
fn view_data(site: &Path, id: &str) -> (String, Value) {
    let page = std::fs::read_to_string(site.join(format!("entry/{id}.html"))).unwrap();
    let json = between(
        &page,
        "<script type=\"application/json\" id=\"kinsyn-data\">",
        "</script>",
    );
    assert_eq!(json.len(), 1, "{id}: one view");
    let data = serde_json::from_str(json[0]).expect("the view's data is JSON");
    (page, data)
}

/// The page's end-effector frame (`state`, computed by its script from joint values `q`) is the
/// chain's end link frame by kinsyn's forward kinematics, to 1e-9.
fn assert_chain_frame(chain: &SerialChain, q: &[f64], state: &Value, what: &str) {
    let g = chain.forward(q);
    let origin = chain.joints().last().unwrap().point;
    let expected = g * nalgebra::Point3::from(origin);
    let position = numbers(&state["end_effector_position"]);
    for (i, p) in position.iter().enumerate() {
        let d = (p - expected[i]).abs();
        assert!(
            d <= 1e-9 * (1.0 + expected.coords.norm()),
            "{what}: position {i} off by {d:e}"
        );
    }
    let rotation = numbers(&state["end_effector_rotation"]);
    let r = g.rotation.matrix();
    for k in 0..9 {
        let d = (rotation[k] - r[(k / 3, k % 3)]).abs();
        assert!(d <= 1e-9, "{what}: rotation {k} off by {d:e}");
    }
}

/// The canvas on an entry page's screenshot (1200 × 800): below the title, 420 pixels high.
const CANVAS_COLUMNS: std::ops::Range<usize> = 40..1140;
const CANVAS_ROWS: std::ops::Range<usize> = 130..520;

#[test]
#[allow(clippy::too_many_lines, reason = "one scenario per entry, in order")]
fn entry_pages_draw_the_chain_in_3d_and_animate_each_lock_set_where_kinsyn_puts_it() {
    let Some(chromium) = chromium("the catalogue site test") else {
        return;
    };
    let site = build_site();
    let cat = Catalogue::committed().unwrap();
    let seed = cat.verification.map_or(VERIFICATION_SEED, |(_, seed)| seed);
    // An RRRRRR with an S and a U, a PPPRRR with a C and a U, the first PRRRRR.
    let prrrrr = cat.entries.iter().find(|e| e.family == "PRRRRR").unwrap();
    for id in ["T7-002", "T1-002", prrrrr.id.as_str()] {
        let entry = cat.entries.iter().find(|e| e.id == id).unwrap();
        let chain = entry.serial_chain(seed).unwrap();
        let (page, data) = view_data(site.path(), id);
        // The scene is the chain of the verification: its joints' axes and points.
        let joints = data["scene"]["joints"].as_array().unwrap();
        assert_eq!(joints.len(), chain.len(), "{id}");
        for (j, k) in joints.iter().zip(chain.joints()) {
            let (axis, point) = (numbers(&j["axis"]), numbers(&j["point"]));
            for i in 0..3 {
                assert!((axis[i] - k.axis[i]).abs() < 1e-12, "{id}: axis");
                assert!((point[i] - k.point[i]).abs() < 1e-12, "{id}: point");
            }
        }
        // One mode per row of the lock table, in its order, named by the row's lock set.
        let table = between(&page, "<table class=\"locks\">", "</table>")[0];
        let sets: Vec<&str> = between(table, "<tr class=\"", "</code>")
            .into_iter()
            .map(|row| &row[row.find("<code>").unwrap() + 6..])
            .collect();
        let modes = data["modes"].as_array().unwrap();
        let locks: Vec<&str> = modes.iter().map(|m| m["locks"].as_str().unwrap()).collect();
        assert_eq!(locks, sets, "{id}");
        let links: Vec<&str> = between(table, "href=\"#play=", "\"");
        let expected: Vec<String> = (0..modes.len()).map(|k| k.to_string()).collect();
        assert_eq!(links, expected, "{id}: a link per row");
        // The start is generic (not the reference), and shown where kinsyn puts it.
        let start = numbers(&data["start"]);
        assert!(
            start.iter().any(|v| v.abs() > 1e-3),
            "{id}: the start is the reference"
        );
        // A lock set that locks some joints and leaves motion: its walk, end to end.
        let (k, mode) = modes
            .iter()
            .enumerate()
            .find(|(_, m)| m["locks"] != "-" && m["dof"].as_u64().unwrap() > 0)
            .unwrap();
        let set: LockSet = mode["locks"].as_str().unwrap().parse().unwrap();
        let walk: Vec<Vec<f64>> = mode["joint_values"]
            .as_array()
            .unwrap()
            .iter()
            .map(numbers)
            .collect();
        assert!(walk.len() > 2, "{id}: the walk of {set} does not move");
        for q in &walk {
            for j in set.joints() {
                // Exactly zero, the reference value, at every frame.
                assert!(
                    q[j - 1].to_bits() == 0f64.to_bits(),
                    "{id} {set}: joint {j} is not held at its reference"
                );
            }
        }
        let last = walk.len() - 1;
        let frames = [
            0,
            usize::try_from(mode["start"].as_u64().unwrap()).unwrap(),
            last / 3,
            last,
        ];
        let mut items = vec!["start:0".to_string()];
        items.extend(frames.iter().map(|f| format!("mode:{k}:{f}")));
        let shown = view_states(&chromium, site.path(), &format!("entry/{id}.html"), &items);
        assert_chain_frame(&chain, &start, &shown[0], &format!("{id} start"));
        for (f, state) in frames.iter().zip(&shown[1..]) {
            assert_chain_frame(&chain, &walk[*f], state, &format!("{id} {set} frame {f}"));
        }
        // The end link moves along the walk (dof > 0): kinsyn's frames at its two ends.
        let (a, b) = (chain.forward(&walk[0]), chain.forward(&walk[last]));
        let moved = (a.translation.vector - b.translation.vector).norm()
            + (a.rotation.matrix() - b.rotation.matrix()).norm();
        assert!(
            moved > 1e-2,
            "{id} {set}: the end link does not move ({moved:e})"
        );
        // Drawn: the canvas is not blank, and it changes between the walk's two ends.
        let dir = tempfile::tempdir().unwrap();
        let shots: Vec<Screenshot> = [0, last]
            .iter()
            .map(|f| {
                let png = dir.path().join(format!("{f}.png"));
                let address = format!(
                    "{}#mode={k}&frame={f}",
                    url(site.path(), &format!("entry/{id}.html"))
                );
                screenshot(&chromium, &address, &png);
                Screenshot::read(&png)
            })
            .collect();
        let share = shots[0].drawn_share(CANVAS_COLUMNS, CANVAS_ROWS);
        assert!(share > 1e-3, "{id}: the canvas is blank ({share})");
        let changed = CANVAS_ROWS
            .flat_map(|y| CANVAS_COLUMNS.map(move |x| (x, y)))
            .filter(|&(x, y)| shots[0].at(x, y) != shots[1].at(x, y))
            .count();
        assert!(
            changed > 50,
            "{id} {set}: the drawing does not move ({changed} pixels)"
        );
    }
}
