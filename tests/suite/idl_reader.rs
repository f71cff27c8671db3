//! The IDL reader (`rtcdoc::idl`) on hand-written fixtures: declarations, doc comments,
//! preprocessing, encodings, positions, error recovery, hostile input and lookups.

use rtcdoc::idl::{
    self, IdlConstValue, IdlDefinition, IdlFile, IdlOptions, IdlParamDirection, IdlPrimitive,
    IdlSet, IdlType, SourceFile,
};
use std::path::Path;

fn fixture(rel: &str) -> SourceFile {
    let p = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures/idl")
        .join(rel);
    SourceFile::new(rel, std::fs::read(&p).expect("fixture"))
}

fn read(files: Vec<SourceFile>) -> IdlSet {
    idl::read(&files, &IdlOptions::default())
}

fn one(name: &str, text: &str) -> IdlSet {
    read(vec![SourceFile::new(name, text.as_bytes().to_vec())])
}

fn diags(set: &IdlSet) -> Vec<String> {
    set.diagnostics.iter().map(|d| d.to_string()).collect()
}

/// Reads every `*.idl` below `RTCDOC_IDL_DIR` (e.g. an OpenRTM checkout) and prints what it
/// found; skipped (and says so) when the variable is not set.
#[test]
fn real_idl_directory_when_given() {
    let Ok(dir) = std::env::var("RTCDOC_IDL_DIR") else {
        eprintln!("skipped: RTCDOC_IDL_DIR is not set");
        return;
    };
    let mut files = Vec::new();
    let mut stack = vec![std::path::PathBuf::from(&dir)];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|e| e == "idl") {
                let rel = p
                    .strip_prefix(&dir)
                    .unwrap()
                    .to_string_lossy()
                    .replace('\\', "/");
                files.push(SourceFile::new(rel, std::fs::read(&p).unwrap()));
            }
        }
    }
    files.sort_by(|a, b| a.path.cmp(&b.path));
    let t = std::time::Instant::now();
    let set = read(files);
    let el = t.elapsed();
    let mut counts = std::collections::BTreeMap::new();
    fn count(defs: &[IdlDefinition], c: &mut std::collections::BTreeMap<&'static str, usize>) {
        for d in defs {
            *c.entry(d.kind_word()).or_default() += 1;
            count(d.children(), c);
        }
    }
    for f in &set.files {
        count(&f.definitions, &mut counts);
    }
    for d in &set.diagnostics {
        eprintln!("{d}");
    }
    eprintln!("{} files in {el:?}: {counts:?}", set.files.len());
}

fn def<'a>(set: &'a IdlSet, name: &str) -> &'a IdlDefinition {
    set.find(name)
        .unwrap_or_else(|| panic!("{name} not found"))
        .definition
}

fn strukt<'a>(set: &'a IdlSet, name: &str) -> &'a idl::IdlStruct {
    match def(set, name) {
        IdlDefinition::Struct(s) => s,
        other => panic!("{name} is a {}", other.kind_word()),
    }
}

fn interface<'a>(set: &'a IdlSet, name: &str) -> &'a idl::IdlInterface {
    match def(set, name) {
        IdlDefinition::Interface(s) => s,
        other => panic!("{name} is a {}", other.kind_word()),
    }
}

fn named(ty: &IdlType) -> (&str, Option<&str>) {
    match ty {
        IdlType::Named { name, resolved } => (name, resolved.as_deref()),
        other => panic!("not a named type: {other:?}"),
    }
}

fn brief(d: &Option<Box<idl::IdlDoc>>) -> &str {
    d.as_ref().map_or("", |d| d.brief.as_str())
}

fn data_types() -> IdlSet {
    read(vec![fixture("MyDataTypes.idl"), fixture("MyService.idl")])
}

#[test]
fn fixtures_read_without_errors() {
    let set = data_types();
    let errors: Vec<String> = set
        .diagnostics
        .iter()
        .filter(|d| d.is_error() || d.severity == rtcdoc::diagnostic::Severity::Warning)
        .map(|d| d.to_string())
        .collect();
    assert!(errors.is_empty(), "{errors:#?}");
    // valuetype, valuetype and eventtype: skipped with a note each.
    let skipped: Vec<&str> = set
        .diagnostics
        .iter()
        .filter(|d| d.code == "RTC026")
        .map(|d| d.message.as_str())
        .collect();
    assert_eq!(skipped.len(), 3, "{skipped:?}");
    assert!(skipped[0].contains("`valuetype Box`"), "{skipped:?}");
}

#[test]
fn structs_fields_and_their_docs() {
    let set = data_types();
    let time = strukt(&set, "RTC::Time");
    assert_eq!(time.repository_id, "IDL:RTC/Time:1.0");
    assert_eq!(time.file, "MyDataTypes.idl");
    assert_eq!((time.pos.line, time.pos.column), (17, 3));
    let doc = time.doc.as_ref().unwrap();
    assert_eq!(doc.brief, "Time stamp.");
    assert_eq!(doc.details, "Seconds and nanoseconds since the epoch.");
    assert_eq!(doc.labels[0].tag, "struct");
    assert_eq!(time.fields.len(), 2);
    assert_eq!(time.fields[0].name, "sec");
    assert_eq!(
        time.fields[0].ty,
        IdlType::Primitive {
            name: IdlPrimitive::UnsignedLong
        }
    );
    assert_eq!(brief(&time.fields[0].doc), "Seconds.");
    assert_eq!(brief(&time.fields[1].doc), "Nanoseconds.");

    let foo = strukt(&set, "RTC::TimedFoo");
    assert_eq!(
        foo.doc.as_ref().unwrap().text,
        "A timed value.\nSecond line of the same comment."
    );
    let f: Vec<&str> = foo.fields.iter().map(|f| f.name.as_str()).collect();
    assert_eq!(
        f,
        [
            "tm",
            "data",
            "x",
            "y",
            "matrix",
            "nested",
            "label",
            "wide",
            "map",
            "interface"
        ]
    );
    assert_eq!(named(&foo.fields[0].ty), ("Time", Some("RTC::Time")));
    assert_eq!(brief(&foo.fields[0].doc), "Time stamp.");
    assert_eq!(brief(&foo.fields[1].doc), "The value, in metres.");
    assert_eq!(brief(&foo.fields[2].doc), "Coordinates.");
    assert_eq!(brief(&foo.fields[3].doc), "Coordinates.");
    let dims: Vec<Option<u64>> = foo.fields[4].array.iter().map(|b| b.value).collect();
    assert_eq!(dims, [Some(3), Some(4)]);
    assert_eq!(foo.fields[5].ty.to_idl(), "sequence<sequence<long>>");
    assert!(
        matches!(&foo.fields[6].ty, IdlType::String { wide: false, bound: Some(b) } if b.value == Some(16))
    );
    assert!(matches!(
        &foo.fields[7].ty,
        IdlType::String {
            wide: true,
            bound: None
        }
    ));
    // An IDL-4 keyword as a field name, a CORBA-3 type resolved later in the file.
    assert_eq!(
        named(&foo.fields[8].ty),
        ("OGMapTile", Some("RTC::OGMapTile"))
    );
    assert!(foo.fields[4].doc.is_none(), "plain comments are not docs");

    let again = strukt(&set, "RTC::Again");
    let r: Vec<Option<&str>> = again.fields.iter().map(|f| named(&f.ty).1).collect();
    assert_eq!(r, [Some("RTC::Time"); 3]);
    // The module is reopened: two entries in the file.
    let modules = set.files[0]
        .definitions
        .iter()
        .filter(|d| d.scoped_name() == "RTC")
        .count();
    assert_eq!(modules, 2);
    let file_doc = set.files[0].doc.as_ref().unwrap();
    assert_eq!(
        file_doc.brief,
        "Data types of the demo robot (hand-written test fixture)."
    );
}

