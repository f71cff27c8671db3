//! `rtcdoc diff`: what changed between two catalogues, and what it breaks.
//!
//! Two [`Catalog`]s in, classified [`Change`]s out. Components are matched by id — vendor,
//! category and name, in either id form ([`IdParts`]) — never by file path, so a moved file is
//! no change. Inside a matched pair every value of both profiles is compared: ports,
//! interfaces, configuration parameters, actions, properties and the other named lists are
//! matched by name (the n-th of several with one name as `name#n`), everything else by field.
//! Each difference gets a code from [`codes::CODES`]; a difference no rule classifies is
//! reported as `other-changed`, so nothing goes unreported.
//!
//! The comparison works on the model's JSON form (positions left out), which keeps it complete
//! as the model grows; the typed model is consulted where the meaning matters (canonical type
//! names, directions, value types, constraints).
//!
//! With IDL on the sides, the types the ports and interfaces of a matched pair carry are also
//! compared inside (`idl`: members, enum values, union cases, typedefs, operations); with
//! RT System profiles, the systems themselves are compared (instances, connectors,
//! configuration, execution contexts) and the connectors the component changes break are
//! reported ([`systems`]). Where each side's code and profile disagree (the implementation
//! check's drift), a finding on one side only is a change too ([`drift`]).

pub mod baseline;
pub mod codes;
mod constraint;
mod drift;
mod idl;
pub mod impact;
pub mod policy;
pub mod report;
pub mod side;
pub mod stability;
pub mod systems;

pub use codes::{Code, Level, CODES};
pub use idl::compare_idl_files;
pub use policy::{Standing, Status};

use crate::catalog::{Catalog, Component};
use crate::model::fields::{self, Field, Holds, Node as Kind};
use crate::model::{non_empty, IdParts, Pos, Profile};
use crate::types::canonical_type;
use serde::Serialize;
use serde_json::Value;
use std::collections::BTreeMap;

/// One classified change (the object `--format json` writes; the catalogue keeps the same
/// object with plain strings in a component's history).
pub type Change = crate::catalog::history::Change<Level, &'static str>;

/// Counts of the components, or of the RT System profiles, of both sides.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct Counts {
    pub old: usize,
    pub new: usize,
    /// Found on both sides.
    pub matched: usize,
    /// Matched, with at least one change.
    pub changed: usize,
    pub added: usize,
    pub removed: usize,
}

/// The result of a comparison.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct Diff {
    /// Sorted by component, then path, then code.
    pub changes: Vec<Change>,
    pub components: Counts,
    pub systems: Counts,
    /// The IDL definitions (types and constants, by scoped name) of both sides; `changed`
    /// counts those found on both with a change, compared through a port or on their own.
    pub idl: Counts,
    /// What the `[diff]` policy and the baseline made of each change, in the order of
    /// `changes` (empty: every change counts; see [`Diff::status`]).
    #[serde(skip)]
    pub gate: Vec<Standing>,
    /// The entries of the baseline that no change matches.
    #[serde(skip)]
    pub stale: Vec<baseline::Stale>,
    /// The baseline file applied, as the user named it.
    #[serde(skip)]
    pub baseline: Option<String>,
    /// What the catalogues say the changes reach ([`impact`]; [`Diff::impact`] sums it up).
    #[serde(skip)]
    pub facts: impact::Facts,
}

/// Counts of a set of changes.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct Summary {
    pub breaking: usize,
    pub warning: usize,
    pub info: usize,
    pub by_code: BTreeMap<String, usize>,
    /// Changes a baseline entry accepts (not in the counts above).
    pub accepted: usize,
    /// Changes the `[diff]` policy ignores (not in the counts above).
    pub ignored: usize,
    /// Baseline entries no change matches.
    pub stale: usize,
}

impl Summary {
    /// The counts of `changes`, all of which count.
    pub fn of(changes: &[Change]) -> Summary {
        Summary::of_counting(changes.iter())
    }

    fn of_counting<'a>(changes: impl Iterator<Item = &'a Change>) -> Summary {
        let changes: Vec<&Change> = changes.collect();
        let ([breaking, warning, info], by_code) =
            crate::diagnostic::tally(&changes, |c| c.severity as usize, |c| c.code);
        Summary {
            breaking,
            warning,
            info,
            by_code,
            ..Summary::default()
        }
    }

    /// `2 breaking, 1 warning, 3 infos`, and when there are any `, 1 accepted (baseline), 2
    /// ignored (policy), 1 stale baseline entry`.
    pub fn counts(&self) -> String {
        use crate::diagnostic::counted;
        let mut s = format!(
            "{} breaking, {}, {}",
            self.breaking,
            counted(self.warning, "warning"),
            counted(self.info, "info")
        );
        if self.accepted > 0 {
            s.push_str(&format!(", {} accepted (baseline)", self.accepted));
        }
        if self.ignored > 0 {
            s.push_str(&format!(", {} ignored (policy)", self.ignored));
        }
        if self.stale > 0 {
            let entries = if self.stale == 1 { "entry" } else { "entries" };
            s.push_str(&format!(", {} stale baseline {entries}", self.stale));
        }
        s
    }

    /// Whether a change reaches `fail_on` (`None`: never fail).
    pub fn fails(&self, fail_on: Option<Level>) -> bool {
        match fail_on {
            None => false,
            Some(Level::Breaking) => self.breaking > 0,
            Some(Level::Warning) => self.breaking + self.warning > 0,
            Some(Level::Info) => self.breaking + self.warning + self.info > 0,
        }
    }
}

impl Diff {
    /// The counts of the changes that count, and of those accepted or ignored.
    pub fn summary(&self) -> Summary {
        let counting = (0..self.changes.len()).filter(|&i| *self.status(i) == Status::Counts);
        let mut s = Summary::of_counting(counting.map(|i| &self.changes[i]));
        for g in &self.gate {
            match g.status {
                Status::Counts => {}
                Status::Ignored => s.ignored += 1,
                Status::Accepted(_) => s.accepted += 1,
            }
        }
        s.stale = self.stale.len();
        s
    }

    /// What the policy and the baseline made of the `i`-th change.
    pub fn status(&self, i: usize) -> &Status {
        static COUNTS: Status = Status::Counts;
        self.gate.get(i).map_or(&COUNTS, |g| &g.status)
    }

    /// The registry severity of the `i`-th change, when `[diff] severity` gave it another (or
    /// its severity before an experimental item relaxed it).
    pub fn default_severity(&self, i: usize) -> Option<Level> {
        self.gate.get(i).and_then(|g| g.default_severity)
    }

    /// The experimental item the `i`-th change was relaxed for ([`stability`]).
    pub fn relaxed(&self, i: usize) -> Option<&str> {
        self.gate.get(i).and_then(|g| g.relaxed.as_deref())
    }
}

/// The matching key of a component: vendor, category and name of its id (either form), else of
/// its BasicInfo, else the id as written, else its file.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
struct Key(String, String, String);

struct Ident {
    key: Key,
    version: String,
    /// `RTC:vendor:category:name:version`, the colon form whatever the profile wrote.
    id: String,
    language: String,
}

fn ident(c: &Component) -> Ident {
    ident_of(&c.profile, &c.source)
}

fn ident_of(p: &Profile, source: &str) -> Ident {
    let b = &p.basic_info;
    let language = p.language_kind().unwrap_or("").to_string();
    let raw = non_empty(&p.id);
    if let Some(parts) = raw.and_then(|id| IdParts::parse(id, b)) {
        let key = Key(
            parts.vendor.trim().into(),
            parts.category.trim().into(),
            parts.name.trim().into(),
        );
        return Ident {
            id: format!("RTC:{}:{}:{}:{}", key.0, key.1, key.2, parts.version.trim()),
            version: parts.version.trim().into(),
            key,
            language,
        };
    }
    let field = |s: &Option<crate::model::Text>| non_empty(s).unwrap_or("").to_string();
    let (v, cat, n) = (field(&b.vendor), field(&b.category), field(&b.name));
    let version = field(&b.version);
    if !(v.is_empty() && cat.is_empty() && n.is_empty()) {
        return Ident {
            id: format!("RTC:{v}:{cat}:{n}:{version}"),
            key: Key(v, cat, n),
            version,
            language,
        };
    }
    // Nothing names the component (a fragment, a test file): its file name is all there is,
    // so a file moved to another folder is still found.
    let (id, key) = match raw {
        Some(id) => (
            id.to_string(),
            Key(id.to_string(), String::new(), String::new()),
        ),
        None => {
            let file = source.rsplit('/').next().unwrap_or(source).to_string();
            (
                format!("(no id: {source})"),
                Key(String::new(), String::new(), file),
            )
        }
    };
    Ident {
        key,
        id,
        version,
        language,
    }
}

