//! The HTML page of a [`View`]: one file holding the data, three.js and its orbit controls
//! (vendored, MIT licence, in `assets/three/`), and the viewer script (`assets/view/`).

use super::View;
use crate::markup::escape;
use std::fmt::Write as _;

/// The version of three.js the page carries.
pub const THREE_JS_VERSION: &str = "0.147.0";

const THREE_JS: &str = include_str!("../../assets/three/three.min.js");
const ORBIT_CONTROLS: &str = include_str!("../../assets/three/OrbitControls.js");
const THREE_LICENCE: &str = include_str!("../../assets/three/LICENSE");
const VIEWER: &str = include_str!("../../assets/view/viewer.js");

/// Collects the page's errors (uncaught exceptions and `console.error`, where three.js reports
/// WebGL failures) into `window.kinsynErrors`, shown in the page's state.
const ERRORS: &str = "window.kinsynErrors = [];
function kinsynError(text) {
  window.kinsynErrors.push(String(text));
  var s = document.getElementById('kinsyn-state');
  if (s) s.textContent = JSON.stringify({errors: window.kinsynErrors});
}
window.addEventListener('error', function (e) { kinsynError(e.message); });
(function () { var original = console.error; console.error = function () {
  kinsynError(Array.prototype.join.call(arguments, ' ')); original.apply(console, arguments); }; }());";

