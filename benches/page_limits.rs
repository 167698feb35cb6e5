//! How long the browser playground is busy with the largest scene each of
//! its limits accepts (`zsim::page_limits`), and with one past each, which it
//! refuses naming the limit; measured in headless Chromium through WebDriver
//! on `web/build`'s site. Each scene is opened as a link opens it (its
//! address's `#scene=` changed) and pasted into the scene's text, with the
//! figure closed and open, and timed with the page's `performance.now()` to
//! the first frame painted after the page's work: a link from the address
//! changed, a paste from the page's input event (the browser's own putting
//! of the text in the box and laying it out timed apart); the scenes
//! are taken in turn, round after round, and the median and the largest of
//! each printed, with a line for each past one second. Run with `cargo bench
//! --bench page_limits` after `web/build`.

use std::time::Duration;

use zsim::page_limits::{
    MAX_PAGE_CELLS, MAX_PAGE_POLYGONS, MAX_PAGE_REACH, MAX_PAGE_SCENE_BYTES, MAX_PAGE_VERTICES, MAX_PRINTED_CELLS,
    MAX_SHOWN_CELLS, MAX_SHOWN_POLYGONS,
};

mod in_browser;
pub use in_browser::missing;
use in_browser::{chromium, median, site};

const ROUNDS: usize = 7;

