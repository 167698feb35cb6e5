//! The lesson in every front end: the same keys and answers give the same
//! verdicts, moves and score in the line mode, the full-screen app (in a real
//! terminal, tmux) and the browser playground (headless Chromium through
//! WebDriver), each held to what the library's own `Lesson` says. The
//! browser's student flows: the quiz hides what it asks, blocks moving on,
//! hints then reveals, takes zsim's notations, keeps the score; the pixel's
//! history follows an edit; the keys; the address in both directions; the
//! site from `file://`; axe-core; a 390 px phone.

use fantoccini::actions::{InputSource, KeyAction, KeyActions, MOUSE_BUTTON_LEFT, MouseActions, PointerAction};
use fantoccini::key::Key;
use fantoccini::{Client, Locator};
use zsim::Lang;
use zsim::lesson::Command;
use zsim::playground;
use zsim::step::QuizMode;

use crate::browser::{click, text, text_when};
use crate::chromium::{driver, serve, session_as};
use crate::playground::{
    inner_text, manifest, run_final, runtime, scene_text, scratch, shown_buffers, site, type_vertex,
};

/// One student's keys and answers on the book's triangle from scanline 15, with the depth quiz,
/// the one script every front end's test drives (the app's in-process test reads it too).
fn script() -> Vec<String> {
    let text = std::fs::read_to_string(manifest().join("tests/fixtures/lesson-script.txt")).unwrap();
    text.lines().filter(|line| !line.starts_with('#') && !line.is_empty()).map(str::to_string).collect()
}

fn book() -> String {
    std::fs::read_to_string(manifest().join("examples/rogers.json")).unwrap()
}

/// What the library's lesson says to each step of [`script`], and its summary at the end.
fn library_says() -> (Vec<String>, String) {
    let (said, _, summary) = library_goes();
    (said, summary)
}

/// What the library's lesson says to each step of [`script`], the row it is at after each (as the
/// page's state gives it), and its summary at the end.
fn library_goes() -> (Vec<String>, Vec<u64>, String) {
    let mut lesson = playground::lesson(Lang::En, &book(), Some(QuizMode::Depth), Some((2, 15))).unwrap();
    let mut rows = Vec::new();
    let said = script()
        .iter()
        .map(|typed| {
            let said = lesson.act(Lang::En, Command::parse(typed)).text(Lang::En, lesson.scene());
            rows.push(playground::lesson_state(Lang::En, &mut lesson)["at"]["row"].as_u64().unwrap());
            said
        })
        .collect();
    (said, rows, lesson.summary(Lang::En))
}

#[test]
fn the_librarys_answers_to_the_script_are_the_rules() {
    let (said, summary) = library_says();
    let refused = |open: u32| format!("{open} open questions on this scanline: answer them first, or s to skip them");
    assert_eq!(said[0], refused(13));
    assert_eq!(said[1], "14: not yet: it looks as if you rounded a half down: halves round up (one more try)");
    assert!(said[2].starts_with("13: wrong again. The answer is 15: z = 29/2"), "{}", said[2]);
    assert!(said[3].starts_with("14 (the value written): right. z = 55/4"), "{}", said[3]);
    assert_eq!(said[4], "skipped: 11 questions (counted as not answered)");
    assert_eq!((said[5].as_str(), said[6].as_str()), ("", refused(12).as_str()));
    assert_eq!(said[7], "skipped: 12 questions (counted as not answered)");
    // Back to 15, then 16 again: nothing asked on a scanline whose questions ended, then 17 asks.
    assert_eq!(said[8..11], ["", "", ""]);
    assert_eq!(said[11], "3: not yet (one more try)");
    assert_eq!(said[12], "");
    // The question answered once and left open at q counts as not answered right: 1 + 0 + 1 + 24 = 26.
    assert!(
        summary.starts_with("quiz: 1 right at the first try, 0 at the second, 1 shown, 24 skipped, of 26 questions\n"),
        "{summary}"
    );
}

/// The kinds of question, as `--quiz` and the page's address name them.
const KINDS: [(QuizMode, &str); 3] =
    [(QuizMode::Depth, "depth"), (QuizMode::Frame, "frame"), (QuizMode::Coverage, "coverage")];

