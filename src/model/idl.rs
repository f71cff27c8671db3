//! The IDL document model: plain data, `Serialize + Deserialize` (camelCase), no I/O.
//!
//! One [`IdlFile`] per source file, holding its [`IdlDefinition`]s in source order (a module
//! reopened in the same file appears once per opening, as written). Every declaration carries
//! its name as written, its scoped name (`RTC::TimedLong`), its repository id
//! (`IDL:RTC/TimedLong:1.0`, after `#pragma prefix/ID/version`, `typeid`, `typeprefix`), the doc
//! comment attached to it, its position in the original file and that file's display path.

use crate::model::{is_false, Pos};
use serde::{Deserialize, Serialize};

/// Declares a kind of IDL declaration: the struct with its derives and, before the fields
/// written, the six every declaration starts with.
macro_rules! declaration {
    ($(#[$meta:meta])* pub struct $name:ident { $($fields:tt)* }) => {
        $(#[$meta])*
        #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
        #[serde(rename_all = "camelCase")]
        pub struct $name {
            /// The name as written (escape underscore removed).
            pub name: String,
            /// The scoped name without leading `::` (`RTC::TimedLong`).
            pub scoped_name: String,
            /// The repository id (`IDL:RTC/TimedLong:1.0`).
            pub repository_id: String,
            /// The doc comment attached to the declaration.
            #[serde(default, skip_serializing_if = "Option::is_none")]
            pub doc: Option<Box<IdlDoc>>,
            /// Where the declaration starts.
            pub pos: Pos,
            /// The display path of the file it is in.
            pub file: String,
            $($fields)*
        }
    };
}

/// `$value` of whichever declaration `$def` holds, bound to `$d` (every kind has the field).
macro_rules! each_kind {
    ($def:expr, $d:ident => $value:expr) => {
        match $def {
            IdlDefinition::Module($d) => $value,
            IdlDefinition::Struct($d) => $value,
            IdlDefinition::Union($d) => $value,
            IdlDefinition::Enum($d) => $value,
            IdlDefinition::Typedef($d) => $value,
            IdlDefinition::Const($d) => $value,
            IdlDefinition::Interface($d) => $value,
            IdlDefinition::Exception($d) => $value,
            IdlDefinition::Forward($d) => $value,
            IdlDefinition::Native($d) => $value,
            IdlDefinition::Skipped($d) => $value,
        }
    };
}

/// One IDL source file as read.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct IdlFile {
    /// The path as given (for display).
    pub path: String,
    /// The `[[source]]` repository the file was read from (none: the input directory).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub origin: Option<super::Origin>,
    /// Read from the IDL search path (`--idl-path`, e.g. an OpenRTM installation's `rtm/idl`),
    /// not from the input or a source: its interfaces get pages only when a port uses them
    /// (those of the input's own IDL always do).
    #[serde(default, skip_serializing_if = "is_false")]
    pub idl_path: bool,
    /// The encoding the bytes were decoded from: `UTF-8`, `EUC-JP` or `Shift_JIS`.
    pub encoding: String,
    /// The file's own documentation: a doc comment carrying `@file`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub doc: Option<Box<IdlDoc>>,
    /// `#include` directives met in active regions, in order.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub includes: Vec<IdlInclude>,
    /// Every active `#pragma`, in order (including ones rtcdoc does not interpret, such as
    /// `#pragma keylist`), so that nothing in the file is lost.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub pragmas: Vec<IdlPragma>,
    pub definitions: Vec<IdlDefinition>,
}

/// An `#include "name"` or `#include <name>`.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct IdlInclude {
    /// The name as written between the quotes or brackets.
    pub name: String,
    /// `<…>` rather than `"…"`.
    #[serde(default, skip_serializing_if = "is_false")]
    pub system: bool,
    /// The display path of the file it resolved to, if any.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub resolved: Option<String>,
    pub pos: Pos,
}

/// A `#pragma` line: its text after `#pragma`, trimmed.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct IdlPragma {
    pub text: String,
    pub pos: Pos,
}

/// One declaration.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "camelCase")]
pub enum IdlDefinition {
    Module(IdlModule),
    Struct(IdlStruct),
    Union(IdlUnion),
    Enum(IdlEnum),
    Typedef(IdlTypedef),
    Const(IdlConst),
    Interface(IdlInterface),
    Exception(IdlException),
    /// `interface X;`, `struct X;`, `union X;`.
    Forward(IdlForward),
    Native(IdlNative),
    /// A declaration rtcdoc does not model (valuetype, eventtype, component, home, …), skipped
    /// as a whole with an info diagnostic.
    Skipped(IdlSkipped),
}

