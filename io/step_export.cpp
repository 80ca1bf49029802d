// The one OpenCASCADE translation unit (io/step_export.h).
#include "bezierpde/io/step_export.h"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRep_Tool.hxx>
#include <GeomAbs_SurfaceType.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierSurface.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <string>
#include <vector>

#include "bezierpde/core/errors.h"
#include "bezierpde/io/atomic_file.h"
#include "bezierpde/triangular/tensor_form.h"

namespace bpde {
namespace {

// OpenCASCADE reports on stdout by default; bpde's stdout carries JSON only.
void silence_opencascade() {
  static std::once_flag once;
  std::call_once(once, [] { Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream)); });
}

gp_Pnt pnt(const Eigen::MatrixX3d& P, int row) { return gp_Pnt(P(row, 0), P(row, 1), P(row, 2)); }

Handle(Geom_Surface) bezier(const TensorNet& t) {
  TColgp_Array2OfPnt poles(1, t.n() + 1, 1, t.m() + 1);
  for (int i = 0; i <= t.n(); ++i)
    for (int j = 0; j <= t.m(); ++j) poles.SetValue(i + 1, j + 1, pnt(t.points(), t.index(i, j)));
  return new Geom_BezierSurface(poles);
}

// Distinct knots and multiplicities of a full knot vector.
void split_knots(const std::vector<double>& K, std::vector<double>& knots, std::vector<int>& mults) {
  for (double k : K) {
    if (!knots.empty() && k == knots.back()) {
      ++mults.back();
    } else {
      knots.push_back(k);
      mults.push_back(1);
    }
  }
}

// The shortest decimal that reads back as x.
std::string shortest(double x) {
  char buf[32];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    if (std::strtod(buf, nullptr) == x) break;
  }
  return buf;
}

// OpenCASCADE takes interior knots of multiplicity <= degree; a bspline net may hold an interior
// knot of multiplicity degree + 1 (FORMATS.md "bspline"), where the surface may jump. With
// K[k] = ... = K[k+deg] = t interior, the row of poles k-1 is the surface at t- and row k the
// surface at t+. Where the two rows are equal (bit for bit) the surface is continuous there and
// dropping one copy of t and row k is exact (the same surface); otherwise UnsupportedProblem
// (exit 2): one face cannot hold the jump. rows[i][j]: the poles with index i in this direction.
void lower_full_multiplicity(std::vector<double>& K, std::vector<std::vector<gp_Pnt>>& rows, int deg,
                             const char* direction) {
  const auto same = [](const gp_Pnt& a, const gp_Pnt& b) { return a.X() == b.X() && a.Y() == b.Y() && a.Z() == b.Z(); };
  for (size_t k = 1; k + static_cast<size_t>(deg) + 1 < K.size(); ++k) {
    if (K[k] == K[k - 1] || K[k + static_cast<size_t>(deg)] != K[k]) continue;  // not the start of a run of deg + 1
    bool continuous = true;
    for (size_t j = 0; j < rows[k].size(); ++j) continuous = continuous && same(rows[k - 1][j], rows[k][j]);
    if (!continuous)
      throw UnsupportedProblem(std::string("STEP export: the bspline surface is discontinuous at the ") + direction +
                               " knot " + shortest(K[k]) +
                               " (multiplicity degree + 1 and different control points on either side); a STEP "
                               "face holds a continuous surface");
    K.erase(K.begin() + static_cast<std::ptrdiff_t>(k));
    rows.erase(rows.begin() + static_cast<std::ptrdiff_t>(k));
  }
}

