//! `kinsyn catalogue site`: the static site loaded in headless Chromium. The rows its index
//! shows for a filter in the address are the rows of `kinsyn query` with the same options (an
//! independent path: the query command against the page's script), and every entry page's
//! schematic is well-formed XML (Chromium's XML parser) with one symbol per joint letter.
//!
//! Chromium is required in CI (`CI` set; `.ci/run` sets it and installs Chromium): without it
//! the test fails there. Elsewhere a missing Chromium prints a notice and the test passes, like
//! the other external tools' checks (Singular, PHCpack). Debian: `apt-get install chromium`.

use crate::common;

use common::browser::{chromium, dump_dom, url};
use common::{kinsyn, stdout};

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