/// Whether two profiles are versions of one component, as `diff` pairs them: the vendor,
/// category and name of their ids (or BasicInfo) agree, and their languages when both name
/// one. A profile that names no component is no other's.
pub fn same_component(a: &Profile, b: &Profile) -> bool {
    let (x, y) = (ident_of(a, ""), ident_of(b, ""));
    // Not the fallbacks of `ident_of`: the id as written alone, or the file name.
    let named = |i: &Ident| !(i.key.1.is_empty() && (i.key.0.is_empty() || i.key.2.is_empty()));
    named(&x)
        && x.key == y.key
        && (x.language.is_empty() || y.language.is_empty() || x.language == y.language)
}

/// How the files of a catalogue (relative to its input) are named in the changes.
pub type Namer<'a> = &'a dyn Fn(&str) -> String;

/// Compares two catalogues; files are named as in the catalogues.
pub fn diff(old: &Catalog, new: &Catalog) -> Diff {
    diff_named(old, new, &|f| f.to_string(), &|f| f.to_string())
}

/// Compares two versions of one component profile, whatever their ids (a component's history:
/// the same file at two commits): the changes `diff` reports for a matched pair, DIFF208
/// included, sorted. `idl` resolves the types of both versions; `old_file` and `new_file` name
/// the versions' files in the changes.
pub fn compare_profiles(
    (old, old_file): (&Profile, &str),
    (new, new_file): (&Profile, &str),
    idl: &crate::idl::IdlSet,
) -> Vec<Change> {
    let (oi, ni) = (ident_of(old, old_file), ident_of(new, new_file));
    let mut idl = idl::IdlDiff::new(idl, idl);
    let mut out = Vec::new();
    compare(
        &ni.id,
        (old, &oi, old_file),
        (new, &ni, new_file),
        &mut idl,
        &mut out,
    );
    // The IDL of the catalogue is not compared beyond the component's ports here.
    let _ = idl.finish(&mut out);
    sort(&mut out);
    out
}

/// Compares two catalogues, naming the files of OLD with `old_name` and those of NEW with
/// `new_name` (e.g. relative to the current directory).
pub fn diff_named(old: &Catalog, new: &Catalog, old_name: Namer, new_name: Namer) -> Diff {
    let none = systems::Systems::default();
    diff_with_systems(old, new, old_name, new_name, (&none, &none))
}

/// [`diff_named`], and the connectors of the RT System profiles of both sides that the changes
/// break (DIFF14x; see [`systems`]).
pub fn diff_with_systems(
    old: &Catalog,
    new: &Catalog,
    old_name: Namer,
    new_name: Namer,
    (old_systems, new_systems): (&systems::Systems, &systems::Systems),
) -> Diff {
    let mut idl = idl::IdlDiff::new(&old.idl, &new.idl);
    let mut breaks = systems::Breaks::default();
    let old_ids: Vec<Ident> = old.components.iter().map(ident).collect();
    let new_ids: Vec<Ident> = new.components.iter().map(ident).collect();
    let mut groups = groups_by_key(&old_ids, &new_ids);
    pair_renamed(&mut groups, (old, new));
    let mut out = Vec::new();
    let mut labels = impact::Labels::new();
    let mut counts = Counts {
        old: old.components.len(),
        new: new.components.len(),
        ..Default::default()
    };
    for (olds, news) in groups.values() {
        let shared = olds.len() > 1 || news.len() > 1;
        let label = |id: &Ident, c: &Component| -> String {
            if !shared {
                id.id.clone()
            } else if !id.language.is_empty() {
                format!("{} ({})", id.id, id.language)
            } else {
                format!("{} ({})", id.id, c.source)
            }
        };
        let sides = Sides {
            old,
            new,
            old_ids: &old_ids,
            new_ids: &new_ids,
            old_name,
            new_name,
        };
        for (o, n) in pair(olds, news, &sides, &mut out) {
            match (o, n) {
                (Some(o), Some(n)) => {
                    counts.matched += 1;
                    let (oc, nc) = (&old.components[o], &new.components[n]);
                    let before = out.len();
                    let component = label(&new_ids[n], nc);
                    labels.insert(component.clone(), (Some(o), Some(n)));
                    compare(
                        &component,
                        (&oc.profile, &old_ids[o], &old_name(&oc.source)),
                        (&nc.profile, &new_ids[n], &new_name(&nc.source)),
                        &mut idl,
                        &mut out,
                    );
                    breaks.note_ports(&new_ids[n].key, &component, &out[before..]);
                    // Where the code and the profile disagree, on one side only: a pull
                    // request that edits only the code changes this and nothing above.
                    drift::compare(&component, (oc, old_name), (nc, new_name), &mut out);
                    // Renamed (`pair_renamed`): to the systems, the old id is gone.
                    if old_ids[o].key != new_ids[n].key {
                        breaks.note_removed(&old_ids[o].key, &label(&old_ids[o], oc));
                    }
                    if out.len() > before {
                        counts.changed += 1;
                    }
                }
                (Some(o), None) => {
                    counts.removed += 1;
                    let c = &old.components[o];
                    breaks.note_removed(&old_ids[o].key, &label(&old_ids[o], c));
                    labels.insert(label(&old_ids[o], c), (Some(o), None));
                    out.push(component_gone_or_new(
                        (codes::COMPONENT_REMOVED, true),
                        label(&old_ids[o], c),
                        (c, &old_ids[o].id, old_name(&c.source)),
                    ));
                }
                (None, Some(n)) => {
                    counts.added += 1;
                    let c = &new.components[n];
                    labels.insert(label(&new_ids[n], c), (None, Some(n)));
                    out.push(component_gone_or_new(
                        (codes::COMPONENT_ADDED, false),
                        label(&new_ids[n], c),
                        (c, &new_ids[n].id, new_name(&c.source)),
                    ));
                }
                (None, None) => {}
            }
        }
    }
    unreadable_files(
        (old, old_systems, old_name),
        (new, new_systems, new_name),
        &mut out,
    );
    let compared = idl.finish(&mut out);
    let idl_counts = idl::unused_types(
        (&old.idl, old_name),
        (&new.idl, new_name),
        &compared,
        &mut out,
    );
    let system_counts = systems_changes(
        &breaks,
        (old_systems, old_name),
        (new_systems, new_name),
        &mut out,
    );
    sort(&mut out);
    Diff {
        facts: impact::Facts::of(old, new, &out, &labels),
        changes: out,
        components: counts,
        systems: system_counts,
        idl: idl_counts,
        ..Diff::default()
    }
}

/// The files of either side that could not be read (the readers' errors), each a change that
/// says what the comparison misses; RT System profiles are reported with the systems.
fn unreadable_files(
    old: (&Catalog, &systems::Systems, Namer),
    new: (&Catalog, &systems::Systems, Namer),
    out: &mut Vec<Change>,
) {
    for (side, (cat, sys, name)) in [("OLD", old), ("NEW", new)] {
        let is_system =
            |d: &crate::diagnostic::Diagnostic| sys.unreadable.iter().any(|u| u.file == d.file);
        // Only the readers' errors mean a file could not be read: a catalog.json side also
        // holds the check rules' findings, whose files were read.
        for d in cat
            .diagnostics
            .iter()
            .filter(|d| d.is_error() && crate::diagnostic::is_reader_code(d.code) && !is_system(d))
        {
            let then = if is_idl_file(&d.file) {
                "types it defines may be missing from the comparison"
            } else {
                "a component in it counts as absent"
            };
            out.push(unreadable(side, d, name, ("", then)));
        }
    }
}

/// DIFF101 / DIFF304: component `c` (labelled `label`, id `id`) removed
/// (`removed`) or added, at the profile in its file `file`.
fn component_gone_or_new(
    (code, removed): (&'static str, bool),
    label: String,
    (c, id, file): (&Component, &str, String),
) -> Change {
    let at = Some(c.profile.pos).filter(|p| !p.is_unknown());
    let (what, old, new) = if removed {
        ("removed", Some(id.to_string()), None)
    } else {
        ("added", None, Some(id.to_string()))
    };
    let base = change(
        code,
        label,
        String::new(),
        old,
        new,
        format!("component `{}` was {what}", c.profile.name()),
    );
    if removed {
        Change {
            old_file: Some(file),
            old_line: at.map(|p| p.line),
            old_column: at.map(|p| p.column),
            ..base
        }
    } else {
        Change {
            file: Some(file),
            line: at.map(|p| p.line),
            column: at.map(|p| p.column),
            ..base
        }
    }
}

/// The changes of the RT Systems of both sides: those that could not be read, the connectors
/// the components' changes break (`breaks`), and each pair of systems compared; their counts.
fn systems_changes(
    breaks: &systems::Breaks,
    (old_systems, old_name): (&systems::Systems, Namer),
    (new_systems, new_name): (&systems::Systems, Namer),
    out: &mut Vec<Change>,
) -> Counts {
    systems::unreadable("OLD", &old_systems.unreadable, old_name, out);
    systems::unreadable("NEW", &new_systems.unreadable, new_name, out);
    breaks.connectors(
        &old_systems.systems,
        &new_systems.systems,
        old_name,
        new_name,
        out,
    );
    systems::compare_all(
        &old_systems.systems,
        &new_systems.systems,
        old_name,
        new_name,
        out,
    )
}

/// The components of both sides by key (vendor, category, name): the indexes of the old and
/// the new ones of each.
fn groups_by_key<'k>(
    old_ids: &'k [Ident],
    new_ids: &'k [Ident],
) -> BTreeMap<&'k Key, (Vec<usize>, Vec<usize>)> {
    let mut groups: BTreeMap<&Key, (Vec<usize>, Vec<usize>)> = BTreeMap::new();
    for (i, id) in old_ids.iter().enumerate() {
        groups.entry(&id.key).or_default().0.push(i);
    }
    for (i, id) in new_ids.iter().enumerate() {
        groups.entry(&id.key).or_default().1.push(i);
    }
    groups
}

