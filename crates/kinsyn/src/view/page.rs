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

/// The page of `view`: self-contained HTML (no network, no server).
///
/// # Panics
/// Never: a view holds only numbers, strings and lists, which always serialise.
#[must_use]
pub fn page(view: &View) -> String {
    let scene = &view.scene;
    // The data, as JSON that cannot close the script element holding it.
    let json = serde_json::to_string(view)
        .expect("a view serialises")
        .replace('<', "\\u003c");
    let mut out = String::with_capacity(THREE_JS.len() + json.len() + 32_000);
    let title = escape(&scene.name);
    let _ = write!(
        out,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"generator\" content=\"kinsyn {}\">\n<title>{title} — kinsyn view</title>\n\
         <style>{STYLE}</style>\n\
         <script>{ERRORS}</script>\n\
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
        "<p>{}</p>\n<p class=\"legend\"><span style=\"background:#f76707\"></span>input\
         <span style=\"background:#4c6ef5\"></span>passive joint<span style=\"background:#2f9e44\">\
         </span>end-effector<span style=\"background:#343a40\"></span>ground</p>",
        escape(&view.classification)
    );
    let _ = writeln!(
        out,
        "<p>Showing: <span id=\"kinsyn-shown\"></span></p>\n<p class=\"tools\">\
         <button id=\"kinsyn-reset\">start</button> <button id=\"kinsyn-stop\">stop</button></p>"
    );
    if !view.inputs.is_empty() {
        let _ = writeln!(
            out,
            "<p class=\"note\">Inputs at the start: {}</p>",
            escape(&view.inputs.join(", "))
        );
    }
    let _ = writeln!(
        out,
        "<h2>Inputs</h2>\n<p class=\"note\">Each slider moves one input with the others held.</p>\n\
         <div id=\"kinsyn-sliders\"></div>\n<h2>Operation modes</h2>\n\
         <p class=\"note\">The motion left when the listed inputs are locked; choose one to animate it.</p>\n\
         <div id=\"kinsyn-modes\"></div>\n<h2>Assemblies at these inputs</h2>\n<div id=\"kinsyn-assemblies\"></div>"
    );
    if !view.notes.is_empty() {
        out.push_str("<h2>Notes</h2>\n");
        for note in &view.notes {
            let _ = writeln!(out, "<p class=\"note\">{}</p>", escape(note));
        }
    }
    let _ = writeln!(
        out,
        "<p class=\"note\">Drawn with three.js {THREE_JS_VERSION} (MIT licence, in this page's \
         source).</p>\n<pre id=\"kinsyn-state\"></pre>\n<pre id=\"kinsyn-checks\"></pre>\n</aside>"
    );
    let _ = writeln!(
        out,
        "<script type=\"application/json\" id=\"kinsyn-data\">{json}</script>"
    );
    let _ = writeln!(
        out,
        "<!-- three.js {THREE_JS_VERSION}, https://threejs.org, licence:\n{}-->",
        THREE_LICENCE.replace("--", "- -")
    );
    let _ = writeln!(out, "<script>{THREE_JS}</script>");
    let _ = writeln!(out, "<script>{ORBIT_CONTROLS}</script>");
    let _ = writeln!(out, "<script>{VIEWER}</script>\n</body>\n</html>");
    out
}
