//! The document models: plain data, `Serialize + Deserialize`, no I/O.
//!
//! - [`component`] — an RTC Profile (`RTC.xml` or YAML), re-exported here
//!   (`crate::model::Profile`), with the shared pieces every model uses ([`Pos`], [`Extra`],
//!   [`Text`], [`prose`]);
//! - [`system`] — an RT System profile (`RtsProfile`);
//! - [`fields`] — the field table: every scalar field of the component model with its XML,
//!   YAML and JSON names;
//! - [`idl`] — an IDL file's declarations (re-exported by [`crate::idl`], which reads them).
//!
//! Readers (`crate::parse`, `crate::idl`) fill them; the catalogue, checks, diff and renderers
//! read them.

pub mod component;
pub mod fields;
pub mod idl;
pub mod system;

pub use component::*;
