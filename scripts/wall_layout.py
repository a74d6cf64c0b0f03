#!/usr/bin/env python3
"""A generated layout with a wall across the whole domain, for timing the net router on nets the
blockages alone keep apart (docs/PERFORMANCE.md, "A wall across the domain").

Reads a layout written by `taut gen` (its <net> elements last, point pins), drops every net with a pin
within 150 DBU of the wall's line x = X (so that no pin lies in the wall or its clearance), and
writes it with a blockage `wall` 40 DBU wide from the boundary's bottom to its top at x = X. The
nets with pins on both sides (those within a tenth of the layout's side of the line, about 3 % of
them) cannot be routed: `ROUTE-0002`.

Usage: scripts/wall_layout.py IN.xml OUT.xml [--x X]   (X: default the boundary's middle)
"""
import argparse
import re
import sys


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("input")
    ap.add_argument("output")
    ap.add_argument("--x", type=int)
    a = ap.parse_args()
    text = open(a.input, encoding="utf-8").read()
    b = re.search(r'<boundary x0="(-?\d+)" y0="(-?\d+)" x1="(-?\d+)" y1="(-?\d+)"', text)
    if not b:
        print(f"{a.input}: no <boundary>", file=sys.stderr)
        return 1
    x0, y0, x1, y1 = map(int, b.groups())
    x = a.x if a.x is not None else (x0 + x1) // 2
    first = text.find("  <net ")
    if first < 0:
        print(f"{a.input}: no <net>", file=sys.stderr)
        return 1
    nets = re.findall(r"  <net .*?</net>\n", text[first:], flags=re.S)
    kept = [n for n in nets if not any(abs(int(v) - x) <= 150 for v in re.findall(r'<pin [^>]*\bx="(-?\d+)"', n))]
    wall = f'  <blockage id="wall"><rect x0="{x - 20}" y0="{y0}" x1="{x + 20}" y1="{y1}"/></blockage>\n'
    with open(a.output, "w", encoding="utf-8") as f:
        f.write(text[:first] + wall + "".join(kept) + "</layout>\n")
    print(f"{a.output}: wall at x = {x}, {len(kept)} of {len(nets)} nets kept")
    return 0


if __name__ == "__main__":
    sys.exit(main())