impl IdlDefinition {
    /// The declared name (as written, escape underscore removed).
    pub fn name(&self) -> &str {
        each_kind!(self, d => &d.name)
    }
    /// The scoped name without leading `::` (`RTC::TimedLong`).
    pub fn scoped_name(&self) -> &str {
        each_kind!(self, d => &d.scoped_name)
    }
    /// The repository id (`IDL:RTC/TimedLong:1.0`); empty for modules' reopenings never.
    pub fn repository_id(&self) -> &str {
        each_kind!(self, d => &d.repository_id)
    }
    /// Where the declaration starts.
    pub fn pos(&self) -> Pos {
        each_kind!(self, d => d.pos)
    }
    /// The doc comment attached to the declaration.
    pub fn doc(&self) -> Option<&IdlDoc> {
        match self {
            IdlDefinition::Module(d) => d.doc.as_deref(),
            IdlDefinition::Struct(d) => d.doc.as_deref(),
            IdlDefinition::Union(d) => d.doc.as_deref(),
            IdlDefinition::Enum(d) => d.doc.as_deref(),
            IdlDefinition::Typedef(d) => d.doc.as_deref(),
            IdlDefinition::Const(d) => d.doc.as_deref(),
            IdlDefinition::Interface(d) => d.doc.as_deref(),
            IdlDefinition::Exception(d) => d.doc.as_deref(),
            IdlDefinition::Forward(d) => d.doc.as_deref(),
            IdlDefinition::Native(d) => d.doc.as_deref(),
            IdlDefinition::Skipped(_) => None,
        }
    }
    /// Nested definitions (modules, and types declared inside interfaces).
    pub fn children(&self) -> &[IdlDefinition] {
        match self {
            IdlDefinition::Module(m) => &m.definitions,
            IdlDefinition::Interface(i) => &i.definitions,
            _ => &[],
        }
    }
    /// A short word for the kind (`struct`, `interface`, …), as IDL spells it.
    pub fn kind_word(&self) -> &'static str {
        match self {
            IdlDefinition::Module(_) => "module",
            IdlDefinition::Struct(_) => "struct",
            IdlDefinition::Union(_) => "union",
            IdlDefinition::Enum(_) => "enum",
            IdlDefinition::Typedef(_) => "typedef",
            IdlDefinition::Const(_) => "const",
            IdlDefinition::Interface(_) => "interface",
            IdlDefinition::Exception(_) => "exception",
            IdlDefinition::Forward(_) => "forward",
            IdlDefinition::Native(_) => "native",
            IdlDefinition::Skipped(_) => "skipped",
        }
    }
}

declaration! {
    /// `module Name { … };`
    pub struct IdlModule {
        pub definitions: Vec<IdlDefinition>,
    }
}

declaration! {
    /// `struct Name { members };`
    pub struct IdlStruct {
        pub fields: Vec<IdlField>,
    }
}

/// A struct or exception member, or the element of a union case: `Type name[dims];`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct IdlField {
    pub name: String,
    #[serde(rename = "type")]
    pub ty: IdlType,
    /// Array dimensions (`double m[3][4]` → two).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub array: Vec<IdlBound>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub doc: Option<Box<IdlDoc>>,
    pub pos: Pos,
}

/// A bound or array size: the expression as written and its value when it evaluates.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct IdlBound {
    pub expr: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub value: Option<u64>,
}

declaration! {
    /// `union Name switch (Type) { case …: member; … };`
    pub struct IdlUnion {
        pub switch_type: IdlType,
        pub cases: Vec<IdlUnionCase>,
    }
}

/// One case of a union: its labels (expressions as written; `default` for the default label)
/// and the member it selects.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct IdlUnionCase {
    pub labels: Vec<String>,
    #[serde(default, skip_serializing_if = "is_false")]
    pub is_default: bool,
    pub field: IdlField,
}

declaration! {
    /// `enum Name { A, B };`
    pub struct IdlEnum {
        pub values: Vec<IdlEnumerator>,
    }
}

/// One enumerator with its doc comment.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct IdlEnumerator {
    pub name: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub doc: Option<Box<IdlDoc>>,
    pub pos: Pos,
}

declaration! {
    /// `typedef Type Name[dims];` (one entry per declarator).
    pub struct IdlTypedef {
        #[serde(rename = "type")]
        pub ty: IdlType,
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        pub array: Vec<IdlBound>,
    }
}

declaration! {
    /// `const Type Name = expression;`
    pub struct IdlConst {
        #[serde(rename = "type")]
        pub ty: IdlType,
        /// The expression as written (tokens joined).
        pub expr: String,
        /// Its value, when it evaluates in this file (a constant of another file is not followed).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pub value: Option<IdlConstValue>,
    }
}

/// An evaluated constant.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub enum IdlConstValue {
    Integer(i64),
    /// An integer above `i64::MAX` (an `unsigned long long`).
    Unsigned(u64),
    Float(f64),
    String(String),
    Char(String),
    Boolean(bool),
    /// An enumerator (`const Color c = RED;`): its scoped name.
    Enumerator(String),
}

