//! The browser playground (`web/build`'s site in `target/web/`, and the one
//! file `zsim step --html` writes) in headless Chromium, driven from outside
//! through WebDriver as a person would: typing into the vertex table,
//! dragging a vertex on the grid, opening scenes through `#scene=`, ticking
//! the quiz and pasting a homework answer. Every buffer it shows is held to
//! what the native `zsim run --final` prints, every verdict to the library's.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

use fantoccini::actions::{InputSource, MOUSE_BUTTON_LEFT, MouseActions, PointerAction};
use fantoccini::key::Key;
use fantoccini::{Client, Locator};
use zsim::Lang;
use zsim::playground;

use crate::browser::{click, text, text_when};
use crate::chromium::{Driver, driver, serve, session_as};

pub(crate) fn manifest() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The site `web/build` wrote.
pub(crate) fn site() -> PathBuf {
    let site = manifest().join("target/web");
    if !(site.join("index.html").is_file() && site.join("zsim_web_bg.wasm").is_file()) {
        crate::missing("the playground's site (web/build writes it into target/web)", "the browser playground");
    }
    site
}

/// The site served on loopback, a browser to open it with and a scratch
/// folder `name`.
fn served(name: &str) -> (Driver, PathBuf, PathBuf, u16) {
    let site = site();
    let (driver, browser) = driver();
    (driver, browser, scratch(name), serve(site))
}

pub(crate) fn runtime() -> tokio::runtime::Runtime {
    tokio::runtime::Builder::new_current_thread().enable_all().build().unwrap()
}

/// The final buffers `zsim run --final` prints for `scene`, bare: (framebuffer, z-buffer).
pub(crate) fn run_final(scene: &str, scratch: &Path) -> (String, String) {
    let file = scratch.join("scene.json");
    std::fs::write(&file, scene).unwrap();
    let output =
        Command::new(env!("CARGO_BIN_EXE_zsim")).args(["run", "--final", "--lang", "en"]).arg(&file).output().unwrap();
    assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
    let stdout = String::from_utf8(output.stdout).unwrap();
    let matrix = |heading: &str| {
        let start = stdout.find(heading).unwrap_or_else(|| panic!("{heading} in {stdout}"));
        let body = &stdout[start..];
        let body = &body[body.find('\n').unwrap() + 1..];
        let end = body.find("\n\n").unwrap_or(body.len());
        format!("{}\n", body[..end].trim_end_matches('\n'))
    };
    (matrix("framebuffer after"), matrix("z-buffer after"))
}

/// Waits until the page shows a final framebuffer, and returns both buffers as the page holds them.
pub(crate) async fn shown_buffers(client: &Client) -> (String, String) {
    let start = Instant::now();
    loop {
        let frame = inner_text(client, "framebuffer").await;
        if !frame.is_empty() {
            return (frame, inner_text(client, "zbuffer").await);
        }
        assert!(start.elapsed() < Duration::from_secs(30), "the page showed no framebuffer within 30 s");
        tokio::time::sleep(Duration::from_millis(50)).await;
    }
}

/// An element's text exactly as it is in the page (a `<pre>`'s spaces and its last newline kept).
pub(crate) async fn inner_text(client: &Client, id: &str) -> String {
    let script = format!("const e = document.getElementById('{id}'); return e ? e.textContent : '';");
    client.execute(&script, vec![]).await.unwrap().as_str().unwrap_or_default().to_string()
}

pub(crate) async fn scene_text(client: &Client) -> String {
    client.execute("return document.getElementById('json').value;", vec![]).await.unwrap().as_str().unwrap().to_string()
}

/// Types `value` into vertex `vertex`'s coordinate `coordinate` of polygon `polygon` (0-based) and leaves the box.
pub(crate) async fn type_vertex(client: &Client, polygon: usize, vertex: usize, coordinate: usize, value: &str) {
    let css = format!("input.coord[data-p='{polygon}'][data-v='{vertex}'][data-c='{coordinate}']");
    let input = client.find(Locator::Css(&css)).await.unwrap();
    input.clear().await.unwrap();
    input.send_keys(&format!("{value}\u{e004}")).await.unwrap();
}

