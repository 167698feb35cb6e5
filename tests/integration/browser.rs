//! The step page in a real browser, driven from outside as a person would:
//! headless Chromium through WebDriver (Debian's `chromium-driver`), clicking
//! the page's buttons and typing into its boxes. Nothing in the page knows it
//! is being tested.

use std::path::{Path, PathBuf};
use std::process::Command;

use fantoccini::{Client, Locator};
use zsim::step::{Moved, Stepper, judge_depth};
use zsim::{Outcome, Scene};

/// A headless Chromium session that reaches nothing outside this machine.
async fn session(driver: &crate::chromium::Driver, browser: &Path, profile: &Path) -> Client {
    crate::chromium::session_as(driver, browser, profile, "en-US", (1280, 900)).await
}

/// The text of the element `css` finds.
pub async fn text(client: &Client, css: &str) -> String {
    client.find(Locator::Css(css)).await.unwrap().text().await.unwrap()
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

/// The book's scene stepped in the page: Next moves on, the triangle's
/// scanline 15 shows the book's depth 43/4 at (20, 15); in the quiz the grid
/// shows the row before the scanline until the answers are checked, and each
/// typed answer gets the verdict the library's own judge gives it (`15`,
/// `24/2`, `12.0` and `1.1e1` by value; `zz` is no number; `16` and `10.5` no
/// cell of a 4-bit z-buffer can hold; `-` is right for the hidden pixel).
#[test]
fn the_step_page_is_clicked_and_typed_through_as_the_library_judges() {
    let Some((driver, browser)) = crate::chromium::driver() else { return };
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("browser-step");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    // The recorded stepper's page, as `zsim step --html` writes it where zsim was built without the playground.
    let page = dir.join("step.html");
    let scene =
        Scene::load(zsim::Lang::En, &Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/rogers.json")).unwrap();
    let recorded =
        zsim::page::page(zsim::Lang::En, &mut Stepper::new(&scene, zsim::arith::Arith::Exact), "rogers.json");
    std::fs::write(&page, recorded).unwrap();

    // What the library says of each answer, pixel by pixel, on the triangle's scanline 15.
    let mut stepper = Stepper::new(&scene, zsim::arith::Arith::Exact);
    stepper.start(None);
    while stepper.record().is_some_and(|r| r.index != 1 || r.row != 15) {
        assert!(matches!(stepper.forward(), Moved::To { at: Some(_), .. }));
    }
    let pixels = stepper.record().unwrap().pixels.clone();
    let typed = ["15", "10", "zz", "24/2", "12.0", "1.1e1", "-", "16", "10.5", "", "", "", ""];
    let expected: Vec<&str> = pixels
        .iter()
        .zip(typed)
        .map(|(pixel, typed)| match judge_depth(zsim::Lang::En, &scene, pixel, typed) {
            _ if typed.is_empty() => "unanswered",
            Ok((true, ..)) => "right",
            Ok((false, ..)) => "wrong",
            Err(_) => "unanswered",
        })
        .collect();
    assert_eq!(pixels.iter().find(|p| p.x == 21).map(|p| p.outcome), Some(Outcome::Hidden));
    assert_eq!(
        expected,
        ["right", "wrong", "unanswered", "right", "right", "right", "right", "unanswered", "unanswered"]
            .into_iter()
            .chain(["unanswered"; 4])
            .collect::<Vec<_>>(),
        "the library's verdicts this test holds the page to"
    );

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

        click(&client, "#quiz").await;
        click(&client, "#depth").await;
        assert_eq!(
            text(&client, "#raster div").await,
            "z-buffer before this scanline (the quiz: check your answers to see after)"
        );
        assert_eq!(current_row(&client).await, "10 10 10 10 10 10 10 10 10 10 0 0 0", "the grid gives nothing away");
        let inputs = client.find_all(Locator::Css("#pixels input")).await.unwrap();
        assert_eq!(inputs.len(), pixels.len());
        for (input, typed) in inputs.iter().zip(typed) {
            if !typed.is_empty() {
                input.send_keys(typed).await.unwrap();
            }
        }
        click(&client, "#check").await;
        let mut verdicts = Vec::new();
        for cell in client.find_all(Locator::Css("#pixels td.why")).await.unwrap() {
            let class = cell.attr("class").await.unwrap().unwrap_or_default();
            verdicts.push(class.trim_start_matches("why ").to_string());
        }
        assert_eq!(verdicts, expected, "the page's verdicts are the library's");
        assert_eq!(text(&client, "#raster div").await, "z-buffer after this scanline");
        assert_eq!(current_row(&client).await, "15 14 13 12 12 11 10 10 10 10 7 6 6");
        assert_eq!(text(&client, "#status").await, "quiz: 5 of 13 right on this scanline");
        let shot = client.screenshot().await.unwrap();
        std::fs::write(dir.join("quiz-1280.png"), shot).unwrap();
        client.close().await.unwrap();
    });
    let version = Command::new(&browser).arg("--version").output().map(|o| o.stdout).unwrap_or_default();
    crate::ran("the step page through WebDriver", String::from_utf8_lossy(&version).trim());
}
