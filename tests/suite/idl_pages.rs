//! IDL on the pages: data-type and interface pages show their definitions (fields with types
//! and doc comments, enum values, operations with parameters), types with pages are linked,
//! `--idl-path` adds IDL outside the input (shown by a relative path), `catalog.json` carries
//! the files, and IDL findings are reported like the profiles'.

use crate::common;
use common::*;
use std::path::Path;

fn read(p: &Path) -> String {
    common::read_page(p)
}

fn stderr(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn example_type_and_interface_pages_show_their_idl() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("site");
    let b = rtcdoc(&["build", "examples", "-o", out.to_str().unwrap()], &root());
    assert!(b.status.success(), "{}", stderr(&b));
    let t = read(&out.join("types/detection-timedobjectlist.html"));
    assert!(
        t.contains("Defined in <code>idl/Detection.idl:38</code>"),
        "{t}"
    );
    assert!(t.contains("IDL:Detection/TimedObjectList:1.0"));
    assert!(t.contains("<p>The detections of one processed image.</p>"));
    assert!(t.contains("<tr id=\"field-tm\"><td data-label=\"Field\"><code>tm</code></td><td data-label=\"Type\"><a href=\"../types/example-time.html\"><code>Example::Time</code></a></td><td data-label=\"Description\">Capture time of the image</td></tr>"), "{t}");
    assert!(t.contains("<tr id=\"field-data\">"));
    let i = read(&out.join("interfaces/detection-modelrepository.html"));
    assert!(i.contains("id=\"op-fetch\""), "{i}");
    assert!(i.contains("<code><strong>fetch</strong>(</code><code>in </code><code>string</code> <code>name</code>"), "{i}");
    assert!(i.contains("<code>raises (</code><a href=\"../types/detection-notfound.html\"><code>NotFound</code></a>"));
    assert!(i.contains("<dd>true when the model came from the local cache</dd>"));
    assert!(i.contains("<code>models</code> (read-only)"));
    let c = read(&out.join("interfaces/camera-cameracontrol.html"));
    assert!(
        c.contains("id=\"op-setExposure\"")
            && c.contains("Sets the exposure time for MANUAL mode."),
        "{c}"
    );
    // Types reachable through fields have pages of their own, linked both ways.
    assert!(
        t.contains("<a href=\"../types/example-time.html\"><code>Example::Time</code></a>"),
        "{t}"
    );
    assert!(
        t.contains("<a href=\"../types/detection-objectlist.html\"><code>ObjectList</code></a>"),
        "{t}"
    );
    let list = read(&out.join("types/detection-objectlist.html"));
    assert!(list.contains("<code>typedef</code>") && list.contains("<a href=\"../types/detection-detectedobject.html\"><code>sequence&lt;DetectedObject&gt;</code></a>"), "{list}");
    assert!(list.contains("<a href=\"../types/detection-timedobjectlist.html\"><code>Detection::TimedObjectList</code></a>"), "{list}");
    let bbox = read(&out.join("types/detection-boundingbox.html"));
    assert!(bbox.contains("id=\"contained-in\"") && bbox.contains("Detection::DetectedObject"));
    assert!(
        bbox.contains("<td data-label=\"Description\">Left edge</td>"),
        "{bbox}"
    );
    // Enum values and exceptions reachable from an interface.
    let mode = read(&out.join("types/camera-exposuremode.html"));
    assert!(
        mode.contains(
            "<tr id=\"value-AUTO\"><td data-label=\"Name\"><code>AUTO</code></td><td data-label=\"Description\">The camera decides</td></tr>"
        ),
        "{mode}"
    );
    assert!(out.join("types/detection-notfound.html").is_file());
    let index = read(&out.join("types/index.html"));
    assert!(index.contains("detection-boundingbox.html"));
    // A type no IDL defines has no definition section.
    let l = read(&out.join("types/rtc-timedlong.html"));
    assert!(!l.contains("id=\"definition\""));
    // Japanese labels.
    let ja = dir.path().join("ja");
    let b = rtcdoc(
        &[
            "build",
            "examples",
            "--language",
            "ja",
            "-o",
            ja.to_str().unwrap(),
        ],
        &root(),
    );
    assert!(b.status.success());
    assert!(read(&ja.join("types/detection-timedobjectlist.html")).contains("フィールド"));
}

