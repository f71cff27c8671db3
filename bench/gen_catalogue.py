#!/usr/bin/env python3
"""Generate a synthetic catalogue of N realistic RTC profiles for benchmarks.

usage: gen_catalogue.py N OUT_DIR [--examples DIR] [--no-idl] [--implementation]
       gen_catalogue.py N OUT_DIR --shape corpus [--corpus DIR] [--openrtm-idl DIR] [--implementation]

Clones the bundled example profiles (examples/) under new component names, vendors and
categories, and spreads their data and interface types over groups so that cross-links look like
a real catalogue: each type is shared by a few dozen components (producers and consumers), not
by all of them and not by none. Deterministic: the same N gives the same files.

Each group's types and interfaces are defined in a generated IDL file, OUT_DIR/idl/BenchNNN.idl
(module BenchNNN: the port types, the structs, enums, sequences and exceptions they contain,
the service interfaces with operations), which the ports name as their idlFile; all of them
include OUT_DIR/idl/BenchCommon.idl (time stamps, geometry). Fields and operations are
documented or not in a fixed pattern, so that the coverage rules have something to count.
--no-idl leaves the IDL out and the idlFile attributes as the examples have them: the catalogue
of earlier versions of this script, byte for byte.

--shape corpus clones the real-world profiles of the shared corpus instead (every RTC*.xml
profile under ../shared/corpus/rtc-xml beside the repository, or --corpus DIR; read at run time,
never copied into the repository), as labs write them: long Japanese descriptions, many
configuration parameters, OpenRTM's data types (RTC::TimedLong, RTC::CameraImage, …) shared by
the whole catalogue. Each clone gets a new name (the original name and the clone's number), one
of VENDORS vendors, and the id built from them; everything else is the original's, byte for
byte. --openrtm-idl DIR copies the *.idl files of an OpenRTM installation's IDL directory
(BasicDataType.idl, ExtendedDataTypes.idl, InterfaceDataTypes.idl, …) into OUT_DIR/idl, so the
build reads and renders OpenRTM's IDL as a catalogue with `idl-path` pointing there would.

--implementation also writes, beside each profile, the code RTCBuilder generates from it, in
its layout: C++ `src/<Name>.cpp` and `include/<Name>/<Name>.h`, or Python `<Name>.py` when the
profile's language is Python: the spec array, the port and parameter declarations and
registrations, every lifecycle callback (a body for those marked implemented, the generated
stub commented out for the others) and RTCBuilder's comment blocks, so that the implementation
check reads files of the real size (about 6-12 KB a component). The profiles are the same as
without the flag, byte for byte.
"""
import xml.etree.ElementTree as ET
import os
import re
import shutil
import sys

VENDORS = 40
CATEGORIES = ["Sensor", "ImageProcessing", "Navigation", "Actuator", "UI", "Localization",
              "Manipulation", "Speech", "Planning", "Simulation", "Vision", "Control"]
# Types of the examples that carry cross-links; each is moved into one of GROUPS modules.
SHARED_TYPES = ["CameraImage", "RangeData", "TimedPose2D", "TimedVelocity2D", "TimedLong",
                "TimedBoolean", "TimedString", "TimedDouble", "TimedObjectList",
                "OGMapServer", "CameraControl", "ModelRepository"]


COMMON_IDL = """// BenchCommon.idl: shared types of the generated benchmark catalogue.
#ifndef BENCH_COMMON_IDL
#define BENCH_COMMON_IDL

module BenchCommon
{
  /// A time stamp: seconds and nanoseconds since the epoch.
  struct Time
  {
    unsigned long sec;   ///< Seconds
    unsigned long nsec;  ///< Nanoseconds
  };

  /// A point in the plane, in metres.
  struct Point2D
  {
    double x;  ///< Along the x axis
    double y;  ///< Along the y axis
  };

  /// A position and a heading.
  struct Pose2D
  {
    Point2D position;  ///< Where
    double heading;    ///< Radians, counter-clockwise from x
  };

  /// A planar velocity.
  struct Velocity2D
  {
    double vx;  ///< m/s forward
    double vy;  ///< m/s to the left
    double va;  ///< rad/s
  };

  /// How an operation ended.
  enum ReturnCode
  {
    OK,            ///< Done
    BAD_PARAMETER, ///< A parameter is out of range
    UNSUPPORTED    ///< Not implemented by this component
  };
};

#endif
"""