const STYLE: &str = "
body { margin: 0; font: 14px/1.4 system-ui, sans-serif; color: #212529; display: flex; height: 100vh; }
#kinsyn-canvas { flex: 1; min-width: 0; position: relative; }
#kinsyn-canvas canvas { display: block; }
aside { width: 24rem; overflow-y: auto; padding: 0.8rem 1rem; border-left: 1px solid #dee2e6; background: #fff; }
h1 { font-size: 1.2rem; margin: 0 0 0.3rem; }
h2 { font-size: 0.95rem; margin: 1rem 0 0.3rem; }
.row { display: grid; grid-template-columns: 4rem 1fr 7rem; align-items: center; gap: 0.4rem; }
.row .note, .note { grid-column: 1 / -1; color: #868e96; font-size: 0.8rem; }
.value { font-variant-numeric: tabular-nums; text-align: right; }
button { display: block; width: 100%; text-align: left; margin: 0.15rem 0; padding: 0.25rem 0.4rem; border: 1px solid #ced4da; background: #f8f9fa; border-radius: 3px; cursor: pointer; font: inherit; }
button:hover { background: #e9ecef; }
.tools button { display: inline-block; width: auto; }
.legend span { display: inline-block; width: 0.8rem; height: 0.8rem; margin: 0 0.2rem 0 0.6rem; vertical-align: -0.1rem; border-radius: 2px; }
#kinsyn-shown { color: #495057; }
#kinsyn-state, #kinsyn-checks { display: none; }
";

/// The colours of the drawing, as the legend says them (HTML).
pub const LEGEND: &str = "<span style=\"background:#f76707\"></span>input\
    <span style=\"background:#4c6ef5\"></span>passive joint<span style=\"background:#2f9e44\">\
    </span>end-effector<span style=\"background:#343a40\"></span>ground";

/// Where a page's scripts (three.js, its orbit controls, the viewer) come from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scripts<'a> {
    /// In the page, with three.js's licence in a comment: one self-contained file.
    Inline,
    /// `<script src>` references to the files of [`SCRIPT_FILES`] at this relative address
    /// (`../` for a folder above the page, empty for the page's own folder): many pages share
    /// one copy, with no network either.
    Linked(&'a str),
}

/// The files pages with [`Scripts::Linked`] refer to, by name and content, with three.js's
/// licence.
pub const SCRIPT_FILES: [(&str, &str); 4] = [
    ("three.min.js", THREE_JS),
    ("OrbitControls.js", ORBIT_CONTROLS),
    ("viewer.js", VIEWER),
    ("three-LICENSE.txt", THREE_LICENCE),
];

/// The pieces of a view's page that another page can hold (the catalogue site's entry pages):
/// with an element `<div id="kinsyn-canvas">` sized by the page's style, they make the view.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ViewParts {
    /// What is shown and the start and stop buttons.
    pub controls: String,
    /// The input sliders, operation modes and assemblies the script fills in, with their
    /// headings and the view's notes.
    pub lists: String,
    /// The end of the body: the hidden state and check elements, the error collector, the
    /// data and the scripts.
    pub scripts: String,
}

/// The pieces of `view`'s page with its scripts from `scripts`.
///
/// # Panics
/// Never: a view holds only numbers, strings and lists, which always serialise.
#[must_use]
pub fn parts(view: &View, scripts: Scripts) -> ViewParts {
    // The data, as JSON that cannot close the script element holding it.
    let json = serde_json::to_string(view)
        .expect("a view serialises")
        .replace('<', "\\u003c");
    let controls = "<p>Showing: <span id=\"kinsyn-shown\"></span></p>\n<p class=\"tools\">\
         <button id=\"kinsyn-reset\">start</button> <button id=\"kinsyn-stop\">stop</button></p>\n"
        .to_string();
    let mut lists = String::new();
    if !view.inputs.is_empty() {
        let _ = writeln!(
            lists,
            "<p class=\"note\">Inputs at the start: {}</p>",
            escape(&view.inputs.join(", "))
        );
    }
    let _ = writeln!(
        lists,
        "<h2>Inputs</h2>\n<p class=\"note\">Each slider moves one input with the others held.</p>\n\
         <div id=\"kinsyn-sliders\"></div>\n<h2>Operation modes</h2>\n\
         <p class=\"note\">The motion left when the listed inputs are locked; choose one to animate it.</p>\n\
         <div id=\"kinsyn-modes\"></div>\n<h2>Assemblies at these inputs</h2>\n<div id=\"kinsyn-assemblies\"></div>"
    );
    if !view.notes.is_empty() {
        lists.push_str("<h2>Notes</h2>\n");
        for note in &view.notes {
            let _ = writeln!(lists, "<p class=\"note\">{}</p>", escape(note));
        }
    }
    let licence = match scripts {
        Scripts::Inline => "this page's source".to_string(),
        Scripts::Linked(at) => format!(
            "<a href=\"{0}three-LICENSE.txt\">{0}three-LICENSE.txt</a>",
            escape(at)
        ),
    };
    let _ = writeln!(
        lists,
        "<p class=\"note\">Drawn with three.js {THREE_JS_VERSION} (MIT licence, in {licence}).</p>"
    );
    let mut tail = String::with_capacity(json.len() + 1024);
    let _ = writeln!(
        tail,
        "<pre id=\"kinsyn-state\"></pre>\n<pre id=\"kinsyn-checks\"></pre>\n<script>{ERRORS}</script>\n\
         <script type=\"application/json\" id=\"kinsyn-data\">{json}</script>"
    );
    match scripts {
        Scripts::Inline => {
            let _ = writeln!(
                tail,
                "<!-- three.js {THREE_JS_VERSION}, https://threejs.org, licence:\n{}-->",
                THREE_LICENCE.replace("--", "- -")
            );
            for text in [THREE_JS, ORBIT_CONTROLS, VIEWER] {
                let _ = writeln!(tail, "<script>{text}</script>");
            }
        }
        Scripts::Linked(at) => {
            for (name, _) in &SCRIPT_FILES[..3] {
                let _ = writeln!(tail, "<script src=\"{}{name}\"></script>", escape(at));
            }
        }
    }
    ViewParts {
        controls,
        lists,
        scripts: tail,
    }
}

/// The page of `view`: self-contained HTML (no network, no server).
#[must_use]
pub fn page(view: &View) -> String {
    page_with(view, Scripts::Inline)
}

/// The page of `view` with its scripts from `scripts`: self-contained when inline, otherwise
/// beside the files of [`SCRIPT_FILES`] (no network either way).
#[must_use]
pub fn page_with(view: &View, scripts: Scripts) -> String {
    let scene = &view.scene;
    let parts = parts(view, scripts);
    let inline = matches!(scripts, Scripts::Inline);
    let mut out = String::with_capacity(
        if inline { THREE_JS.len() } else { 0 } + parts.scripts.len() + 32_000,
    );
    let title = escape(&scene.name);
    let _ = write!(
        out,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"generator\" content=\"kinsyn {}\">\n<title>{title} — kinsyn view</title>\n\
         <style>{STYLE}</style>\n\
         </head>\n<body>\n<div id=\"kinsyn-canvas\"></div>\n<aside>\n<h1>{title}</h1>\n",
        env!("CARGO_PKG_VERSION")
    );
    let _ = writeln!(
        out,
        "<p>Lengths in {}, angles in {}. Drag to orbit, scroll to zoom, right-drag to pan.</p>",
        escape(&scene.length_unit),
        if scene.angle_unit == "deg" {
            "degrees"
        } else {
            "radians"
        }
    );
    let _ = writeln!(
        out,
        "<p>{}</p>\n<p class=\"legend\">{LEGEND}</p>",
        escape(&view.classification)
    );
    out.push_str(&parts.controls);
    out.push_str(&parts.lists);
    out.push_str("</aside>\n");
    out.push_str(&parts.scripts);
    out.push_str("</body>\n</html>\n");
    out
}
