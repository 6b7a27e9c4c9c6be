// Writes bracket.step: a 120 x 80 x 30 block with a rounded pocket (and a drilled hole in its floor), a step, a
// slot, four through holes and a counterbore (Open CASCADE, AP214). Built by hand when the part changes:
//   g++ -std=c++20 -I/usr/include/opencascade make_bracket.cpp -o make_bracket -lTKSTEP -lTKXSBase -lTKBRep \
//       -lTKTopAlgo -lTKPrim -lTKBO -lTKFillet -lTKGeomBase -lTKG3d -lTKG2d -lTKMath -lTKernel && ./make_bracket bracket.step
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Tool.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Writer.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <cmath>
TopoDS_Shape cyl(double x, double y, double r, double z0, double h) { return BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, y, z0), gp_Dir(0, 0, 1)), r, h).Shape(); }
int main(int, char** argv) {
  TopoDS_Shape part = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 120, 80, 30).Shape();
  TopoDS_Shape pocket = BRepPrimAPI_MakeBox(gp_Pnt(15, 35, 20), 50, 30, 20).Shape();
  BRepFilletAPI_MakeFillet f(pocket);
  for (TopExp_Explorer e(pocket, TopAbs_EDGE); e.More(); e.Next()) {
    const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
    gp_Pnt a = BRep_Tool::Pnt(TopExp::FirstVertex(edge)), b = BRep_Tool::Pnt(TopExp::LastVertex(edge));
    if (std::abs(a.X() - b.X()) < 1e-9 && std::abs(a.Y() - b.Y()) < 1e-9) f.Add(6, edge);
  }
  part = BRepAlgoAPI_Cut(part, f.Shape()).Shape();
  part = BRepAlgoAPI_Cut(part, BRepPrimAPI_MakeBox(gp_Pnt(105, -1, 20), 20, 82, 20).Shape()).Shape();  // step along x+
  part = BRepAlgoAPI_Cut(part, BRepPrimAPI_MakeBox(gp_Pnt(-1, 10, 24), 107, 12, 10).Shape()).Shape();  // slot along x
  for (auto [x, y] : {std::pair{85.0, 35.0}, {85.0, 65.0}, {112.5, 20.0}, {112.5, 60.0}}) part = BRepAlgoAPI_Cut(part, cyl(x, y, 4.25, -5, 50)).Shape();
  part = BRepAlgoAPI_Cut(part, cyl(85, 50, 5.5, -5, 50)).Shape();         // counterbore: 11 through,
  part = BRepAlgoAPI_Cut(part, cyl(85, 50, 9, 23.5, 20)).Shape();         // 18 wide, 6.5 deep
  const double tip = 3 / std::tan(59 * M_PI / 180);
  TopoDS_Shape drill = BRepAlgoAPI_Fuse(cyl(30, 50, 3, 8, 30), BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(30, 50, 8 - tip), gp_Dir(0, 0, 1)), 0, 3, tip).Shape()).Shape();
  part = BRepAlgoAPI_Cut(part, drill).Shape();                            // a 6 mm hole with a drill point in the pocket floor
  Interface_Static::SetCVal("write.step.schema", "AP214IS");
  STEPControl_Writer w;
  w.Transfer(part, STEPControl_AsIs);
  return w.Write(argv[1]) == IFSelect_RetDone ? 0 : 1;
}
