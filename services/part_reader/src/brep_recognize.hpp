#pragma once
// Feature recognition on a plain B-rep (brep_model.hpp), for a setup with z up: round holes and
// their compounds from concave cylinders however many faces they are split into (brep_holes.cpp),
// pockets, slots, steps and open pockets from the floors and the walls that rise from them
// (brep_floors.cpp), the part's outline from the faces it stands on (brep_footprint.cpp).
#include <string>
#include <vector>

#include "brep_model.hpp"
#include "ncbridge/part_reader/part.hpp"

namespace ncbridge::part_reader::brep {

constexpr double kTol = 1e-3;  // mm: heights and distances that are the same

struct Recognized {
  std::vector<Feature> features;
  std::vector<Compound> compounds;
  std::vector<Warning> warnings;
  std::vector<char> used;  // per face: part of a recognised feature
  double top_z = 0, bottom_z = 0;
  std::vector<OutlineVertex> footprint;
};

void recognize_holes(const Model& model, Recognized& out);
void recognize_floors(const Model& model, Recognized& out);
void recognize_footprint(const Model& model, Recognized& out);
// Faces no feature explains and that face another way than +z (undercuts, inclined faces).
void report_other_faces(const Model& model, Recognized& out);

// ---- loops (brep_loops.cpp)

// An oriented edge of a face's boundary, with the face it belongs to.
struct BoundaryEdge {
  const OrientedEdge* edge = nullptr;
  int face = -1;
};
using Chain = std::vector<BoundaryEdge>;

// The boundary of a set of faces (edges not shared by two faces of the set) chained into loops.
std::vector<Chain> boundary_loops(const Model& model, const std::vector<int>& faces);
// Twice the area a loop encloses seen from +z (counter-clockwise positive).
double area_about_z(const Chain& chain);
// The loop as outline corners in the setup XY plane (arcs about z as bulges, other curves as
// chords), in the loop's own direction.
std::vector<OutlineVertex> outline_of(const Chain& chain);
// "faces 3, 12, 40" (1-based, as the model numbers them).
std::string faces_text(const Model& model, std::vector<int> faces);
// A length for a message: "19.76", "0" (mm, 6 significant digits).
std::string length_text(double mm);

}  // namespace ncbridge::part_reader::brep