/// A lab's own types outside the input, through `--idl-path`: nested types that are port types
/// link to each other's pages; the file is shown relative to the IDL directory.
#[test]
fn idl_path_types_are_resolved_and_linked() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(
        d,
        "in/a/RTC.xml",
        &xml_profile(
            "A",
            &[
                ("DataOutPort", "pose", "Lab::Pose"),
                ("DataOutPort", "stamped", "Lab::StampedPose"),
            ],
        ),
    );
    write(
        d,
        "shared-idl/lab/Lab.idl",
        "module Lab {\n  /// A position.\n  struct Pose { double x; ///< metres\n double y; };\n  struct StampedPose { unsigned long long stamp; Pose pose; ///< where\n sequence<Pose> trail; };\n};\n",
    );
    let out = d.join("site");
    let b = rtcdoc(
        &["build", "in", "-o", "site", "--idl-path", "shared-idl"],
        d,
    );
    assert!(b.status.success(), "{}", stderr(&b));
    let s = read(&out.join("types/lab-stampedpose.html"));
    assert!(
        s.contains("Defined in <code>shared-idl/lab/Lab.idl:5</code>"),
        "{s}"
    );
    assert!(
        !s.contains(&d.to_string_lossy().to_string()),
        "absolute path on the page"
    );
    assert!(
        s.contains("<a href=\"../types/lab-pose.html\"><code>Pose</code></a>"),
        "{s}"
    );
    assert!(
        s.contains("<a href=\"../types/lab-pose.html\"><code>sequence&lt;Pose&gt;</code></a>"),
        "{s}"
    );
    let p = read(&out.join("types/lab-pose.html"));
    assert!(
        p.contains("<p>A position.</p>")
            && p.contains("<td data-label=\"Description\">metres</td>"),
        "{p}"
    );
    // Without the IDL path: no definition, and the build says nothing about it.
    let b = rtcdoc(&["build", "in", "-o", "site2"], d);
    assert!(b.status.success());
    assert!(!read(&d.join("site2/types/lab-pose.html")).contains("id=\"definition\""));
    // The JSON carries the IDL files and their definitions.
    let j = rtcdoc(
        &[
            "build",
            "in",
            "-f",
            "json",
            "-o",
            "j",
            "--idl-path",
            "shared-idl",
        ],
        d,
    );
    assert!(j.status.success());
    let v: serde_json::Value = serde_json::from_str(&read(&d.join("j/catalog.json"))).unwrap();
    let files = v["idl"]["files"].as_array().expect("idl.files");
    assert_eq!(files[0]["path"], "shared-idl/lab/Lab.idl");
    let text = serde_json::to_string(&files[0]).unwrap();
    assert!(
        text.contains("\"StampedPose\"") && text.contains("metres"),
        "{text}"
    );
    // Without IDL, catalog.json has no idl key (unchanged for IDL-less catalogues).
    let j = rtcdoc(&["build", "in", "-f", "json", "-o", "j2"], d);
    assert!(j.status.success());
    assert!(!read(&d.join("j2/catalog.json")).contains("\"idl\""));
    // A missing --idl-path directory is an error (exit 2).
    let m = rtcdoc(&["build", "in", "-o", "site3", "--idl-path", "nope"], d);
    assert_eq!(m.status.code(), Some(2), "{}", stderr(&m));
    assert!(stderr(&m).contains("--idl-path `nope`"), "{}", stderr(&m));
}

#[test]
fn idl_findings_are_reported_with_their_position() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(
        d,
        "in/a/RTC.xml",
        &xml_profile("A", &[("DataOutPort", "p", "M::S")]),
    );
    write(
        d,
        "in/idl/Bad.idl",
        "module M {\n  struct S { long x }; \n};\n",
    );
    let out = rtcdoc(&["check", "in", "--format", "json"], d);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let idl: Vec<&serde_json::Value> = v["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|x| x["code"] == "RTC020")
        .collect();
    assert_eq!(idl.len(), 1, "{v}");
    assert_eq!(idl[0]["file"], "in/idl/Bad.idl");
    assert_eq!(idl[0]["line"], 2);
    let b = rtcdoc(&["build", "in", "-o", "site"], d);
    assert!(stderr(&b).contains("in/idl/Bad.idl:2:"), "{}", stderr(&b));
    // An input of IDL alone is something to document.
    write(d, "only/X.idl", "module X { struct Y { long z; }; };\n");
    assert!(rtcdoc(&["check", "only"], d).status.success());
}

