#include "brep_extract.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepGProp_Face.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <STEPControl_Reader.hxx>
#include <TColStd_SequenceOfAsciiString.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Circ.hxx>
#include <gp_Cone.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Pln.hxx>
#include <gp_Sphere.hxx>
#include <gp_Trsf.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iterator>

#include "ncbridge/common/error.hpp"

namespace ncbridge::part_reader::brep {

namespace {

Vec3 vec(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
Vec3 vec(const gp_Dir& d) { return {d.X(), d.Y(), d.Z()}; }
Vec3 vec(const gp_Vec& d) { return {d.X(), d.Y(), d.Z()}; }

std::string unit_name(const std::string& step_name) {
  std::string n;
  for (char c : step_name) n += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (n == "MM" || n == "MILLIMETRE" || n == "MILLIMETER") return "mm";
  if (n == "INCH" || n == "IN") return "inch";
  if (n == "M" || n == "METRE" || n == "METER") return "m";
  if (n == "CM" || n == "CENTIMETRE") return "cm";
  if (n == "FT" || n == "FOOT") return "foot";
  return step_name;
}

// Open CASCADE names no unit for some AP242 files (it still converts them): the length unit's
// own words in the file.
std::string units_from_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (text.find("CONVERSION_BASED_UNIT('INCH'") != std::string::npos) return "inch";
  if (text.find("SI_UNIT(.MILLI.,.METRE.)") != std::string::npos) return "mm";
  if (text.find("SI_UNIT($,.METRE.)") != std::string::npos) return "m";
  return "mm";
}

STEPControl_Reader open(const std::filesystem::path& path) {
  STEPControl_Reader reader;
  if (reader.ReadFile(path.string().c_str()) != IFSelect_RetDone) {
    throw InputError({path.string(), 0, 0}, "not a STEP file Open CASCADE can read");
  }
  return reader;
}

OrientedEdge oriented_edge(const TopoDS_Edge& e, bool reversed, int index) {
  OrientedEdge o;
  o.edge = index;
  BRepAdaptor_Curve c(e);
  double first = c.FirstParameter(), last = c.LastParameter();
  int samples = 1;
  switch (c.GetType()) {
    case GeomAbs_Line: o.kind = CurveKind::Line; break;
    case GeomAbs_Circle: {
      o.kind = CurveKind::Circle;
      const gp_Circ circ = c.Circle();
      o.centre = vec(circ.Location());
      o.axis = vec(circ.Axis().Direction());
      o.radius = circ.Radius();
      o.sweep = std::abs(last - first);
      if (reversed) o.axis = -1.0 * o.axis;
      samples = std::max(2, static_cast<int>(std::ceil(o.sweep / (M_PI / 36))));
      break;
    }
    default: o.kind = CurveKind::Other; samples = 64; break;
  }
  for (int k = 0; k <= samples; ++k) {
    const double t = reversed ? last + (first - last) * k / samples : first + (last - first) * k / samples;
    o.points.push_back(vec(c.Value(t)));
  }
  o.start = o.points.front();
  o.end = o.points.back();
  return o;
}

void reverse(Loop& loop) {
  std::reverse(loop.edges.begin(), loop.edges.end());
  for (auto& e : loop.edges) {
    std::swap(e.start, e.end);
    std::reverse(e.points.begin(), e.points.end());
    e.axis = -1.0 * e.axis;
  }
}

// Twice the signed area of a loop seen along `normal`.
double signed_area(const Loop& loop, Vec3 normal) {
  double a = 0;
  Vec3 first{};
  bool have = false;
  for (const auto& e : loop.edges) {
    for (std::size_t i = 0; i + 1 < e.points.size(); ++i) {
      if (!have) first = e.points[i], have = true;
      a += dot(cross(e.points[i] - first, e.points[i + 1] - first), normal);
    }
  }
  return a;
}

Surface surface_of(const TopoDS_Face& face, const BRepAdaptor_Surface& s) {
  Surface out;
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  BRepGProp_Face props(face);
  gp_Pnt p;
  gp_Vec n;
  props.Normal((u0 + u1) / 2, (v0 + v1) / 2, p, n);
  const Vec3 normal = unit(vec(n)), point = vec(p);
  auto concave = [&](Vec3 origin, Vec3 axis) {
    const Vec3 foot = origin + dot(point - origin, axis) * axis;
    return dot(normal, foot - point) > 0;
  };
  switch (s.GetType()) {
    case GeomAbs_Plane: {
      out.kind = SurfaceKind::Plane;
      out.origin = vec(s.Plane().Location());
      out.axis = normal;
      break;
    }
    case GeomAbs_Cylinder: {
      const gp_Cylinder c = s.Cylinder();
      out.kind = SurfaceKind::Cylinder;
      out.origin = vec(c.Axis().Location());
      out.axis = vec(c.Axis().Direction());
      out.radius = c.Radius();
      out.concave = concave(out.origin, out.axis);
      break;
    }
    case GeomAbs_Cone: {
      const gp_Cone c = s.Cone();
      out.kind = SurfaceKind::Cone;
      out.origin = vec(c.Axis().Location());
      out.axis = vec(c.Axis().Direction());
      out.radius = c.RefRadius();
      out.semi_angle = c.SemiAngle();
      out.concave = concave(out.origin, out.axis);
      break;
    }
    case GeomAbs_Sphere: {
      const gp_Sphere sp = s.Sphere();
      out.kind = SurfaceKind::Sphere;
      out.origin = vec(sp.Location());
      out.radius = sp.Radius();
      out.concave = dot(normal, out.origin - point) > 0;
      break;
    }
    case GeomAbs_Torus: out.kind = SurfaceKind::Torus; break;
    default: out.kind = SurfaceKind::Other; break;
  }
  return out;
}

}  // namespace

Model load_step(const std::filesystem::path& path, const SetupFrame& frame, double* occt_ms) {
  const auto start = std::chrono::steady_clock::now();
  STEPControl_Reader reader = open(path);
  Model model;
  {
    TColStd_SequenceOfAsciiString lengths, angles, solid_angles;
    reader.FileUnits(lengths, angles, solid_angles);
    model.file_units = lengths.IsEmpty() ? "" : unit_name(lengths.First().ToCString());
  }
  if (model.file_units.empty()) model.file_units = units_from_text(path);
  reader.TransferRoots();
  TopoDS_Shape shape = reader.OneShape();
  TopTools_IndexedMapOfShape solids;
  if (!shape.IsNull()) TopExp::MapShapes(shape, TopAbs_SOLID, solids);
  model.solids = solids.Extent();
  if (model.solids == 0) throw InputError({path.string(), 0, 0}, "the file holds no solid (a part needs a closed B-rep solid)");
  if (model.solids > 1) {
    throw InputError({path.string(), 0, 0}, "the file holds " + std::to_string(model.solids) + " solids (an assembly?): ncbridge plans one part at a time");
  }
  const auto& r = frame.rotation();
  const auto& t = frame.offset();
  gp_Trsf trsf;
  trsf.SetValues(r[0], r[1], r[2], t[0], r[3], r[4], r[5], t[1], r[6], r[7], r[8], t[2]);
  const TopoDS_Shape solid = BRepBuilderAPI_Transform(solids(1), trsf, true).Shape();
  if (occt_ms) *occt_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();

  TopTools_IndexedMapOfShape faces, edges;
  TopExp::MapShapes(solid, TopAbs_FACE, faces);
  TopExp::MapShapes(solid, TopAbs_EDGE, edges);
  TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
  TopExp::MapShapesAndAncestors(solid, TopAbs_EDGE, TopAbs_FACE, edge_faces);
  model.edges.resize(static_cast<std::size_t>(edges.Extent()));
  for (int i = 1; i <= edges.Extent(); ++i) {
    const int k = edge_faces.FindIndex(edges(i));
    if (k == 0) continue;
    int slot = 0;
    for (const auto& f : edge_faces(k)) {
      if (slot > 1) break;
      model.edges[static_cast<std::size_t>(i - 1)].faces[static_cast<std::size_t>(slot++)] = faces.FindIndex(f) - 1;
    }
    if (slot == 1) model.edges[static_cast<std::size_t>(i - 1)].faces[1] = model.edges[static_cast<std::size_t>(i - 1)].faces[0];
  }

  bool first_point = true;
  for (int i = 1; i <= faces.Extent(); ++i) {
    const TopoDS_Face face = TopoDS::Face(faces(i));
    Face f;
    f.index = i;
    BRepAdaptor_Surface adaptor(face, true);
    f.surface = surface_of(face, adaptor);
    const TopoDS_Wire outer = BRepTools::OuterWire(face);
    for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) {
      const TopoDS_Wire wire = TopoDS::Wire(w.Current());
      Loop loop;
      loop.outer = wire.IsSame(outer);
      for (BRepTools_WireExplorer we(wire, face); we.More(); we.Next()) {
        const TopoDS_Edge& e = we.Current();
        if (BRep_Tool::Degenerated(e)) continue;
        loop.edges.push_back(oriented_edge(e, we.Orientation() == TopAbs_REVERSED, edges.FindIndex(e) - 1));
      }
      if (loop.edges.empty()) continue;
      if (f.surface.kind == SurfaceKind::Plane) {  // outer loops counter-clockwise about the normal, inner clockwise
        const double a = signed_area(loop, f.surface.axis);
        if ((a < 0) == loop.outer) reverse(loop);
      }
      if (loop.outer) f.loops.insert(f.loops.begin(), std::move(loop));
      else f.loops.push_back(std::move(loop));
    }
    bool first = true, first_axial = true;
    const bool axial = f.surface.kind == SurfaceKind::Cylinder || f.surface.kind == SurfaceKind::Cone;
    for (const auto& loop : f.loops) {
      for (const auto& e : loop.edges) {
        for (const auto& p : e.points) {
          if (first) f.box_min = f.box_max = p, first = false;
          f.box_min = {std::min(f.box_min.x, p.x), std::min(f.box_min.y, p.y), std::min(f.box_min.z, p.z)};
          f.box_max = {std::max(f.box_max.x, p.x), std::max(f.box_max.y, p.y), std::max(f.box_max.z, p.z)};
          if (first_point) model.box_min = model.box_max = p, first_point = false;
          model.box_min = {std::min(model.box_min.x, p.x), std::min(model.box_min.y, p.y), std::min(model.box_min.z, p.z)};
          model.box_max = {std::max(model.box_max.x, p.x), std::max(model.box_max.y, p.y), std::max(model.box_max.z, p.z)};
          if (!axial) continue;
          const double along = dot(p - f.surface.origin, f.surface.axis);
          if (first_axial) f.axis_min = f.axis_max = along, first_axial = false;
          f.axis_min = std::min(f.axis_min, along);
          f.axis_max = std::max(f.axis_max, along);
        }
      }
    }
    if (f.surface.kind == SurfaceKind::Cylinder || f.surface.kind == SurfaceKind::Cone) {
      double u0, u1, v0, v1;
      BRepTools::UVBounds(face, u0, u1, v0, v1);
      f.angle_span = u1 - u0;
    }
    model.faces.push_back(std::move(f));
  }
  return model;
}

Box step_box(const std::filesystem::path& path) {
  STEPControl_Reader reader = open(path);
  reader.TransferRoots();
  const TopoDS_Shape shape = reader.OneShape();
  TopTools_IndexedMapOfShape solids;
  if (!shape.IsNull()) TopExp::MapShapes(shape, TopAbs_SOLID, solids);
  if (solids.Extent() == 0) throw InputError({path.string(), 0, 0}, "the stock file holds no solid");
  Bnd_Box box;
  BRepBndLib::AddOptimal(shape, box, false, false);
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  return Box{{x0, y0, z0}, {x1, y1, z1}};
}

}  // namespace ncbridge::part_reader::brep