/// An IDL file (its errors leave types undefined rather than components absent).
fn is_idl_file(file: &str) -> bool {
    std::path::Path::new(file)
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("idl"))
}

/// Sorts changes by component, path, severity, code and message.
pub fn sort(changes: &mut [Change]) {
    changes.sort_by(|a, b| {
        (
            &a.component,
            &a.path,
            a.severity,
            a.code,
            &a.message,
            &a.file,
        )
            .cmp(&(
                &b.component,
                &b.path,
                b.severity,
                b.code,
                &b.message,
                &b.file,
            ))
    });
}

/// Both catalogues with their identities and file namers.
struct Sides<'a> {
    old: &'a Catalog,
    new: &'a Catalog,
    old_ids: &'a [Ident],
    new_ids: &'a [Ident],
    old_name: Namer<'a>,
    new_name: Namer<'a>,
}

/// Of the components no component of the other side shares an id key with, those that are one
/// component renamed: the one component of each side (two files, folders or revisions of one
/// component compared), or the same file on both sides, when the two share a port or parameter
/// name ([`shares_an_element`]). The NEW one is moved into the OLD one's group, so that the two are compared as
/// a pair, as a component's history compares two versions of its file: the id's change is
/// DIFF101 with every other change beside it, instead of the whole component removed and
/// another added.
fn pair_renamed(
    groups: &mut BTreeMap<&Key, (Vec<usize>, Vec<usize>)>,
    (old, new): (&Catalog, &Catalog),
) {
    let lone = |g: &(Vec<usize>, Vec<usize>), old_side: bool| {
        let (mine, theirs) = if old_side { (&g.0, &g.1) } else { (&g.1, &g.0) };
        (mine.len() == 1 && theirs.is_empty()).then(|| mine[0])
    };
    let removed: Vec<usize> = groups.values().filter_map(|g| lone(g, true)).collect();
    let added: Vec<usize> = groups.values().filter_map(|g| lone(g, false)).collect();
    let mut pairs: Vec<(usize, usize)> = Vec::new();
    let one_each = old.components.len() == 1 && new.components.len() == 1;
    for &o in &removed {
        let oc = &old.components[o];
        let found = added.iter().find(|&&n| {
            let nc = &new.components[n];
            (one_each || oc.source == nc.source)
                && shares_an_element(&oc.profile, &nc.profile)
                && !pairs.iter().any(|&(_, m)| m == n)
        });
        if let Some(&n) = found {
            pairs.push((o, n));
        }
    }
    for &(o, n) in &pairs {
        for g in groups.values_mut() {
            if g.1 == [n] && g.0.is_empty() {
                g.1.clear();
            }
            if g.0 == [o] && g.1.is_empty() {
                g.1.push(n);
            }
        }
    }
    groups.retain(|_, g| !g.0.is_empty() || !g.1.is_empty());
}

/// Whether two profiles have a data port, service port (or interface) or configuration
/// parameter of the same name (their keys as the diff names them,
/// [`crate::catalog::history::ElementKeys`]): what makes a component under a new id the same
/// component rather than another one.
fn shares_an_element(a: &Profile, b: &Profile) -> bool {
    use crate::catalog::history::ElementKeys;
    let (a, b) = (ElementKeys::of(a), ElementKeys::of(b));
    let theirs: std::collections::BTreeSet<&String> = b.all().collect();
    let shared = a
        .all()
        .filter(|k| !k.contains("(unnamed)"))
        .any(|k| theirs.contains(k));
    shared
}

/// Pairs the components of one id: one on each side is a pair; several are paired by language,
/// then by identical path, then by identical content (copies), and when one is left on each side
/// those two. What is left on both sides is ambiguous (reported, not compared); what is left on
/// one side only is added or removed.
fn pair(
    olds: &[usize],
    news: &[usize],
    sides: &Sides,
    out: &mut Vec<Change>,
) -> Vec<(Option<usize>, Option<usize>)> {
    let Sides {
        old,
        new,
        old_ids,
        new_ids,
        old_name,
        new_name,
    } = *sides;
    if olds.len() <= 1 && news.len() <= 1 {
        return vec![(olds.first().copied(), news.first().copied())];
    }
    let mut result = Vec::new();
    let mut langs: BTreeMap<String, (Vec<usize>, Vec<usize>)> = BTreeMap::new();
    for &o in olds {
        langs
            .entry(old_ids[o].language.to_lowercase())
            .or_default()
            .0
            .push(o);
    }
    for &n in news {
        langs
            .entry(new_ids[n].language.to_lowercase())
            .or_default()
            .1
            .push(n);
    }
    for (lang, (mut lo, mut ln)) in langs {
        if lo.len() == 1 && ln.len() == 1 {
            result.push((Some(lo[0]), Some(ln[0])));
            continue;
        }
        // Same file on both sides: the same component.
        lo.retain(|&o| {
            match ln
                .iter()
                .position(|&n| new.components[n].source == old.components[o].source)
            {
                Some(at) => {
                    result.push((Some(o), Some(ln.remove(at))));
                    false
                }
                None => true,
            }
        });
        // Copies: a profile equal to one of the other side (positions aside) is that one.
        // Looked up by a fingerprint, so that a thousand copies of one id stay linear.
        let mut by_print: BTreeMap<u64, Vec<usize>> = BTreeMap::new();
        for &n in ln.iter().rev() {
            by_print
                .entry(fingerprint(&new.components[n].profile))
                .or_default()
                .push(n);
        }
        lo.retain(|&o| {
            let op = &old.components[o].profile;
            let twin = by_print.get_mut(&fingerprint(op)).and_then(|v| {
                let at = v
                    .iter()
                    .rposition(|&n| same_values(op, &new.components[n].profile))?;
                Some(v.remove(at))
            });
            match twin {
                Some(n) => {
                    ln.retain(|&x| x != n);
                    result.push((Some(o), Some(n)));
                    false
                }
                None => true,
            }
        });
        // One left on each side: the changed one.
        if lo.len() == 1 && ln.len() == 1 {
            result.push((Some(lo[0]), Some(ln[0])));
            continue;
        }
        if !lo.is_empty() && !ln.is_empty() {
            let files = |v: &[usize], cat: &Catalog, name: Namer| {
                v.iter().map(|&i| name(&cat.components[i].source)).collect()
            };
            let id = &new_ids[ln[0]];
            let lang_text = if lang.is_empty() {
                String::new()
            } else {
                format!(" in {}", id.language)
            };
            out.push(ambiguous(
                codes::AMBIGUOUS_COMPONENT,
                &id.id,
                [files(&lo, old, old_name), files(&ln, new, new_name)],
                format!(
                    "{} profiles in OLD and {} in NEW declare component `{}`{lang_text}; they cannot be paired and are not compared (give each component its own id)",
                    lo.len(),
                    ln.len(),
                    id.id
                ),
            ));
            continue;
        }
        result.extend(lo.into_iter().map(|o| (Some(o), None)));
        result.extend(ln.into_iter().map(|n| (None, Some(n))));
    }
    result
}

/// The change of an id that several profiles declare on each side, so that none of them is
/// paired: the files of both sides (as the user names them), the first the one it points at.
fn ambiguous(
    code: &'static str,
    id: &str,
    [old, new]: [Vec<String>; 2],
    message: String,
) -> Change {
    Change {
        file: new.first().cloned(),
        old_file: old.first().cloned(),
        ..change(
            code,
            id.to_string(),
            String::new(),
            Some(old.join(", ")),
            Some(new.join(", ")),
            message,
        )
    }
}

fn change(
    code: &'static str,
    component: String,
    path: String,
    old: Option<String>,
    new: Option<String>,
    message: String,
) -> Change {
    let c = codes::code(code).expect("every code used is registered");
    Change {
        severity: c.level,
        code: c.code,
        name: c.name,
        component,
        path,
        old,
        new,
        message,
        file: None,
        line: None,
        column: None,
        old_file: None,
        old_line: None,
        old_column: None,
    }
}

// ---------------------------------------------------------------------------------------------
// The value tree both profiles are compared on.

/// A profile as a tree of records (struct fields), keyed lists (items matched by name) and
/// leaves (compared as a whole). Positions are kept beside the values, not compared.
#[derive(Debug, Clone, PartialEq)]
enum Node {
    Leaf(Value),
    Record(BTreeMap<String, Node>, Option<Pos>),
    Keyed(BTreeMap<String, Node>),
}