#[test]
fn enums_typedefs_consts_unions_exceptions_and_the_rest() {
    let set = data_types();
    let IdlDefinition::Enum(e) = def(&set, "RTC::Colour") else {
        panic!()
    };
    let v: Vec<(&str, &str)> = e
        .values
        .iter()
        .map(|v| (v.name.as_str(), brief(&v.doc)))
        .collect();
    assert_eq!(
        v,
        [
            ("RED", "Red."),
            ("GREEN", "Green."),
            ("BLUE", "Blue, documented before.")
        ]
    );
    let IdlDefinition::Typedef(t) = def(&set, "RTC::TimedFooSeq") else {
        panic!()
    };
    assert_eq!(t.ty.to_idl(), "sequence<TimedFoo, 10>");
    let IdlDefinition::Typedef(arr) = def(&set, "FooArray") else {
        panic!()
    };
    assert_eq!(arr.array[0].value, Some(2));
    let IdlDefinition::Typedef(big) = def(&set, "RTC::Big") else {
        panic!()
    };
    assert_eq!(big.ty.to_idl(), "long long");

    let value = |n: &str| match def(&set, n) {
        IdlDefinition::Const(c) => (c.expr.clone(), c.value.clone()),
        _ => panic!(),
    };
    assert_eq!(
        value("RTC::MAX_SIZE"),
        ("8 * (2 + 2)".into(), Some(IdlConstValue::Integer(32)))
    );
    assert_eq!(
        value("RTC::HUGE").1,
        Some(IdlConstValue::Unsigned(u64::MAX))
    );
    assert_eq!(value("RTC::HALF").1, Some(IdlConstValue::Float(0.5)));
    assert_eq!(
        value("RTC::NAME").1,
        Some(IdlConstValue::String("demo-robot".into()))
    );
    assert_eq!(value("RTC::ON").1, Some(IdlConstValue::Boolean(true)));
    assert_eq!(
        value("RTC::LETTER").1,
        Some(IdlConstValue::Char("x".into()))
    );
    assert_eq!(
        value("RTC::DEFAULT_COLOUR").1,
        Some(IdlConstValue::Enumerator("RTC::GREEN".into()))
    );
    assert_eq!(value("RTC::SHIFTED").1, Some(IdlConstValue::Integer(128)));
    let IdlDefinition::Const(c) = def(&set, "RTC::MAX_SIZE") else {
        panic!()
    };
    assert_eq!(brief(&c.doc), "Largest size.");
    let IdlDefinition::Typedef(buf) = def(&set, "RTC::Buffer") else {
        panic!()
    };
    assert!(
        matches!(&buf.ty, IdlType::Sequence { bound: Some(b), .. } if b.value == Some(32) && b.expr == "MAX_SIZE")
    );

    let IdlDefinition::Union(u) = def(&set, "RTC::Reading") else {
        panic!()
    };
    assert_eq!(u.switch_type.to_idl(), "long");
    let cases: Vec<(Vec<&str>, bool, &str)> = u
        .cases
        .iter()
        .map(|c| {
            (
                c.labels.iter().map(|l| l.as_str()).collect(),
                c.is_default,
                c.field.name.as_str(),
            )
        })
        .collect();
    assert_eq!(
        cases,
        [
            (vec!["1", "2"], false, "count"),
            (vec!["MAX_SIZE"], false, "value"),
            (vec!["default"], true, "text"),
        ]
    );
    assert_eq!(brief(&u.cases[0].field.doc), "A count.");

    let IdlDefinition::Exception(x) = def(&set, "RTC::Failure") else {
        panic!()
    };
    assert_eq!(x.fields.len(), 2);
    assert_eq!(brief(&x.doc), "Something went wrong.");
    assert!(matches!(def(&set, "RTC::Empty"), IdlDefinition::Exception(e) if e.fields.is_empty()));
    assert!(matches!(def(&set, "RTC::Later"), IdlDefinition::Forward(f) if f.of == "interface"));
    assert!(matches!(def(&set, "RTC::Pending"), IdlDefinition::Forward(f) if f.of == "struct"));
    assert!(matches!(def(&set, "RTC::Handle"), IdlDefinition::Native(_)));
    assert!(
        matches!(def(&set, "RTC::Thing"), IdlDefinition::Skipped(s) if s.keyword == "valuetype")
    );
}

