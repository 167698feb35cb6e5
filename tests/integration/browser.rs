//! The step page in a real browser, driven from outside as a person would:
//! headless Chromium through WebDriver (Debian's `chromium-driver`), clicking
//! the page's buttons and typing into its boxes. Nothing in the page knows it
//! is being tested.

use std::path::{Path, PathBuf};
use std::process::Command;

use fantoccini::{Client, Locator};
use zsim::Scene;
use zsim::step::Stepper;

/// A headless Chromium session that reaches nothing outside this machine.
async fn session(driver: &crate::chromium::Driver, browser: &Path, profile: &Path) -> Client {
    crate::chromium::session_as(driver, browser, profile, "en-US", (1280, 900)).await
}

/// The text of the element `css` finds.
pub async fn text(client: &Client, css: &str) -> String {
    client.find(Locator::Css(css)).await.unwrap().text().await.unwrap()
}

/// The text of the element `css` finds once `ready` holds of it (waited for
/// up to five seconds; the last text read otherwise).
pub async fn text_when(client: &Client, css: &str, ready: impl Fn(&str) -> bool) -> String {
    for _ in 0..100 {
        let shown = text(client, css).await;
        if ready(&shown) {
            return shown;
        }
        tokio::time::sleep(std::time::Duration::from_millis(50)).await;
    }
    text(client, css).await
}

/// Clicks the element `css` finds.
pub async fn click(client: &Client, css: &str) {
    client.find(Locator::Css(css)).await.unwrap().click().await.unwrap();
}

/// The grid's current row, columns 15 … 27 (the triangle's span on row 15).
async fn current_row(client: &Client) -> String {
    let cells = client.find_all(Locator::Css("#raster tr.current td")).await.unwrap();
    let mut values = Vec::new();
    for cell in &cells[15..28] {
        values.push(cell.text().await.unwrap());
    }
    values.join(" ")
}

/// The book's scene stepped in the recorded page (what `zsim step --html`
/// writes where zsim was built without the playground): Next moves on, the
/// triangle's scanline 15 shows the book's depth 43/4 at (20, 15), and the
/// page asks nothing: no box to type an answer in, one line saying where
/// the quiz is, and no rule of the library in its script.
#[test]
#[ignore = "needs Chromium and chromedriver"]
fn the_recorded_step_page_is_clicked_through_and_asks_nothing() {
    let (driver, browser) = crate::chromium::driver();
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("browser-step");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let page = dir.join("step.html");
    let scene = Scene::load(&Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/rogers.json")).unwrap();
    let recorded =
        zsim::page::page(zsim::Lang::En, &mut Stepper::new(&scene, zsim::arith::Arith::Exact), "rogers.json");
    for judging in ["BigInt", "function judge", "<input"] {
        assert!(!recorded.contains(judging), "the recorded page judges nothing: it has {judging:?}");
    }
    std::fs::write(&page, recorded).unwrap();
    let runtime = tokio::runtime::Builder::new_current_thread().enable_all().build().unwrap();
    runtime.block_on(async {
        let client = session(&driver, &browser, &dir.join("profile")).await;
        client.goto(&format!("file://{}", page.display())).await.unwrap();
        assert_eq!(text(&client, "#panel p").await, "scanline y = 5.5 (row 5)");
        click(&client, "#next").await;
        assert_eq!(text(&client, "#panel p").await, "scanline y = 6.5 (row 6)", "a click on Next moves on");
        click(&client, "#nextPolygon").await;
        for _ in 0..40 {
            if text(&client, "#panel p").await == "scanline y = 15.5 (row 15)" {
                break;
            }
            click(&client, "#next").await;
        }
        assert_eq!(text(&client, "#panel p").await, "scanline y = 15.5 (row 15)");
        let panel = text(&client, "#panel").await;
        assert!(panel.contains("43/4 ≈ 10.75"), "pixel (20, 15): {panel}");
        assert!(panel.contains("z = 43/4 ≈ 10.75 > 10 stored, so 11 is stored"), "{panel}");

        click(&client, "#depth").await;
        assert_eq!(text(&client, "#raster div").await, "z-buffer after this scanline");
        assert_eq!(current_row(&client).await, "15 14 13 12 12 11 10 10 10 10 7 6 6");
        assert!(client.find_all(Locator::Css("input")).await.unwrap().is_empty(), "nothing to type an answer in");
        let no_quiz = text(&client, "#noQuiz").await;
        assert_eq!(no_quiz, zsim::message(zsim::Lang::En, "quiz-not-on-recorded-steps", &[]));
        std::fs::write(dir.join("recorded-1280.png"), client.screenshot().await.unwrap()).unwrap();
        client.close().await.unwrap();
    });
    let version = Command::new(&browser).arg("--version").output().map(|o| o.stdout).unwrap_or_default();
    crate::ran("the step page through WebDriver", String::from_utf8_lossy(&version).trim());
}