pub(crate) fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The book's scene, edited by typing a vertex and by dragging one, and
/// random scenes opened through `#scene=`: after each, the page's final
/// buffers are exactly what the native `zsim run --final` prints for the
/// scene the page holds.
#[test]
#[ignore = "needs Chromium, chromedriver and web/build's site (target/web)"]
fn the_playground_shows_what_run_final_prints_as_a_scene_is_typed_dragged_and_linked() {
    let (driver, browser, dir, port) = served("playground-edit");
    let mut random_scenes = Vec::new();
    for seed in 1..=6 {
        let output = Command::new(env!("CARGO_BIN_EXE_zsim"))
            .args(["random", "--count", "6", "--width", "24", "--height", "20", "--depth-bits", "6", "--seed"])
            .arg(seed.to_string())
            .output()
            .unwrap();
        assert!(output.status.success());
        random_scenes.push(String::from_utf8(output.stdout).unwrap());
    }
    let runtime = runtime();
    runtime.block_on(async {
        let client = session_as(&driver, &browser, &dir.join("profile"), "en-US", (1280, 900)).await;
        client.goto(&format!("http://127.0.0.1:{port}/")).await.unwrap();
        let book = std::fs::read_to_string(manifest().join("examples/rogers.json")).unwrap();
        assert_eq!(shown_buffers(&client).await, run_final(&book, &dir), "the book's scene");

        // Typed: the triangle's first vertex moves from x = 15 to x = 12.
        type_vertex(&client, 1, 0, 0, "12").await;
        let typed = scene_text(&client).await;
        assert!(typed.contains("[[12, 15, 15], [25, 25, 5], [30, 10, 5]]"), "{typed}");
        let expected = run_final(&typed, &dir);
        assert_ne!(expected, run_final(&book, &dir), "the edit changes the picture");
        assert_eq!(shown_buffers(&client).await, expected, "after typing a vertex");

        // Dragged: the triangle's third vertex, (30, 10), moved on the grid.
        let handle = client.find(Locator::Css("circle.vertex[data-p='1'][data-v='2']")).await.unwrap();
        let grid = client.find(Locator::Css("#grid")).await.unwrap();
        let (_, _, width, _) = grid.rectangle().await.unwrap();
        let cell = width / 32.0;
        let actions = MouseActions::new("mouse".to_string())
            .then(PointerAction::MoveToElement { element: handle, duration: None, x: 0.0, y: 0.0 })
            .then(PointerAction::Down { button: MOUSE_BUTTON_LEFT })
            .then(PointerAction::MoveBy {
                duration: Some(Duration::from_millis(100)),
                x: -(3.0 * cell),
                y: -(4.0 * cell),
            })
            .then(PointerAction::Up { button: MOUSE_BUTTON_LEFT });
        client.perform_actions(actions).await.unwrap();
        let dragged = scene_text(&client).await;
        assert!(!dragged.contains("[30, 10, 5]"), "the vertex moved: {dragged}");
        assert!(dragged.contains("[27, 14, 5]"), "three cells left and four up, snapped to whole pixels: {dragged}");
        assert_eq!(shown_buffers(&client).await, run_final(&dragged, &dir), "after dragging a vertex");

        // Linked: each random scene opened through #scene=, as a teacher's link opens it.
        for scene in &random_scenes {
            let address = format!("http://127.0.0.1:{port}/#{}", playground::fragment_of(scene));
            client.goto("about:blank").await.unwrap();
            client.goto(&address).await.unwrap();
            assert_eq!(shown_buffers(&client).await, run_final(scene, &dir), "a random scene through #scene=");
            assert_eq!(scene_text(&client).await, *scene, "the page holds the linked scene as sent");
        }
        client.close().await.unwrap();
    });
    crate::ran("the playground's edits and links through WebDriver", &format!("{} random scenes", random_scenes.len()));
}