#[test]
fn interfaces_with_every_operation_form() {
    let set = data_types();
    let s = interface(&set, "Demo::PathService");
    assert_eq!(s.repository_id, "IDL:Demo/PathService:1.0");
    let bases: Vec<(&str, Option<&str>)> = s.bases.iter().map(named).collect();
    assert_eq!(
        bases,
        [
            ("Base", Some("Demo::Base")),
            ("::Demo::Other", Some("Demo::Other"))
        ]
    );
    let doc = s.doc.as_ref().unwrap();
    assert_eq!(doc.brief, "The path service.");
    assert_eq!(doc.details, "Plans paths.");
    assert_eq!(doc.languages[0].lang, "jp");
    assert_eq!(doc.languages[0].doc.brief, "経路サービス");

    let attrs: Vec<(&str, bool, String)> = s
        .attributes
        .iter()
        .map(|a| (a.name.as_str(), a.readonly, a.ty.to_idl()))
        .collect();
    assert_eq!(
        attrs,
        [
            ("count", true, "long".into()),
            ("name", false, "string".into()),
            ("alias", false, "string".into()),
            ("cost", true, "double".into()),
        ]
    );
    assert_eq!(brief(&s.attributes[0].doc), "Number of plans.");
    assert_eq!(
        named(&s.attributes[3].raises[0]),
        ("NoPath", Some("Demo::PathService::NoPath"))
    );

    let op = |n: &str| s.operations.iter().find(|o| o.name == n).unwrap();
    let plan = op("plan");
    assert_eq!(plan.return_type.as_ref().unwrap().to_idl(), "boolean");
    let params: Vec<(IdlParamDirection, String, &str)> = plan
        .params
        .iter()
        .map(|p| (p.direction, p.ty.to_idl(), p.name.as_str()))
        .collect();
    assert_eq!(
        params,
        [
            (IdlParamDirection::In, "RTC::TimedFoo".into(), "start"),
            (IdlParamDirection::Out, "NameList".into(), "path"),
            (IdlParamDirection::Inout, "long".into(), "hint"),
        ]
    );
    assert_eq!(named(&plan.params[0].ty).1, Some("RTC::TimedFoo"));
    assert_eq!(named(&plan.params[1].ty).1, Some("Demo::NameList"));
    assert_eq!(
        named(&plan.raises[0]),
        ("NoPath", Some("Demo::PathService::NoPath"))
    );
    let pd = plan.doc.as_ref().unwrap();
    assert_eq!(pd.brief, "Plans a path.");
    let pdoc: Vec<(&str, Option<&str>)> = pd
        .params
        .iter()
        .map(|p| (p.name.as_str(), p.direction.as_deref()))
        .collect();
    assert_eq!(
        pdoc,
        [
            ("start", Some("in")),
            ("path", Some("out")),
            ("hint", Some("in,out"))
        ]
    );
    assert_eq!(pd.returns.as_deref(), Some("true when a path was found."));
    assert_eq!(pd.exceptions[0].name, "NoPath");

    let notify = op("notify");
    assert!(notify.oneway && notify.return_type.is_none());
    assert_eq!(op("now").context, ["LANG", "TZ"]);
    let history = op("history");
    assert_eq!(
        history.return_type.as_ref().unwrap().to_idl(),
        "sequence<RTC::Time>"
    );
    assert_eq!(brief(&history.params[0].doc), "How many.");
    assert_eq!(brief(&history.params[1].doc), "Which mode.");
    assert_eq!(
        named(&history.params[1].ty).1,
        Some("Demo::PathService::Mode")
    );
    assert_eq!(
        op("self_ref").return_type.as_ref().unwrap().to_idl(),
        "Object"
    );
    assert_eq!(op("anything").params[0].ty.to_idl(), "any");
    assert_eq!(
        op("price").return_type.as_ref().unwrap().to_idl(),
        "fixed<8, 2>"
    );
    // Types declared inside the interface are definitions of their own.
    assert!(matches!(
        def(&set, "Demo::PathService::Mode"),
        IdlDefinition::Enum(_)
    ));
    assert_eq!(
        brief(&interface(&set, "Demo::Base").operations[0].doc),
        "Pings."
    );
    assert_eq!(
        interface(&set, "Demo::Shape").modifier.as_deref(),
        Some("abstract")
    );
    assert_eq!(
        interface(&set, "Demo::Local").modifier.as_deref(),
        Some("local")
    );
}

#[test]
fn lookup_by_every_name_form() {
    let set = data_types();
    for q in [
        "RTC::TimedFoo",
        "TimedFoo",
        "::RTC::TimedFoo",
        "IDL:RTC/TimedFoo:1.0",
        "IDL:RTC/TimedFoo:2.0",
        " RTC::TimedFoo ",
    ] {
        assert_eq!(
            set.scoped_name_of(q).as_deref(),
            Some("RTC::TimedFoo"),
            "{q}"
        );
    }
    assert!(set.find("Nope").is_none());
    assert!(set.find("IDL:RTC/Nope:1.0").is_none());
    // Two definitions named `Mode`? Only one here; `Time` is unique; ambiguity gives none.
    let twice = read(vec![
        SourceFile::new("a.idl", "module A { struct T { long x; }; };"),
        SourceFile::new("b.idl", "module B { struct T { long x; }; };"),
    ]);
    assert!(twice.find("T").is_none());
    assert!(twice.find("A::T").is_some());
    assert_eq!(twice.find_all("B::T").len(), 1);
    // The same scoped name in two files: both are found, in file order.
    let vendored = read(vec![
        SourceFile::new("x/Basic.idl", "module RTC { struct Time { long s; }; };"),
        SourceFile::new("y/Basic.idl", "module RTC { struct Time { long s; }; };"),
    ]);
    let all = vendored.find_all("RTC::Time");
    assert_eq!(
        all.iter().map(|i| i.file.path.as_str()).collect::<Vec<_>>(),
        ["x/Basic.idl", "y/Basic.idl"]
    );
    // A forward declaration gives way to the definition.
    let fwd = one("f.idl", "interface I; interface I { void f(); };");
    assert!(matches!(
        fwd.find("I").unwrap().definition,
        IdlDefinition::Interface(_)
    ));
}

