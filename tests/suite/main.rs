//! The integration tests, one binary: each file of this folder is a module (cargo links one
//! test executable instead of one per file, which kept `cargo test` from needing gigabytes
//! of disk). Run one file's tests with `cargo test --test suite <file>::`.

mod common;
mod html_support;

mod action;
mod backups;
mod book;
mod book_ja;
mod build_pipeline;
mod check_rules;
mod cli;
mod cli_findings;
mod diagnostics_scale;
mod diagrams;
mod dialects;
mod diff;
mod diff_drift;
mod diff_fixtures;
mod diff_gate;
mod diff_idl;
mod diff_impact;
mod function_length;
mod guide_commands;
mod hints;
mod history;
mod history_feed;
mod history_more;
mod history_noise;
mod history_pages;
mod html_browser;
mod html_native;
mod html_site;
mod idl_pages;
mod idl_reader;
mod implementation;
mod layers;
mod manual;
mod neighbourhood;
mod page_kinds;
mod page_paths;
mod prose;
mod readme;
mod render_markdown_doxygen;
mod rts_reader;
mod serve;
mod sources;
mod spec_sample;
mod stability;
mod systems;
mod xml_reader;
mod yaml_reader;
