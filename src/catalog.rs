//! The catalogue: every document read (component profiles, IDL files) as entries keyed by
//! stable ids, the cross-references between them, and the one list of pages made from them.
//!
//! - **Entries and ids.** A component is keyed by its id (`RTC:vendor:category:name:version`,
//!   [`Component::id`]), a data type or interface by its canonical scoped name
//!   (`RTC::TimedLong`), a facet by its name. References are ids, never positions: a data port
//!   is [`PortRef`] = component id + port name, a service interface [`InterfaceRef`] = component
//!   id + service port name + interface name ([`member_key`] tells repeated names apart). Maps
//!   built once resolve them ([`Catalog::component`], [`Catalog::resolve_port`],
//!   [`Catalog::data_type`]). Ids make two catalogues comparable entry by entry (`rtcdoc diff`)
//!   and `catalog.json` readable back ([`Catalog::with_lookups`] and [`Catalog::bound`], `render::json::read_catalog`).
//! - **Indexes**, built in O(n) over the ports of all profiles: who produces and who consumes
//!   each data type, who provides and who requires each service interface, which IDL types hold
//!   which ([`Catalog::attach_idl`]), category and vendor facets, slugs and row anchors.
//! - **Pages.** [`Catalog::pages`] is the one list of pages (kind, id, path stem, title),
//!   computed once; every renderer, the sitemap, the search index and `serve`'s incremental
//!   rebuild take page paths from it ([`Page::path_in`] gives each output's file name,
//!   [`Output::carries`] which kinds an output writes). Links between pages come from
//!   [`Catalog::href`] ([`pages`]).
//!
//! Renderers only read the catalogue; all cross-linking logic lives here. A new kind of
//! document is a reader (in `parse`), an entry kind with its id here, a [`PageKind`], and views.

pub mod backups;
pub mod dataflow;
pub mod history;
pub mod implementations;
pub mod neighbourhood;
pub mod pages;
pub mod reach;
pub mod readmes;
pub mod sources;
pub mod stability;
pub mod systems;

use crate::diagnostic::{codes, Diagnostic, Severity};
use crate::model::{DataPort, Direction, PortDirection, Profile, ServiceInterface};
use crate::parse::SourceFormat;
pub use crate::slug::{fnv1a, slugify};
use crate::types::canonical_type;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::collections::{BTreeMap, HashMap, HashSet};

/// One loaded profile and where it came from.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct Component {
    /// The stable id of the entry: the component id in its documented form
    /// (`RTC:vendor:category:name:version`, also for a profile that wrote the dotted form),
    /// else BasicInfo's parts in that form; `@source` is appended when several profiles of the
    /// catalogue share it. Other entries refer to a component by this id; in `catalog.json` it
    /// is the component's key.
    #[serde(skip)]
    pub id: ComponentId,
    /// Path of the profile relative to the input directory, forward slashes; for a profile of a
    /// `[[source]]` repository `<name>/<path in the repository>`.
    pub source: String,
    /// The `[[source]]` repository the profile was read from (none: the input directory).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub origin: Option<crate::model::Origin>,
    pub format: SourceFormat,
    /// File-name-safe, stable identifier of the component's pages.
    pub slug: String,
    /// Anchors of the rows of the component page (ports, interfaces, parameters).
    pub anchors: Anchors,
    /// What tells this component apart from others of the same name (the C++ and Python
    /// variants of one component, a copy in another folder): its language, else its folder.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub qualifier: Option<String>,
    /// The hand-written README of the profile's folder ([`crate::readme`]), when it has one.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub readme: Option<crate::readme::Readme>,
    /// What the component's code registers and where it differs from the profile
    /// ([`crate::implementation`]); `None`: no source file found, or the check is off.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub implementation: Option<Box<crate::implementation::Implementation>>,
    /// Set when the component has no profile: it is documented from its code
    /// ([`crate::implementation::recover`]), and this names what the code does not say.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub recovered: Option<Box<crate::implementation::recover::Recovered>>,
    /// RTCBuilder's backups of this profile (`RTC.xml<timestamp>` beside it), oldest first:
    /// older versions of it, not components ([`backups`]).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub backups: Vec<backups::Backup>,
    /// Its past versions, newest first, each with its classified changes ([`history`]);
    /// empty when the history is off or nothing records one.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub history: Vec<history::Entry>,
    /// When each port, service interface and configuration parameter younger than the oldest
    /// version of the history was added ([`history::since`]): keyed by the path its `rtcdoc
    /// diff` change names (`dataPorts/status`), the version (else the date) that added it.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub since: BTreeMap<String, String>,
    /// Its stability mark: `rtcdoc.toml`'s `[stability]` entry, else its profile's
    /// `rtcdoc.stability` properties ([`stability`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stability: Option<crate::model::stability::Stability>,
    #[serde(flatten)]
    pub profile: Box<Profile>,
}

impl Component {
    /// The name, with the qualifier when others share it: `RobotController (Python)`.
    pub fn display_name(&self) -> std::borrow::Cow<'_, str> {
        match &self.qualifier {
            Some(q) => format!("{} ({q})", self.profile.name()).into(),
            None => self.profile.name().into(),
        }
    }
}

/// A slug for a qualifier (`C++` → `cpp`, `C#` → `csharp`).
pub(crate) fn qualifier_slug(q: &str) -> String {
    slugify(&q.replace("++", "pp").replace('#', "sharp"))
}

/// What tells the files `sources` apart by place: the folders of
/// their paths that they do not all share (common leading and trailing folders dropped), as
/// few leading ones of those as make them distinct; the file name when they share a folder.
pub(crate) fn folder_qualifiers(sources: &[&str]) -> Vec<String> {
    let dirs: Vec<Vec<&str>> = sources
        .iter()
        .map(|s| {
            let mut d: Vec<&str> = s.split('/').collect();
            d.pop();
            d
        })
        .collect();
    let shortest = dirs.iter().map(Vec::len).min().unwrap_or(0);
    let prefix = (0..shortest)
        .take_while(|&k| dirs.iter().all(|d| d[k] == dirs[0][k]))
        .count();
    let suffix = (0..shortest - prefix)
        .take_while(|&k| {
            let last = |d: &Vec<&str>| d[d.len() - 1 - k].to_string();
            dirs.iter().all(|d| last(d) == last(&dirs[0]))
        })
        .count();
    let middle: Vec<&[&str]> = dirs.iter().map(|d| &d[prefix..d.len() - suffix]).collect();
    let longest = middle.iter().map(|m| m.len()).max().unwrap_or(0);
    let take = |k: usize| -> Vec<String> {
        middle
            .iter()
            .map(|m| m[..k.min(m.len())].join("/"))
            .collect()
    };
    for k in 1..=longest {
        let q = take(k);
        let mut sorted = q.clone();
        sorted.sort();
        sorted.dedup();
        if sorted.len() == q.len() && q.iter().all(|s| !s.is_empty()) {
            return q;
        }
    }
    sources
        .iter()
        .map(|s| s.rsplit('/').next().unwrap_or("").to_string())
        .collect()
}

/// Component slugs and qualifiers. A name used once keeps its plain slug; components sharing
/// a name are told apart by their language when it is theirs alone among them
/// (`robotcontroller-python`), else by language and the folders that differ
/// (`robotcontroller-python-openrtm-rtm-tutorial-ev3`; the language is left out only when
/// none of the group is told apart by it), else by the file name; a number only when all of
/// that still collides.
fn component_slugs(loaded: &[LoadedProfile]) -> Vec<(String, Option<String>)> {
    let base: Vec<String> = loaded
        .par_iter()
        .map(|l| slugify(l.profile.name()))
        .collect();
    let mut groups: BTreeMap<&str, Vec<usize>> = BTreeMap::new();
    for (i, b) in base.iter().enumerate() {
        groups.entry(b.as_str()).or_default().push(i);
    }
    let lang = |i: usize| loaded[i].profile.language_kind().map(str::to_string);
    let mut qualifier: Vec<Option<String>> = vec![None; loaded.len()];
    for idx in groups.values().filter(|g| g.len() > 1) {
        let count = |l: &Option<String>| idx.iter().filter(|&&j| &lang(j) == l).count();
        let mut rest = Vec::new();
        for &i in idx {
            let l = lang(i);
            match l {
                Some(l) if count(&Some(l.clone())) == 1 => qualifier[i] = Some(l),
                _ => rest.push(i),
            }
        }
        if rest.len() < 2 {
            // One left without a language of its own: the others are told apart already.
            continue;
        }
        // Some named by their language alone: the others say theirs too, so that one group
        // reads one way (`C++, projects` beside `Python`, not `projects`).
        let by_language = rest.len() < idx.len();
        let mut langs: Vec<Option<String>> = rest.iter().map(|&i| lang(i)).collect();
        langs.sort();
        langs.dedup();
        for l in &langs {
            let part: Vec<usize> = rest.iter().copied().filter(|&i| &lang(i) == l).collect();
            let sources = |members: &[usize]| -> Vec<&str> {
                members.iter().map(|&i| loaded[i].source.as_str()).collect()
            };
            let places = if part.len() > 1 {
                folder_qualifiers(&sources(&part))
            } else {
                // Alone in its language (none): told apart from the rest by place.
                let all = folder_qualifiers(&sources(&rest));
                let at = rest.iter().position(|&i| i == part[0]).unwrap_or(0);
                vec![all[at].clone()]
            };
            for (&i, place) in part.iter().zip(places) {
                qualifier[i] = Some(match l {
                    Some(l) if langs.len() > 1 || by_language => format!("{l}, {place}"),
                    _ => place,
                });
            }
        }
    }
    let bases: Vec<String> = base
        .into_iter()
        .zip(&qualifier)
        .zip(loaded)
        .map(|((b, q), l)| {
            let mut s = match q {
                Some(q) => format!("{b}-{}", qualifier_slug(q)),
                // `index` is reserved for the index page of each page folder.
                None if b == "index" => {
                    format!("{b}-{:06x}", fnv1a(l.source.as_bytes()) as u32 & 0xff_ffff)
                }
                None => b,
            };
            if s.len() > 96 {
                let hash = fnv1a(l.source.as_bytes()) as u32 & 0xff_ffff;
                s = format!("{}-{hash:06x}", s[..64].trim_end_matches('-'));
            }
            s
        })
        .collect();
    let slugs = claim_slugs(&bases, |i| qualifier[i].is_none());
    slugs.into_iter().zip(qualifier).collect()
}

/// Unique slugs for `bases`: those `first` marks are claimed before the others (a name used once
/// keeps its plain slug, whatever sorts before it), each in order; a slug already taken gets the
/// lowest free `-N` (N ≥ 2), never one that another page has as its own.
pub(crate) fn claim_slugs(bases: &[String], first: impl Fn(usize) -> bool) -> Vec<String> {
    let mut taken: std::collections::HashSet<String> = std::collections::HashSet::new();
    let mut out = vec![String::new(); bases.len()];
    for pass in [true, false] {
        for (i, b) in bases.iter().enumerate().filter(|&(i, _)| first(i) == pass) {
            out[i] = claim(&mut taken, b.clone());
        }
    }
    out
}

/// Stable fragment ids for the rows of a component page, unique within the page.
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct Anchors {
    /// One per data port, in profile order.
    pub data_ports: Vec<String>,
    /// One per service port, in profile order.
    pub service_ports: Vec<String>,
    /// One per service interface, per service port.
    pub interfaces: Vec<Vec<String>>,
    /// One per configuration parameter.
    pub configurations: Vec<String>,
}

/// The id of a component entry ([`Component::id`]): its own type, so that it is never confused
/// with a name or a path; shared (one allocation) by every reference to the entry. A string at
/// the boundary (`catalog.json`, URLs, messages); inside the build a reference also carries the
/// entry's dense handle ([`RefHandle`]).
#[derive(Debug, Clone, Default, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[serde(transparent)]
pub struct ComponentId(std::sync::Arc<str>);

impl ComponentId {
    pub fn as_str(&self) -> &str {
        &self.0
    }

    /// The same entry's id: the very allocation, not only the same text (a [`RefHandle`] is
    /// trusted only then).
    pub fn same_entry(a: &ComponentId, b: &ComponentId) -> bool {
        std::sync::Arc::ptr_eq(&a.0, &b.0)
    }
}

impl std::ops::Deref for ComponentId {
    type Target = str;
    fn deref(&self) -> &str {
        &self.0
    }
}

impl std::borrow::Borrow<str> for ComponentId {
    fn borrow(&self) -> &str {
        &self.0
    }
}

