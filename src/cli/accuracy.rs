//! `zsim accuracy`: what accuracy costs in time.

use std::io::Write;

use clap::{Args, ValueEnum};
use comfy_table::{Table, presets};
use zsim::accuracy::{self, AccuracyRequest};

use super::{Failure, Finish, emit, json_line};

/// Arguments of `zsim accuracy`.
#[derive(Debug, Args)]
pub struct AccuracyArgs {
    /// Seed of the generated scenes.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Raster size of the generated scenes, WxH.
    #[arg(long, default_value = "256x256", value_parser = parse_size)]
    size: (u32, u32),
    /// Random scenes per triangle size (4, 16, 64 and 256 px).
    #[arg(long, default_value_t = 2)]
    scenes: u32,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
enum Format {
    /// Two tables.
    Text,
    /// {"modes": [...], "depth_bits": [...]}.
    Json,
}

fn parse_size(text: &str) -> Result<(u32, u32), String> {
    let (w, h) = text.split_once('x').ok_or_else(|| format!("\"{text}\" is not WxH (for example 256x256)"))?;
    let side = |v: &str| match v.parse::<u32>() {
        Ok(n @ 16..=4096) => Ok(n),
        _ => Err(format!("\"{v}\" is not a side from 16 to 4096")),
    };
    Ok((side(w)?, side(h)?))
}

pub fn run(lang: zsim::Lang, args: &AccuracyArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    if args.scenes == 0 || args.scenes > 100 {
        return Err(super::flags::Flag::ScenesOutOfRange.into());
    }
    let settings = AccuracyRequest { seed: args.seed, width: args.size.0, height: args.size.1, scenes: args.scenes };
    let scenes = accuracy::scenes(&settings)?;
    let origin = std::time::Instant::now();
    let clock = || origin.elapsed();
    let modes = accuracy::modes(&scenes, &clock)?;
    let bits = accuracy::bits_sweep(&settings, &clock)?;
    let exact = modes[0].clone();
    let ns = |row: &accuracy::ModeRow| row.ns_per_pixel(&exact);
    if args.format == Format::Json {
        emit(out, &json_line(&accuracy::AccuracyJson::of(&modes, &bits)))?;
        return Ok(Finish::Ok);
    }
    let mut table = Table::new();
    table.load_style(presets::ASCII_MARKDOWN).set_header(
        [
            "accuracy-header-mode",
            "accuracy-header-ns",
            "accuracy-header-pixels",
            "accuracy-header-frame",
            "accuracy-header-depth",
            "accuracy-header-worst",
            "accuracy-header-time",
        ]
        .map(|key| zsim::words!(lang, key)),
    );
    for row in &modes {
        table.add_row([
            row.mode.to_string(),
            format!("{:.2}", ns(row)),
            row.pixels.to_string(),
            row.frame_mismatches.to_string(),
            row.depth_mismatches.to_string(),
            row.worst_depth_error.to_string(),
            format!("{:.2}×", row.time.as_secs_f64() / exact.time.as_secs_f64()),
        ]);
    }
    let mut sweep = Table::new();
    sweep.load_style(presets::ASCII_MARKDOWN).set_header(
        ["accuracy-header-bits", "accuracy-header-fighting", "accuracy-header-memory", "accuracy-header-ms"]
            .map(|key| zsim::words!(lang, key)),
    );
    for row in &bits {
        sweep.add_row([
            row.bits.to_string(),
            row.z_fighting.to_string(),
            row.memory.to_string(),
            format!("{:.3}", row.time.as_secs_f64() * 1000.0),
        ]);
    }
    let cells = u64::from(settings.width) * u64::from(settings.height);
    emit(
        out,
        &format!(
            "{}\n{table}\n\n{}\n{sweep}\n",
            zsim::words!(
                lang,
                "accuracy-set",
                scenes = scenes.len().to_string(),
                width = settings.width.to_string(),
                height = settings.height.to_string(),
                seed = settings.seed.to_string()
            ),
            zsim::words!(lang, "accuracy-sweep", cells = cells.to_string())
        ),
    )?;
    Ok(Finish::Ok)
}