def doc(g, k, text):
    """A trailing doc comment, left out for one item in three (varying with the group)."""
    return "" if (g + k) % 3 == 0 else f"  ///< {text}"


def group_idl(g):
    m = f"Bench{g:03d}"
    d = lambda k, t: doc(g, k, t)
    timed = "\n".join(
        f"""  /// A time-stamped {what}.
  struct Timed{name}
  {{
    BenchCommon::Time tm;{d(i, "Time of the value")}
    {ty} data;{d(i + 1, "The value")}
  }};
"""
        for i, (name, ty, what) in enumerate([
            ("Long", "long", "integer"), ("Boolean", "boolean", "flag"),
            ("String", "string", "text"), ("Double", "double", "number"),
            ("Pose2D", "BenchCommon::Pose2D", "pose"),
            ("Velocity2D", "BenchCommon::Velocity2D", "velocity")]))
    return f"""// {m}.idl: types and interfaces of group {g} of the generated benchmark catalogue.
#ifndef {m.upper()}_IDL
#define {m.upper()}_IDL

#include "BenchCommon.idl"

/*!
 * @brief Data types and service interfaces of benchmark group {g}.
 */
module {m}
{{
{timed}
  /// Pixel layouts.
  enum PixelFormat
  {{
    GRAY,{d(1, "One byte a pixel")}
    RGB,{d(2, "Three bytes a pixel")}
    JPEG{d(3, "Compressed")}
  }};

  /// An image with its capture time.
  struct CameraImage
  {{
    BenchCommon::Time tm;{d(0, "Capture time")}
    unsigned short width;{d(1, "Pixels")}
    unsigned short height;{d(2, "Pixels")}
    PixelFormat format;{d(3, "Layout of pixels")}
    sequence<octet> pixels;{d(4, "Row by row")}
  }};

  /// Where a range sensor sits and what it sees.
  struct RangerConfig
  {{
    double minAngle;{d(0, "Radians")}
    double maxAngle;{d(1, "Radians")}
    double angularRes;{d(2, "Radians between readings")}
    double minRange;{d(3, "Metres")}
    double maxRange;{d(4, "Metres")}
  }};

  typedef sequence<double> RangeList;

  /// One scan of a range sensor.
  struct RangeData
  {{
    BenchCommon::Time tm;{d(0, "Scan time")}
    RangeList ranges;{d(1, "Metres, one per angle")}
    RangerConfig config;{d(2, "Sensor geometry")}
    BenchCommon::Pose2D origin;{d(3, "Sensor pose on the robot")}
  }};

  /// An axis-aligned box in image coordinates.
  struct BoundingBox
  {{
    long x;{d(0, "Left")}
    long y;{d(1, "Top")}
    long width;{d(2, "Width")}
    long height;{d(3, "Height")}
  }};

  /// One detected object.
  struct DetectedObject
  {{
    string label;{d(0, "Class")}
    float confidence;{d(1, "0 to 1")}
    BoundingBox box;{d(2, "Where")}
  }};

  typedef sequence<DetectedObject> ObjectList;

  /// Detections of one image.
  struct TimedObjectList
  {{
    BenchCommon::Time tm;{d(0, "Capture time")}
    ObjectList data;{d(1, "Best first")}
  }};

  /// An occupancy grid.
  struct OGMap
  {{
    BenchCommon::Pose2D origin;{d(0, "Pose of cell 0,0")}
    double resolution;{d(1, "Metres a cell")}
    unsigned long width;{d(2, "Cells")}
    unsigned long height;{d(3, "Cells")}
    sequence<octet> cells;{d(4, "0 free to 255 occupied")}
  }};

  /// A name nobody knows.
  exception NotFound
  {{
    string name;{d(0, "The name asked for")}
  }};

  /// Serves the map being built.
  interface OGMapServer
  {{
{"" if g % 2 else "    /// The current map." + chr(10)}    BenchCommon::ReturnCode requestCurrentBuiltMap(out OGMap map);
    /// The map of a named area.
    BenchCommon::ReturnCode requestMap(in string area, out OGMap map) raises (NotFound);
  }};

  /// Camera settings.
  interface CameraControl
  {{
    /// Sets the exposure time in microseconds.
    long setExposure(in long microseconds);
{"" if g % 3 else "    /// Switches the pixel format." + chr(10)}    void setFormat(in PixelFormat format);
    readonly attribute PixelFormat format;
  }};

  typedef sequence<octet> ModelData;

  /// Serves models by name.
  interface ModelRepository
  {{
    /*!
     * @brief Fetches a model.
     * @param name File name
     * @param data The model
     */
    boolean fetch(in string name, out ModelData data) raises (NotFound);
{"" if g % 4 else "    /// Every model name." + chr(10)}    sequence<string> list();
  }};
}};

#endif
"""


