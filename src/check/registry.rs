//! The rule registry: every diagnostic code with its default severity, short name, rationale
//! (citing the spec section it comes from) and a generic hint. `rtcdoc check --explain CODE`
//! prints an entry; the SARIF output lists them as `tool.driver.rules`.

use crate::diagnostic::Severity;

/// One rule (or loader diagnostic) and its documentation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Rule {
    /// Stable code, e.g. `RTC101`. Codes are never reused.
    pub code: &'static str,
    pub severity: Severity,
    /// Short kebab-case name (`missing-required`).
    pub name: &'static str,
    /// One-line summary.
    pub summary: &'static str,
    /// Why the rule exists and what it checks exactly.
    pub explanation: &'static str,
    /// The spec section(s) it comes from (spec v0.2 numbering).
    pub spec: &'static str,
    /// What to do about a finding.
    pub hint: &'static str,
}

// Loader codes (RTC001–RTC019, produced by the readers, the walk and the catalogue).
pub const MALFORMED: &str = crate::diagnostic::codes::MALFORMED;
// IDL reader codes (RTC020–RTC029, produced and spelled by crate::idl).
pub const IDL_SYNTAX: &str = crate::idl::codes::SYNTAX;
pub const IDL_PREPROCESSOR: &str = crate::idl::codes::PREPROCESSOR;
pub const IDL_INCLUDE: &str = crate::idl::codes::INCLUDE;
pub const IDL_INCLUDE_CYCLE: &str = crate::idl::codes::INCLUDE_CYCLE;
pub const IDL_LIMIT: &str = crate::idl::codes::LIMIT;
pub const IDL_ENCODING: &str = crate::idl::codes::ENCODING;
pub const IDL_SKIPPED: &str = crate::idl::codes::SKIPPED;
pub const IDL_DIRECTIVE: &str = crate::idl::codes::DIRECTIVE;
pub const IDL_REDEFINITION: &str = crate::idl::codes::REDEFINITION;
pub const IDL_UNRESOLVED: &str = crate::idl::codes::UNRESOLVED;
// Schema level (spec chapter 6).
pub const MISSING_REQUIRED: &str = "RTC101";
pub const INVALID_ENUM: &str = "RTC102";
pub const EXECUTION_RATE: &str = "RTC103";
pub const MAX_INSTANCES: &str = "RTC104";
pub const DATE_TIME: &str = "RTC105";
pub const BOOLEAN: &str = "RTC106";
// Spec semantics (chapter 2).
pub const ID_FORMAT: &str = "RTC201";
pub const ID_MISMATCH: &str = "RTC202";
pub const VENDOR_VERSION_CHARS: &str = "RTC203";
pub const NAME_WHITESPACE: &str = "RTC204";
pub const DUPLICATE_PORT: &str = "RTC205";
pub const DUPLICATE_INTERFACE: &str = "RTC206";
pub const DUPLICATE_PARAMETER: &str = "RTC207";
pub const COMPONENT_KIND: &str = "RTC208";
pub const EXECUTION_TYPE: &str = "RTC209";
pub const INTERFACE_TYPE: &str = "RTC210";
pub const DATAFLOW_TYPE: &str = "RTC211";
pub const SUBSCRIPTION_TYPE: &str = "RTC212";
// Values and constraints.
pub const DEFAULT_TYPE: &str = "RTC301";
pub const UNKNOWN_TYPE: &str = "RTC302";
pub const CONSTRAINT_VIOLATED: &str = "RTC303";
pub const CONSTRAINT_LITERAL: &str = "RTC304";
pub const CONSTRAINT_MALFORMED: &str = "RTC305";
pub const PLACEHOLDER: &str = "RTC306";
pub const DATANAME_MISMATCH: &str = "RTC307";
// Catalogue level.
pub const UNPROVIDED_INTERFACE: &str = "RTC401";
pub const IDL_CONFLICT: &str = "RTC402";
pub const TYPE_NOT_IN_IDL: &str = "RTC403";
pub const IDL_FILE_NOT_FOUND: &str = "RTC404";
pub const IDL_FILE_MISMATCH: &str = "RTC405";
pub const IDL_DEFINITIONS_DIFFER: &str = "RTC406";
pub const USES_DEPRECATED: &str = "RTC407";
pub const STABILITY_MARK_INVALID: &str = crate::catalog::stability::MARK_INVALID;
// Document coverage.
pub const DOC_COMPONENT: &str = "RTC501";
pub const DOC_PORT: &str = "RTC502";
pub const DOC_INTERFACE: &str = "RTC503";
pub const DOC_CONFIGURATION: &str = "RTC504";
pub const DOC_ACTION: &str = "RTC505";
pub const DOC_IDL_FIELD: &str = "RTC506";
pub const DOC_IDL_ENUMERATOR: &str = "RTC507";
pub const DOC_IDL_OPERATION: &str = "RTC508";
// RT System profiles (issue 16).
pub const SYSTEM_UNKNOWN_PORT: &str = "RTC601";
pub const SYSTEM_TYPE_MISMATCH: &str = "RTC602";
pub const SYSTEM_COMPONENT_MISSING: &str = "RTC603";
pub const SYSTEM_VERSION_DRIFT: &str = "RTC604";
pub const SYSTEM_DUPLICATE_INSTANCE: &str = "RTC605";
pub const SYSTEM_CONFIG_INVALID: &str = "RTC606";
pub const SYSTEM_CONFIG_UNDECLARED: &str = "RTC607";
pub const SYSTEM_UNKNOWN_INSTANCE: &str = "RTC608";
pub const SYSTEM_DUPLICATE_CONNECTOR_ID: &str = "RTC609";
pub const SYSTEM_USES_DEPRECATED: &str = "RTC610";
// Component folders (issue 17).
pub const README_GENERATED: &str = crate::readme::GENERATED;
pub const README_UNREADABLE: &str = crate::readme::UNREADABLE;
pub const README_IMAGE: &str = crate::readme::IMAGE;
// Specification and implementation (issue 51).
pub const DRIFT_ONLY_IN_PROFILE: &str = crate::implementation::drift::codes::ONLY_IN_PROFILE;
pub const DRIFT_ONLY_IN_CODE: &str = crate::implementation::drift::codes::ONLY_IN_CODE;
pub const DRIFT_NAME_CASE: &str = crate::implementation::drift::codes::NAME_CASE;
pub const DRIFT_DATA_TYPE: &str = crate::implementation::drift::codes::DATA_TYPE;
pub const DRIFT_DIRECTION: &str = crate::implementation::drift::codes::DIRECTION;
pub const DRIFT_DEFAULT: &str = crate::implementation::drift::codes::DEFAULT;
pub const DRIFT_CALLBACK_UNMARKED: &str = crate::implementation::drift::codes::CALLBACK_UNMARKED;
pub const DRIFT_CALLBACK_MISSING: &str = crate::implementation::drift::codes::CALLBACK_MISSING;
pub const DRIFT_SPEC_VALUE: &str = crate::implementation::drift::codes::SPEC_VALUE;
pub const DRIFT_UNVERIFIED: &str = crate::implementation::drift::codes::UNVERIFIED;
pub const SOURCE_UNREADABLE: &str = crate::implementation::codes::UNREADABLE;
pub const SOURCE_RECOVERED: &str = crate::implementation::codes::RECOVERED;

use Severity::{Error, Info, Warning};

