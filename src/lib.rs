//! rtcdoc: documentation for OpenRTM RT-Component profiles.
//!
//! Pipeline: files → [`walk`] → [`parse`] / [`idl`] → documents ([`model`]: component profiles,
//! RT Systems, IDL files) → [`catalog::Catalog::assemble`] (entries, cross-references, systems,
//! RTCBuilder backups, READMEs, the page list) → [`check`] / [`diff`] → [`render`]ers (HTML,
//! Markdown, Doxygen, JSON), driven by [`build`] (and [`incremental`] for `serve`).
//! `ARCHITECTURE.md` is the map.

#[cfg(feature = "alloc-stats")]
pub mod alloc_stats;
pub mod allocator;
pub mod build;
pub mod bytes;
pub mod catalog;
pub mod check;
pub mod config;
pub mod constraint;
pub mod diagnostic;
pub mod diff;
pub mod history;
pub mod i18n;
pub mod idl;
pub mod implementation;
pub mod incremental;
pub mod init;
pub mod layout;
pub mod model;
pub mod output;
pub mod parse;
pub mod progress;
pub mod quote;
pub mod readme;
pub mod render;
pub mod serve;
pub mod slug;
pub mod sources;
pub mod suggest;

pub mod types;
pub mod value;
pub mod walk;
pub mod word_diff;

/// Generated text for the property tests that hold a fast path to its reference.
#[cfg(test)]
pub(crate) mod test_text {
    /// Strings made of up to `max - 1` of `parts` in any order and number.
    pub fn concat_of(
        parts: &'static [&'static str],
        max: usize,
    ) -> impl proptest::strategy::Strategy<Value = String> {
        use proptest::strategy::Strategy as _;
        proptest::collection::vec(proptest::sample::select(parts), 0..max).prop_map(|p| p.concat())
    }

    /// The property that a fast path gives what its reference gives: on each of `known`
    /// (texts that once failed), then on `cases` texts of [`concat_of`]`(parts, max)` (`None`:
    /// proptest's default number, `PROPTEST_CASES`); a failure panics with the smallest text
    /// found.
    pub fn agrees<T: PartialEq + std::fmt::Debug>(
        (parts, max, cases): (&'static [&'static str], usize, Option<u32>),
        known: &[&str],
        fast: impl Fn(&str) -> T,
        reference: impl Fn(&str) -> T,
    ) {
        for text in known {
            assert_eq!(fast(text), reference(text), "{text:?}");
        }
        let default = proptest::test_runner::Config::default();
        let config = proptest::test_runner::Config {
            cases: cases.unwrap_or(default.cases),
            failure_persistence: None,
            ..default
        };
        let result =
            proptest::test_runner::TestRunner::new(config).run(&concat_of(parts, max), |text| {
                proptest::prop_assert_eq!(fast(&text), reference(&text), "{:?}", text);
                Ok(())
            });
        if let Err(e) = result {
            panic!("{e}");
        }
    }

    /// A difference fails the property, and the failure names the smallest text.
    #[test]
    #[should_panic(expected = r#"minimal failing input: "b""#)]
    fn agrees_fails_on_a_difference() {
        agrees(
            (&["a", "b"], 6, Some(64)),
            &[],
            |t| t.replace('b', "c"),
            str::to_string,
        );
    }

    /// A known text is tried first, whatever the generated ones give.
    #[test]
    #[should_panic(expected = "\"x\"")]
    fn agrees_tries_the_known_texts() {
        agrees(
            (&["a"], 2, Some(1)),
            &["x"],
            |t| t.replace('x', "y"),
            str::to_string,
        );
    }
}