# A backup RTCBuilder leaves beside a profile (RTC.xml20230831164412.xml): not a profile of its own.
BACKUP_RE = re.compile(r"\.xml\d{14}\.xml$")


def corpus_templates(corpus):
    """The corpus's XML profiles, in a fixed order: (name, file name, text)."""
    templates = []
    for root, dirs, files in os.walk(corpus):
        dirs.sort()
        for f in sorted(files):
            if not f.endswith(".xml") or BACKUP_RE.search(f):
                continue
            with open(os.path.join(root, f), encoding="utf-8") as fh:
                text = fh.read()
            m = re.search(r"<rtc:BasicInfo\b[^>]*\srtc:name=\"([^\"]*)\"", text)
            if "<rtc:RtcProfile" not in text or not m:
                continue
            templates.append((m.group(1), f, text))
    return templates


def gen_corpus(n, out, corpus, idl_dir):
    templates = corpus_templates(corpus)
    if not templates:
        print(f"no profiles in {corpus}", file=sys.stderr)
        return 1
    os.makedirs(out)
    attr = lambda name: re.compile(r"(\s" + name + r"=\")[^\"]*(\")")
    name_re, vendor_re, id_re = attr("rtc:name"), attr("rtc:vendor"), attr("rtc:id")
    basic_re = re.compile(r"<rtc:BasicInfo\b[^>]*>")
    head_re = re.compile(r"<rtc:RtcProfile\b[^>]*>")
    for i in range(n):
        name, fname, text = templates[i % len(templates)]
        new_name = f"{name}{i:05d}"
        vendor = f"Lab{i % VENDORS:02d}"
        # Only the BasicInfo element's name and vendor and the profile's id change: the same
        # words in descriptions, port names and paths stay as the lab wrote them.
        t = basic_re.sub(lambda m: vendor_re.sub(
            lambda a: a.group(1) + vendor + a.group(2),
            name_re.sub(lambda a: a.group(1) + new_name + a.group(2), m.group(0), count=1),
            count=1), text, count=1)

        def new_id(a):
            parts = a.group(0)[len(a.group(1)):-1].split(":")
            if len(parts) == 5:
                parts[1], parts[3] = vendor, new_name
            else:
                parts = ["RTC", vendor, "Category", new_name, "1.0.0"]
            return a.group(1) + ":".join(parts) + a.group(2)

        t = head_re.sub(lambda m: id_re.sub(new_id, m.group(0), count=1), t, count=1)
        d = os.path.join(out, f"{i // 1000:02d}", new_name)
        os.makedirs(d)
        with open(os.path.join(d, fname), "w", encoding="utf-8") as fh:
            fh.write(t)
        if "--implementation" in sys.argv and fname.endswith(".xml"):
            write_implementation(d, t)
    idl_files = 0
    if idl_dir:
        d = os.path.join(out, "idl")
        os.makedirs(d)
        for f in sorted(os.listdir(idl_dir)):
            if f.endswith(".idl") and os.path.isfile(os.path.join(idl_dir, f)):
                shutil.copyfile(os.path.join(idl_dir, f), os.path.join(d, f))
                idl_files += 1
    print(f"wrote {n} profiles cloned from {len(templates)} corpus profiles to {out}"
          + (f", {idl_files} IDL files" if idl_dir else ""))
    return 0


CALLBACKS = ["onInitialize", "onFinalize", "onStartup", "onShutdown", "onActivated",
             "onDeactivated", "onAborting", "onError", "onReset", "onExecute",
             "onStateUpdate", "onRateChanged", "onAction", "onModeChanged"]
BLOCK = """  /***
   * The {cb} action, as RTCBuilder documents it: called by the execution context
   * when the component enters the corresponding state. The return value tells the
   * execution context whether the action succeeded.
   *
   * @param ec_id target ExecutionContext Id
   * @return RTC::ReturnCode_t
   *
   */
"""