declaration! {
    /// `interface Name : Bases { exports };`
    pub struct IdlInterface {
        /// `abstract` or `local`, when written.
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pub modifier: Option<String>,
        /// Base interfaces, as written and resolved.
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        pub bases: Vec<IdlType>,
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        pub attributes: Vec<IdlAttribute>,
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        pub operations: Vec<IdlOperation>,
        /// Types, constants and exceptions declared inside the interface.
        #[serde(default, skip_serializing_if = "Vec::is_empty")]
        pub definitions: Vec<IdlDefinition>,
    }
}

/// `[readonly] attribute Type name;`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct IdlAttribute {
    pub name: String,
    #[serde(rename = "type")]
    pub ty: IdlType,
    #[serde(default, skip_serializing_if = "is_false")]
    pub readonly: bool,
    /// `raises`, `getraises` and `setraises` exceptions (all listed together).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub raises: Vec<IdlType>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub doc: Option<Box<IdlDoc>>,
    pub pos: Pos,
}

/// `[oneway] ReturnType name(params) [raises (…)] [context (…)];`
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct IdlOperation {
    pub name: String,
    /// `None` for `void`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub return_type: Option<IdlType>,
    #[serde(default, skip_serializing_if = "is_false")]
    pub oneway: bool,
    pub params: Vec<IdlParam>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub raises: Vec<IdlType>,
    /// `context ("a", "b")` string literals.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub context: Vec<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub doc: Option<Box<IdlDoc>>,
    pub pos: Pos,
}

/// A parameter: direction, type and name.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct IdlParam {
    pub direction: IdlParamDirection,
    #[serde(rename = "type")]
    pub ty: IdlType,
    pub name: String,
    /// A trailing `///<` comment on the parameter.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub doc: Option<Box<IdlDoc>>,
    pub pos: Pos,
}

/// `in`, `out` or `inout`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum IdlParamDirection {
    In,
    Out,
    Inout,
}

declaration! {
    /// `exception Name { members };`
    pub struct IdlException {
        pub fields: Vec<IdlField>,
    }
}

declaration! {
    /// A forward declaration: `interface X;` (also `abstract`/`local`), `struct X;`, `union X;`.
    pub struct IdlForward {
        /// `interface`, `struct` or `union`.
        pub of: String,
    }
}

declaration! {
    /// `native Name;`
    pub struct IdlNative {
    }
}

/// A declaration skipped as a whole (`valuetype`, `eventtype`, `component`, `home`, `import`,
/// `porttype`, `connector`, …): its keyword and name, so that pages can at least list it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct IdlSkipped {
    pub keyword: String,
    /// The name after the keyword, when there is one.
    pub name: String,
    pub scoped_name: String,
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub repository_id: String,
    pub pos: Pos,
    pub file: String,
}

/// A type as written in a declaration.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "camelCase")]
pub enum IdlType {
    /// A basic type: `long`, `unsigned long long`, `double`, `octet`, `any`, `Object`, …
    Primitive { name: IdlPrimitive },
    /// `string`, `string<N>`, `wstring`, `wstring<N>`.
    #[serde(rename_all = "camelCase")]
    String {
        #[serde(default, skip_serializing_if = "is_false")]
        wide: bool,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        bound: Option<IdlBound>,
    },
    /// `sequence<T>` or `sequence<T, N>`.
    #[serde(rename_all = "camelCase")]
    Sequence {
        element: Box<IdlType>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        bound: Option<IdlBound>,
    },
    /// `fixed<digits, scale>` (bare `fixed` in a const type has neither).
    #[serde(rename_all = "camelCase")]
    Fixed {
        #[serde(default, skip_serializing_if = "Option::is_none")]
        digits: Option<IdlBound>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        scale: Option<IdlBound>,
    },
    /// A name of a declared type, as written (`Time`, `RTC::Time`, `::RTC::Time`) and the
    /// scoped name it resolved to by IDL scoping rules, when a definition was found.
    #[serde(rename_all = "camelCase")]
    Named {
        name: String,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        resolved: Option<String>,
    },
}

impl IdlType {
    /// The type as IDL writes it (`sequence<RTC::Time, 4>`, `unsigned long`).
    pub fn to_idl(&self) -> String {
        match self {
            IdlType::Primitive { name } => name.as_str().to_string(),
            IdlType::String { wide, bound } => {
                let w = if *wide { "wstring" } else { "string" };
                match bound {
                    Some(b) => format!("{w}<{}>", b.expr),
                    None => w.to_string(),
                }
            }
            IdlType::Sequence { element, bound } => match bound {
                Some(b) => format!("sequence<{}, {}>", element.to_idl(), b.expr),
                None => format!("sequence<{}>", element.to_idl()),
            },
            IdlType::Fixed { digits, scale } => match (digits, scale) {
                (Some(d), Some(s)) => format!("fixed<{}, {}>", d.expr, s.expr),
                _ => "fixed".to_string(),
            },
            IdlType::Named { name, .. } => name.clone(),
        }
    }
}