/// Markdown and Doxygen pages carry the same definitions, with the same links.
#[test]
fn markdown_and_doxygen_show_the_idl_too() {
    let dir = tempfile::tempdir().unwrap();
    let md = dir.path().join("md");
    let b = rtcdoc(
        &[
            "build",
            "examples",
            "-f",
            "markdown",
            "-o",
            md.to_str().unwrap(),
        ],
        &root(),
    );
    assert!(b.status.success(), "{}", stderr(&b));
    let t = read(&md.join("types/detection-timedobjectlist.md"));
    assert!(t.contains("## Definition (struct)"), "{t}");
    assert!(t.contains("Defined in idl/Detection.idl:38"));
    assert!(
        t.contains(
            "| tm | [Example::Time](../types/example-time.md) | Capture time of the image |"
        ),
        "{t}"
    );
    let i = read(&md.join("interfaces/detection-modelrepository.md"));
    assert!(i.contains("| fetch | boolean | in string name: Model file name, e.g. \\\"yolov5s.onnx\\\"; out [ModelData](../types/detection-modeldata.md) data: The model as bytes | [NotFound](../types/detection-notfound.md) |"), "{i}");
    assert!(md.join("types/detection-boundingbox.md").is_file());
    let dox = dir.path().join("dox");
    let b = rtcdoc(
        &[
            "build",
            "examples",
            "-f",
            "doxygen",
            "-o",
            dox.to_str().unwrap(),
        ],
        &root(),
    );
    assert!(b.status.success(), "{}", stderr(&b));
    let t = read(&dox.join("types/detection-timedobjectlist.dox"));
    assert!(
        t.contains("Capture time of the image") && t.contains("\\ref rtc_type_example_time"),
        "{t}"
    );
    let i = read(&dox.join("interfaces/detection-modelrepository.dox"));
    assert!(
        i.contains("fetch") && i.contains("\\ref rtc_type_detection_notfound"),
        "{i}"
    );
}

/// Type pages name the `idlFile`s by file name, not by the authors' absolute paths.
#[test]
fn type_pages_do_not_lead_with_absolute_idl_paths() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let p = xml_profile("A", &[("DataOutPort", "out", "RTC::TimedLong")]).replace(
        "rtcExt:position=\"LEFT\"/>",
        "rtcExt:position=\"LEFT\" rtc:idlFile=\"C:\\Program Files\\OpenRTM-aist\\1.2.2\\rtm\\idl\\BasicDataType.idl\"/>",
    );
    write(d, "in/a/RTC.xml", &p);
    write(
        d,
        "in/b/RTC.xml",
        &p.replace("RTC:Test:Cat:A:", "RTC:Test:Cat:B:")
            .replace("rtc:name=\"A\"", "rtc:name=\"B\"")
            .replace(
                "C:\\Program Files\\OpenRTM-aist\\1.2.2\\rtm\\idl\\",
                "/usr/include/openrtm-1.2/rtm/idl/",
            ),
    );
    let b = rtcdoc(&["build", "in", "-o", "site"], d);
    assert!(b.status.success(), "{}", stderr(&b));
    let t = read(&d.join("site/types/rtc-timedlong.html"));
    assert!(t.contains("<code>BasicDataType.idl</code></dd>"), "{t}");
    assert!(
        !t.contains("Program Files") && !t.contains("/usr/include"),
        "{t}"
    );
    // The component page keeps the value as written.
    let c = read(&d.join("site/components/a.html"));
    assert!(c.contains("Program Files"), "{c}");
}

/// A type that no IDL file read defines: its page says where the definition would come from, in
/// every output, and `check` names it at default verbosity.
#[test]
fn a_type_without_idl_says_where_its_definition_would_come_from() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    write(
        &input,
        "c/RTC.xml",
        &xml_profile("c", &[("DataInPort", "pose", "RTC::TimedPose2D")]),
    );
    let o = rtcdoc(
        &["build", "in", "-o", "site", "-f", "html,markdown,doxygen"],
        dir.path(),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let hint = "Defined in no IDL file read, so its definition is not shown: add the IDL file below the input, pass --idl-path DIR, or let rtcdoc init find an OpenRTM installation.";
    let html = read(&dir.path().join("site/html/types/rtc-timedpose2d.html"));
    assert!(
        html.contains(&format!("<p class=\"no-definition\">{hint}</p>")),
        "{html}"
    );
    let md = read(&dir.path().join("site/markdown/types/rtc-timedpose2d.md"));
    assert!(md.contains("Defined in no IDL file read"), "{md}");
    let dox = std::fs::read_dir(dir.path().join("site/doxygen/types"))
        .unwrap()
        .map(|e| read(&e.unwrap().path()))
        .collect::<String>();
    assert!(dox.contains("Defined in no IDL file read"), "{dox}");
    let o = rtcdoc(&["check", "in"], dir.path());
    let err = stderr(&o);
    assert!(
        err.contains("note: no IDL file was read: the pages of 1 data type(s) and interface(s) show no definition (RTC::TimedPose2D)"),
        "{err}"
    );
    // With IDL that defines it, the note and the sentence go.
    write(
        &input,
        "idl/Pose.idl",
        "module RTC { struct Time { unsigned long sec; unsigned long nsec; }; struct Pose2D { double x; }; struct TimedPose2D { Time tm; Pose2D data; }; };\n",
    );
    let o = rtcdoc(&["check", "in"], dir.path());
    assert!(!stderr(&o).contains("show no definition"), "{}", stderr(&o));
}