def profile_facts(text):
    """(name, language, data ports, service ports, configurations, implemented callbacks) of an
    RTC.xml, or None when it is not XML ElementTree reads."""
    try:
        root = ET.fromstring(text.encode("utf-8"))
    except ET.ParseError:
        return None
    local = lambda t: t.rsplit("}", 1)[-1]
    xsi = "{http://www.w3.org/2001/XMLSchema-instance}"
    get = lambda e, k: next((v for a, v in e.attrib.items()
                             if local(a) == k and not a.startswith(xsi)), "")
    facts = {"name": "", "lang": "C++", "ports": [], "services": [], "confs": [], "impl": set(),
             "spec": {}}
    for e in root.iter():
        t = local(e.tag)
        if t == "BasicInfo":
            facts["name"] = get(e, "name")
            for k, key in [("vendor", "vendor"), ("category", "category"), ("version", "version"),
                           ("activityType", "activity_type"), ("maxInstances", "max_instance"),
                           ("description", "description")]:
                facts["spec"][key] = get(e, k)
        elif t == "DataPorts":
            facts["ports"].append((get(e, "name"), get(e, "portType"), get(e, "type")))
        elif t == "ServicePorts":
            ifs = [(get(i, "name"), get(i, "type"), get(i, "direction"))
                   for i in e if local(i.tag) == "ServiceInterface"]
            facts["services"].append((get(e, "name"), ifs))
        elif t == "Configuration":
            facts["confs"].append((get(e, "name"), get(e, "type"), get(e, "defaultValue")))
        elif t == "Language" and get(e, "kind"):
            facts["lang"] = get(e, "kind")
        elif t.startswith("On") and get(e, "implemented").lower() == "true":
            facts["impl"].add("o" + t[1:])
    return facts


def ident(s):
    return re.sub(r"\W", "_", s) or "x"


def c_string(s):
    return s.replace("\\", "\\\\").replace('"', '\\"').replace("\n", " ")


