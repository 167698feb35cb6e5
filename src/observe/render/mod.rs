//! Rendering what a run left: the printed matrices, headings and the run's
//! JSON (`report`), the figure as SVG (`figure`), and that SVG as PNG, PDF
//! (`picture`) and TikZ (`tikz`).
pub mod figure;
pub mod picture;
pub mod report;
pub mod tikz;