/// The basic types, serialized as IDL spells them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum IdlPrimitive {
    #[serde(rename = "short")]
    Short,
    #[serde(rename = "unsigned short")]
    UnsignedShort,
    #[serde(rename = "long")]
    Long,
    #[serde(rename = "unsigned long")]
    UnsignedLong,
    #[serde(rename = "long long")]
    LongLong,
    #[serde(rename = "unsigned long long")]
    UnsignedLongLong,
    #[serde(rename = "float")]
    Float,
    #[serde(rename = "double")]
    Double,
    #[serde(rename = "long double")]
    LongDouble,
    #[serde(rename = "char")]
    Char,
    #[serde(rename = "wchar")]
    Wchar,
    #[serde(rename = "boolean")]
    Boolean,
    #[serde(rename = "octet")]
    Octet,
    #[serde(rename = "any")]
    Any,
    #[serde(rename = "Object")]
    Object,
    #[serde(rename = "ValueBase")]
    ValueBase,
}

impl IdlPrimitive {
    pub fn as_str(self) -> &'static str {
        match self {
            IdlPrimitive::Short => "short",
            IdlPrimitive::UnsignedShort => "unsigned short",
            IdlPrimitive::Long => "long",
            IdlPrimitive::UnsignedLong => "unsigned long",
            IdlPrimitive::LongLong => "long long",
            IdlPrimitive::UnsignedLongLong => "unsigned long long",
            IdlPrimitive::Float => "float",
            IdlPrimitive::Double => "double",
            IdlPrimitive::LongDouble => "long double",
            IdlPrimitive::Char => "char",
            IdlPrimitive::Wchar => "wchar",
            IdlPrimitive::Boolean => "boolean",
            IdlPrimitive::Octet => "octet",
            IdlPrimitive::Any => "any",
            IdlPrimitive::Object => "Object",
            IdlPrimitive::ValueBase => "ValueBase",
        }
    }
}

/// A doc comment: its text (markers and leading `*` stripped — nothing else removed) and the
/// Doxygen structure found in it.
///
/// OpenRTM writes bilingual blocks `@if jp … @else … @endif`: the `@else` (English) part and
/// the text outside any `@if` make the main fields; each `@if LANG` part is parsed into
/// [`IdlDoc::languages`] (with the shared text), so a Japanese site can use it.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase", default)]
pub struct IdlDoc {
    /// The whole comment text.
    pub text: String,
    /// `@brief`, or else the first sentence of the text.
    #[serde(skip_serializing_if = "String::is_empty")]
    pub brief: String,
    /// The rest of the untagged text (and `@details`).
    #[serde(skip_serializing_if = "String::is_empty")]
    pub details: String,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub params: Vec<IdlDocParam>,
    /// `@return` / `@returns` / `@retval` text.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub returns: Option<String>,
    /// `@exception` / `@throw` / `@throws` / `@raise`: (name, text).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub exceptions: Vec<IdlDocParam>,
    /// `@note` / `@remark` / `@remarks`.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub notes: Vec<String>,
    /// `@see` / `@sa`.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub see: Vec<String>,
    /// `@section Title` / `@subsection` / `@par` blocks.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub sections: Vec<IdlDocSection>,
    /// Structural labels that only repeat what the declaration says (`@struct Pose2D`,
    /// `@interface X`, `@enum`, `@typedef`, `@file`, …): (tag, text).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub labels: Vec<IdlDocTag>,
    /// Every other tag, kept as (tag, text): `@author`, `@date`, `@pre`, `@post`, …
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub tags: Vec<IdlDocTag>,
    /// `@if LANG` parts, parsed the same way.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub languages: Vec<IdlDocLanguage>,
}

/// `@param[dir] name text` (also used for exceptions, without direction).
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase", default)]
pub struct IdlDocParam {
    pub name: String,
    /// `in`, `out` or `in,out` from `@param[in]`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub direction: Option<String>,
    pub text: String,
}

/// A tag and its text.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase", default)]
pub struct IdlDocTag {
    pub tag: String,
    pub text: String,
}

/// `@section Title` and the text up to the next tag.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase", default)]
pub struct IdlDocSection {
    pub title: String,
    pub text: String,
}

/// The part of a bilingual doc comment written under `@if LANG`.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "camelCase", default)]
pub struct IdlDocLanguage {
    pub lang: String,
    pub doc: Box<IdlDoc>,
}