#[test]
fn pragmas_and_typeid_change_repository_ids() {
    let set = read(vec![fixture("pragmas.idl")]);
    let id = |n: &str| def(&set, n).repository_id().to_string();
    assert_eq!(id("RTC"), "IDL:omg.org/RTC:1.0");
    assert_eq!(id("RTC::A"), "IDL:omg.org/RTC/A:1.2");
    assert_eq!(id("RTC::B"), "IDL:inner.org/B:1.0");
    assert_eq!(id("RTC::Deep::C"), "IDL:inner.org/Deep/C:1.0");
    assert_eq!(id("RTC::D"), "IDL:custom/D:3.0");
    assert_eq!(id("Other::E"), "IDL:omg.org/Other/E:1.0");
    assert_eq!(id("T::F"), "IDL:typed/F:1.0");
    assert_eq!(id("U::G"), "IDL:u.org/G:1.0");
    assert_eq!(
        set.scoped_name_of("IDL:omg.org/RTC/A:1.2").as_deref(),
        Some("RTC::A")
    );
    assert_eq!(
        set.scoped_name_of("IDL:custom/D:3.0").as_deref(),
        Some("RTC::D")
    );
    assert_eq!(
        diags(&set),
        ["pragmas.idl:15:1: warning[RTC027]: the repository id setting names `Nowhere`, which this file does not declare; it is ignored"]
    );
    assert_eq!(set.files[0].pragmas.len(), 5);
}

#[test]
fn preprocessor_conditionals_macros_and_directives() {
    let files = vec![fixture("preprocessor.idl")];
    let set = idl::read(&files, &IdlOptions::default());
    assert!(set.find("Arith").is_some());
    assert!(set.find("FeatureX").is_none() && set.find("Never").is_none());
    assert!(set.find("Undefined").is_none(), "#undef");
    let IdlDefinition::Typedef(t) = def(&set, "P::Handle_t") else {
        panic!()
    };
    assert_eq!(t.ty.to_idl(), "long");
    let IdlDefinition::Exception(x) = def(&set, "P::Bad") else {
        panic!()
    };
    assert_eq!(x.fields[0].name, "description");
    // `#line` has no effect: positions stay those of the file.
    assert_eq!(def(&set, "Last").pos().line, 29);
    assert_eq!(
        diags(&set),
        ["preprocessor.idl:26:1: warning[RTC027]: unknown preprocessor directive `#frobnicate`; the line is ignored"]
    );
    assert_eq!(set.files[0].pragmas[0].text, "keylist P::Foo");
    // A define from the options switches the branch.
    let opts = IdlOptions {
        defines: vec!["FEATURE_X".into(), "TAO_IDL".into()],
        ..IdlOptions::default()
    };
    let set = idl::read(&files, &opts);
    assert!(set.find("FeatureX").is_some() && set.find("Arith").is_none());
    assert!(diags(&set)
        .iter()
        .any(|d| d.contains("info[RTC022]: included file <tao/orb.idl> was not found")));
    let opts = IdlOptions {
        defines: vec!["FEATURE_X".into(), "NO_Y=1".into()],
        ..IdlOptions::default()
    };
    assert!(idl::read(&files, &opts).find("Arith").is_some());
}

#[test]
fn preprocessor_errors_are_reported() {
    let set = one("p.idl", "#ifdef X\nstruct A { long a; };\n#else\n#else\n#endif\n#endif\n#if 1 +\n#endif\n#error stop here\n#ifndef Y\n");
    assert_eq!(
        diags(&set),
        [
            "p.idl:4:1: error[RTC021]: a second `#else` for one `#if`",
            "p.idl:6:1: error[RTC021]: `#endif` without `#if`",
            "p.idl:7:7: error[RTC021]: expected an expression, found the end of the line",
            "p.idl:9:1: error[RTC021]: #error stop here",
            "p.idl:10:1: error[RTC021]: `#ifdef` has no matching `#endif`",
        ]
    );
    // `#error` is the file's own stop: its hint is not about balancing directives.
    let hints: Vec<&str> = set
        .diagnostics
        .iter()
        .map(|d| d.hint.as_deref().unwrap_or(""))
        .collect();
    assert!(hints[3].contains("on purpose"), "{hints:?}");
    assert!(hints[0].contains("balance"), "{hints:?}");
}

#[test]
fn includes_by_relative_path_search_path_and_file_name() {
    let files = vec![
        fixture("include/main.idl"),
        fixture("include/lib/Base.idl"),
        fixture("include/sys/Sys.idl"),
        fixture("include/far/away/Named.idl"),
    ];
    let opts = IdlOptions {
        search_path: vec!["include/sys".into()],
        ..IdlOptions::default()
    };
    let set = idl::read(&files, &opts);
    let inc: Vec<(&str, Option<&str>)> = set.files[0]
        .includes
        .iter()
        .map(|i| (i.name.as_str(), i.resolved.as_deref()))
        .collect();
    assert_eq!(
        inc,
        [
            ("lib/Base.idl", Some("include/lib/Base.idl")),
            ("Sys.idl", Some("include/sys/Sys.idl")),
            (
                "C:\\Program Files\\OpenRTM-aist\\1.2.2\\rtm\\idl\\Named.idl",
                Some("include/far/away/Named.idl")
            ),
            ("Missing.idl", None),
            ("orb.idl", None),
        ]
    );
    assert!(set.files[0].includes[1].system);
    let uses = strukt(&set, "M::UsesAll");
    let r: Vec<Option<&str>> = uses.fields[..3].iter().map(|f| named(&f.ty).1).collect();
    assert_eq!(r, [Some("B::Base"), Some("S::Sys"), Some("N::Named")]);
    // A macro defined in an included file applies to the includer.
    assert_eq!(uses.fields[3].ty.to_idl(), "long");
    // Definitions stay in the file that declares them, with that file's positions.
    let base = strukt(&set, "B::Base");
    assert_eq!(
        (base.file.as_str(), base.pos.line),
        ("include/lib/Base.idl", 7)
    );
    assert_eq!(brief(&base.doc), "The base type.");
    assert_eq!(set.files[0].definitions.len(), 1);
    assert_eq!(
        diags(&set),
        [
            "include/main.idl:5:1: warning[RTC022]: included file \"Missing.idl\" was not found among the IDL files read",
            "include/main.idl:6:1: info[RTC022]: included file <orb.idl> was not found among the IDL files read",
        ]
    );
    // Without the search path, <Sys.idl> is still found by file name.
    let set = read(files);
    assert_eq!(
        set.files[0].includes[1].resolved.as_deref(),
        Some("include/sys/Sys.idl")
    );
}