impl AsRef<str> for ComponentId {
    fn as_ref(&self) -> &str {
        &self.0
    }
}

impl std::fmt::Display for ComponentId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl From<String> for ComponentId {
    fn from(s: String) -> ComponentId {
        ComponentId(s.into())
    }
}

impl From<&str> for ComponentId {
    fn from(s: &str) -> ComponentId {
        ComponentId(s.into())
    }
}

impl PartialEq<str> for ComponentId {
    fn eq(&self, other: &str) -> bool {
        &*self.0 == other
    }
}

/// The key of a port, service port or interface within its component: its name, and for a
/// second (third, …) member of the same name `name#2` (`#3`, …): a profile may repeat a name
/// (RTC302 and its siblings warn about it), and each member keeps an id of its own.
pub fn member_key<'a>(names: impl Iterator<Item = &'a str>, at: usize) -> Text {
    let upto: Vec<&str> = names.take(at + 1).collect();
    let Some((mine, before)) = upto.split_last() else {
        return Text::default();
    };
    match before.iter().filter(|n| *n == mine).count() {
        0 => Text::from(*mine),
        n => Text::from(format!("{mine}#{}", n + 1)),
    }
}

/// The position of the member with key `key` (see [`member_key`]) among `names`.
pub fn member_at<'a>(names: impl Iterator<Item = &'a str> + Clone, key: &str) -> Option<usize> {
    if let Some(i) = names.clone().position(|n| n == key) {
        return Some(i);
    }
    let (name, nth) = key.rsplit_once('#')?;
    let nth: usize = nth.parse().ok().filter(|&n| n >= 2)?;
    names
        .enumerate()
        .filter(|(_, n)| *n == name)
        .nth(nth - 1)
        .map(|(i, _)| i)
}

use crate::model::Text;

/// A dense handle of an entry of kind `T` inside the build: its position in the catalogue's
/// vector of `T`s ([`Catalog::components`], [`Catalog::data_types`], [`Catalog::interfaces`],
/// [`Catalog::systems`]). Handles of different kinds are different types, so a data type's
/// position is never taken for a component's; the catalogue is indexed by them (`cat[ci]`).
/// Strings ([`ComponentId`], a type's name, a system's file) are for the boundary only.
pub struct Ix<T>(u32, std::marker::PhantomData<fn() -> T>);

/// A component's handle.
pub type ComponentIx = Ix<Component>;
/// A data type's handle.
pub type DataTypeIx = Ix<DataType>;
/// A service interface type's handle.
pub type InterfaceIx = Ix<InterfaceType>;
/// An RT System's handle.
pub type SystemIx = Ix<systems::System>;

/// The handle of a type entry of either kind: a data type or a service interface type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TypeIx {
    Data(DataTypeIx),
    Interface(InterfaceIx),
}

impl<T> Ix<T> {
    /// No entry (a reference not resolved by the catalogue it is used with).
    pub const NONE: Ix<T> = Ix(u32::MAX, std::marker::PhantomData);

    /// The handle of position `i` ([`Ix::NONE`] past `u32::MAX`).
    pub fn new(i: usize) -> Ix<T> {
        u32::try_from(i).map_or(Ix::NONE, |i| Ix(i, std::marker::PhantomData))
    }

    /// The position in the catalogue's vector (`usize::MAX` for [`Ix::NONE`]).
    pub fn get(self) -> usize {
        if self == Ix::NONE {
            usize::MAX
        } else {
            self.0 as usize
        }
    }

    /// The handles of a vector of `len` entries, in order.
    pub fn all(len: usize) -> impl DoubleEndedIterator<Item = Ix<T>> + ExactSizeIterator + Clone {
        (0..len).map(Ix::new)
    }

    /// Each of `entries` with its handle, in order.
    pub fn enumerate(entries: &[T]) -> impl DoubleEndedIterator<Item = (Ix<T>, &T)> + Clone {
        Ix::all(entries.len()).zip(entries)
    }
}

impl<T> Clone for Ix<T> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<T> Copy for Ix<T> {}

impl<T> PartialEq for Ix<T> {
    fn eq(&self, other: &Self) -> bool {
        self.0 == other.0
    }
}

impl<T> Eq for Ix<T> {}

impl<T> PartialOrd for Ix<T> {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl<T> Ord for Ix<T> {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        self.0.cmp(&other.0)
    }
}

impl<T> std::hash::Hash for Ix<T> {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        self.0.hash(state);
    }
}

impl<T> std::fmt::Debug for Ix<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Ix({})", self.0)
    }
}

/// A handle is written as its position (a template context may carry one).
impl<T> Serialize for Ix<T> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.0.serialize(s)
    }
}

impl<T> Default for Ix<T> {
    fn default() -> Ix<T> {
        Ix::NONE
    }
}

/// A value for each entry of kind `K` (one per component, say), looked up by the entry's
/// handle: `of[ci]`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PerEntry<K, V>(Vec<V>, std::marker::PhantomData<fn() -> K>);

impl<K, V> PerEntry<K, V> {
    /// The table of `values`, the value of entry `i` at position `i`.
    pub fn new(values: Vec<V>) -> PerEntry<K, V> {
        PerEntry(values, std::marker::PhantomData)
    }
}

impl<K, V> std::ops::Index<Ix<K>> for PerEntry<K, V> {
    type Output = V;
    fn index(&self, ix: Ix<K>) -> &V {
        &self.0[ix.get()]
    }
}

impl<K, V> std::ops::IndexMut<Ix<K>> for PerEntry<K, V> {
    fn index_mut(&mut self, ix: Ix<K>) -> &mut V {
        &mut self.0[ix.get()]
    }
}

/// The handle of each of `entries` by its key.
fn handle_map<T, K: Eq + std::hash::Hash>(
    entries: &[T],
    key: impl Fn(&T) -> K,
) -> HashMap<K, Ix<T>> {
    let handles = Ix::all(entries.len());
    entries
        .iter()
        .zip(handles)
        .map(|(e, i)| (key(e), i))
        .collect()
}

/// The catalogue is indexed by handles: `cat[ci]` is the component of handle `ci`.
macro_rules! index_by_handle {
    ($($t:ty => $field:ident),*) => {$(
        impl std::ops::Index<Ix<$t>> for Catalog {
            type Output = $t;
            fn index(&self, ix: Ix<$t>) -> &$t {
                &self.$field[ix.get()]
            }
        }
    )*};
}

index_by_handle!(
    Component => components,
    DataType => data_types,
    InterfaceType => interfaces,
    systems::System => systems
);

impl RefHandle {
    fn new(component: ComponentIx, port: usize, interface: usize) -> RefHandle {
        RefHandle {
            component,
            port: u32::try_from(port).unwrap_or(u32::MAX),
            interface: u32::try_from(interface).unwrap_or(u32::MAX),
        }
    }
}

/// Where a [`PortRef`] or [`InterfaceRef`] points in the catalogue that resolved it: the
/// component's handle and the port's (and interface's) position in it, so that rendering
/// never looks a component up by its id string. Not part of `catalog.json` (ids are strings at
/// the boundary) nor of a reference's equality; a handle is trusted only by the catalogue whose
/// component entry holds the very id the reference holds ([`ComponentId::same_entry`]), and any
/// other reference is resolved by id.
#[derive(Debug, Clone, Copy, Default)]
pub struct RefHandle {
    pub component: ComponentIx,
    port: u32,
    interface: u32,
}

/// A reference to a data port of a component: the component's id and the port's key.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct PortRef {
    /// [`Component::id`].
    pub component: ComponentId,
    /// The data port's name ([`member_key`]).
    pub port: Text,
    /// Where it points in the catalogue that made it ([`RefHandle`]).
    #[serde(skip)]
    pub at: RefHandle,
}

impl PartialEq for PortRef {
    fn eq(&self, other: &PortRef) -> bool {
        self.component == other.component && self.port == other.port
    }
}

impl Eq for PortRef {}

/// A reference to a service interface of a component.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct InterfaceRef {
    /// [`Component::id`].
    pub component: ComponentId,
    /// The service port's name ([`member_key`]).
    pub port: Text,
    /// The interface's name within that port ([`member_key`]).
    pub interface: Text,
    /// Where it points in the catalogue that made it ([`RefHandle`]).
    #[serde(skip)]
    pub at: RefHandle,
}

impl PartialEq for InterfaceRef {
    fn eq(&self, other: &InterfaceRef) -> bool {
        self.component == other.component
            && self.port == other.port
            && self.interface == other.interface
    }
}

impl Eq for InterfaceRef {}

/// A data type or a service interface type used somewhere in the catalogue: one entry shape
/// for both; `U` holds its uses by role ([`PortUses`] for a data type, [`InterfaceUses`] for an
/// interface).
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct TypeEntry<U> {
    /// Canonical name (`RTC::TimedLong`).
    pub name: String,
    pub slug: String,
    /// Every spelling met in the profiles (`TimedLong`, `IDL:RTC/TimedLong:1.0`, …), sorted.
    pub spellings: Vec<String>,
    /// Every non-empty `idlFile` given for this type, sorted.
    pub idl_files: Vec<String>,
    #[serde(flatten)]
    pub uses: U,
    /// Types whose fields (or typedef) hold this one, by canonical name, sorted: filled from
    /// the IDL for data types ([`Catalog::attach_idl`]).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub contained_in: Vec<String>,
    /// The operations and attributes of the catalogue's interfaces that use this type directly
    /// (as a parameter, a result, an attribute or an exception raised), interface by interface
    /// in name order, each in declaration order ([`Catalog::attach_idl`]).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub used_by: Vec<IdlUse>,
    /// Its stability mark, from `rtcdoc.toml`'s `[stability]` ([`stability`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stability: Option<crate::model::stability::Stability>,
}

/// A use of a type by an operation or attribute of an interface of the catalogue.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct IdlUse {
    /// The interface, by canonical name (an entry of [`Catalog::interfaces`]).
    pub interface: String,
    /// The operation or attribute, by name.
    pub member: String,
    /// How the member uses the type.
    pub role: IdlUseRole,
    /// The parameter's name, for [`IdlUseRole::Parameter`].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub parameter: Option<String>,
}

/// How an operation or attribute uses a type ([`IdlUse`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub enum IdlUseRole {
    /// A parameter of an operation (`in`, `out` or `inout`).
    Parameter,
    /// An operation's result.
    Result,
    /// An attribute's type.
    Attribute,
    /// An exception the operation or attribute raises.
    Raises,
}

/// A data type used by some data port in the catalogue.
pub type DataType = TypeEntry<PortUses>;

/// A service interface type used by some service port in the catalogue.
pub type InterfaceType = TypeEntry<InterfaceUses>;