/// What answers a question of `kind` on the book's triangle at scanline 15, as the library's own
/// lesson shows it when nothing is asked: the first pixel's exact z and its decimal, the buffers'
/// rows after the scanline, and for the coverage question the crossings and the covered columns.
fn answers(kind: QuizMode) -> Vec<String> {
    let mut lesson = playground::lesson(Lang::En, &book(), None, Some((2, 15))).unwrap();
    let state = playground::lesson_state(Lang::En, &mut lesson);
    let text = |value: &serde_json::Value| value.as_str().unwrap().to_string();
    let mut answers = vec![text(&state["rows"][0]["z"]), text(&state["rows"][0]["approx"])];
    for matrix in ["frame", "depth"] {
        answers.push(text(&state[matrix]).lines().find(|line| line.starts_with('▶')).unwrap().to_string());
    }
    if kind == QuizMode::Coverage {
        answers.push(text(&state["crossings"]).trim_start_matches("crossings: ").to_string());
        let columns = state["columns"].as_array().unwrap();
        answers.push(format!("{} … {}", columns[0], columns[columns.len() - 1]));
    }
    assert_eq!(answers[..2], ["29/2", "14.50"], "the library's values for (15, 15)");
    answers
}

/// The line mode, for each kind of question, prints none of what answers it before it is
/// answered or skipped, and all of it once skipped.
#[test]
fn the_line_mode_shows_nothing_that_answers_an_open_question() {
    for (kind, name) in KINDS {
        let args =
            ["step", "examples/rogers.json", "--quiz", name, "--polygon", "2", "--scanline", "15", "--lang", "en"];
        let asked = crate::zsim_stdin(&args, "q\n");
        assert_eq!(asked.code, 0, "{}", asked.stderr);
        let answers = answers(kind);
        for answer in &answers {
            assert!(!asked.stdout.contains(answer.as_str()), "{name}: {answer:?} shown while asked:\n{}", asked.stdout);
        }
        let skipped = crate::zsim_stdin(&args, "s\ns\nq\n");
        for answer in &answers {
            assert!(skipped.stdout.contains(answer.as_str()), "{name}: {answer:?} once skipped:\n{}", skipped.stdout);
        }
    }
}

/// The line mode, driven line by line, says what the library says, in order.
#[test]
fn the_line_mode_says_what_the_lesson_says() {
    let (said, summary) = library_says();
    let input = format!("{}\n", script().join("\n"));
    let run = crate::zsim_stdin(
        &["step", "examples/rogers.json", "--quiz", "depth", "--polygon", "2", "--scanline", "15", "--lang", "en"],
        &input,
    );
    assert_eq!((run.code, run.stderr.as_str()), (0, ""));
    let mut from = 0;
    for line in said.iter().filter(|s| !s.is_empty()) {
        let at = run.stdout[from..]
            .find(&format!("  {line}\n"))
            .unwrap_or_else(|| panic!("{line:?} in order in {}", run.stdout));
        from += at + line.len();
    }
    assert!(run.stdout.ends_with(&summary), "{}", run.stdout);
    assert!(run.stdout.contains("scanline y = 16.5 (row 16)"), "moved on after the skip: {}", run.stdout);
}

/// The full-screen app in a real terminal, given the same keys, ends with the same summary.
#[test]
#[ignore = "needs tmux"]
fn the_full_screen_app_ends_with_the_same_score() {
    let (_, summary) = library_says();
    let command = "zsim step examples/rogers.json --quiz depth --polygon 2 --scanline 15 --lang en; echo EXIT=$?";
    // A key that acts alone, or an answer's characters and Enter.
    let steps: Vec<Vec<String>> = script()
        .iter()
        .map(|step| match Command::parse(step) {
            Command::Answer(_) => step.chars().map(String::from).chain(["Enter".to_string()]).collect(),
            _ => vec![step.clone()],
        })
        .collect();
    let steps: Vec<Vec<&str>> = steps.iter().map(|keys| keys.iter().map(String::as_str).collect()).collect();
    let keys: Vec<&[&str]> = steps.iter().map(Vec::as_slice).collect();
    let shown = crate::teaching::in_tmux((110, 32), command, "the z-buffer after?", &keys, "EXIT=");
    // Each line's start (a long line wraps at the terminal's width).
    for line in summary.lines() {
        let start: String = line.chars().take(80).collect();
        assert!(shown.contains(&start), "{start:?} in:\n{shown}");
    }
    assert!(shown.contains("EXIT=0"), "{shown}");
}

/// Presses `key` as a person does, with the focus on the page itself.
async fn press(client: &Client, key: char) {
    client.execute("document.activeElement && document.activeElement.blur();", vec![]).await.unwrap();
    let actions =
        KeyActions::new("keyboard".to_string()).then(KeyAction::Down { value: key }).then(KeyAction::Up { value: key });
    client.perform_actions(actions).await.unwrap();
}