/// A pasted and a typed homework answer and a pixel's history: each verdict
/// the page shows is `zsim check`'s, the homework's misconception the one
/// it names for the same file, the history `zsim explain`'s. (The quiz is
/// the lesson's: `lesson.rs`.)
#[test]
#[ignore = "needs Chromium, chromedriver and web/build's site (target/web)"]
fn the_playground_checks_a_homework_as_check_does() {
    let (driver, browser, dir, port) = served("playground-homework");
    let book = std::fs::read_to_string(manifest().join("examples/rogers.json")).unwrap();
    // A homework drawn with the depth test the wrong way round, and zsim check's verdict on it.
    let reversed = book.replace(r#""depth_test": "greater""#, r#""depth_test": "less""#);
    let (_, answer) = run_final(&reversed, &dir);
    std::fs::write(dir.join("depth.txt"), &answer).unwrap();
    std::fs::write(dir.join("book.json"), &book).unwrap();
    let checked = Command::new(env!("CARGO_BIN_EXE_zsim"))
        .args(["check", "--lang", "en", "book.json", "--depth", "depth.txt"])
        .current_dir(&dir)
        .output()
        .unwrap();
    assert_eq!(checked.status.code(), Some(1));
    let report = String::from_utf8(checked.stdout).unwrap();
    let verdict_line = report.lines().next().unwrap().replace("depth.txt", "your answer");
    let diagnosis = report.lines().last().unwrap().to_string();

    // Named as the page names the scene it holds.
    std::fs::write(dir.join("the scene"), &book).unwrap();
    let explain = Command::new(env!("CARGO_BIN_EXE_zsim"))
        .args(["explain", "--lang", "en", "the scene", "--pixel", "20,15"])
        .current_dir(&dir)
        .output()
        .unwrap();
    assert!(explain.status.success());
    let explained = String::from_utf8(explain.stdout).unwrap();
    assert!(explained.contains("43/4 ≈ 10.75 > 10 stored, so 11 is stored"), "{explained}");
    let runtime = runtime();
    runtime.block_on(async {
        let client = session_as(&driver, &browser, &dir.join("profile"), "en-US", (1280, 900)).await;
        client.goto(&format!("http://127.0.0.1:{port}/")).await.unwrap();
        shown_buffers(&client).await;
        // A click on pixel (20, 15) shows its history as `zsim explain` prints it (the scene named as the page names it).
        client.find(Locator::Css("rect.cell[data-x='20'][data-y='15']")).await.unwrap().click().await.unwrap();
        assert_eq!(inner_text(&client, "explain").await, explained, "the pixel's history");

        // The homework, pasted as the book prints it.
        client.find(Locator::Css("#hwBuffer option[value='depth']")).await.unwrap().click().await.unwrap();
        let answer_box = client.find(Locator::Css("#answer")).await.unwrap();
        answer_box.send_keys(&answer).await.unwrap();
        click(&client, "#checkAnswer").await;
        assert_eq!(text(&client, "#verdict p").await, verdict_line, "check's verdict");
        assert_eq!(text(&client, "#diagnosis").await, diagnosis, "check's misconception");
        let rows = client.find_all(Locator::Css("#wrongCells tr")).await.unwrap();
        let wrong_in_report = report.lines().filter(|l| l.starts_with("| ") && !l.starts_with("| x")).count();
        assert!(wrong_in_report > 0 && rows.len() > 1, "{report}");

        // Typed into the grid instead: the cleared framebuffer, two cells filled in, checked as zsim check checks it.
        client.execute("document.getElementById('answer').value = '';", vec![]).await.unwrap();
        client.find(Locator::Css("#hwBuffer option[value='frame']")).await.unwrap().click().await.unwrap();
        click(&client, "#answerGrid").await;
        for (x, y, value) in [(20, 15, "2"), (10, 5, "1")] {
            let cell =
                client.find(Locator::Css(&format!("#answerCells input[data-x='{x}'][data-y='{y}']"))).await.unwrap();
            cell.clear().await.unwrap();
            cell.send_keys(value).await.unwrap();
        }
        let typed_answer = client.execute("return document.getElementById('answer').value;", vec![]).await.unwrap();
        let typed_answer = typed_answer.as_str().unwrap().to_string();
        let rows: Vec<&str> = typed_answer.lines().collect();
        assert_eq!(rows.len(), 32);
        assert_eq!(rows[31 - 15].split(' ').nth(20), Some("2"), "{typed_answer}");
        assert_eq!(rows[31 - 5].split(' ').nth(10), Some("1"), "{typed_answer}");
        std::fs::write(dir.join("frame.txt"), &typed_answer).unwrap();
        let checked = Command::new(env!("CARGO_BIN_EXE_zsim"))
            .args(["check", "--lang", "en", "book.json", "--frame", "frame.txt"])
            .current_dir(&dir)
            .output()
            .unwrap();
        let report = String::from_utf8(checked.stdout).unwrap();
        click(&client, "#checkAnswer").await;
        assert_eq!(
            text(&client, "#verdict p").await,
            report.lines().next().unwrap().replace("frame.txt", "your answer")
        );
        client.close().await.unwrap();
    });
    crate::ran("the playground's homework through WebDriver", "two answers");
}

/// A student's link from `exercise --roster --site` opens their scene with
/// the quiz on and names their variant; the homework they type is saved as
/// the file `grade --variants` reads, which scores it as the page did.
#[test]
#[ignore = "needs Chromium, chromedriver and web/build's site (target/web)"]
fn a_students_link_saves_the_homework_that_grade_scores_as_the_page_did() {
    let (driver, browser, dir, port) = served("playground-course");
    std::fs::write(dir.join("roster.txt"), "ana@uni.edu\nbo@uni.edu\n").unwrap();
    let site = format!("http://127.0.0.1:{port}/");
    let made = Command::new(env!("CARGO_BIN_EXE_zsim"))
        .args(["exercise", "--roster", "roster.txt", "--hand-in", "frame", "--site", &site, "-o", "out"])
        .current_dir(&dir)
        .output()
        .unwrap();
    assert!(made.status.success(), "{}", String::from_utf8_lossy(&made.stderr));
    let hand_in = std::fs::read_to_string(dir.join("out/students/ana@uni.edu/hand-in.txt")).unwrap();
    let link = hand_in.lines().find_map(|l| l.split_once("with questions: ")).unwrap().1.to_string();
    let manifest: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("out/variants.json")).unwrap()).unwrap();
    let code = manifest["students"][0]["code"].as_str().unwrap().to_string();
    // Ana's framebuffer with the first two cells of the top row wrong.
    let key = std::fs::read_to_string(dir.join("out/keys/ana@uni.edu.frame.txt")).unwrap();
    let mut rows: Vec<String> = key.lines().filter(|l| !l.starts_with('#')).map(str::to_string).collect();
    let mut top: Vec<&str> = rows[0].split_whitespace().collect();
    top[0] = "3";
    top[1] = "3";
    rows[0] = top.join(" ");
    let answer = rows.join("\n") + "\n";
    let downloads = dir.join("profile/downloads");
    let shown_score = runtime().block_on(async {
        let client = session_as(&driver, &browser, &dir.join("profile"), "en-US", (1280, 900)).await;
        client.goto(&link).await.unwrap();
        shown_buffers(&client).await;
        let line = text_when(&client, "#variantLine", |t| !t.is_empty()).await;
        assert_eq!(line, format!("Your variant: {code} (ana@uni.edu)"));
        assert!(client.find(Locator::Css("#quiz")).await.unwrap().is_selected().await.unwrap(), "the quiz is on");
        client.find(Locator::Css("#hwBuffer option[value='frame']")).await.unwrap().click().await.unwrap();
        client.find(Locator::Css("#answer")).await.unwrap().send_keys(&answer).await.unwrap();
        click(&client, "#checkAnswer").await;
        let score = text_when(&client, "#hwScore", |t| t.starts_with("score ")).await;
        click(&client, "#saveAnswer").await;
        let saved = downloads.join("ana@uni.edu.frame.txt");
        let start = Instant::now();
        while !saved.is_file() && start.elapsed() < Duration::from_secs(20) {
            tokio::time::sleep(Duration::from_millis(100)).await;
        }
        // Not saved: what the page said instead (a refusal shows in the verdict), and what it downloaded.
        let said = if saved.is_file() { String::new() } else { text(&client, "#verdict").await };
        client.close().await.unwrap();
        let downloaded: Vec<_> =
            std::fs::read_dir(&downloads).map_or(Vec::new(), |d| d.flatten().map(|e| e.file_name()).collect());
        assert!(
            saved.is_file(),
            "no {} after 20 s; the page said {said:?}; downloaded {downloaded:?}",
            saved.display()
        );
        score
    });
    std::fs::create_dir_all(dir.join("class")).unwrap();
    std::fs::copy(downloads.join("ana@uni.edu.frame.txt"), dir.join("class/ana@uni.edu.frame.txt")).unwrap();
    let saved = std::fs::read_to_string(dir.join("class/ana@uni.edu.frame.txt")).unwrap();
    assert!(saved.starts_with(&format!("# variant {code}\n")), "{saved}");
    let graded = Command::new(env!("CARGO_BIN_EXE_zsim"))
        .args(["grade", "--variants", "out/variants.json", "class", "--format", "csv"])
        .current_dir(&dir)
        .output()
        .unwrap();
    let csv = String::from_utf8(graded.stdout).unwrap();
    let ana = csv.lines().find(|l| l.starts_with("ana@uni.edu,")).unwrap();
    let score = ana.split(',').nth(4).unwrap();
    assert!(score != "100.0" && score != "0.0", "{csv}");
    assert_eq!(shown_score, format!("score {score} %"), "the page's score and grade's");
    crate::ran("a student's link, saved and graded", &format!("score {score}"));
}