/// Every code, in order.
pub static RULES: &[Rule] = &[
    Rule {
        code: "RTC001",
        severity: Error,
        name: "malformed",
        summary: "the file is not well-formed XML or YAML",
        explanation: "The reader could not parse the file at all, so no rule could run on it. The position points at the first syntax error the parser met.",
        spec: "3.1 (UML-XML mapping), 3.2 (UML-YAML mapping)",
        hint: "fix the syntax error at the position shown (an unclosed tag, a bad indentation, a stray character)",
    },
    Rule {
        code: "RTC002",
        severity: Error,
        name: "too-large",
        summary: "the file is larger than the configured limit",
        explanation: "Profiles are small (a few kB). A file above the limit (16 MiB by default) is refused so that a hostile or mistaken input cannot exhaust memory.",
        spec: "— (robustness limit of rtcdoc)",
        hint: "raise --max-file-size if the file is genuine, or exclude it with --exclude",
    },
    Rule {
        code: "RTC003",
        severity: Error,
        name: "too-deep",
        summary: "elements or YAML collections nest deeper than the configured limit",
        explanation: "Real profiles nest about ten levels deep (constraints add a few). A deeper file is refused so that parsing stays bounded.",
        spec: "— (robustness limit of rtcdoc)",
        hint: "raise --max-depth if the nesting is genuine",
    },
    Rule {
        code: "RTC004",
        severity: Error,
        name: "entity",
        summary: "a DOCTYPE with entity declarations, or an undefined entity reference",
        explanation: "Entity declarations enable entity-expansion attacks (billion laughs) and external file reads; RTC profiles never need them (the XSD of chapter 6 declares no DTD).",
        spec: "6 (XML schema)",
        hint: "remove the DOCTYPE and write the text directly; use the predefined entities (&amp; &lt; &gt; &quot; &apos;) or numeric character references",
    },
    Rule {
        code: "RTC005",
        severity: Error,
        name: "encoding",
        summary: "bytes that are not valid in the declared (or default UTF-8) encoding",
        explanation: "The file declares (or defaults to) an encoding its bytes do not follow, so text would be garbled.",
        spec: "3.1.1 (XML basic types)",
        hint: "save the file as UTF-8, or declare the encoding it is really in (e.g. encoding=\"Shift_JIS\")",
    },
    Rule {
        code: "RTC006",
        severity: Warning,
        name: "unknown-value",
        summary: "an attribute, element or key the spec does not define",
        explanation: "The value is kept as an extra property and shown on the component page, but it is not part of the RTC Profile format, so other tools will ignore it. Often a typo of a known name.",
        spec: "6 (XSD), 7 (YAML schema)",
        hint: "check the spelling against the XSD / YAML schema; remove the value if it is not needed",
    },
    Rule {
        code: "RTC007",
        severity: Error,
        name: "io",
        summary: "the file could not be read",
        explanation: "An operating-system error (permissions, a vanished file) stopped reading the file.",
        spec: "—",
        hint: "check the file's permissions",
    },
    Rule {
        code: "RTC008",
        severity: Error,
        name: "yaml-structure",
        summary: "a YAML alias expands too much, or the YAML structure is not a profile",
        explanation: "Either aliases expand beyond the limit (an alias bomb) or the document does not have the `rtcProfile` structure of chapter 7.",
        spec: "7 (YAML schema), 3.2",
        hint: "write the profile with the keys of chapter 7 and without deeply nested aliases",
    },
    Rule {
        code: "RTC009",
        severity: Warning,
        name: "shape",
        summary: "a value has the wrong shape for its place",
        explanation: "A map or list where text is expected (or the reverse). The value is kept as an extra property.",
        spec: "6 (XSD), 7 (YAML schema)",
        hint: "write a plain value where the schema expects one",
    },
    Rule {
        code: "RTC010",
        severity: Warning,
        name: "duplicate-id",
        summary: "two profiles declare the same component id",
        explanation: "The id identifies a component uniquely (`RTC:<vendor>:<category>:<name>:<version>`). Two profiles with the same id are ambiguous for repositories and tools that look components up by id; rtcdoc renders both on separate pages. Reported by the catalogue for every profile involved. Not for the implementations of one component in different languages (`rtc:Language` `C++` and `Python`, which RTCBuilder generates from one specification with one id): rtcdoc tells them apart by their language (`RobotController (Python)`, and `diff` pairs them so); profiles of the same language, or without one, are still reported.",
        spec: "2.3.1.1 (id)",
        hint: "give each component its own id: change the name, category or version (and the id with it), or exclude a stale copy of the profile",
    },
    Rule {
        code: "RTC011",
        severity: Info,
        name: "empty-unknown",
        summary: "empty attributes or keys the spec does not define (one note per profile)",
        explanation: "Some writers (wasanbon) put many empty attributes the spec does not define on every node (`rtcDoc:license=\"\"` on a configuration doc, …). They carry no value: they are kept in the JSON as extra properties, not shown on the page, and summarised in this one note instead of one RTC006 warning each. A non-empty unknown value is still an RTC006 warning.",
        spec: "6 (XSD), 7 (YAML schema)",
        hint: "nothing to do: they carry no value (wasanbon writes them); remove them to tidy the profile",
    },
    Rule {
        code: "RTC012",
        severity: Warning,
        name: "not-a-profile",
        summary: "a file named like a profile cannot be read as one",
        explanation: "Files named `RTC.xml`, `RTC.yaml` or `*.rtc.xml` are component profiles by convention (RTCBuilder's backups `RTC.xml<timestamp>` are listed on their component's page instead, with the reason when one cannot be read). One that is empty, binary, not XML, has another root element or ends before its root is not documented; the warning says which, because it is usually a failed save or a file put in the wrong place, and skipping it silently would leave a component out of the catalogue unnoticed.",
        spec: "3.1 (XML mapping)",
        hint: "restore the profile from version control or RTCBuilder, or rename or exclude the file (`--exclude PATH`)",
    },
    Rule {
        code: "RTC013",
        severity: Warning,
        name: "orphan-backup",
        summary: "RTCBuilder backups whose RTC.xml is gone",
        explanation: "Every save in RTCBuilder keeps the previous profile beside the new one as `RTC.xml<yyyymmddhhmmss>`. rtcdoc reads such a backup as an older version of the `RTC.xml` in its folder, never as a component of its own (it is listed on that component's page). When a folder holds backups but no `RTC.xml`, the profile was deleted or renamed: the backups are not documented, and this warning (one per folder, at the newest backup) says so instead of dropping them silently.",
        spec: "3.1 (XML mapping); RTCBuilder's save behaviour",
        hint: "copy the newest backup to `RTC.xml` in its folder to document the component, or delete the backups",
    },
    Rule {
        code: "RTC014",
        severity: Warning,
        name: "duplicate-id-across-sources",
        summary: "two sources declare the same component id",
        explanation: "With `[[source]]` repositories in rtcdoc.toml, the same component id can come from two of them (or from one and the input directory): a fork, a vendored copy, two versions of one component. Both profiles are kept and documented on separate pages, and this warning on each names the source and the file of the others, so that the reader can tell which is which. It replaces RTC010 for those profiles.",
        spec: "5.2 (BasicInfo: the id identifies a component)",
        hint: "if they are the same component, document it from one source only (its `path`, or --exclude); else give each its own id",
    },
    Rule {
        code: "RTC015",
        severity: Info,
        name: "source-file-skipped",
        summary: "a symbolic link or submodule in a source repository is not followed",
        explanation: "Files of `[[source]]` repositories are read from git objects at the pinned commit, never from a checked-out work tree. A symbolic link (mode 120000) could point anywhere on the machine that builds, and a submodule is another repository at another commit: neither is followed, as a symbolic link in an input directory is not. This note names each such file that rtcdoc would otherwise have read (a profile, an IDL file, a README or an image), each submodule, and each link without an extension (it may stand for a folder of profiles; nothing behind it is read).",
        spec: "rtcdoc's reading of git repositories",
        hint: "commit the file or folder itself instead of a link; add a submodule's repository as a [[source]] of its own",
    },
    Rule {
        code: IDL_SYNTAX,
        severity: Error,
        name: "idl-syntax",
        summary: "an IDL file has a syntax error",
        explanation: "The IDL reader could not parse a declaration (a missing `;`, an unknown keyword, an unbalanced bracket, a malformed literal or constant expression such as a division by zero). The message says what was expected and what was found. The reader skips to the next `;` or to the `}` closing the current scope and goes on, so one bad declaration hides nothing else; the declarations read before the error in the same struct or enum are kept.",
        spec: "OMG IDL 3.5 chapter 7 (grammar)",
        hint: "fix the declaration at the position shown; compare with a working declaration such as `struct S { long x; };`",
    },
    Rule {
        code: IDL_PREPROCESSOR,
        severity: Error,
        name: "idl-preprocessor",
        summary: "a malformed or unbalanced preprocessor directive, or #error",
        explanation: "`#if`/`#ifdef`/`#ifndef` without `#endif` (or the reverse), `#else`/`#elif` out of place, an `#if` expression that does not parse, `#include` without a `\"file\"` or `<file>`, `#define` without a name, or an active `#error`. The rest of the file is read as if the directive were absent.",
        spec: "OMG IDL 3.5 §7.3 (preprocessing), C preprocessor",
        hint: "balance every #if/#ifdef/#ifndef with #endif and write directives as a C preprocessor expects",
    },
    Rule {
        code: IDL_INCLUDE,
        severity: Warning,
        name: "idl-include-not-found",
        summary: "an #include names no IDL file that was read",
        explanation: "An include is looked for as the project's own build (a C preprocessor with the IDL path as its -I folders) looks for it, and by file name too, since authors often include absolute paths of their own machines: relative to the including file, then by file name among the files of its own tree (the input directory, or its own [[source]]), then on the IDL path (--idl-path, idl-path), by path and then by file name; of several copies, the one nearest the including file, then the shallowest. Another source's files are not on the include path: a copy found only there is not used, and the warning names it. When none matches, the macros and include guards of that file are unknown, and the types it defines stay unresolved. A `<file>` include that is not found is a warning too (`<BasicDataType.idl>` is how labs include OpenRTM's types), except an ORB's own file (<orb.idl>, <corba.idl>, <ir.idl>, <TimeBase.idl>, <CosNaming.idl> and the like, or one in TAO's or omniORB's folders such as <tao/…>), which no project has among its IDL: that is an info only.",
        spec: "OMG IDL 3.5 §7.3 (#include)",
        hint: "add the directory holding the file with --idl-path (e.g. the OpenRTM installation's rtm/idl), or remove the include",
    },
    Rule {
        code: IDL_INCLUDE_CYCLE,
        severity: Error,
        name: "idl-include-cycle",
        summary: "IDL files include each other without include guards",
        explanation: "Following the includes leads back to a file that is still being read and has no include guard that is already defined. The include that closes the cycle is not followed; the error names the whole cycle once. A guarded cycle (`#ifndef X_IDL / #define X_IDL`) is harmless and not reported.",
        spec: "OMG IDL 3.5 §7.3 (#include)",
        hint: "add an include guard (#ifndef X / #define X / #endif) to the files, or remove one of the includes",
    },
    Rule {
        code: IDL_LIMIT,
        severity: Error,
        name: "idl-limit",
        summary: "an IDL file exceeds a limit against hostile input",
        explanation: "A file larger than the maximum file size (16 MiB by default), scopes, types, expressions or conditionals nesting deeper than the nesting limit (64), includes deeper than the include depth limit (32), or more tokens than the token limit (2,000,000, after macro expansion). The reader stops reading that part so that a hostile or broken file cannot exhaust memory or the stack.",
        spec: "— (robustness limit of rtcdoc)",
        hint: "raise the limit if the file is genuine, or exclude it",
    },
    Rule {
        code: IDL_ENCODING,
        severity: Info,
        name: "idl-encoding",
        summary: "an IDL file is not UTF-8",
        explanation: "IDL files declare no encoding, so it is detected: valid UTF-8 (with or without BOM), else EUC-JP, else Shift_JIS, whichever decodes without error (OpenRTM's own RTC.idl is EUC-JP). The info says which one was used. When no encoding decodes the bytes, they are read as EUC-JP with replacement characters and the diagnostic is a warning.",
        spec: "— (Japanese IDL files as found)",
        hint: "nothing to do if the text shows correctly; saving the file as UTF-8 avoids the guess",
    },
    Rule {
        code: IDL_SKIPPED,
        severity: Info,
        name: "idl-skipped",
        summary: "an IDL declaration that rtcdoc does not model was skipped",
        explanation: "valuetype, eventtype, component, home, porttype, connector and import declarations are read to their end and listed by name, but their contents are not modelled (RT components exchange structs and interfaces). Also reported: an #include inside a module, whose declarations rtcdoc reads as the included file's own, at global scope.",
        spec: "OMG IDL 3.5 §7.8–7.9 (value types), §7.17–7.20 (components)",
        hint: "nothing to do, unless a port type is one of these declarations",
    },
    Rule {
        code: IDL_DIRECTIVE,
        severity: Warning,
        name: "idl-directive-ignored",
        summary: "a preprocessor directive or pragma was ignored",
        explanation: "An unknown directive (`#frobnicate`), a function-like macro (`#define F(x) …`, whose uses are left as written), `#warning`, a malformed `#pragma prefix/ID/version`, or a `#pragma ID`/`#pragma version`/`typeid`/`typeprefix` naming a declaration the file does not have. Unknown pragmas (such as `#pragma keylist`) are kept silently.",
        spec: "OMG IDL 3.5 §7.3, CORBA 3 §10.7.5 (repository id pragmas)",
        hint: "remove the directive, or name a declaration of this file relative to the scope the pragma stands in",
    },
    Rule {
        code: IDL_REDEFINITION,
        severity: Warning,
        name: "idl-redefinition",
        summary: "one IDL file declares the same name twice",
        explanation: "Two declarations with the same scoped name in one file (modules may be reopened, and a forward declaration may precede its definition; anything else is an error for IDL compilers). Both are kept; lookups find the first.",
        spec: "OMG IDL 3.5 §7.20 (names and scoping)",
        hint: "rename one of the declarations, or remove the duplicate",
    },
    Rule {
        code: IDL_UNRESOLVED,
        severity: Info,
        name: "idl-unresolved-type",
        summary: "a type name that no IDL file read defines",
        explanation: "A field, parameter, typedef or base interface names a type that is not declared in any IDL file read, after IDL scoping rules (the enclosing scopes from the innermost outward, then the global scope). Reported once per name and file. Usually the file that defines it was not given, e.g. the OpenRTM IDL directory.",
        spec: "OMG IDL 3.5 §7.20 (names and scoping)",
        hint: "add the IDL file that defines the type with --idl-path",
    },
    Rule {
        code: MISSING_REQUIRED,
        severity: Error,
        name: "missing-required",
        summary: "a required attribute or element is missing or empty",
        explanation: "The XSD marks these attributes `use=\"required\"`: rtc_profile id and version; BasicInfo name, componentType, activityType, componentKind, category, executionType, vendor, version, creationDate, updateDate; each listed action's implemented; Configuration name, type and defaultValue; DataPort portType, name, type; ServicePort name; ServiceInterface name, type, direction; Parameter name; Language kind. An empty value counts as missing, except for defaultValue (an empty string is a valid default) — so empty port, interface and parameter names are reported here. A profile without Actions is also reported (Actions has multiplicity 1).",
        spec: "2.3.1–2.3.16 (multiplicities), 6.1 (RtcProfile_basic.xsd)",
        hint: "add the attribute (or the element, for `Actions`) with a meaningful value (RTCBuilder writes all of them)",
    },
    Rule {
        code: INVALID_ENUM,
        severity: Error,
        name: "invalid-enumeration",
        summary: "a value outside its enumeration",
        explanation: "componentType ∈ {STATIC, UNIQUE, COMMUTATIVE}; activityType ∈ {PERIODIC, SPORADIC, EVENTDRIVEN}; DataPort portType ∈ {DataInPort, DataOutPort} (EventPort is accepted for FSM components, as RTCBuilder 2.x writes); ServiceInterface direction ∈ {Provided, Required}; rtcExt:position ∈ {left, right, top, bottom}. direction and position are accepted in any case (real files write PROVIDED and LEFT); the others must be written exactly.",
        spec: "2.3.3, 2.3.4, 2.3.10, 2.3.14, 2.5.6; 6.1, 6.3",
        hint: "use one of the values listed in the message",
    },
    Rule {
        code: EXECUTION_RATE,
        severity: Error,
        name: "execution-rate",
        summary: "executionRate is not a number greater than 0",
        explanation: "executionRate is the frequency (Hz) of the periodic execution context, an xsd:double. A negative rate cannot drive a periodic execution context, and text that is not a number cannot be read at all: both are errors. A rate of 0 is only a warning: OpenRTM then takes the rate set at run time (rtc.conf `exec_cxt.periodic.rate`, else its default), which is how a suite whose rates are set per deployment writes its profiles. An externally triggered or event-driven context (executionType ExtTrig… or EventDriven…) runs at no rate, so 0 is accepted there without a finding; a negative rate is not.",
        spec: "2.3.2 (basic_info executionRate), 6.1",
        hint: "write the rate in Hz as a positive number, e.g. executionRate=\"1000.0\"",
    },
    Rule {
        code: MAX_INSTANCES,
        severity: Error,
        name: "max-instances",
        summary: "maxInstances is not a non-negative integer",
        explanation: "maxInstances (the largest number of instances the manager may create) is an xsd:integer; a negative count is meaningless.",
        spec: "2.3.2 (basic_info maxInstances), 6.1",
        hint: "write a whole number, e.g. maxInstances=\"1\"",
    },
    Rule {
        code: DATE_TIME,
        severity: Error,
        name: "date-time",
        summary: "creationDate or updateDate is not a valid xsd:dateTime",
        explanation: "Dates are xsd:dateTime: YYYY-MM-DDThh:mm:ss with optional fractional seconds and an optional offset (Z or ±hh:mm). The date must exist (no 2023-02-30) and the time be in range. YAML date maps are converted to this form by the reader.",
        spec: "2.3.2 (creationDate, updateDate), 6.1, 7",
        hint: "write e.g. 2014-02-04T17:15:06+09:00",
    },
    Rule {
        code: BOOLEAN,
        severity: Error,
        name: "boolean",
        summary: "a boolean attribute is not true/false/1/0",
        explanation: "implemented (actions), matchCase (comparisons) and saveProject are xsd:boolean, whose lexical forms are true, false, 1 and 0.",
        spec: "2.3.6 (action_status implemented), 2.3.30 (matchCase), 6.1, 6.3",
        hint: "write true or false",
    },
    Rule {
        code: ID_FORMAT,
        severity: Error,
        name: "id-format",
        summary: "the id is not `RTC:<vendor>:<category>:<name>:<version>`",
        explanation: "The component id has the fixed form `RTC:[vendor]:[category]:[component name]:[version]`: five parts separated by `:`, the first being `RTC`. The dotted form of RTCBuilder's first profile format and of OpenRTM-aist-Python's rtc-template, `RTC:[vendor].[category].[name]:[version]`, is read as the same parts and accepted (the JSON notes it in `writtenAs`).",
        spec: "2.3.1.1 (id)",
        hint: "write the id as `RTC:<vendor>:<category>:<name>:<version>` from the BasicInfo values",
    },
    Rule {
        code: ID_MISMATCH,
        severity: Warning,
        name: "id-mismatch",
        summary: "a part of the id disagrees with BasicInfo",
        explanation: "The id is built from BasicInfo's vendor, category, name and version; when a part differs (often after renaming a component, or when the id was written without the spaces the vendor has), tools that look components up by id and tools that use BasicInfo disagree. Each differing part is reported with both values.",
        spec: "2.3.1.1 (id), 2.3.2 (basic_info)",
        hint: "make the id and BasicInfo agree (RTCBuilder regenerates the id from BasicInfo)",
    },
    Rule {
        code: VENDOR_VERSION_CHARS,
        severity: Warning,
        name: "vendor-version-characters",
        summary: "vendor or version contains whitespace or `:`",
        explanation: "vendor and version are parts of the `:`-separated id; a `:` makes the id ambiguous and whitespace breaks naming-service paths and command lines that use the id.",
        spec: "2.3.1.1 (id), 2.3.2 (vendor, version)",
        hint: "remove what the message names, in BasicInfo and in the id (spaces: `AIST Lab` → `AISTLab`; a `:`); when vendor and version are swapped, swap them back",
    },
    Rule {
        code: NAME_WHITESPACE,
        severity: Error,
        name: "name-whitespace",
        summary: "a port, interface, configuration or parameter name contains whitespace",
        explanation: "Port, interface and configuration names become identifiers: port names in connector profiles (`comp.port`), configuration names in rtc.conf keys (`conf.default.name`), interface names in the naming service. Whitespace breaks all of them.",
        spec: "2.3.8, 2.3.9, 2.3.11, 2.3.13, 2.3.15 (name)",
        hint: "use an identifier without spaces, e.g. `target_velocity`",
    },
    Rule {
        code: DUPLICATE_PORT,
        severity: Error,
        name: "duplicate-port",
        summary: "two ports of the component have the same name",
        explanation: "Port names identify ports within a component; OpenRTM registers data and service ports in one namespace, so a data port and a service port may not share a name either.",
        spec: "2.3.9 (dataPort name), 2.3.11 (serviceport name)",
        hint: "rename one of the ports",
    },
    Rule {
        code: DUPLICATE_INTERFACE,
        severity: Error,
        name: "duplicate-interface",
        summary: "two interfaces of one service port have the same name",
        explanation: "Interface names identify the interfaces of a service port (`port.interface` in connector profiles).",
        spec: "2.3.13 (serviceinterface name)",
        hint: "rename one of the interfaces",
    },
    Rule {
        code: DUPLICATE_PARAMETER,
        severity: Error,
        name: "duplicate-parameter",
        summary: "two configuration parameters (or two system parameters) have the same name",
        explanation: "Configuration names are keys of the configuration set (`conf.default.<name>`); system parameter names are rtc.conf keys. A duplicate makes one of them unreachable.",
        spec: "2.3.8 (configuration name), 2.3.15 (parameter name)",
        hint: "rename or remove one of them",
    },
    Rule {
        code: COMPONENT_KIND,
        severity: Warning,
        name: "component-kind",
        summary: "componentKind is not a known kind",
        explanation: "Known kinds: the 5.1 names (DataFlowComponent, FiniteStateMachineComponent, DataFlowFiniteStateMachineComponent, FiniteStateMachineMultiModeComponent, DataFlowMultiModeComponent, DataFlowFiniteStateMachineMultiModeComponent, MultiModeComponent) and the DDC4RTC short forms (DataFlow, FiniteStateMachine, MultiMode, …); any case, comma-separated lists allowed.",
        spec: "2.3.2 (componentKind), 5.1",
        hint: "use one of the kinds of appendix 5.1, usually DataFlowComponent",
    },
    Rule {
        code: EXECUTION_TYPE,
        severity: Warning,
        name: "execution-type",
        summary: "executionType is not a known execution context",
        explanation: "Known: the 5.2 values (PERIODIC, EVENTDRIVEN, OTHER) and OpenRTM's execution context class names (PeriodicExecutionContext, ExtTrigExecutionContext, EventDrivenExecutionContext, OpenHRPExecutionContext, SimulatorExecutionContext, RTPreemptEC, MultilayerCompositeEC, PeriodicECSharedComposite, ArtExecutionContext, OpenHRP, …); any case.",
        spec: "2.3.2 (executionType), 5.2, 5.4",
        hint: "use PeriodicExecutionContext (or another execution context class OpenRTM provides)",
    },
    Rule {
        code: INTERFACE_TYPE,
        severity: Warning,
        name: "interface-type",
        summary: "a data port's interfaceType is not a known transport",
        explanation: "Known: corba_cdr, data_service, shared_memory, direct (and CorbaPort, which old RTCBuilder versions wrote); any case, comma-separated lists allowed, empty = unspecified.",
        spec: "2.3.9 (interfaceType), OpenRTM glossary",
        hint: "use corba_cdr unless the component needs another transport",
    },
    Rule {
        code: DATAFLOW_TYPE,
        severity: Warning,
        name: "dataflow-type",
        summary: "a data port's dataflowType is not push or pull",
        explanation: "Known: push, pull; any case, comma-separated lists allowed (Push,Pull), empty = unspecified.",
        spec: "2.3.9 (dataflowType), OpenRTM glossary",
        hint: "use push, pull or push,pull",
    },
    Rule {
        code: SUBSCRIPTION_TYPE,
        severity: Warning,
        name: "subscription-type",
        summary: "a data port's subscriptionType is not flush, new or periodic",
        explanation: "Known: flush, new, periodic; any case, comma-separated lists allowed (New,Periodic), empty = unspecified. An in-port (DataInPort, EventPort) may also say Any: it is what OpenRTM's in-ports report (an in-port has no publisher and takes a connection of every subscription type) and what RTSystemEditor saves. An out-port's publisher is flush, new or periodic, so Any on an out-port is reported.",
        spec: "2.3.9 (subscriptionType), OpenRTM glossary",
        hint: "use flush, new or periodic (or Any on an in-port)",
    },
    Rule {
        code: DEFAULT_TYPE,
        severity: Error,
        name: "default-value-type",
        summary: "a configuration's defaultValue does not parse for its type",
        explanation: "The default value is what the component starts with; OpenRTM converts it to the declared type at activation and fails (or silently uses 0) when it cannot. Types: short, long, int, long long and their unsigned variants (range-checked), octet, float, double, boolean (true/false, 1/0, yes/no, on/off), char (one character), string; `vector<T>`, `std::vector<T>`, `sequence<T>` and `T[]` take comma-separated elements.",
        spec: "2.3.8 (configuration type, defaultValue)",
        hint: "write a value of the declared type (or change the type)",
    },
    Rule {
        code: UNKNOWN_TYPE,
        severity: Info,
        name: "unknown-configuration-type",
        summary: "a configuration type rtcdoc cannot check",
        explanation: "The type is not one of the basic C++/IDL types or a vector of one (a user struct, an enum, a typo), so its default value and constraint literals are not checked.",
        spec: "2.3.8 (configuration type)",
        hint: "nothing to do if the type is genuine; otherwise fix its spelling",
    },
    Rule {
        code: CONSTRAINT_VIOLATED,
        severity: Error,
        name: "constraint-violated",
        summary: "a configuration's defaultValue does not satisfy its constraint",
        explanation: "The whole constraint tree is evaluated: comparisons (numeric when the type is numeric, string otherwise, matchCase absent = case-sensitive), like patterns with their wildCard/singleChar/escapeChar, between (inclusive), and/or/not, null (= empty), list constraints item by item over vector elements and hash constraints over key:value pairs. A default that its own constraint forbids is a contradiction tools such as RTSystemEditor will reject.",
        spec: "2.3.17–2.3.41 (constraints), 8 (samples)",
        hint: "change the default value or widen the constraint",
    },
    Rule {
        code: CONSTRAINT_LITERAL,
        severity: Error,
        name: "constraint-literal",
        summary: "a constraint literal does not parse for the configuration's type",
        explanation: "A literal or boundary of a numeric or boolean configuration must be a value of that type, or the comparison is meaningless (`x < ten`).",
        spec: "2.3.30 (binary comparison literal), 2.3.39 (between boundaries), 2.3.41 (literal)",
        hint: "write the literal as a value of the configuration's type",
    },
    Rule {
        code: CONSTRAINT_MALFORMED,
        severity: Warning,
        name: "constraint-malformed",
        summary: "a constraint is malformed or cannot be evaluated",
        explanation: "An empty constraint, an and/or without operands, a comparison without literal, a between without a boundary or with lower > upper, a hash item without key, or a hash constraint over a value that is not key:value pairs. The constraint cannot be (fully) checked.",
        spec: "2.3.17–2.3.41, 6.1 (constraint_type)",
        hint: "complete the constraint (RTCBuilder's constraint editor writes well-formed ones)",
    },
    Rule {
        code: PLACEHOLDER,
        severity: Info,
        name: "placeholder",
        summary: "a value is a placeholder RTCBuilder left unfilled",
        explanation: "RTCBuilder pre-fills fields with placeholders until the user edits them: the constraints `conf_constraint` (configuration) and `dp_constraint` (data port), vendor `VenderName`, category `Category`, name `ModuleName`, description `ModuleDescription`, and `$`-variables such as `$VenderName`. They are kept in the JSON as written, but a placeholder constraint is neither evaluated (no RTC303/RTC304) nor rendered, and a placeholder description does not count as documentation (RTC501).",
        spec: "2.3.2 (basic_info), 2.3.17 (constraint)",
        hint: "fill the field in RTCBuilder (or remove the placeholder constraint)",
    },
    Rule {
        code: DATANAME_MISMATCH,
        severity: Warning,
        name: "dataname-mismatch",
        summary: "a configuration's documentation names another parameter of the component",
        explanation: "RTCBuilder's documentation of a configuration parameter carries the name of the data it describes (`rtcDoc:dataname`): the parameter's own name or a label for people (`wheel base`, `画像幅`). When it is the name of *another* parameter of the component, the documentation was copied from that parameter and not updated (real profiles document `dir_lf0` under `dir_rf1`): the description, unit and range shown for the parameter may belong to the other one (or, as often, only the data name was left unchanged).",
        spec: "2.4.4 (configuration documentation: dataname)",
        hint: "set the documentation's data name to the parameter's own name, and check that its description, unit and range are this parameter's",
    },
    Rule {
        code: UNPROVIDED_INTERFACE,
        severity: Info,
        name: "unprovided-interface",
        summary: "a required service interface that no component in the catalogue provides",
        explanation: "A Required interface must be connected to a Provided one of the same type to work. Nothing in this catalogue provides it — fine if it comes from elsewhere, but worth knowing.",
        spec: "2.3.13, 2.3.14 (interface_direction)",
        hint: "add the providing component to the catalogue, or ignore if it is provided outside it",
    },
    Rule {
        code: IDL_CONFLICT,
        severity: Warning,
        name: "idl-conflict",
        summary: "one data type name is used with different IDL files",
        explanation: "Data ports of the same type should come from the same IDL definition; two different IDL file names for one type usually mean two incompatible definitions under one name. File names are compared, not full paths (IDL paths are often absolute Windows paths).",
        spec: "2.3.9 (dataPort type, idlFile)",
        hint: "use one IDL file for the type, or rename one of the types",
    },
    Rule {
        code: TYPE_NOT_IN_IDL,
        severity: Warning,
        name: "type-not-in-idl",
        summary: "a port type is defined in no IDL file read",
        explanation: "The page of a data type or interface shows its fields or operations only when an IDL file defines it. Reported once per type, at the first port that uses it, when IDL files were read: a warning when the IDL read declares the type's module (the type is missing from its own files, or its name is misspelt), an info when it does not, or when the type is one of OpenRTM's own `RTC` types (the type's IDL — often OpenRTM's — was not given; a project's IDL may add to module `RTC`). A catalogue without any IDL gets no such finding. In both cases the type's page says that no IDL file defines it and where the definition would come from, and `check` (and `build`) name the undefined types once in a `note:` line at default verbosity. When the IDL read defines a type of the same last name in another module (`Img::CameraCaptureService` for `OpenHRP::CameraCaptureService`), or of a last name a few letters apart (case ignored), the hint names up to three of them first (`did you mean …?`).",
        spec: "2.3.9 (dataPort type, idlFile), 2.3.11 (serviceInterface type, idlFile)",
        hint: "put the IDL file that defines the type below the input, or pass `--idl-path DIR` (e.g. an OpenRTM installation's `rtm/idl`)",
    },
    Rule {
        code: IDL_FILE_NOT_FOUND,
        severity: Warning,
        name: "idl-file-not-found",
        summary: "a port's idlFile names no IDL file that was read",
        explanation: "`idlFile` is usually an absolute path on the author's machine, so it is matched by file name among the IDL files read (below the input and on the IDL path). When the port's type was read from another file but no file of the named one's name was read, the `idlFile` is either misnamed (code generated from the profile includes the named file) or names a file that was not given: the message names the file that defines the type. A type no IDL file read defines is RTC403 instead. Not reported when no IDL was read at all.",
        spec: "2.3.9 (dataPort idlFile), 2.3.11 (serviceInterface idlFile)",
        hint: "set `idlFile` to the file that defines the type (the message names it), or add the named IDL file below the input or pass `--idl-path DIR`",
    },
    Rule {
        code: IDL_FILE_MISMATCH,
        severity: Warning,
        name: "idl-file-mismatch",
        summary: "a port type is defined in another IDL file than its idlFile says",
        explanation: "The type was found, but only in files with another name than the port's `idlFile`: code generated from the profile includes the named file and will not find the type there.",
        spec: "2.3.9 (dataPort idlFile), 2.3.11 (serviceInterface idlFile)",
        hint: "set `idlFile` to the file that defines the type",
    },
    Rule {
        code: IDL_DEFINITIONS_DIFFER,
        severity: Warning,
        name: "idl-definitions-differ",
        summary: "one type name has different definitions in two IDL files",
        explanation: "Repositories often carry their own copies of OpenRTM's IDL files. Equal copies are one type; copies whose definitions of a type differ (a field added, retyped or reordered) describe incompatible data under one name, since CDR is positional. Reported at the second definition, naming the first.",
        spec: "OMG IDL 3.5 §7.19 (names and scoping)",
        hint: "keep one definition (delete or update the stale copy), or rename one of the types",
    },
    Rule {
        code: USES_DEPRECATED,
        severity: Warning,
        name: "uses-deprecated",
        summary: "a port uses a deprecated data type or service interface",
        explanation: "A data type or service interface can be marked deprecated in rtcdoc.toml (`[stability.\"Img::OldImage\"] status = \"deprecated\"`, with `since`, `replacement` and `note`). Each data port carrying a deprecated data type and each service interface (provided or required) of a deprecated interface type is reported at the port or interface, with the version it is deprecated since, its replacement and the note. A component that is itself deprecated is shown so on its page; an RT System instance of it is RTC610.",
        spec: "rtcdoc (stability marks; not in the RTC Profile spec)",
        hint: "change the type to the replacement the stability mark names, or keep it knowingly until it is removed",
    },
    Rule {
        code: STABILITY_MARK_INVALID,
        severity: Warning,
        name: "stability-mark-invalid",
        summary: "a stability mark that marks nothing: an unknown status, or a key naming nothing",
        explanation: "A component's profile marks it with the BasicInfo property `rtcdoc.stability` (`experimental`, `stable` or `deprecated`, any case); another value is reported at the property and the component has no mark. A `[stability]` key of rtcdoc.toml names a component (its id or name), a data type or a service interface (its scoped name, any spelling the profiles use, or a definition of the IDL files read); a key that names none of them is reported at the key, with the nearest name. An unknown status in rtcdoc.toml is an error when the file is read.",
        spec: "rtcdoc (stability marks; not in the RTC Profile spec)",
        hint: "write the status as experimental, stable or deprecated, and name an entry of the catalogue",
    },
    Rule {
        code: DOC_COMPONENT,
        severity: Info,
        name: "doc-component",
        summary: "the component has no description",
        explanation: "The description is the first thing readers of the catalogue see. Either BasicInfo's `description` (spec 2.3.2) or the Document Profile's (2.4.1) documents the component; this fires only when neither is written (a placeholder such as `ModuleDescription` does not count).",
        spec: "2.3.2 (basic_info description), 2.4.1 (doc_basic description)",
        hint: "describe what the component does in BasicInfo description (or rtcDoc:Doc description)",
    },
    Rule {
        code: DOC_PORT,
        severity: Info,
        name: "doc-port",
        summary: "a data or service port has no description",
        explanation: "Port descriptions say what flows through a port; without them the catalogue shows only a type name.",
        spec: "2.4.4 (doc_dataport), 2.4.5 (doc_serviceport)",
        hint: "add rtcDoc:Doc description to the port",
    },
    Rule {
        code: DOC_INTERFACE,
        severity: Info,
        name: "doc-interface",
        summary: "a service interface has no description",
        explanation: "Interface descriptions say what a service offers or needs.",
        spec: "2.4.6 (doc_serviceinterface)",
        hint: "add rtcDoc:Doc description to the interface",
    },
    Rule {
        code: DOC_CONFIGURATION,
        severity: Info,
        name: "doc-configuration",
        summary: "a configuration parameter has no description",
        explanation: "Configuration descriptions tell operators what a parameter changes.",
        spec: "2.4.3 (doc_configuration)",
        hint: "add rtcDoc:Doc description to the configuration",
    },
    Rule {
        code: DOC_ACTION,
        severity: Info,
        name: "doc-action",
        summary: "an implemented action has no description",
        explanation: "Implemented callbacks are the component's behaviour; their descriptions document what happens on activation, execution, error …",
        spec: "2.4.2 (doc_action)",
        hint: "add rtcDoc:Doc description to the action",
    },
    Rule {
        code: DOC_IDL_FIELD,
        severity: Info,
        name: "doc-idl-field",
        summary: "a field of an IDL struct, exception or union the pages show has no doc comment",
        explanation: "The type pages show every field of a port's data type and of the types it contains, with its doc comment: the unit, frame and range of a value live there, not in the profile. Counted (in the documentation coverage too) for every struct, exception and union that has a page: those a port of the catalogue reaches, or an interface of the input's IDL, through fields, sequences, typedefs and the operations of the interfaces; a type defined in several files counts once. A comment documents a field when it is a doc comment: `/** … */` or `/*! … */` before it, `///` lines before it, or `///<` / `//!<` after it on its line (also a plain `///` after its `;` on its line, which rtcdoc reads as `///<`, as its writer meant; Doxygen would give it to the next field, so write `///<` where Doxygen reads the IDL itself). Plain `//` and `/* */` comments are not documentation (Doxygen ignores them too).",
        spec: "— (documentation coverage; Doxygen doc-comment syntax)",
        hint: "add a doc comment to the field: `///< what it holds, in which unit`",
    },
    Rule {
        code: DOC_IDL_ENUMERATOR,
        severity: Info,
        name: "doc-idl-enumerator",
        summary: "a value of an IDL enum the pages show has no doc comment",
        explanation: "An enum's values are what a reader must choose between or interpret; the type page lists them with their doc comments. Counted for every enum that has a page (a port of the catalogue reaches it directly, through fields, or through the operations of an interface with a page), once per enum, like the fields of RTC506.",
        spec: "— (documentation coverage; Doxygen doc-comment syntax)",
        hint: "add a doc comment to the value: `VALUE, ///< what it means`",
    },
    Rule {
        code: DOC_IDL_OPERATION,
        severity: Info,
        name: "doc-idl-operation",
        summary: "an operation or attribute of an IDL interface the pages show has no doc comment",
        explanation: "The interface page lists every operation with its parameters, result and exceptions, and every attribute; the doc comment (with `@param` and `@return`) is what tells a caller what the operation does. Counted for every service interface that has a page — those a port of the catalogue names, every one the input's IDL defines — and for their base interfaces, once each.",
        spec: "— (documentation coverage; Doxygen doc-comment syntax)",
        hint: "add a doc comment before the operation: `/** @brief … @param name … @return … */`",
    },
    Rule {
        code: SYSTEM_UNKNOWN_PORT,
        severity: Warning,
        name: "system-unknown-port",
        summary: "a connector end names a port the component does not have",
        explanation: "A connector of an RT System profile joins a port of one instance to a port of another. When the instance's component profile is in the catalogue and has no data or service port of that name (RTSystemEditor's `Instance0.port` and the plain `port` are both read), the connector cannot be restored: the port was renamed or removed since the system was saved, or the system was saved against another version of the component. When the component is not in the catalogue, the ports the system file lists for the instance are the reference: a connector end naming none of them is a misspelt or stale end.",
        spec: "RtsProfile schema (DataPortConnectors, ServicePortConnectors: sourceDataPort/targetDataPort portName), spec 10.4",
        hint: "reconnect the port in RTSystemEditor and save the system again, or restore the port in the component profile",
    },
    Rule {
        code: SYSTEM_TYPE_MISMATCH,
        severity: Error,
        name: "system-type-mismatch",
        summary: "a data connector's type differs from the types of its ports",
        explanation: "OpenRTM connects a data out-port to an in-port only when both carry the same data type, and a data port connector records that type (`dataType`, often as a repository id such as `IDL:RTC/TimedLong:1.0`). Types are compared by their scoped IDL names, so `TimedLong`, `RTC::TimedLong` and the repository id are one. Reported when the connector's type differs from the type of its source or target port in the component profiles of the catalogue (for a component not in the catalogue, the type the system file records for the port, RTSystemEditor's `dataport.data_type`), or the two ports carry different types.",
        spec: "RtsProfile schema (DataPortConnectors dataType), spec 2.3.9 (dataPort type)",
        hint: "connect ports of the same data type, or correct the connector's dataType",
    },
    Rule {
        code: SYSTEM_COMPONENT_MISSING,
        severity: Info,
        name: "system-component-missing",
        summary: "an instance's component is not in the catalogue",
        explanation: "An instance names its component by the `RTC:vendor:category:name:version` id of the component's profile. No component profile of the input has that vendor, category and name (nor, for a damaged category, that vendor and name alone), so the system page cannot link the instance, and its ports and configuration are not checked. An id whose name is the instance's (`RTC:AIST:Controller:RobotController0:1.0.0`, as Choreonoid saves systems) gets a hint naming the component of that vendor and category whose name is the id's name without its trailing number, when the input has one.",
        spec: "RtsProfile schema (Components id), spec 2.3.1 (id)",
        hint: "add the component's RTC.xml below the input, or correct the instance's component id",
    },
    Rule {
        code: SYSTEM_VERSION_DRIFT,
        severity: Warning,
        name: "system-version-drift",
        summary: "an instance names another version of its component than the catalogue has",
        explanation: "The instance's component id ends with a version; the component profile of the catalogue with the same vendor, category and name has another. The system was saved against another release of the component: its ports and configuration may have changed since.",
        spec: "RtsProfile schema (Components id), spec 2.3.2 (basic_info version)",
        hint: "save the system again with the current component, or document the component version the system needs",
    },
    Rule {
        code: SYSTEM_DUPLICATE_INSTANCE,
        severity: Error,
        name: "system-duplicate-instance",
        summary: "two instances of a system have the same instance name",
        explanation: "Connectors, orders, groups and execution-context participants name instances by `instanceName`; two instances with one name make every such reference ambiguous, and the naming service registers only one of them.",
        spec: "RtsProfile schema (Components instanceName)",
        hint: "give each instance its own instanceName",
    },
    Rule {
        code: SYSTEM_CONFIG_INVALID,
        severity: Error,
        name: "system-configuration-invalid",
        summary: "a system's configuration value is not valid for the component's parameter",
        explanation: "A configuration set of an instance gives a value to a parameter the component declares. The value is checked as a default value is (RTC301, RTC303): it must parse for the parameter's type and satisfy its constraint. The editor's own sets (`__widget__`, `__constraints__`, any `__name__`) are not configuration and are not checked.",
        spec: "RtsProfile schema (ConfigurationSets, ConfigurationData), spec 2.3.8 (configuration), 2.3.17–2.3.41 (constraints)",
        hint: "give a value of the parameter's type within its constraint",
    },
    Rule {
        code: SYSTEM_CONFIG_UNDECLARED,
        severity: Warning,
        name: "system-configuration-undeclared",
        summary: "a system configures a parameter the component does not declare",
        explanation: "A configuration set of an instance names a parameter that the component profile of the catalogue does not have: it is ignored at run time (a renamed or removed parameter, or a typo).",
        spec: "RtsProfile schema (ConfigurationData name), spec 2.3.8 (configuration name)",
        hint: "rename the value to a declared parameter, or remove it",
    },
    Rule {
        code: SYSTEM_UNKNOWN_INSTANCE,
        severity: Error,
        name: "system-unknown-instance",
        summary: "a connector end names no instance of the system",
        explanation: "Each end of a connector names its instance by `instanceName`; no instance of the system has that name, so the connector joins nothing.",
        spec: "RtsProfile schema (sourceDataPort, targetDataPort, sourceServicePort, targetServicePort instanceName)",
        hint: "name an instance of the system, or remove the connector",
    },
    Rule {
        code: SYSTEM_DUPLICATE_CONNECTOR_ID,
        severity: Warning,
        name: "system-duplicate-connector-id",
        summary: "two connectors of a system have the same connector id",
        explanation: "A port keeps its connections by connector id: OpenRTM refuses to connect a port that already has a connector of the id given (RTSystemEditor's copy and paste leaves such twins), and tools that key connectors by id (`rtcdoc diff` among them) must tell the twins apart by their ends.",
        spec: "RtsProfile schema (DataPortConnectors, ServicePortConnectors connectorId)",
        hint: "give each connector its own connectorId (RTSystemEditor makes a new one when the connector is drawn again)",
    },
    Rule {
        code: SYSTEM_USES_DEPRECATED,
        severity: Warning,
        name: "system-uses-deprecated-component",
        summary: "an RT System instance is of a deprecated component",
        explanation: "A component can be marked deprecated by its profile (`rtcdoc.stability` properties) or in rtcdoc.toml (`[stability.\"RTC:Lab:Sensor:Camera:1.0.0\"] status = \"deprecated\"`, with `since`, `replacement` and `note`). Each instance of an RT System whose component is deprecated is reported at the instance, with the version it is deprecated since, its replacement and the note: the system still runs, but it is built on a component its owners mean to remove.",
        spec: "rtcdoc (stability marks; not in the RTC Profile or RtsProfile spec)",
        hint: "replace the instance by one of the replacement the stability mark names (in RTSystemEditor, then save the system again), or keep it knowingly until it is removed",
    },
    Rule {
        code: README_GENERATED,
        severity: Info,
        name: "readme-generated",
        summary: "the README of a component's folder was generated from the profile and is not shown",
        explanation: "rtc-template and RTCBuilder write a README from the profile (it says `This file is generated by rtc-template`, holds `<rtc-template block=…>` markers, or starts with `RTComponent: <Name> specificatioin`). It repeats what the component page shows, so it is left out; this note says so, so that a README missing from the page is never a mystery. The position is the marker's.",
        spec: "— (rtcdoc: component folder READMEs)",
        hint: "write a README.md of your own (what the component is for, how to build and run it) to have it shown on the component page",
    },
    Rule {
        code: README_UNREADABLE,
        severity: Warning,
        name: "readme-unreadable",
        summary: "the README of a component's folder cannot be shown",
        explanation: "A `README.md` (or `README.markdown`) beside a profile is shown on the component page, unless it is larger than 1 MiB, is in no encoding rtcdoc reads (UTF-8, with or without a byte order mark; else Shift_JIS or EUC-JP, as older Japanese READMEs are saved, when every byte decodes), is a symbolic link (rtcdoc follows none) or not a regular file, or cannot be read. The message says which; the position, for an unreadable encoding, is the first byte that is not UTF-8.",
        spec: "— (rtcdoc: component folder READMEs; robustness limit)",
        hint: "save the README as UTF-8 and keep it under 1 MiB (move long material into other files and link them); replace a link by the file",
    },
    Rule {
        code: README_IMAGE,
        severity: Warning,
        name: "readme-image",
        summary: "an image of a component's README cannot be shown",
        explanation: "A README's relative image is copied into the site when it resolves inside the input directory to a regular file of type PNG, JPEG, GIF, WebP or SVG of at most 5 MiB. Any other — missing, outside the input, a link or a folder, of another type, too large — is dropped and its alt text shown instead; the message says why. (An absolute `http(s)` image becomes a link to it: the site makes no external requests.)",
        spec: "— (rtcdoc: component folder READMEs)",
        hint: "add the image or correct its path (relative to the README's folder), and use one of the types shown",
    },
    Rule {
        code: DRIFT_ONLY_IN_PROFILE,
        severity: Warning,
        name: "only-in-profile",
        summary: "a port, interface or parameter of the profile is not registered by the code",
        explanation: "The component's source files (found beside the profile in RTCBuilder's layout: C++ `src/<Name>.cpp` and `include/<Name>/<Name>.h`, Python `<Name>.py`, Java `src/<Name>Impl.java`, or named in rtcdoc.toml) are read with a tokenizer that knows comments and strings, and what they register is compared with the profile: `addInPort` / `addOutPort`, `registerProvider` / `registerConsumer` on a `CorbaPort`, `bindParameter`. A data port, service port, service interface or configuration parameter the profile declares and the code never registers is documented but does not exist when the component runs. It is reported only when the code's registrations of that kind can all be read: a name built at run time, a macro or a base class whose file is not found makes it RTC810 instead. A data port is compared under the name its constructor gives it (`m_xIn(\"x\", m_x)`, `OpenRTM_aist.InPort(\"x\", …)`), the name OpenRTM runs it under (`addInPort`'s name only keys its properties); the component's class is the one deriving from `DataFlowComponentBase`, and its base classes are followed to the files beside it (the Python module it is imported from, a C++ header of the component's folders with its source, `<Base>.java`).",
        spec: "— (rtcdoc: the code RTCBuilder generates; OpenRTM-aist RTObject API)",
        hint: "register it in the code, or remove it from the profile",
    },
    Rule {
        code: DRIFT_ONLY_IN_CODE,
        severity: Warning,
        name: "only-in-code",
        summary: "the code registers a port, interface or parameter the profile does not declare",
        explanation: "The code registers it with a literal name (`addInPort(\"distance_sensor\", …)`, `bindParameter(\"Red\", …)`), and the profile has no element of that name, so the running component has something its documentation does not show. The finding is at the registration, with the profile as its related location.",
        spec: "— (rtcdoc: the code RTCBuilder generates; OpenRTM-aist RTObject API)",
        hint: "add it to the profile (RTCBuilder), or remove the registration",
    },
    Rule {
        code: DRIFT_NAME_CASE,
        severity: Warning,
        name: "name-case",
        summary: "a name differs between profile and code only in case",
        explanation: "OpenRTM compares port and parameter names exactly: a system that connects the profile's `attach_Port` finds no port when the code registers `Attach_Port`. Reported once, instead of one name only in the profile and another only in the code.",
        spec: "— (rtcdoc: the code RTCBuilder generates; OpenRTM-aist RTObject API)",
        hint: "spell the name the same in both",
    },
    Rule {
        code: DRIFT_DATA_TYPE,
        severity: Warning,
        name: "type-differs",
        summary: "a port's data type or an interface's type differs between profile and code",
        explanation: "For a data port, the code's type is `T` of the `InPort<T>` / `OutPort<T>` member the registration names (C++, Java), or the data object given to `OpenRTM_aist.InPort` (Python: `RTC.TimedLong(…)`, `instantiateDataType(RTC.TimedLong)`). For an interface it is the type name given to `registerProvider` / `registerConsumer`. Names are compared as scoped names (`RTC.TimedLong`, `IDL:RTC/TimedLong:1.0` and `RTC::TimedLong` are one); a name written without its module (`TimedLong` under `using namespace RTC`, Java's imports) matches on its last part. For a configuration parameter the declared type of the bound variable is compared by family (integer, real, string, bool) only.",
        spec: "— (rtcdoc: the code RTCBuilder generates; OpenRTM-aist RTObject API)",
        hint: "change the profile's type or the code's declaration so they agree",
    },
    Rule {
        code: DRIFT_DIRECTION,
        severity: Warning,
        name: "direction-differs",
        summary: "a port's direction or an interface's direction differs between profile and code",
        explanation: "The profile says DataInPort and the code's port is an `OutPort` (or the reverse; the port object's class decides, else the registering call `addOutPort` / `addInPort`), or an interface the profile marks Provided is registered with `registerConsumer` (or the reverse).",
        spec: "— (rtcdoc: the code RTCBuilder generates; OpenRTM-aist RTObject API)",
        hint: "make the profile say what the code registers",
    },
    Rule {
        code: DRIFT_DEFAULT,
        severity: Warning,
        name: "default-differs",
        summary: "a configuration parameter's default value differs between profile and code",
        explanation: "The default given to `bindParameter(name, var, \"default\")`, or the spec array's `conf.default.<name>`, is not the profile's `defaultValue` (compared as text, spaces at the ends ignored). The component then starts with another value than the documentation says.",
        spec: "— (rtcdoc: the code RTCBuilder generates; OpenRTM-aist RTObject API)",
        hint: "make the code's default and the profile's defaultValue the same",
    },
    Rule {
        code: DRIFT_CALLBACK_UNMARKED,
        severity: Warning,
        name: "callback-unmarked",
        summary: "a callback is implemented in the code, but the profile marks it not implemented",
        explanation: "RTCBuilder generates each lifecycle callback commented out unless the profile marks it implemented. A callback the class defines with a body beyond the generated `return RTC::RTC_OK;` (and registrations) does work the profile says is not there: its Activity documentation is missing. Comments, commented-out definitions and the generated stubs are not implementations.",
        spec: "— (rtcdoc: the code RTCBuilder generates; OpenRTM-aist RTObject API)",
        hint: "mark the action implemented in the profile and document it",
    },
    Rule {
        code: DRIFT_CALLBACK_MISSING,
        severity: Warning,
        name: "callback-missing",
        summary: "the profile marks a callback implemented, but the code does not define it",
        explanation: "The action is marked `implemented=\"true\"`, and no file read defines the callback (it is commented out or was removed), so the documented behaviour does not run. `onInitialize` is exempt: the base class defines it. `onAction` and `onModeChanged` are exempt unless the component kind is a state machine or multi-mode one: RTCBuilder generates neither for a data-flow component. Nothing is reported when the files read define no callback at all, or a base class is not found.",
        spec: "— (rtcdoc: the code RTCBuilder generates; OpenRTM-aist RTObject API)",
        hint: "mark the action not implemented, or define the callback",
    },
    Rule {
        code: DRIFT_SPEC_VALUE,
        severity: Warning,
        name: "spec-array-differs",
        summary: "the spec array says another version, vendor, category, activity type, … than BasicInfo",
        explanation: "The spec array (`<name>_spec[]`) is what the running component reports to tools (rtshell, RTSystemEditor); it is generated from BasicInfo once. Compared: `implementation_id` with the name, `version`, `vendor`, `category`, `activity_type` (any case), `max_instance`, `language` (any case), and each parameter's `conf.__widget__` and `conf.__type__`. A value written as a macro (`PACKAGE_VERSION`) is not compared (RTC810).",
        spec: "— (rtcdoc: the code RTCBuilder generates; OpenRTM-aist RTObject API)",
        hint: "regenerate the spec array from the profile, or correct the stale one",
    },
    Rule {
        code: DRIFT_UNVERIFIED,
        severity: Info,
        name: "could-not-verify",
        summary: "part of the code cannot be verified statically",
        explanation: "A registration whose name is not a literal (built at run time, in a loop), a macro that registers ports, a service port whose name is not a literal, or code that registers nothing at all (ports added by a base class or a library): what it registers is not compared, and nothing of that kind is reported missing from the code. Never a warning: the code may well be right.",
        spec: "— (rtcdoc: the code RTCBuilder generates; OpenRTM-aist RTObject API)",
        hint: "nothing to change; if another file registers them, name it in rtcdoc.toml ([[implementation.component]])",
    },
    Rule {
        code: SOURCE_UNREADABLE,
        severity: Info,
        name: "source-unreadable",
        summary: "a source file of a component cannot be read",
        explanation: "A source file larger than the file-size limit (16 MiB by default, --max-file-size), nested deeper than 256 brackets or with more than four million tokens is not read; the component's implementation is compared without it. The build goes on. Files in Shift_JIS are read as such; other invalid UTF-8 is replaced.",
        spec: "— (rtcdoc: the code RTCBuilder generates; OpenRTM-aist RTObject API)",
        hint: "nothing to change if the file is generated or vendored; else split it",
    },
    Rule {
        code: SOURCE_RECOVERED,
        severity: Info,
        name: "recovered-from-source",
        summary: "a component has code and no profile: it is documented from its code",
        explanation: "A source file holding a spec array (`<name>_spec[]` in C++, `<name>_spec = [...]` in Python, the `component_conf` array in Java) in a folder no profile documents is a component without an RTC.xml. It is documented from what its code registers (ports with their data types, service ports and interfaces, configuration parameters with their defaults, the callbacks it implements) and marked \"recovered from the source\" on its page and in catalog.json. A value the code does not spell out — a macro such as `PACKAGE_VERSION`, a port whose variable's declaration was not found — is named in the message and left empty, never guessed. The profile rules do not run on it: there is no profile to correct. The component folder is the one above the file's `src/`, else its own; test and build folders are not looked in. A profile documents the code whose component folder is its own folder or that folder's component folder: `X/src/RTC.xml`, a project kept in a folder named src, documents `X/src/src/X.cpp`.",
        spec: "— (rtcdoc: the code RTCBuilder generates)",
        hint: "run `rtcdoc extract FOLDER` to write its RTC.xml (then describe the component there), or exclude the folder",
    },
];

