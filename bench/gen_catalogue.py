#!/usr/bin/env python3
"""Generate a synthetic catalogue of N realistic RTC profiles for benchmarks.

usage: gen_catalogue.py N OUT_DIR [--examples DIR]

Clones the bundled example profiles (examples/) under new component names, vendors and
categories, and spreads their data and interface types over groups so that cross-links look like
a real catalogue: each type is shared by a few dozen components (producers and consumers), not
by all of them and not by none. Deterministic: the same N gives the same files.
"""
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


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    if len(args) != 2:
        print(__doc__)
        return 2
    n, out = int(args[0]), args[1]
    here = os.path.dirname(os.path.abspath(__file__))
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
        t = text.replace(name, new_name)
        t = re.sub(r"ExampleRobotics( Inc\.)?|Example Robotics", f"Vendor{i % VENDORS:02d}", t)
        cat = CATEGORIES[i % len(CATEGORIES)]
        t = re.sub(r'(rtc:category=")[^"]*(")', r"\g<1>" + cat + r"\g<2>", t)
        t = re.sub(r"(\n\s*category: ).*", r"\g<1>" + cat, t)
        t = re.sub(r"(RTC:[^:\"]*:)[^:\"]*(:" + re.escape(new_name) + ")", r"\g<1>" + cat + r"\g<2>", t)
        t = type_re.sub(lambda m: f"Bench{g:03d}::{m.group(1)}", t)
        t = t.replace("IDL:RTC/TimedPose2D:1.0", f"Bench{g:03d}::TimedPose2D")
        d = os.path.join(out, f"{i // 1000:02d}", new_name)
        os.makedirs(d)
        with open(os.path.join(d, fname), "w", encoding="utf-8") as fh:
            fh.write(t)
    print(f"wrote {n} profiles in {groups} type groups to {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