/// Declares the uses of a type entry by role: a struct of three lists of references (the two
/// directions, then `others`; serialised in that order) and its [`Uses`] impl.
macro_rules! uses {
    (
        $(#[$doc:meta])* $name:ident of $r:ty {
            $(#[$doc_a:meta])* $a:ident: $role_a:ident,
            $(#[$doc_b:meta])* $b:ident: $role_b:ident,
            $(#[$doc_o:meta])* others,
        }
    ) => {
        $(#[$doc])*
        #[derive(Debug, Clone, Default, Serialize, Deserialize)]
        #[serde(rename_all = "camelCase")]
        pub struct $name {
            $(#[$doc_a])*
            pub $a: Vec<$r>,
            $(#[$doc_b])*
            pub $b: Vec<$r>,
            $(#[$doc_o])*
            pub others: Vec<$r>,
        }

        impl Uses for $name {
            type Ref = $r;
            fn by_role(&self) -> [(Role, &[$r]); 3] {
                [
                    (Role::$role_a, &self.$a),
                    (Role::$role_b, &self.$b),
                    (Role::Other, &self.others),
                ]
            }
            fn refs_mut(&mut self) -> [&mut Vec<$r>; 3] {
                [&mut self.$a, &mut self.$b, &mut self.others]
            }
            fn from_slots([$a, $b, others]: [Vec<$r>; 3]) -> Self {
                $name { $a, $b, others }
            }
        }
    };
}

uses! {
    /// The data ports carrying a data type, by direction.
    PortUses of PortRef {
        /// Out ports carrying the type.
        producers: Producer,
        /// In ports carrying the type.
        consumers: Consumer,
        /// Other ports carrying it (event ports, unknown port types).
        others,
    }
}

uses! {
    /// The interfaces of service ports of an interface type, by direction.
    InterfaceUses of InterfaceRef {
        /// Components providing the interface.
        providers: Provider,
        /// Components requiring (consuming) the interface.
        requirers: Requirer,
        /// Interfaces of this type with a direction other than Provided/Required.
        others,
    }
}

/// How a port or interface uses its type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Role {
    Producer,
    Consumer,
    Provider,
    Requirer,
    Other,
}

/// A reference held by a type entry's uses: a port or interface of a component.
pub trait UseRef {
    /// Points the reference at the element `at` of the component entry with id `id`.
    fn bind(&mut self, id: ComponentId, at: RefHandle);
    /// The id of the component the port or interface is of.
    fn component(&self) -> &ComponentId;
}

impl UseRef for PortRef {
    fn bind(&mut self, id: ComponentId, at: RefHandle) {
        (self.component, self.at) = (id, at);
    }
    fn component(&self) -> &ComponentId {
        &self.component
    }
}

impl UseRef for InterfaceRef {
    fn bind(&mut self, id: ComponentId, at: RefHandle) {
        (self.component, self.at) = (id, at);
    }
    fn component(&self) -> &ComponentId {
        &self.component
    }
}

/// The uses of a type entry, by role, in the order pages list them (declared by `uses!`).
pub trait Uses: Sized {
    type Ref: UseRef;
    fn by_role(&self) -> [(Role, &[Self::Ref]); 3];
    /// The lists of [`Uses::by_role`], to change.
    fn refs_mut(&mut self) -> [&mut Vec<Self::Ref>; 3];
    /// The uses from the lists of [`Uses::by_role`], in that order.
    fn from_slots(slots: [Vec<Self::Ref>; 3]) -> Self;
    /// Required somewhere but provided nowhere in the catalogue (interfaces only).
    fn is_unprovided(&self) -> bool {
        let [(role, provided), (_, required), _] = self.by_role();
        role == Role::Provider && provided.is_empty() && !required.is_empty()
    }
}

impl<U: Uses> TypeEntry<U> {
    /// Every use, role by role.
    pub fn all_uses(&self) -> impl Iterator<Item = &U::Ref> {
        self.uses
            .by_role()
            .into_iter()
            .flat_map(|(_, refs)| refs.iter())
    }

    /// Required somewhere but provided nowhere in the catalogue (interfaces only).
    pub fn is_unprovided(&self) -> bool {
        self.uses.is_unprovided()
    }
}

/// A category or vendor and its components. Spellings that differ only in case or spacing
/// ("Hardware Interface" / "Hardware interface" / "Hardware_interface") are one facet, named
/// by the most frequent spelling.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct Facet {
    pub name: String,
    pub slug: String,
    /// The components, by [`Component::id`], in catalogue order.
    pub components: Vec<ComponentId>,
    /// The other spellings met, sorted (empty when all components agree).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub variants: Vec<String>,
}

/// The key that groups category and vendor spellings into one facet: lower case, without
/// whitespace (`PointCloud`, `Pointcloud` and `Point cloud` are one).
pub fn facet_key(s: &str) -> String {
    if s.is_ascii() {
        // The same for ASCII text, byte by byte (systems match every component on three).
        return s
            .bytes()
            .filter(|&b| !char::from(b).is_whitespace())
            .map(|b| char::from(b.to_ascii_lowercase()))
            .collect();
    }
    s.split_whitespace()
        .flat_map(|w| w.chars().flat_map(char::to_lowercase))
        .collect()
}

/// The key that groups category and vendor spellings into one facet: [`facet_key`], and `_`
/// and `-` count as spaces too (`Information_acquisition` is `Information acquisition`, as
/// their slugs already said). Systems match their instances on [`facet_key`] alone: there
/// `Camera_1` and `Camera1` are two components.
pub fn facet_group_key(s: &str) -> String {
    let mut k = facet_key(s);
    k.retain(|c| c != '_' && c != '-');
    k
}

/// The facet of `value` (a component's category or vendor, as written) among `facets`.
pub fn facet_of<'a>(facets: &'a [Facet], value: &str) -> Option<&'a Facet> {
    let key = facet_group_key(value);
    facets.iter().find(|f| facet_group_key(&f.name) == key)
}

/// The file names of `idlFile` values, sorted and without repeats: `idlFile` is usually an
/// absolute path on the author's machine (`C:\Program Files\OpenRTM-aist\1.2.2\rtm\idl\…`),
/// which type pages do not lead with (the component pages and the JSON keep it as written).
pub fn idl_file_names(files: &[String]) -> Vec<String> {
    let mut names: Vec<String> = files
        .iter()
        .map(|f| f.rsplit(['/', '\\']).next().unwrap_or(f).trim().to_string())
        .filter(|n| !n.is_empty())
        .collect();
    names.sort();
    names.dedup();
    names
}

/// The whole catalogue. [`Catalog::default`] is an empty one, without lookups
/// ([`Catalog::with_lookups`]).
#[derive(Debug, Clone, Default, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct Catalog {
    pub components: Vec<Component>,
    pub data_types: Vec<DataType>,
    pub interfaces: Vec<InterfaceType>,
    pub categories: Vec<Facet>,
    pub vendors: Vec<Facet>,
    pub diagnostics: Vec<Diagnostic>,
    /// The IDL files read (below the input and on the IDL path): what is inside the data types
    /// and service interfaces. Left out of `catalog.json` when there are none.
    #[serde(skip_serializing_if = "crate::idl::IdlSet::is_empty")]
    pub idl: crate::idl::IdlSet,
    /// The history of each IDL file of `idl`, by its path ([`history`]; `catalog.json` has it
    /// as the file's `history`); files without one are absent.
    #[serde(skip)]
    pub idl_history: std::collections::BTreeMap<String, Vec<history::Entry>>,
    /// Every page of the catalogue, computed once ([`Catalog::pages`]).
    #[serde(skip)]
    pages: Vec<Page>,
    #[serde(skip)]
    page_starts: PageStarts,
    #[serde(skip)]
    by_id: HashMap<ComponentId, ComponentIx>,
    /// The RT System profiles read ([`Catalog::attach_systems`]), by source path. Left out of
    /// `catalog.json` when there are none.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub systems: Vec<systems::System>,
    /// RTCBuilder backups whose `RTC.xml` is no component of the catalogue (it failed to read,
    /// was excluded or is gone): older versions kept for the history, not documented.
    #[serde(skip)]
    pub detached_backups: Vec<backups::Backup>,
    /// The `[[source]]` repositories read ([`Catalog::attach_sources`]), by name.
    #[serde(skip)]
    pub sources: Vec<crate::model::SourceInfo>,
    /// What cut the git histories short (a repository git refuses, a shallow clone, a file
    /// whose log git could not give), sorted: `build` prints them as warnings.
    #[serde(skip)]
    pub history_notes: Vec<String>,
    #[serde(skip)]
    type_index: HashMap<String, DataTypeIx>,
    #[serde(skip)]
    interface_index: HashMap<String, InterfaceIx>,
    /// How many components each type's producers and consumers (providers and requirers)
    /// name ([`Catalog::index_peers`]).
    #[serde(skip)]
    peer_runs: PeerRuns,
    /// Each component's data ports' types and service interfaces' types, resolved once when
    /// the catalogue is made ([`Catalog::index_port_types`]): pages ask by handle, not by name.
    #[serde(skip)]
    port_types: PortTypes,
}

/// The type of each port of each component, by position ([`Catalog::port_type`],
/// [`Catalog::interface_type`]).
#[derive(Debug, Clone, Default)]
struct PortTypes {
    /// `data[component][port]`.
    data: Vec<Vec<Option<DataTypeIx>>>,
    /// `interfaces[component][service port][interface]`.
    interfaces: Vec<Vec<Vec<Option<InterfaceIx>>>>,
}

/// For each data type and interface, for its two directions: the length of the list of uses
/// and how many components the list names, when it is sorted by component (as the catalogue
/// makes it); `None` otherwise, and a list whose length no longer matches is counted again.
#[derive(Debug, Clone, Default)]
struct PeerRuns {
    data: Vec<[Counted; 2]>,
    interfaces: Vec<[Counted; 2]>,
}

/// The length of a list of uses, and how many components it names when it is sorted.
type Counted = (usize, Option<usize>);

/// The uses of a type that a port connects to ([`Catalog::data_port_peers`]), in catalogue
/// order (so grouped by component), and how many components they name when the catalogue
/// knows it: then a port's peers are found without walking a popular type's whole list.
#[derive(Debug)]
pub struct PeerRefs<'a, R> {
    pub refs: &'a [R],
    pub components: Option<usize>,
}

impl<R> Clone for PeerRefs<'_, R> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<R> Copy for PeerRefs<'_, R> {}

impl<'a, R> PeerRefs<'a, R> {
    /// References whose components are not counted (every one is looked at).
    pub fn uncounted(refs: &'a [R]) -> Self {
        PeerRefs {
            refs,
            components: None,
        }
    }
}

/// How many components `refs` name, when they are sorted by component (each component's
/// references together) and every one resolves; `None` otherwise.
fn component_runs<R>(refs: &[R], component: impl Fn(&R) -> Option<ComponentIx>) -> Option<usize> {
    let mut runs = 0;
    let mut last = None;
    for r in refs {
        let c = component(r)?;
        match last {
            Some(l) if c < l => return None,
            Some(l) if c == l => {}
            _ => runs += 1,
        }
        last = Some(c);
    }
    Some(runs)
}

/// What a page documents.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub enum PageKind {
    /// The front page: every component by category.
    Index,
    Search,
    Diagnostics,
    /// The page a server shows for a missing path.
    NotFound,
    Component,
    DataTypes,
    DataType,
    Interfaces,
    Interface,
    Categories,
    Category,
    Vendors,
    Vendor,
    /// The index of RT Systems (only when there are some).
    Systems,
    System,
    /// Which groups of components can feed which ([`dataflow`]).
    DataFlow,
    /// Every change of every history (components, RT Systems, IDL files), newest first (only
    /// when something has a history).
    WhatsNew,
    /// The whole history of one component (only for a component with a history).
    ComponentHistory,
    /// The whole history of one RT System profile (only for a system with a history).
    SystemHistory,
    /// The whole history of one IDL file (only for a file with a history).
    IdlHistory,
}

/// One page of the documentation: the same list for every output (HTML, Markdown, Doxygen),
/// which takes the paths from it with its own extension ([`Page::path`]).
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct Page {
    pub kind: PageKind,
    /// The id of the entry the page documents: [`Component::id`], a type's or interface's
    /// scoped name, a facet's name; empty for the pages of the site itself.
    pub id: String,
    /// The path below the output root, without extension, with forward slashes
    /// (`components/camera`, `types/rtc-timedlong`, `index`).
    pub stem: String,
    /// The name of what the page documents (a component's display name, a type's name).
    pub title: String,
}

/// The output formats that write pages, each with its own file names for the index pages.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Output {
    Html,
    /// An mdBook `src/`.
    Markdown,
    /// Doxygen `.dox` input.
    Doxygen,
    /// A system manual (`-f manual`): one HTML file per RT System in which the pages it
    /// holds (the system, its components, their types) are sections, and every link an
    /// anchor of that file ([`Page::section_id`]).
    Manual,
}

impl Page {
    /// The page's path below the output root in HTML (`components/camera.html`).
    pub fn path(&self, ext: &str) -> String {
        let mut s = String::with_capacity(self.stem.len() + 1 + ext.len());
        s.push_str(&self.stem);
        s.push('.');
        s.push_str(ext);
        s
    }

