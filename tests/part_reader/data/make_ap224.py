#!/usr/bin/env python3
"""Writes the AP224 test parts of tests/part_reader/data/ (run from that folder).

paper_block_ap224.stp: the AP224 block of Xu, Anwer, Lavernhe (2014) from its instance
listings: block stock 225 x 100 x 12.5 mm, a round hole of 75 mm through, a slot 25 wide and
12.5 deep (open at the x+ edge, radiused at its other end).

milled_plate_ap224.stp: the other AP224 milling features: a flat face, a closed rectangular
pocket with corner radius, a circular cutout, an open rectangular pocket, a step, a counterbore
(composite hole) and a blind hole with a conical (118 deg) bottom, in inches.

The instances follow the shapes of the RAMP AP224 file (corpus/ap224): each feature's
parameters in a shape_representation_with_parameters through property_definition, its
components (profiles, paths, bottoms, slot ends) related to shape aspects of its
product_definition_shape.
"""


class Writer:
    def __init__(self):
        self.lines = []
        self.n = 0

    def add(self, text):
        self.n += 1
        self.lines.append(f"#{self.n}={text};")
        return f"#{self.n}"


def header(description, name):
    return ("ISO-10303-21;\nHEADER;\n"
            f"FILE_DESCRIPTION(('{description}'),'2;1');\n"
            f"FILE_NAME('{name}','2025-11-30T00:00:00',('ncbridge'),('ncbridge'),'ncbridge tests','ncbridge','');\n"
            "FILE_SCHEMA(('FEATURE_BASED_PROCESS_PLANNING'));\nENDSEC;\nDATA;\n")