def write_cpp(d, f):
    n = ident(f["name"])
    spec = [("implementation_id", f["name"]), ("type_name", f["name"])]
    spec += [(k, v) for k, v in f["spec"].items()]
    spec += [("language", "C++"), ("lang_type", "compile")]
    spec += [(f"conf.default.{c}", v) for c, _, v in f["confs"] if c]
    spec += [(f"conf.__type__.{c}", t) for c, t, _ in f["confs"] if c and t]
    out = ["// -*- C++ -*-", "/*!", f" * @file  {n}.cpp", f" * @brief {c_string(f['spec'].get('description', ''))}",
           " * @date $Date$", " *", " * $Id$", " */", "", f'#include "{n}.h"', "",
           "// Module specification", "// <rtc-template block=\"module_spec\">",
           f"static const char* {n.lower()}_spec[] =", "  {"]
    out += [f'    "{c_string(k)}", "{c_string(v)}",' for k, v in spec]
    out += ['    ""', "  };", "// </rtc-template>", "", "/*!", " * @brief constructor",
            " * @param manager Maneger Object", " */", f"{n}::{n}(RTC::Manager* manager)",
            "    // <rtc-template block=\"initializer\">", "  : RTC::DataFlowComponentBase(manager)"]
    for p, kind, _ in f["ports"]:
        v = ident(p)
        suffix = "In" if kind == "DataInPort" else "Out"
        out.append(f'    , m_{v}{suffix}("{c_string(p)}", m_{v})')
    for s, _ in f["services"]:
        out.append(f'    , m_{ident(s)}Port("{c_string(s)}")')
    out += ["    // </rtc-template>", "{", "}", "", "/*!", " * @brief destructor", " */",
            f"{n}::~{n}()", "{", "}", "", ""]
    for cb in CALLBACKS:
        args = "" if cb in ("onInitialize", "onFinalize") else "RTC::UniqueId /*ec_id*/"
        body = []
        if cb == "onInitialize":
            body.append("  // Registration: InPort/OutPort/Service")
            body.append("  // <rtc-template block=\"registration\">")
            for p, kind, _ in f["ports"]:
                v = ident(p)
                if kind == "DataInPort":
                    body.append(f'  addInPort("{c_string(p)}", m_{v}In);')
                else:
                    body.append(f'  addOutPort("{c_string(p)}", m_{v}Out);')
            for s, ifs in f["services"]:
                for i, t, direction in ifs:
                    call = "registerConsumer" if direction == "Required" else "registerProvider"
                    body.append(f'  m_{ident(s)}Port.{call}("{c_string(i)}", "{c_string(t)}", m_{ident(i)});')
                body.append(f"  addPort(m_{ident(s)}Port);")
            body += ["  // </rtc-template>", "", "  // <rtc-template block=\"bind_config\">",
                     "  // Bind variables and configuration variable"]
            for c, _, v in f["confs"]:
                if c:
                    body.append(f'  bindParameter("{c_string(c)}", m_{ident(c)}, "{c_string(v)}");')
            body.append("  // </rtc-template>")
        elif cb in f["impl"]:
            body += ["  // The lab's code: read the inputs, compute, write the outputs.",
                     "  static int calls = 0;", "  ++calls;"]
        text = [f"RTC::ReturnCode_t {n}::{cb}({args})", "{"] + body + ["  return RTC::RTC_OK;", "}"]
        if cb == "onInitialize" or cb in f["impl"]:
            out += text
        else:
            out += ["/*"] + text + ["*/"]
        out.append("")
    out += ['extern "C"', "{", f"  void {n}Init(RTC::Manager* manager)", "  {",
            f"    coil::Properties profile({n.lower()}_spec);",
            f"    manager->registerFactory(profile, RTC::Create<{n}>, RTC::Delete<{n}>);",
            "  }", "};", ""]
    os.makedirs(os.path.join(d, "src"), exist_ok=True)
    with open(os.path.join(d, "src", f"{n}.cpp"), "w", encoding="utf-8") as fh:
        fh.write("\n".join(out))
    h = [f"#ifndef {n.upper()}_H", f"#define {n.upper()}_H", "",
         "#include <rtm/Manager.h>", "#include <rtm/DataFlowComponentBase.h>",
         "#include <rtm/CorbaPort.h>", "#include <rtm/DataInPort.h>", "#include <rtm/DataOutPort.h>",
         "", "using namespace RTC;", "", f"class {n}", "  : public RTC::DataFlowComponentBase", "{",
         " public:", f"  {n}(RTC::Manager* manager);", f"  ~{n}() override;", ""]
    for cb in CALLBACKS:
        args = "" if cb in ("onInitialize", "onFinalize") else "RTC::UniqueId ec_id"
        decl = f"  RTC::ReturnCode_t {cb}({args}) override;"
        h += BLOCK.format(cb=cb).splitlines()
        h.append(decl if cb == "onInitialize" or cb in f["impl"] else "  // " + decl.strip())
        h.append("")
    h += [" protected:", "  // <rtc-template block=\"config_declare\">"]
    for c, t, _ in f["confs"]:
        if c:
            ty = {"string": "std::string", "": "std::string"}.get(t, t)
            h.append(f"  {ty} m_{ident(c)};")
    h += ["  // </rtc-template>", "  // <rtc-template block=\"inport_declare\">"]
    for p, kind, t in f["ports"]:
        ty = t or "RTC::TimedLong"
        v = ident(p)
        port = "InPort" if kind == "DataInPort" else "OutPort"
        suffix = "In" if kind == "DataInPort" else "Out"
        h += [f"  {ty} m_{v};", f"  /*!", f"   * {c_string(p)}", "   */", f"  RTC::{port}<{ty}> m_{v}{suffix};"]
    h += ["  // </rtc-template>", "  // <rtc-template block=\"corbaport_declare\">"]
    for s, ifs in f["services"]:
        h.append(f"  RTC::CorbaPort m_{ident(s)}Port;")
    h.append("  // </rtc-template>")
    for s, ifs in f["services"]:
        for i, t, direction in ifs:
            h.append(f"  {ident(t)}SVC_impl m_{ident(i)};")
    h += ["", " private:", "", "};", "", 'extern "C"', "{",
          f"  DLL_EXPORT void {n}Init(RTC::Manager* manager);", "};", "", f"#endif // {n.upper()}_H", ""]
    os.makedirs(os.path.join(d, "include", n), exist_ok=True)
    with open(os.path.join(d, "include", n, f"{n}.h"), "w", encoding="utf-8") as fh:
        fh.write("\n".join(h))