    /// The name of the page in output `out` when that output's layout fixes it (mdBook's
    /// `types.md`, Doxygen's `mainpage.dox`), else `None`: the page's stem and the output's
    /// extension.
    fn fixed_name(&self, out: Output) -> Option<&'static str> {
        /// The index pages whose name the layout fixes: (kind, Markdown name, Doxygen name).
        const FIXED: [(PageKind, Option<&str>, &str); 6] = [
            (PageKind::Index, None, "mainpage.dox"),
            (PageKind::DataTypes, Some("types.md"), "types.dox"),
            (
                PageKind::Interfaces,
                Some("interfaces.md"),
                "interfaces.dox",
            ),
            (
                PageKind::Categories,
                Some("categories.md"),
                "categories.dox",
            ),
            (PageKind::Vendors, Some("vendors.md"), "vendors.dox"),
            (PageKind::Systems, Some("systems.md"), "systems.dox"),
        ];
        let &(_, md, dox) = FIXED.iter().find(|(k, _, _)| *k == self.kind)?;
        match out {
            Output::Html | Output::Manual => None,
            Output::Markdown => md,
            Output::Doxygen => Some(dox),
        }
    }

    /// The page's path in output `out`. The entry pages have the same stem everywhere; the
    /// index pages follow each tool's layout: mdBook's `index.md`, `types.md`, `interfaces.md`,
    /// `vendors.md` beside `SUMMARY.md` (so that no entry slug can collide with them),
    /// Doxygen's `mainpage.dox`, `types.dox`, `interfaces.dox`, `vendors.dox`. Links between
    /// pages come from [`Catalog::href`]; which pages an output writes, [`Output::carries`].
    pub fn path_in(&self, out: Output) -> String {
        let mut s = String::new();
        self.push_path_in(out, &mut s);
        s
    }

    /// Appends [`Page::path_in`] to `s`.
    pub(crate) fn push_path_in(&self, out: Output, s: &mut String) {
        match self.fixed_name(out) {
            Some(name) => s.push_str(name),
            None => {
                s.push_str(&self.stem);
                s.push_str(match out {
                    Output::Html | Output::Manual => ".html",
                    Output::Markdown => ".md",
                    Output::Doxygen => ".dox",
                });
            }
        }
    }

    /// How many folders deep the page is in output `out`.
    pub(crate) fn depth_in(&self, out: Output) -> usize {
        let path = self.fixed_name(out).unwrap_or(&self.stem);
        path.bytes().filter(|&b| b == b'/').count()
    }

    /// The file name alone (`camera.html`), for links between pages of one folder.
    pub fn file_name(&self, ext: &str) -> String {
        let name = self.stem.rsplit('/').next().unwrap_or(&self.stem);
        format!("{name}.{ext}")
    }
}

/// Where each kind of entry page starts in [`Catalog::pages`]: entries are listed in the
/// order of their vectors, so the page of entry `i` is `pages[start + i]`.
#[derive(Debug, Clone, Default)]
struct PageStarts {
    /// The history page of each component (its position in the page list), if it has one.
    history: Vec<Option<usize>>,
    /// The history page of each system, if it has one.
    system_history: Vec<Option<usize>>,
    /// The history page of each IDL file ([`crate::idl::IdlSet::files`]), if it has one.
    idl_history: Vec<Option<usize>>,
    component: usize,
    data_type: usize,
    interface: usize,
    category: usize,
    vendor: usize,
    system: usize,
}

/// The name of a member (port, interface) as its key starts: empty when it has none.
fn name_of(n: &Option<Text>) -> &str {
    n.as_deref().unwrap_or_default()
}

/// The key of each component of `loaded` (in parallel), and whether its profile writes an id:
/// `RTC:vendor:category:name:version` from the id written (the dotted form of RTCBuilder 0.1
/// read as the colon form with the same parts), the id as written when it has no such parts,
/// or made from the basic info when the profile writes none.
fn id_keys(loaded: &[LoadedProfile]) -> Vec<(String, bool)> {
    loaded
        .par_iter()
        .map(|l| {
            let p = &l.profile;
            let written = p.id.as_deref().map(str::trim).filter(|s| !s.is_empty());
            let key = match written.and_then(|id| crate::model::IdParts::parse(id, &p.basic_info)) {
                Some(x) => format!("RTC:{}:{}:{}:{}", x.vendor, x.category, x.name, x.version),
                None => match written {
                    Some(id) => id.to_string(),
                    None => {
                        let b = &p.basic_info;
                        let part =
                            |v: &Option<Text>| v.as_deref().unwrap_or_default().trim().to_string();
                        format!(
                            "RTC:{}:{}:{}:{}",
                            part(&b.vendor),
                            part(&b.category),
                            part(&b.name),
                            part(&b.version)
                        )
                    }
                },
            };
            (key, written.is_some())
        })
        .collect()
}

/// Ids of the components of `loaded` ([`Component::id`]), from their [`id_keys`]: the key, or
/// the key and the source path when other components have the same key.
fn component_ids(loaded: &[LoadedProfile], keys: &[(String, bool)]) -> Vec<ComponentId> {
    let mut count: HashMap<&str, usize> = HashMap::new();
    for (k, _) in keys {
        *count.entry(k.as_str()).or_default() += 1;
    }
    keys.iter()
        .map(|(k, _)| k)
        .zip(loaded)
        .map(|(k, l)| {
            if count[k.as_str()] > 1 {
                ComponentId::from(format!("{k}@{}", l.source))
            } else {
                ComponentId::from(k.as_str())
            }
        })
        .collect()
}

/// A profile read from one file, ready for the catalogue.
#[derive(Debug, Clone)]
pub struct LoadedProfile {
    pub source: String,
    pub format: SourceFormat,
    pub profile: Box<Profile>,
}

/// [`crate::catalog::Catalog::documented`] from the counts (several inputs of `check` add up).
pub fn documented(components: usize, systems: usize, idl_files: usize) -> String {
    let plural =
        |n: usize, one: &str, many: &str| format!("{n} {}", if n == 1 { one } else { many });
    let mut parts = Vec::new();
    if components > 0 || (systems == 0 && idl_files == 0) {
        parts.push(plural(
            components,
            "component profile",
            "component profiles",
        ));
    }
    if systems > 0 {
        parts.push(plural(systems, "RT System", "RT Systems"));
    }
    if idl_files > 0 {
        parts.push(plural(idl_files, "IDL file", "IDL files"));
    }
    match parts.pop() {
        Some(last) if !parts.is_empty() => format!("{} and {last}", parts.join(", ")),
        Some(last) => last,
        None => String::new(),
    }
}

/// Assigns unique slugs: the plain slug when it is unique, else slug + hash of `disambiguator`
/// (stable: adding another component never renames an existing page unless it collides).
fn unique_slugs(items: &[(String, String)]) -> Vec<String> {
    let mut count: HashMap<String, usize> = HashMap::new();
    let base: Vec<String> = items.par_iter().map(|(name, _)| slugify(name)).collect();
    for b in &base {
        *count.entry(b.clone()).or_default() += 1;
    }
    let mut used: HashMap<String, usize> = HashMap::new();
    let mut out = Vec::with_capacity(items.len());
    for (b, (_, dis)) in base.iter().zip(items) {
        // `index` is reserved for the index page of each page folder.
        let mut s = if count[b] > 1 || b == "index" {
            format!("{b}-{:06x}", fnv1a(dis.as_bytes()) as u32 & 0xff_ffff)
        } else {
            b.clone()
        };
        // A hash collision, or a plain slug equal to a disambiguated one: number it.
        let n = used.entry(s.clone()).or_default();
        *n += 1;
        if *n > 1 {
            s = format!("{s}-{n}");
        }
        out.push(s);
    }
    out
}

/// Each of `bases`, numbered from its second time on (`number(base, n)`), so that all differ.
fn numbered(
    bases: impl Iterator<Item = String>,
    number: impl Fn(&str, usize) -> String,
) -> Vec<String> {
    let mut seen: HashMap<String, usize> = HashMap::new();
    bases
        .map(|base| {
            let c = seen.entry(base.clone()).or_default();
            *c += 1;
            if *c > 1 {
                number(&base, *c)
            } else {
                base
            }
        })
        .collect()
}

fn anchors_for(prefix: &str, names: impl Iterator<Item = String>) -> Vec<String> {
    numbered(
        names.map(|n| format!("{prefix}-{}", slugify(&n))),
        |base, c| format!("{base}-{c}"),
    )
}

fn anchors(profile: &Profile) -> Anchors {
    per_element(
        profile,
        ["port", "sport", "conf"],
        |sport| format!("if-{}", &sport[6..]),
        |prefix, names| anchors_for(prefix, names.map(|n| n.unwrap_or_default().to_string())),
    )
}

/// One string per element of a profile, in the shape of [`Anchors`]: `strings(prefix, names)`
/// makes a list's from its elements' names, the prefix `lists`' (data ports, service ports,
/// configurations) or, for a service port's interfaces, `interfaces(the port's string)`.
pub(crate) fn per_element<'p>(
    p: &'p Profile,
    [data_ports, service_ports, configurations]: [&str; 3],
    interfaces: impl Fn(&str) -> String,
    strings: impl Fn(&str, &mut dyn Iterator<Item = Option<&'p str>>) -> Vec<String>,
) -> Anchors {
    let names = |v: &'p Option<crate::model::Text>| v.as_deref();
    let sports = strings(
        service_ports,
        &mut p.service_ports.iter().map(|s| names(&s.name)),
    );
    let ifs = p.service_ports.iter().zip(&sports).map(|(sp, key)| {
        strings(
            &interfaces(key),
            &mut sp.interfaces.iter().map(|i| names(&i.name)),
        )
    });
    Anchors {
        data_ports: strings(data_ports, &mut p.data_ports.iter().map(|d| names(&d.name))),
        interfaces: ifs.collect(),
        service_ports: sports,
        configurations: strings(
            configurations,
            &mut p.configurations().iter().map(|c| names(&c.name)),
        ),
    }
}

/// The slot of a data port among its type's uses ([`Uses::by_role`]): out ports produce, in
/// ports consume, other ports come last.
fn port_slot(p: &DataPort) -> usize {
    match p.direction() {
        Some(PortDirection::Out) => 0,
        Some(PortDirection::In) => 1,
        _ => 2,
    }
}

/// The slot of a service interface among its type's uses: provided, required, other.
fn interface_slot(i: &ServiceInterface) -> usize {
    match i.direction_kind() {
        Some(Direction::Provided) => 0,
        Some(Direction::Required) => 1,
        None => 2,
    }
}

/// The uses of type `t` among `entries` (their components counted in `runs`) that a use in
/// slot `slot` connects to: those of the other direction (none for the others, or when the
/// catalogue does not have the type).
fn peers<'a, U: Uses>(
    entries: &'a [TypeEntry<U>],
    runs: &[[Counted; 2]],
    t: Option<Ix<TypeEntry<U>>>,
    slot: usize,
) -> PeerRefs<'a, U::Ref> {
    let t = t.and_then(|t| Some((entries.get(t.get())?, runs.get(t.get())?)));
    match (t, slot) {
        (Some((t, runs)), 0 | 1) => {
            let refs = t.uses.by_role()[1 - slot].1;
            let (len, components) = runs[1 - slot];
            PeerRefs {
                refs,
                components: components.filter(|_| len == refs.len()),
            }
        }
        _ => PeerRefs::uncounted(&[]),
    }
}

/// Where a port or interface is: (component, port, interface within the port; 0 for a data
/// port).
type UseAt = (usize, usize, usize);

/// What the ports say about one type name while the catalogue is assembled: its spellings,
/// `idlFile`s and uses, in the three slots of [`Uses::by_role`] (the two directions, others).
#[derive(Default)]
struct TypeAcc<'a> {
    spellings: Vec<&'a str>,
    idl_files: Vec<&'a str>,
    uses: [Vec<UseAt>; 3],
}

impl<'a> TypeAcc<'a> {
    /// A use spelled `t` with `idl_file`, in role slot `slot`, at `at`.
    fn add(&mut self, t: &'a str, idl_file: Option<&'a str>, slot: usize, at: UseAt) {
        self.spellings.push(t.trim());
        if let Some(f) = idl_file.filter(|f| !f.trim().is_empty()) {
            self.idl_files.push(f.trim());
        }
        self.uses[slot].push(at);
    }

