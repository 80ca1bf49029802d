// The STEP plugin (io/step_plugin.h): the one OpenCASCADE translation unit, built as the module
// bpde_step_plugin.so that io/step_export.cpp opens on first use. It links OpenCASCADE only (no
// bezierpde library), and reports through status codes: no exception leaves it.
#include "bezierpde/io/step_plugin.h"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRep_Builder.hxx>
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
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shell.hxx>
#include <cstdio>
#include <exception>
#include <mutex>
#include <string>
#include <vector>

namespace {

// OpenCASCADE reports on stdout by default; bpde's stdout carries JSON only.
void silence_opencascade() {
  static std::once_flag once;
  std::call_once(once, [] { Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream)); });
}

int fail(int status, const std::string& what, char* message, size_t size) {
  if (message && size > 0) std::snprintf(message, size, "%s", what.c_str());
  return status;
}

TColgp_Array2OfPnt poles_of(const bpde_step_surface& s) {
  TColgp_Array2OfPnt poles(1, s.nu, 1, s.nv);
  for (int i = 0; i < s.nu; ++i)
    for (int j = 0; j < s.nv; ++j) {
      const double* x = s.poles + 3 * (static_cast<size_t>(i) * s.nv + j);
      poles.SetValue(i + 1, j + 1, gp_Pnt(x[0], x[1], x[2]));
    }
  return poles;
}

// Distinct knots and multiplicities of a full knot vector.
void split_knots(const double* K, int count, std::vector<double>& knots, std::vector<int>& mults) {
  for (int k = 0; k < count; ++k) {
    if (!knots.empty() && K[k] == knots.back()) {
      ++mults.back();
    } else {
      knots.push_back(K[k]);
      mults.push_back(1);
    }
  }
}

Handle(Geom_Surface) bspline(const bpde_step_surface& s) {
  std::vector<double> ku, kv;
  std::vector<int> mu, mv;
  split_knots(s.knots_u, s.nu + s.p + 1, ku, mu);
  split_knots(s.knots_v, s.nv + s.q + 1, kv, mv);
  TColStd_Array1OfReal UK(1, static_cast<int>(ku.size())), VK(1, static_cast<int>(kv.size()));
  TColStd_Array1OfInteger UM(1, static_cast<int>(mu.size())), VM(1, static_cast<int>(mv.size()));
  for (size_t k = 0; k < ku.size(); ++k)
    UK.SetValue(static_cast<int>(k) + 1, ku[k]), UM.SetValue(static_cast<int>(k) + 1, mu[k]);
  for (size_t k = 0; k < kv.size(); ++k)
    VK.SetValue(static_cast<int>(k) + 1, kv[k]), VM.SetValue(static_cast<int>(k) + 1, mv[k]);
  return new Geom_BSplineSurface(poles_of(s), UK, VK, UM, VM, s.p, s.q);
}

// The face of a surface on its natural parameter range; degenerate edges (the collapsed edge of a
// triangular patch's tensor form) detected at 1e-7.
TopoDS_Face make_face(const bpde_step_surface& s) {
  const Handle(Geom_Surface) surface =
      s.kind == BPDE_STEP_BSPLINE ? bspline(s) : Handle(Geom_Surface)(new Geom_BezierSurface(poles_of(s)));
  double u0, u1, v0, v1;
  surface->Bounds(u0, u1, v0, v1);
  BRepBuilderAPI_MakeFace make(surface, u0, u1, v0, v1, 1e-7);
  if (!make.IsDone()) throw Standard_Failure("could not make a face");
  return make.Face();
}

int write_shape(const TopoDS_Shape& shape, const char* path, char* message, size_t size) {
  STEPControl_Writer writer;
  Interface_Static::SetCVal("write.step.schema", "AP214IS");
  Interface_Static::SetCVal("write.step.product.name", "bezierpde surface");
  if (writer.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone)
    return fail(BPDE_STEP_REFUSED, "OpenCASCADE could not transfer the shape", message, size);
  if (writer.Write(path) != IFSelect_RetDone) return fail(BPDE_STEP_FILE, "cannot write file", message, size);
  return BPDE_STEP_OK;
}

// The shape a STEP file holds (all its roots transferred); false when the file cannot be read.
bool read_shape(const char* path, TopoDS_Shape& shape) {
  STEPControl_Reader reader;
  if (reader.ReadFile(path) != IFSelect_RetDone) return false;
  reader.TransferRoots();
  shape = reader.OneShape();
  return true;
}

// An entry point's body with OpenCASCADE silenced and every exception turned into a status and
// message: nothing may leave the plugin's C interface as an exception.
template <class Body>
int guarded(char* message, size_t size, Body&& body) {
  try {
    silence_opencascade();
    return body();
  } catch (const Standard_Failure& e) {
    return fail(BPDE_STEP_REFUSED, std::string("OpenCASCADE: ") + e.GetMessageString(), message, size);
  } catch (const std::exception& e) {
    return fail(BPDE_STEP_REFUSED, e.what(), message, size);
  }
}

}  // namespace