def write_python(d, f):
    n = ident(f["name"])
    spec = [("implementation_id", f["name"]), ("type_name", f["name"])]
    spec += list(f["spec"].items()) + [("language", "Python"), ("lang_type", "SCRIPT")]
    spec += [(f"conf.default.{c}", v) for c, _, v in f["confs"] if c]
    out = ["#!/usr/bin/env python", "# -*- coding: utf-8 -*-", f'"""{n}.py (generated by RTCBuilder)"""',
           "import sys", "import time", "import RTC", "import OpenRTM_aist", "",
           "# <rtc-template block=\"module_spec\">", f"{n.lower()}_spec = ["]
    out += [f'    "{c_string(k)}", "{c_string(v)}",' for k, v in spec]
    out += ['    ""]', "# </rtc-template>", "", "", f"class {n}(OpenRTM_aist.DataFlowComponentBase):",
            "    def __init__(self, manager):", "        OpenRTM_aist.DataFlowComponentBase.__init__(self, manager)"]
    for p, kind, t in f["ports"]:
        v = ident(p)
        dt = (t or "RTC::TimedLong").replace("::", ".")
        cls = "InPort" if kind == "DataInPort" else "OutPort"
        suffix = "In" if kind == "DataInPort" else "Out"
        out += [f"        self._d_{v} = OpenRTM_aist.instantiateDataType({dt})",
                f'        self._{v}{suffix} = OpenRTM_aist.{cls}("{c_string(p)}", self._d_{v})']
    for c, t, v in f["confs"]:
        if c:
            # RTCBuilder's Python holds each parameter in a list of its type's literal.
            number = t in ("int", "long", "short", "float", "double") and re.fullmatch(r"-?[\d.]+", v)
            lit = v if number else f'"{c_string(v)}"'
            out.append(f'        self._{ident(c)} = [{lit}]')
    out.append("")
    for cb in CALLBACKS:
        args = "self" if cb in ("onInitialize", "onFinalize") else "self, ec_id"
        body = []
        if cb == "onInitialize":
            for c, _, v in f["confs"]:
                if c:
                    body.append(f'        self.bindParameter("{c_string(c)}", self._{ident(c)}, "{c_string(v)}")')
            for p, kind, _ in f["ports"]:
                v = ident(p)
                if kind == "DataInPort":
                    body.append(f'        self.addInPort("{c_string(p)}", self._{v}In)')
                else:
                    body.append(f'        self.addOutPort("{c_string(p)}", self._{v}Out)')
        elif cb in f["impl"]:
            body.append("        self._calls = getattr(self, '_calls', 0) + 1")
        lines = [f"    def {cb}({args}):", f'        """The {cb} action."""'] + body + ["        return RTC.RTC_OK"]
        if cb == "onInitialize" or cb in f["impl"]:
            out += lines
        else:
            out += ["    #" + l[4:] for l in lines]
        out.append("")
    out += ["", f"def {n}Init(manager):", f"    profile = OpenRTM_aist.Properties(defaults_str={n.lower()}_spec)",
            f"    manager.registerFactory(profile, {n}, OpenRTM_aist.Delete)", ""]
    with open(os.path.join(d, f"{n}.py"), "w", encoding="utf-8") as fh:
        fh.write("\n".join(out))


def write_implementation(d, text):
    """The code RTCBuilder generates from the profile `text`, in its layout below `d`."""
    f = profile_facts(text)
    if f is None or not f["name"] or not re.fullmatch(r"\w+", f["name"]):
        return False
    lang = f["lang"].lower()
    if lang.startswith("python"):
        write_python(d, f)
    elif lang.startswith("c++") or lang in ("", "cpp"):
        write_cpp(d, f)
    else:  # Java, Processing, C#: no code (as a catalogue of mixed languages has)
        return False
    return True