/// Types `answer` into the quiz's box and presses Enter.
async fn answer(client: &Client, answer: &str) {
    let input = client.find(Locator::Css("#quizAnswer")).await.unwrap();
    input.send_keys(&format!("{answer}{}", char::from(Key::Enter))).await.unwrap();
}

/// The page's address after `#`.
async fn fragment(client: &Client) -> String {
    client.current_url().await.unwrap().fragment().unwrap_or_default().to_string()
}

/// axe-core's critical and serious violations on the page as it is now, one line each.
async fn axe(client: &Client) -> Vec<String> {
    let source = manifest().join("target/web-tools/node_modules/axe-core/axe.min.js");
    let axe = std::fs::read_to_string(&source)
        .unwrap_or_else(|_| panic!("{} (npm install --prefix target/web-tools axe-core)", source.display()));
    client.execute(&axe, vec![]).await.unwrap();
    let found = client
        .execute_async(
            "const done = arguments[arguments.length - 1];
             axe.run(document, {resultTypes: ['violations']}).then((r) => done(r.violations
               .filter((v) => v.impact === 'critical' || v.impact === 'serious')
               .map((v) => v.id + ': ' + v.nodes.map((n) => n.target.join(' ')).join(', '))));",
            vec![],
        )
        .await
        .unwrap();
    found.as_array().unwrap().iter().map(|v| v.as_str().unwrap().to_string()).collect()
}

/// The address the page opens: the book at the triangle's scanline 15 with a quiz.
fn address(port: u16, quiz: &str) -> String {
    format!("http://127.0.0.1:{port}/#{}&polygon=2&scanline=15&quiz={quiz}", playground::fragment_of(&book()))
}

/// The playground given the same keys and answers says what the library
/// says, step by step, and keeps the same score; the quiz hides the asked
/// pixel's z and the coverage answer; the address follows the stepper and
/// back goes back; screenshots before and after a wrong answer are saved.
#[test]
#[ignore = "needs Chromium, chromedriver and web/build's site (target/web)"]
fn the_playground_asks_as_the_lesson_asks() {
    let site = site();
    let (driver, browser) = driver();
    let port = serve(site);
    let dir = scratch("lesson-browser");
    let (said, rows, summary) = library_goes();
    runtime().block_on(async {
        let client = session_as(&driver, &browser, &dir.join("profile"), "en-US", (1280, 1000)).await;
        client.goto(&address(port, "depth")).await.unwrap();
        shown_buffers(&client).await;
        assert_eq!(
            text(&client, "#prompt").await,
            "pixel (15, 15), stored 10: the z-buffer after? (a value, or - if not written)"
        );
        let stop = text(&client, "#stop").await;
        assert!(!stop.contains("29/2") && !stop.contains("14.50"), "the asked pixel's z is hidden: {stop}");
        std::fs::write(dir.join("quiz-before-1280.png"), client.screenshot().await.unwrap()).unwrap();
        // Each step as a person takes it: a key, an answer typed and Enter, the browser's Back for
        // `b`; the page says what the library says and its address follows the lesson's place,
        // a refused Back included.
        for ((step, expected), row) in script().iter().zip(&said).zip(&rows) {
            match step.as_str() {
                "b" => client.back().await.unwrap(),
                "n" | "s" | "q" => press(&client, step.chars().next().unwrap()).await,
                typed => answer(&client, typed).await,
            }
            let place = format!("&polygon=2&scanline={row}");
            let there = |fragment: &str| fragment.contains(&format!("{place}&")) || fragment.ends_with(&place);
            for _ in 0..100 {
                if there(&fragment(&client).await) {
                    break;
                }
                tokio::time::sleep(std::time::Duration::from_millis(50)).await;
            }
            assert!(there(&fragment(&client).await), "after {step:?}: {}", client.current_url().await.unwrap());
            let expected = if step == "q" { summary.trim_end() } else { expected.as_str() };
            assert_eq!(text_when(&client, "#said", |t| t == expected).await, expected, "after {step:?}");
            if step == "14" && expected.contains("not yet") {
                std::fs::write(dir.join("quiz-after-wrong-1280.png"), client.screenshot().await.unwrap()).unwrap();
            }
        }
        // The quiz ended: the stepper goes on where it was, without the quiz, asking nothing.
        assert!(!fragment(&client).await.contains("quiz="), "{}", fragment(&client).await);
        assert_eq!(text(&client, "#prompt").await, "");
        // Every word the page showed was in the module's catalogue (built without the command
        // line's, the GPU's and the courses' messages): a message it lacked would show its key.
        let shown = text(&client, "body").await;
        let keys: Vec<String> = std::fs::read_dir(manifest().join("src/words/en"))
            .unwrap()
            .flat_map(|entry| {
                std::fs::read_to_string(entry.unwrap().path()).unwrap().lines().map(str::to_string).collect::<Vec<_>>()
            })
            .filter_map(|line| {
                Some(line.split_once(" =")?.0.to_string())
                    .filter(|key| key.contains('-') && !key.starts_with([' ', '#']))
            })
            .collect();
        assert!(keys.len() > 800, "{} keys", keys.len());
        let missing: Vec<&String> = keys.iter().filter(|key| shown.contains(key.as_str())).collect();
        assert!(missing.is_empty(), "keys shown for want of their messages: {missing:?}");

        // The coverage question: nothing on the page gives the columns away; zsim's own notation answers it.
        client.goto(&address(port, "coverage")).await.unwrap();
        shown_buffers(&client).await;
        let stop = text(&client, "#stop").await;
        assert!(!stop.contains("crossings") && !stop.contains("columns"), "{stop}");
        let covered = client.find_all(Locator::Css("#grid .covered")).await.unwrap();
        assert!(covered.is_empty(), "the raster marks no covered cell while coverage is asked");
        answer(&client, "15 … 27").await;
        assert!(
            text(&client, "#said").await.starts_with("15 … 27: right. the spans are"),
            "{}",
            text(&client, "#said").await
        );
        assert_eq!(client.find_all(Locator::Css("#grid .covered")).await.unwrap().len(), 13);
        client.close().await.unwrap();
    });
    crate::ran("the lesson in the playground through WebDriver", &format!("{} steps", script().len()));
}

