// The nets. `points` is a writable N x 3 view of the net's storage (no copy).
#include "bindings.h"

namespace bpde::python {

namespace {

// The `points` setter: the net's row count (SizeError) and finite values (NonFiniteError), as the
// constructors check them; the net is unchanged when either check fails.
template <class NetT>
void set_points(NetT& net, py::handle points) {
  Eigen::MatrixX3d P = points_arg<3>(points, "points", net.points().rows());
  require_finite(P, "points");
  net.points() = std::move(P);
}

}  // namespace

void bind_nets(py::module_& m) {
  py::class_<bpde::TensorNet>(m, "TensorNet", "Tensor Bézier net of degree (n, m); points row i*(m+1)+j, N x 3.")
      .def(py::init<int, int>(), py::arg("n"), py::arg("m"))
      .def(py::init(
               [](int n, int m, py::handle points) { return bpde::TensorNet(n, m, points_arg<3>(points, "points")); }),
           py::arg("n"), py::arg("m"), py::arg("points"))
      .def_property_readonly("n", &bpde::TensorNet::n)
      .def_property_readonly("m", &bpde::TensorNet::m)
      .def_property(
          "points", [](bpde::TensorNet& n) -> Eigen::MatrixX3d& { return n.points(); },
          [](bpde::TensorNet& n, py::handle P) { set_points(n, P); }, py::return_value_policy::reference_internal)
      .def("evaluate", &bpde::TensorNet::evaluate, py::arg("u"), py::arg("v"))
      .def("to_dict", [](const bpde::TensorNet& n) { return from_json(bpde::net_to_json(n)); })
      .def("__repr__", [](const bpde::TensorNet& n) {
        return "TensorNet(n=" + std::to_string(n.n()) + ", m=" + std::to_string(n.m()) + ")";
      });
  py::class_<bpde::TriangularNet>(m, "TriangularNet",
                                  "Triangular Bézier net of degree n; points P_{n00} first, P_{00n} last, N x 3.")
      .def(py::init<int>(), py::arg("n"))
      .def(py::init([](int n, py::handle points) { return bpde::TriangularNet(n, points_arg<3>(points, "points")); }),
           py::arg("n"), py::arg("points"))
      .def_property_readonly("n", &bpde::TriangularNet::n)
      .def_property(
          "points", [](bpde::TriangularNet& n) -> Eigen::MatrixX3d& { return n.points(); },
          [](bpde::TriangularNet& n, py::handle P) { set_points(n, P); }, py::return_value_policy::reference_internal)
      .def("evaluate", &bpde::TriangularNet::evaluate, py::arg("u"), py::arg("v"))
      .def("to_dict", [](const bpde::TriangularNet& n) { return from_json(bpde::net_to_json(n)); })
      .def("__repr__", [](const bpde::TriangularNet& n) { return "TriangularNet(n=" + std::to_string(n.n()) + ")"; });
  py::class_<bpde::BSplineNet>(m, "BSplineNet",
                               "Tensor B-spline net of degree (p, q) over the knots (U, V) (FORMATS.md \"bspline\"); "
                               "points row i*nv + j, (nu*nv) x 3.")
      .def(py::init([](int p, int q, std::vector<double> U, std::vector<double> V, py::handle points) {
             // The point count is checked by the constructor, after the knots.
             return bpde::BSplineNet(p, q, std::move(U), std::move(V), points_arg<3>(points, "points"));
           }),
           py::arg("p"), py::arg("q"), py::arg("U"), py::arg("V"), py::arg("points"))
      .def_property_readonly("p", &bpde::BSplineNet::p)
      .def_property_readonly("q", &bpde::BSplineNet::q)
      .def_property_readonly("nu", &bpde::BSplineNet::nu)
      .def_property_readonly("nv", &bpde::BSplineNet::nv)
      .def_property_readonly("knots_u", &bpde::BSplineNet::knots_u)
      .def_property_readonly("knots_v", &bpde::BSplineNet::knots_v)
      .def_property(
          "points", [](bpde::BSplineNet& n) -> Eigen::MatrixX3d& { return n.points(); },
          [](bpde::BSplineNet& n, py::handle P) { set_points(n, P); }, py::return_value_policy::reference_internal)
      .def("evaluate", &bpde::BSplineNet::evaluate, py::arg("u"), py::arg("v"), "A point; (u, v) in the knot domain.")
      .def("derivative", &bpde::BSplineNet::derivative, py::arg("u"), py::arg("v"), py::arg("du"), py::arg("dv"))
      .def("to_dict", [](const bpde::BSplineNet& n) { return from_json(bpde::net_to_json(n)); })
      .def("__repr__", [](const bpde::BSplineNet& n) {
        return "BSplineNet(p=" + std::to_string(n.p()) + ", q=" + std::to_string(n.q()) +
               ", nu=" + std::to_string(n.nu()) + ", nv=" + std::to_string(n.nv()) + ")";
      });
  m.def(
      "net_from_dict", [](py::handle d) { return net_object(net_arg(d)); }, py::arg("net"),
      "A TensorNet, TriangularNet or BSplineNet from a NET dict (FORMATS.md \"Nets\").");
}

}  // namespace bpde::python
