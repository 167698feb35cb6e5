//! Headless Chromium driven through WebDriver (Debian's `chromium-driver`),
//! and a static file server on loopback: what the browser tests (and the
//! playground's benchmark) open pages with.

use std::io::{Read, Write};
use std::net::TcpListener;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use fantoccini::{Client, ClientBuilder};

/// chromedriver on a free loopback port, ended when dropped.
pub struct Driver {
    child: Child,
    port: u16,
}

impl Drop for Driver {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// chromedriver and Chromium; a test that needs them is `#[ignore = "needs Chromium and chromedriver"]`.
pub fn driver() -> (Driver, PathBuf) {
    let browser =
        ["/usr/bin/chromium", "/usr/bin/chromium-browser"].into_iter().map(PathBuf::from).find(|p| p.exists());
    let found = |name: &str| Command::new(name).arg("--version").output().is_ok_and(|o| o.status.success());
    let (Some(browser), true) = (browser, found("chromedriver")) else {
        crate::missing("Chromium and its WebDriver (apt-get install chromium chromium-driver)", "a page in a browser");
    };
    let port = std::net::TcpListener::bind("127.0.0.1:0").unwrap().local_addr().unwrap().port();
    let child = Command::new("chromedriver")
        .arg(format!("--port={port}"))
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .expect("chromedriver starts");
    let driver = Driver { child, port };
    let start = Instant::now();
    while std::net::TcpStream::connect(("127.0.0.1", port)).is_err() {
        assert!(start.elapsed() < Duration::from_secs(20), "chromedriver did not listen within 20 s");
        std::thread::sleep(Duration::from_millis(50));
    }
    (driver, browser)
}

/// Serves `folder` on a loopback port, as a static host would, for as long as the test runs.
pub fn serve(folder: PathBuf) -> u16 {
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let port = listener.local_addr().unwrap().port();
    std::thread::spawn(move || {
        for stream in listener.incoming() {
            let Ok(mut stream) = stream else { continue };
            let mut request = [0u8; 4096];
            let read = stream.read(&mut request).unwrap_or(0);
            let request = String::from_utf8_lossy(&request[..read]);
            let path = request.split_whitespace().nth(1).unwrap_or("/").split(['?', '#']).next().unwrap_or("/");
            let name = if path == "/" { "index.html" } else { path.trim_start_matches('/') };
            let file = (!name.contains("..")).then(|| std::fs::read(folder.join(name)).ok()).flatten();
            let kind = match name.rsplit('.').next() {
                Some("html") => "text/html; charset=utf-8",
                Some("js") => "text/javascript",
                Some("css") => "text/css",
                Some("wasm") => "application/wasm",
                _ => "application/octet-stream",
            };
            let _ = match file {
                Some(body) => stream
                    .write_all(
                        format!("HTTP/1.1 200 OK\r\nContent-Type: {kind}\r\nContent-Length: {}\r\nConnection: close\r\n\r\n", body.len())
                            .as_bytes(),
                    )
                    .and_then(|_| stream.write_all(&body)),
                None => stream.write_all(b"HTTP/1.1 404 Not Found\r\nContent-Length: 0\r\nConnection: close\r\n\r\n"),
            };
        }
    });
    port
}

/// A headless Chromium session that reaches nothing outside this machine, in a
/// browser whose language is `lang`, with a window of `size` (width, height).
pub async fn session_as(driver: &Driver, browser: &Path, profile: &Path, lang: &str, size: (u32, u32)) -> Client {
    let options = serde_json::json!({
        "binary": browser,
        "args": ["--headless", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync",
                 format!("--lang={lang}"), format!("--window-size={},{}", size.0, size.1),
                 format!("--user-data-dir={}", profile.display())],
        // A download (a homework saved as a file) goes into the profile's `downloads`, unasked.
        "prefs": {"intl.accept_languages": lang, "download.default_directory": profile.join("downloads"),
                  "download.prompt_for_download": false},
    });
    // A window narrower than headless Chromium's smallest is a phone's screen, emulated.
    let mut options = options;
    if size.0 < 500 {
        options["mobileEmulation"] =
            serde_json::json!({"deviceMetrics": {"width": size.0, "height": size.1, "pixelRatio": 1.0}});
    }
    let mut capabilities = serde_json::Map::new();
    capabilities.insert("goog:chromeOptions".to_string(), options);
    ClientBuilder::new(hyper_util::client::legacy::connect::HttpConnector::new())
        .capabilities(capabilities)
        .connect(&format!("http://127.0.0.1:{}", driver.port))
        .await
        .expect("a WebDriver session")
}