/// The page, for each kind of question, shows none of what answers it anywhere (the stepper, the
/// final buffers, the buffers after each polygon, a pixel's history) before it is answered or
/// skipped; once skipped, the stepper shows the pixel's z.
#[test]
#[ignore = "needs Chromium, chromedriver and web/build's site (target/web)"]
fn the_page_shows_nothing_that_answers_an_open_question() {
    let site = site();
    let (driver, browser) = driver();
    let port = serve(site);
    let dir = scratch("lesson-browser-hidden");
    runtime().block_on(async {
        let client = session_as(&driver, &browser, &dir.join("profile"), "en-US", (1280, 1000)).await;
        for (kind, name) in KINDS {
            client.goto("about:blank").await.unwrap();
            // The asked pixel's history asked for too, as a link asks for it.
            client.goto(&format!("{}&pixel=15,15", address(port, name))).await.unwrap();
            text_when(&client, "#prompt", |t| !t.is_empty()).await;
            text_when(&client, "#explain", |t| !t.is_empty()).await;
            let shown = text(&client, "body").await;
            let answers = answers(kind);
            for answer in &answers {
                assert!(!shown.contains(answer.as_str()), "{name}: {answer:?} shown while asked:\n{shown}");
            }
            press(&client, 's').await;
            if kind == QuizMode::Coverage {
                text_when(&client, "#prompt", |t| t.contains("pixel (15, 15)")).await;
                press(&client, 's').await;
            }
            let stop = text_when(&client, "#stop", |t| t.contains(answers[0].as_str())).await;
            assert!(stop.contains(answers[0].as_str()), "{name}: once skipped:\n{stop}");
        }
        client.close().await.unwrap();
    });
    crate::ran("the page while each kind of question is open", "the book's scanline 15");
}