Handle(Geom_Surface) bspline(const BSplineNet& b) {
  std::vector<std::vector<gp_Pnt>> rows(b.nu(), std::vector<gp_Pnt>(b.nv()));  // [i][j]
  for (int i = 0; i < b.nu(); ++i)
    for (int j = 0; j < b.nv(); ++j) rows[i][j] = pnt(b.points(), b.index(i, j));
  std::vector<double> U = b.knots_u(), V = b.knots_v();
  lower_full_multiplicity(U, rows, b.p(), "u");
  std::vector<std::vector<gp_Pnt>> cols(rows.empty() ? 0 : rows[0].size(), std::vector<gp_Pnt>(rows.size()));
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t j = 0; j < rows[i].size(); ++j) cols[j][i] = rows[i][j];
  lower_full_multiplicity(V, cols, b.q(), "v");
  const int nu = static_cast<int>(rows.size()), nv = static_cast<int>(cols.size());
  TColgp_Array2OfPnt poles(1, nu, 1, nv);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) poles.SetValue(i + 1, j + 1, cols[j][i]);
  std::vector<double> ku, kv;
  std::vector<int> mu, mv;
  split_knots(U, ku, mu);
  split_knots(V, kv, mv);
  TColStd_Array1OfReal UK(1, static_cast<int>(ku.size())), VK(1, static_cast<int>(kv.size()));
  TColStd_Array1OfInteger UM(1, static_cast<int>(mu.size())), VM(1, static_cast<int>(mv.size()));
  for (size_t k = 0; k < ku.size(); ++k)
    UK.SetValue(static_cast<int>(k) + 1, ku[k]), UM.SetValue(static_cast<int>(k) + 1, mu[k]);
  for (size_t k = 0; k < kv.size(); ++k)
    VK.SetValue(static_cast<int>(k) + 1, kv[k]), VM.SetValue(static_cast<int>(k) + 1, mv[k]);
  return new Geom_BSplineSurface(poles, UK, VK, UM, VM, b.p(), b.q());
}

Handle(Geom_Surface) surface_of(const Net& net) {
  if (const auto* t = std::get_if<TensorNet>(&net)) return bezier(*t);
  if (const auto* b = std::get_if<BSplineNet>(&net)) return bspline(*b);
  const auto& tri = std::get<TriangularNet>(net);
  return bezier(tensor_form(tri));
}

}  // namespace

void write_step(const std::string& path, const Net& net) {
  check_step_degree(net, "write_step");
  silence_opencascade();
  TopoDS_Face face;
  try {
    const Handle(Geom_Surface) s = surface_of(net);
    double u0, u1, v0, v1;
    s->Bounds(u0, u1, v0, v1);
    BRepBuilderAPI_MakeFace make(s, u0, u1, v0, v1, 1e-7);
    if (!make.IsDone())
      throw InternalError("STEP export: OpenCASCADE could not make a face of the " + net_kind(net) + " net");
    face = make.Face();
  } catch (const Standard_Failure& e) {
    throw InternalError(std::string("STEP export: OpenCASCADE refused the surface: ") + e.GetMessageString());
  }
  STEPControl_Writer writer;
  Interface_Static::SetCVal("write.step.schema", "AP214IS");
  Interface_Static::SetCVal("write.step.product.name", "bezierpde surface");
  if (writer.Transfer(face, STEPControl_AsIs) != IFSelect_RetDone)
    throw InternalError("STEP export: OpenCASCADE could not transfer the face");
  // Into a temporary beside the target, renamed onto it only when complete: a failed write (a
  // full disk, a file-size limit) leaves an existing target as it was.
  replace_file_atomically(path, [&](const std::string& tmp) {
    if (writer.Write(tmp.c_str()) != IFSelect_RetDone) throw FileError("cannot write file '" + path + "'");
  });
}

StepReadBack read_step(const std::string& path, const Eigen::MatrixX2d& uv) {
  silence_opencascade();
  STEPControl_Reader reader;
  if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) throw FileError("cannot read STEP file '" + path + "'");
  reader.TransferRoots();
  const TopoDS_Shape shape = reader.OneShape();
  StepReadBack out;
  out.points.resize(uv.rows(), 3);
  TopoDS_Face first;
  for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) {
    if (out.faces++ == 0) first = TopoDS::Face(ex.Current());
  }
  if (out.faces == 0) return out;
  const Handle(Geom_Surface) s = BRep_Tool::Surface(first);
  s->Bounds(out.u0, out.u1, out.v0, out.v1);
  const GeomAdaptor_Surface a(s);
  out.surface = a.GetType() == GeomAbs_BezierSurface    ? "bezier"
                : a.GetType() == GeomAbs_BSplineSurface ? "bspline"
                                                        : "other";
  if (out.surface != "other") out.u_degree = a.UDegree(), out.v_degree = a.VDegree();
  for (Eigen::Index k = 0; k < uv.rows(); ++k) {
    const gp_Pnt p = s->Value(uv(k, 0), uv(k, 1));
    out.points.row(k) << p.X(), p.Y(), p.Z();
  }
  return out;
}

}  // namespace bpde
