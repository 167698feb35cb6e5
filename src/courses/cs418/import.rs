//! A CS 418 case as a zsim scene: what the course's pipeline draws, in exact
//! arithmetic, as polygons that zsim's rasterizer covers sample for sample
//! as the course's DDA does.
//!
//! The course samples at integer points with rows counted from the top and
//! the top-left rule of a y-down raster. zsim samples at centres with y up,
//! so each point (x, y) becomes (x + 1/2, height − y − 1/2): the picture is
//! not flipped, and the `gpu` rules (rows `top-left`, columns `half-open`) then
//! cover exactly the samples the course's DDA visits. Depth is z/w, which is
//! linear on the screen, so zsim's plane gives the DDA's exact depth; the
//! depth test is `less-equal` (the course keeps z ≤ stored, cleared to 1) or,
//! without `depth`, `always`. Each polygon's framebuffer value is its
//! primitive's number, so the framebuffer shows which primitive a sample
//! shows last; colours stay with `zsim cs418 run`.

use std::fmt::Write as _;

use super::{Cs418Error, Cs418Problem, RastFile, raster};

/// The scene JSON for a case.
pub fn scene_json(case: &RastFile) -> Result<String, Cs418Error> {
    let (primitives, shapes) = raster::shapes(case)?;
    let level = case.features.fsaa.max(1);
    let count = primitives.len() as u64;
    let frame_bits = (64 - count.leading_zeros()).clamp(1, 32);
    if count >= 1 << 32 {
        return Err(Cs418Error { line: None, problem: Cs418Problem::TooManyPrimitives { count } });
    }
    let mut out = String::new();
    let _ = writeln!(out, "{{");
    let _ = writeln!(out, "  \"width\": {}, \"height\": {},", case.width * level, case.height * level);
    let _ = writeln!(out, "  \"frame_bits\": {frame_bits}, \"background\": 0,");
    let _ = writeln!(out, "  \"rules\": {{\"preset\": \"vulkan\", \"store\": \"exact\"}},");
    let test = if case.features.depth { "less-equal" } else { "always" };
    let _ = writeln!(out, "  \"depth_test\": \"{test}\", \"clear_depth\": 1,");
    let _ = writeln!(out, "  \"polygons\": [");
    let mut parts = std::collections::BTreeMap::<u32, usize>::new();
    for (i, shape) in shapes.iter().enumerate() {
        let primitive = &primitives[shape.primitive as usize - 1];
        let part = parts.entry(shape.primitive).or_insert(0);
        *part += 1;
        let pieces = shapes.iter().filter(|s| s.primitive == shape.primitive).count();
        let name = format!(
            "{} {}{}",
            if primitive.vertices.len() == 1 { "point" } else { "triangle" },
            shape.primitive,
            if pieces > 1 { format!(" part {part}") } else { String::new() }
        );
        let vertices: Vec<String> =
            shape.vertices.iter().map(|[x, y, z]| format!("[\"{x}\", \"{y}\", \"{z}\"]")).collect();
        let comma = if i + 1 < shapes.len() { "," } else { "" };
        let _ = writeln!(
            out,
            "    {{\"name\": \"{name} (line {})\", \"value\": {}, \"vertices\": [{}]}}{comma}",
            primitive.line,
            shape.primitive,
            vertices.join(", ")
        );
    }
    let _ = writeln!(out, "  ]");
    let _ = writeln!(out, "}}");
    Ok(out)
}