    /// One entry per name of `accs`, in name order, each with its slug; `refs` makes the
    /// references of each slot. The entries are made on every core.
    fn entries<U: Uses>(
        accs: BTreeMap<String, TypeAcc<'a>>,
        refs: impl Fn(Vec<UseAt>) -> Vec<U::Ref> + Sync,
    ) -> Vec<TypeEntry<U>>
    where
        TypeEntry<U>: Send,
    {
        let names: Vec<(String, String)> = accs.keys().map(|k| (k.clone(), k.clone())).collect();
        let accs: Vec<(String, TypeAcc<'a>)> = accs.into_iter().collect();
        accs.into_par_iter()
            .zip(unique_slugs(&names))
            .map(|((name, acc), slug)| TypeEntry {
                name,
                slug,
                spellings: sorted_unique(acc.spellings),
                idl_files: sorted_unique(acc.idl_files),
                uses: U::from_slots(acc.uses.map(&refs)),
                contained_in: Vec::new(),
                used_by: Vec::new(),
                stability: None,
            })
            .collect()
    }
}

fn sorted_unique(mut v: Vec<&str>) -> Vec<String> {
    v.sort_unstable();
    v.dedup();
    v.into_iter().map(str::to_string).collect()
}

/// Everything read from one input, before it is a catalogue ([`Catalog::assemble`]).
pub struct Documents {
    pub profiles: Vec<LoadedProfile>,
    /// The load diagnostics: reader warnings, files that could not be read, IDL findings.
    pub diagnostics: Vec<Diagnostic>,
    pub idl: crate::idl::IdlSet,
    pub systems: Vec<systems::LoadedSystem>,
    pub backups: Vec<backups::Backup>,
    /// The folders that may hold a README (the walk met an entry named like one there:
    /// [`crate::walk::Candidates::readme_dirs`]); `None`: every component folder is looked in.
    pub readme_dirs: Option<std::collections::BTreeSet<String>>,
    /// Whether and how each component's implementation is read ([`crate::implementation`]).
    pub implementation: implementations::Settings,
    /// The components found in code alone ([`crate::implementation::recover::find_all`]),
    /// by source; their profiles are among `profiles`.
    pub recovered: BTreeMap<String, implementations::Recovery>,
    /// The `[stability]` marks of `rtcdoc.toml` ([`stability`]).
    pub stability: stability::Settings,
}

impl Catalog {
    /// The one assembly of a catalogue from its documents, used by `build`, `check`, `diff` and
    /// `serve`'s rebuild alike: components, then IDL, systems, RTCBuilder backups (`exists`
    /// says whether an input-relative file is there) and READMEs (read below `root`, unless
    /// `excluded` names them). The `check` findings are not added here.
    pub fn assemble(
        docs: Documents,
        root: &sources::Roots,
        excluded: &(dyn Fn(&str) -> bool + Sync),
    ) -> Catalog {
        // The page list and the peer runs are made once, when the entries are all there.
        let mut catalog = Catalog::build_entries(docs.profiles, docs.diagnostics, &docs.idl);
        catalog.attach_idl(docs.idl);
        catalog.attach_systems(docs.systems);
        catalog.index();
        catalog.attach_stability(&docs.stability);
        catalog.attach_backups(docs.backups, &|rel| root.dir_of(rel).join(rel).is_file());
        catalog.attach_readmes(root, excluded, docs.readme_dirs.as_ref());
        catalog.attach_recovered(docs.recovered);
        catalog.attach_implementations(root, excluded, &docs.implementation);
        catalog.attach_sources(root.sources.clone());
        catalog
    }
}

/// The data-type and interface entries of `components`, from each component's canonical
/// port type names (`canonical`, in [`Profile::port_types`] order).
fn type_indexes(
    components: &[Component],
    canonical: Vec<Vec<Option<String>>>,
) -> (Vec<DataType>, Vec<InterfaceType>) {
    let mut types: BTreeMap<String, TypeAcc<'_>> = BTreeMap::new();
    let mut ifaces: BTreeMap<String, TypeAcc<'_>> = BTreeMap::new();
    for ((ci, c), keys) in components.iter().enumerate().zip(canonical) {
        // Each port's and interface's type in `port_types` order: whether it is an
        // interface, its spelling and `idlFile`, its role slot and where it is.
        let data = c
            .profile
            .data_ports
            .iter()
            .enumerate()
            .map(|(pi, p)| (false, &p.type_, &p.idl_file, port_slot(p), (ci, pi, 0)));
        let service = c
            .profile
            .service_interfaces()
            .map(|(pi, ii, i)| (true, &i.type_, &i.idl_file, interface_slot(i), (ci, pi, ii)));
        for ((interface, t, idl_file, slot, at), key) in data.chain(service).zip(keys) {
            let (Some(key), Some(t)) = (key, t.as_deref()) else {
                continue;
            };
            let accs = if interface { &mut ifaces } else { &mut types };
            let acc = accs.entry(key).or_default();
            acc.add(t, idl_file.as_deref(), slot, at);
        }
    }
    let port = |v: Vec<UseAt>| {
        v.into_iter()
            .map(|(ci, pi, _)| {
                let c = &components[ci];
                PortRef {
                    component: c.id.clone(),
                    port: member_key(c.profile.data_ports.iter().map(|p| name_of(&p.name)), pi),
                    at: RefHandle::new(Ix::new(ci), pi, 0),
                }
            })
            .collect()
    };
    let iref = |v: Vec<UseAt>| {
        v.into_iter()
            .map(|(ci, pi, ii)| {
                let c = &components[ci];
                let sp = &c.profile.service_ports[pi];
                InterfaceRef {
                    component: c.id.clone(),
                    port: member_key(c.profile.service_ports.iter().map(|p| name_of(&p.name)), pi),
                    interface: member_key(sp.interfaces.iter().map(|i| name_of(&i.name)), ii),
                    at: RefHandle::new(Ix::new(ci), pi, ii),
                }
            })
            .collect()
    };
    let data_types: Vec<DataType> = TypeAcc::entries(types, port);
    let interfaces: Vec<InterfaceType> = TypeAcc::entries(ifaces, iref);
    (data_types, interfaces)
}

impl Catalog {
    /// Builds the catalogue. Components are ordered by source path; `diagnostics` are the load
    /// diagnostics (reader warnings and errors of files that could not be read).
    pub fn build(loaded: Vec<LoadedProfile>, diagnostics: Vec<Diagnostic>) -> Catalog {
        let mut catalog =
            Catalog::build_entries(loaded, diagnostics, &crate::idl::IdlSet::default());
        catalog.index();
        catalog
    }

    /// [`Catalog::build`] without the page list and the peer runs ([`Catalog::index`]), for
    /// [`Catalog::assemble`], which makes them once, after the IDL and the systems.
    /// A port type spelled as a repository id is keyed by the definition `idl` has under that
    /// id ([`crate::idl::IdlSet::canonical_name`]).
    fn build_entries(
        mut loaded: Vec<LoadedProfile>,
        mut diagnostics: Vec<Diagnostic>,
        idl: &crate::idl::IdlSet,
    ) -> Catalog {
        loaded.sort_by(|a, b| a.source.cmp(&b.source));

        // Component slugs from names, disambiguated by language or folder.
        let slugs = component_slugs(&loaded);
        let all_anchors: Vec<Anchors> = loaded.par_iter().map(|l| anchors(&l.profile)).collect();
        let keys = id_keys(&loaded);
        let ids = component_ids(&loaded, &keys);
        let components: Vec<Component> = loaded
            .into_iter()
            .zip(slugs)
            .zip(all_anchors)
            .zip(ids)
            .map(|(((l, (slug, qualifier)), anchors), id)| Component {
                id,
                anchors,
                qualifier,
                readme: None,
                implementation: None,
                recovered: None,
                backups: Vec::new(),
                history: Vec::new(),
                since: BTreeMap::new(),
                stability: None,
                origin: None,
                source: l.source,
                format: l.format,
                slug,
                profile: l.profile,
            })
            .collect();

        // Duplicate ids: kept apart (both rendered), warned about. The dotted form of
        // RTCBuilder 0.1 names the same component as the colon form with the same parts.
        let mut by_id: BTreeMap<&str, Vec<usize>> = BTreeMap::new();
        for (i, (key, written)) in keys.iter().enumerate() {
            if *written {
                by_id.entry(key).or_default().push(i);
            }
        }
        let lang = |i: usize| components[i].profile.language_kind();
        for (id, idx) in &by_id {
            if idx.len() > 1 {
                for &i in idx {
                    // The C++ and Python implementations of one component share its id
                    // (RTCBuilder generates both from one specification): each is told apart
                    // by its language (its page, and `diff` pairs them so), so only profiles
                    // of the same language, or without one, are ambiguous.
                    let clashes = |j: usize| {
                        j != i
                            && match (lang(i), lang(j)) {
                                (Some(a), Some(b)) => a == b,
                                _ => true,
                            }
                    };
                    // Name a few of the other files, not all: a copied profile can be
                    // duplicated hundreds of times and the message must stay short.
                    let others: Vec<&str> = idx
                        .iter()
                        .filter(|&&j| clashes(j))
                        .map(|&j| components[j].source.as_str())
                        .collect();
                    if others.is_empty() {
                        continue;
                    }
                    let list = crate::diagnostic::a_few(&others);
                    diagnostics.push(
                        Diagnostic::warning(
                            codes::DUPLICATE_ID,
                            &components[i].source,
                            format!("component id `{id}` is also declared by {list}"),
                        )
                        .at(components[i].profile.pos)
                        .with_hint("both profiles are rendered on separate pages; give each component its own id"),
                    );
                }
            }
        }

        // Data-type and interface indexes, one pass over all ports. The canonical type names
        // are computed in parallel first, in the order the loop meets them.
        let canonical: Vec<Vec<Option<String>>> = components
            .par_iter()
            .map(|c| {
                c.profile
                    .port_types()
                    .map(|t| {
                        t.as_deref()
                            .filter(|t| !t.trim().is_empty())
                            .map(|t| idl.canonical_name(t))
                    })
                    .collect()
            })
            .collect();

        let facet = |key: &dyn Fn(&Profile) -> Option<&str>| -> Vec<Facet> {
            // key → (spelling → components)
            let mut groups: BTreeMap<String, BTreeMap<String, Vec<usize>>> = BTreeMap::new();
            for (i, c) in components.iter().enumerate() {
                let k = key(&c.profile)
                    .map(str::trim)
                    .filter(|s| !s.is_empty())
                    .unwrap_or("");
                groups
                    .entry(facet_group_key(k))
                    .or_default()
                    .entry(k.to_string())
                    .or_default()
                    .push(i);
            }
            // Named by the most frequent spelling (the first in sort order on a tie).
            let mut m: BTreeMap<String, (Vec<ComponentId>, Vec<String>)> = BTreeMap::new();
            for spellings in groups.into_values() {
                let name = spellings
                    .iter()
                    .max_by(|a, b| a.1.len().cmp(&b.1.len()).then_with(|| b.0.cmp(a.0)))
                    .map(|(s, _)| s.clone())
                    .unwrap_or_default();
                let variants = spellings.keys().filter(|s| **s != name).cloned().collect();
                let mut members: Vec<usize> = spellings.into_values().flatten().collect();
                members.sort_unstable();
                let members: Vec<ComponentId> = members
                    .into_iter()
                    .map(|i| components[i].id.clone())
                    .collect();
                m.insert(name, (members, variants));
            }
            // Listed case-insensitively (`camera` beside `Camera…`, not after `Z…`), the name
            // as written breaking ties.
            type Group = (Vec<ComponentId>, Vec<String>);
            let mut m: Vec<(String, Group)> = m.into_iter().collect();
            m.sort_by_cached_key(|(name, _)| (name.to_lowercase(), name.clone()));
            let names: Vec<(String, String)> =
                m.iter().map(|(k, _)| (k.clone(), k.clone())).collect();
            m.into_iter()
                .zip(unique_slugs(&names))
                .map(|((name, (components, variants)), slug)| Facet {
                    name,
                    slug,
                    components,
                    variants,
                })
                .collect()
        };
        // The type indexes and the two facet lists are independent: made side by side. The
        // findings' sort runs on every core by itself.
        let ((data_types, interfaces), (categories, vendors)) = rayon::join(
            || type_indexes(&components, canonical),
            || {
                // RTCBuilder's placeholders (`Category`, `VenderName`) name no group: their
                // components are uncategorised (the value stays in the profile and its page).
                rayon::join(
                    || facet(&|p| crate::model::documented("category", &p.basic_info.category)),
                    || facet(&|p| crate::model::documented("vendor", &p.basic_info.vendor)),
                )
            },
        );
        crate::diagnostic::sort(&mut diagnostics);
        Catalog {
            components,
            data_types,
            interfaces,
            categories,
            vendors,
            diagnostics,
            ..Catalog::default()
        }
        .with_lookups()
    }

    /// This catalogue, its entries set on [`Catalog::default`], with their lookups, without the
    /// page list and the peer runs (no systems, backups or sources yet). Entries read back from
    /// `catalog.json` get those and their handles from [`Catalog::bound`].
    pub fn with_lookups(mut self) -> Catalog {
        self.type_index = handle_map(&self.data_types, |t| t.name.clone());
        self.interface_index = handle_map(&self.interfaces, |t| t.name.clone());
        self.by_id = handle_map(&self.components, |c| c.id.clone());
        self
    }

    /// Makes the page list and the peer runs of the entries as they are now.
    fn index(&mut self) {
        self.index_pages();
        self.index_peers();
        self.index_port_types();
    }

    /// Resolves the type of every data port and service interface once ([`PortTypes`]).
    fn index_port_types(&mut self) {
        let components = self.components.iter();
        self.port_types = PortTypes {
            data: components
                .clone()
                .map(|c| {
                    let ports = c.profile.data_ports.iter();
                    ports.map(|p| self.data_port_type_by_name(p)).collect()
                })
                .collect(),
            interfaces: components
                .map(|c| {
                    let ports = c.profile.service_ports.iter();
                    ports
                        .map(|sp| {
                            let all = sp.interfaces.iter();
                            all.map(|i| self.interface_type_by_name(i)).collect()
                        })
                        .collect()
                })
                .collect(),
        };
    }