extern "C" {

__attribute__((visibility("default"))) int bpde_step_plugin_abi(void) { return BPDE_STEP_PLUGIN_ABI; }

__attribute__((visibility("default"))) int bpde_step_plugin_write(const bpde_step_surface* s, const char* path,
                                                                  char* message, size_t size) {
  return guarded(message, size, [&]() -> int {
    TopoDS_Face face;
    try {
      face = make_face(*s);
    } catch (const Standard_Failure& e) {
      return fail(BPDE_STEP_REFUSED, std::string("OpenCASCADE refused the surface: ") + e.GetMessageString(), message,
                  size);
    }
    return write_shape(face, path, message, size);
  });
}

__attribute__((visibility("default"))) int bpde_step_plugin_read(const char* path, const double* uv, long rows,
                                                                 bpde_step_readback* out, double* points,
                                                                 char* message, size_t size) {
  return guarded(message, size, [&]() -> int {
    TopoDS_Shape shape;
    if (!read_shape(path, shape)) return fail(BPDE_STEP_FILE, "cannot read STEP file", message, size);
    *out = bpde_step_readback{};
    out->surface = 2;
    TopoDS_Face first;
    for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) {
      if (out->faces++ == 0) first = TopoDS::Face(ex.Current());
    }
    if (out->faces == 0) return BPDE_STEP_OK;
    const Handle(Geom_Surface) s = BRep_Tool::Surface(first);
    s->Bounds(out->u0, out->u1, out->v0, out->v1);
    const GeomAdaptor_Surface a(s);
    out->surface = a.GetType() == GeomAbs_BezierSurface ? 0 : a.GetType() == GeomAbs_BSplineSurface ? 1 : 2;
    if (out->surface != 2) out->u_degree = a.UDegree(), out->v_degree = a.VDegree();
    for (long k = 0; k < rows; ++k) {
      const gp_Pnt p = s->Value(uv[2 * k], uv[2 * k + 1]);
      points[3 * k] = p.X(), points[3 * k + 1] = p.Y(), points[3 * k + 2] = p.Z();
    }
    return BPDE_STEP_OK;
  });
}

__attribute__((visibility("default"))) int bpde_step_plugin_write_shell(const bpde_step_surface* s, int count,
                                                                        double tolerance, const char* path,
                                                                        char* message, size_t size) {
  return guarded(message, size, [&]() -> int {
    if (count < 1) return fail(BPDE_STEP_REFUSED, "no surfaces to write", message, size);
    TopoDS_Shape shape;
    try {
      BRepBuilderAPI_Sewing sewing(tolerance);
      for (int k = 0; k < count; ++k) sewing.Add(make_face(s[k]));
      sewing.Perform();
      shape = sewing.SewedShape();
      if (shape.IsNull()) return fail(BPDE_STEP_REFUSED, "OpenCASCADE could not sew the faces", message, size);
      if (shape.ShapeType() == TopAbs_FACE) {  // one face: sewing returns it as it is
        BRep_Builder builder;
        TopoDS_Shell shell;
        builder.MakeShell(shell);
        builder.Add(shell, shape);
        shape = shell;
      }
    } catch (const Standard_Failure& e) {
      return fail(BPDE_STEP_REFUSED, std::string("OpenCASCADE refused the surfaces: ") + e.GetMessageString(), message,
                  size);
    }
    return write_shape(shape, path, message, size);
  });
}

__attribute__((visibility("default"))) int bpde_step_plugin_topology(const char* path, bpde_step_topology* out,
                                                                     char* message, size_t size) {
  return guarded(message, size, [&]() -> int {
    TopoDS_Shape shape;
    if (!read_shape(path, shape)) return fail(BPDE_STEP_FILE, "cannot read STEP file", message, size);
    *out = bpde_step_topology{};
    if (shape.IsNull()) return BPDE_STEP_OK;
    out->valid = BRepCheck_Analyzer(shape).IsValid() ? 1 : 0;
    auto count = [&](TopAbs_ShapeEnum type) {
      TopTools_IndexedMapOfShape map;
      TopExp::MapShapes(shape, type, map);
      return map.Extent();
    };
    out->solids = count(TopAbs_SOLID);
    out->shells = count(TopAbs_SHELL);
    out->faces = count(TopAbs_FACE);
    TopTools_IndexedDataMapOfShapeListOfShape edge_faces;
    TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, edge_faces);
    out->edges = edge_faces.Extent();
    for (int k = 1; k <= edge_faces.Extent(); ++k) {
      const TopoDS_Edge& e = TopoDS::Edge(edge_faces.FindKey(k));
      if (BRep_Tool::Degenerated(e)) {
        ++out->degenerate_edges;
        continue;
      }
      // a seam edge of one face is listed twice for it; count distinct faces
      TopTools_IndexedMapOfShape faces;
      for (const TopoDS_Shape& f : edge_faces.FindFromIndex(k)) faces.Add(f);
      if (faces.Extent() == 1) ++out->free_edges;
    }
    return BPDE_STEP_OK;
  });
}

}  // extern "C"
