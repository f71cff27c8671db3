//! Diagram layout: geometry only (boxes, ports, connector routes, text lines), drawn by the
//! renderers. [`text`] estimates text widths and wraps long names; [`wiring`] lays out the
//! wiring diagram of an RT System.

pub mod text;
pub mod wiring;
