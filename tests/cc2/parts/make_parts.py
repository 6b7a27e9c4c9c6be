#!/usr/bin/env python3
"""Writes the hand-designed recognition test parts of tests/cc2/parts/<name>/: part.ngc (RS274/NGC
as a CAM post writes it: safe-height rapids, plunges, ramps and helices, step-downs, offset and
zigzag clearing, finishing contours, canned cycles; no comments), tools.json, stock.json and
truth.json (the designed features, in the corpus' format, with the operations each is cut by).

The truth is the design, not what the recogniser finds. Run from anywhere:
    python3 tests/cc2/parts/make_parts.py
"""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def fmt(v):
    s = "%.3f" % v
    return "0.000" if s == "-0.000" else s


class Program:
    """An RS274/NGC program in the style of a CAM post (every move with X, Y and Z)."""

    def __init__(self, safe, clearance):
        self.lines = ["G17 G54 G40 G49 G80 G90", "G21"]
        self.safe, self.clearance = safe, clearance
        self.x = self.y = 0.0
        self.z = safe

    def tool(self, number, rpm):
        self.lines += ["M5", "M6 T%d" % number, "G43 H%d" % number, "M3 S%d" % rpm]
        self.lines.append("G0 Z%s" % fmt(self.safe))
        self.z = self.safe

    def rapid(self, x=None, y=None, z=None):
        words = []
        if x is not None:
            self.x = x
            words.append("X" + fmt(x))
        if y is not None:
            self.y = y
            words.append("Y" + fmt(y))
        if z is not None:
            self.z = z
            words.append("Z" + fmt(z))
        self.lines.append("G0 " + " ".join(words))

    def feed(self, x, y, z, f):
        self.x, self.y, self.z = x, y, z
        self.lines.append("G1 X%s Y%s Z%s F%s" % (fmt(x), fmt(y), fmt(z), fmt(f)))

    def arc(self, ccw, x, y, z, cx, cy, f):
        i, j = cx - self.x, cy - self.y
        self.lines.append("%s X%s Y%s Z%s I%s J%s F%s" % ("G3" if ccw else "G2", fmt(x), fmt(y), fmt(z), fmt(i), fmt(j), fmt(f)))
        self.x, self.y, self.z = x, y, z

    def go_to(self, x, y, z_start):
        """Retract, rapid over the start, rapid down to the clearance above z_start."""
        self.rapid(z=self.safe)
        self.rapid(x, y)
        self.rapid(z=z_start + self.clearance)

    def retract(self):
        self.rapid(z=self.safe)

    def cycle(self, code, holes, z, r, f, extra=""):
        """A canned cycle at every hole, G98 (back to the initial level) between holes."""
        self.retract()
        first = True
        for (x, y) in holes:
            if first:
                self.lines.append("G98 %s X%s Y%s Z%s R%s %sF%s" % (code, fmt(x), fmt(y), fmt(z), fmt(r), extra, fmt(f)))
                first = False
            else:
                self.lines.append("X%s Y%s" % (fmt(x), fmt(y)))
            self.x, self.y = x, y
        self.lines.append("G80")

    def text(self):
        return "\n".join(self.lines + ["M5", "G17 G54 G90 G80 G40", "M2"]) + "\n"


# ---------------------------------------------------------------- geometry of toolpaths

def rotate(p, c, angle_deg):
    a = math.radians(angle_deg)
    dx, dy = p[0] - c[0], p[1] - c[1]
    return (c[0] + dx * math.cos(a) - dy * math.sin(a), c[1] + dx * math.sin(a) + dy * math.cos(a))


def rounded_rectangle(c, half_l, half_w, r, angle_deg=0.0, ccw=True):
    """Closed contour: start point and segments ('L', end) / ('A', end, centre, ccw), starting
    in the middle of the +x side (of the rectangle's own frame)."""
    r = max(0.0, min(r, half_l, half_w))
    pts = []
    # Corners CCW from (+x,+y): each corner an arc from side to side.
    corners = [(half_l - r, half_w - r, 0), (-(half_l - r), half_w - r, 90), (-(half_l - r), -(half_w - r), 180),
               (half_l - r, -(half_w - r), 270)]
    start = (half_l, 0.0)
    segs = []
    for (qx, qy, a0) in corners:
        a = math.radians(a0)
        p0 = (qx + r * math.cos(a), qy + r * math.sin(a))
        p1 = (qx + r * math.cos(a + math.pi / 2), qy + r * math.sin(a + math.pi / 2))
        segs.append(("L", p0))
        if r > 1e-9:
            segs.append(("A", p1, (qx, qy), True))
    segs.append(("L", start))

    def place(p):
        return rotate((c[0] + p[0], c[1] + p[1]), c, angle_deg)

    placed = []
    for s in segs:
        if s[0] == "L":
            placed.append(("L", place(s[1])))
        else:
            placed.append(("A", place(s[1]), place(s[2]), True))
    start_p = place(start)
    if not ccw:
        rev = []
        prev = start_p
        pts = [start_p] + [s[1] for s in placed]
        for k in range(len(placed) - 1, -1, -1):
            s = placed[k]
            end = pts[k]
            if s[0] == "L":
                rev.append(("L", end))
            else:
                rev.append(("A", end, s[2], False))
        placed = rev
    return start_p, placed


def circle_contour(c, radius, ccw, start_angle_deg=0.0):
    a = math.radians(start_angle_deg)
    p = (c[0] + radius * math.cos(a), c[1] + radius * math.sin(a))
    return p, [("A", p, c, ccw)]


def run_contour(prog, start, segs, z, f):
    for s in segs:
        if s[0] == "L":
            prog.feed(s[1][0], s[1][1], z, f)
        else:
            prog.arc(s[3], s[1][0], s[1][1], z, s[2][0], s[2][1], f)


def contour_levels(prog, start, segs, levels, top, f, plunge):
    """A closed contour at each level, plunging at its start; no retract between levels."""
    prog.go_to(start[0], start[1], top)
    for z in levels:
        prog.feed(start[0], start[1], z, plunge)
        run_contour(prog, start, segs, z, f)
    prog.retract()


def offset_rings(half_l, half_w, r_corner, first, stepover):
    """Offsets of a rounded rectangle inward from `first`, until the ring collapses."""
    rings = []
    d = first
    while half_w - d > 0.05:
        rings.append((half_l - d, half_w - d, max(0.0, r_corner - d)))
        d += stepover
    return rings


def pocket_offset(prog, c, half_l, half_w, r_corner, angle, tool_r, allowance, stepover, levels, top, f, plunge,
                  inside_out=True, ramp=None):
    """Contour-parallel clearing of a rounded rectangle: concentric rings joined by short feed
    moves, the centre line first when working from the inside out."""
    rings = offset_rings(half_l, half_w, r_corner, tool_r + allowance, stepover)
    order = list(reversed(rings)) if inside_out else rings
    inner = rings[-1]
    centre_line = [rotate((c[0] - (inner[0] - inner[1]), c[1]), c, angle), rotate((c[0] + (inner[0] - inner[1]), c[1]), c, angle)]
    prev_z = top
    for z in levels:
        if inside_out:
            a, b = centre_line
            if ramp:
                prog.go_to(a[0], a[1], prev_z)
                prog.feed(a[0], a[1], prev_z, plunge)
                prog.feed(b[0], b[1], z, plunge)  # ramp along the centre line
                prog.feed(a[0], a[1], z, f)
            else:
                prog.go_to(a[0], a[1], prev_z)
                prog.feed(a[0], a[1], z, plunge)
            prog.feed(b[0], b[1], z, f)
        for k, (hl, hw, rr) in enumerate(order):
            start, segs = rounded_rectangle(c, hl, hw, rr, angle, ccw=True)
            if k == 0 and not inside_out:
                prog.go_to(start[0], start[1], prev_z)
                prog.feed(start[0], start[1], z, plunge)
            else:
                prog.feed(start[0], start[1], z, f)
            run_contour(prog, start, segs, z, f)
        if not inside_out:
            a, b = centre_line
            prog.feed(a[0], a[1], z, f)
            prog.feed(b[0], b[1], z, f)
        prog.retract()
        prev_z = z