/// An include found only by file name, with two equally distant copies: the shallower one
/// (the project's own `idl/Shared.idl`, not a copy kept deeper down), whatever the order.
#[test]
fn an_include_by_file_name_takes_the_shallowest_of_equally_close_copies() {
    let shared = |v: &str| format!("module Shared {{ struct V{v} {{ long x; }}; }};");
    for names in [
        ["lib/attic/old/Shared.idl", "lib/idl/Shared.idl"],
        ["lib/idl/Shared.idl", "lib/zz/old/Shared.idl"],
    ] {
        let deep = names.iter().position(|n| n.contains("old")).unwrap();
        let mut files: Vec<SourceFile> = names
            .iter()
            .enumerate()
            .map(|(i, n)| {
                let v = if i == deep { "Deep" } else { "Top" };
                SourceFile::new(*n, shared(v).into_bytes())
            })
            .collect();
        files.push(SourceFile::new(
            "app/App.idl",
            b"#include \"Shared.idl\"\nstruct A { Shared::VTop t; };".to_vec(),
        ));
        let set = read(files);
        let app = set.files.iter().find(|f| f.path == "app/App.idl").unwrap();
        assert_eq!(
            app.includes[0].resolved.as_deref(),
            Some("lib/idl/Shared.idl"),
            "{names:?}"
        );
    }
}

#[test]
fn include_cycles_are_reported_once_and_guarded_ones_not_at_all() {
    let set = read(vec![fixture("cycle/a.idl"), fixture("cycle/b.idl")]);
    assert_eq!(
        diags(&set),
        ["cycle/b.idl:1:1: error[RTC023]: include cycle: cycle/a.idl → cycle/b.idl → cycle/a.idl"]
    );
    assert!(set.find("CA::A").is_some() && set.find("CB::B").is_some());
    let set = read(vec![fixture("cycle/ga.idl"), fixture("cycle/gb.idl")]);
    assert!(set.diagnostics.is_empty(), "{:?}", diags(&set));
    let set = one("self.idl", "#include \"self.idl\"\nstruct S { long s; };");
    assert_eq!(
        diags(&set),
        ["self.idl:1:1: error[RTC023]: include cycle: self.idl → self.idl"]
    );
}

#[test]
fn include_depth_is_limited() {
    let files: Vec<SourceFile> = (0..10)
        .map(|i| {
            SourceFile::new(
                format!("f{i}.idl"),
                format!("#include \"f{}.idl\"\n", i + 1),
            )
        })
        .collect();
    let opts = IdlOptions {
        max_include_depth: 3,
        ..IdlOptions::default()
    };
    let set = idl::read(&files, &opts);
    assert!(
        diags(&set)
            .iter()
            .any(|d| d.contains("error[RTC024]: includes nest deeper than 3 files")),
        "{:?}",
        diags(&set)
    );
}

#[test]
fn syntax_errors_recover_at_the_next_declaration() {
    let set = read(vec![fixture("errors.idl")]);
    assert_eq!(
        diags(&set),
        [
            "errors.idl:3:26: error[RTC020]: expected `;` after struct member, found `long`",
            "errors.idl:5:24: error[RTC020]: expected `in`, `out` or `inout` before a parameter of `f`, found `long`",
            "errors.idl:6:15: error[RTC020]: expected `,` or `}` after enumerator, found `B`",
            "errors.idl:7:25: error[RTC020]: expected `;` after struct member, found `}`",
        ]
    );
    for n in ["E::Good1", "E::Good2", "E::Good3", "AfterAll"] {
        assert!(set.find(n).is_some(), "{n} lost");
    }
    assert_eq!(interface(&set, "E::I").operations.len(), 1);
    assert_eq!(strukt(&set, "E::Broken").fields.len(), 1);
    assert_eq!(strukt(&set, "E::Good3").fields[0].name, "d");
    let hint = set.diagnostics[0].hint.as_deref().unwrap();
    assert!(hint.contains("`long x;`"), "{hint}");
}

#[test]
fn more_syntax_errors_name_what_was_expected() {
    for (src, want) in [
        (
            "struct S { long a; }",
            "expected `;` after the `}` of struct `S`, found end of file",
        ),
        (
            "module M { struct S { long a; };",
            "expected `}` to close module `M`, found end of file",
        ),
        (
            "typedef sequence<long LongSeq;",
            "expected `>` to close `sequence<…`, found `LongSeq`",
        ),
        ("const long X = ;", "expected an expression, found `;`"),
        (
            "const long X = 1 / 0;",
            "division by zero in constant expression",
        ),
        (
            "interface I { void f(in long) ; };",
            "expected a parameter name, found `)`",
        ),
        (
            "union U { case 1: long a; };",
            "expected `switch` after `union U`, found `{`",
        ),
        ("struct S { long a; }; $", "unexpected character `$`"),
        (
            "struct S { unsigned char c; };",
            "expected `short` or `long` after `unsigned`, found `char`",
        ),
        ("/* open", "unterminated comment: `/*` has no closing `*/`"),
        ("const string S = \"open;\n", "unterminated string literal"),
        (
            "valuetype V { long x;",
            "`valuetype` declaration is not closed before the end of the file",
        ),
    ] {
        let set = one("e.idl", src);
        let d = diags(&set);
        assert!(d.iter().any(|l| l.contains(want)), "{src:?}: {d:#?}");
        assert!(
            set.diagnostics
                .iter()
                .all(|d| d.pos.is_some() || d.code == "RTC025"),
            "{d:?}"
        );
    }
}

#[test]
fn encodings_and_line_ends() {
    let text = "/// 時刻の構造体\nmodule J {\n  struct T { long a; }; ///< 日本語\n};\n";
    for (enc, name) in [
        (encoding_rs::EUC_JP, "EUC-JP"),
        (encoding_rs::SHIFT_JIS, "Shift_JIS"),
    ] {
        let (bytes, _, unmappable) = enc.encode(text);
        assert!(!unmappable);
        let set = one("j.idl", "");
        drop(set);
        let set = read(vec![SourceFile::new("j.idl", bytes.into_owned())]);
        assert_eq!(set.files[0].encoding, name);
        let m = def(&set, "J");
        assert_eq!(m.doc().unwrap().brief, "時刻の構造体");
        assert_eq!(
            diags(&set),
            [format!(
                "j.idl: info[RTC025]: the file is not UTF-8; it was read as {name}"
            )]
        );
    }
    let bom = [b"\xEF\xBB\xBF".as_slice(), text.as_bytes()].concat();
    let set = read(vec![SourceFile::new("bom.idl", bom)]);
    assert_eq!(set.files[0].encoding, "UTF-8");
    assert!(set.diagnostics.is_empty());
    let crlf = "module C {\r\n  struct T {\r\n    long a;\r\n  };\r\n};\r\n";
    let cr = crlf.replace("\r\n", "\r");
    for src in [crlf.to_string(), cr] {
        let set = one("c.idl", &src);
        let t = strukt(&set, "C::T");
        assert_eq!(
            (t.pos.line, t.fields[0].pos.line, t.fields[0].pos.column),
            (2, 3, 10)
        );
    }
    let set = read(vec![SourceFile::new(
        "bad.idl",
        b"struct A { long a; }; // \xFF\xFE\xFF\n".to_vec(),
    )]);
    assert!(diags(&set)[0].contains("warning[RTC025]"));
    assert!(set.find("A").is_some());
}

