#pragma once
// A B-rep as plain values, made from the Open CASCADE shape once (brep_extract.cpp) so that
// recognition (brep_*.cpp) needs no Open CASCADE header: faces with their surface (plane,
// cylinder, cone, sphere, other), their boundary loops of oriented edges (lines, arcs, other
// curves as points), and which two faces share each edge. Lengths in mm, in the setup frame.
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace ncbridge::part_reader::brep {

struct Vec3 {
  double x = 0, y = 0, z = 0;
  friend Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
};
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline double norm(Vec3 a) { return std::sqrt(dot(a, a)); }
inline Vec3 unit(Vec3 a) {
  const double n = norm(a);
  return n > 0 ? (1 / n) * a : a;
}

enum class SurfaceKind { Plane, Cylinder, Cone, Sphere, Torus, Other };

struct Surface {
  SurfaceKind kind = SurfaceKind::Other;
  Vec3 origin;       // plane: a point on it; cylinder, cone: a point on the axis; sphere: centre
  Vec3 axis{0, 0, 1};  // plane: the face's outward normal; cylinder, cone: the axis direction
  double radius = 0;    // cylinder, sphere; cone: the radius at `origin`
  double semi_angle = 0;  // cone, radians (the radius grows along +axis when positive)
  bool concave = false;   // cylinder, cone, sphere: the material is outside (a hole's wall)
};

enum class CurveKind { Line, Circle, Other };

// An edge as one face's boundary runs along it.
struct OrientedEdge {
  int edge = 0;  // index into Model::edges
  CurveKind kind = CurveKind::Other;
  Vec3 start, end;
  Vec3 centre;        // circle
  Vec3 axis{0, 0, 1};  // circle: its axis, oriented so that the edge runs counter-clockwise about it
  double radius = 0;  // circle
  double sweep = 0;   // circle: radians swept, > 0
  std::vector<Vec3> points;  // along the edge, start and end included (circles and others sampled)
};

struct Loop {
  std::vector<OrientedEdge> edges;
  bool outer = false;
};

struct Face {
  int index = 0;  // 1-based, as the faces are numbered in messages ("faces 3, 12")
  Surface surface;
  std::vector<Loop> loops;  // outer first
  Vec3 box_min, box_max;
  double angle_span = 0;  // cylinders and cones: the angle the face covers about the axis (radians)
  double axis_min = 0, axis_max = 0;  // cylinders and cones: the face's extent along the axis, from `origin`
};

struct Edge {
  std::array<int, 2> faces{-1, -1};  // indices into Model::faces (-1: a free edge)
};

struct Model {
  std::vector<Face> faces;
  std::vector<Edge> edges;
  Vec3 box_min, box_max;
  int solids = 0;
  std::string file_units;  // "mm", "inch", ...
  std::string schema;      // FILE_SCHEMA's first name
};

// The other face of an edge seen from `face`, or -1.
inline int other_face(const Model& m, int edge, int face) {
  const auto& f = m.edges[static_cast<std::size_t>(edge)].faces;
  return f[0] == face ? f[1] : f[0];
}

}  // namespace ncbridge::part_reader::brep
