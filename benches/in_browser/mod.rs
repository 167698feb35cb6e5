//! What the browser benchmarks share: headless Chromium through WebDriver
//! (the browser tests' own driver), the site `web/build` writes, and medians.

use std::path::{Path, PathBuf};

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

/// A headless Chromium session (a fresh profile, `profile`) on the site
/// served at `port`, once the playground has drawn the book's scene.
pub async fn playground(driver: &chromium::Driver, browser: &Path, port: u16, profile: &str) -> fantoccini::Client {
    let profile = Path::new(env!("CARGO_TARGET_TMPDIR")).join(profile);
    let _ = std::fs::remove_dir_all(&profile);
    let client = chromium::session_as(driver, browser, &profile, "en-US", (1280, 900)).await;
    client.goto(&format!("http://127.0.0.1:{port}/")).await.unwrap();
    for _ in 0..600 {
        let shown = client.execute("return document.getElementById('framebuffer').textContent.length;", vec![]);
        if shown.await.unwrap().as_u64().unwrap_or(0) > 0 {
            break;
        }
        tokio::time::sleep(std::time::Duration::from_millis(50)).await;
    }
    client
}