def main():
    argv = sys.argv[1:]
    for opt in ("--examples", "--shape", "--corpus", "--openrtm-idl"):
        if opt in argv:  # its value is not a positional argument
            del argv[argv.index(opt) + 1]
    args = [a for a in argv if not a.startswith("--")]
    if len(args) != 2:
        print(__doc__)
        return 2
    n, out = int(args[0]), args[1]
    here = os.path.dirname(os.path.abspath(__file__))
    opt = lambda o, default=None: sys.argv[sys.argv.index(o) + 1] if o in sys.argv else default
    shape = opt("--shape", "example")
    if shape not in ("example", "corpus"):
        print(f"unknown shape {shape!r} (example or corpus)", file=sys.stderr)
        return 2
    if shape == "corpus":
        if os.path.exists(out):
            shutil.rmtree(out)
        corpus = opt("--corpus", os.path.join(here, "..", "..", "shared", "corpus", "rtc-xml"))
        return gen_corpus(n, out, corpus, opt("--openrtm-idl"))
    with_idl = "--no-idl" not in sys.argv
    examples = os.path.join(here, "..", "examples")
    if "--examples" in sys.argv:
        examples = sys.argv[sys.argv.index("--examples") + 1]
    templates = []
    for name in sorted(os.listdir(examples)):
        d = os.path.join(examples, name)
        if not os.path.isdir(d):
            continue
        for f in sorted(os.listdir(d)):
            if f.startswith("RTC."):
                with open(os.path.join(d, f), encoding="utf-8") as fh:
                    templates.append((name, f, fh.read()))
    if os.path.exists(out):
        shutil.rmtree(out)
    os.makedirs(out)
    groups = max(1, n // 40)  # about 40 components share one module's types
    type_re = re.compile(r"\b(?:RTC::|Detection::|Camera::)?(" + "|".join(SHARED_TYPES) + r")\b")
    for i in range(n):
        name, fname, text = templates[i % len(templates)]
        g = (i // len(templates)) % groups
        new_name = f"{name}{i:05d}"
        if with_idl:
            # Keep the shared type names whole (`OGMapServer` holds the template name
            # `MapServer`; earlier versions of this script renamed it per component).
            t = text
            for k, ty in enumerate(SHARED_TYPES):
                t = t.replace(ty, f"@TYPE{k}@")
            t = t.replace(name, new_name)
            for k, ty in enumerate(SHARED_TYPES):
                t = t.replace(f"@TYPE{k}@", ty)
        else:
            t = text.replace(name, new_name)
        t = re.sub(r"ExampleRobotics( Inc\.)?|Example Robotics", f"Vendor{i % VENDORS:02d}", t)
        cat = CATEGORIES[i % len(CATEGORIES)]
        t = re.sub(r'(rtc:category=")[^"]*(")', r"\g<1>" + cat + r"\g<2>", t)
        t = re.sub(r"(\n\s*category: ).*", r"\g<1>" + cat, t)
        t = re.sub(r"(RTC:[^:\"]*:)[^:\"]*(:" + re.escape(new_name) + ")", r"\g<1>" + cat + r"\g<2>", t)
        if with_idl:
            # A repository id names the group's type too (without IDL, as earlier versions of
            # this script did: the id was rewritten into `IDL:RTC/BenchNNN::TimedPose2D:1.0`).
            t = t.replace("IDL:RTC/TimedPose2D:1.0", "@REPOSITORY-ID@")
        t = type_re.sub(lambda m: f"Bench{g:03d}::{m.group(1)}", t)
        t = t.replace("IDL:RTC/TimedPose2D:1.0", f"Bench{g:03d}::TimedPose2D")
        t = t.replace("@REPOSITORY-ID@", f"IDL:Bench{g:03d}/TimedPose2D:1.0")
        if with_idl:
            t = re.sub(r'(rtc:idlFile=")[^"]*(")', r"\g<1>" + f"Bench{g:03d}.idl" + r"\g<2>", t)
            t = re.sub(r"(\n\s*idlFile: ).*", r"\g<1>" + f"Bench{g:03d}.idl", t)
        d = os.path.join(out, f"{i // 1000:02d}", new_name)
        os.makedirs(d)
        with open(os.path.join(d, fname), "w", encoding="utf-8") as fh:
            fh.write(t)
        if "--implementation" in sys.argv and fname.endswith(".xml"):
            write_implementation(d, t)
    if with_idl:
        d = os.path.join(out, "idl")
        os.makedirs(d)
        with open(os.path.join(d, "BenchCommon.idl"), "w", encoding="utf-8") as fh:
            fh.write(COMMON_IDL)
        for g in range(groups):
            with open(os.path.join(d, f"Bench{g:03d}.idl"), "w", encoding="utf-8") as fh:
                fh.write(group_idl(g))
    print(f"wrote {n} profiles in {groups} type groups to {out}" + (
        f", {groups + 1} IDL files" if with_idl else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
