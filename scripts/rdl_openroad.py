#!/usr/bin/env python3
"""taut against OpenROAD's RDL router on OpenROAD's flip-chip test case (../shared/data/openroad-rdl).

Imports the design with `taut import --bump-to-pad` (metal10, 4 um wires at 4 um spacing, the
nets "VDD DVDD VSS DVSS p_*", as OpenROAD's test ran `rdl_route`), routes it with `taut route`,
checks it with `taut check`, and compares per net group with OpenROAD's routing
(rdl_route.defok): connections made, wirelength and bends.

A fair length: OpenROAD ends its wires at the pins' centres, taut on their edges (a wire may end
anywhere on a pin shape, FORMAT.md), so both are measured outside the pins of their net: OpenROAD's
wiring is read by `taut import --keep-wiring` (each segment taken back to its centreline where it is
drawn out by half the width past a corner), and the parts inside the net's pins are cut off; taut's
wires are measured the same way.

Usage: scripts/rdl_openroad.py [--taut build/tools/taut] [--data ../shared/data/openroad-rdl]
       [--out out/rdl] [--orientations rectilinear|octilinear]
Exit status: 0, or 1 when a step fails.
"""
import argparse
import json
import os
import subprocess
import sys
import time
import xml.etree.ElementTree as ET


def run(cmd):
    t = time.monotonic()
    p = subprocess.run(cmd, capture_output=True, text=True)
    return p, time.monotonic() - t


def inside_length(a, b, rect):
    """Length of the axis-parallel segment a-b inside the closed rectangle."""
    (x0, y0), (x1, y1) = a, b
    rx0, ry0, rx1, ry1 = rect
    if y0 == y1:
        if not (ry0 <= y0 <= ry1):
            return 0
        lo, hi = max(min(x0, x1), rx0), min(max(x0, x1), rx1)
    elif x0 == x1:
        if not (rx0 <= x0 <= rx1):
            return 0
        lo, hi = max(min(y0, y1), ry0), min(max(y0, y1), ry1)
    else:  # a 45-degree segment (octilinear taut): clip by the parameter range
        n = max(abs(x1 - x0), abs(y1 - y0))
        ts = []
        for (p0, p1, r0, r1) in ((x0, x1, rx0, rx1), (y0, y1, ry0, ry1)):
            if p1 == p0:
                continue
            t0, t1 = (r0 - p0) / (p1 - p0), (r1 - p0) / (p1 - p0)
            ts.append((min(t0, t1), max(t0, t1)))
        lo_t = max([0.0] + [t[0] for t in ts])
        hi_t = min([1.0] + [t[1] for t in ts])
        return max(0.0, hi_t - lo_t) * n * 2 ** 0.5
    return max(0, hi - lo)