    /// The data type data port `p` names.
    fn data_port_type_by_name(&self, p: &crate::model::DataPort) -> Option<DataTypeIx> {
        self.data_type_index(p.type_.as_deref()?)
    }

    /// The interface type service interface `i` names.
    fn interface_type_by_name(&self, i: &crate::model::ServiceInterface) -> Option<InterfaceIx> {
        self.interface_index_of(i.type_.as_deref()?)
    }

    /// The data type of data port `port` of `component` (none: no type, or not in the
    /// catalogue); resolved when the catalogue was made, looked up by name in one that was
    /// not indexed.
    pub fn port_type(&self, component: ComponentIx, port: usize) -> Option<DataTypeIx> {
        match self.port_types.data.get(component.get()) {
            Some(ports) => ports.get(port).copied().flatten(),
            None => {
                let c = self.components.get(component.get())?;
                self.data_port_type_by_name(c.profile.data_ports.get(port)?)
            }
        }
    }

    /// The interface type of interface `interface` of service port `port` of `component`, as
    /// [`Catalog::port_type`].
    pub fn interface_type(
        &self,
        component: ComponentIx,
        port: usize,
        interface: usize,
    ) -> Option<InterfaceIx> {
        match self.port_types.interfaces.get(component.get()) {
            Some(ports) => ports.get(port)?.get(interface).copied().flatten(),
            None => {
                let c = self.components.get(component.get())?;
                let sp = c.profile.service_ports.get(port)?;
                self.interface_type_by_name(sp.interfaces.get(interface)?)
            }
        }
    }

    /// This catalogue, made by [`Catalog::with_lookups`] of its entries as `catalog.json`
    /// holds them, with each reference given its handle and the page list and peer runs made.
    /// Every reference must name an entry of the catalogue.
    pub fn bound(self) -> Result<Catalog, String> {
        let mut catalog = self;
        if catalog.by_id.len() < catalog.components.len() {
            let mut seen = std::collections::HashSet::new();
            if let Some(c) = catalog.components.iter().find(|c| !seen.insert(&c.id)) {
                return Err(format!("component id `{}` appears twice", c.id));
            }
        }
        // Each reference gets its handle ([`Catalog::rebind`]).
        let mut data_types = std::mem::take(&mut catalog.data_types);
        catalog.rebind(&mut data_types, |cat, name, r| {
            let (ci, pi) = cat.resolve_port(r).ok_or_else(|| {
                format!(
                    "data type `{name}` names port `{}` of `{}`, which the catalogue does not have",
                    r.port, r.component
                )
            })?;
            Ok((ci, pi, 0))
        })?;
        catalog.data_types = data_types;
        let mut interfaces = std::mem::take(&mut catalog.interfaces);
        catalog.rebind(&mut interfaces, |cat, name, r| {
            cat.resolve_interface(r).ok_or_else(|| {
                format!(
                    "interface `{name}` names `{}.{}` of `{}`, which the catalogue does not have",
                    r.port, r.interface, r.component
                )
            })
        })?;
        catalog.interfaces = interfaces;
        for f in catalog.categories.iter().chain(&catalog.vendors) {
            if let Some(id) = f
                .components
                .iter()
                .find(|id| catalog.component(id).is_none())
            {
                return Err(format!(
                    "facet `{}` names component `{id}`, which the catalogue does not have",
                    f.name
                ));
            }
        }
        catalog.index();
        Ok(catalog)
    }

    /// Gives each reference of `entries` its handle in this catalogue, and the id of the
    /// component entry it names (the same text: the handle is trusted only for that entry's
    /// id); `resolve` finds where a reference of entry `name` points, or says what is missing.
    fn rebind<U: Uses>(
        &self,
        entries: &mut [TypeEntry<U>],
        resolve: impl Fn(&Catalog, &str, &U::Ref) -> Result<(ComponentIx, usize, usize), String>,
    ) -> Result<(), String> {
        for t in entries {
            for r in t.uses.refs_mut().into_iter().flatten() {
                let (ci, pi, ii) = resolve(self, &t.name, r)?;
                r.bind(self[ci].id.clone(), RefHandle::new(ci, pi, ii));
            }
        }
        Ok(())
    }

