//! rtcdoc: documentation for OpenRTM RT-Component profiles.
//!
//! Pipeline: files → [`walk`] → [`parse`] → [`model::Profile`] → [`catalog::Catalog`]
//! (cross-references) → [`render`]ers (HTML, Markdown, Doxygen, JSON), driven by [`build`].
//! RT System profiles are read by [`parse::rts`] into [`system::RtSystem`] (not yet in the
//! catalogue).

#[cfg(feature = "alloc-stats")]
pub mod alloc_stats;
pub mod build;
pub mod catalog;
pub mod check;
pub mod config;
pub mod constraint;
pub mod diagnostic;
pub mod diff;
pub mod i18n;
pub mod idl;
pub mod incremental;
pub mod init;
pub mod layout;
pub mod model;
pub mod output;
pub mod parse;
pub mod readme;
pub mod render;
pub mod serve;
pub mod system;
pub mod types;
pub mod value;
pub mod walk;