/// A scene of `width` × `height` with `polygons` (each a list of `[x, y, z]`
/// vertices, values 1 … 3 in turn), written as compactly as JSON allows.
fn scene(width: u64, height: u64, polygons: &[Vec<[u64; 3]>]) -> String {
    let list: Vec<String> = polygons
        .iter()
        .enumerate()
        .map(|(k, vertices)| {
            let points: Vec<String> = vertices.iter().map(|[x, y, z]| format!("[{x},{y},{z}]")).collect();
            format!(r#"{{"value":{},"vertices":[{}]}}"#, 1 + k % 3, points.join(","))
        })
        .collect();
    format!(r#"{{"width":{width},"height":{height},"polygons":[{}]}}"#, list.join(","))
}

/// Raster-sized triangles on a `side` × `side` raster, each sloped in depth
/// and crossing the last: `count` of them.
fn raster_sized(side: u64, count: u64) -> String {
    let full: Vec<Vec<[u64; 3]>> = (0..count)
        .map(|k| match k % 2 {
            0 => vec![[0, 0, 1 + k % 7], [side, 0, 9], [0, side, 15 - k % 5]],
            _ => vec![[side, side, 1 + k % 7], [0, side, 9], [side, 0, 15 - k % 5]],
        })
        .collect();
    scene(side, side, &full)
}

/// `count` triangles of one pixel's side, as short as JSON writes them.
fn small(side: u64, count: u64) -> String {
    let small: Vec<Vec<[u64; 3]>> = (0..count)
        .map(|k| {
            let (x, y) = ((k * 7) % 9, (k * 5) % 9);
            vec![[x, y, 1], [x + 1, y, 2], [x, y + 1, 3]]
        })
        .collect();
    scene(side, side, &small)
}

/// A comb of `vertices` vertices whose teeth every scanline crosses.
fn comb(side: u64, vertices: u64) -> String {
    let teeth = (vertices - 2) / 4;
    let step = side / (teeth + 1);
    let mut comb = vec![[0, 0, 1]];
    for t in 0..teeth {
        let x = t * step;
        comb.extend([[x, side, 1], [x + step / 2, side, 1], [x + step / 2, 4, 1], [x + step, 4, 1]]);
    }
    // The rest along the bottom, back to the start.
    let rest = vertices - comb.len() as u64;
    comb.extend((0..rest).map(|k| [teeth * step - k, 2, 1]));
    assert_eq!(comb.len() as u64, vertices);
    scene(side, side, &[comb])
}

/// A scene at one of the page's limits: the largest the page draws, or one
/// past it, which the page refuses naming the limit (`refused`: the number
/// the refusal names).
struct Case {
    name: String,
    text: String,
    refused: Option<u64>,
}

fn case(name: String, text: String, refused: Option<u64>) -> Case {
    Case { name, text, refused }
}

/// The scenes at each limit and one past it.
fn cases() -> Vec<Case> {
    let side = (MAX_PAGE_CELLS as f64).sqrt() as u64;
    let figured = (MAX_PRINTED_CELLS as f64).sqrt() as u64;
    let shown = (MAX_SHOWN_CELLS as f64).sqrt() as u64;
    let whole = vec![vec![[0, 0, 1], [side, 0, 9], [0, side, 15]], vec![[side, 0, 2], [side, side, 14], [0, side, 8]]];
    let mut cases = vec![
        case(
            format!("the largest raster, {side} × {side}, two triangles covering it"),
            scene(side, side, &whole),
            None,
        ),
        case(format!("a raster of {side} × {}", side + 1), scene(side, side + 1, &whole), Some(MAX_PAGE_CELLS)),
    ];
    // What polygons may reach, on the largest raster, the largest figure's and the largest shown cell by cell.
    for side in [side, figured, shown] {
        let most = MAX_PAGE_REACH / (side * side);
        let name = format!("{most} raster-sized triangles on {side} × {side} ({} pixels reached)", most * side * side);
        cases.push(case(name, raster_sized(side, most), None));
    }
    // The most polygons the stepper steps, each raster-sized, on the largest raster it steps.
    let stepped = format!("{MAX_SHOWN_POLYGONS} raster-sized triangles on {shown} × {shown}, stepped");
    cases.push(case(stepped, raster_sized(shown, MAX_SHOWN_POLYGONS as u64), None));
    let most = MAX_PAGE_REACH / (side * side) + 1;
    cases.push(case(
        format!("{most} raster-sized triangles on {side} × {side}"),
        raster_sized(side, most),
        Some(MAX_PAGE_REACH),
    ));
    let polygons = MAX_PAGE_POLYGONS as u64;
    cases.push(case(format!("{polygons} small triangles on {side} × {side}"), small(side, polygons), None));
    cases.push(case(format!("{} small triangles", polygons + 1), small(side, polygons + 1), Some(polygons)));
    let vertices = MAX_PAGE_VERTICES as u64;
    cases.push(case(format!("a comb of {vertices} vertices on {side} × {side}"), comb(side, vertices), None));
    cases.push(case(format!("a comb of {} vertices", vertices + 1), comb(side, vertices + 1), Some(vertices)));
    // The longest text: the book's scene padded with spaces; then one byte more, and ten megabytes.
    let book = include_str!("../examples/rogers.json");
    let padded = |bytes: usize| format!("{book}{}", " ".repeat(bytes - book.len()));
    let bytes = MAX_PAGE_SCENE_BYTES;
    cases.push(case(format!("the book's scene padded to {bytes} bytes"), padded(bytes), None));
    cases.push(case(format!("the book's scene padded to {} bytes", bytes + 1), padded(bytes + 1), Some(bytes as u64)));
    cases.push(case("the book's scene padded to 10000000 bytes".into(), padded(10_000_000), Some(bytes as u64)));
    cases
}

fn main() {
    let site = site();
    let cases = cases();
    for case in &cases {
        let view = zsim::playground::view(zsim::Lang::En, &case.text);
        match case.refused {
            None => assert!(view["ok"] == true, "{} is refused: {}", case.name, view["error"]),
            Some(limit) => assert!(
                view["error"].as_str().is_some_and(|e| e.contains(&limit.to_string())),
                "{} is not refused for its limit: {}",
                case.name,
                view["error"]
            ),
        }
    }
    let (driver, browser) = chromium::driver();
    let port = chromium::serve(site);
    let runtime = tokio::runtime::Builder::new_current_thread().enable_all().build().unwrap();
    let times = runtime.block_on(async {
        let client = in_browser::playground(&driver, &browser, port, "bench-page-limits-profile").await;
        // Each way in, timed in parts. A link: from the address changed to the first frame painted
        // after the page's work (the browser's own reading of the address included: the page's
        // handlers run on its popstate and hashchange events), and until its handler is done. A
        // paste: the browser's own work first (the text put in the box and the box laid out), then
        // from the page's input event to its handler done and to the first frame painted.
        let open = r#"const [fragment, done] = arguments;
            const t = performance.now();
            window.addEventListener("hashchange", () => {
              document.body.getBoundingClientRect(); const handled = performance.now();
              requestAnimationFrame(() => setTimeout(() => done([0, handled - t, performance.now() - t, document.getElementById("error").textContent])));
            }, { once: true });
            location.hash = fragment;"#;
        let paste = r#"const [text, done] = arguments, json = document.getElementById("json");
            const t = performance.now();
            json.value = text;
            document.body.getBoundingClientRect();
            const heard = performance.now();
            json.dispatchEvent(new Event("input"));
            document.body.getBoundingClientRect(); const handled = performance.now();
            requestAnimationFrame(() => setTimeout(() => done([heard - t, handled - heard, performance.now() - heard, document.getElementById("error").textContent])));"#;
        let book = include_str!("../examples/rogers.json");
        // Per scene, per way in (a link, a paste) and with the figure closed and open: the times.
        let mut times: Vec<Vec<Vec<(f64, f64, f64)>>> = vec![vec![Vec::new(); 4]; cases.len()];
        for _ in 0..ROUNDS {
            for (k, Case { name, text, refused }) in cases.iter().enumerate() {
                for (way, (script, argument)) in
                    [(open, format!("#{}", zsim::playground::fragment_of(text))), (paste, text.clone())].into_iter().enumerate()
                {
                    for figure in [false, true] {
                        // From the book's scene each time, so that each is a new scene to the page.
                        client.execute_async(paste, vec![book.into()]).await.unwrap();
                        // The page writes the book's address a moment after (150 ms).
                        tokio::time::sleep(Duration::from_millis(300)).await;
                        client.execute(&format!("document.getElementById('figureBox').open = {figure};"), vec![]).await.unwrap();
                        let result = client.execute_async(script, vec![argument.clone().into()]).await;
                        let result = result.unwrap_or_else(|e| panic!("{name}: {e}"));
                        let error = result[3].as_str().unwrap_or_default();
                        match refused {
                            None => assert!(error.is_empty(), "{name}: the page said {error:?}"),
                            Some(limit) => assert!(error.contains(&limit.to_string()), "{name}: the page said {error:?}"),
                        }
                        let part = |i: usize| result[i].as_f64().unwrap();
                        times[k][way * 2 + usize::from(figure)].push((part(0), part(1), part(2)));
                    }
                }
            }
        }
        client.close().await.unwrap();
        times
    });
    let version = std::process::Command::new(&browser).arg("--version").output().map(|o| o.stdout).unwrap_or_default();
    println!("browser: {}", String::from_utf8_lossy(&version).trim());
    let mut slow = Vec::new();
    for (Case { name, text, refused }, lists) in cases.iter().zip(&times) {
        let what = if refused.is_some() { "refused" } else { "drawn" };
        println!("{name} ({} bytes), {what}:", text.len());
        for (list, how) in lists.iter().zip([
            "opened as a link",
            "opened as a link, the figure open",
            "pasted into the scene's text",
            "pasted into the scene's text, the figure open",
        ]) {
            let browser: Vec<f64> = list.iter().map(|t| t.0).collect();
            let handled: Vec<f64> = list.iter().map(|t| t.1).collect();
            let painted: Vec<f64> = list.iter().map(|t| t.2).collect();
            let worst = painted.iter().copied().fold(0.0, f64::max);
            let browser = match how.starts_with("pasted") {
                true => format!(
                    "; the browser's own before it (the text in the box, laid out): median {:.0} ms",
                    median(browser)
                ),
                false => String::new(),
            };
            println!(
                "  {how}: busy until painted: median {:.0} ms, at most {:.0} ms (the handlers: median {:.0} ms){browser} ({ROUNDS} runs)",
                median(painted.clone()),
                worst,
                median(handled)
            );
            if median(painted) > 1000.0 {
                slow.push(format!("{name}, {how}"));
            }
        }
    }
    for what in &slow {
        println!("past one second: {what}");
    }
}