    /// Computes [`Catalog::pages`] from the entries and their slugs.
    fn index_pages(&mut self) {
        use PageKind as K;
        fn site(kind: PageKind, stem: &str) -> Page {
            Page {
                kind,
                id: String::new(),
                stem: stem.to_string(),
                title: String::new(),
            }
        }
        let mut pages = vec![
            site(K::Index, "index"),
            site(K::Search, "search"),
            site(K::Diagnostics, "diagnostics"),
            site(K::NotFound, "404"),
            site(K::DataFlow, "dataflow"),
        ];
        // One kind of entry: its index page (when it has one), then a page
        // per entry, as (id, slug, title) in the entries' order, in the kind's directory;
        // gives where the entries' pages start.
        fn section<'a>(
            pages: &mut Vec<Page>,
            (kind, dir, index): Section,
            entries: impl Iterator<Item = (&'a str, &'a str, std::borrow::Cow<'a, str>)>,
        ) -> usize {
            pages.extend(index.map(|index| site(index, &format!("{dir}/index"))));
            let start = pages.len();
            pages.extend(entries.map(|(id, slug, title)| Page {
                kind,
                id: id.to_string(),
                stem: format!("{dir}/{slug}"),
                title: title.into_owned(),
            }));
            start
        }
        fn facet(f: &Facet) -> (&str, &str, std::borrow::Cow<'_, str>) {
            (&f.name, &f.slug, f.name.as_str().into())
        }
        fn type_entry<U>(t: &TypeEntry<U>) -> (&str, &str, std::borrow::Cow<'_, str>) {
            (&t.name, &t.slug, t.name.as_str().into())
        }
        // (entry page kind, directory, index page kind)
        type Section = (PageKind, &'static str, Option<PageKind>);
        const TYPES: Section = (K::DataType, "types", Some(K::DataTypes));
        const INTERFACES: Section = (K::Interface, "interfaces", Some(K::Interfaces));
        const CATEGORIES: Section = (K::Category, "categories", Some(K::Categories));
        const VENDORS: Section = (K::Vendor, "vendors", Some(K::Vendors));
        let p = &mut pages;
        let mut starts = PageStarts {
            history: Vec::new(),
            system_history: Vec::new(),
            idl_history: Vec::new(),
            component: section(
                p,
                (K::Component, "components", None),
                self.components
                    .iter()
                    .map(|c| (&*c.id, c.slug.as_str(), c.display_name())),
            ),
            data_type: section(p, TYPES, self.data_types.iter().map(type_entry)),
            interface: section(p, INTERFACES, self.interfaces.iter().map(type_entry)),
            category: section(p, CATEGORIES, self.categories.iter().map(facet)),
            vendor: section(p, VENDORS, self.vendors.iter().map(facet)),
            system: section(
                p,
                // The systems' index only when there are systems.
                (
                    K::System,
                    "systems",
                    Some(K::Systems).filter(|_| !self.systems.is_empty()),
                ),
                self.systems
                    .iter()
                    .map(|s| (s.source.as_str(), s.slug.as_str(), s.display_name())),
            ),
        };
        // The history pages: the catalogue's What's new, then one per component, system and
        // IDL file with a history, each kind in its folder one down (as every entry page).
        let (history, system_history, idl_history) = self.history_pages(&mut pages);
        self.pages = pages;
        starts.history = history;
        starts.system_history = system_history;
        starts.idl_history = idl_history;
        self.page_starts = starts;
    }

    /// Recomputes the page list after the histories were filled in (the history pages exist
    /// only for components, systems and IDL files with a history).
    pub fn index_history_pages(&mut self) {
        self.index_pages();
    }

    /// Every page of the documentation, in a fixed order: the site's own pages (index, search,
    /// diagnostics, not-found), then each kind's index page followed by its entries' pages.
    /// Renderers, the sitemap, the search index and `serve` take page paths from here.
    pub fn pages(&self) -> &[Page] {
        &self.pages
    }

    /// The page of the site itself of kind `kind` (index, search, diagnostics, not found, and
    /// the index pages of each entry kind).
    pub fn site_page(&self, kind: PageKind) -> &Page {
        self.pages
            .iter()
            .find(|p| p.kind == kind && p.id.is_empty())
            .unwrap_or(&self.pages[0])
    }

    /// The page of component `ci`.
    pub fn component_page(&self, ci: ComponentIx) -> &Page {
        &self.pages[self.page_starts.component + ci.get()]
    }

    /// The page of data type `ti` ([`Catalog::data_types`]).
    pub fn data_type_page(&self, ti: DataTypeIx) -> &Page {
        &self.pages[self.page_starts.data_type + ti.get()]
    }

    /// The page of interface `ii` ([`Catalog::interfaces`]).
    pub fn interface_page(&self, ii: InterfaceIx) -> &Page {
        &self.pages[self.page_starts.interface + ii.get()]
    }

    /// The page of data type or interface `t`.
    pub fn type_page(&self, t: TypeIx) -> &Page {
        match t {
            TypeIx::Data(i) => self.data_type_page(i),
            TypeIx::Interface(i) => self.interface_page(i),
        }
    }

    /// The page of category `fi` ([`Catalog::categories`]).
    pub fn category_page(&self, fi: usize) -> &Page {
        &self.pages[self.page_starts.category + fi]
    }

    /// The page of vendor `fi` ([`Catalog::vendors`]).
    pub fn vendor_page(&self, fi: usize) -> &Page {
        &self.pages[self.page_starts.vendor + fi]
    }

    /// The page of system `si` ([`Catalog::systems`]).
    pub fn system_page(&self, si: SystemIx) -> &Page {
        &self.pages[self.page_starts.system + si.get()]
    }

    /// The page of a system of the catalogue, found by its key (its file).
    pub fn page_of_system(&self, s: &systems::System) -> Option<&Page> {
        let si = self.systems.iter().position(|x| x.source == s.source)?;
        Some(self.system_page(Ix::new(si)))
    }

    /// The handle of the component with id `id`.
    pub fn component_index(&self, id: &str) -> Option<ComponentIx> {
        self.by_id.get(id).copied()
    }

    /// The component with id `id`.
    pub fn component(&self, id: &str) -> Option<&Component> {
        self.component_index(id).map(|i| &self[i])
    }

    /// The handles of a facet's components.
    pub fn members<'a>(&'a self, f: &'a Facet) -> impl Iterator<Item = ComponentIx> + 'a {
        f.components
            .iter()
            .filter_map(|id| self.component_index(id))
    }

    /// The category facet of each component, by handle (every component is in one).
    pub fn category_of_each(&self) -> PerEntry<Component, usize> {
        Self::facet_of_each(&self.categories, self.components.len(), self)
    }

    /// The vendor facet of each component, by handle (every component is in one).
    pub fn vendor_of_each(&self) -> PerEntry<Component, usize> {
        Self::facet_of_each(&self.vendors, self.components.len(), self)
    }

    fn facet_of_each(facets: &[Facet], n: usize, cat: &Catalog) -> PerEntry<Component, usize> {
        let mut of = PerEntry::new(vec![0; n]);
        for (fi, f) in facets.iter().enumerate() {
            for ci in cat.members(f) {
                of[ci] = fi;
            }
        }
        of
    }

    /// The component entry a handle points at, when it is the entry of id `id` (the very
    /// allocation: a handle made by this catalogue, or by a clone of its entry).
    fn handled(&self, id: &ComponentId, at: ComponentIx) -> Option<(ComponentIx, &Component)> {
        let c = self.components.get(at.get())?;
        ComponentId::same_entry(&c.id, id).then_some((at, c))
    }

    /// The handle of the component a port reference names: O(1) through the reference's
    /// handle ([`RefHandle`]), by id otherwise.
    pub fn port_component(&self, r: &PortRef) -> Option<ComponentIx> {
        match self.handled(&r.component, r.at.component) {
            Some((ci, _)) => Some(ci),
            None => self.component_index(&r.component),
        }
    }

    /// The handle of the component an interface reference names: O(1) through the
    /// reference's handle, by id otherwise.
    pub fn interface_component(&self, r: &InterfaceRef) -> Option<ComponentIx> {
        match self.handled(&r.component, r.at.component) {
            Some((ci, _)) => Some(ci),
            None => self.component_index(&r.component),
        }
    }

    /// The component and data port a reference names: (component handle, port position).
    pub fn resolve_port(&self, r: &PortRef) -> Option<(ComponentIx, usize)> {
        if let Some((ci, c)) = self.handled(&r.component, r.at.component) {
            let pi = r.at.port as usize;
            if c.profile
                .data_ports
                .get(pi)
                .is_some_and(|p| name_of(&p.name) == r.port.as_str())
            {
                return Some((ci, pi));
            }
        }
        let ci = self.component_index(&r.component)?;
        let ports = &self[ci].profile.data_ports;
        let pi = member_at(ports.iter().map(|p| name_of(&p.name)), &r.port)?;
        Some((ci, pi))
    }

    /// The component, service port and interface a reference names: the component's handle
    /// and the positions of the port and the interface.
    pub fn resolve_interface(&self, r: &InterfaceRef) -> Option<(ComponentIx, usize, usize)> {
        if let Some((ci, c)) = self.handled(&r.component, r.at.component) {
            let (pi, ii) = (r.at.port as usize, r.at.interface as usize);
            if let Some(sp) = c.profile.service_ports.get(pi) {
                if name_of(&sp.name) == r.port.as_str()
                    && sp
                        .interfaces
                        .get(ii)
                        .is_some_and(|i| name_of(&i.name) == r.interface.as_str())
                {
                    return Some((ci, pi, ii));
                }
            }
        }
        let ci = self.component_index(&r.component)?;
        let sps = &self[ci].profile.service_ports;
        let pi = member_at(sps.iter().map(|p| name_of(&p.name)), &r.port)?;
        let ii = member_at(
            sps[pi].interfaces.iter().map(|i| name_of(&i.name)),
            &r.interface,
        )?;
        Some((ci, pi, ii))
    }

    /// The component and data port a reference names.
    pub fn port_of(&self, r: &PortRef) -> Option<(&Component, &crate::model::DataPort)> {
        let (ci, pi) = self.resolve_port(r)?;
        let c = &self[ci];
        Some((c, &c.profile.data_ports[pi]))
    }

    /// The component, service port and interface a reference names.
    pub fn interface_of(
        &self,
        r: &InterfaceRef,
    ) -> Option<(
        &Component,
        &crate::model::ServicePort,
        &crate::model::ServiceInterface,
    )> {
        let (ci, pi, ii) = self.resolve_interface(r)?;
        let c = &self[ci];
        let sp = &c.profile.service_ports[pi];
        Some((c, sp, &sp.interfaces[ii]))
    }

    /// Takes in the IDL read for this catalogue. Every struct, union, enum, typedef and
    /// exception reachable from a port type or an interface (through fields, union cases,
    /// typedefs, sequences, operation parameters and results) gets a data-type entry of its own
    /// (so a page: a nested `RTC::Time` is documented, not only the `RTC::TimedLong` a port
    /// names), and each type learns which types contain it. Their pages join the page list when
    /// it is made ([`Catalog::assemble`]).
    pub fn attach_idl(&mut self, idl: crate::idl::IdlSet) {
        use crate::idl::IdlDefinition;
        self.idl = idl;
        if self.idl.is_empty() {
            return;
        }
        // Every interface the input's own IDL defines has a page, whether a port uses it or
        // not: a suite's service API is mostly in IDL alone (issue #55).
        self.add_defined_interfaces();
        use named_types as named;
        fn refs(d: &IdlDefinition) -> Vec<String> {
            let mut out = Vec::new();
            match d {
                IdlDefinition::Struct(s) => s.fields.iter().for_each(|f| named(&f.ty, &mut out)),
                IdlDefinition::Exception(e) => e.fields.iter().for_each(|f| named(&f.ty, &mut out)),
                IdlDefinition::Union(u) => {
                    u.cases.iter().for_each(|c| named(&c.field.ty, &mut out))
                }
                IdlDefinition::Typedef(t) => named(&t.ty, &mut out),
                IdlDefinition::Interface(i) => {
                    for o in &i.operations {
                        if let Some(r) = &o.return_type {
                            named(r, &mut out);
                        }
                        o.params.iter().for_each(|p| named(&p.ty, &mut out));
                        o.raises.iter().for_each(|r| named(r, &mut out));
                    }
                    i.attributes.iter().for_each(|a| named(&a.ty, &mut out));
                }
                _ => {}
            }
            out
        }
        let documented = |d: &IdlDefinition| {
            matches!(
                d,
                IdlDefinition::Struct(_)
                    | IdlDefinition::Union(_)
                    | IdlDefinition::Enum(_)
                    | IdlDefinition::Typedef(_)
                    | IdlDefinition::Exception(_)
            )
        };
        // Breadth first from every port type and interface; `contains` maps a type to the
        // types holding it.
        let mut queue: std::collections::VecDeque<String> = self
            .data_types
            .iter()
            .map(|t| t.name.clone())
            .chain(self.interfaces.iter().map(|t| t.name.clone()))
            .collect();
        let mut seen: std::collections::BTreeSet<String> = queue.iter().cloned().collect();
        let mut contains: BTreeMap<String, Vec<String>> = BTreeMap::new();
        let mut found: Vec<String> = Vec::new();
        let mut bases: Vec<String> = Vec::new();
        while let Some(name) = queue.pop_front() {
            let Some(item) = self.idl.find(&name) else {
                continue;
            };
            let holder = canonical_type(item.definition.scoped_name());
            let holder_is_type = !matches!(item.definition, IdlDefinition::Interface(_));
            // An interface's bases get pages of their own (a provider implements their
            // operations too), and the types their operations use.
            if let IdlDefinition::Interface(i) = item.definition {
                for b in &i.bases {
                    let mut r = Vec::new();
                    named(b, &mut r);
                    let Some(base) = r.first().and_then(|r| self.idl.find(r)) else {
                        continue;
                    };
                    let scoped = canonical_type(base.definition.scoped_name());
                    if matches!(base.definition, IdlDefinition::Interface(_))
                        && seen.insert(scoped.clone())
                    {
                        bases.push(scoped.clone());
                        queue.push_back(scoped);
                    }
                }
            }
            for r in refs(item.definition) {
                let Some(target) = self.idl.find(&r) else {
                    continue;
                };
                if !documented(target.definition) {
                    continue;
                }
                let scoped = canonical_type(target.definition.scoped_name());
                if holder_is_type && scoped != holder {
                    contains
                        .entry(scoped.clone())
                        .or_default()
                        .push(holder.clone());
                }
                if seen.insert(scoped.clone()) {
                    found.push(scoped.clone());
                    queue.push_back(scoped);
                }
            }
        }
        let index = &self.type_index;
        add_unused(&mut self.data_types, found, |name| {
            index.contains_key(&canonical_type(name))
        });
        for t in &mut self.data_types {
            if let Some(mut by) = contains.remove(&t.name) {
                by.sort();
                by.dedup();
                t.contained_in = by;
            }
        }
        self.type_index = handle_map(&self.data_types, |t| t.name.clone());
        self.add_interfaces(bases);
        self.index_idl_uses();
    }

    /// Interface entries (no port uses them) for `names`: the base interfaces of interfaces
    /// with pages, the interfaces the input's IDL defines ([`Catalog::attach_idl`]).
    fn add_interfaces(&mut self, names: Vec<String>) {
        if names.is_empty() {
            return;
        }
        let index = &self.interface_index;
        add_unused(&mut self.interfaces, names, |name| index.contains_key(name));
        self.interface_index = handle_map(&self.interfaces, |t| t.name.clone());
    }

    /// Entries for the interfaces declared in the IDL files of the input and the sources (not
    /// those of the IDL path, an installation's `rtm/idl`, which get one when a port uses them).
    fn add_defined_interfaces(&mut self) {
        use crate::idl::IdlDefinition as D;
        fn walk(defs: &[D], out: &mut Vec<String>) {
            for d in defs {
                match d {
                    D::Module(m) => walk(&m.definitions, out),
                    D::Interface(i) => out.push(canonical_type(&i.scoped_name)),
                    _ => {}
                }
            }
        }
        let mut names = Vec::new();
        for f in self.idl.files.iter().filter(|f| !f.idl_path) {
            walk(&f.definitions, &mut names);
        }
        names.sort();
        names.dedup();
        self.add_interfaces(names);
    }

    /// Fills each data type's and interface's [`TypeEntry::used_by`]: the operations and
    /// attributes of the catalogue's interfaces naming it directly (a sequence of it counts; a
    /// struct holding it is its `contained_in`). One pass over the interfaces' members.
    fn index_idl_uses(&mut self) {
        use crate::idl::IdlDefinition;
        let mut data: Vec<Vec<IdlUse>> = vec![Vec::new(); self.data_types.len()];
        let mut ifaces: Vec<Vec<IdlUse>> = vec![Vec::new(); self.interfaces.len()];
        for t in &self.interfaces {
            let Some(item) = self.idl.find(&t.name) else {
                continue;
            };
            let IdlDefinition::Interface(i) = item.definition else {
                continue;
            };
            let mut add = |member: &str, role: IdlUseRole, parameter: Option<&str>, ty| {
                let mut names = Vec::new();
                named_types(ty, &mut names);
                for n in names {
                    let Some(target) = self.idl.find(&n) else {
                        continue;
                    };
                    let key = canonical_type(target.definition.scoped_name());
                    let list = match (self.type_index.get(&key), self.interface_index.get(&key)) {
                        (Some(ti), _) => &mut data[ti.get()],
                        (None, Some(ii)) => &mut ifaces[ii.get()],
                        (None, None) => continue,
                    };
                    let u = IdlUse {
                        interface: t.name.clone(),
                        member: member.to_string(),
                        role,
                        parameter: parameter.map(str::to_string),
                    };
                    if list.last() != Some(&u) {
                        list.push(u);
                    }
                }
            };
            for o in &i.operations {
                if let Some(r) = &o.return_type {
                    add(&o.name, IdlUseRole::Result, None, r);
                }
                for p in &o.params {
                    add(&o.name, IdlUseRole::Parameter, Some(&p.name), &p.ty);
                }
                for r in &o.raises {
                    add(&o.name, IdlUseRole::Raises, None, r);
                }
            }
            for a in &i.attributes {
                add(&a.name, IdlUseRole::Attribute, None, &a.ty);
                for r in &a.raises {
                    add(&a.name, IdlUseRole::Raises, None, r);
                }
            }
        }
        for (t, u) in self.data_types.iter_mut().zip(data) {
            t.used_by = u;
        }
        for (t, u) in self.interfaces.iter_mut().zip(ifaces) {
            t.used_by = u;
        }
    }

    /// The data type entry for any spelling of a type name.
    pub fn data_type(&self, name: &str) -> Option<&DataType> {
        self.data_type_index(name).map(|i| &self[i])
    }

    /// The handle of the data type of any spelling of a type name.
    pub fn data_type_index(&self, name: &str) -> Option<DataTypeIx> {
        self.type_index.get(&self.idl.canonical_name(name)).copied()
    }

    /// The interface entry for any spelling of an interface type name.
    pub fn interface(&self, name: &str) -> Option<&InterfaceType> {
        self.interface_index_of(name).map(|i| &self[i])
    }

    /// The handle of the interface of any spelling of an interface type name.
    pub fn interface_index_of(&self, name: &str) -> Option<InterfaceIx> {
        self.interface_index
            .get(&self.idl.canonical_name(name))
            .copied()
    }

    /// Ports of other components that can connect to data port `port` of `component`:
    /// out → in ports of the same type, in → out ports of the same type.
    pub fn data_port_peers(&self, component: ComponentIx, port: usize) -> PeerRefs<'_, PortRef> {
        let p = &self[component].profile.data_ports[port];
        let t = self.port_type(component, port);
        peers(&self.data_types, &self.peer_runs.data, t, port_slot(p))
    }

    /// Interfaces matching interface `interface` of service port `port`: required ↔ provided of
    /// the same type.
    pub fn interface_peers(
        &self,
        component: ComponentIx,
        port: usize,
        interface: usize,
    ) -> PeerRefs<'_, InterfaceRef> {
        let i = &self[component].profile.service_ports[port].interfaces[interface];
        let t = self.interface_type(component, port, interface);
        peers(
            &self.interfaces,
            &self.peer_runs.interfaces,
            t,
            interface_slot(i),
        )
    }

