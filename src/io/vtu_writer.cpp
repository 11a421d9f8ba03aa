#include "io/vtu_writer.hpp"

#include <limits>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

namespace si {
namespace {

void check_field(const std::string& name, const Eigen::MatrixXd& values, int rows,
                 const std::string& kind) {
  if (values.rows() != rows)
    throw_input(kind + " field '" + name + "' has " + std::to_string(values.rows()) +
                " rows, expected " + std::to_string(rows));
  if (values.cols() != 1 && values.cols() != 3 && values.cols() != 6)
    throw_input(kind + " field '" + name + "' has " + std::to_string(values.cols()) +
                " components, expected 1, 3 or 6");
  if (name.empty() || name.find_first_of("\"<>&") != std::string::npos)
    throw_input(kind + " field name '" + name + "' is empty or not valid in XML");
}

void write_array(std::ostream& os, const std::string& name, const Eigen::MatrixXd& values) {
  os << "        <DataArray type=\"Float64\" Name=\"" << name << "\" NumberOfComponents=\""
     << values.cols() << "\" format=\"ascii\">\n";
  for (Eigen::Index i = 0; i < values.rows(); ++i) {
    os << "         ";
    for (Eigen::Index j = 0; j < values.cols(); ++j) os << ' ' << values(i, j);
    os << '\n';
  }
  os << "        </DataArray>\n";
}

Eigen::MatrixXd rows_of(const std::vector<NodeState>& state, bool displacement) {
  Eigen::MatrixXd m(static_cast<Eigen::Index>(state.size()), 3);
  for (std::size_t i = 0; i < state.size(); ++i)
    m.row(static_cast<Eigen::Index>(i)) = (displacement ? state[i].u : state[i].d).transpose();
  return m;
}

void write_grid(std::ostream& os, const Mesh& mesh, const std::vector<NodeState>& state,
                const VtuFields& fields) {
  os.precision(std::numeric_limits<double>::max_digits10);
  os << "<?xml version=\"1.0\"?>\n"
     << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
     << "  <UnstructuredGrid>\n"
     << "    <Piece NumberOfPoints=\"" << mesh.num_nodes() << "\" NumberOfCells=\""
     << mesh.num_elements() << "\">\n"
     << "      <Points>\n"
     << "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const Vector3d x = fields.deformed ? Vector3d(mesh.nodes[n] + state[n].u) : mesh.nodes[n];
    os << "          " << x.x() << ' ' << x.y() << ' ' << x.z() << '\n';
  }
  os << "        </DataArray>\n      </Points>\n      <Cells>\n"
     << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& el : mesh.elements)
    os << "          " << el[0] << ' ' << el[1] << ' ' << el[2] << ' ' << el[3] << '\n';
  os << "        </DataArray>\n"
     << "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (int e = 0; e < mesh.num_elements(); ++e) os << "          " << 4 * (e + 1) << '\n';
  os << "        </DataArray>\n"
     << "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (int e = 0; e < mesh.num_elements(); ++e) os << "          9\n";
  os << "        </DataArray>\n      </Cells>\n"
     << "      <PointData Vectors=\"displacement\">\n";
  write_array(os, "displacement", rows_of(state, true));
  write_array(os, "director", rows_of(state, false));
  for (const auto& [name, values] : fields.point_data) write_array(os, name, values);
  os << "      </PointData>\n      <CellData>\n";
  for (const auto& [name, values] : fields.cell_data) write_array(os, name, values);
  os << "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
}

}  // namespace

void write_vtu(const std::string& path, const Mesh& mesh, const std::vector<NodeState>& state,
               const VtuFields& fields) {
  SI_REQUIRE(static_cast<int>(state.size()) == mesh.num_nodes(),
             "VTU output needs one nodal state per node");
  for (const auto& [name, values] : fields.point_data) {
    check_field(name, values, mesh.num_nodes(), "point");
    if (name == "displacement" || name == "director")
      throw_input("point field name '" + name + "' is reserved (written from the nodal state)");
  }
  for (const auto& [name, values] : fields.cell_data)
    check_field(name, values, mesh.num_elements(), "cell");

  write_file_atomically(path, [&](std::ostream& os) { write_grid(os, mesh, state, fields); });
}

}  // namespace si