/// Found by a student: with the quiz on, the page showed what it asked: the
/// asked pixel's history on a click, the final buffers and the buffers after
/// each polygon. While a question is open they are hidden, the library's
/// words in their place; once the scanline's questions are skipped, the
/// final buffers are `run --final`'s and the clicked pixel's history shows.
#[test]
#[ignore = "needs Chromium, chromedriver and web/build's site (target/web)"]
fn while_a_question_is_open_the_page_shows_nothing_that_answers_it() {
    let (driver, browser, dir, port) = served("playground-quiz-hidden");
    let book = std::fs::read_to_string(manifest().join("examples/rogers.json")).unwrap();
    let (frame, _) = run_final(&book, &dir);
    let hidden = "hidden until this scanline's questions are answered or skipped";
    runtime().block_on(async {
        let client = session_as(&driver, &browser, &dir.join("profile"), "en-US", (1280, 900)).await;
        client.goto(&format!("http://127.0.0.1:{port}/#polygon=2&scanline=15&quiz=depth")).await.unwrap();
        text_when(&client, "#prompt", |t| t.contains("pixel (15, 15)")).await;
        for id in ["framebuffer", "zbuffer", "afterFrame", "afterDepth"] {
            assert_eq!(inner_text(&client, id).await, hidden, "#{id} while (15, 15) is asked");
        }
        // (20, 15), asked later on this scanline (the crossing's mark lies over (15, 15)).
        client.find(Locator::Css("rect.cell[data-x='20'][data-y='15']")).await.unwrap().click().await.unwrap();
        assert_eq!(text_when(&client, "#explain", |t| !t.is_empty()).await, hidden);
        click(&client, "#skip").await;
        let start = Instant::now();
        while inner_text(&client, "framebuffer").await == hidden && start.elapsed() < Duration::from_secs(10) {
            tokio::time::sleep(Duration::from_millis(50)).await;
        }
        assert_eq!(inner_text(&client, "framebuffer").await, frame, "the final framebuffer, once nothing is asked");
        let history = text_when(&client, "#explain", |t| t.contains("43/4")).await;
        assert!(history.contains("43/4 ≈ 10.75 > 10 stored, so 11 is stored"), "{history}");
        client.close().await.unwrap();
    });
    crate::ran("the page while a question is open", "the book's (20, 15)");
}

