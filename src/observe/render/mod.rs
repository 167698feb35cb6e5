//! Rendering what a run left: the printed matrices, headings and the run's
//! JSON (`report`), the figure as SVG (`figure`), and that SVG as PNG, PDF
//! (`picture`) and TikZ (`tikz`), and what a variant of the loop did
//! (`variant_report`).
pub mod figure;
pub mod picture;
pub mod report;
pub(crate) mod svg_text;
pub mod tikz;
pub mod variant_report;
mod vertex_labels;