/// Lists whose items are matched by name (`actions` by kind), from the field table; other
/// lists are compared whole.
fn item_key(list: &str) -> Option<&'static str> {
    fields::item_key(list)
}

/// The JSON keys of the configuration set on the profile and of its parameters on the set:
/// the tree lifts the parameters to the top level under the second.
fn configuration_keys() -> (&'static str, &'static str) {
    let key = |parent: Kind, node: Kind| {
        fields::CHILDREN
            .iter()
            .find(|c| c.parent == parent && c.node == node)
            .map_or("", |c| c.json)
    };
    (
        key(Kind::Profile, Kind::ConfigurationSet),
        key(Kind::ConfigurationSet, Kind::Configuration),
    )
}

/// What a path of the tree points at, by the field table: a typed field path, so that a
/// renamed serde field cannot silently change a change's code.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Place {
    /// A scalar field (`dataPorts/<name>/unit` → [`Field::DataPortUnit`]).
    Field(Field),
    /// An item of a list matched by name (`dataPorts/<name>`).
    Item(Kind),
    /// A child node or a value compared whole, on its parent (`…/<name>/constraint`).
    Child { parent: Kind, node: Kind },
    /// Anything else (`extra`, `writtenAs`, an unknown key).
    Other,
}

/// The [`Place`] of a path, and whether a change there is documentation only (inside a doc
/// node, or a field the table marks as documentation).
fn place(p: &[String]) -> (Place, bool) {
    let (_, configurations) = configuration_keys();
    let mut node = Kind::Profile;
    let mut doc = false;
    let mut at = Place::Other;
    let mut i = 0;
    while i < p.len() {
        let seg = p[i].as_str();
        // The parameters are lifted to the top level (see [`tree`]).
        let child = if node == Kind::Profile && seg == configurations {
            Kind::ConfigurationSet.child(seg)
        } else {
            node.child(seg)
        };
        if let Some(c) = child {
            doc |= c.doc || c.node.is_doc();
            i += 1;
            at = match c.holds {
                Holds::Keyed(_) if i < p.len() => {
                    i += 1;
                    Place::Item(c.node)
                }
                _ => Place::Child {
                    parent: node,
                    node: c.node,
                },
            };
            node = c.node;
            continue;
        }
        return match node.json_field(seg) {
            Some(f) if i + 1 == p.len() => (Place::Field(f), doc || f.def().doc),
            _ => (Place::Other, doc),
        };
    }
    (at, doc)
}

/// The label of each item: its name (`(unnamed)` when empty), `name#2` for the second with the
/// same name. The typed lookups use the same labels.
fn labels<'a>(names: impl Iterator<Item = Option<&'a str>>) -> Vec<String> {
    crate::catalog::history::item_labels(names)
}

/// A hash of a profile's values without positions: equal for copies of one profile (a match
/// is confirmed by comparing the two, so a collision cannot pair different profiles).
fn fingerprint(p: &Profile) -> u64 {
    use std::hash::{Hash, Hasher};
    fn feed(v: &Value, h: &mut std::collections::hash_map::DefaultHasher) {
        match v {
            Value::Null => 0u8.hash(h),
            Value::Bool(b) => (1u8, b).hash(h),
            Value::Number(n) => (2u8, n.to_string()).hash(h),
            Value::String(s) => (3u8, s).hash(h),
            Value::Array(a) => {
                (4u8, a.len()).hash(h);
                a.iter().for_each(|x| feed(x, h));
            }
            Value::Object(m) => {
                5u8.hash(h);
                for (k, x) in m.iter().filter(|(k, _)| !bookkeeping(k)) {
                    k.hash(h);
                    feed(x, h);
                }
            }
        }
    }
    let mut h = std::collections::hash_map::DefaultHasher::new();
    feed(&serde_json::to_value(p).unwrap_or(Value::Null), &mut h);
    h.finish()
}

/// Whether two profiles have the same values (positions aside).
fn same_values(a: &Profile, b: &Profile) -> bool {
    let (x, y) = (tree(a), tree(b));
    let mut found = Vec::new();
    walk(&mut Vec::new(), &x, &y, None, &mut found);
    found.is_empty()
}

fn pos_of(v: &Value) -> Option<Pos> {
    let line = v.get("line")?.as_u64()? as u32;
    let column = v.get("column")?.as_u64()? as u32;
    (line > 0).then_some(Pos::new(line, column))
}

/// The reader's bookkeeping, not values of the profile: positions, and which older spellings
/// the file used (`writtenAs`; the values are read into the fields they mean, so a file
/// re-saved with the current spellings has the same values).
fn bookkeeping(key: &str) -> bool {
    matches!(key, "pos" | "actionsPos" | "writtenAs")
}

/// `v` without its bookkeeping keys, for comparing leaves.
fn strip_pos(v: Value) -> Value {
    match v {
        Value::Object(m) => Value::Object(
            m.into_iter()
                .filter(|(k, _)| !bookkeeping(k))
                .map(|(k, v)| (k, strip_pos(v)))
                .collect(),
        ),
        Value::Array(a) => Value::Array(a.into_iter().map(strip_pos).collect()),
        other => other,
    }
}

fn node(key: &str, v: Value) -> Node {
    match v {
        // A constraint is compared whole (as a formula, by the classification).
        Value::Object(mut m) if !fields::compared_whole(key) => {
            let pos = m.get("pos").and_then(pos_of);
            m.retain(|k, _| !bookkeeping(k));
            Node::Record(
                m.into_iter()
                    .map(|(k, v)| (k.clone(), node(&k, v)))
                    .collect(),
                pos,
            )
        }
        Value::Array(items) => match item_key(key) {
            Some(field) if items.iter().all(Value::is_object) => {
                let names = labels(items.iter().map(|i| i.get(field).and_then(Value::as_str)));
                Node::Keyed(
                    names
                        .into_iter()
                        .zip(items)
                        .map(|(n, i)| (n, node("", i)))
                        .collect(),
                )
            }
            _ => Node::Leaf(strip_pos(Value::Array(items))),
        },
        other => Node::Leaf(strip_pos(other)),
    }
}

/// The tree of a profile: its JSON form with the configuration parameters lifted to a
/// top-level `configurations` list (paths read `configurations/max_speed/defaultValue`).
fn tree(p: &Profile) -> Node {
    let mut v = serde_json::to_value(p).unwrap_or(Value::Null);
    let (set, configurations) = configuration_keys();
    if let Some(m) = v.as_object_mut() {
        let configs = m
            .get_mut(set)
            .and_then(Value::as_object_mut)
            .and_then(|cs| cs.remove(configurations))
            .unwrap_or(Value::Array(Vec::new()));
        m.insert(configurations.into(), configs);
    }
    node("", v)
}

/// One difference between the trees, before classification.
enum Raw<'a> {
    Changed(Value, Value),
    Added(&'a Node),
    Removed(&'a Node),
}

struct Found<'a> {
    path: Vec<String>,
    raw: Raw<'a>,
    /// NEW's position of the item, or of its nearest enclosing record.
    pos: Option<Pos>,
}

static EMPTY: std::sync::LazyLock<BTreeMap<String, Node>> = std::sync::LazyLock::new(BTreeMap::new);
const NULL: Node = Node::Leaf(Value::Null);

fn walk<'a>(
    path: &mut Vec<String>,
    o: &'a Node,
    n: &'a Node,
    pos: Option<Pos>,
    out: &mut Vec<Found<'a>>,
) {
    match (o, n) {
        (Node::Leaf(a), Node::Leaf(b)) => {
            // An empty list is no list: a `Language` element without targets adds no targets.
            let absent = |v: &Value| v.is_null() || v.as_array().is_some_and(Vec::is_empty);
            if a != b && !(absent(a) && absent(b)) {
                out.push(Found {
                    path: path.clone(),
                    raw: Raw::Changed(a.clone(), b.clone()),
                    pos,
                });
            }
        }
        (Node::Record(a, _), Node::Record(b, np)) => children(path, (a, b), np.or(pos), out, false),
        (Node::Record(a, _), Node::Leaf(Value::Null)) => {
            children(path, (a, &EMPTY), pos, out, false)
        }
        (Node::Leaf(Value::Null), Node::Record(b, np)) => {
            children(path, (&EMPTY, b), np.or(pos), out, false)
        }
        (Node::Keyed(a), Node::Keyed(b)) => children(path, (a, b), pos, out, true),
        (Node::Keyed(a), Node::Leaf(Value::Null)) => children(path, (a, &EMPTY), pos, out, true),
        (Node::Leaf(Value::Null), Node::Keyed(b)) => children(path, (&EMPTY, b), pos, out, true),
        _ => out.push(Found {
            path: path.clone(),
            raw: Raw::Changed(plain(o), plain(n)),
            pos,
        }),
    }
}

