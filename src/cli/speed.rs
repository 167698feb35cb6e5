//! `zsim speed`: zsim beside the machine's OpenGL on the same scene.

use std::io::Write;

use clap::Args;
use zsim::Scene;

use super::{Failure, Finish, emit};

/// Arguments of `zsim speed`.
#[derive(Debug, Args)]
pub struct SpeedArgs {
    /// The scene (JSON), for example from `zsim random`.
    scene: std::path::PathBuf,
    /// How many alternating pairs (zsim, then the GPU) are timed.
    #[arg(long, default_value_t = 7, value_parser = clap::value_parser!(u32).range(1..=1000))]
    pairs: u32,
    /// How many threads zsim draws on (1: polygon by polygon, the loop `zsim run --threads 1` runs). llvmpipe is given as many through LP_NUM_THREADS (0 for one: it then rasterizes on the calling thread) unless the environment sets it.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=1024))]
    threads: u32,
    /// Draw in tiles of N×N pixels (default as `zsim run` draws: tiles of 256 with more than one thread or buffers larger than 8 MiB, else polygon by polygon).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(8..=65536))]
    tile: Option<u32>,
}

pub fn run(lang: zsim::Lang, args: &SpeedArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    let lp_threads = match std::env::var("LP_NUM_THREADS") {
        Ok(set) => set,
        Err(_) => {
            let value = if args.threads == 1 { "0".to_string() } else { args.threads.to_string() };
            // SAFETY: the command's first step, before this process starts any other thread.
            unsafe { std::env::set_var("LP_NUM_THREADS", &value) };
            value
        }
    };
    let scene = Scene::load(&args.scene)?;
    let threads = args.threads as usize;
    let race = zsim::race::race(&scene, args.pairs as usize, args.tile, threads)?;
    let text = race.report(lang, &zsim::shown_path(&args.scene), &lp_threads);
    emit(out, &text)?;
    Ok(Finish::Ok)
}