/// What a student does first: the pixel's history follows an edit, the keys
/// do as the buttons say, the site opens from disk, and axe-core finds no
/// critical or serious violation in the default and the quiz views; on a
/// 390 px phone nothing scrolls sideways and every control is at least 24 px.
#[test]
#[ignore = "needs Chromium, chromedriver, web/build's site and npm's axe-core in target/web-tools"]
fn a_student_finds_the_playground_usable() {
    let site = site();
    let (driver, browser) = driver();
    let port = serve(site.clone());
    let dir = scratch("lesson-usable");
    let book = book();
    runtime().block_on(async {
        let client = session_as(&driver, &browser, &dir.join("profile"), "en-US", (1280, 1000)).await;
        client.goto(&format!("http://127.0.0.1:{port}/")).await.unwrap();
        shown_buffers(&client).await;
        let violations = axe(&client).await;
        assert!(violations.is_empty(), "the default view: {violations:#?}");
        // The history of (20, 15), then the triangle's first vertex typed to x = 12: the history follows.
        client.find(Locator::Css("rect.cell[data-x='20'][data-y='15']")).await.unwrap().click().await.unwrap();
        assert!(fragment(&client).await.ends_with("&pixel=20,15"));
        type_vertex(&client, 1, 0, 0, "12").await;
        let edited = scene_text(&client).await;
        let expected = playground::explain(Lang::En, &edited, 20, 15)["text"].as_str().unwrap().to_string();
        assert_eq!(inner_text(&client, "explain").await, expected, "the history of the edited scene");
        // Then the triangle's third vertex dragged three cells left: the history follows the drag too.
        let handle = client.find(Locator::Css("circle.vertex[data-p='1'][data-v='2']")).await.unwrap();
        let (_, _, width, _) = client.find(Locator::Css("#grid")).await.unwrap().rectangle().await.unwrap();
        let drag = MouseActions::new("mouse".to_string())
            .then(PointerAction::MoveToElement { element: handle, duration: None, x: 0.0, y: 0.0 })
            .then(PointerAction::Down { button: MOUSE_BUTTON_LEFT })
            .then(PointerAction::MoveBy {
                duration: Some(std::time::Duration::from_millis(100)),
                x: -3.0 * width / 32.0,
                y: 0.0,
            })
            .then(PointerAction::Up { button: MOUSE_BUTTON_LEFT });
        client.perform_actions(drag).await.unwrap();
        let dragged = scene_text(&client).await;
        assert_ne!(dragged, edited, "the drag moved the vertex");
        let expected = playground::explain(Lang::En, &dragged, 20, 15)["text"].as_str().unwrap().to_string();
        assert_eq!(inner_text(&client, "explain").await, expected, "the history of the dragged scene");
        // The keys as the buttons say: n and b move, p the next polygon.
        click(&client, "#reset").await;
        shown_buffers(&client).await;
        assert_eq!(text(&client, "#status").await, "scanline y = 5.5 (row 5)");
        press(&client, 'n').await;
        assert_eq!(text(&client, "#status").await, "scanline y = 6.5 (row 6)");
        press(&client, 'b').await;
        assert_eq!(text(&client, "#status").await, "scanline y = 5.5 (row 5)");
        press(&client, 'p').await;
        assert_eq!(text(&client, "#status").await, "scanline y = 10.5 (row 10)");
        // The raster by keyboard: the cursor from the top-left cell, Enter explains it.
        let grid = client.find(Locator::Css("#grid")).await.unwrap();
        grid.send_keys(&format!("{}{}", char::from(Key::Right), char::from(Key::Enter))).await.unwrap();
        assert!(fragment(&client).await.ends_with("&pixel=1,31"), "{}", fragment(&client).await);
        // The quiz view.
        click(&client, "#quiz").await;
        let violations = axe(&client).await;
        assert!(violations.is_empty(), "the quiz view: {violations:#?}");
        client.close().await.unwrap();

        // From disk: the site's own folder, no server.
        let client = session_as(&driver, &browser, &dir.join("profile-file"), "en-US", (1280, 1000)).await;
        client.goto(&format!("file://{}", site.join("index.html").display())).await.unwrap();
        assert_eq!(shown_buffers(&client).await, run_final(&book, &dir), "the site opened from disk");
        client.close().await.unwrap();

        // A phone: 390 px, nothing wider than the window, every control a 24 px target.
        let client = session_as(&driver, &browser, &dir.join("profile-390"), "en-US", (390, 844)).await;
        client
            .goto(&format!(
                "http://127.0.0.1:{port}/#{}&polygon=2&scanline=15&quiz=depth",
                playground::fragment_of(&book)
            ))
            .await
            .unwrap();
        shown_buffers(&client).await;
        let width = client.execute("return document.documentElement.scrollWidth;", vec![]).await.unwrap();
        assert!(width.as_u64() <= Some(390), "the page is {width} px wide on a 390 px phone");
        let small = client
            .execute(
                "return [...document.querySelectorAll('button, select, input, circle.vertex')]
                   .filter((e) => e.getClientRects().length && !e.closest('[hidden]'))
                   .map((e) => [e.id || e.className.baseVal || e.tagName, e.getBoundingClientRect()])
                   .filter(([, r]) => r.width < 24 || r.height < 24)
                   .map(([name, r]) => name + ' ' + Math.round(r.width) + 'x' + Math.round(r.height));",
                vec![],
            )
            .await
            .unwrap();
        assert_eq!(small.as_array().map(Vec::len), Some(0), "targets under 24 px: {small}");
        std::fs::write(dir.join("lesson-390.png"), client.screenshot().await.unwrap()).unwrap();
        client.execute("document.getElementById('stepper').scrollIntoView();", vec![]).await.unwrap();
        std::fs::write(dir.join("lesson-390-stepper.png"), client.screenshot().await.unwrap()).unwrap();
        client.close().await.unwrap();
    });
    crate::ran("the playground as a student meets it", &dir.display().to_string());
}
