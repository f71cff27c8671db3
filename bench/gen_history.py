#!/usr/bin/env python3
"""Generate a git work tree whose component profiles have a long history, for bench/history.sh.

usage: gen_history.py OUT_DIR [--commits N] [--profiles P] [--examples DIR]
       gen_history.py OUT_DIR --from CATALOGUE [--commits N]

The first form clones the example XML profiles (examples/*/RTC.xml) into P components
(comp000/RTC.xml, …; default 50) and writes N commits (default 1,000) as labs make them: ports
and configuration parameters added, removed, renamed and retyped, descriptions edited, version
bumps, whitespace-only commits, commits touching two or three profiles, commits touching no
profile (source files), two component folders moved (followed by `git log --follow`) and two
RTCBuilder backups (RTC.xml<yyyymmddhhmmss>) committed beside their profile.

The second form commits an existing catalogue (bench/gen_catalogue.py's output) as the first
commit, then N commits (default 200) editing its XML profiles the same way.

The repository is written with `git fast-import` (seconds for thousands of commits), then checked
out. Deterministic: the same arguments give the same commits (ids included).
"""
import argparse
import os
import random
import re
import subprocess
import sys

TYPES = ["RTC::TimedLong", "RTC::TimedDouble", "RTC::TimedString", "RTC::TimedBoolean",
         "RTC::TimedPose2D", "RTC::TimedVelocity2D", "RTC::RangeData", "RTC::CameraImage"]
CONFIG_TYPES = [("int", "10"), ("double", "0.5"), ("string", "default"), ("bool", "true")]
WORDS = ["left", "right", "front", "rear", "raw", "filtered", "target", "current", "debug",
         "status", "command", "estimate", "limit", "gain", "offset", "rate", "mode", "scale"]
AUTHORS = [("Aiko Tanaka", "aiko@lab.example"), ("Ben Okafor", "ben@lab.example"),
           ("Chen Wei", "chen@lab.example"), ("Dora Lind", "dora@lab.example")]
START = 1577836800  # 2020-01-01T00:00:00Z


def esc(s):
    return s.replace("&", "&amp;").replace("<", "&lt;").replace('"', "&quot;")