/// The children of two records (`keyed` false: a field one side lacks is compared as null) or
/// of two keyed lists (`keyed` true: an item one side lacks is removed or added).
fn children<'a>(
    path: &mut Vec<String>,
    (a, b): (&'a BTreeMap<String, Node>, &'a BTreeMap<String, Node>),
    pos: Option<Pos>,
    out: &mut Vec<Found<'a>>,
    keyed: bool,
) {
    let mut keys: Vec<&String> = a.keys().chain(b.keys()).collect();
    keys.sort();
    keys.dedup();
    for k in keys {
        path.push(k.clone());
        match (a.get(k), b.get(k)) {
            (Some(x), Some(y)) => walk(path, x, y, pos, out),
            (x, y) if !keyed => walk(path, x.unwrap_or(&NULL), y.unwrap_or(&NULL), pos, out),
            (Some(x), None) => out.push(Found {
                path: path.clone(),
                raw: Raw::Removed(x),
                pos,
            }),
            (None, Some(y)) => out.push(Found {
                path: path.clone(),
                raw: Raw::Added(y),
                pos: record_pos(y).or(pos),
            }),
            (None, None) => {}
        }
        path.pop();
    }
}

fn record_pos(n: &Node) -> Option<Pos> {
    match n {
        Node::Record(_, p) => *p,
        _ => None,
    }
}

/// A node back as plain JSON (for a value whose shape changed).
fn plain(n: &Node) -> Value {
    match n {
        Node::Leaf(v) => v.clone(),
        Node::Record(m, _) | Node::Keyed(m) => {
            Value::Object(m.iter().map(|(k, v)| (k.clone(), plain(v))).collect())
        }
    }
}

/// A leaf as text: strings as written, `null` as absent, anything else as compact JSON.
fn text(v: &Value) -> Option<String> {
    match v {
        Value::Null => None,
        Value::String(s) => Some(s.clone()),
        other => Some(other.to_string()),
    }
}

/// A field of an item node, as text.
fn field(n: &Node, f: Field) -> Option<String> {
    match n {
        Node::Record(m, _) => match m.get(f.json()) {
            Some(Node::Leaf(v)) => text(v).filter(|s| !s.trim().is_empty()),
            _ => None,
        },
        _ => None,
    }
}

// ---------------------------------------------------------------------------------------------
// Classification.

struct Ctx<'a> {
    component: &'a str,
    old: &'a Profile,
    new: &'a Profile,
    file: &'a str,
    old_file: &'a str,
}

impl Ctx<'_> {
    fn push(
        &self,
        out: &mut Vec<Change>,
        code: &'static str,
        path: &[String],
        pos: Option<Pos>,
        (old, new): (Option<String>, Option<String>),
        message: String,
    ) {
        out.push(Change {
            file: Some(self.file.to_string()),
            old_file: Some(self.old_file.to_string()),
            line: pos.map(|p| p.line),
            column: pos.map(|p| p.column),
            ..change(
                code,
                self.component.to_string(),
                path.join("/"),
                old,
                new,
                message,
            )
        });
    }
}

fn compare(
    component: &str,
    (op, oi, old_file): (&Profile, &Ident, &str),
    (np, ni, file): (&Profile, &Ident, &str),
    idl: &mut idl::IdlDiff,
    out: &mut Vec<Change>,
) {
    let (ot, nt) = (tree(op), tree(np));
    let mut found = Vec::new();
    walk(
        &mut Vec::new(),
        &ot,
        &nt,
        Some(np.pos).filter(|p| !p.is_unknown()),
        &mut found,
    );
    let ctx = Ctx {
        component,
        old: op,
        new: np,
        file,
        old_file,
    };
    let start = out.len();
    let basic_version_changed = found
        .iter()
        .any(|f| place(&f.path).0 == Place::Field(Field::BasicVersion));
    for f in &found {
        classify(&ctx, f, basic_version_changed, oi, ni, out);
    }
    idl::component(idl, &ctx, op, np, out);
    let breaking = out[start..].iter().any(|c| c.severity == Level::Breaking);
    let bumped = oi.version != ni.version || basic_version_changed;
    if breaking && !bumped {
        let version = non_empty(&np.basic_info.version)
            .map(str::to_string)
            .or_else(|| Some(ni.version.clone()).filter(|v| !v.is_empty()));
        let pos = np
            .basic_info
            .attr_pos
            .field(Field::BasicVersion)
            .or(Some(np.basic_info.pos));
        ctx.push(
            out,
            codes::BREAKING_WITHOUT_BUMP,
            &[
                Kind::Profile
                    .children()
                    .find(|c| c.node == Kind::BasicInfo)
                    .map_or("", |c| c.json)
                    .into(),
                Field::BasicVersion.json().into(),
            ],
            pos.filter(|p| !p.is_unknown()),
            (version.clone(), version.clone()),
            format!(
                "`{}` has breaking changes but keeps version {}; raise the version (in the id and in BasicInfo)",
                np.name(),
                version.as_deref().unwrap_or("(none)")
            ),
        );
    }
}

fn s(p: &[String], i: usize) -> &str {
    p.get(i).map(String::as_str).unwrap_or("")
}

/// The typed item labelled `label` among `items`.
/// The items of `new` that `old` has an item of the same label for: (label, old, new).
fn same_label<'a, T>(
    old: &'a [T],
    new: &'a [T],
    name: impl Fn(&T) -> Option<&str>,
) -> Vec<(String, &'a T, &'a T)> {
    let old_labels = labels(old.iter().map(&name));
    labels(new.iter().map(&name))
        .into_iter()
        .zip(new)
        .filter_map(|(l, n)| {
            let o = old_labels.iter().position(|x| *x == l).map(|i| &old[i])?;
            Some((l, o, n))
        })
        .collect()
}

fn by_label<'a, T>(
    items: &'a [T],
    name: impl Fn(&T) -> Option<&str>,
    label: &str,
) -> Option<&'a T> {
    let names = labels(items.iter().map(&name));
    names.iter().position(|n| n == label).map(|i| &items[i])
}