class Part:
    def __init__(self, unit):
        w = self.w = Writer()
        if unit == "mm":
            self.length = w.add("(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.))")
        else:
            mm = w.add("(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.))")
            factor = w.add(f"LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(25.4),{mm})")
            dims = w.add("DIMENSIONAL_EXPONENTS(1.,0.,0.,0.,0.,0.,0.)")
            self.length = w.add(f"(CONVERSION_BASED_UNIT('INCH',{factor})LENGTH_UNIT()NAMED_UNIT({dims}))")
        radian = w.add("(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.))")
        one = w.add("DIMENSIONAL_EXPONENTS(0.,0.,0.,0.,0.,0.,0.)")
        factor = w.add(f"PLANE_ANGLE_MEASURE_WITH_UNIT(PLANE_ANGLE_MEASURE(0.0174532925199433),{radian})")
        self.degree = w.add(f"(CONVERSION_BASED_UNIT('DEGREE',{factor})NAMED_UNIT({one})PLANE_ANGLE_UNIT())")
        solid = w.add("(NAMED_UNIT(*)SI_UNIT($,.STERADIAN.)SOLID_ANGLE_UNIT())")
        tolerance = w.add(f"UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(0.0001),{self.length},'closure','maximum model space distance')")
        self.ctx = w.add(f"(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT(({tolerance}))"
                         f"GLOBAL_UNIT_ASSIGNED_CONTEXT(({self.length},{self.degree},{solid}))REPRESENTATION_CONTEXT('ID1','3D'))")
        self.count = w.add(f"CONTEXT_DEPENDENT_UNIT({one},'COUNT')")
        app = w.add("APPLICATION_CONTEXT('Mechanical Process Planning with Features')")
        w.add(f"APPLICATION_PROTOCOL_DEFINITION('international standard','feature_based_process_planning',2001,{app})")
        pc = w.add(f"PRODUCT_CONTEXT('Feature Based Process Planning',{app},'Mechanical')")
        self.app, self.pc = app, pc

    def product(self, pid, name):
        w = self.w
        prod = w.add(f"PRODUCT('{pid}','{name}','',({self.pc}))")
        self.formation = w.add(f"PRODUCT_DEFINITION_FORMATION('1','ORIGINAL',{prod})")
        self.pdc = w.add(f"PRODUCT_DEFINITION_CONTEXT('feature definitions',{self.app},'manufacturing planning')")
        pd = w.add(f"PRODUCT_DEFINITION('{pid}','product design',{self.formation},{self.pdc})")
        self.shape = w.add(f"PRODUCT_DEFINITION_SHAPE('product shape','shape for product',{pd})")

    def placement(self, origin, axis, ref, name="orientation"):
        w = self.w
        p = w.add("CARTESIAN_POINT('',(%s))" % ",".join(repr(float(v)) for v in origin))
        a = w.add("DIRECTION('',(%s))" % ",".join(repr(float(v)) for v in axis))
        r = w.add("DIRECTION('',(%s))" % ",".join(repr(float(v)) for v in ref))
        return w.add(f"AXIS2_PLACEMENT_3D('{name}',{p},{a},{r})"), a

    def length_item(self, name, value):
        return self.w.add(f"(LENGTH_MEASURE_WITH_UNIT()MEASURE_REPRESENTATION_ITEM()MEASURE_WITH_UNIT(LENGTH_MEASURE({float(value)!r}),{self.length})"
                          f"REPRESENTATION_ITEM('{name}'))")

    def angle_item(self, name, value):
        return self.w.add(f"(MEASURE_REPRESENTATION_ITEM()MEASURE_WITH_UNIT(PLANE_ANGLE_MEASURE({float(value)!r}),{self.degree})"
                          f"PLANE_ANGLE_MEASURE_WITH_UNIT()REPRESENTATION_ITEM('{name}'))")

    def parameters(self, of, items, name="PROPERTY_DEFINITION('','',{})"):
        w = self.w
        pd = w.add(name.format(of))
        rep = w.add(f"SHAPE_REPRESENTATION_WITH_PARAMETERS('',({','.join(items)}),{self.ctx})")
        w.add(f"SHAPE_DEFINITION_REPRESENTATION({pd},{rep})")
        return pd

    def direction_rep(self, pd, direction, name=""):
        rep = self.w.add(f"DIRECTION_SHAPE_REPRESENTATION('{name}',({direction}),{self.ctx})")
        self.w.add(f"PROPERTY_DEFINITION_REPRESENTATION({pd},{rep})")

    def block_stock(self, origin, length, width, height):
        w = self.w
        o, _ = self.placement(origin, (0, 0, 1), (1, 0, 0))
        items = [o, self.length_item("length", length), self.length_item("width", width), self.length_item("height", height)]
        rep = w.add(f"BLOCK_SHAPE_REPRESENTATION('base shape',({','.join(items)}),{self.ctx})")
        material = w.add(f"PRODUCT_DEFINITION('','stock',{self.formation},{self.pdc})")
        pds = w.add(f"PRODUCT_DEFINITION_SHAPE('base shape','base shape for part',{material})")
        w.add(f"SHAPE_DEFINITION_REPRESENTATION({pds},{rep})")

    def feature(self, entity, description):
        w = self.w
        records = sorted(["CHARACTERIZED_OBJECT('','%s')" % description, "FEATURE_DEFINITION()", "INSTANCED_FEATURE()",
                          "MACHINING_FEATURE()", f"SHAPE_ASPECT('','{description}',{self.shape},.T.)", f"{entity}()"])
        f = w.add("(" + "".join(records) + ")")
        pds = w.add(f"PRODUCT_DEFINITION_SHAPE('','',{f})")
        return f, pds

    def component(self, entity, name, description):
        w = self.w
        fcd = w.add("FEATURE_COMPONENT_DEFINITION('','')")
        pds = w.add(f"PRODUCT_DEFINITION_SHAPE('','',{fcd})")
        return w.add(f"{entity}('{name}','{description}',{pds},.F.)")

    def use(self, feature_pds, component, aspect, rel_name, rel_description, relationship="SHAPE_DEFINING_RELATIONSHIP"):
        sa = self.w.add(f"SHAPE_ASPECT('','{aspect}',{feature_pds},.T.)")
        self.w.add(f"{relationship}('{rel_name}','{rel_description}',{component},{sa})")

    def linear_path(self, feature_pds, placement, distance, direction, aspect, rel_name):
        path = self.component("PATH_FEATURE_COMPONENT", "linear path", "linear")
        pd = self.parameters(path, [placement, self.length_item("distance", distance)])
        self.direction_rep(pd, direction)
        self.use(feature_pds, path, aspect, rel_name, "path feature component usage")

    def round_hole(self, description, top, diameter, depth, bottom, tip_angle=None):
        f, pds = self.feature("ROUND_HOLE", description)
        o, into = self.placement(top, (0, 0, -1), (1, 0, 0))
        self.parameters(f, [o])
        profile = self.component("CIRCULAR_CLOSED_PROFILE", "circular profile", "")
        self.parameters(profile, [o, self.length_item("diameter", diameter)])
        self.use(pds, profile, "diameter occurrence", "diameter", "profile usage")
        self.linear_path(pds, o, depth, into, "hole depth occurrence", "hole depth")
        hb = self.component("HOLE_BOTTOM", "bottom condition", bottom)
        if tip_angle is not None:
            self.parameters(hb, [self.angle_item("tip angle", tip_angle)])
        self.use(pds, hb, "bottom condition occurrence", "", "hole bottom usage", "FEATURE_COMPONENT_RELATIONSHIP")
        return f

    def write(self, path, description):
        with open(path, "w") as out:
            out.write(header(description, path))
            out.write("\n".join(self.w.lines))
            out.write("\nENDSEC;\nEND-ISO-10303-21;\n")