    /// Counts the components of each type's two directions of uses ([`PeerRuns`]), for
    /// [`Catalog::data_port_peers`] and [`Catalog::interface_peers`].
    fn index_peers(&mut self) {
        /// The two directions of each entry's uses, counted.
        fn counted<U: Uses>(
            entries: &[TypeEntry<U>],
            component: impl Fn(&U::Ref) -> Option<ComponentIx> + Copy,
        ) -> Vec<[Counted; 2]> {
            entries
                .iter()
                .map(|t| {
                    let [(_, a), (_, b), _] = t.uses.by_role();
                    [a, b].map(|refs| (refs.len(), component_runs(refs, component)))
                })
                .collect()
        }
        self.peer_runs = PeerRuns {
            data: counted(&self.data_types, |r| self.port_component(r)),
            interfaces: counted(&self.interfaces, |r| self.interface_component(r)),
        };
    }

    /// What the catalogue documents, for a summary line: `83 component profiles, 1 RT System
    /// and 66 IDL files` (kinds with none left out; `nothing` when empty).
    pub fn documented(&self) -> String {
        documented(
            self.components.len(),
            self.systems.len(),
            self.idl.files.len(),
        )
    }

    /// The data types and interfaces of the catalogue that no IDL file read defines (their
    /// pages show no definition), in catalogue order.
    pub fn undefined_types(&self) -> Vec<&str> {
        self.data_types
            .iter()
            .map(|t| t.name.as_str())
            .chain(self.interfaces.iter().map(|t| t.name.as_str()))
            .filter(|n| self.idl.find_all(n).is_empty())
            .collect()
    }

    /// The types and interfaces declared at module level in the IDL files `input_files`
    /// (paths as the IDL set names them: the files below the input, not those of
    /// `--idl-path`) that have no page: no data type or interface entry resolves to them, in
    /// file order. Constants, exceptions, forward and nested declarations are left out (they
    /// are shown where they are used).
    pub fn idl_on_no_page(&self, input_files: &HashSet<&str>) -> Vec<String> {
        use crate::idl::IdlDefinition as D;
        fn walk<'a>(defs: &'a [D], shown: &HashSet<&str>, out: &mut Vec<&'a str>) {
            for d in defs {
                match d {
                    D::Module(m) => walk(&m.definitions, shown, out),
                    D::Struct(_) | D::Union(_) | D::Enum(_) | D::Typedef(_) | D::Interface(_)
                        if !shown.contains(d.scoped_name()) =>
                    {
                        out.push(d.scoped_name());
                    }
                    _ => {}
                }
            }
        }
        let shown: HashSet<&str> = self
            .data_types
            .iter()
            .map(|t| t.name.as_str())
            .chain(self.interfaces.iter().map(|t| t.name.as_str()))
            .filter_map(|n| self.idl.find(n))
            .map(|item| item.definition.scoped_name())
            .collect();
        let mut out = Vec::new();
        for f in self
            .idl
            .files
            .iter()
            .filter(|f| input_files.contains(f.path.as_str()))
        {
            walk(&f.definitions, &shown, &mut out);
        }
        let mut seen = HashSet::new();
        out.into_iter()
            .filter(|n| seen.insert(*n))
            .map(str::to_string)
            .collect()
    }

    /// Counts of diagnostics by severity: (errors, warnings, infos).
    pub fn counts(&self) -> (usize, usize, usize) {
        let mut c = (0, 0, 0);
        for d in &self.diagnostics {
            match d.severity {
                Severity::Error => c.0 += 1,
                Severity::Warning => c.1 += 1,
                Severity::Info => c.2 += 1,
            }
        }
        c
    }
}

/// The named types an IDL type refers to (resolved scoped names), through sequences.
fn named_types(ty: &crate::idl::IdlType, out: &mut Vec<String>) {
    use crate::idl::IdlType;
    match ty {
        IdlType::Sequence { element, .. } => named_types(element, out),
        IdlType::Named { name, resolved } => {
            out.push(resolved.clone().unwrap_or_else(|| name.clone()))
        }
        _ => {}
    }
}

/// Adds to `entries` an entry that no port uses (its IDL definition gives it a page) for each of
/// `names` that `known` does not hold yet, with a free slug; then sorts the entries by name.
fn add_unused<U: Default>(
    entries: &mut Vec<TypeEntry<U>>,
    names: Vec<String>,
    known: impl Fn(&str) -> bool,
) {
    let mut taken = taken_slugs(entries.iter().map(|t| t.slug.as_str()));
    for name in names {
        if known(&name) {
            continue;
        }
        let slug = free_slug(&mut taken, &name);
        entries.push(TypeEntry {
            spellings: vec![name.clone()],
            name,
            slug,
            idl_files: Vec::new(),
            uses: U::default(),
            contained_in: Vec::new(),
            used_by: Vec::new(),
            stability: None,
        });
    }
    entries.sort_by(|a, b| a.name.cmp(&b.name));
}

/// The slugs of a page kind's pages, and `index` (its index page).
fn taken_slugs<'a>(slugs: impl Iterator<Item = &'a str>) -> std::collections::HashSet<String> {
    slugs
        .map(str::to_string)
        .chain(std::iter::once("index".to_string()))
        .collect()
}

/// The slug of `name` that no page in `taken` has yet (`name`, `name-2`, …), taken.
fn free_slug(taken: &mut std::collections::HashSet<String>, name: &str) -> String {
    claim(taken, slugify(name))
}

/// `base`, else the first of `base-2`, `base-3`, … that `taken` does not hold; added to `taken`.
fn claim(taken: &mut std::collections::HashSet<String>, base: String) -> String {
    let mut slug = base.clone();
    let mut n = 1;
    while !taken.insert(slug.clone()) {
        n += 1;
        slug = format!("{base}-{n}");
    }
    slug
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// The port types resolved when the catalogue is made are those the names give, on the
    /// example and (when present) the corpus; a catalogue not indexed answers by name too.
    #[test]
    fn resolved_port_types_are_those_of_the_names() {
        let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"));
        let opts = crate::build::LoadOptions::default();
        let mut typed = 0;
        for dir in [root.join("examples"), root.join("../shared/corpus")] {
            if !dir.is_dir() {
                continue;
            }
            let cat = crate::build::load(&dir, &opts).unwrap().catalog;
            let unindexed = Catalog {
                components: cat.components.clone(),
                data_types: cat.data_types.clone(),
                interfaces: cat.interfaces.clone(),
                idl: cat.idl.clone(),
                ..Catalog::default()
            }
            .with_lookups();
            for (ci, c) in Ix::enumerate(&cat.components) {
                for (pi, p) in c.profile.data_ports.iter().enumerate() {
                    let by_name =
                        crate::model::non_empty(&p.type_).and_then(|t| cat.data_type_index(t));
                    assert_eq!(cat.port_type(ci, pi), by_name, "{} {pi}", c.source);
                    assert_eq!(unindexed.port_type(ci, pi), by_name);
                    typed += usize::from(by_name.is_some());
                }
                for (si, sp) in c.profile.service_ports.iter().enumerate() {
                    for (ii, i) in sp.interfaces.iter().enumerate() {
                        let by_name = crate::model::non_empty(&i.type_)
                            .and_then(|t| cat.interface_index_of(t));
                        assert_eq!(cat.interface_type(ci, si, ii), by_name, "{}", c.source);
                        assert_eq!(unindexed.interface_type(ci, si, ii), by_name);
                        typed += usize::from(by_name.is_some());
                    }
                }
                assert_eq!(cat.port_type(ci, c.profile.data_ports.len()), None);
            }
        }
        assert!(typed > 20, "{typed} typed ports");
    }

    #[test]
    fn facet_keys_of_ascii_text_are_those_of_the_general_path() {
        let general = |s: &str| -> String {
            s.split_whitespace()
                .flat_map(|w| w.chars().flat_map(char::to_lowercase))
                .collect()
        };
        for s in [
            "",
            "AIST",
            "  Sugar Sweet\tRobotics \n",
            "a\u{b}b\u{c}c\rd",
            "MixedCASE_with-Punct.1",
            "Ünïcode Vendor",
            "画像 処理",
        ] {
            assert_eq!(facet_key(s), general(s), "{s:?}");
        }
    }

    #[test]
    fn handles_index_their_own_kind_and_say_none_past_u32() {
        let cat = Catalog::build(
            vec![
                xml_profile("A", "Cat", &[("DataOutPort", "RTC::TimedLong")], &[]),
                xml_profile("B", "Cat", &[("DataInPort", "RTC::TimedLong")], &[]),
            ],
            Vec::new(),
        );
        let handles: Vec<ComponentIx> = Ix::all(cat.components.len()).collect();
        assert_eq!(handles.len(), 2);
        for (ci, c) in Ix::enumerate(&cat.components) {
            assert_eq!(cat[ci].id, c.id);
            assert_eq!(cat.component_index(&c.id), Some(ci));
            assert_eq!(cat.component_page(ci).id, c.id.as_str());
        }
        let ti = cat.data_type_index("TimedLong").expect("type");
        assert_eq!(cat[ti].name, "RTC::TimedLong");
        assert_eq!(cat.type_page(TypeIx::Data(ti)), cat.data_type_page(ti));
        let (pc, pi) = cat.resolve_port(&cat[ti].uses.consumers[0]).expect("port");
        assert_eq!((cat[pc].profile.name(), pi), ("B", 0));
        let of = cat.category_of_each();
        assert_eq!((of[handles[0]], of[handles[1]]), (0, 0));
        assert_eq!(ComponentIx::new(usize::MAX), Ix::NONE);
        assert_eq!(Ix::<Component>::NONE.get(), usize::MAX);
        assert_eq!(serde_json::to_string(&handles[1]).expect("json"), "1");
    }

    /// A component `name` of `category` with data ports (port type, data type) and service
    /// ports of one interface each (direction, interface type), loaded from its RTC.xml.
    pub(crate) fn xml_profile(
        name: &str,
        category: &str,
        ports: &[(&str, &str)],
        services: &[(&str, &str)],
    ) -> LoadedProfile {
        let mut xml = format!(
            r#"<rtc:RtcProfile xmlns:rtc="http://www.openrtp.org/namespaces/rtc" xmlns:rtcExt="http://www.openrtp.org/namespaces/rtc_ext" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" rtc:id="RTC:V:{category}:{name}:1" rtc:version="0.2"><rtc:BasicInfo rtc:name="{name}" rtc:vendor="V" rtc:category="{category}" rtc:version="1"/>"#
        );
        for (i, (dir, ty)) in ports.iter().enumerate() {
            xml.push_str(&format!(
                r#"<rtc:DataPorts rtc:portType="{dir}" rtc:name="p{i}" rtc:type="{ty}"/>"#
            ));
        }
        for (i, (dir, ty)) in services.iter().enumerate() {
            xml.push_str(&format!(
                r#"<rtc:ServicePorts rtc:name="s{i}"><rtc:ServiceInterface rtc:direction="{dir}" rtc:name="i{i}" rtc:type="{ty}"/></rtc:ServicePorts>"#
            ));
        }
        xml.push_str("</rtc:RtcProfile>");
        let parsed = crate::parse::parse(
            crate::parse::SourceFormat::Xml,
            xml.as_bytes(),
            name,
            &crate::parse::Limits::default(),
        )
        .expect("profile");
        LoadedProfile {
            source: format!("{name}/RTC.xml"),
            format: crate::parse::SourceFormat::Xml,
            profile: Box::new(parsed.profile),
        }
    }

    #[test]
    fn slugs_are_safe() {
        assert_eq!(slugify("UsbCamera"), "usbcamera");
        assert_eq!(slugify("../../etc/passwd"), "etc-passwd");
        assert_eq!(slugify("RTC::TimedLong"), "rtc-timedlong");
        assert!(slugify("カメラ").starts_with("x-"));
        assert_ne!(slugify("カメラ"), slugify("レーザ"));
        assert!(slugify("..").starts_with("x-"));
        assert!(slugify(&"a".repeat(500)).len() <= 64);
    }

    #[test]
    fn unique_slugs_disambiguate_deterministically() {
        let items = vec![
            ("Cam".to_string(), "a/RTC.xml".to_string()),
            ("cam".to_string(), "b/RTC.xml".to_string()),
            ("Other".to_string(), "c/RTC.xml".to_string()),
        ];
        let s = unique_slugs(&items);
        assert_ne!(s[0], s[1]);
        assert!(s[0].starts_with("cam-") && s[1].starts_with("cam-"));
        assert_eq!(s[2], "other");
        assert_eq!(s, unique_slugs(&items));
        let reserved = unique_slugs(&[("Index".to_string(), "x".to_string())]);
        assert!(reserved[0].starts_with("index-"), "{reserved:?}");
    }
}
