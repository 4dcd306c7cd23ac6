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