/// With a configuration file, the note points at its `idl-path` (`rtcdoc init` would refuse
/// to overwrite it), and following it works.
#[test]
fn with_a_configuration_the_note_points_at_its_idl_path() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(
        d,
        "in/c/RTC.xml",
        &xml_profile("c", &[("DataInPort", "pose", "RTC::TimedPose2D")]),
    );
    write(d, "in/rtcdoc.toml", "title = \"Lab\"\n");
    write(
        d,
        "openrtm-idl/Pose.idl",
        "module RTC { struct Time { unsigned long sec; unsigned long nsec; }; struct Pose2D { double x; }; struct TimedPose2D { Time tm; Pose2D data; }; };\n",
    );
    let err = stderr(&rtcdoc(&["check", "in"], d));
    assert!(err.contains("or set `idl-path` in in/rtcdoc.toml"), "{err}");
    assert!(!err.contains("rtcdoc init"), "{err}");
    let idl = d.join("openrtm-idl");
    write(
        d,
        "in/rtcdoc.toml",
        &format!(
            "title = \"Lab\"\nidl-path = [{:?}]\n",
            idl.to_string_lossy()
        ),
    );
    let err = stderr(&rtcdoc(&["check", "in"], d));
    assert!(!err.contains("show no definition"), "{err}");
}

/// A project's own IDL may add to module `RTC` without copying OpenRTM's: a type of OpenRTM's
/// own `RTC` module that no IDL read defines is an info (its IDL was not given), while a type
/// of the project's, missing from the module the project's IDL declares, stays a warning.
#[test]
fn openrtm_s_own_types_missing_beside_a_project_s_module_rtc_are_an_info() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    write(
        &input,
        "c/RTC.xml",
        &xml_profile(
            "c",
            &[
                ("DataInPort", "pose", "RTC::TimedPose2D"),
                ("DataOutPort", "plan", "RTC::PlanMisspelt"),
            ],
        ),
    );
    write(
        &input,
        "c/idl/Follower.idl",
        "module RTC { struct Plan { double x; }; };\n",
    );
    let o = rtcdoc(&["check", "in", "--format", "json"], dir.path());
    let json: serde_json::Value = serde_json::from_slice(&o.stdout).expect("json");
    let severity = |ty: &str| -> String {
        json["diagnostics"]
            .as_array()
            .expect("diagnostics")
            .iter()
            .find(|d| d["code"] == "RTC403" && d["message"].as_str().unwrap_or("").contains(ty))
            .map(|d| d["severity"].as_str().unwrap_or("").to_string())
            .unwrap_or_else(|| panic!("no RTC403 for {ty}: {json:#}"))
    };
    assert_eq!(severity("RTC::TimedPose2D"), "info");
    assert_eq!(severity("RTC::PlanMisspelt"), "warning");
}

/// RTC403 names what the author may have meant: the type of the same last name in another
/// module (`Img::CameraCaptureService` for `OpenHRP::CameraCaptureService`), or a near
/// spelling; a name like none of the IDL's gets the usual hint only.
#[test]
fn a_type_not_in_the_idl_is_given_its_near_matches() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    let profile = xml_profile(
        "c",
        &[
            ("DataInPort", "pose", "Lab::Pse"),
            ("DataOutPort", "other", "Lab::Unrelated"),
        ],
    )
    .replace(
        "</rtc:RtcProfile>",
        r#"  <rtc:ServicePorts xsi:type="rtcExt:serviceport_ext" rtc:name="cam" rtcExt:position="LEFT">
    <rtc:ServiceInterface xsi:type="rtcExt:serviceinterface_ext" rtc:name="capture" rtc:type="OpenHRP::CameraCaptureService" rtc:direction="Required" rtc:idlFile="CameraCaptureService.idl"/>
  </rtc:ServicePorts>
</rtc:RtcProfile>"#,
    );
    write(&input, "c/RTC.xml", &profile);
    write(
        &input,
        "c/idl/Lab.idl",
        "module Lab { struct Pose { double x; }; };\nmodule Img { interface CameraCaptureService { void take(); }; };\nmodule OpenHRP { struct Other { long a; }; };\n",
    );
    let o = rtcdoc(&["check", "in", "--format", "json"], dir.path());
    let json: serde_json::Value = serde_json::from_slice(&o.stdout).expect("json");
    let hint = |ty: &str| -> String {
        json["diagnostics"]
            .as_array()
            .expect("diagnostics")
            .iter()
            .find(|d| d["code"] == "RTC403" && d["message"].as_str().unwrap_or("").contains(ty))
            .map(|d| d["hint"].as_str().unwrap_or("").to_string())
            .unwrap_or_else(|| panic!("no RTC403 for {ty}: {json:#}"))
    };
    let cam = hint("OpenHRP::CameraCaptureService");
    assert!(
        cam.starts_with("did you mean `Img::CameraCaptureService`?"),
        "{cam}"
    );
    let pose = hint("Lab::Pse");
    assert!(pose.starts_with("did you mean `Lab::Pose`?"), "{pose}");
    let other = hint("Lab::Unrelated");
    assert!(!other.contains("did you mean"), "{other}");
    assert!(other.contains("--idl-path"), "{other}");
}