fn classify(
    ctx: &Ctx,
    f: &Found,
    basic_version_changed: bool,
    oi: &Ident,
    ni: &Ident,
    out: &mut Vec<Change>,
) {
    let p = &f.path;
    let pos = f.pos;
    let (at, documentation) = place(p);
    // Any other item removed or added: a documentation change or another change, its text
    // the value.
    let other = |verb: &str, node: &Node| {
        let code = if documentation {
            codes::DOCUMENTATION_CHANGED
        } else {
            codes::OTHER_CHANGED
        };
        let value = Some(plain(node)).as_ref().and_then(text);
        (code, format!("was {verb}"), value)
    };
    // Documentation left blank and documentation left out say the same: RTCBuilder writes
    // `rtcDoc:description=""` for every field it leaves blank, other writers (and its other
    // versions) leave the attribute or the whole doc element out.
    let blank = |v: &Value| text(v).is_none_or(|s| s.trim().is_empty());
    if let Raw::Changed(a, b) = &f.raw {
        if documentation && blank(a) && blank(b) {
            return;
        }
    }
    // Save stamps: RTCBuilder rewrites `updateDate` at every save (and `creationDate` when it
    // re-creates the profile); they date the file, they change nothing of the component.
    if let Place::Field(Field::BasicCreationDate | Field::BasicUpdateDate) = at {
        return;
    }
    // An action not implemented and an action not listed say the same (RTCBuilder lists
    // every callback, `implemented="false"` for those left out; other writers list only the
    // implemented ones): nothing to report when it holds nothing else.
    if let (Place::Item(Kind::Action), Raw::Added(node) | Raw::Removed(node)) = (at, &f.raw) {
        if unimplemented_only(node, item_key(s(p, 0))) {
            return;
        }
    }
    match &f.raw {
        Raw::Removed(node) => {
            let (code, message, old) = match at {
                Place::Item(Kind::DataPort) => (
                    codes::DATA_PORT_REMOVED,
                    format!("data port `{}` was removed", p[1]),
                    field(node, Field::DataPortType),
                ),
                Place::Item(Kind::ServicePort) => (
                    codes::SERVICE_PORT_REMOVED,
                    format!("service port `{}` was removed", p[1]),
                    None,
                ),
                Place::Item(Kind::ServiceInterface) => (
                    codes::INTERFACE_REMOVED,
                    format!(
                        "{} interface `{}` of service port `{}` was removed",
                        field(node, Field::InterfaceDirection).unwrap_or_else(|| "service".into()),
                        p[3],
                        p[1]
                    ),
                    field(node, Field::InterfaceType),
                ),
                Place::Item(Kind::Configuration) => (
                    codes::CONFIGURATION_REMOVED,
                    format!("configuration parameter `{}` was removed", p[1]),
                    field(node, Field::ConfigurationType),
                ),
                Place::Item(Kind::Action)
                    if crate::model::parse_bool(
                        field(node, Field::ActionImplemented).as_deref(),
                    ) == Some(true) =>
                {
                    (
                        codes::ACTION_NOT_IMPLEMENTED,
                        format!("action `{}` is no longer listed (it was implemented)", p[1]),
                        field(node, Field::ActionImplemented),
                    )
                }
                _ => other("removed", node),
            };
            // Where it was: in OLD, the side where it exists; in NEW, a removed parameter's
            // configuration set (an annotation of NEW's file needs a line there), else nothing
            // (NEW's enclosing record is not where the item was).
            let in_new = match (p.first(), &ctx.new.configuration_set) {
                (Some(k), Some(cs)) if k == configuration_keys().1 && !cs.pos.is_unknown() => {
                    Some(cs.pos)
                }
                _ => None,
            };
            ctx.push(out, code, p, in_new, (old, None), message);
            if let (Some(last), Some(at)) = (out.last_mut(), record_pos(node)) {
                last.old_line = Some(at.line);
                last.old_column = Some(at.column);
            }
        }
        Raw::Added(node) => {
            let (code, message, new) = match at {
                Place::Item(Kind::DataPort) => (
                    codes::PORT_ADDED,
                    format!(
                        "data port `{}` ({}) was added",
                        p[1],
                        field(node, Field::DataPortPortType).unwrap_or_default()
                    ),
                    field(node, Field::DataPortType),
                ),
                Place::Item(Kind::ServicePort) => (
                    codes::PORT_ADDED,
                    format!("service port `{}` was added", p[1]),
                    None,
                ),
                Place::Item(Kind::ServiceInterface) => {
                    let required = field(node, Field::InterfaceDirection)
                        .is_some_and(|d| d.trim().eq_ignore_ascii_case("required"));
                    let code = if required {
                        codes::REQUIRED_INTERFACE_ADDED
                    } else {
                        codes::INTERFACE_ADDED
                    };
                    (
                        code,
                        format!(
                            "{} interface `{}` was added to service port `{}`",
                            field(node, Field::InterfaceDirection)
                                .unwrap_or_else(|| "service".into()),
                            p[3],
                            p[1]
                        ),
                        field(node, Field::InterfaceType),
                    )
                }
                Place::Item(Kind::Configuration) => (
                    codes::CONFIGURATION_ADDED,
                    format!(
                        "configuration parameter `{}` was added (default {})",
                        p[1],
                        field(node, Field::ConfigurationDefaultValue)
                            .map(|d| format!("`{d}`"))
                            .unwrap_or_else(|| "empty".into())
                    ),
                    field(node, Field::ConfigurationType),
                ),
                _ => other("added", node),
            };
            ctx.push(out, code, p, pos, (None, new), message);
        }
        Raw::Changed(a, b) => {
            let (old, new) = (text(a), text(b));
            let (code, message) = changed(
                ctx,
                p,
                old.as_deref(),
                new.as_deref(),
                basic_version_changed,
                oi,
                ni,
            );
            let Some(code) = code else { return };
            // Constraints are shown as formulas, not as their JSON.
            let (old, new) = if at
                == (Place::Child {
                    parent: Kind::Configuration,
                    node: Kind::Constraint,
                }) {
                let c = |prof: &Profile| {
                    by_label(prof.configurations(), |c| c.name.as_deref(), s(p, 1))
                        .and_then(|c| c.constraint.as_ref())
                        .map(crate::constraint::describe)
                };
                (c(ctx.old), c(ctx.new))
            } else {
                (old, new)
            };
            ctx.push(out, code, p, pos, (old, new), message);
        }
    }
}

/// Whether the vendor, category or name of an id changed, and each part that changed was
/// RTCBuilder's placeholder for it (`VenderName`, `Category`, `ModuleName`, a `$` variable):
/// the component named for the first time.
fn named_first(old: &Ident, new: &Ident) -> bool {
    let parts = [
        ("vendor", &old.key.0, &new.key.0),
        ("category", &old.key.1, &new.key.1),
        ("name", &old.key.2, &new.key.2),
    ];
    old.key != new.key
        && parts
            .iter()
            .all(|(field, o, n)| o == n || crate::model::is_placeholder(field, o))
}

/// An action item that says only that it is not implemented: its kind (`key`), an
/// `implemented` that is not true, and nothing else but blank values.
fn unimplemented_only(node: &Node, key: Option<&str>) -> bool {
    fn blank(n: &Node) -> bool {
        match n {
            Node::Leaf(v) => text(v).is_none_or(|s| s.trim().is_empty()),
            Node::Record(m, _) | Node::Keyed(m) => m.values().all(blank),
        }
    }
    let Node::Record(m, _) = node else {
        return false;
    };
    let implemented = Field::ActionImplemented.json();
    let not_true =
        crate::model::parse_bool(field(node, Field::ActionImplemented).as_deref()) != Some(true);
    not_true
        && m.iter()
            .all(|(k, v)| k == implemented || Some(k.as_str()) == key || blank(v))
}

/// DIFF002 for a file `side` could not read: "{side}: {what}FILE could not be read (…); {then}",
/// at the file (NEW's) or the old file.
fn unreadable(
    side: &str,
    d: &crate::diagnostic::Diagnostic,
    name: Namer,
    (what, then): (&str, &str),
) -> Change {
    let mut c = change(
        codes::UNREADABLE_PROFILE,
        String::new(),
        String::new(),
        None,
        None,
        format!(
            "{side}: {what}{} could not be read ({}[{}]: {}); {then}",
            name(&d.file),
            d.severity,
            d.code,
            d.message,
        ),
    );
    if side == "NEW" {
        c.file = Some(name(&d.file));
        c.line = d.pos.map(|p| p.line);
        c.column = d.pos.map(|p| p.column);
    } else {
        c.old_file = Some(name(&d.file));
    }
    c
}

fn quoted(s: Option<&str>) -> String {
    match s {
        None => "(absent)".into(),
        // `` would open a code span instead of showing an empty one.
        Some("") => "(empty)".into(),
        Some(s) => crate::render::text::code_span(s),
    }
}

/// "{subject} is spelled differently ({o} → {n}) but {same}": a value written another way
/// with the same meaning (`o` and `n` already [`quoted`]); without a subject (the change's
/// path names it) "spelled differently …".
fn respelled_message(subject: &str, o: &str, n: &str, same: &str) -> String {
    if subject.is_empty() {
        return format!("spelled differently ({o} → {n}) but {same}");
    }
    format!("{subject} is spelled differently ({o} → {n}) but {same}")
}

