//! Headless Chromium for the tests of pages kinsyn writes (the catalogue site, the 3D view).
//!
//! Chromium is required in CI (`CI` set; `.ci/run` sets it and installs Chromium): without it
//! the tests that need it fail there. Elsewhere a missing Chromium prints a notice and the test
//! passes, like the other external tools' checks (Singular, PHCpack). Debian: `apt-get install
//! chromium`. WebGL runs on `SwiftShader`, Chromium's software renderer, so no GPU is needed.

use std::path::{Path, PathBuf};
use std::process::Command;

/// The Chromium binary on PATH, or `None` when it may be absent (module documentation);
/// `test` names the test in the notice.
pub fn chromium(test: &str) -> Option<PathBuf> {
    let found = std::env::var_os("PATH").and_then(|paths| {
        std::env::split_paths(&paths).find_map(|dir| {
            ["chromium", "chromium-browser", "google-chrome"]
                .iter()
                .map(|name| dir.join(name))
                .find(|p| p.is_file())
        })
    });
    if found.is_none() {
        assert!(
            std::env::var_os("CI").is_none(),
            "chromium is not installed: {test} needs it in CI (apt-get install chromium)"
        );
        eprintln!("NOTICE: chromium not found; {test} did not run (apt-get install chromium)");
    }
    found
}

/// The flags of every run: headless, software WebGL, a fixed window, ten seconds of virtual
/// time for the page's scripts.
const FLAGS: [&str; 6] = [
    "--headless",
    "--no-sandbox",
    "--use-angle=swiftshader",
    "--enable-unsafe-swiftshader",
    "--window-size=1200,800",
    "--virtual-time-budget=10000",
];

/// The DOM of `url` after its scripts ran, as Chromium serialises it.
pub fn dump_dom(chromium: &Path, url: &str) -> String {
    let out = Command::new(chromium)
        .args(FLAGS)
        .args(["--dump-dom", url])
        .output()
        .expect("run chromium");
    assert!(out.status.success(), "chromium failed on {url}");
    String::from_utf8(out.stdout).unwrap()
}

/// A screenshot of `url` (1200 × 800) written to `png`.
pub fn screenshot(chromium: &Path, url: &str, png: &Path) {
    let out = Command::new(chromium)
        .args(FLAGS)
        .arg(format!("--screenshot={}", png.display()))
        .arg(url)
        .output()
        .expect("run chromium");
    assert!(
        out.status.success() && png.is_file(),
        "chromium took no screenshot of {url}"
    );
}

/// The address of a file in `dir`.
pub fn url(dir: &Path, page: &str) -> String {
    format!("file://{}/{page}", dir.display())
}

/// The states of a 3D view page (`kinsyn view`, a catalogue entry page) `page` in `dir` after
/// it loaded and showed each of `items` in turn (`mode:K:F`, `sweep:K:F`, `assembly:K`,
/// `start:0`), from its hidden `kinsyn-checks` element: none with an error, the mechanism on
/// screen in each.
pub fn view_states(
    chromium: &Path,
    dir: &Path,
    page: &str,
    items: &[String],
) -> Vec<serde_json::Value> {
    let hash = format!("check={}", items.join(","));
    let dom = dump_dom(chromium, &format!("{}#{hash}", url(dir, page)));
    let start = dom
        .find("<pre id=\"kinsyn-checks\">")
        .expect("the checks element")
        + 24;
    let text = &dom[start..start + dom[start..].find("</pre>").unwrap()];
    let states: Vec<serde_json::Value> =
        serde_json::from_str(&text.replace("&quot;", "\"").replace("&amp;", "&"))
            .unwrap_or_else(|e| panic!("{page}#{hash}: checks {text:?}: {e}"));
    assert_eq!(states.len(), items.len(), "{page}#{hash}");
    for (s, item) in states.iter().zip(items) {
        assert_eq!(s["errors"], serde_json::json!([]), "{page} {item}: errors");
        assert_eq!(
            s["bounding_box_on_screen"],
            serde_json::Value::Bool(true),
            "{page} {item}: the mechanism is off screen"
        );
    }
    states
}

/// A JSON array of numbers.
pub fn numbers(v: &serde_json::Value) -> Vec<f64> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect()
}

/// A screenshot's pixels (RGB).
pub struct Screenshot {
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
    rgb: Vec<[u8; 3]>,
}

impl Screenshot {
    /// The PNG file `png`.
    pub fn read(png: &Path) -> Self {
        let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(png).unwrap()));
        let mut reader = decoder.read_info().unwrap();
        let mut buf = vec![0; reader.output_buffer_size()];
        let info = reader.next_frame(&mut buf).unwrap();
        let channels = info.line_size / info.width as usize;
        let (width, height) = (info.width as usize, info.height as usize);
        let rgb = (0..height)
            .flat_map(|y| (0..width).map(move |x| (y, x)))
            .map(|(y, x)| {
                let p = &buf[y * info.line_size + x * channels..][..3];
                [p[0], p[1], p[2]]
            })
            .collect();
        Screenshot { width, height, rgb }
    }

    /// The pixel at column `x`, row `y`.
    pub fn at(&self, x: usize, y: usize) -> [u8; 3] {
        self.rgb[y * self.width + x]
    }

    /// The share of the pixels in the rectangle whose colour differs from the view's background
    /// (#f8f9fa) by more than 40 in a channel: what is drawn there.
    pub fn drawn_share(
        &self,
        columns: std::ops::Range<usize>,
        rows: std::ops::Range<usize>,
    ) -> f64 {
        let background = [0xf8u8, 0xf9, 0xfa];
        let total = columns.len() * rows.len();
        let drawn = rows
            .flat_map(|y| columns.clone().map(move |x| (x, y)))
            .filter(|&(x, y)| {
                self.at(x, y)
                    .iter()
                    .zip(background)
                    .any(|(a, b)| a.abs_diff(b) > 40)
            })
            .count();
        drawn as f64 / total as f64
    }
}