/// An IDL file's types that no port uses have no page: the build and `check` say so, naming
/// them (an input of IDL alone built an empty site without a word), and catalog.json has them.
/// A type a port uses, and the types inside it, are not named.
#[test]
fn idl_types_on_no_page_are_named() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    common::write(
        d,
        "in/idl/Lab.idl",
        "module Lab {\n  struct Point2D { double x; double y; };\n  struct Pose { Point2D position; double heading; };\n  interface Ranger { double range(); };\n  struct Orphan { long a; };\n};\n",
    );
    let note = |args: &[&str]| -> String {
        let o = common::rtcdoc(args, d);
        let err = String::from_utf8_lossy(&o.stderr).into_owned();
        err.lines()
            .find(|l| l.contains("are on no page"))
            .unwrap_or("")
            .to_string()
    };
    let built = note(&["build", "in", "-o", "site", "-f", "html,json"]);
    assert!(
        built.starts_with("note: 3 type(s) and interface(s) that the IDL files below the input define are on no page (Lab::Point2D, Lab::Pose, Lab::Orphan)"),
        "{built}"
    );
    let json = std::fs::read_to_string(d.join("site/json/catalog.json")).unwrap();
    assert!(json.contains("Lab::Orphan"), "catalog.json has them");
    // Every interface of the input's IDL has a page, used by a port or not (#55).
    assert!(d.join("site/html/interfaces/lab-ranger.html").is_file());
    // A port uses Pose: it and the Point2D inside it get pages; Orphan is still named.
    common::write(
        d,
        "in/Nav/RTC.xml",
        &common::xml_profile("Nav", &[("DataInPort", "pose", "Lab::Pose")]),
    );
    let checked = note(&["check", "in"]);
    assert!(
        checked.starts_with("note: 1 type(s) and interface(s) that the IDL files below the input define are on no page (Lab::Orphan)"),
        "{checked}"
    );
}

/// Everything an IDL comment says reaches the type and interface pages of every output: the
/// text after the first sentence, `@section`s, `@exception`, `@pre`/`@post`, a member's second
/// sentence; inline commands (`@c`, `\ref`) keep their words; a Japanese site shows the `@if jp`
/// part of a bilingual comment, and a comment written only in Japanese shows on both.
#[test]
fn every_part_of_an_idl_comment_is_on_its_pages() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(
        d,
        "in/Arm/RTC.xml",
        &xml_profile("Arm", &[("DataInPort", "pose", "Lab::Pose")]),
    );
    let profile = read(&d.join("in/Arm/RTC.xml")).replace(
        "</rtc:RtcProfile>",
        "<rtc:ServicePorts rtc:name=\"arm\"><rtc:ServiceInterface rtc:name=\"arm\" rtc:type=\"Lab::Arm\" rtc:direction=\"Provided\" rtc:instanceName=\"arm\" rtc:idlFile=\"Lab.idl\"/></rtc:ServicePorts></rtc:RtcProfile>",
    );
    assert!(profile.contains("Lab::Arm"));
    write(d, "in/Arm/RTC.xml", &profile);
    write(
        d,
        "in/Arm/idl/Lab.idl",
        "module Lab {\n\
  /*!\n   * @if jp\n   * @brief 腕のサービス\n   * @else\n   * @brief Moves the arm.\n   *\n   * @section Description\n   * Sends motion commands to the controller.\n   * @endif\n   */\n\
  interface Arm {\n\
    /*!\n     * Start a motion. Returns at once.\n     * @param target goal in metres\n     * @return @c true when accepted\n     * @exception Busy when already moving\n     * @pre the arm is homed\n     * @post the arm moves\n     */\n\
    boolean move(in double target);\n\
    /*!\n     * @if jp\n     * 止める。\n     * @endif\n     */\n\
    void stop();\n\
  };\n\
  /// A pose. See \\ref Arm for the frame.\n\
  struct Pose {\n\
    double x; ///< X in metres. Positive forward.\n\
  };\n\
};\n",
    );
    let o = rtcdoc(
        &["build", "in", "-o", "site", "-f", "html,markdown,doxygen"],
        d,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let all = |format: &str, folder: &str| -> String {
        std::fs::read_dir(d.join("site").join(format).join(folder))
            .unwrap()
            .map(|e| read(&e.unwrap().path()))
            .collect()
    };
    for (format, types, interfaces) in [
        ("html", "types", "interfaces"),
        ("markdown", "types", "interfaces"),
        ("doxygen", "types", "interfaces"),
    ] {
        let text = all(format, types) + &all(format, interfaces);
        for want in [
            "Moves the arm",
            "Sends motion commands to the controller",
            "Returns at once",
            "Busy",
            "when already moving",
            "the arm is homed",
            "the arm moves",
            "true when accepted",
            "Positive forward",
            "See Arm for the frame",
            // A comment only in Japanese is shown on the English site too.
            "止める",
        ] {
            assert!(text.contains(want), "{format}: {want}");
        }
    }
    let o = rtcdoc(&["build", "in", "-o", "ja", "--language", "ja"], d);
    assert!(o.status.success(), "{}", stderr(&o));
    let html = read(&d.join("ja/interfaces/lab-arm.html"));
    assert!(html.contains("腕のサービス"), "{html}");
    assert!(!html.contains("Moves the arm"), "{html}");
    assert!(html.contains("事前条件: the arm is homed"), "{html}");
}