/// Found by a maintainer: the page showed `depth_test || "greater"`, its own
/// default, though a `"rules": "buet"` scene draws with `less`. The fields
/// show the settings as the library draws the scene.
#[test]
#[ignore = "needs Chromium, chromedriver and web/build's site (target/web)"]
fn the_pages_fields_show_the_settings_as_the_library_draws_the_scene() {
    let (driver, browser, dir, port) = served("playground-settings");
    let buet = r#"{"width": 8, "height": 4, "rules": "buet", "polygons": [{"value": 1, "vertices": [[0, 0, 1], [8, 0, 1], [0, 4, 1]]}]}"#;
    runtime().block_on(async {
        let client = session_as(&driver, &browser, &dir.join("profile"), "en-US", (1280, 900)).await;
        client.goto(&format!("http://127.0.0.1:{port}/#{}", playground::fragment_of(buet))).await.unwrap();
        shown_buffers(&client).await;
        let value = |id: &'static str| {
            let client = client.clone();
            async move {
                let script = format!("return document.getElementById('{id}').value;");
                client.execute(&script, vec![]).await.unwrap().as_str().unwrap().to_string()
            }
        };
        assert_eq!(value("depthTest").await, "less", "buet's depth test");
        assert_eq!((value("width").await, value("frameBits").await), ("8".to_string(), "2".to_string()));
        client.close().await.unwrap();
    });
}

/// Found by a student: `#pixel=0,32` (one past the book's raster) panicked
/// the module and the page stopped answering until a reload. It is said as
/// `zsim explain` says it, and the page still answers a click.
#[test]
#[ignore = "needs Chromium, chromedriver and web/build's site (target/web)"]
fn a_pixel_off_the_raster_in_the_address_is_said_and_the_page_keeps_answering() {
    let (driver, browser, dir, port) = served("playground-off-raster");
    runtime().block_on(async {
        let client = session_as(&driver, &browser, &dir.join("profile"), "en-US", (1280, 900)).await;
        client.goto(&format!("http://127.0.0.1:{port}/#pixel=0,32")).await.unwrap();
        shown_buffers(&client).await;
        let said = text_when(&client, "#explain", |t| !t.is_empty()).await;
        assert_eq!(said, "pixel (0, 32) is outside the 32×32 raster (x 0 … 31, y 0 … 31)");
        client.find(Locator::Css("rect.cell[data-x='20'][data-y='15']")).await.unwrap().click().await.unwrap();
        let history = text_when(&client, "#explain", |t| t.contains("43/4")).await;
        assert!(history.contains("43/4 ≈ 10.75 > 10 stored, so 11 is stored"), "{history}");
        client.close().await.unwrap();
    });
    crate::ran("a pixel off the raster in the page's address", "#pixel=0,32");
}

