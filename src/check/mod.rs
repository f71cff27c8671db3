//! `rtcdoc check`: validation rules over the loaded catalogue, for CI.
//!
//! Every rule has a stable code, a default severity, a short name, an explanation citing the
//! spec section it comes from and a hint ([`registry::RULES`]). Codes: RTC001–RTC019 come from
//! the loader and the catalogue; RTC020–RTC029 from the IDL reader ([`crate::idl::codes`]);
//! RTC1xx schema level (spec chapter 6), RTC2xx spec semantics
//! (chapter 2), RTC3xx values and constraints, RTC4xx catalogue level, RTC5xx doc coverage, RTC6xx RT System
//! profiles.
//!
//! [`run`] returns the rule diagnostics (not the loader's); [`check`] returns a [`Report`] with
//! the loader's and the rules' diagnostics together, counts and the documentation coverage.

mod drift;
mod idl_coverage;
pub mod registry;
pub mod report;
mod rules;
mod systems;

pub use idl_coverage::IdlCoverage;
pub use registry::{explain, rule, Rule, RULES};
pub use rules::check_date_time;

use crate::catalog::Catalog;
use crate::diagnostic::Diagnostic;
use serde::Serialize;
use std::collections::BTreeMap;

/// The most components a core checks without offering the rest to the other cores.
const CHECK_PIECE: usize = 8;

/// Runs every rule over every component and over the catalogue. The catalogue's own
/// diagnostics (loader codes, RTC010 duplicate ids) are not repeated here.
pub fn run(catalog: &Catalog) -> Vec<Diagnostic> {
    use rayon::prelude::*;
    // The rules over the whole catalogue run beside the per-component ones; the findings are
    // joined in the same order either way, and sorted. Each component's findings are sorted
    // where they are made (in parallel; the components are in file order), so that the final
    // (stable) sort meets sorted runs and merges them: the same order, with less serial work.
    let (mut out, whole): (Vec<Diagnostic>, Vec<Diagnostic>) = rayon::join(
        || {
            catalog
                .components
                .par_iter()
                // Small pieces, so that the cores finish together (rayon's adaptive split
                // leaves pieces of a quarter of the list on two cores).
                .with_max_len(CHECK_PIECE)
                .flat_map_iter(|c| {
                    let mut found = rules::component(c);
                    sort(&mut found);
                    found
                })
                .collect()
        },
        || {
            let mut whole = rules::catalogue(catalog);
            whole.extend(idl_coverage::diagnostics(catalog));
            whole.extend(systems::run(catalog));
            whole
        },
    );
    out.extend(whole);
    sort(&mut out);
    out
}

use crate::diagnostic::sort;

/// Documentation coverage of one component.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct ComponentCoverage {
    pub source: String,
    pub name: String,
    /// Items with a non-empty description (component, implemented actions, ports, interfaces,
    /// configurations).
    pub documented: usize,
    pub total: usize,
    /// `documented / total` in percent (100 when there is nothing to document).
    pub percent: f64,
}

/// Documentation coverage of the catalogue: the components' items and the members of the IDL
/// definitions the ports use (RTC506–RTC508) together.
#[derive(Debug, Clone, Serialize, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct Coverage {
    pub documented: usize,
    pub total: usize,
    pub percent: f64,
    pub components: Vec<ComponentCoverage>,
    /// The IDL definitions counted (left out of the JSON when no IDL was read).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub idl: Vec<IdlCoverage>,
}

impl Coverage {
    /// Documented and total members of the IDL definitions alone.
    pub fn idl_counts(&self) -> (usize, usize) {
        (
            self.idl.iter().map(|c| c.documented).sum(),
            self.idl.iter().map(|c| c.total).sum(),
        )
    }
}

pub(crate) fn percent(documented: usize, total: usize) -> f64 {
    if total == 0 {
        100.0
    } else {
        // One decimal, so JSON output is stable and readable.
        (documented as f64 * 1000.0 / total as f64).round() / 10.0
    }
}

/// Computes the documentation coverage of every component and of the whole catalogue.
pub fn coverage(catalog: &Catalog) -> Coverage {
    let components: Vec<ComponentCoverage> = catalog
        .components
        .iter()
        .map(|c| {
            let (documented, total) = rules::doc_items(&c.profile, None);
            ComponentCoverage {
                source: c.source.clone(),
                name: c.profile.name().to_string(),
                documented,
                total,
                percent: percent(documented, total),
            }
        })
        .collect();
    let idl = idl_coverage::coverage(catalog);
    let documented = components.iter().map(|c| c.documented).sum::<usize>()
        + idl.iter().map(|c| c.documented).sum::<usize>();
    let total = components.iter().map(|c| c.total).sum::<usize>()
        + idl.iter().map(|c| c.total).sum::<usize>();
    Coverage {
        documented,
        total,
        percent: percent(documented, total),
        components,
        idl,
    }
}