/// A port type written as a repository id with the `#pragma prefix` of its file (as
/// RTCBuilder writes it) is the type that file defines: one page, `Lab::Pose`, with its
/// definition.
#[test]
fn a_repository_id_with_a_pragma_prefix_is_the_type_it_names() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    common::write(
        d,
        "in/idl/Lab.idl",
        "#pragma prefix \"example.com\"\nmodule Lab {\n  struct Pose { double x; double y; };\n};\n",
    );
    common::write(
        d,
        "in/Nav/RTC.xml",
        &common::xml_profile(
            "Nav",
            &[
                ("DataInPort", "pose", "IDL:example.com/Lab/Pose:1.0"),
                ("DataOutPort", "out", "Lab::Pose"),
            ],
        ),
    );
    let o = common::rtcdoc(
        &["build", "in", "-o", "site", "-f", "html,markdown,json"],
        d,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!stderr(&o).contains("on no page"), "{}", stderr(&o));
    let page = read(&d.join("site/html/types/lab-pose.html"));
    assert!(page.contains("id=\"definition\""), "{page}");
    assert!(page.contains("IDL:example.com/Lab/Pose:1.0"), "{page}");
    assert!(!d.join("site/html/types/example-com-lab-pose.html").exists());
    let md = read(&d.join("site/markdown/types/lab-pose.md"));
    assert!(md.contains("idl/Lab.idl"), "{md}");
    let json = read(&d.join("site/json/catalog.json"));
    assert!(
        !json.contains("\"name\": \"example.com::Lab::Pose\""),
        "{json}"
    );
}

/// The base interfaces of an interface with a page get pages of their own (and the types
/// their operations use), are linked, and their operations and attributes are listed on the
/// derived page, transitively, in every output (a base with attributes only too).
#[test]
fn base_interfaces_have_pages_and_their_operations_are_inherited() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    common::write(
        d,
        "in/idl/Arm.idl",
        "module Lab {\n  struct Cfg { long rate; };\n  interface Root { void ping(); readonly attribute long serial; };\n  interface Base : Root { /** Reads the configuration. */ Cfg get_config(); void reset(); };\n  interface Named { /** The arm's name. */ attribute string label; };\n  interface Arm : Base, Named { void stop(); };\n};\n",
    );
    let service = r#"  <rtc:ServicePorts xsi:type="rtcExt:serviceport_ext" rtcExt:position="RIGHT" rtc:name="armPort">
    <rtc:ServiceInterface xsi:type="rtcExt:serviceinterface_ext" rtc:type="Lab::Arm" rtc:idlFile="idl/Arm.idl" rtc:instanceName="" rtc:direction="Provided" rtc:name="arm"/>
  </rtc:ServicePorts>