#[test]
fn escaped_identifiers_keywords_as_names_and_literals() {
    let set = one(
        "k.idl",
        "module _module { struct map { long bitset; long int8; string _string; }; };\n\
         const wstring W = L\"wide\";\nconst wchar C = L'c';\nconst long O = 010 + 0x10;",
    );
    assert!(set.diagnostics.is_empty(), "{:?}", diags(&set));
    let s = strukt(&set, "module::map");
    let f: Vec<&str> = s.fields.iter().map(|f| f.name.as_str()).collect();
    assert_eq!(f, ["bitset", "int8", "string"]);
    let IdlDefinition::Const(w) = def(&set, "W") else {
        panic!()
    };
    assert_eq!(w.value, Some(IdlConstValue::String("wide".into())));
    assert_eq!(w.expr, "L\"wide\"");
    let IdlDefinition::Const(o) = def(&set, "O") else {
        panic!()
    };
    assert_eq!(o.value, Some(IdlConstValue::Integer(24)));
}

#[test]
fn hostile_input_ends_in_diagnostics() {
    let n = 100_000;
    let cases: Vec<(String, &str)> = vec![
        (
            format!("const long X = {}1{};", "(".repeat(n), ")".repeat(n)),
            "expression nests deeper than 64",
        ),
        (
            format!("typedef {}long{} T;", "sequence<".repeat(n), ">".repeat(n)),
            "declarations nest deeper than 64",
        ),
        (
            format!("{}{}", "module M { ".repeat(n), "};".repeat(n)),
            "declarations nest deeper than 64",
        ),
        (
            format!("{}\n", "#if 1\n".repeat(200)),
            "conditionals nest deeper than 64",
        ),
        (
            (0..40)
                .map(|i| format!("#define M{i} M{} M{}\n", i + 1, i + 1))
                .collect::<String>()
                + "const long X = M0;",
            "macro expansion makes more than",
        ),
    ];
    for (src, want) in cases {
        let set = one("h.idl", &src);
        let d = diags(&set);
        assert!(
            d.iter().any(|l| l.contains(want)),
            "{want}: {:?}",
            &d[..d.len().min(3)]
        );
    }
    let opts = IdlOptions {
        max_file_size: 10,
        ..IdlOptions::default()
    };
    let set = idl::read(&[SourceFile::new("big.idl", vec![b' '; 11])], &opts);
    assert!(diags(&set)[0].contains("error[RTC024]: file is larger than the limit of 10 bytes"));
    let opts = IdlOptions {
        max_tokens: 100,
        ..IdlOptions::default()
    };
    let set = idl::read(&[SourceFile::new("many.idl", "long ".repeat(200))], &opts);
    assert!(
        diags(&set)
            .iter()
            .any(|d| d.contains("more than 100 tokens")),
        "{:?}",
        diags(&set)
    );
}

#[test]
fn json_round_trip() {
    let set = data_types();
    for f in &set.files {
        let json = serde_json::to_string(f).unwrap();
        let back: IdlFile = serde_json::from_str(&json).unwrap();
        assert_eq!(&back, f);
        assert!(json.contains("\"scopedName\""));
    }
    let v = serde_json::to_value(strukt(&set, "RTC::TimedFoo")).unwrap();
    assert_eq!(v["fields"][0]["type"]["kind"], "named");
    assert_eq!(v["fields"][0]["type"]["resolved"], "RTC::Time");
    assert_eq!(v["fields"][1]["type"]["name"], "double");
}

#[test]
fn unresolved_types_are_noted_once_per_file() {
    let set = one("u.idl", "struct S { Time a; Time b; sequence<Other> c; };");
    assert_eq!(
        diags(&set),
        [
            "u.idl:1:17: info[RTC029]: type `Time` is not defined in any IDL file read",
            "u.idl:1:44: info[RTC029]: type `Other` is not defined in any IDL file read",
        ]
    );
    let set = one("r.idl", "struct S { long a; }; struct S { long b; };");
    assert!(diags(&set)[0].starts_with(
        "r.idl:1:23: warning[RTC028]: `S` is declared again (first at line 1, column 1)"
    ));
}

mod fuzz {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig { cases: 300, ..ProptestConfig::default() })]

        #[test]
        fn arbitrary_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..400)) {
            let _ = idl::read(&[SourceFile::new("f.idl", bytes)], &IdlOptions::default());
        }

        #[test]
        fn mutated_valid_idl_never_panics(cut in 0usize..4000, len in 0usize..40, ins in "[{}();:<>,#/*\"'a-z0-9 \n]{0,8}") {
            let base = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/idl/MyService.idl")).unwrap()
                + &std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/idl/MyDataTypes.idl")).unwrap();
            let b = base.as_bytes();
            let at = cut.min(b.len());
            let end = (at + len).min(b.len());
            let mut m = b[..at].to_vec();
            m.extend_from_slice(ins.as_bytes());
            m.extend_from_slice(&b[end..]);
            let set = idl::read(&[SourceFile::new("m.idl", m)], &IdlOptions::default());
            for d in &set.diagnostics {
                prop_assert!(!d.message.is_empty());
            }
        }
    }
}

