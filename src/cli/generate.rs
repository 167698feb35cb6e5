//! `zsim memory` and `zsim random`.

use std::io::Write;

use clap::{Args, ValueEnum};
use zsim::{RandomScene, memory};

use super::{Failure, Finish, emit};

/// Arguments of `zsim memory`.
#[derive(Debug, Args)]
pub struct MemoryArgs {
    /// Raster width in pixels.
    #[arg(long, default_value_t = 32)]
    width: u64,
    /// Raster height in pixels.
    #[arg(long, default_value_t = 32)]
    height: u64,
    /// Bits per framebuffer cell.
    #[arg(long, default_value_t = 2)]
    frame_bits: u32,
    /// Bits per z-buffer cell.
    #[arg(long, default_value_t = 4)]
    depth_bits: u32,
    /// Supersampling: K×K sub-pixels per pixel.
    #[arg(long, default_value_t = 1, value_name = "K")]
    supersample: u64,
    /// Where the depth is kept when supersampling (the two approaches of the Russian coursework on Rogers' example).
    #[arg(long, value_enum, default_value_t = DepthAt::Sample)]
    depth_at: DepthAt,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
enum DepthAt {
    /// Both buffers at the higher resolution (the second approach).
    Sample,
    /// The z-buffer at screen resolution, depth at each pixel's centre (the first approach).
    Pixel,
}

/// A size in MB (MiB) with three decimals, or in kB (KiB) below a megabyte, which would show as 0.000 MB.
fn megabytes(bytes: u64) -> String {
    if bytes < 1_000_000 {
        return format!("{}.{:03} kB ({:.3} KiB)", bytes / 1000, bytes % 1000, bytes as f64 / 1024.0);
    }
    format!("{}.{:03} MB ({:.3} MiB)", bytes / 1_000_000, (bytes % 1_000_000) / 1000, bytes as f64 / 1_048_576.0)
}

pub fn memory_command(lang: zsim::Lang, args: &MemoryArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    for (name, bits) in [("--frame-bits", args.frame_bits), ("--depth-bits", args.depth_bits)] {
        if !(1..=64).contains(&bits) {
            return Err(super::flags::Flag::MemoryBits { option: name, bits }.into());
        }
    }
    if args.width == 0 || args.height == 0 || args.supersample == 0 {
        return Err(super::flags::Flag::MemoryZeroSize.into());
    }
    if args
        .width
        .checked_mul(args.height)
        .and_then(|c| c.checked_mul(args.supersample.pow(2)))
        .is_none_or(|c| c > 1 << 50)
    {
        return Err(super::flags::Flag::MemoryTooLarge.into());
    }
    let [frame, depth] = memory(
        args.width,
        args.height,
        args.frame_bits,
        args.depth_bits,
        args.supersample,
        args.depth_at == DepthAt::Sample,
    );
    let listed = zsim::report::memory_table(lang, [frame, depth]);
    let total = frame.bytes() + depth.bytes();
    let table = super::table(listed);
    let k = args.supersample;
    let sampling = if k == 1 {
        String::new()
    } else {
        let at = if args.depth_at == DepthAt::Sample { "memory-at-sample" } else { "memory-at-pixel" };
        zsim::words!(lang, "memory-supersampled", k = k.to_string(), at = zsim::words!(lang, at))
    };
    emit(
        out,
        &format!(
            "{}\n{table}\n{}\n",
            zsim::words!(
                lang,
                "memory-heading",
                width = args.width.to_string(),
                height = args.height.to_string(),
                frame_bits = args.frame_bits.to_string(),
                depth_bits = args.depth_bits.to_string(),
                sampling = sampling
            ),
            zsim::words!(lang, "memory-total-line", total = total.to_string(), megabytes = megabytes(total))
        ),
    )?;
    Ok(Finish::Ok)
}

/// Arguments of `zsim random`.
#[derive(Debug, Args)]
pub struct RandomArgs {
    /// Number of triangles.
    #[arg(long)]
    count: usize,
    /// Seed: the same seed prints the same scene.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Raster width.
    #[arg(long, default_value_t = 32)]
    width: u32,
    /// Raster height.
    #[arg(long, default_value_t = 32)]
    height: u32,
    /// Largest extent of a triangle in x and in y, in pixels (default: the raster).
    #[arg(long, value_name = "PX")]
    max_size: Option<u32>,
    /// Bits per framebuffer cell.
    #[arg(long, default_value_t = 2)]
    frame_bits: u32,
    /// Bits per z-buffer cell (depths are drawn from 0 … 2^min(bits, 24) − 1).
    #[arg(long, default_value_t = 4)]
    depth_bits: u32,
    /// Write the scene to this file instead of standard output.
    #[arg(short, long, value_name = "FILE")]
    output: Option<std::path::PathBuf>,
}

/// Most triangles `zsim random` writes: 10 million is about 1 GB of JSON,
/// and reading it back takes about ten times that in memory.
const MAX_RANDOM_COUNT: usize = 10_000_000;

pub fn random_command(lang: zsim::Lang, args: &RandomArgs, out: &mut dyn Write) -> Result<Finish, Failure> {
    if args.count > MAX_RANDOM_COUNT {
        return Err(super::flags::Flag::RandomCount { count: args.count, max: MAX_RANDOM_COUNT }.into());
    }
    if !(1..=32).contains(&args.frame_bits) || !(1..=32).contains(&args.depth_bits) {
        return Err(super::flags::Flag::RandomBits.into());
    }
    let side = zsim::MAX_SIDE as u32;
    if !(1..=side).contains(&args.width) || !(1..=side).contains(&args.height) {
        return Err(super::flags::Flag::RandomSide { max: side }.into());
    }
    let spec = RandomScene {
        count: args.count,
        seed: args.seed,
        width: args.width,
        height: args.height,
        max_size: args.max_size.unwrap_or(args.width.max(args.height)),
        frame_bits: args.frame_bits,
        depth_bits: args.depth_bits,
    };
    super::emit_or_write(lang, out, args.output.as_deref(), &spec.json(), &[])?;
    Ok(Finish::Ok)
}