/// A Russian browser gets the page in Russian, errors included; screenshots
/// at 1280 and 360 pixels wide are saved for a person to look at, and at 360
/// nothing is wider than the window.
#[test]
#[ignore = "needs Chromium, chromedriver and web/build's site (target/web)"]
fn a_russian_browser_gets_russian_and_a_phone_gets_a_page_that_fits() {
    let (driver, browser, dir, port) = served("playground-lang");
    let runtime = runtime();
    runtime.block_on(async {
        let client = session_as(&driver, &browser, &dir.join("profile-ru"), "ru-RU", (1280, 900)).await;
        client.goto(&format!("http://127.0.0.1:{port}/")).await.unwrap();
        shown_buffers(&client).await;
        let words = playground::page_words(Lang::Ru);
        assert_eq!(text(&client, "#title").await, words["title"].as_str().unwrap());
        let bad = r#"{"width": 32, "height": 32, "polygons": [{"value": 1, "vertices": [[1, 2, 3], [4, 5]]}]}"#;
        client
            .execute(
                &format!(
                    "const j = document.getElementById('json'); j.value = {bad:?}; j.dispatchEvent(new Event('input'));"
                ),
                vec![],
            )
            .await
            .unwrap();
        let error = playground::view(Lang::Ru, bad)["error"].as_str().unwrap().to_string();
        // Under it, the JSON's line it is on, quoted.
        assert_eq!(text(&client, "#error").await, format!("{error}\nстрока 1: {bad}"), "the scene's error in Russian");
        assert!(error.contains("вершин"), "{error}");
        // A scene larger than the page draws, linked: refused in one line that names the limit.
        let huge = r#"{"width": 4096, "height": 4096, "polygons": [{"value": 1, "vertices": [[0, 0, 1], [9, 0, 1], [0, 9, 1]]}]}"#;
        client.goto(&format!("http://127.0.0.1:{port}/#{}", playground::fragment_of(huge))).await.unwrap();
        let limit = playground::view(Lang::Ru, huge)["error"].as_str().unwrap().to_string();
        assert!(limit.contains("4194304") && limit.contains("zsim run"), "{limit}");
        let shown = text_when(&client, "#error", |t| t.starts_with(&limit)).await;
        assert!(shown.starts_with(&limit), "the page's limit, in Russian: {shown}");
        // Polygons reaching more than the page draws: refused, the limit named, nothing drawn.
        let raster_sized = r#"{"value": 1, "vertices": [[0, 0, 1], [2048, 0, 5], [0, 2048, 9]]}"#;
        let reaching = format!(r#"{{"width": 2048, "height": 2048, "polygons": [{}]}}"#, [raster_sized; 5].join(", "));
        client.goto(&format!("http://127.0.0.1:{port}/#{}", playground::fragment_of(&reaching))).await.unwrap();
        let limit = playground::view(Lang::Ru, &reaching)["error"].as_str().unwrap().to_string();
        assert!(limit.contains("16777216") && limit.contains("20971520"), "{limit}");
        let shown = text_when(&client, "#error", |t| t.starts_with(&limit)).await;
        assert!(shown.starts_with(&limit), "the reach limit, in Russian: {shown}");
        // A raster past the figure's limit: drawn, its figure refused in words, no answer grid offered.
        let wide = r#"{"width": 1024, "height": 1024, "polygons": [{"value": 1, "vertices": [[0, 0, 1], [1024, 0, 5], [0, 1024, 9]]}]}"#;
        client.goto(&format!("http://127.0.0.1:{port}/#{}", playground::fragment_of(wide))).await.unwrap();
        client.execute("document.getElementById('figureBox').open = true;", vec![]).await.unwrap();
        let said = playground::figure(Lang::Ru, wide)["error"].as_str().unwrap().to_string();
        assert!(said.contains("262144"), "{said}");
        assert_eq!(text_when(&client, "#figure", |t| t == said).await, said, "the figure's limit, in Russian");
        let grid = client.execute("return document.getElementById('answerGrid').disabled;", vec![]).await.unwrap();
        assert_eq!(grid, serde_json::Value::Bool(true), "no grid of a million inputs");
        std::fs::write(dir.join("playground-ru-1280.png"), client.screenshot().await.unwrap()).unwrap();
        client.close().await.unwrap();

        let client = session_as(&driver, &browser, &dir.join("profile-360"), "en-US", (360, 800)).await;
        client.goto(&format!("http://127.0.0.1:{port}/")).await.unwrap();
        shown_buffers(&client).await;
        let width = client.execute("return document.documentElement.scrollWidth;", vec![]).await.unwrap();
        let inner = client.execute("return window.innerWidth;", vec![]).await.unwrap();
        assert_eq!(inner.as_u64(), Some(360), "a phone's width");
        assert!(width.as_u64() <= inner.as_u64(), "the page is {width} px wide in a {inner} px window");
        std::fs::write(dir.join("playground-360.png"), client.screenshot().await.unwrap()).unwrap();
        for part in ["grid", "framebuffer", "stop"] {
            client.execute(&format!("document.getElementById('{part}').scrollIntoView();"), vec![]).await.unwrap();
            std::fs::write(dir.join(format!("playground-360-{part}.png")), client.screenshot().await.unwrap()).unwrap();
        }
        client.close().await.unwrap();
    });
    crate::ran("the playground in Russian and at 360 px", &dir.display().to_string());
}

/// `zsim step --html -o page.html` writes the playground as one file that
/// opens from `file://` with its scene, where zsim was built with it
/// (`ZSIM_PLAYGROUND`, as .ci/run builds it).
#[test]
#[ignore = "needs Chromium, chromedriver and a zsim built with the playground (ZSIM_PLAYGROUND=target/web)"]
fn step_html_writes_the_playground_as_one_file_that_opens_from_disk() {
    if option_env!("ZSIM_PLAYGROUND").is_none() {
        crate::missing("a zsim built with the playground (ZSIM_PLAYGROUND=target/web)", "step --html's playground");
    }
    let (driver, browser) = driver();
    let dir = scratch("playground-one-file");
    let scene = std::fs::read_to_string(manifest().join("examples/less.json")).unwrap();
    std::fs::write(dir.join("less.json"), &scene).unwrap();
    let output = Command::new(env!("CARGO_BIN_EXE_zsim"))
        .args(["step", "less.json", "--html", "-o", "page.html"])
        .current_dir(&dir)
        .output()
        .unwrap();
    assert!(output.status.success(), "{}", String::from_utf8_lossy(&output.stderr));
    let runtime = runtime();
    runtime.block_on(async {
        let client = session_as(&driver, &browser, &dir.join("profile"), "en-US", (1280, 900)).await;
        client.goto(&format!("file://{}", dir.join("page.html").display())).await.unwrap();
        assert_eq!(shown_buffers(&client).await, run_final(&scene, &dir), "the page's own scene, from disk");
        assert_eq!(scene_text(&client).await, scene, "the page holds the scene it was written for");
        client.close().await.unwrap();
    });
    // The longest scene text the page reads, written as a page within the peak stated; one byte
    // more refused in one line.
    let limit = crate::limits::stated("The one-file page's scene text");
    let padded = format!("{scene}{}", " ".repeat(limit.count() - scene.len()));
    std::fs::write(dir.join("long.json"), &padded).unwrap();
    let long = dir.join("long.json");
    let page = dir.join("long.html");
    let (code, peak) =
        crate::limits::peak_kib(&["step", long.to_str().unwrap(), "--html", "-o", page.to_str().unwrap()]);
    assert_eq!(code, 0);
    limit.hold_peak(peak);
    std::fs::write(&long, padded + " ").unwrap();
    let run = crate::zsim(&["step", long.to_str().unwrap(), "--html", "-o", page.to_str().unwrap()]);
    assert_eq!((run.code, run.stderr.lines().count()), (2, 1), "{}", run.stderr);
    assert!(run.stderr.contains(&limit.value.to_string()), "{}", run.stderr);
    crate::ran("step --html's playground from file://", "examples/less.json");
}

/// The Debian package, unpacked in a temporary folder as it installs: its
/// zsim writes a quiz page from `step --html --quiz` that a student answers
/// from disk, and a site from `zsim playground` that opens from disk and from
/// a static web server (`.ci/package` builds the package into target/debian).
#[test]
#[ignore = "needs Chromium, chromedriver and the Debian package (packaging/deb, as .ci/package builds it)"]
fn the_packages_zsim_writes_a_quiz_page_and_a_site_a_student_answers() {
    let debs: Vec<PathBuf> = std::fs::read_dir(manifest().join("target/debian"))
        .map(|entries| {
            entries.filter_map(|e| Some(e.ok()?.path())).filter(|p| p.extension().is_some_and(|e| e == "deb")).collect()
        })
        .unwrap_or_default();
    let [deb] = &debs[..] else {
        crate::missing("one Debian package in target/debian (packaging/deb)", "the installed playground")
    };
    let dir = scratch("installed-playground");
    let root = dir.join("root");
    let unpacked = Command::new("dpkg-deb").arg("-x").arg(deb).arg(&root).status().unwrap();
    assert!(unpacked.success());
    let installed = |args: &[&str]| {
        let output = Command::new(root.join("usr/bin/zsim")).args(args).current_dir(&dir).output().unwrap();
        assert!(output.status.success(), "{args:?}: {}", String::from_utf8_lossy(&output.stderr));
    };
    let book = root.join("usr/share/doc/zsim/examples/rogers.json");
    installed(&["step", book.to_str().unwrap(), "--html", "--quiz", "-o", "quiz.html", "--lang", "en"]);
    installed(&["playground", "-o", "site"]);
    let (driver, browser) = driver();
    let port = serve(dir.join("site"));
    runtime().block_on(async {
        let client = session_as(&driver, &browser, &dir.join("profile"), "en-US", (1280, 900)).await;
        // The quiz page from disk: it asks before it tells, and takes the answer.
        client.goto(&format!("file://{}#polygon=2&scanline=15", dir.join("quiz.html").display())).await.unwrap();
        let prompt = text_when(&client, "#prompt", |t| !t.is_empty()).await;
        assert_eq!(prompt, "pixel (15, 15), stored 10: the z-buffer after? (a value, or - if not written)");
        let input = client.find(Locator::Css("#quizAnswer")).await.unwrap();
        input.send_keys("15\u{E007}").await.unwrap();
        let said = text_when(&client, "#said", |t| !t.is_empty()).await;
        assert!(said.starts_with("15 (the value written): right. z = 29/2"), "{said}");
        // The site, from disk and from a web server: the book's example drawn as `zsim run` draws it.
        let scene = std::fs::read_to_string(&book).unwrap();
        for address in
            [format!("file://{}", dir.join("site/index.html").display()), format!("http://127.0.0.1:{port}/")]
        {
            client.goto(&address).await.unwrap();
            assert_eq!(shown_buffers(&client).await, run_final(&scene, &dir), "{address}");
        }
        client.close().await.unwrap();
    });
    crate::ran("the Debian package's playground through WebDriver", &deb.display().to_string());
}

/// The page's buttons and keys do what the library says they do, the page
/// deciding nothing: a polygon, a vertex added and removed are the library's
/// edits; the arrow keys and Enter explain the pixel the cursor is on, rows
/// top first as the raster shows them; the buffers after polygon 1 are
/// `after`'s.
#[test]
#[ignore = "needs Chromium, chromedriver and web/build's site (target/web)"]
fn the_pages_buttons_and_keys_do_what_the_library_says() {
    let (driver, browser, dir, port) = served("playground-buttons");
    let book = std::fs::read_to_string(manifest().join("examples/rogers.json")).unwrap();
    let edited = |text: &str, change: &str| playground::edit(Lang::En, text, change).unwrap();
    runtime().block_on(async {
        let client = session_as(&driver, &browser, &dir.join("profile"), "en-US", (1280, 900)).await;
        client.goto(&format!("http://127.0.0.1:{port}/")).await.unwrap();
        shown_buffers(&client).await;
        let mut expected = playground::layout(&serde_json::from_str(&book).unwrap());
        for (button, change) in [
            ("#addPolygon", r#"{"op": "add-polygon"}"#),
            ("table:nth-of-type(3) .addVertex", r#"{"op": "add-vertex", "polygon": 3}"#),
            ("table:nth-of-type(1) .removeVertex", r#"{"op": "remove-vertex", "polygon": 1}"#),
        ] {
            expected = edited(&expected, change);
            client.find(Locator::Css(button)).await.unwrap().click().await.unwrap();
            let start = Instant::now();
            while scene_text(&client).await != expected && start.elapsed() < Duration::from_secs(10) {
                tokio::time::sleep(Duration::from_millis(50)).await;
            }
            assert_eq!(scene_text(&client).await, expected, "after {button}");
        }
        // The cursor starts at the raster's top-left cell, pixel (0, 31); two rows down and three
        // to the right is (3, 29).
        client.execute("document.getElementById('grid').focus();", vec![]).await.unwrap();
        for key in [Key::Down, Key::Down, Key::Right, Key::Right, Key::Right, Key::Down, Key::Up, Key::Enter] {
            client.active_element().await.unwrap().send_keys(&char::from(key).to_string()).await.unwrap();
        }
        let said = text_when(&client, "#explain", |t| t.starts_with("pixel (3, 29)")).await;
        assert!(said.starts_with("pixel (3, 29)"), "{said}");
        // The buffers after polygon 1, as the library's `after` prints them.
        let after = playground::after(Lang::En, &scene_text(&client).await, 1);
        let select = client.find(Locator::Css("#afterSelect")).await.unwrap();
        select.select_by_value("1").await.unwrap();
        let shown = text_when(&client, "#afterFrame", |t| !t.is_empty()).await;
        assert_eq!(shown.trim_end(), after["frame"].as_str().unwrap().trim_end());
        client.close().await.unwrap();
    });
}

/// The module a student downloads stays within its budget, 400 KB gzipped
/// (`gzip -9`, as a static server would send it): the catalogues without
/// what only the command line, the GPU and the courses say, and no threads'
/// code (WebAssembly has one).
#[test]
#[ignore = "needs web/build's site (target/web) and gzip"]
fn the_module_stays_within_400_kb_gzipped() {
    let module = site().join("zsim_web_bg.wasm");
    let gzipped = Command::new("gzip").arg("-9").arg("-c").arg(&module).output().expect("gzip runs").stdout.len();
    assert!(gzipped <= 400_000, "{}: {gzipped} bytes gzipped", module.display());
    crate::ran("the module's size", &format!("{gzipped} bytes gzipped"));
}

/// For every example scene (effects, windows, perspective, clip space,
/// concave polygons, another depth test), the final buffers the page shows
/// are what `zsim run --final` prints, where the scene has no antialiasing
/// (the page draws without it and says so).
#[test]
fn the_pages_buffers_are_run_final_s_for_every_example() {
    let dir = scratch("playground-examples");
    let mut compared = 0;
    for entry in std::fs::read_dir(manifest().join("examples")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "json") {
            continue;
        }
        let scene = std::fs::read_to_string(&path).unwrap();
        let view = playground::view(Lang::En, &scene);
        assert_eq!(view["ok"], true, "{}: {view}", path.display());
        if scene.contains("\"antialias\"") {
            assert_eq!(
                view["notes"].as_array().unwrap().len(),
                1,
                "{}: the page says it draws without antialiasing",
                path.display()
            );
            continue;
        }
        let shown = (view["framebuffer"].as_str().unwrap().to_string(), view["zbuffer"].as_str().unwrap().to_string());
        assert_eq!(shown, run_final(&scene, &dir), "{}", path.display());
        compared += 1;
    }
    assert!(compared >= 10, "{compared} examples compared");
}