class Profile:
    """A profile as its base text (one example, renamed) plus the edits made to it."""

    def __init__(self, text, rnd):
        self.base = text
        self.ports = []    # [name, portType, type, description]
        self.configs = []  # [name, type, default, description]
        self.version = None  # (major, minor, patch) once bumped
        self.description = None
        self.trailing = 0  # whitespace-only edits: blank lines at the end
        self.rnd = rnd
        m = re.search(r'<rtc:BasicInfo[^>]*\brtc:version="(\d+)\.(\d+)\.(\d+)"', text)
        self.base_version = tuple(int(x) for x in m.groups()) if m else (1, 0, 0)

    def text(self):
        t = self.base
        if self.version is not None:
            old = "%d.%d.%d" % self.base_version
            new = "%d.%d.%d" % self.version
            t = re.sub(r'(rtc:id="[^"]*:)' + re.escape(old) + '"', r"\g<1>" + new + '"', t, count=1)
            t = re.sub(r'(<rtc:BasicInfo[^>]*\brtc:version=")' + re.escape(old) + '"',
                       r"\g<1>" + new + '"', t, count=1)
        if self.description is not None:
            t = re.sub(r'(<rtc:BasicInfo[^>]*\brtc:description=")[^"]*"',
                       lambda m: m.group(1) + esc(self.description) + '"', t, count=1)
        if self.configs:
            extra = "".join(
                f'        <rtc:Configuration xsi:type="rtcExt:configuration_ext" rtcExt:variableName="{n}"'
                f' rtc:unit="" rtc:defaultValue="{esc(d)}" rtc:type="{ty}" rtc:name="{n}">\n'
                f'            <rtcDoc:Doc rtcDoc:description="{esc(desc)}"/>\n'
                f'        </rtc:Configuration>\n'
                for n, ty, d, desc in self.configs)
            t = t.replace("    </rtc:ConfigurationSet>", extra + "    </rtc:ConfigurationSet>", 1)
        if self.ports:
            extra = "".join(
                f'    <rtc:DataPorts xsi:type="rtcExt:dataport_ext" rtcExt:position="LEFT"'
                f' rtcExt:variableName="{n}" rtc:unit="" rtc:subscriptionType="" rtc:dataflowType=""'
                f' rtc:interfaceType="" rtc:idlFile="BasicDataType.idl" rtc:type="{ty}" rtc:name="{n}"'
                f' rtc:portType="{pt}">\n'
                f'        <rtcDoc:Doc rtcDoc:description="{esc(desc)}"/>\n'
                f'    </rtc:DataPorts>\n'
                for n, pt, ty, desc in self.ports)
            t = t.replace("    <rtc:Language", extra + "    <rtc:Language", 1)
        return t + "\n" * self.trailing

    def fresh(self, names):
        while True:
            n = "_".join(self.rnd.sample(WORDS, 2))
            if n not in names:
                return n

    def edit(self):
        """One realistic edit; returns the commit subject."""
        r = self.rnd
        kinds = ["add port"] * 20 + ["add config"] * 15 + ["describe"] * 10 + ["whitespace"] * 8
        if self.ports:
            kinds += ["remove port"] * 8 + ["rename port"] * 10 + ["retype port"] * 8
        if self.configs:
            kinds += ["remove config"] * 6 + ["rename config"] * 5 + ["default"] * 5
        kinds += ["bump"] * 5
        k = r.choice(kinds)
        if k == "add port":
            n = self.fresh({p[0] for p in self.ports})
            self.ports.append([n, r.choice(["DataInPort", "DataOutPort"]), r.choice(TYPES),
                               f"The {n.replace('_', ' ')} data."])
            return f"Add the {n} port"
        if k == "remove port":
            p = self.ports.pop(r.randrange(len(self.ports)))
            return f"Remove the {p[0]} port"
        if k == "rename port":
            p = r.choice(self.ports)
            old, p[0] = p[0], self.fresh({q[0] for q in self.ports})
            return f"Rename {old} to {p[0]}"
        if k == "retype port":
            p = r.choice(self.ports)
            p[2] = r.choice([t for t in TYPES if t != p[2]])
            return f"{p[0]}: use {p[2]}"
        if k == "add config":
            n = self.fresh({c[0] for c in self.configs})
            ty, d = r.choice(CONFIG_TYPES)
            self.configs.append([n, ty, d, f"The {n.replace('_', ' ')}."])
            return f"Add the {n} parameter"
        if k == "remove config":
            c = self.configs.pop(r.randrange(len(self.configs)))
            return f"Remove the {c[0]} parameter"
        if k == "rename config":
            c = r.choice(self.configs)
            old, c[0] = c[0], self.fresh({q[0] for q in self.configs})
            return f"Rename the parameter {old} to {c[0]}"
        if k == "default":
            c = r.choice(self.configs)
            c[2] = {"int": str(r.randrange(100)), "double": f"{r.random():.2f}",
                    "string": r.choice(WORDS), "bool": r.choice(["true", "false"])}[c[1]]
            return f"{c[0]}: default {c[2]}"
        if k == "describe":
            self.description = f"{r.choice(WORDS).capitalize()} {r.choice(WORDS)} component, revision {r.randrange(1000)}"
            return "Describe the component better"
        if k == "whitespace":
            self.trailing = (self.trailing + 1) % 3
            return "Whitespace"
        v = self.version or self.base_version
        self.version = (v[0], v[1] + 1, 0) if r.random() < 0.3 else (v[0], v[1], v[2] + 1)
        return "Release %d.%d.%d" % self.version


def renamed(text, name):
    """An example profile under a new component name (BasicInfo's name and the id)."""
    old = re.search(r'<rtc:BasicInfo[^>]*\brtc:name="([^"]*)"', text).group(1)
    text = re.sub(r'(<rtc:BasicInfo[^>]*\brtc:name=")[^"]*"', r"\g<1>" + name + '"', text, count=1)
    return text.replace(f':{old}:', f':{name}:', 1)