/// The registry entry of `code` (any case).
/// The rule of a code as the registry spells it (`RTC101`): one hash lookup, for the rules
/// emitting findings; anything else goes through [`rule`].
pub fn rule_exact(code: &str) -> Option<&'static Rule> {
    static BY_CODE: std::sync::OnceLock<std::collections::HashMap<&'static str, &'static Rule>> =
        std::sync::OnceLock::new();
    BY_CODE
        .get_or_init(|| RULES.iter().rev().map(|r| (r.code, r)).collect())
        .get(code)
        .copied()
        .or_else(|| rule(code))
}

pub fn rule(code: &str) -> Option<&'static Rule> {
    crate::diagnostic::registry_entry(RULES, code, |r| (r.code, r.name))
}

/// `--explain` text for a rule.
pub fn explain(r: &Rule) -> String {
    let severity = format!("Default severity: {}\nSpec: {}", r.severity, r.spec);
    let fix = format!("Fix: {}", r.hint);
    crate::diagnostic::explanation(r.code, r.name, r.summary, &[&severity, r.explanation, &fix])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn codes_are_unique_and_well_formed() {
        let mut seen = std::collections::HashSet::new();
        for r in RULES {
            assert!(seen.insert(r.code), "duplicate {}", r.code);
            assert!(r.code.len() == 6 && r.code.starts_with("RTC"));
            assert!(!r.spec.is_empty() && !r.explanation.is_empty());
        }
        assert!(rule("rtc303").is_some());
        // Every code the IDL reader produces has its rule.
        for code in [
            IDL_SYNTAX,
            IDL_PREPROCESSOR,
            IDL_INCLUDE,
            IDL_INCLUDE_CYCLE,
            IDL_LIMIT,
            IDL_ENCODING,
            IDL_SKIPPED,
            IDL_DIRECTIVE,
            IDL_REDEFINITION,
            IDL_UNRESOLVED,
        ] {
            assert!(rule(code).is_some(), "{code} is not registered");
        }
        assert!(rule(MALFORMED).is_some());
    }
}
