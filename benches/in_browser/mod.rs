//! What the browser benchmarks share: headless Chromium through WebDriver
//! (the browser tests' own driver), the site `web/build` writes, and medians.

use std::path::PathBuf;

#[path = "../../tests/integration/chromium.rs"]
pub mod chromium;

/// What the measurement needs is missing.
pub fn missing(what: &str, check: &str) -> ! {
    panic!("{what} is missing, so {check} cannot be measured")
}

/// The site `web/build` wrote.
pub fn site() -> PathBuf {
    let site = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target/web");
    assert!(site.join("zsim_web_bg.wasm").is_file(), "run web/build first");
    site
}

/// The median of `values`.
pub fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}