class Stream:
    def __init__(self, out):
        self.out = out
        self.mark = 0
        self.time = START

    def data(self, b):
        self.out.write(b"data %d\n" % len(b) + b + b"\n")

    def commit(self, subject, changes, rnd):
        """changes: ("M", path, text) | ("D", path) | ("R", old, new)."""
        self.mark += 1
        self.time += rnd.randrange(3600, 3 * 86400)
        name, mail = rnd.choice(AUTHORS)
        who = f"{name} <{mail}> {self.time} +0900".encode()
        self.out.write(b"commit refs/heads/main\nmark :%d\n" % self.mark)
        self.out.write(b"author " + who + b"\ncommitter " + who + b"\n")
        self.data(subject.encode())
        if self.mark > 1:
            self.out.write(b"from :%d\n" % (self.mark - 1))
        for c in changes:
            if c[0] == "M":
                self.out.write(b"M 100644 inline " + c[1].encode() + b"\n")
                self.data(c[2].encode())
            elif c[0] == "D":
                self.out.write(b"D " + c[1].encode() + b"\n")
            else:
                self.out.write(b'R "' + c[1].encode() + b'" "' + c[2].encode() + b'"\n')
        self.out.write(b"\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--commits", type=int)
    ap.add_argument("--profiles", type=int, default=50)
    ap.add_argument("--examples", default=os.path.join(os.path.dirname(__file__), "..", "examples"))
    ap.add_argument("--from", dest="source")
    a = ap.parse_args()
    rnd = random.Random(25)
    os.makedirs(a.out)
    subprocess.run(["git", "init", "-q", "-b", "main", a.out], check=True)
    fi = subprocess.Popen(["git", "-C", a.out, "fast-import", "--quiet"], stdin=subprocess.PIPE)
    s = Stream(fi.stdin)
    folders = {}  # path of the profile -> Profile
    if a.source:
        commits = 200 if a.commits is None else a.commits
        first = []
        for root, dirs, files in os.walk(a.source):
            dirs.sort()
            for f in sorted(files):
                p = os.path.join(root, f)
                rel = os.path.relpath(p, a.source)
                with open(p, encoding="utf-8") as fh:
                    text = fh.read()
                first.append(("M", rel, text))
                if f == "RTC.xml" and "</rtc:ConfigurationSet>" in text and "<rtc:Language" in text:
                    folders[rel] = Profile(text, rnd)
        s.commit("Import the catalogue", first, rnd)
    else:
        commits = 1000 if a.commits is None else a.commits
        examples = sorted(
            os.path.join(a.examples, d, "RTC.xml") for d in os.listdir(a.examples)
            if os.path.isfile(os.path.join(a.examples, d, "RTC.xml")))
        first = []
        for i in range(a.profiles):
            with open(examples[i % len(examples)], encoding="utf-8") as fh:
                text = renamed(fh.read(), f"Comp{i:03d}")
            path = f"comp{i:03d}/RTC.xml"
            folders[path] = Profile(text, rnd)
            first.append(("M", path, text))
        first.append(("M", "README.md", "# Lab components\n"))
        s.commit("First version of the components", first, rnd)
    paths = sorted(folders)
    moves = {commits // 3: 0, 2 * commits // 3: 1}
    backups = {commits // 4: 2, commits // 2: 3}
    for n in range(1, commits):
        if n in moves and not a.source:
            old = paths[moves[n]]
            new = "moved/" + old
            folders[new] = folders.pop(old)
            paths[moves[n]] = new
            s.commit(f"Move {os.path.dirname(old)} into moved/", [("R", os.path.dirname(old), os.path.dirname(new))], rnd)
            continue
        if n in backups:
            path = paths[backups[n]]
            stamp = subprocess.run(["date", "-u", "-d", f"@{s.time}", "+%Y%m%d%H%M%S"],
                                   capture_output=True, text=True, check=True).stdout.strip()
            before = folders[path].text()
            subject = folders[path].edit()
            s.commit(subject + " (RTCBuilder backup kept)",
                     [("M", path + stamp, before), ("M", path, folders[path].text())], rnd)
            continue
        if rnd.random() < 0.1:
            s.commit("Tune the implementation", [("M", f"src/impl{n % 7}.cpp", f"// revision {n}\n")], rnd)
            continue
        touched = rnd.sample(paths, 1 if rnd.random() < 0.85 else rnd.choice([2, 3]))
        subjects = [folders[p].edit() for p in touched]
        s.commit("; ".join(subjects), [("M", p, folders[p].text()) for p in touched], rnd)
    fi.stdin.close()
    if fi.wait() != 0:
        sys.exit("git fast-import failed")
    subprocess.run(["git", "-C", a.out, "checkout", "-q", "-f", "main"], check=True)
    print(f"{a.out}: {commits} commits, {len(paths)} profiles")


if __name__ == "__main__":
    main()