/// `typedef struct X {…} Y;` (and its union and enum forms, as CORBA service IDL writes them)
/// declares X where the typedef stands and Y as its alias.
#[test]
fn a_struct_union_or_enum_declared_in_a_typedef_is_read() {
    let set = one(
        "Life.idl",
        "module Life {\n\
         /// A name and its value.\n\
         typedef struct NameValuePair { string name; long value; } NVP;\n\
         typedef sequence<NVP> Criteria;\n\
         typedef enum Colour { RED, GREEN } Col, Hue;\n\
         typedef union Choice switch (long) { case 1: long a; default: double b; } Pick;\n\
         struct After { Col c; NVP p; };\n\
         };\n",
    );
    assert!(set.diagnostics.is_empty(), "{:?}", diags(&set));
    assert!(matches!(
        def(&set, "Life::NameValuePair"),
        IdlDefinition::Struct(_)
    ));
    assert!(matches!(def(&set, "Life::Colour"), IdlDefinition::Enum(_)));
    assert!(matches!(def(&set, "Life::Choice"), IdlDefinition::Union(_)));
    for (alias, of) in [
        ("Life::NVP", "Life::NameValuePair"),
        ("Life::Col", "Life::Colour"),
        ("Life::Hue", "Life::Colour"),
        ("Life::Pick", "Life::Choice"),
    ] {
        let IdlDefinition::Typedef(t) = def(&set, alias) else {
            panic!("{alias} is no typedef")
        };
        assert_eq!(named(&t.ty).1, Some(of), "{alias}");
    }
    let IdlDefinition::Typedef(t) = def(&set, "Life::NVP") else {
        panic!()
    };
    assert!(
        t.doc
            .as_ref()
            .is_some_and(|d| d.text.contains("A name and its value")),
        "{:?}",
        t.doc
    );
    assert!(set.find("Life::Criteria").is_some() && set.find("Life::After").is_some());
}

/// A name an interface inherits is found in its scope: a base's exception in `raises`, a base's
/// struct as a return type, through two levels of inheritance and across modules.
#[test]
fn names_an_interface_inherits_are_found() {
    let set = one(
        "Naming.idl",
        "module Naming {\n\
         interface Base { exception NotFound { string why; }; struct Goal { double x; }; };\n\
         interface Mid : Base {};\n\
         };\n\
         module Ext {\n\
         interface Leaf : Naming::Mid {\n\
         Goal lookup(in string name) raises(NotFound);\n\
         };\n\
         interface Loop1 : Loop2 {}; interface Loop2 : Loop1 { Missing m(); };\n\
         };\n",
    );
    let unresolved: Vec<String> = diags(&set)
        .into_iter()
        .filter(|d| d.contains("RTC029"))
        .collect();
    assert_eq!(unresolved.len(), 1, "{unresolved:?}");
    assert!(unresolved[0].contains("`Missing`"), "{unresolved:?}");
    let leaf = interface(&set, "Ext::Leaf");
    let op = &leaf.operations[0];
    assert_eq!(
        named(op.return_type.as_ref().unwrap()).1,
        Some("Naming::Base::Goal")
    );
    assert_eq!(named(&op.raises[0]).1, Some("Naming::Base::NotFound"));
}

/// A `#pragma version`/`ID` name is looked up as IDL names are: in the scope the pragma stands
/// in, then in each enclosing one, so a pragma inside a module may name the module itself.
#[test]
fn a_pragma_may_name_its_enclosing_module() {
    let set = one(
        "poa.idl",
        "#pragma prefix \"omg.org\"\n\
         module PortableServer {\n\
         #pragma version PortableServer 2.3\n\
         exception ForwardRequest { long forward_reference; };\n\
         #pragma version ForwardRequest 2.3\n\
         struct Inner { long x; };\n\
         #pragma ID Inner \"IDL:own/Inner:9.9\"\n\
         };\n",
    );
    assert!(set.diagnostics.is_empty(), "{:?}", diags(&set));
    let id = |n: &str| match def(&set, n) {
        IdlDefinition::Module(m) => m.repository_id.clone(),
        IdlDefinition::Exception(e) => e.repository_id.clone(),
        IdlDefinition::Struct(s) => s.repository_id.clone(),
        other => panic!("{n} is a {}", other.kind_word()),
    };
    assert_eq!(id("PortableServer"), "IDL:omg.org/PortableServer:2.3");
    assert_eq!(
        id("PortableServer::ForwardRequest"),
        "IDL:omg.org/PortableServer/ForwardRequest:2.3"
    );
    assert_eq!(id("PortableServer::Inner"), "IDL:own/Inner:9.9");
}

/// A `///` after a declaration's `;` or `,` on its own line describes that declaration, as
/// `///<` does (a real pattern: it was read as the next member's doc, moving every text one
/// member down and losing the last); one on a line of its own still describes the next.
#[test]
fn a_same_line_doc_comment_describes_its_own_member() {
    let set = one(
        "Map.idl",
        "module Lab {\n  enum Style { BYTE, /// One byte a cell.\n    TWO_BIT /// Two bits.\n  };\n  struct Map {\n    Style style; /// How cells are stored.\n    /// The cells.\n    sequence<octet> cells;\n    double resolution; /// Metres per cell.\n  };\n};\n",
    );
    let map = strukt(&set, "Lab::Map");
    let docs: Vec<&str> = map.fields.iter().map(|f| brief(&f.doc)).collect();
    assert_eq!(
        docs,
        ["How cells are stored.", "The cells.", "Metres per cell."],
        "{:?}",
        diags(&set)
    );
    let IdlDefinition::Enum(style) = def(&set, "Lab::Style") else {
        panic!("an enum");
    };
    let docs: Vec<&str> = style.values.iter().map(|v| brief(&v.doc)).collect();
    assert_eq!(docs, ["One byte a cell.", "Two bits."]);
}