def paper_block():
    p = Part("mm")
    p.product("PAPER_BLOCK", "block with a through hole and a slot")
    p.block_stock((0, 0, 0), 225, 100, 12.5)
    p.round_hole("through hole", (62.5, 50, 12.5), 75, 12.5, "through")
    # The slot: from the open x+ edge towards -x, 75 from its open end to the centre of its
    # radiused end; its U profile sits on the floor at the open end.
    f, pds = p.feature("SLOT", "slot")
    o, _ = p.placement((225, 50, 12.5), (0, 0, -1), (-1, 0, 0))
    p.parameters(f, [o])
    u = p.component("SQUARE_U_PROFILE", "", "sweep")
    uo, along = p.placement((225, 50, 0), (-1, 0, 0), (0, -1, 0))
    p.parameters(u, [uo, p.length_item("width", 25), p.length_item("depth", 12.5), p.angle_item("first angle", 90),
                     p.angle_item("second angle", 90), p.length_item("first radius", 0), p.length_item("second radius", 0)])
    p.use(pds, u, "swept shape occurrence", "swept shape", "profile usage")
    p.linear_path(pds, o, 75, along, "course of travel occurrence", "course of travel")
    for which, end in (("course of travel start", "open"), ("course of travel end", "radiused")):
        e = p.component("SLOT_END", "", end)
        p.use(pds, e, "end condition occurrence", which, "slot end usage", "FEATURE_COMPONENT_RELATIONSHIP")
    p.write("paper_block_ap224.stp", "AP224 block of Xu, Anwer, Lavernhe (2014): a hole of 75 through and a slot 25 wide, 12.5 deep")


