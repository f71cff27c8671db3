//! Progress reports of a long build (the CLI draws a progress bar from them): read by
//! `build`, `sources` and `config`, so it sits below them all.

/// Receives progress reports of a long build.
pub trait Progress: Sync {
    /// A new stage starts with `total` steps (0 = unknown).
    fn stage(&self, _name: &str, _total: usize) {}
    /// `n` more steps of the current stage are done.
    fn advance(&self, _n: usize) {}
}

/// Reports nothing.
pub struct Quiet;
impl Progress for Quiet {}