</rtc:RtcProfile>"#;
    let p = common::xml_profile("Comp", &[]).replace("</rtc:RtcProfile>", service);
    common::write(d, "in/Comp/RTC.xml", &p);
    let o = common::rtcdoc(
        &[
            "build",
            "in",
            "-o",
            "site",
            "-f",
            "html,markdown,doxygen,json",
        ],
        d,
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!stderr(&o).contains("on no page"), "{}", stderr(&o));
    let s = d.join("site");
    let arm = read(&s.join("html/interfaces/lab-arm.html"));
    assert!(
        arm.contains(
            "Base interfaces: <a href=\"../interfaces/lab-base.html\"><code>Base</code></a>"
        ),
        "{arm}"
    );
    assert!(arm.contains("<h3>Inherited from <a href=\"../interfaces/lab-base.html\"><code>Lab::Base</code></a></h3>"), "{arm}");
    assert!(arm.contains("<li><a href=\"../interfaces/lab-base.html#op-get_config\"><code>get_config</code></a>: Reads the configuration.</li>"), "{arm}");
    assert!(
        arm.contains("#op-reset\"") && arm.contains("../interfaces/lab-root.html#op-ping\""),
        "{arm}"
    );
    assert!(arm.contains("<p>Attributes:</p>\n<ul class=\"idl-inherited\"><li><a href=\"../interfaces/lab-root.html#attr-serial\"><code>serial</code></a> (read-only)</li>"), "{arm}");
    assert!(arm.contains("<h3>Inherited from <a href=\"../interfaces/lab-named.html\"><code>Lab::Named</code></a></h3>\n<p>Attributes:</p>\n<ul class=\"idl-inherited\"><li><a href=\"../interfaces/lab-named.html#attr-label\"><code>label</code></a>: The arm&#39;s name.</li>"), "{arm}");
    let root = read(&s.join("html/interfaces/lab-root.html"));
    assert!(root.contains("<tr id=\"attr-serial\">"), "{root}");
    let base = read(&s.join("html/interfaces/lab-base.html"));
    assert!(base.contains("id=\"op-get_config\""), "{base}");
    assert!(
        base.contains("<a href=\"../types/lab-cfg.html\"><code>Cfg</code></a>"),
        "{base}"
    );
    assert!(s.join("html/interfaces/lab-root.html").is_file());
    let index = read(&s.join("html/interfaces/index.html"));
    assert!(index.contains("lab-base.html"), "{index}");
    let md = read(&s.join("markdown/interfaces/lab-arm.md"));
    assert!(
        md.contains("Base interfaces: [Base](../interfaces/lab-base.md)"),
        "{md}"
    );
    assert!(
        md.contains("Inherited from [Lab::Base](../interfaces/lab-base.md)"),
        "{md}"
    );
    assert!(
        md.contains("| [reset](../interfaces/lab-base.md) |"),
        "{md}"
    );
    assert!(s.join("markdown/interfaces/lab-base.md").is_file());
    assert!(
        md.contains("| [label](../interfaces/lab-named.md) | The arm\\'s name. |"),
        "{md}"
    );
    assert!(
        md.contains("| [serial](../interfaces/lab-root.md) (read-only) |"),
        "{md}"
    );
    let dox = read(&s.join("doxygen/interfaces/lab-arm.dox"));
    assert!(
        dox.contains("\\ref rtc_if_lab_base \"get_config\""),
        "{dox}"
    );
    assert!(dox.contains("\\ref rtc_if_lab_root \"ping\""), "{dox}");
    assert!(dox.contains("\\ref rtc_if_lab_named \"label\""), "{dox}");
    assert!(dox.contains("\\ref rtc_if_lab_root \"serial\""), "{dox}");
    let json = read(&s.join("json/catalog.json"));
    assert!(json.contains("\"name\": \"Lab::Base\""), "{json}");
}

/// A union's `default:` case is labelled once.
#[test]
fn a_union_default_case_is_labelled_once() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    write(
        d,
        "in/C/RTC.xml",
        &xml_profile("C", &[("DataInPort", "u", "Un::U")]),
    );
    write(
        d,
        "in/C/idl/U.idl",
        "module Un { union U switch (long) { case 1: long a; default: octet o; }; };\n",
    );
    let o = rtcdoc(&["build", "in", "-o", "site", "-f", "html,markdown"], d);
    assert!(o.status.success(), "{}", stderr(&o));
    let html = read(&d.join("site/html/types/un-u.html"));
    assert!(html.contains("<code>default</code>"), "{html}");
    assert!(!html.contains("default, default"), "{html}");
    let md = read(&d.join("site/markdown/types/un-u.md"));
    assert!(!md.contains("default, default"), "{md}");
}