def milled_plate():
    # Inches: stock 6 x 4 x 1.25; the finished top at 1.2 (a 0.05 flat face).
    p = Part("inch")
    p.product("MILLED_PLATE", "plate with pockets, a step and holes")
    p.block_stock((0, 0, 0), 6, 4, 1.25)
    # Flat face: the whole top, 0.05 deep, passes along x.
    f, pds = p.feature("FLAT_FACE", "top face")
    o, _ = p.placement((0, 0, 1.2), (0, 0, 1), (1, 0, 0))
    p.parameters(f, [o, p.length_item("removal depth", 0.05)])
    removal = p.w.add("DIRECTION('removal direction',(0.,0.,1.))")
    pd = p.w.add(f"PROPERTY_DEFINITION('','removal direction',{f})")
    p.direction_rep(pd, removal, "removal direction")
    along = p.w.add("DIRECTION('',(1.,0.,0.))")
    p.linear_path(pds, o, 6, along, "course of travel occurrence", "course of travel")
    lp = p.component("LINEAR_PROFILE", "", "removal boundary")
    lo, _ = p.placement((0, 0, 1.2), (0, 0, 1), (0, 1, 0))
    p.parameters(lp, [lo, p.length_item("profile length", 4)])
    p.use(pds, lp, "removal boundary occurrence", "removal boundary", "profile usage")
    # Closed rectangular pocket 2 x 1.2, corner radius 0.25, 0.5 deep, at (1.5, 2).
    f, pds = p.feature("POCKET", "closed rectangular")
    o, into = p.placement((1.5, 2, 1.2), (0, 0, -1), (1, 0, 0))
    p.parameters(f, [o, p.length_item("fillet radius", 0)])
    rp = p.component("RECTANGULAR_CLOSED_PROFILE", "", "closed boundary")
    ro, _ = p.placement((1.5, 2, 1.2), (0, 0, 1), (0, 1, 0))
    p.parameters(rp, [ro, p.length_item("length", 2), p.length_item("width", 1.2), p.length_item("corner radius", 0.25)])
    p.use(pds, rp, "closed boundary occurrence", "", "profile usage")
    p.linear_path(pds, o, 0.5, into, "pocket depth occurrence", "pocket depth")
    pb = p.component("POCKET_BOTTOM", "", "planar")
    p.use(pds, pb, "bottom condition occurrence", "", "pocket bottom usage", "FEATURE_COMPONENT_RELATIONSHIP")
    # Circular cutout: diameter 1, through, at (4.25, 3).
    f, pds = p.feature("POCKET", "circular cutout")
    o, into = p.placement((4.25, 3, 1.2), (0, 0, -1), (1, 0, 0))
    p.parameters(f, [o])
    cp = p.component("CIRCULAR_CLOSED_PROFILE", "", "enclosed boundary")
    p.parameters(cp, [o, p.length_item("diameter", 1)])
    p.use(pds, cp, "enclosed boundary occurrence", "", "profile usage")
    p.linear_path(pds, o, 1.2, into, "pocket depth occurrence", "pocket depth")
    pb = p.component("POCKET_BOTTOM", "", "through")
    p.use(pds, pb, "bottom condition occurrence", "", "pocket bottom usage", "FEATURE_COMPONENT_RELATIONSHIP")
    # Open rectangular pocket from the y- edge: 1.5 wide (x 3.5..5), reaching 1 into the part, 0.3 deep.
    f, pds = p.feature("POCKET", "open rectangular")
    o, into = p.placement((4.25, 0.5, 1.2), (0, 0, -1), (1, 0, 0))
    p.parameters(f, [o])
    up = p.component("SQUARE_U_PROFILE", "", "open boundary")
    uo, _ = p.placement((4.25, 1, 1.2), (0, 0, -1), (1, 0, 0))  # closed side at y = 1, opening towards y-
    p.parameters(up, [uo, p.length_item("width", 1.5), p.length_item("depth", 1), p.angle_item("first angle", 90),
                      p.angle_item("second angle", 90), p.length_item("first radius", 0.125), p.length_item("second radius", 0.125)])
    p.use(pds, up, "open boundary occurrence", "", "profile usage")
    p.linear_path(pds, o, 0.3, into, "pocket depth occurrence", "pocket depth")
    pb = p.component("POCKET_BOTTOM", "", "planar")
    p.use(pds, pb, "bottom condition occurrence", "", "pocket bottom usage", "FEATURE_COMPONENT_RELATIONSHIP")
    # Step along the x- edge: floor 0.75 wide (x 0..0.75), 0.45 below the finished top, along y.
    f, pds = p.feature("STEP", "step")
    o, _ = p.placement((0.75, 0, 0.75), (0, 1, 0), (-1, 0, 0))
    p.parameters(f, [o])
    along = p.w.add("DIRECTION('',(0.,1.,0.))")
    p.linear_path(pds, o, 4, along, "course of travel occurrence", "course of travel")
    vp = p.component("VEE_PROFILE", "", "removal boundary")
    p.parameters(vp, [o, p.angle_item("profile angle", 90), p.angle_item("tilt angle", 0), p.length_item("profile radius", 0),
                      p.length_item("first length", 0.75), p.length_item("second length", 0.45)])
    p.use(pds, vp, "removal boundary occurrence", "", "profile usage")
    # Counterbore: 0.5 x 0.25 deep over a 0.3125 through hole, at (2.5, 0.75).
    large = p.round_hole("", (2.5, 0.75, 1.2), 0.5, 0.25, "flat")
    small = p.round_hole("", (2.5, 0.75, 1.2), 0.3125, 1.2, "through")
    c = p.w.add(f"COMPOSITE_HOLE(*,*,'','counterbore',{p.shape},.T.)")
    p.w.add(f"FEATURE_COMPONENT_RELATIONSHIP('large hole','',{c},{large})")
    p.w.add(f"FEATURE_COMPONENT_RELATIONSHIP('small hole','',{c},{small})")
    # Blind hole 0.25, 0.6 deep, 118 deg conical bottom, at (5.25, 1.75).
    p.round_hole("", (5.25, 1.75, 1.2), 0.25, 0.6, "conical", 118)
    p.write("milled_plate_ap224.stp", "AP224 milled plate: flat face, pockets, step, counterbore, conical-bottom hole (inches)")


if __name__ == "__main__":
    paper_block()
    milled_plate()