def seg_length(a, b):
    return ((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2) ** 0.5


def outside(segments, pins):
    """Total length of the segments outside the (disjoint) pin rectangles."""
    total = 0.0
    for a, b in segments:
        total += seg_length(a, b) - sum(inside_length(a, b, r) for r in pins)
    return total


def kept_routes(path):
    """{net: ([segment], [pin rect], bends)} of a file written by `taut import --keep-wiring`: each
    wire a 2-point segment on its centreline; a bend where two perpendicular wires meet end to end."""
    root = ET.parse(path).getroot()
    pins = {n.get("name"): [tuple(int(r.get(k)) for k in ("x0", "y0", "x1", "y1")) for r in n.iter("rect")]
            for n in root.findall("net")}
    out = {}
    for r in root.find("routes").findall("route"):
        segs = []
        for w in r.findall("wire"):
            pts = [tuple(int(v) for v in p.split(",")) for p in w.get("points").split()]
            segs += list(zip(pts, pts[1:]))
        ends = {}
        for a, b in segs:
            for p in (a, b):
                ends.setdefault(p, []).append(a[0] == b[0])
        bends = sum(1 for v in ends.values() if len(v) == 2 and v[0] != v[1])
        out[r.get("net")] = (segs, pins[r.get("net")], bends)
    return out


def group(net):
    return net.split("/")[0] if not net.startswith("p_") else "signal (p_*)"


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--taut", default=os.path.join(here, "..", "build", "tools", "taut"))
    ap.add_argument("--data", default=os.path.join(here, "..", "..", "shared", "data", "openroad-rdl"))
    ap.add_argument("--out", default=os.path.join(here, "..", "out", "rdl"))
    ap.add_argument("--orientations", default="rectilinear")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    layout, routed = os.path.join(a.out, "rdl.xml"), os.path.join(a.out, "rdl.routed.xml")
    openroad = os.path.join(a.out, "openroad.xml")
    steps = [
        [a.taut, "import", os.path.join(a.data, "floorplan_flipchip.def"), "--lef", os.path.join(a.data, "dummy_pads.lef"),
         "--layer", "metal10", "--nets", "VDD DVDD VSS DVSS p_*", "--wire-width", "4", "--spacing", "4", "--bump-to-pad",
         "-q", "-o", layout],
        [a.taut, "route", layout, "-o", routed, "--svg", os.path.join(a.out, "rdl.svg"), "--stats",
         os.path.join(a.out, "rdl.json"), "--orientations", a.orientations, "-q"],
        [a.taut, "check", routed],
        [a.taut, "import", os.path.join(a.data, "rdl_route.defok"), "--lef", os.path.join(a.data, "dummy_pads.lef"),
         "--layer", "metal10", "--nets", "VDD DVDD VSS DVSS p_*", "--wire-width", "4", "--spacing", "4",
         "--keep-wiring", "-q", "-o", openroad],
    ]
    seconds = []
    for cmd in steps:
        p, s = run(cmd)
        seconds.append(s)
        if p.returncode not in (0, 1) or (cmd[1] != "route" and p.returncode != 0):
            sys.stderr.write(p.stdout + p.stderr)
            sys.stderr.write("rdl_openroad: %s failed (exit %d)\n" % (cmd[1], p.returncode))
            return 1

    root = ET.parse(routed).getroot()
    pins = {}  # net -> [rect]
    for n in root.findall("net"):
        rects = []
        for pin in n.findall("pin"):
            r = pin.find("rect")
            rects.append(tuple(int(r.get(k)) for k in ("x0", "y0", "x1", "y1")))
        pins[n.get("name")] = rects
    by_group = {}

    def g(name):
        return by_group.setdefault(group(name), {"taut_routed": 0, "taut_nets": 0, "taut_len": 0.0, "taut_bends": 0,
                                                 "or_len": 0.0, "or_bends": 0, "or_pins": []})

    for r in root.find("routes").findall("route"):
        e = g(r.get("net"))
        e["taut_nets"] += 1
        if r.get("status") != "routed":
            continue
        e["taut_routed"] += 1
        e["taut_bends"] += int(r.get("bends"))
        segs = []
        for w in r.findall("wire"):
            pts = [tuple(int(v) for v in p.split(",")) for p in w.get("points").split()]
            segs += list(zip(pts, pts[1:]))
        e["taut_len"] += outside(segs, pins[r.get("net")])
    # OpenROAD's routing, read by taut import --keep-wiring (the same nets, whole)
    for name, (segs, net_pins, bends) in kept_routes(openroad).items():
        e = g(name)
        e["or_len"] += outside(segs, net_pins)
        e["or_bends"] += bends

    print("taut %s against OpenROAD rdl_route on %s (metal10, 4 um wires, 4 um spacing)" % (a.orientations, a.data))
    print("import %.2f s, route %.2f s, check %.2f s; taut check: ok" % tuple(seconds[:3]))
    print("%-14s %6s %8s %16s %16s %7s %9s %9s" % ("nets", "taut", "routed", "OpenROAD length", "taut length", "ratio",
                                                  "OR bends", "taut bends"))
    tot = {"n": 0, "r": 0, "ol": 0.0, "tl": 0.0, "ob": 0, "tb": 0}
    for k in sorted(by_group):
        e = by_group[k]
        print("%-14s %6d %8d %16.0f %16.0f %7.3f %9d %9d" % (k, e["taut_nets"], e["taut_routed"], e["or_len"], e["taut_len"],
                                                             e["taut_len"] / e["or_len"] if e["or_len"] else 0,
                                                             e["or_bends"], e["taut_bends"]))
        tot["n"] += e["taut_nets"]
        tot["r"] += e["taut_routed"]
        tot["ol"] += e["or_len"]
        tot["tl"] += e["taut_len"]
        tot["ob"] += e["or_bends"]
        tot["tb"] += e["taut_bends"]
    print("%-14s %6d %8d %16.0f %16.0f %7.3f %9d %9d" % ("total", tot["n"], tot["r"], tot["ol"], tot["tl"],
                                                         tot["tl"] / tot["ol"], tot["ob"], tot["tb"]))
    print("(lengths in DBU, 2000 per micron, outside the pins of their net; OpenROAD's power nets are compared"
          " whole: a bump taut leaves unrouted still counts in OpenROAD's length)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
