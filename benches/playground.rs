//! How fast the browser playground answers, measured in headless Chromium
//! through WebDriver on `web/build`'s site: an edit (a vertex typed into the
//! table) of the book's scene and of a 64×64 scene of 64 triangles (`zsim
//! random --count 64 --width 64 --height 64 --seed 1`), and a step of the
//! stepper (Next), each from the event to the page redrawn, timed with the
//! page's `performance.now()` around the event's dispatch, 41 times each,
//! alternating; and the module's size, plain and gzipped. Run with `cargo
//! bench --bench playground` after `web/build`.

use std::time::Duration;

mod in_browser;
pub use in_browser::missing;
use in_browser::{chromium, median, site};

const ROUNDS: usize = 41;

fn main() {
    let site = site();
    let wasm = std::fs::read(site.join("zsim_web_bg.wasm")).unwrap();
    let gzipped = std::process::Command::new("gzip")
        .args(["-9", "-c"])
        .arg(site.join("zsim_web_bg.wasm"))
        .output()
        .map(|o| o.stdout.len())
        .unwrap_or(0);
    let (driver, browser) = chromium::driver();
    let port = chromium::serve(site);
    let runtime = tokio::runtime::Builder::new_current_thread().enable_all().build().unwrap();
    let (edits, steps, class_edits, parts) = runtime.block_on(async {
        let client = in_browser::playground(&driver, &browser, port, "bench-playground-profile").await;
        let measure = |polygon: usize| {
            format!(
                r#"const edits = [], steps = [];
                for (let i = 0; i < {ROUNDS}; i++) {{
                  const input = document.querySelector("input.coord[data-p='{polygon}'][data-v='0'][data-c='0']");
                  input.value = String(12 + (i % 3));
                  let t = performance.now();
                  input.dispatchEvent(new Event("change"));
                  edits.push(performance.now() - t);
                  const button = document.getElementById(i % 2 ? "back" : "next");
                  t = performance.now();
                  button.click();
                  steps.push(performance.now() - t);
                }}
                return [edits, steps];"#
            )
        };
        let list = |times: &serde_json::Value, i: usize| {
            times[i].as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).collect::<Vec<_>>()
        };
        let book = client.execute(&measure(1), vec![]).await.unwrap();
        // The class-sized scene, opened as a link opens it.
        let large =
            zsim::RandomScene { count: 64, seed: 1, width: 64, height: 64, max_size: 64, frame_bits: 2, depth_bits: 4 }
                .json();
        let address = format!("http://127.0.0.1:{port}/#{}", zsim::playground::fragment_of(&large));
        client.goto("about:blank").await.unwrap();
        client.goto(&address).await.unwrap();
        for _ in 0..600 {
            let shown = client.execute("return document.querySelectorAll('input.coord').length;", vec![]);
            if shown.await.unwrap().as_u64().unwrap_or(0) > 0 {
                break;
            }
            tokio::time::sleep(Duration::from_millis(50)).await;
        }
        let class = client.execute(&measure(1), vec![]).await.unwrap();
        // Where an edit of the class-sized scene goes: each of the library's calls alone.
        let parts = format!(
            r#"const text = document.getElementById("json").value, z = wasm_bindgen, times = {{}};
            const time = (name, f) => {{ const t = performance.now(); f(); (times[name] = times[name] || []).push(performance.now() - t); }};
            const read = new z.WebLesson("en", text, "", 0, 0);
            for (let i = 0; i < {ROUNDS}; i++) {{
              time("view", () => JSON.parse(read.view()));
              time("lesson", () => {{ const l = new z.WebLesson("en", text, "", 0, 0); JSON.parse(l.state()); l.free(); }});
              time("after", () => JSON.parse(read.after(1)));
              time("edit", () => z.edit("en", text, JSON.stringify({{op: "set", path: ["width"], value: "64"}})));
            }}
            read.free();
            return times;"#
        );
        let parts = client.execute(&parts, vec![]).await.unwrap();
        client.close().await.unwrap();
        (list(&book, 0), list(&book, 1), list(&class, 0), parts)
    });
    let version = std::process::Command::new(&browser).arg("--version").output().map(|o| o.stdout).unwrap_or_default();
    println!("browser: {}", String::from_utf8_lossy(&version).trim());
    println!("module: {} bytes, {} gzipped (gzip -9)", wasm.len(), gzipped);
    println!(
        "edit of the book's scene (a vertex typed), event to page redrawn: median {:.2} ms, max {:.2} ms ({ROUNDS} runs)",
        median(edits.clone()),
        edits.iter().copied().fold(0.0, f64::max)
    );
    println!(
        "edit of a 64×64 scene of 64 triangles (a vertex typed), event to page redrawn: median {:.2} ms, max {:.2} ms ({ROUNDS} runs)",
        median(class_edits.clone()),
        class_edits.iter().copied().fold(0.0, f64::max)
    );
    for (name, what) in [
        ("view", "the scene's view, of the lesson's reading (WebLesson::view)"),
        ("lesson", "a new lesson and its state (WebLesson)"),
        ("after", "the buffers after polygon 1, of the lesson's reading (WebLesson::after)"),
        ("edit", "the edit of the scene's text (zsim::playground::edit)"),
    ] {
        let times: Vec<f64> = parts[name].as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).collect();
        println!("  of which {what}: median {:.2} ms", median(times));
    }
    println!(
        "step (Next/Back), event to page redrawn: median {:.2} ms, max {:.2} ms ({ROUNDS} runs)",
        median(steps.clone()),
        steps.iter().copied().fold(0.0, f64::max)
    );
}
