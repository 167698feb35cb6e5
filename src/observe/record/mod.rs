//! Recording a run as it happens: what each scanline and pixel did
//! (`trace`), and the polygons recorded one at a time as a student steps
//! through them (`tracer`).
pub mod trace;
pub mod tracer;
