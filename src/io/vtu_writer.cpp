#include "io/vtu_writer.hpp"

#include <cstdint>
#include <cstring>
#include <limits>
#include <ostream>

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

bool little_endian() {
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

// Writes the DataArray elements: inline text, or an `offset` into the appended block, which
// holds per array a UInt64 byte count followed by the values (VTK XML file formats,
// "appended" data, encoding raw).
class ArrayWriter {
 public:
  ArrayWriter(std::ostream& os, bool binary) : os_(os), binary_(binary) {}

  template <class T>
  void write(const char* type, const std::string& name, int components,
             const std::vector<T>& values) {
    os_ << "        <DataArray type=\"" << type << '"'
        << (name.empty() ? "" : " Name=\"" + name + '"') << " NumberOfComponents=\"" << components
        << '"';
    if (binary_) {
      os_ << " format=\"appended\" offset=\"" << appended_.size() << "\"/>\n";
      const std::uint64_t bytes = values.size() * sizeof(T);
      append(&bytes, sizeof bytes);
      append(values.data(), bytes);
      return;
    }
    os_ << " format=\"ascii\">\n";
    const std::size_t per_line = static_cast<std::size_t>(components);
    for (std::size_t i = 0; i < values.size(); ++i) {
      os_ << (i % per_line == 0 ? "         " : "") << ' ' << +values[i];
      if ((i + 1) % per_line == 0) os_ << '\n';
    }
    os_ << "        </DataArray>\n";
  }

  void write(const std::string& name, const Eigen::MatrixXd& values) {
    std::vector<double> flat(static_cast<std::size_t>(values.size()));
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
        flat.data(), values.rows(), values.cols()) = values;
    write("Float64", name, static_cast<int>(values.cols()), flat);
  }

  // The appended block, after the XML that refers to it (the '_' marks its start).
  void finish() {
    if (!binary_) return;
    os_ << "  <AppendedData encoding=\"raw\">\n   _";
    os_.write(appended_.data(), static_cast<std::streamsize>(appended_.size()));
    os_ << "\n  </AppendedData>\n";
  }

 private:
  void append(const void* data, std::size_t bytes) {
    const char* p = static_cast<const char*>(data);
    appended_.insert(appended_.end(), p, p + bytes);
  }

  std::ostream& os_;
  bool binary_;
  std::vector<char> appended_;
};

void write_grid(std::ostream& os, const VtuGrid& grid, bool binary) {
  os.precision(std::numeric_limits<double>::max_digits10);
  os << "<?xml version=\"1.0\"?>\n"
     << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\""
     << (little_endian() ? "LittleEndian" : "BigEndian") << "\" header_type=\"UInt64\">\n"
     << "  <UnstructuredGrid>\n"
     << "    <Piece NumberOfPoints=\"" << grid.points.rows() << "\" NumberOfCells=\""
     << grid.cells.size() << "\">\n"
     << "      <Points>\n";
  ArrayWriter arrays(os, binary);
  arrays.write("", grid.points);
  os << "      </Points>\n      <Cells>\n";
  std::vector<std::int64_t> connectivity, offsets;
  for (const auto& q : grid.cells) {
    connectivity.insert(connectivity.end(), q.begin(), q.end());
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
  }
  arrays.write("Int64", "connectivity", 1, connectivity);
  arrays.write("Int64", "offsets", 1, offsets);
  arrays.write("UInt8", "types", 1, std::vector<std::uint8_t>(grid.cells.size(), 9));
  os << "      </Cells>\n      <PointData Vectors=\"displacement\">\n";
  // displacement and director first, then the other fields by name (as before binary output).
  for (const char* first : {"displacement", "director"})
    arrays.write(first, grid.point_data.at(first).values);
  for (const auto& [name, array] : grid.point_data)
    if (name != "displacement" && name != "director") arrays.write(name, array.values);
  os << "      </PointData>\n      <CellData>\n";
  for (const auto& [name, array] : grid.cell_data) arrays.write(name, array.values);
  os << "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n";
  arrays.finish();
  os << "</VTKFile>\n";
}

VtuArray kind_of(const VtuFields& fields, const std::string& name, const Eigen::MatrixXd& values) {
  const auto it = fields.kinds.find(name);
  return {values, it == fields.kinds.end() ? FieldKind::kScalars : it->second};
}

VtuGrid grid_of(const Mesh& mesh, const std::vector<NodeState>& state, const VtuFields& fields) {
  VtuGrid grid;
  const int n = mesh.num_nodes();
  grid.points.resize(n, 3);
  Eigen::MatrixXd u(n, 3), d(n, 3);
  for (int i = 0; i < n; ++i) {
    grid.points.row(i) = mesh.nodes[i].transpose();
    u.row(i) = state[i].u.transpose();
    d.row(i) = state[i].d.transpose();
  }
  grid.cells = mesh.elements;
  grid.point_data["displacement"] = {u, FieldKind::kVector};
  grid.point_data["director"] = {d, FieldKind::kVector};
  for (const auto& [name, values] : fields.point_data)
    grid.point_data[name] = kind_of(fields, name, values);
  for (const auto& [name, values] : fields.cell_data)
    grid.cell_data[name] = kind_of(fields, name, values);
  return grid;
}

}  // namespace

void write_vtu(const std::string& path, const Mesh& mesh, const std::vector<NodeState>& state,
               const VtuFields& fields, const VtuFormat& format) {
  SI_REQUIRE(static_cast<int>(state.size()) == mesh.num_nodes(),
             "VTU output needs one nodal state per node");
  for (const auto& [name, values] : fields.point_data) {
    check_field(name, values, mesh.num_nodes(), "point");
    if (name == "displacement" || name == "director")
      throw_input("point field name '" + name + "' is reserved (written from the nodal state)");
  }
  for (const auto& [name, values] : fields.cell_data)
    check_field(name, values, mesh.num_elements(), "cell");

  VtuGrid grid = grid_of(mesh, state, fields);
  if (format.mirror_quarter) {
    const double size = grid.points.cwiseAbs().maxCoeff();
    for (int axis : {0, 1}) grid = mirrored(grid, axis, 1e-9 * size);
  }
  const bool binary =
      format.encoding == VtuEncoding::kBinary ||
      (format.encoding == VtuEncoding::kAuto && grid.points.rows() >= kBinaryFromPoints);
  write_file_atomically(path, [&](std::ostream& os) { write_grid(os, grid, binary); });
}

}  // namespace si
