//! Embeds the browser playground in `zsim step --html` when the build is
//! given it: `ZSIM_PLAYGROUND` names the folder `web/build` writes
//! (`target/web`). Without it, `step --html` writes the recorded stepper page.

fn main() {
    println!("cargo::rustc-check-cfg=cfg(playground)");
    println!("cargo::rerun-if-env-changed=ZSIM_PLAYGROUND");
    let Some(folder) = std::env::var_os("ZSIM_PLAYGROUND") else { return };
    let folder = std::path::PathBuf::from(folder);
    let out = std::path::PathBuf::from(std::env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    for name in ["index.html", "playground.js", "playground.css", "zsim_web.js", "zsim_web_bg.wasm"] {
        let from = folder.join(name);
        println!("cargo::rerun-if-changed={}", from.display());
        if let Err(error) = std::fs::copy(&from, out.join(name)) {
            panic!("ZSIM_PLAYGROUND={}: cannot read {name} ({error}): run web/build first", folder.display());
        }
    }
    println!("cargo::rustc-cfg=playground");
}