/// A syntax error at a name a macro replaced says so, and the fix it names works: an include
/// guard named like the module (`#define A`, then `module A {`) and a macro with a value.
#[test]
fn an_error_at_a_macro_name_says_the_preprocessor_replaced_it() {
    let guard = "#ifndef A\n#define A\nmodule A {\n  struct S { long x; };\n};\n#endif\n";
    let set = one("idl/A.idl", guard);
    let hints: Vec<&str> = set
        .diagnostics
        .iter()
        .filter_map(|d| d.hint.as_deref())
        .collect();
    assert_eq!(hints, ["`A` here is a macro defined empty at idl/A.idl:2:1 (an include guard?), so the preprocessor removed it: give the macro another name (`A_IDL`) or rename this `A`"], "{:?}", diags(&set));
    // Followed: the guard renamed, the file reads.
    let set = one(
        "idl/A.idl",
        &guard
            .replace("ifndef A\n", "ifndef A_IDL\n")
            .replace("define A\n", "define A_IDL\n"),
    );
    assert!(set.diagnostics.is_empty(), "{:?}", diags(&set));
    assert!(set.find("A::S").is_some());
    // A macro with a value.
    let set = one("idl/P.idl", "#define Pose 1\nstruct Pose { long x; };\n");
    let d = &set.diagnostics[0];
    assert_eq!(d.hint.as_deref(), Some("`Pose` here is a macro defined at idl/P.idl:1:1 as `1`, so the preprocessor replaced it: give the macro another name (`Pose_IDL`) or rename this `Pose`"), "{:?}", diags(&set));
    // An error elsewhere keeps its own hint.
    let set = one("idl/Q.idl", "#define X\nstruct { long x; };\n");
    assert!(
        set.diagnostics[0]
            .hint
            .as_deref()
            .is_some_and(|h| !h.contains("macro")),
        "{:?}",
        diags(&set)
    );
}

/// A `<…>` include that is not found is a warning like a quoted one: `<BasicDataType.idl>` is
/// how labs include OpenRTM's data types, and without them its macros and guards are unknown
/// (an info, shown only with --verbose, hid that). Only an ORB's own file (`<orb.idl>`, TAO's
/// and omniORB's folders), which no project has among its IDL, stays an info.
#[test]
fn an_angle_include_not_found_is_a_warning_unless_the_orb_supplies_it() {
    let set = one(
        "idl/Lab.idl",
        "#include <BasicDataType.idl>\n#include <rtm/idl/ExtendedDataTypes.idl>\n#include <orb.idl>\n#include <tao/TimeBase.pidl>\n#include <omniORB4/CORBA.idl>\nmodule Lab { struct S { long a; }; };\n",
    );
    assert_eq!(
        diags(&set),
        [
            "idl/Lab.idl:1:1: warning[RTC022]: included file <BasicDataType.idl> was not found among the IDL files read",
            "idl/Lab.idl:2:1: warning[RTC022]: included file <rtm/idl/ExtendedDataTypes.idl> was not found among the IDL files read",
            "idl/Lab.idl:3:1: info[RTC022]: included file <orb.idl> was not found among the IDL files read",
            "idl/Lab.idl:4:1: info[RTC022]: included file <tao/TimeBase.pidl> was not found among the IDL files read",
            "idl/Lab.idl:5:1: info[RTC022]: included file <omniORB4/CORBA.idl> was not found among the IDL files read",
        ]
    );
}

/// An include is looked for as a C preprocessor with the IDL path as its `-I` folders looks for
/// it: in the including file's own folder, then its own tree (the input directory or its own
/// `[[source]]`), then the IDL path. Another source's copy of the file is not on that include
/// path: it is not used (it was, silently: `labB`'s `BasicDataType.idl` satisfied `labA`'s
/// include), and the warning names it.
#[test]
fn an_include_is_not_taken_from_another_sources_tree() {
    use rtcdoc::idl::Tree;
    let main = "#include \"BasicDataType.idl\"\nmodule A { struct S { long a; }; };\n";
    let basic =
        "#ifndef BASIC\n#define BASIC\nmodule RTC { struct Time { long sec; }; };\n#endif\n";
    let file = |path: &str, text: &str, tree: Tree| SourceFile::new(path, text).in_tree(tree);
    let a = || Tree::Source("labA".into());
    let b = || Tree::Source("labB".into());
    let resolved = |set: &IdlSet| set.files[0].includes[0].resolved.clone();
    // Only another source has the file: not resolved, and the warning names both files.
    let set = read(vec![
        file("labA/idl/Main.idl", main, a()),
        file("labB/idl/BasicDataType.idl", basic, b()),
    ]);
    assert_eq!(resolved(&set), None);
    let d = &set.diagnostics[0];
    assert_eq!((d.code, d.file.as_str()), ("RTC022", "labA/idl/Main.idl"));
    assert_eq!(
        d.message,
        "included file \"BasicDataType.idl\" was not found in the source `labA` or on the IDL path; the source `labB` has `labB/idl/BasicDataType.idl`, which is not used: the files of the source `labB` are not on the include path of the source `labA`"
    );
    assert!(
        d.hint.as_deref().unwrap_or("").contains("--idl-path"),
        "{d:?}"
    );
    assert_eq!(set.diagnostics.len(), 1, "{:?}", diags(&set));
    // The IDL path is searched from every tree, by its folder or by file name.
    let on_path = |search_path: Vec<String>| {
        let opts = IdlOptions {
            search_path,
            ..IdlOptions::default()
        };
        idl::read(
            &[
                file("labA/idl/Main.idl", main, a()),
                file("labB/idl/BasicDataType.idl", basic, b()),
                file("idl/BasicDataType.idl", basic, Tree::SearchPath),
            ],
            &opts,
        )
    };
    for search_path in [vec!["idl".to_string()], Vec::new()] {
        let set = on_path(search_path);
        assert_eq!(resolved(&set).as_deref(), Some("idl/BasicDataType.idl"));
        assert!(set.diagnostics.is_empty(), "{:?}", diags(&set));
    }
    // The own source's copy comes before the IDL path's, wherever it is in the source.
    let set = read(vec![
        file("labA/idl/Main.idl", main, a()),
        file("labA/vendor/rtm/BasicDataType.idl", basic, a()),
        file("labB/idl/BasicDataType.idl", basic, b()),
        file("idl/BasicDataType.idl", basic, Tree::SearchPath),
    ]);
    assert_eq!(
        resolved(&set).as_deref(),
        Some("labA/vendor/rtm/BasicDataType.idl")
    );
    // The input directory is a tree of its own too: a source's copy does not serve it.
    let set = read(vec![
        SourceFile::new("idl/Main.idl", main),
        file("labB/idl/BasicDataType.idl", basic, b()),
    ]);
    assert_eq!(resolved(&set), None);
    assert!(set.diagnostics[0]
        .message
        .contains("was not found in the input directory or on the IDL path; the source `labB` has `labB/idl/BasicDataType.idl`"));
}