/// A column of an interface's tables that is empty in every row is left out (formats.md):
/// `Raises` only where an operation raises something.
#[test]
fn empty_interface_columns_are_left_out() {
    let dir = tempfile::tempdir().unwrap();
    let o = rtcdoc(
        &[
            "build",
            &root().join("examples").to_string_lossy(),
            "-o",
            "site",
            "-f",
            "markdown,doxygen",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let md = |f: &str| read(&dir.path().join("site/markdown/interfaces").join(f));
    let camera = md("camera-cameracontrol.md");
    assert!(
        camera.contains("| Operations | Returns | Parameters | Description |"),
        "{camera}"
    );
    assert!(md("detection-modelrepository.md")
        .contains("| Operations | Returns | Parameters | Raises | Description |"));
}

/// Issue #55: the interfaces a suite defines in IDL alone (no port uses them) have pages like
/// those of service ports, linked from the index and search; a struct used in their operations
/// lists those operations and is not shown as unused; the IDL path's interfaces get pages only
/// when used. `tests/fixtures/idl-api`.
#[test]
fn interfaces_of_the_input_idl_have_pages_and_types_list_the_interfaces_using_them() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let input = root().join("tests/fixtures/idl-api");
    let ext = "module Ext {\n  struct Unit { long a; };\n  interface Installed { void run(in Unit u); };\n};\n";
    common::write(d, "ext/Ext.idl", ext);
    let b = rtcdoc(
        &[
            "build",
            input.to_str().unwrap(),
            "-o",
            d.join("site").to_str().unwrap(),
            "-f",
            "html,markdown,doxygen,json",
            "--idl-path",
            d.join("ext").to_str().unwrap(),
        ],
        &root(),
    );
    assert!(b.status.success(), "{}", stderr(&b));
    let site = d.join("site/html");
    // The interface no port uses: a page with its operations, docs, IDL location, and the
    // sentence that no component provides or requires it.
    let m = read(&site.join("interfaces/api-motion.html"));
    assert!(m.contains("Defined in <code>Api.idl:21</code>"), "{m}");
    assert!(m.contains("<p>Moves the arm.</p>"), "{m}");
    assert!(
        m.contains("id=\"op-moveTo\"") && m.contains("id=\"attr-home\""),
        "{m}"
    );
    assert!(
        m.contains("<p class=\"none\">No component of this catalogue provides or requires it: it is defined in IDL only.</p>"),
        "{m}"
    );
    // The used one says nothing of the kind.
    let g = read(&site.join("interfaces/api-gripper.html"));
    assert!(!g.contains("defined in IDL only"), "{g}");
    // Linked from the index and the search.
    let index = read(&site.join("interfaces/index.html"));
    assert!(
        index.contains("<a href=\"api-motion.html\"><code>Api::Motion</code></a>"),
        "{index}"
    );
    let search = common::search_index::read(&site);
    assert!(search
        .entries
        .iter()
        .any(|e| e.href == "interfaces/api-motion.html"));
    // The IDL path's interface is no page (it is an installation's, not the suite's).
    assert!(!site.join("interfaces/ext-installed.html").exists());
    // The struct: the operations and the attribute using it, linked to their rows.
    let p = read(&site.join("types/api-pose.html"));
    let s = p
        .find("<section id=\"used-by-interfaces\">")
        .expect("section");
    let sec = &p[s..s + p[s..].find("</section>").unwrap()];
    assert!(
        sec.contains("Used by interfaces <span class=\"count\">1</span>"),
        "{sec}"
    );
    for (href, member, how) in [
        ("op-moveTo", "moveTo", "parameter goal"),
        ("op-current", "current", "result"),
        ("attr-home", "home", "attribute"),
    ] {
        let row = format!("<td data-label=\"Operation or attribute\"><a href=\"../interfaces/api-motion.html#{href}\"><code>{member}</code></a></td><td data-label=\"Use\">{how}</td>");
        assert!(sec.contains(&row), "{row}\n{sec}");
    }
    // Through a typedef, a struct and an exception: contained in those, which list theirs.
    assert!(p.contains("<a href=\"../types/api-path.html\"><code>Api::Path</code></a>"));
    let e = read(&site.join("types/api-unreachable.html"));
    assert!(
        e.contains("#op-moveTo\"><code>moveTo</code></a></td><td data-label=\"Use\">raised</td>"),
        "{e}"
    );
    let w = read(&site.join("types/api-waypoint.html"));
    assert!(w.contains("parameter w"), "{w}");
    // The index counts the interfaces beside producers and consumers.
    let types = read(&site.join("types/index.html"));
    assert!(
        types.contains("<th scope=\"col\" class=\"num\">Used by interfaces</th>"),
        "{types}"
    );
    assert!(
        types.contains("<td class=\"num\" data-label=\"Used by interfaces\">1</td>"),
        "{types}"
    );
    // Markdown and Doxygen alike.
    let md = read(&d.join("site/markdown/types/api-pose.md"));
    assert!(
        md.contains("Used by interfaces (1)")
            && md.contains("`moveTo`")
            && md.contains("parameter goal"),
        "{md}"
    );
    assert!(
        md.contains("[Api::Motion](../interfaces/api-motion.md)"),
        "{md}"
    );
    let mm = read(&d.join("site/markdown/interfaces/api-motion.md"));
    assert!(mm.contains("defined in IDL only"), "{mm}");
    let dox = read(&d.join("site/doxygen/types/api-pose.dox"));
    assert!(
        dox.contains("Used by interfaces (1)") && dox.contains("rtc_if_api_motion"),
        "{dox}"
    );
    // JSON: the uses, and the interface entry.
    let j: serde_json::Value =
        serde_json::from_str(&read(&d.join("site/json/catalog.json"))).unwrap();
    let used = &j["dataTypes"]["Api::Pose"]["usedBy"];
    assert_eq!(
        used[0],
        serde_json::json!({"interface": "Api::Motion", "member": "moveTo", "role": "parameter", "parameter": "goal"})
    );
    assert_eq!(used.as_array().map(Vec::len), Some(3), "{used}");
    assert!(j["interfaces"]["Api::Motion"].is_object());
    assert!(j["interfaces"].get("Ext::Installed").is_none());
    assert_eq!(
        j["idl"]["files"][1]["idlPath"], true,
        "{}",
        j["idl"]["files"]
    );
}
