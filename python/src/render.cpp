// petersen._petersen's pictures and quad measure (petersen/render).

#include "render.hpp"

#include <pybind11/stl.h>

#include <optional>

#include "arrays.hpp"
#include "petersen/dualize/quad_quality.hpp"
#include "petersen/render/render_mesh.hpp"

namespace petersen::python {

namespace {

void render_py(const std::string& path, const py::handle& V, const py::handle& F,
               std::optional<std::int64_t> first_added_vertex, std::vector<std::string> caption,
               std::optional<std::array<double, 3>> view, std::uint32_t width,
               std::uint32_t height) {
  PolygonMesh mesh;
  mesh.positions = positions_from(V);
  add_faces_from(F, mesh);
  RenderOptions options;
  options.width = width;
  options.height = height;
  options.view = view;
  options.caption = std::move(caption);
  if (first_added_vertex) {
    if (*first_added_vertex < 0) throw py::value_error("first_added_vertex must be >= 0");
    options.first_added_vertex =
        VertexId(std::min<std::int64_t>(*first_added_vertex, mesh.positions.size()));
  }
  py::gil_scoped_release release;
  render_mesh(mesh, path, options);
}

py::array_t<double> quad_quality_py(const py::handle& V, const py::handle& quads) {
  PolygonMesh mesh;
  mesh.positions = positions_from(V);
  add_faces_from(quads, mesh);
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    if (mesh.arity(f) != 4) {
      throw py::value_error("face " + std::to_string(f) + " has " + std::to_string(mesh.arity(f)) +
                            " corners, not 4");
    }
    for (VertexId v : mesh.face(f)) {
      if (v >= mesh.positions.size()) {
        throw py::value_error("quad " + std::to_string(f) + ": vertex index " + std::to_string(v) +
                              " is out of range (" + std::to_string(mesh.positions.size()) +
                              " vertices)");
      }
    }
  }
  std::vector<double> costs;
  {
    py::gil_scoped_release release;
    costs = quad_costs(mesh);
  }
  py::array_t<double> out(costs.size());
  std::copy(costs.begin(), costs.end(), out.mutable_data());
  return out;
}

}  // namespace

void add_render(py::module_& m) {
  m.def("render", &render_py, py::arg("path"), py::arg("V"), py::arg("F"),
        py::arg("first_added_vertex"), py::arg("caption"), py::arg("view"), py::arg("width"),
        py::arg("height"));
  m.def("quad_quality", &quad_quality_py, py::arg("V"), py::arg("quads"));
}

}  // namespace petersen::python