/// The code and message of a changed leaf (the generic "changed from … to …" where its place
/// has none of its own); no code to report nothing (a change already reported under another
/// path).
fn changed(
    ctx: &Ctx,
    p: &[String],
    old: Option<&str>,
    new: Option<&str>,
    basic_version_changed: bool,
    oi: &Ident,
    ni: &Ident,
) -> (Option<&'static str>, String) {
    let last = p.last().map(String::as_str).unwrap_or("");
    let (at, documentation) = place(p);
    let (o, n) = (quoted(old), quoted(new));
    // The change's path names the value: the messages do not say it again.
    let spelled = |what: &str| Some(respelled_message("", &o, &n, what));
    // `code` with `message`, unless the two spellings are the `same` (`what` says in what way).
    let same_or = |same: bool, what: &str, code: &'static str, message: String| {
        if same {
            (Some(codes::OTHER_CHANGED), spelled(what))
        } else {
            (Some(code), Some(message))
        }
    };
    let (code, message) = match at {
        Place::Field(Field::ProfileId) => {
            if oi.version != ni.version && oi.key == ni.key {
                if basic_version_changed {
                    (None, None)
                } else {
                    (
                        Some(codes::VERSION_CHANGED),
                        Some(format!("version {} → {}", oi.version, ni.version)),
                    )
                }
            } else if named_first(oi, ni) {
                // RTCBuilder's first save, before the wizard was filled in: the component
                // had no name of its own yet, so no one can refer to the old one.
                (
                    Some(codes::OTHER_CHANGED),
                    Some(format!(
                        "the component is named for the first time: RTCBuilder's placeholder id `{}` → `{}`",
                        oi.id, ni.id
                    )),
                )
            } else if oi.key != ni.key {
                // Versions paired by their file (a component's history), whose vendor,
                // category or name changed: the old id names nothing any more, which is what
                // `rtcdoc diff` reports as the component removed (and one added).
                (
                    Some(codes::COMPONENT_REMOVED),
                    Some(format!(
                        "the id now names another component: `{}` → `{}` (vendor, category or name changed); systems and catalogues that refer to `{}` no longer find it",
                        oi.id, ni.id, oi.id
                    )),
                )
            } else {
                (
                    Some(codes::OTHER_CHANGED),
                    spelled("names the same component"),
                )
            }
        }
        Place::Field(Field::BasicVersion) => (
            Some(codes::VERSION_CHANGED),
            Some(format!("version {o} → {n}")),
        ),
        Place::Field(Field::BasicExecutionType) => (Some(codes::EXECUTION_TYPE), None),
        Place::Field(Field::BasicExecutionRate) => {
            let num = |s: Option<&str>| s.and_then(|s| s.trim().parse::<f64>().ok());
            let same = matches!((num(old), num(new)), (Some(a), Some(b)) if a == b);
            let message = format!("execution rate {o} → {n}");
            same_or(same, "is the same rate", codes::EXECUTION_RATE, message)
        }
        Place::Field(Field::BasicMaxInstances) => {
            // Absent or empty: unlimited.
            let count = |s: Option<&str>| -> Option<Option<u64>> {
                match s.map(str::trim).filter(|s| !s.is_empty()) {
                    None => Some(None),
                    Some(t) => t.parse::<u64>().ok().map(Some),
                }
            };
            match (count(old), count(new)) {
                (Some(a), Some(b)) => {
                    let lowered = match (a, b) {
                        (None, Some(_)) => true,
                        (Some(x), Some(y)) => y < x,
                        _ => false,
                    };
                    if lowered {
                        (
                            Some(codes::MAX_INSTANCES_LOWERED),
                            Some(format!(
                                "at most {} instance(s) now (was {})",
                                b.map_or("unlimited".into(), |v| v.to_string()),
                                a.map_or("unlimited".into(), |v| v.to_string())
                            )),
                        )
                    } else {
                        (Some(codes::OTHER_CHANGED), None)
                    }
                }
                _ => (
                    Some(codes::MAX_INSTANCES_LOWERED),
                    Some(format!(
                        "maxInstances {o} → {n} cannot be compared as numbers"
                    )),
                ),
            }
        }
        Place::Field(Field::ActionImplemented) => {
            let b = |s: Option<&str>| crate::model::parse_bool(s).unwrap_or(false);
            if !b(old) && !b(new) {
                // Absent and `false` say the same: not implemented.
                (None, None)
            } else if b(old) && !b(new) {
                (
                    Some(codes::ACTION_NOT_IMPLEMENTED),
                    Some(format!("action `{}` is no longer implemented", p[1])),
                )
            } else {
                (Some(codes::OTHER_CHANGED), None)
            }
        }
        Place::Field(Field::DataPortPortType) => {
            let message = format!("data port `{}` changed from {o} to {n}", p[1]);
            let same = same_kind(old, new, crate::model::PortDirection::parse);
            same_or(
                same,
                "means the same port kind",
                codes::DATA_PORT_DIRECTION,
                message,
            )
        }
        Place::Field(Field::DataPortType) => {
            let message = format!("data port `{}` now carries {n} instead of {o}", p[1]);
            let same = same_type(old, new);
            same_or(same, "names the same type", codes::DATA_PORT_TYPE, message)
        }
        Place::Field(
            Field::DataPortInterfaceType
            | Field::DataPortDataflowType
            | Field::DataPortSubscriptionType,
        ) => {
            let set = |s: Option<&str>| -> std::collections::BTreeSet<String> {
                s.unwrap_or("")
                    .split(',')
                    .map(|x| x.trim().to_lowercase())
                    .filter(|x| !x.is_empty())
                    .collect()
            };
            let (a, b) = (set(old), set(new));
            // Empty: unrestricted.
            let narrowed = !b.is_empty() && (a.is_empty() || !a.is_subset(&b));
            if narrowed {
                let dropped: Vec<&String> = a.difference(&b).collect();
                let what = if a.is_empty() {
                    format!("now restricted to {n}")
                } else {
                    format!(
                        "no longer offers {}",
                        dropped
                            .iter()
                            .map(|d| format!("`{d}`"))
                            .collect::<Vec<_>>()
                            .join(", ")
                    )
                };
                (
                    Some(codes::TRANSPORT_NARROWED),
                    Some(format!("{last} of data port `{}` {what}", p[1])),
                )
            } else {
                (Some(codes::OTHER_CHANGED), None)
            }
        }
        Place::Field(Field::DataPortUnit | Field::ConfigurationUnit) => (
            Some(codes::UNIT_CHANGED),
            Some(format!("unit of `{}` changed from {o} to {n}", p[1])),
        ),
        Place::Field(Field::InterfaceType) => {
            let message = format!(
                "interface `{}` of service port `{}` is now {n} instead of {o}",
                p[3], p[1]
            );
            let same = same_type(old, new);
            same_or(
                same,
                "names the same interface",
                codes::INTERFACE_TYPE,
                message,
            )
        }
        Place::Field(Field::InterfaceDirection) => {
            let message = format!(
                "interface `{}` of service port `{}` changed from {o} to {n}",
                p[3], p[1]
            );
            let same = same_kind(old, new, crate::model::Direction::parse);
            same_or(
                same,
                "means the same direction",
                codes::INTERFACE_DIRECTION,
                message,
            )
        }
        Place::Field(Field::ConfigurationType) => {
            use crate::value::ValueType;
            let ty = |s: Option<&str>| ValueType::parse(s.unwrap_or(""));
            let same = match (ty(old), ty(new)) {
                (ValueType::Unknown, ValueType::Unknown) => {
                    old.map(str::trim) == new.map(str::trim)
                }
                (a, b) => a == b,
            };
            let message = format!(
                "configuration parameter `{}` is now {n} instead of {o}",
                p[1]
            );
            same_or(
                same,
                "means the same value type",
                codes::CONFIGURATION_TYPE,
                message,
            )
        }
        Place::Field(Field::ConfigurationDefaultValue) => (
            Some(codes::DEFAULT_CHANGED),
            Some(format!("default of `{}` changed from {o} to {n}", p[1])),
        ),
        Place::Child {
            parent: Kind::Configuration,
            node: Kind::Constraint,
        } => constraint_change(ctx, &p[1]),
        _ if documentation => (Some(codes::DOCUMENTATION_CHANGED), None),
        _ => (Some(codes::OTHER_CHANGED), None),
    };
    // A long text (a description) changed: its words that changed, not both texts in full.
    let message = message.unwrap_or_else(|| {
        crate::word_diff::message(old, new).unwrap_or_else(|| format!("changed from {o} to {n}"))
    });
    (code, message)
}

/// Both spellings read as the same known kind.
fn same_kind<K: PartialEq>(
    old: Option<&str>,
    new: Option<&str>,
    kind: impl Fn(&str) -> Option<K>,
) -> bool {
    let kind = |s: Option<&str>| s.and_then(&kind);
    kind(old).is_some() && kind(old) == kind(new)
}

/// Both name the same type (any spelling of it), or neither names one.
fn same_type(old: Option<&str>, new: Option<&str>) -> bool {
    let c = |s: Option<&str>| {
        s.map(str::trim)
            .filter(|s| !s.is_empty())
            .map(canonical_type)
    };
    c(old) == c(new)
}

