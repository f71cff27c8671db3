//! rtcdoc: documentation for OpenRTM RT-Component profiles.
//!
//! Pipeline (see `DESIGN` in the book): files → [`walk`] → [`parse`] → [`model::Profile`] →
//! [`catalog::Catalog`] (cross-references) → renderers (HTML, Markdown, Doxygen, JSON).

pub mod diagnostic;
pub mod model;
pub mod parse;
