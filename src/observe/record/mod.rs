//! Recording a run as it happens: what each scanline and pixel did
//! (`trace`), and the polygons recorded one at a time as a student steps
//! through them (`step`).
pub mod step;
pub mod trace;