/// Counts of a set of diagnostics.
#[derive(Debug, Clone, Default, Serialize, PartialEq)]
#[serde(rename_all = "camelCase")]
pub struct Summary {
    pub errors: usize,
    pub warnings: usize,
    pub infos: usize,
    /// Number of diagnostics per code.
    pub by_code: BTreeMap<String, usize>,
}

impl Summary {
    pub fn of(diagnostics: &[Diagnostic]) -> Summary {
        let ([errors, warnings, infos], by_code) =
            crate::diagnostic::tally(diagnostics, |d| d.severity as usize, |d| d.code);
        Summary {
            errors,
            warnings,
            infos,
            by_code,
        }
    }

    /// `check: 0 errors, 3 warnings, 12 infos`.
    pub fn one_line(&self) -> String {
        use crate::diagnostic::counted;
        format!(
            "check: {}, {}, {}",
            counted(self.errors, "error"),
            counted(self.warnings, "warning"),
            counted(self.infos, "info")
        )
    }
}

/// Everything `rtcdoc check` reports about a catalogue.
#[derive(Debug, Clone, Serialize)]
pub struct Report {
    /// Loader, catalogue and rule diagnostics, sorted by file and position.
    pub diagnostics: Vec<Diagnostic>,
    pub summary: Summary,
    pub coverage: Coverage,
}

/// Runs the rules and gathers the catalogue's diagnostics, counts and coverage.
pub fn check(catalog: &Catalog) -> Report {
    let mut diagnostics = catalog.diagnostics.clone();
    diagnostics.extend(run(catalog));
    sort(&mut diagnostics);
    Report {
        summary: Summary::of(&diagnostics),
        coverage: coverage(catalog),
        diagnostics,
    }
}

impl Report {
    /// Merges the reports of several inputs (`rtcdoc check a b`).
    pub fn merge(reports: Vec<Report>) -> Report {
        let mut diagnostics = Vec::new();
        let mut components = Vec::new();
        let mut idl = Vec::new();
        let (mut documented, mut total) = (0, 0);
        for r in reports {
            diagnostics.extend(r.diagnostics);
            components.extend(r.coverage.components);
            idl.extend(r.coverage.idl);
            documented += r.coverage.documented;
            total += r.coverage.total;
        }
        Report {
            summary: Summary::of(&diagnostics),
            coverage: Coverage {
                documented,
                total,
                percent: percent(documented, total),
                components,
                idl,
            },
            diagnostics,
        }
    }

    /// Whether the check fails: errors, or warnings too with `deny_warnings`.
    pub fn failed(&self, deny_warnings: bool) -> bool {
        self.summary.errors > 0 || (deny_warnings && self.summary.warnings > 0)
    }
}

/// One line naming the types whose pages show no definition, for the summary at default
/// verbosity (the per-use findings, RTC5xx infos, need `--verbose`): `note: 3 data types and
/// interfaces are defined in no IDL file read: RTC::TimedLong, … ; add …`. `None` when every
/// type is defined.
/// `config` is the configuration file read, if any: `idl-path` is then set there, since
/// `rtcdoc init` would refuse to overwrite it.
pub fn undefined_types_note(
    cat: &crate::catalog::Catalog,
    config: Option<&std::path::Path>,
) -> Option<String> {
    let names = cat.undefined_types();
    if names.is_empty() {
        return None;
    }
    let list = first_names(&names);
    let what = if cat.idl.is_empty() {
        "no IDL file was read: the pages of".to_string()
    } else {
        "the pages of".to_string()
    };
    let last = match config {
        Some(file) => format!(
            "or set `idl-path` in {} (an OpenRTM installation's rtm/idl)",
            file.display()
        ),
        None => {
            "pass --idl-path DIR (an OpenRTM installation's rtm/idl), or run `rtcdoc init` to find one"
                .to_string()
        }
    };
    Some(format!(
        "{what} {} data type(s) and interface(s) show no definition ({list}); add their IDL files below the input, {last}",
        names.len()
    ))
}

/// The note on the types and interfaces that IDL files below the input define and no page
/// shows (`build::Loaded::idl_on_no_page`); `None` when every one has a page.
pub fn idl_on_no_page_note(names: &[String]) -> Option<String> {
    if names.is_empty() {
        return None;
    }
    Some(format!(
        "{} type(s) and interface(s) that the IDL files below the input define are on no page ({}): a page is made for every interface they define, for what a port uses (`rtc:type` of a data port or service interface) and for the types inside those; catalog.json has them all",
        names.len(),
        first_names(names)
    ))
}

/// The first five of `names`, then how many more (`A, B, C, D, E and 3 more`): a note names
/// a few, not hundreds.
fn first_names<S: AsRef<str>>(names: &[S]) -> String {
    const SHOWN: usize = 5;
    let mut list = names
        .iter()
        .take(SHOWN)
        .map(AsRef::as_ref)
        .collect::<Vec<_>>()
        .join(", ");
    if names.len() > SHOWN {
        list.push_str(&format!(" and {} more", names.len() - SHOWN));
    }
    list
}