def zigzag_lines(prog, lines, levels, top, f, plunge, island=None, bidirectional=True):
    """Parallel passes (each a pair of points), alternating in sense when bidirectional and
    joined at their ends by feed moves. With an island (centre, clearance radius), a pass that
    would cut into it is broken: retract, rapid over, plunge again."""
    prev_z = top
    for z in levels:
        need_entry = True
        for k, (a, b) in enumerate(lines):
            if bidirectional and k % 2 == 1:
                a, b = b, a
            pieces = split_around(a, b, island[0], island[1]) if island else [(a, b)]
            for idx, (p, q) in enumerate(pieces):
                if need_entry or idx > 0:
                    prog.go_to(p[0], p[1], prev_z)
                    prog.feed(p[0], p[1], z, plunge)
                else:
                    prog.feed(p[0], p[1], z, f)
                prog.feed(q[0], q[1], z, f)
                need_entry = False
            need_entry = not bidirectional
        prog.retract()
        prev_z = z


def split_around(a, b, centre, radius):
    """The parts of segment a-b farther than radius from centre."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    L = math.hypot(dx, dy)
    ux, uy = dx / L, dy / L
    t0 = (centre[0] - a[0]) * ux + (centre[1] - a[1]) * uy
    d = abs(-(centre[0] - a[0]) * uy + (centre[1] - a[1]) * ux)
    if d >= radius:
        return [(a, b)]
    h = math.sqrt(radius * radius - d * d)
    out = []
    if t0 - h > 0:
        out.append((a, (a[0] + ux * (t0 - h), a[1] + uy * (t0 - h))))
    if t0 + h < L:
        out.append(((a[0] + ux * (t0 + h), a[1] + uy * (t0 + h)), b))
    return out


def helix_bore(prog, c, radii, top, bottom, pitch, f, ccw=True):
    """Hole milling by helical interpolation: for each radius (inner first) a helix from above
    the top down to the bottom in whole turns, a full circle at the bottom, back to the centre."""
    for radius in radii:
        start = (c[0] + radius, c[1])
        prog.go_to(start[0], start[1], top)
        z = top + 0.5
        prog.feed(start[0], start[1], z, f / 2)
        while z - pitch > bottom + 1e-9:
            z -= pitch
            prog.arc(ccw, start[0], start[1], z, c[0], c[1], f)
        prog.arc(ccw, start[0], start[1], bottom, c[0], c[1], f)
        prog.arc(ccw, start[0], start[1], bottom, c[0], c[1], f)
        prog.feed(c[0], c[1], bottom, f)
        prog.retract()


def concentric_circles(prog, c, radii, levels, top, f, plunge):
    """A circular pocket: plunge at the centre, then circles outward at each level."""
    prev = top
    for z in levels:
        prog.go_to(c[0], c[1], prev)
        prog.feed(c[0], c[1], z, plunge)
        for radius in radii:
            prog.feed(c[0] + radius, c[1], z, f)
            prog.arc(True, c[0] + radius, c[1], z, c[0], c[1], f)
        prog.retract()
        prev = z


def centre_line_slot(prog, a, b, levels, top, f, plunge, ramp=False):
    """A slot cut along its centre line: back and forth, a plunge (or a ramp) at each level."""
    prog.go_to(a[0], a[1], top)
    here, there = a, b
    prev = top
    if ramp:
        prog.feed(a[0], a[1], top, plunge)
        for z in levels:
            prog.feed(b[0], b[1], z, plunge)   # ramp down along the slot
            prog.feed(a[0], a[1], z, f)        # back at the level
            prev = z
        prog.feed(b[0], b[1], levels[-1], f)   # the last ramp's floor
    else:
        for z in levels:
            prog.feed(here[0], here[1], z, plunge)
            prog.feed(there[0], there[1], z, f)
            here, there = there, here
    prog.retract()


def levels_down(top, bottom, step):
    out = []
    z = top
    while z - step > bottom + 1e-9:
        z -= step
        out.append(round(z, 4))
    out.append(bottom)
    return out


# ---------------------------------------------------------------- files

def tool(number, name, kind, diameter, rpm, feed, plunge, **extra):
    t = {"number": number, "name": name, "type": kind, "diameter": diameter, "length": 50 + 5 * number,
         "flute_length": 3 * diameter, "rpm": rpm, "feed": feed, "plunge": plunge}
    t.update(extra)
    return t


def stock(smin, smax, pmin, pmax, zero):
    return {"units": "mm", "shape": "block", "min": list(smin), "max": list(smax),
            "size": [round(smax[i] - smin[i], 3) for i in range(3)], "program_zero": zero,
            "part_bbox_min": list(pmin), "part_bbox_max": list(pmax), "finished_top_z": pmax[2],
            "stock_top_z": smax[2], "note": "hand-designed test part (tests/cc2/parts/make_parts.py)"}


def op(kind, tool_number, strategy):
    return {"type": kind, "tool_number": tool_number, "strategy": strategy}


def feature(fid, kind, position, top, bottom, operations, **extra):
    f = {"id": fid, "type": kind, "position": [position[0], position[1], top], "top_z": top, "bottom_z": bottom,
         "depth": round(top - bottom, 4)}
    f.update(extra)
    f["operations"] = operations
    return f


def write_part(name, description, prog, tools, stock_json, features):
    d = os.path.join(HERE, name)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, "part.ngc"), "w") as out:
        out.write(prog.text())
    with open(os.path.join(d, "tools.json"), "w") as out:
        json.dump(tools, out, indent=1)
        out.write("\n")
    with open(os.path.join(d, "stock.json"), "w") as out:
        json.dump(stock_json, out, indent=1)
        out.write("\n")
    with open(os.path.join(d, "truth.json"), "w") as out:
        json.dump({"part": name, "description": description, "generator": "tests/cc2/parts/make_parts.py",
                   "features": features}, out, indent=1)
        out.write("\n")


# ---------------------------------------------------------------- (a) nested pockets

def nested_pockets():
    tools = [tool(1, "FaceMill_D50", "face_mill", 50, 2200, 1000, 300),
             tool(2, "EndMill_D12", "flat_end_mill", 12, 6500, 900, 250),
             tool(3, "EndMill_D10", "flat_end_mill", 10, 7000, 800, 200),
             tool(4, "EndMill_D6", "flat_end_mill", 6, 10000, 600, 150),
             tool(5, "Drill_D6", "twist_drill", 6, 2200, 120, 120, tip_angle=118)]
    p = Program(safe=15, clearance=3)
    p.tool(1, 2200)
    zigzag_lines(p, [((-30, y), (140, y)) for y in (10, 40, 70)], [0.0], 1.0, 1000, 300)
    p.tool(2, 6500)
    start, segs = rounded_rectangle((55, 40), 55 + 6, 40 + 6, 6, 0, ccw=False)
    contour_levels(p, start, segs, levels_down(0, -25, 6.25), 0, 900, 250)
    p.tool(3, 7000)
    pocket_offset(p, (40, 40), 30, 20, 6, 0, 5, 0.3, 4.5, [-4.0, -8.0], 0, 800, 200, inside_out=True)
    p.tool(4, 10000)
    start, segs = rounded_rectangle((40, 40), 30 - 3, 20 - 3, 3, 0, ccw=True)
    contour_levels(p, start, segs, [-8.0], -8.0, 600, 150)
    pocket_offset(p, (30, 40), 15, 8, 4, 0, 3, 0.0, 2.5, [-11.0, -14.0], -8, 600, 150, inside_out=False)
    concentric_circles(p, (58, 40), [1.5, 4.0], [-10.0, -12.0, -14.0, -16.0], -8, 600, 150)
    p.tool(5, 2200)
    p.cycle("G83", [(58, 40)], -27, -15, 120, "Q3.000 ")
    p.retract()
    features = [
        feature("F1", "planar_face", (55, 40), 1.0, 0.0, [op("plane_finish_milling", 1, "bidirectional")]),
        feature("F2", "general_outside_profile", (55, 40), 0.0, -25.0, [op("side_finish_milling", 2, "contour")],
                outline="rectangle 110 x 80, corner radius 0"),
        feature("F3", "closed_pocket", (40, 40), 0.0, -8.0,
                [op("bottom_and_side_rough_milling", 3, "contour_parallel"), op("bottom_and_side_finish_milling", 4, "contour")],
                shape="rounded_rectangle", dimensions={"length": 60, "width": 40, "corner_radius": 6, "angle_deg": 0}),
        feature("F4", "closed_pocket", (30, 40), -8.0, -14.0, [op("bottom_and_side_rough_milling", 4, "contour_parallel")],
                shape="rounded_rectangle", dimensions={"length": 30, "width": 16, "corner_radius": 4, "angle_deg": 0},
                note="nested in F3's floor"),
        feature("F5", "closed_pocket", (58, 40), -8.0, -16.0, [op("bottom_and_side_rough_milling", 4, "contour_parallel")],
                shape="circular", dimensions={"diameter": 14}, note="nested in F3's floor, concentric circles"),
        feature("F6", "round_hole", (58, 40), -16.0, -25.0, [op("multistep_drilling", 5, "plunge")],
                dimensions={"diameter": 6}, bottom_condition="through", note="in F5's floor"),
    ]
    write_part("p06_nested_pockets", "110x80x25 block, zero at the finished top's front left corner: faced, "
               "outside profile, 60x40 R6 pocket roughed (offset, inside out) and finished, a 30x16 R4 pocket and "
               "a D14 circular pocket nested in its floor, a D6 through hole peck-drilled in the circular pocket's floor",
               p, tools, stock((-4, -4, -25), (114, 84, 1), (0, 0, -25), (110, 80, 0), "part_top_corner"), features)


# ---------------------------------------------------------------- (b) helix-milled holes

def helix_holes():
    tools = [tool(1, "SpotDrill_D10", "spot_drill", 10, 2500, 150, 150, tip_angle=90),
             tool(2, "EndMill_D8", "flat_end_mill", 8, 8000, 600, 200),
             tool(3, "Drill_D7.8", "twist_drill", 7.8, 2000, 140, 140, tip_angle=118),
             tool(4, "Reamer_D8", "reamer", 8, 600, 90, 90)]
    p = Program(safe=10, clearance=2)
    reamed = [(-42, -25), (42, 25)]
    p.tool(1, 2500)
    p.cycle("G82", reamed, -1.5, 2, 150, "P0.300 ")
    p.tool(2, 8000)
    helix_bore(p, (-30, 15), [2.0], 0, -20.5, 1.5, 600)
    helix_bore(p, (-30, -15), [4.0], 0, -10.0, 1.0, 600)
    helix_bore(p, (0, 10), [2.4, 6.0], 0, -20.5, 1.5, 600)
    helix_bore(p, (30, 0), [2.0, 5.5, 9.0], 0, -6.0, 1.0, 600)
    helix_bore(p, (30, 0), [3.0], -6.0, -20.5, 1.5, 600)
    p.tool(3, 2000)
    p.cycle("G83", reamed, -23, 2, 140, "Q4.000 ")
    p.tool(4, 600)
    p.cycle("G85", reamed, -21, 2, 90)
    p.retract()
    features = [
        feature("F1", "round_hole", (-30, 15), 0.0, -20.0, [op("bottom_and_side_rough_milling", 2, "helical")],
                dimensions={"diameter": 12}, bottom_condition="through"),
        feature("F2", "round_hole", (-30, -15), 0.0, -10.0, [op("bottom_and_side_rough_milling", 2, "helical")],
                dimensions={"diameter": 16}, bottom_condition="flat"),
        feature("F3", "round_hole", (0, 10), 0.0, -20.0, [op("bottom_and_side_rough_milling", 2, "helical")],
                dimensions={"diameter": 20}, bottom_condition="through", note="two helices, inner then outer"),
        feature("F4", "round_hole", (30, 0), 0.0, -6.0, [op("bottom_and_side_rough_milling", 2, "helical")],
                dimensions={"diameter": 26}, bottom_condition="flat", note="counterbore, three helices"),
        feature("F5", "round_hole", (30, 0), -6.0, -20.0, [op("bottom_and_side_rough_milling", 2, "helical")],
                dimensions={"diameter": 14}, bottom_condition="through", note="under the counterbore"),
        feature("F6", "round_hole", reamed[0], 0.0, -20.0,
                [op("center_drilling", 1, "plunge"), op("multistep_drilling", 3, "plunge"), op("reaming", 4, "plunge")],
                dimensions={"diameter": 8}, bottom_condition="through"),
        feature("F7", "round_hole", reamed[1], 0.0, -20.0,
                [op("center_drilling", 1, "plunge"), op("multistep_drilling", 3, "plunge"), op("reaming", 4, "plunge")],
                dimensions={"diameter": 8}, bottom_condition="through"),
    ]
    write_part("p07_helix_holes", "100x70x20 plate blank, zero at top centre: holes milled by helical interpolation "
               "with a D8 end mill (D12 and D20 through, D16 blind, a D26 counterbore over a D14 through hole; "
               "several helix radii where one does not clear the hole), two D8 holes spotted, peck-drilled and reamed",
               p, tools, stock((-50, -35, -20), (50, 35, 0), (-50, -35, -20), (50, 35, 0), "part_top_center"), features)


# ---------------------------------------------------------------- (c) multi-level part

def multi_level():
    tools = [tool(1, "FaceMill_D50", "face_mill", 50, 2200, 1000, 300),
             tool(2, "EndMill_D16", "flat_end_mill", 16, 5000, 900, 250),
             tool(3, "EndMill_D10", "flat_end_mill", 10, 7000, 800, 200),
             tool(4, "Drill_D8", "twist_drill", 8, 2000, 150, 150, tip_angle=118)]
    p = Program(safe=55, clearance=3)
    p.tool(1, 2200)
    zigzag_lines(p, [((x, -30), (x, 90)) for x in (5, 35, 65, 95)], [40.0], 42.0, 1000, 300)
    p.tool(2, 5000)
    # x- step, 20 wide, down to 30: passes along Y, the last beyond the open side
    zigzag_lines(p, [((x, -10), (x, 70)) for x in (12, 2, -8)], [35.0, 30.0], 40, 900, 250)
    # x+ step, 20 wide, down to 22, around a D16 boss standing at (90, 30)
    zigzag_lines(p, [((x, -10), (x, 70)) for x in (88, 95, 102, 109)], levels_down(40, 22, 6), 40, 900, 250,
                 island=((90, 30), 16.5))
    # the boss: an outside contour around it at each level (climb, clockwise)
    start, segs = circle_contour((90, 30), 16, ccw=False)
    contour_levels(p, start, segs, levels_down(40, 22, 6), 40, 900, 250)
    p.tool(3, 7000)
    # y- step between the two lower steps: 10 wide, down to 36, passes along X
    zigzag_lines(p, [((15, y), (85, y)) for y in (5, -2)], [36.0], 40, 800, 200)
    # open pocket from the y+ side: 30 x 20 (inner corners R5), extended 6 beyond the open side
    pocket_offset(p, (50, 53), 15, 13, 5, 0, 5, 0.0, 4.0, [36.5, 33.0], 40, 800, 200, inside_out=False)
    p.tool(4, 2000)
    p.cycle("G81", [(10, 15), (10, 45)], -2, 32, 150)
    p.retract()
    features = [
        feature("F1", "planar_face", (50, 30), 42.0, 40.0, [op("plane_finish_milling", 1, "bidirectional")]),
        feature("F2", "step", (10, 30), 40.0, 30.0, [op("bottom_and_side_rough_milling", 2, "bidirectional")],
                open_sides=["x-"], region_xy=[0, 0, 20, 60]),
        feature("F3", "step", (90, 30), 40.0, 22.0, [op("bottom_and_side_rough_milling", 2, "bidirectional")],
                open_sides=["x+"], region_xy=[80, 0, 100, 60], note="the D16 boss stands in it"),
        feature("F4", "general_outside_profile", (90, 30), 40.0, 22.0, [op("side_finish_milling", 2, "contour")],
                outline="circle D16 (a boss)"),
        feature("F5", "step", (50, 5), 40.0, 36.0, [op("bottom_and_side_rough_milling", 3, "bidirectional")],
                open_sides=["y-"], region_xy=[20, 0, 80, 10], note="between the two lower steps"),
        feature("F6", "open_pocket", (50, 50), 40.0, 33.0, [op("bottom_and_side_rough_milling", 3, "contour_parallel")],
                open_sides=["y+"], region_xy=[35, 40, 65, 60]),
        feature("F7", "round_hole", (10, 15), 30.0, 0.0, [op("drilling", 4, "plunge")], dimensions={"diameter": 8},
                bottom_condition="through"),
        feature("F8", "round_hole", (10, 45), 30.0, 0.0, [op("drilling", 4, "plunge")], dimensions={"diameter": 8},
                bottom_condition="through"),
    ]
    write_part("p08_multi_level", "100x60x40 block, zero at the part's bottom front left corner: faced; steps at three "
               "heights (x- to 30, x+ to 22 around a D16 boss left standing, y- to 36 between them); an open pocket "
               "from y+; two through holes in the x- step's floor",
               p, tools, stock((-3, -3, 0), (103, 63, 42), (0, 0, 0), (100, 60, 40), "part_bottom_corner"), features)


# ---------------------------------------------------------------- (d) small part

def small_part():
    tools = [tool(1, "EndMill_D3", "flat_end_mill", 3, 18000, 400, 100),
             tool(2, "EndMill_D2", "flat_end_mill", 2, 22000, 300, 80),
             tool(3, "SpotDrill_D3", "spot_drill", 3, 8000, 80, 80, tip_angle=90),
             tool(4, "Drill_D1.5", "twist_drill", 1.5, 9000, 60, 60, tip_angle=118)]
    p = Program(safe=5, clearance=1)
    p.tool(1, 18000)
    # face 0.5: passes along X, 2 mm apart
    zigzag_lines(p, [((-2, y), (22, y)) for y in [0.5 + 2.0 * k for k in range(8)]], [7.5], 8.0, 400, 100)
    # closed pocket 8 x 5 R1.5, 2 deep: offset clearing with the D2
    p.tool(2, 22000)
    pocket_offset(p, (6, 9), 4, 2.5, 1.5, 0, 1, 0.0, 0.8, [6.5, 5.5], 7.5, 300, 80, inside_out=True)
    # slot with round ends, 3 wide, 1.5 deep, centre line along Y with the D3
    p.tool(1, 18000)
    centre_line_slot(p, (15, 4), (15, 11), [7.0, 6.5, 6.0], 7.5, 400, 100)
    p.tool(3, 8000)
    holes = [(2.5, 2.5), (2.5, 13.5)]
    p.cycle("G81", holes, 7.0, 8.5, 80)
    p.tool(4, 9000)
    p.cycle("G83", holes, -0.8, 8.5, 60, "Q1.000 ")
    # outside profile, step-downs of 2.5 with the D3
    p.tool(1, 18000)
    start, segs = rounded_rectangle((10, 7.5), 10 + 1.5, 7.5 + 1.5, 1.5, 0, ccw=False)
    contour_levels(p, start, segs, levels_down(7.5, 0, 2.5), 7.5, 400, 100)
    features = [
        feature("F1", "planar_face", (10, 7.5), 8.0, 7.5, [op("plane_finish_milling", 1, "bidirectional")]),
        feature("F2", "closed_pocket", (6, 9), 7.5, 5.5, [op("bottom_and_side_rough_milling", 2, "contour_parallel")],
                shape="rounded_rectangle", dimensions={"length": 8, "width": 5, "corner_radius": 1.5, "angle_deg": 0}),
        feature("F3", "slot", (15, 7.5), 7.5, 6.0, [op("bottom_and_side_rough_milling", 1, "center_milling")],
                shape="closed_slot_round_ends", end_conditions=["closed_radiused", "closed_radiused"],
                dimensions={"width": 3, "length_overall": 10}),
        feature("F4", "round_hole", holes[0], 7.5, 0.0, [op("center_drilling", 3, "plunge"), op("multistep_drilling", 4, "plunge")],
                dimensions={"diameter": 1.5}, bottom_condition="through"),
        feature("F5", "round_hole", holes[1], 7.5, 0.0, [op("center_drilling", 3, "plunge"), op("multistep_drilling", 4, "plunge")],
                dimensions={"diameter": 1.5}, bottom_condition="through"),
        feature("F6", "general_outside_profile", (10, 7.5), 7.5, 0.0, [op("side_finish_milling", 1, "contour")],
                outline="rectangle 20 x 15"),
    ]
    write_part("p09_small_part", "20x15x7.5 part from a 22x17x8 blank, zero at the bottom front left corner: faced 0.5 "
               "with a D3, 8x5 R1.5 pocket (D2), 3 mm round-ended slot (D3 centre line), two D1.5 through holes "
               "spotted and peck-drilled, outside profile in step-downs",
               p, tools, stock((-1, -1, 0), (21, 16, 8), (0, 0, 0), (20, 15, 7.5), "part_bottom_corner"), features)


# ---------------------------------------------------------------- (e) plate

def plate():
    tools = [tool(1, "CenterDrill_D4", "center_drill", 4, 3000, 100, 100, tip_angle=60),
             tool(2, "Drill_D6.6", "twist_drill", 6.6, 2400, 150, 150, tip_angle=118),
             tool(3, "Drill_D11", "twist_drill", 11, 1500, 120, 120, tip_angle=118),
             tool(4, "BoringBar_D12", "boring_bar", 12, 1200, 60, 60),
             tool(5, "EndMill_D8", "flat_end_mill", 8, 8000, 700, 200)]
    p = Program(safe=10, clearance=2)
    small = [(10, 10), (110, 10), (110, 70), (10, 70)]
    bore = (30, 40)
    p.tool(1, 3000)
    p.cycle("G82", small + [bore], -2, 2, 100, "P0.200 ")
    p.tool(2, 2400)
    p.cycle("G81", small, -8.5, 2, 150)
    p.tool(3, 1500)
    p.cycle("G81", [bore], -9.5, 2, 120)
    p.tool(4, 1200)
    p.cycle("G85", [bore], -6.5, 2, 60)
    p.tool(5, 8000)
    # through pocket 40 x 25 R5 at (75, 40): ramped centre-line entry, offset rings, 2 mm step-downs to 0.5 below
    pocket_offset(p, (75, 40), 20, 12.5, 5, 0, 4, 0.0, 3.5, [-2.0, -4.0, -6.5], 0, 700, 200, inside_out=True, ramp=True)
    # outside profile through, in step-downs, with four tabs on the last level
    start, segs = rounded_rectangle((60, 40), 60 + 4, 40 + 4, 4, 0, ccw=False)
    contour_levels(p, start, segs, [-2.0, -4.0], 0, 700, 200)
    profile_with_tabs(p, (60, 40), 64, 44, 4, -6.5, -4.5, 6, 700, 200)
    features = [
        feature("F1", "round_hole", small[0], 0.0, -6.0, [op("center_drilling", 1, "plunge"), op("drilling", 2, "plunge")],
                dimensions={"diameter": 6.6}, bottom_condition="through"),
        feature("F2", "round_hole", small[1], 0.0, -6.0, [op("center_drilling", 1, "plunge"), op("drilling", 2, "plunge")],
                dimensions={"diameter": 6.6}, bottom_condition="through"),
        feature("F3", "round_hole", small[2], 0.0, -6.0, [op("center_drilling", 1, "plunge"), op("drilling", 2, "plunge")],
                dimensions={"diameter": 6.6}, bottom_condition="through"),
        feature("F4", "round_hole", small[3], 0.0, -6.0, [op("center_drilling", 1, "plunge"), op("drilling", 2, "plunge")],
                dimensions={"diameter": 6.6}, bottom_condition="through"),
        feature("F5", "round_hole", bore, 0.0, -6.0,
                [op("center_drilling", 1, "plunge"), op("drilling", 3, "plunge"), op("boring", 4, "plunge")],
                dimensions={"diameter": 12}, bottom_condition="through"),
        feature("F6", "closed_pocket", (75, 40), 0.0, -6.0, [op("bottom_and_side_rough_milling", 5, "contour_parallel")],
                shape="rounded_rectangle", dimensions={"length": 40, "width": 25, "corner_radius": 5, "angle_deg": 0},
                bottom_condition="through"),
        feature("F7", "general_outside_profile", (60, 40), 0.0, -6.0, [op("side_finish_milling", 5, "contour")],
                outline="rectangle 120 x 80, four tabs 2 high"),
    ]
    write_part("p10_plate", "120x80x6 plate from a 128x88x6 blank, zero at the top front left corner: four D6.6 "
               "through holes (centre drilled, drilled), a D12 through hole drilled and bored, a 40x25 R5 through "
               "pocket, the outside profile cut through in step-downs with four tabs",
               p, tools, stock((-4, -4, -6), (124, 84, 0), (0, 0, -6), (120, 80, 0), "part_top_corner"), features)


def profile_with_tabs(prog, c, half_l, half_w, r, z, tab_z, tab_len, f, plunge):
    """The last level of an outside contour (clockwise) rising over a tab in the middle of each
    side: ramp-free up and down moves, as CAM tab generators post them."""
    hl, hw = half_l - r, half_w - r
    x0, x1, y0, y1 = c[0] - half_l, c[0] + half_l, c[1] - half_w, c[1] + half_w
    t = tab_len / 2
    prog.go_to(x1, c[1] - t, tab_z)
    prog.feed(x1, c[1] - t, z, plunge)

    def side(points):
        for (px, py, pz) in points:
            prog.feed(px, py, pz, f)

    # begins just past the tab in the middle of the +x side, going -y (clockwise)
    side([(x1, y0 + r, z)])
    prog.arc(False, c[0] + hl, y0, z, c[0] + hl, y0 + r, f)
    side([(c[0] + t, y0, z), (c[0] + t, y0, tab_z), (c[0] - t, y0, tab_z), (c[0] - t, y0, z), (x0 + r, y0, z)])
    prog.arc(False, x0, y0 + r, z, x0 + r, y0 + r, f)
    side([(x0, c[1] - t, z), (x0, c[1] - t, tab_z), (x0, c[1] + t, tab_z), (x0, c[1] + t, z), (x0, y1 - r, z)])
    prog.arc(False, x0 + r, y1, z, x0 + r, y1 - r, f)
    side([(c[0] - t, y1, z), (c[0] - t, y1, tab_z), (c[0] + t, y1, tab_z), (c[0] + t, y1, z), (x1 - r, y1, z)])
    prog.arc(False, x1, y1 - r, z, x1 - r, y1 - r, f)
    side([(x1, c[1] + t, z), (x1, c[1] + t, tab_z), (x1, c[1] - t, tab_z)])
    prog.retract()


# ---------------------------------------------------------------- (f) slots and a rotated pocket

def slots():
    tools = [tool(1, "EndMill_D10", "flat_end_mill", 10, 7000, 800, 200),
             tool(2, "EndMill_D8", "flat_end_mill", 8, 8000, 700, 200),
             tool(3, "EndMill_D6", "flat_end_mill", 6, 10000, 600, 150)]
    p = Program(safe=20, clearance=3)
    # round-ended slot, 8 wide, centre line (15,15)-(65,15), 6 deep: ramps along the centre line
    p.tool(2, 8000)
    centre_line_slot(p, (15, 15), (65, 15), [-2.0, -4.0, -6.0], 0, 700, 200, ramp=True)
    # round-ended slot 10 wide at 45 degrees, plunged back and forth in step-downs of 1.5
    p.tool(1, 7000)
    a, b = (80, 10), (80 + 30 * math.cos(math.radians(45)), 10 + 30 * math.sin(math.radians(45)))
    centre_line_slot(p, a, b, [-1.5, -3.0, -4.5], 0, 800, 200)
    # rotated rectangular pocket 36 x 20 R4 at 25 degrees, centre (45, 48): offset roughing
    # from the outside in with a D10 leaving 0.4, finished with the D6 in one contour
    pocket_offset(p, (45, 48), 18, 10, 4, 25, 5, 0.4, 4.0, [-3.0, -6.0, -9.0], 0, 800, 200, inside_out=False)
    p.tool(3, 10000)
    start, segs = rounded_rectangle((45, 48), 18 - 3, 10 - 3, 1, 25, ccw=True)
    contour_levels(p, start, segs, [-4.5, -9.0], 0, 600, 150)
    features = [
        feature("F1", "slot", (40, 15), 0.0, -6.0, [op("bottom_and_side_rough_milling", 2, "center_milling")],
                shape="closed_slot_round_ends", end_conditions=["closed_radiused", "closed_radiused"],
                dimensions={"width": 8, "length_overall": 58}),
        feature("F2", "slot", ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2), 0.0, -4.5,
                [op("bottom_and_side_rough_milling", 1, "center_milling")], shape="closed_slot_round_ends",
                end_conditions=["closed_radiused", "closed_radiused"], dimensions={"width": 10, "length_overall": 40, "angle_deg": 45}),
        feature("F3", "closed_pocket", (45, 48), 0.0, -9.0,
                [op("bottom_and_side_rough_milling", 1, "contour_parallel"), op("bottom_and_side_finish_milling", 3, "contour")],
                shape="rounded_rectangle", dimensions={"length": 36, "width": 20, "corner_radius": 4, "angle_deg": 25}),
    ]
    write_part("p11_slots_rotated_pocket", "120x70x20 block, zero at the top front left corner: a round-ended 8 mm "
               "slot ramped along its centre line, a round-ended 10 mm slot at 45 degrees in plunged step-downs, "
               "a 36x20 R4 pocket at 25 degrees roughed (offset) and finished with a smaller tool",
               p, tools, stock((0, 0, -20), (120, 70, 0), (0, 0, -20), (120, 70, 0), "part_top_corner"), features)


# ---------------------------------------------------------------- (g) FreeCAD-style variations

def helix_half_turns(prog, c, radii, top, bottom, pitch, f, ccw=False):
    """Hole milling as FreeCAD's Helix operation posts it: per radius, a feed down to the top,
    half-circle arcs falling pitch/2 each, a flat full circle at the bottom, a rapid to the centre
    and up."""
    for radius in radii:
        a, b = (c[0] + radius, c[1]), (c[0] - radius, c[1])
        prog.retract()
        prog.rapid(a[0], a[1])
        prog.feed(a[0], a[1], top, f / 2)
        turns = max(2, int(math.ceil((top - bottom) / pitch)))
        for k in range(1, turns + 1):
            prog.arc(ccw, b[0], b[1], top - (top - bottom) * (2 * k - 1) / (2 * turns), c[0], c[1], f)
            prog.arc(ccw, a[0], a[1], top - (top - bottom) * (2 * k) / (2 * turns), c[0], c[1], f)
        prog.arc(ccw, b[0], b[1], bottom, c[0], c[1], f)
        prog.arc(ccw, a[0], a[1], bottom, c[0], c[1], f)
        prog.rapid(c[0], c[1], bottom)
        prog.retract()


def variations():
    tools = [tool(1, "EndMill_D6", "flat_end_mill", 6, 10000, 600, 150),
             tool(2, "EndMill_D10", "flat_end_mill", 10, 7000, 800, 200)]
    p = Program(safe=12, clearance=3)
    p.tool(1, 10000)
    helix_half_turns(p, (15, 15), [1.5], 0, -12, 1.5, 600)             # D9 blind, one radius
    helix_half_turns(p, (40, 15), [1.5, 4.5], 0, -30.5, 2, 600)        # D15 through, inner first
    start, segs = circle_contour((75, 15), 8, ccw=True)                 # D22 bored by one circle
    contour_levels(p, start, segs, [-3.0, -6.0, -9.0], 0, 600, 150)     # per level, core left
    # open pocket from the y+ edge, not extended: the outer ring's tool edge runs along y = 90
    pocket_offset(p, (67.5, 82.5), 7.5, 7.5, 3, 0, 3, 0.0, 2.5, [-3.0, -6.0], 0, 600, 150, inside_out=False)
    p.tool(2, 7000)
    # a pocket and a large pocket nested in its floor, one after the other with the same tool
    pocket_offset(p, (30, 55), 25, 15, 5, 0, 5, 0.0, 4.0, [-4.0, -8.0], 0, 800, 200, inside_out=False)
    pocket_offset(p, (30, 55), 20, 11, 5, 0, 5, 0.0, 4.0, [-11.0, -14.0], -8, 800, 200, inside_out=False)
    # x+ step to -20, then a pocket on the top level running out over it
    zigzag_lines(p, [((x, -8), (x, 98)) for x in (105, 113, 121)], levels_down(0, -20, 5), 0, 800, 200)
    pocket_offset(p, (93, 65), 13, 10, 3, 0, 5, 0.0, 4.0, [-5.0, -10.0], 0, 800, 200, inside_out=False)
    start, segs = rounded_rectangle((60, 45), 60 + 5, 45 + 5, 5, 0, ccw=False)
    contour_levels(p, start, segs, levels_down(0, -30, 7.5), 0, 800, 200)
    features = [
        feature("F1", "round_hole", (15, 15), 0.0, -12.0, [op("bottom_and_side_rough_milling", 1, "helical")],
                dimensions={"diameter": 9}, bottom_condition="flat"),
        feature("F2", "round_hole", (40, 15), 0.0, -30.0, [op("bottom_and_side_rough_milling", 1, "helical")],
                dimensions={"diameter": 15}, bottom_condition="through"),
        feature("F3", "round_hole", (75, 15), 0.0, -9.0, [op("bottom_and_side_rough_milling", 1, "contour")],
                dimensions={"diameter": 22}, bottom_condition="flat", note="one circle per level, its core a chip"),
        feature("F4", "open_pocket", (67.5, 82.5), 0.0, -6.0, [op("bottom_and_side_rough_milling", 1, "contour_parallel")],
                open_sides=["y+"], region_xy=[60, 75, 75, 90]),
        feature("F5", "closed_pocket", (30, 55), 0.0, -8.0, [op("bottom_and_side_rough_milling", 2, "contour_parallel")],
                shape="rounded_rectangle", dimensions={"length": 50, "width": 30, "corner_radius": 5, "angle_deg": 0}),
        feature("F6", "closed_pocket", (30, 55), -8.0, -14.0, [op("bottom_and_side_rough_milling", 2, "contour_parallel")],
                shape="rounded_rectangle", dimensions={"length": 40, "width": 22, "corner_radius": 5, "angle_deg": 0},
                note="nested in F5's floor, cut right after it with the same tool"),
        feature("F7", "step", (110, 45), 0.0, -20.0, [op("bottom_and_side_rough_milling", 2, "bidirectional")],
                open_sides=["x+"], region_xy=[100, 0, 120, 90]),
        feature("F8", "open_pocket", (90, 65), 0.0, -10.0, [op("bottom_and_side_rough_milling", 2, "contour_parallel")],
                region_xy=[80, 55, 100, 75], note="opens onto the step F7"),
        feature("F9", "general_outside_profile", (60, 45), 0.0, -30.0, [op("side_finish_milling", 2, "contour")],
                outline="rectangle 120 x 90"),
    ]
    write_part("p12_freecad_style", "120x90x30 block, zero at the top front left corner: holes milled as FreeCAD's "
               "Helix posts them (half-circle arcs), a bore by one circle per level, an open pocket not extended "
               "beyond its open side, a large pocket nested in a pocket cut with the same tool, a step and a pocket "
               "running out over it, the outside profile",
               p, tools, stock((-3, -3, -30), (123, 93, 0), (0, 0, -30), (120, 90, 0), "part_top_corner"), features)


# ---------------------------------------------------------------- (h) Fusion 360 / HSM style

def trochoid_lane(prog, a, b, y, loop_r, advance, z, entry_top, f, plunge):
    """Adaptive (trochoidal) clearing along one lane as HSM posts it: a helical ramp into the
    material at the lane's start (turns of 1 mm down to the level), then loops, each two
    half-circles advancing by `advance`, and a lift at the end (no full retract)."""
    prog.go_to(a + loop_r, y, entry_top)
    zz = entry_top + 0.5
    prog.feed(a + loop_r, y, zz, plunge)
    while zz - 1.0 > z + 1e-9:
        zz -= 1.0
        prog.arc(True, a + loop_r, y, zz, a, y, plunge)
    prog.arc(True, a + loop_r, y, z, a, y, plunge)
    prog.feed(a, y - loop_r, z, f)
    x = a
    while x + advance <= b + 1e-9:
        prog.arc(True, x + advance / 2, y + loop_r, z, x + advance / 4, y, f)
        prog.arc(True, x + advance, y - loop_r, z, x + 3 * advance / 4, y, f)
        x += advance
    prog.arc(True, x, y + loop_r, z, x, y, f)
    prog.arc(True, x, y - loop_r, z, x, y, f)
    prog.rapid(z=z + 1)


def faced_with_arc_links(prog, x0, x1, ys, z, f, plunge):
    """Facing in passes along X joined by half-circles outside the stock (HSM's facing)."""
    prog.go_to(x0, ys[0], z)
    prog.feed(x0, ys[0], z, plunge)
    here, there = x0, x1
    for k, y in enumerate(ys):
        prog.feed(there, y, z, f)
        if k + 1 < len(ys):
            ny = ys[k + 1]
            prog.arc(there > here, there, ny, z, there, (y + ny) / 2, f)
            here, there = there, here
    prog.retract()


def hsm_style():
    tools = [tool(1, "FaceMill_D40", "face_mill", 40, 3000, 1200, 400),
             tool(2, "EndMill_D10", "flat_end_mill", 10, 9000, 1800, 400),
             tool(3, "EndMill_D4", "flat_end_mill", 4, 14000, 500, 150),
             tool(4, "SpotDrill_D10", "spot_drill", 10, 3000, 150, 150, tip_angle=90),
             tool(5, "Drill_D6.8", "twist_drill", 6.8, 2200, 180, 180, tip_angle=118)]
    p = Program(safe=15, clearance=2)
    # face 1 mm: three passes along X, half-circle links beyond the stock
    p.tool(1, 3000)
    faced_with_arc_links(p, -25, 125, [8, 33, 58], 0.0, 1200, 400)
    # 50 x 30 R6 pocket at (30, 35), 8 deep: adaptive lanes along X with the D10 (0.3 left),
    # each lane ramped in by a helix; then rest-machined and finished with the D4 (contour)
    p.tool(2, 9000)
    c, hl, hw = (30.0, 35.0), 25.0, 15.0
    loop_r, advance = 2.5, 1.5
    reach = 5 + 0.3 + loop_r
    lanes = [c[1] - hw + reach + k * (2 * (hw - reach)) / 3 for k in range(4)]
    for z in (-4.0, -8.0):
        for y in lanes:
            trochoid_lane(p, c[0] - hl + reach, c[0] + hl - reach, y, loop_r, advance, z, z + 4.0, 1800, 400)
        p.retract()
    p.tool(3, 14000)
    start, segs = rounded_rectangle(c, hl - 2, hw - 2, 4, 0, ccw=True)
    contour_levels(p, start, segs, [-4.0, -8.0], 0, 500, 150)
    # four through holes: spotted (G81, 1.5 deep), peck drilled through (G83)
    holes = [(72, 15), (90, 15), (72, 55), (90, 55)]
    p.tool(4, 3000)
    p.cycle("G81", holes, -1.5, 2, 150)
    p.tool(5, 2200)
    p.cycle("G83", holes, -17.5, 2, 180, "Q3.000 ")
    # outside profile 100 x 70 R5: roughed in three depths leaving 0.3, finished in two
    p.tool(2, 9000)
    start, segs = rounded_rectangle((50, 35), 50 + 5.3, 35 + 5.3, 5.3, 0, ccw=False)
    contour_levels(p, start, segs, [-5.0, -10.0, -15.3], 0, 1800, 400)
    start, segs = rounded_rectangle((50, 35), 50 + 5, 35 + 5, 5, 0, ccw=False)
    contour_levels(p, start, segs, [-7.5, -15.3], 0, 1200, 400)
    features = [
        feature("F1", "planar_face", (50, 35), 1.0, 0.0, [op("plane_finish_milling", 1, "bidirectional")]),
        feature("F2", "closed_pocket", c, 0.0, -8.0,
                [op("bottom_and_side_rough_milling", 2, "adaptive"), op("bottom_and_side_finish_milling", 3, "contour")],
                shape="rounded_rectangle", dimensions={"length": 50, "width": 30, "corner_radius": 6, "angle_deg": 0}),
    ] + [
        feature("F%d" % (3 + k), "round_hole", h, 0.0, -15.0,
                [op("center_drilling", 4, "plunge"), op("multistep_drilling", 5, "plunge")],
                dimensions={"diameter": 6.8}, bottom_condition="through")
        for k, h in enumerate(holes)
    ] + [
        feature("F7", "general_outside_profile", (50, 35), 0.0, -15.0,
                [op("side_rough_milling", 2, "contour"), op("side_finish_milling", 2, "contour")],
                outline="rectangle 100 x 70"),
    ]
    write_part("p13_hsm_style", "100x70x15 part from a 104x74x16 blank, zero at the top front left corner, cut as "
               "Fusion 360 / HSM posts it: facing with half-circle links, a 50x30 R6 pocket by adaptive "
               "(trochoidal) lanes each ramped in by a helix, rest-machined and finished with a smaller tool, holes "
               "spot drilled then peck drilled, the outside profile roughed then finished in depths",
               p, tools, stock((-2, -2, -15), (102, 72, 1), (0, 0, -15), (100, 70, 0), "part_top_corner"), features)


# ---------------------------------------------------------------- (i) a hand-written shop program

SHOP_PROGRAM = """%
(shop program, written at the machine: subprograms, loops, incremental moves, canned cycles)
G17 G21 G40 G49 G80 G90 G94
G54
(face the saw-cut block, 0.5 mm, two passes)
M6 T1
G43 H1
M3 S2000
G0 X-35 Y20 Z10
G1 Z0 F300
G1 X155 F900
G1 Y60
G1 X-35
G0 Z10
(pocket 40 x 24 R4 at 35/40: zigzag per depth in a subprogram, 0.3 left on the walls)
o100 sub
  G0 X[#1] Y[#2]
  G1 Z[#3 + 1] F200
  G1 Z#3
  G91
  #10 = 0
  o110 while [#10 LT 4]
    G1 X[#4] F700
    G1 Y[#5]
    G1 X[-#4]
    G1 Y[#5]
    #10 = [#10 + 1]
  o110 endwhile
  G1 X[#4]
  G90
  G0 Z10
o100 endsub
M6 T2
G43 H2
M3 S6000
G0 X19.3 Y32.3 Z10
o120 repeat [1]
  o100 call [19.3] [32.3] [-3] [31.4] [1.925]
o120 endrepeat
o100 call [19.3] [32.3] [-6] [31.4] [1.925]
(finish the pocket walls with the 6 mm cutter, radius compensation on the drawn outline)
M6 T3
G43 H3
M3 S8000
G0 X35 Y40 Z10
G1 Z-6 F150
G41 D3 G1 X35 Y52 F500
G1 X19
G3 X15 Y48 I0 J-4
G1 Y32
G3 X19 Y28 I4 J0
G1 X51
G3 X55 Y32 I0 J4
G1 Y48
G3 X51 Y52 I-4 J0
G1 X35
G40 G1 X35 Y40
G0 Z10
(bolt circle: six holes on R20 about 90/40, spotted then drilled through, one subprogram)
o200 sub
  #10 = 0
  o210 while [#10 LT 6]
    #11 = [90 + 20 * COS[#10 * 60]]
    #12 = [40 + 20 * SIN[#10 * 60]]
    o220 if [#1 EQ 1]
      G98 G82 X#11 Y#12 Z-2 R2 P0.2 F100
    o220 else
      G98 G81 X#11 Y#12 Z-23 R2 F150
    o220 endif
    #10 = [#10 + 1]
  o210 endwhile
  G80
o200 endsub
M6 T4
G43 H4
M3 S2500
G0 Z10
o200 call [1]
M6 T5
G43 H5
M3 S1800
G0 Z10
o200 call [2]
(keyway slot 10 wide along X at Y68, 4 deep: plunged back and forth, incremental)
M6 T6
G43 H6
M3 S5000
G0 X15 Y68 Z10
G1 Z0.5 F200
G1 Z-2
G91 G1 X40 F400
G90 G1 Z-4 F200
G91 G1 X-40 F400
G90 G0 Z10
M5
G0 Z50
M30
%
"""


def shop_program():
    tools = [tool(1, "FaceMill_D63", "face_mill", 63, 2000, 900, 300),
             tool(2, "EndMill_D8", "flat_end_mill", 8, 6000, 700, 200),
             tool(3, "EndMill_D6", "flat_end_mill", 6, 8000, 500, 150),
             tool(4, "SpotDrill_D12", "spot_drill", 12, 2500, 100, 100, tip_angle=90),
             tool(5, "Drill_D8.5", "twist_drill", 8.5, 1800, 150, 150, tip_angle=118),
             tool(6, "EndMill_D10", "flat_end_mill", 10, 5000, 400, 200)]

    class Text:
        def text(self):
            return SHOP_PROGRAM

    holes = [(round(90 + 20 * math.cos(math.radians(60 * k)), 4), round(40 + 20 * math.sin(math.radians(60 * k)), 4))
             for k in range(6)]
    features = [
        feature("F1", "planar_face", (60, 40), 0.5, 0.0, [op("plane_finish_milling", 1, "bidirectional")]),
        feature("F2", "closed_pocket", (35, 40), 0.0, -6.0,
                [op("bottom_and_side_rough_milling", 2, "bidirectional"), op("bottom_and_side_finish_milling", 3, "contour")],
                shape="rounded_rectangle", dimensions={"length": 40, "width": 24, "corner_radius": 4, "angle_deg": 0}),
    ] + [
        feature("F%d" % (3 + k), "round_hole", h, 0.0, -20.0,
                [op("center_drilling", 4, "plunge"), op("drilling", 5, "plunge")],
                dimensions={"diameter": 8.5}, bottom_condition="through")
        for k, h in enumerate(holes)
    ] + [
        feature("F9", "slot", (35, 68), 0.0, -4.0, [op("bottom_and_side_rough_milling", 6, "center_milling")],
                shape="closed_slot_round_ends", end_conditions=["closed_radiused", "closed_radiused"],
                dimensions={"width": 10, "length_overall": 50}),
    ]
    write_part("p14_shop_program", "120x80x20 saw-cut block faced 0.5, zero at the top front left corner, written by "
               "hand as at the machine: a zigzag subprogram called per depth (incremental moves, a while loop, a "
               "repeat), the pocket walls finished with cutter radius compensation (G41) on the drawn outline, a "
               "bolt circle of six holes computed in a loop and spotted (G82) then drilled (G81) by one subprogram "
               "called twice, a keyway plunged back and forth in incremental moves",
               Text(), tools, stock((0, 0, -20), (120, 80, 0.5), (0, 0, -20), (120, 80, 0), "part_top_corner"), features)


# ---------------------------------------------------------------- (j) hobby CAM style (Estlcam, Carbide Create)

def chamfered_rectangle(c, half_l, half_w, leg):
    """The eight corners (CCW) of a rectangle whose corners are cut at 45 degrees, legs `leg`."""
    x0, x1, y0, y1 = c[0] - half_l, c[0] + half_l, c[1] - half_w, c[1] + half_w
    return [(x1 - leg, y0), (x1, y0 + leg), (x1, y1 - leg), (x1 - leg, y1), (x0 + leg, y1), (x0, y1 - leg),
            (x0, y0 + leg), (x0 + leg, y0)]


def offset_convex(poly, d):
    """A convex CCW polygon's edges moved by d (inward when d > 0), neighbours intersected: the
    tool centre's path along the inside of the polygon (sharp corners; the tool rounds them)."""
    lines = []
    for k in range(len(poly)):
        (ax, ay), (bx, by) = poly[k], poly[(k + 1) % len(poly)]
        L = math.hypot(bx - ax, by - ay)
        nx, ny = -(by - ay) / L, (bx - ax) / L  # left normal: inside of a CCW polygon
        lines.append(((ax + nx * d, ay + ny * d), (bx - ax, by - ay)))
    out = []
    for k in range(len(lines)):
        (p, r), (q, s) = lines[k - 1], lines[k]
        den = r[0] * s[1] - r[1] * s[0]
        t = ((q[0] - p[0]) * s[1] - (q[1] - p[1]) * s[0]) / den
        out.append((p[0] + t * r[0], p[1] + t * r[1]))
    # an edge that the offset turned round has vanished: its half-plane no longer bounds the ring
    keep = []
    for k in range(len(poly)):
        a, b = out[k], out[(k + 1) % len(out)]
        if (b[0] - a[0]) * lines[k][1][0] + (b[1] - a[1]) * lines[k][1][1] > 1e-9:
            keep.append(poly[k:k + 2] if k + 1 < len(poly) else [poly[k], poly[0]])
    if len(keep) == len(poly):
        return out
    short = [e for e in keep]
    pts = []
    for k in range(len(short)):
        pts.append(short[k][0])
    # the polygon of the remaining edges' lines (the vanished edges' corners extended)
    return offset_convex(extend_edges(short), d)


def extend_edges(edges):
    """The convex polygon bounded by the lines of `edges` (each a pair of points, CCW order)."""
    out = []
    for k in range(len(edges)):
        (a0, a1), (b0, b1) = edges[k - 1], edges[k]
        r = (a1[0] - a0[0], a1[1] - a0[1])
        s_ = (b1[0] - b0[0], b1[1] - b0[1])
        den = r[0] * s_[1] - r[1] * s_[0]
        t = ((b0[0] - a0[0]) * s_[1] - (b0[1] - a0[1]) * s_[0]) / den
        out.append((a0[0] + t * r[0], a0[1] + t * r[1]))
    return out


def outside_path(poly, d):
    """The tool centre's path around the outside of a convex CCW polygon at distance d, as a
    hobby CAM posts it: straight offsets joined by arcs about the corners (clockwise, climb)."""
    n = len(poly)
    segs = []
    for k in range(n):
        (ax, ay), (bx, by) = poly[k], poly[(k + 1) % n]
        L = math.hypot(bx - ax, by - ay)
        nx, ny = (by - ay) / L, -(bx - ax) / L  # right normal: outside of a CCW polygon
        segs.append(((ax + nx * d, ay + ny * d), (bx + nx * d, by + ny * d), poly[(k + 1) % n]))
    # run them backwards (clockwise): each edge reversed, then an arc about the corner before it
    return segs


def hobby_style():
    tools = [tool(1, "EndMill_D6", "flat_end_mill", 6, 18000, 1200, 300),
             tool(2, "EndMill_D3", "flat_end_mill", 3, 20000, 800, 200)]
    p = Program(safe=5, clearance=1)
    p.tool(1, 18000)
    # pocket 40 x 24 with 5 mm 45-degree corner chamfers at (35, 30), 6 deep: offset rings of the
    # octagon from the outside in, a ramp along the first side at each level, 2 mm per level
    c = (35.0, 30.0)
    poly = chamfered_rectangle(c, 20, 12, 5)
    rings = []
    d = 3.0
    while 12 - d > 0.5:
        rings.append(offset_convex(poly, d))
        d += 2.5
    prev = 0.0
    for z in (-2.0, -4.0, -6.0):
        a = rings[0][0]
        b = rings[0][1]
        p.go_to(a[0], a[1], prev)
        p.feed(a[0], a[1], prev, 300)
        p.feed(b[0], b[1], z, 300)   # ramp along the first side
        p.feed(a[0], a[1], z, 1200)  # back at the level
        for ring in rings:
            p.feed(ring[0][0], ring[0][1], z, 1200)
            for q in ring[1:] + [ring[0]]:
                p.feed(q[0], q[1], z, 1200)
        p.retract()
        prev = z
    # holes D3 drilled by the end mill in G1 pecks (no canned cycle): 2 mm each, up 1 mm between
    p.tool(2, 20000)
    holes = [(70, 10), (70, 50), (85, 30)]
    for (hx, hy) in holes:
        p.go_to(hx, hy, 0.0)
        last = 0.0
        for depth in (-2.0, -4.0, -6.0, -8.5):
            if last < 0:
                p.rapid(z=last + 0.5)  # back down to 0.5 above the last peck's depth
            p.feed(hx, hy, depth, 200)
            p.rapid(z=1.0)
            last = depth
        p.retract()
    # outside profile 100 x 60 with 6 mm 45-degree corner chamfers, 8 deep (the plate's bottom)
    # in four levels: the octagon at a tool radius, arcs about its corners, clockwise
    p.tool(1, 18000)
    outline = chamfered_rectangle((50, 30), 50, 30, 6)
    segs = outside_path(outline, 3.0)
    start = segs[-1][1]
    prev = 0.0
    for z in (-2.0, -4.0, -6.0, -8.3):
        p.go_to(start[0], start[1], prev)
        p.feed(start[0], start[1], z, 300)
        for k in range(len(segs) - 1, -1, -1):
            a, b, corner = segs[k]
            p.feed(a[0], a[1], z, 1200)  # along edge k backwards, to its start
            prev_edge = segs[k - 1]
            p.arc(False, prev_edge[1][0], prev_edge[1][1], z, outline[k][0], outline[k][1], 1200)
        p.retract()
        prev = z
    features = [
        feature("F1", "closed_pocket", c, 0.0, -6.0, [op("bottom_and_side_rough_milling", 1, "contour_parallel")],
                shape="rectangle_chamfered_corners", dimensions={"length": 40, "width": 24, "corner_chamfer": 5, "angle_deg": 0}),
    ] + [
        feature("F%d" % (2 + k), "round_hole", h, 0.0, -8.0, [op("multistep_drilling", 2, "plunge")],
                dimensions={"diameter": 3}, bottom_condition="through")
        for k, h in enumerate(holes)
    ] + [
        feature("F5", "general_outside_profile", (50, 30), 0.0, -8.0, [op("side_finish_milling", 1, "contour")],
                outline="rectangle 100 x 60, corners chamfered 6 x 45 degrees",
                dimensions={"length": 100, "width": 60, "corner_chamfer": 6}),
    ]
    write_part("p15_hobby_style", "100x60x8 plate from a 110x70x8 blank, zero at the top front left corner, cut as "
               "hobby CAM (Estlcam, Carbide Create) posts it: two end mills and no canned cycles, a 40x24 pocket "
               "with 5 mm 45-degree corner chamfers cleared by offset rings with a ramp along the first side, "
               "through holes drilled by an end mill in G1 pecks, the outside profile with 6 mm corner chamfers "
               "cut in step-downs with arcs about its corners",
               p, tools, stock((-5, -5, -8), (105, 65, 0), (0, 0, -8), (100, 60, 0), "part_top_corner"), features)


if __name__ == "__main__":
    nested_pockets()
    helix_holes()
    multi_level()
    small_part()
    plate()
    slots()
    variations()
    hsm_style()
    shop_program()
    hobby_style()