fn constraint_change(ctx: &Ctx, label: &str) -> (Option<&'static str>, Option<String>) {
    use constraint::Relation;
    fn find<'p>(p: &'p Profile, label: &str) -> Option<&'p crate::model::Configuration> {
        by_label(p.configurations(), |c| c.name.as_deref(), label)
    }
    let (Some(oc), Some(nc)) = (find(ctx.old, label), find(ctx.new, label)) else {
        return (Some(codes::OTHER_CHANGED), None);
    };
    let real = |c: &crate::model::Configuration| {
        c.constraint.clone().filter(|k| k.placeholder().is_none())
    };
    let (ok, nk) = (real(oc), real(nc));
    let rel = constraint::relation(ok.as_ref(), nk.as_ref());
    let describe = |k: &Option<crate::model::Constraint>| match k {
        Some(k) => format!("`{}`", crate::constraint::describe(k)),
        None => "none".to_string(),
    };
    let head = format!(
        "constraint of `{label}` changed from {} to {}",
        describe(&ok),
        describe(&nk)
    );
    let default_note = || -> String {
        let Some(k) = &nk else { return String::new() };
        let Some(d) = oc.default_value.as_deref() else {
            return "; the old default is empty".into();
        };
        let ty = crate::value::ValueType::parse(nc.type_.as_deref().unwrap_or(""));
        match crate::constraint::evaluate(k, d, ty) {
            crate::constraint::Verdict::Satisfied => {
                format!("; the old default `{d}` still satisfies it")
            }
            crate::constraint::Verdict::Violated(why) => {
                format!("; the old default `{d}` no longer satisfies it ({why})")
            }
            crate::constraint::Verdict::Unevaluable(why) => {
                format!("; whether the old default `{d}` satisfies it cannot be decided ({why})")
            }
        }
    };
    match rel {
        Relation::Same => (
            Some(codes::OTHER_CHANGED),
            Some(format!(
                "{head}: written differently, accepts the same values"
            )),
        ),
        Relation::Narrower => (
            Some(codes::CONSTRAINT_NARROWED),
            Some(format!("{head}: it accepts fewer values{}", default_note())),
        ),
        Relation::Wider => (
            Some(codes::CONSTRAINT_WIDENED),
            Some(format!("{head}: it accepts more values")),
        ),
        Relation::Other => (
            Some(codes::CONSTRAINT_CHANGED),
            Some(format!(
                "{head}: it may refuse values it accepted{}",
                default_note()
            )),
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::fields::Fields;
    use crate::model::{Configuration, ConfigurationSet, DataPort, ServiceInterface, ServicePort};

    fn profile() -> Profile {
        Profile {
            id: Some("RTC:v:c:n:1.0".into()),
            data_ports: vec![DataPort {
                name: Some("out".into()),
                port_type: Some("DataOutPort".into()),
                ..Default::default()
            }],
            configuration_set: Some(ConfigurationSet {
                configurations: vec![Configuration {
                    name: Some("gain".into()),
                    ..Default::default()
                }],
                ..Default::default()
            }),
            service_ports: vec![ServicePort {
                name: Some("svc".into()),
                interfaces: vec![ServiceInterface {
                    name: Some("if".into()),
                    ..Default::default()
                }],
                ..Default::default()
            }],
            ..Default::default()
        }
    }

    /// Sets `f` on the first node of its kind in `p` (by the table's slot, not by a name).
    fn set(p: &mut Profile, f: Field, v: &str) {
        let slot = match f.node() {
            Kind::Profile => p.slot(f),
            Kind::BasicInfo => p.basic_info.slot(f),
            Kind::DataPort => p.data_ports[0].slot(f),
            Kind::ServicePort => p.service_ports[0].slot(f),
            Kind::ServiceInterface => p.service_ports[0].interfaces[0].slot(f),
            Kind::Configuration => p
                .configuration_set
                .as_mut()
                .and_then(|cs| cs.configurations.first_mut())
                .and_then(|c| c.slot(f)),
            other => panic!("{other:?} not in the test profile"),
        };
        *slot.expect("a field of the node") = Some(v.into());
    }

    /// The places and codes of the changes from `old` to `new`.
    fn classified(old: &Profile, new: &Profile) -> Vec<(Place, &'static str)> {
        let (ot, nt) = (tree(old), tree(new));
        let mut found = Vec::new();
        walk(&mut Vec::new(), &ot, &nt, None, &mut found);
        let ctx = Ctx {
            component: "n",
            old,
            new,
            file: "new.xml",
            old_file: "old.xml",
        };
        let ident = |v: &str| Ident {
            key: Key("v".into(), "c".into(), "n".into()),
            version: v.into(),
            id: format!("RTC:v:c:n:{v}"),
            language: String::new(),
        };
        let (oi, ni) = (ident("1.0"), ident("1.0"));
        let mut out = Vec::new();
        let mut places = Vec::new();
        for f in &found {
            let before = out.len();
            classify(&ctx, f, false, &oi, &ni, &mut out);
            places.extend(out[before..].iter().map(|c| (place(&f.path).0, c.code)));
        }
        places
    }

    /// The codes `compare_profiles` gives from `old` to `new` (compared as one file's versions).
    fn history_codes(old: &Profile, new: &Profile) -> Vec<(&'static str, String)> {
        compare_profiles((old, "a.xml"), (new, "a.xml"), &Default::default())
            .into_iter()
            .map(|c| (c.code, c.path))
            .collect()
    }

    /// An action not implemented and one not listed, and `implemented` absent and `false`, say
    /// the same; implemented or no longer implemented is a change.
    #[test]
    fn an_action_not_implemented_is_an_action_not_listed() {
        use crate::model::{Action, ActionKind};
        let action = |kind: ActionKind, implemented: Option<&str>| Action {
            kind,
            implemented: implemented.map(Into::into),
            doc: None,
            pos: Default::default(),
            extra: Default::default(),
        };
        let none = profile();
        let mut listed = profile();
        listed.actions = vec![
            action(ActionKind::OnFinalize, Some("false")),
            action(ActionKind::OnStartup, None),
        ];
        assert_eq!(history_codes(&none, &listed), []);
        assert_eq!(history_codes(&listed, &none), []);
        let mut unsaid = profile();
        unsaid.actions = vec![
            action(ActionKind::OnFinalize, None),
            action(ActionKind::OnStartup, Some("false")),
        ];
        assert_eq!(history_codes(&listed, &unsaid), []);
        let mut implemented = profile();
        implemented.actions = vec![action(ActionKind::OnFinalize, Some("true"))];
        assert_eq!(
            history_codes(&listed, &implemented),
            [(
                codes::OTHER_CHANGED,
                "actions/onFinalize/implemented".to_string()
            )]
        );
        assert_eq!(
            history_codes(&implemented, &listed),
            [(
                codes::ACTION_NOT_IMPLEMENTED,
                "actions/onFinalize/implemented".to_string()
            )]
        );
    }

    /// RTCBuilder's placeholder id named: information; a vendor of its own changed: breaking.
    #[test]
    fn a_placeholder_id_named_is_no_breaking_change() {
        let with_id = |id: &str| Profile {
            id: Some(id.into()),
            ..profile()
        };
        let first = with_id("RTC:VenderName:Category:ModuleName:1.0.0");
        let named = with_id("RTC:Lab:Mobile:Base:1.0.0");
        let got = compare_profiles((&first, "a.xml"), (&named, "a.xml"), &Default::default());
        assert_eq!(got.len(), 1, "{got:?}");
        assert_eq!(
            (got[0].code, got[0].severity),
            (codes::OTHER_CHANGED, Level::Info)
        );
        assert!(
            got[0].message.contains("named for the first time"),
            "{got:?}"
        );
        // Only the name was a placeholder; the vendor was the lab's own.
        let half = with_id("RTC:Lab:Category:ModuleName:1.0.0");
        let other = with_id("RTC:Other:Mobile:Base:1.0.0");
        let codes: Vec<&str> = history_codes(&half, &other).iter().map(|c| c.0).collect();
        assert!(codes.contains(&codes::COMPONENT_REMOVED), "{codes:?}");
    }

    /// Every field of the nodes `diff` classifies is found at its typed place when only it
    /// changes: the path the JSON tree gives resolves through the table to the same field.
    #[test]
    fn every_field_change_is_found_at_its_field() {
        let nodes = [
            Kind::Profile,
            Kind::BasicInfo,
            Kind::DataPort,
            Kind::ServicePort,
            Kind::ServiceInterface,
            Kind::Configuration,
        ];
        for node in nodes {
            for d in node.fields() {
                // The names match the items: a renamed item is a removal and an addition.
                if d.json == "name" || d.field == Field::ProfileId {
                    continue;
                }
                let (mut old, mut new) = (profile(), profile());
                set(&mut old, d.field, "1");
                set(&mut new, d.field, "2");
                let got = classified(&old, &new);
                // Save stamps date the file: no change of the component.
                if matches!(d.field, Field::BasicCreationDate | Field::BasicUpdateDate) {
                    assert_eq!(got, [], "{:?}", d.field);
                    continue;
                }
                assert_eq!(got.len(), 1, "{:?}: {got:?}", d.field);
                assert_eq!(got[0].0, Place::Field(d.field), "{:?}", d.field);
                if d.doc {
                    assert_eq!(got[0].1, codes::DOCUMENTATION_CHANGED, "{:?}", d.field);
                }
            }
        }
    }

    #[test]
    fn a_unit_change_is_unit_changed() {
        for f in [Field::DataPortUnit, Field::ConfigurationUnit] {
            let (mut old, mut new) = (profile(), profile());
            set(&mut old, f, "m");
            set(&mut new, f, "mm");
            assert_eq!(
                classified(&old, &new),
                [(Place::Field(f), codes::UNIT_CHANGED)],
                "{f:?}"
            );
        }
        // A unit of the documentation is not the port's unit.
        let (old, mut new) = (profile(), profile());
        new.data_ports[0].doc = Some(crate::model::DataPortDoc {
            unit: Some("mm".into()),
            ..Default::default()
        });
        assert_eq!(
            classified(&old, &new),
            [(
                Place::Field(Field::DataPortDocUnit),
                codes::DOCUMENTATION_CHANGED
            )]
        );
    }

    #[test]
    fn paths_resolve_to_places() {
        let p = |s: &str| s.split('/').map(String::from).collect::<Vec<_>>();
        assert_eq!(
            place(&p("dataPorts/out")),
            (Place::Item(Kind::DataPort), false)
        );
        assert_eq!(
            place(&p("servicePorts/svc/interfaces/if/type")),
            (Place::Field(Field::InterfaceType), false)
        );
        assert_eq!(
            place(&p("configurations/gain/constraint")),
            (
                Place::Child {
                    parent: Kind::Configuration,
                    node: Kind::Constraint
                },
                false
            )
        );
        assert_eq!(
            place(&p("basicInfo/versionUpLogs")),
            (
                Place::Child {
                    parent: Kind::BasicInfo,
                    node: Kind::TextList
                },
                true
            )
        );
        assert_eq!(
            place(&p("dataPorts/out/events/e/doc/description")),
            (Place::Field(Field::DataPortDocDescription), true)
        );
        assert_eq!(place(&p("dataPorts/out/extra")), (Place::Other, false));
        assert_eq!(place(&p("writtenAs")), (Place::Other, false));
    }
}
