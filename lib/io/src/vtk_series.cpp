#include "dda/io/vtk_series.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "dda/io/csv.hpp"

namespace dda::io {

namespace {

namespace fs = std::filesystem;

// VTK cell type numbers (vtkCellType.h).
constexpr int kVtkVertex = 1, kVtkLine = 3, kVtkTriangle = 5, kVtkPolygon = 7;

int cell_type(int size) {
  switch (size) {
    case 1: return kVtkVertex;
    case 2: return kVtkLine;
    case 3: return kVtkTriangle;
    default: return kVtkPolygon;
  }
}

std::string xml_escaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

void check_array(const VtkArray& a, std::size_t tuples, const char* where, const std::string& label) {
  const std::string what = label + ": " + where + " array '" + a.name + "'";
  if (a.name.empty()) throw std::invalid_argument(label + ": " + where + " array without a name");
  if (a.components < 1) throw std::invalid_argument(what + ": components must be >= 1");
  if (a.values.size() != tuples * static_cast<std::size_t>(a.components))
    throw std::invalid_argument(what + ": " + std::to_string(a.values.size()) + " values, expected " +
                                std::to_string(tuples) + " x " + std::to_string(a.components));
  if (!a.component_names.empty() && a.component_names.size() != static_cast<std::size_t>(a.components))
    throw std::invalid_argument(what + ": " + std::to_string(a.component_names.size()) + " component names for " +
                                std::to_string(a.components) + " components");
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    const double v = a.values[i];
    const std::size_t tuple = i / static_cast<std::size_t>(a.components);
    if (!std::isfinite(v))
      throw NonFiniteValue(what + ", tuple " + std::to_string(tuple) + ": " +
                           (std::isnan(v) ? "NaN" : "infinite value") + " (not written)");
    if (a.integer && v != std::floor(v))
      throw std::invalid_argument(what + ", tuple " + std::to_string(tuple) + ": integer array holds " +
                                  format_number(v));
  }
}

// One tuple per line, values separated by spaces.
void append_values(std::string& s, const VtkArray& a) {
  const std::size_t c = static_cast<std::size_t>(a.components);
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    s += a.integer ? std::to_string(static_cast<long long>(a.values[i])) : format_number(a.values[i]);
    s += (i + 1) % c == 0 ? '\n' : ' ';
  }
}

void append_xml_array(std::string& s, const VtkArray& a, const char* indent) {
  s += indent;
  s += "<DataArray type=\"";
  s += a.integer ? "Int64" : "Float64";
  s += "\" Name=\"" + xml_escaped(a.name) + "\" NumberOfComponents=\"" + std::to_string(a.components) + "\"";
  for (std::size_t k = 0; k < a.component_names.size(); ++k)
    s += " ComponentName" + std::to_string(k) + "=\"" + xml_escaped(a.component_names[k]) + "\"";
  s += " format=\"ascii\">\n";
  append_values(s, a);
  s += indent;
  s += "</DataArray>\n";
}

}  // namespace

void VtkMesh::add_cell(const int* first, int count) {
  if (offsets.empty()) offsets.push_back(0);
  connectivity.insert(connectivity.end(), first, first + count);
  offsets.push_back(static_cast<int>(connectivity.size()));
}

void VtkMesh::add_vertex(Vec2 p) {
  const int i = static_cast<int>(points.size());
  points.push_back(p);
  add_cell(&i, 1);
}

const VtkArray* VtkMesh::cell_array(const std::string& name) const {
  for (const VtkArray& a : cell_data)
    if (a.name == name) return &a;
  return nullptr;
}

const VtkArray* VtkMesh::point_array(const std::string& name) const {
  for (const VtkArray& a : point_data)
    if (a.name == name) return &a;
  return nullptr;
}

void check_mesh(const VtkMesh& m, const std::string& label) {
  if (m.offsets.empty() || m.offsets.front() != 0 || m.offsets.back() != static_cast<int>(m.connectivity.size()))
    throw std::invalid_argument(label + ": offsets must start at 0 and end at the connectivity's size");
  const int n = static_cast<int>(m.points.size());
  for (std::size_t c = 0; c + 1 < m.offsets.size(); ++c) {
    if (m.offsets[c + 1] <= m.offsets[c])
      throw std::invalid_argument(label + ": cell " + std::to_string(c) + " has no points");
    for (int k = m.offsets[c]; k < m.offsets[c + 1]; ++k) {
      const int p = m.connectivity[static_cast<std::size_t>(k)];
      if (p < 0 || p >= n)
        throw std::invalid_argument(label + ": cell " + std::to_string(c) + " refers to point " + std::to_string(p) +
                                    " of " + std::to_string(n));
    }
  }
  for (std::size_t i = 0; i < m.points.size(); ++i)
    if (!std::isfinite(m.points[i].x) || !std::isfinite(m.points[i].y))
      throw NonFiniteValue(label + ": point " + std::to_string(i) + " is not finite (not written)");
  for (const VtkArray& a : m.point_data) check_array(a, m.point_count(), "point", label);
  for (const VtkArray& a : m.cell_data) check_array(a, m.cell_count(), "cell", label);
}

std::string vtu_text(const VtkMesh& m, double time, const std::string& label) {
  check_mesh(m, label);
  if (!std::isfinite(time)) throw NonFiniteValue(label + ": the frame's time is not finite (not written)");
  std::string s;
  s.reserve(m.points.size() * 48 + m.connectivity.size() * 8 + 1024);
  s += "<?xml version=\"1.0\"?>\n";
  s += "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n";
  s += "  <UnstructuredGrid>\n";
  s += "    <FieldData>\n";
  s += "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">\n";
  s += format_number(time) + "\n";
  s += "      </DataArray>\n";
  s += "    </FieldData>\n";
  s += "    <Piece NumberOfPoints=\"" + std::to_string(m.point_count()) + "\" NumberOfCells=\"" +
       std::to_string(m.cell_count()) + "\">\n";
  s += "      <PointData>\n";
  for (const VtkArray& a : m.point_data) append_xml_array(s, a, "        ");
  s += "      </PointData>\n";
  s += "      <CellData>\n";
  for (const VtkArray& a : m.cell_data) append_xml_array(s, a, "        ");
  s += "      </CellData>\n";
  s += "      <Points>\n";
  s += "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const Vec2& p : m.points) s += format_number(p.x) + " " + format_number(p.y) + " 0\n";
  s += "        </DataArray>\n";
  s += "      </Points>\n";
  s += "      <Cells>\n";
  s += "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t c = 0; c + 1 < m.offsets.size(); ++c) {
    for (int k = m.offsets[c]; k < m.offsets[c + 1]; ++k) {
      if (k > m.offsets[c]) s += ' ';
      s += std::to_string(m.connectivity[static_cast<std::size_t>(k)]);
    }
    s += '\n';
  }
  s += "        </DataArray>\n";
  s += "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t c = 1; c < m.offsets.size(); ++c) s += std::to_string(m.offsets[c]) + "\n";
  s += "        </DataArray>\n";
  s += "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t c = 0; c + 1 < m.offsets.size(); ++c)
    s += std::to_string(cell_type(m.offsets[c + 1] - m.offsets[c])) + "\n";
  s += "        </DataArray>\n";
  s += "      </Cells>\n";
  s += "    </Piece>\n";
  s += "  </UnstructuredGrid>\n";
  s += "</VTKFile>\n";
  return s;
}

std::string legacy_vtk_text(const VtkMesh& m, const std::string& title, const std::string& label) {
  check_mesh(m, label);
  for (const auto* data : {&m.cell_data, &m.point_data})
    for (const VtkArray& a : *data)
      if (a.components != 1 && a.components != 3)
        throw std::invalid_argument(label + ": legacy VTK array '" + a.name + "' needs 1 or 3 components");
  std::string s;
  s.reserve(m.points.size() * 48 + m.cell_count() * 160 + 512);
  std::string t = title;
  for (char& c : t)
    if (c == '\n' || c == '\r') c = ' ';
  if (t.size() > 255) t.resize(255);  // the legacy format limits the title line to 256 characters
  s += "# vtk DataFile Version 3.0\n" + t + "\nASCII\nDATASET POLYDATA\n";
  s += "POINTS " + std::to_string(m.point_count()) + " double\n";
  for (const Vec2& p : m.points) s += format_number(p.x) + " " + format_number(p.y) + " 0\n";
  s += "POLYGONS " + std::to_string(m.cell_count()) + " " + std::to_string(m.cell_count() + m.connectivity.size()) +
       "\n";
  for (std::size_t c = 0; c + 1 < m.offsets.size(); ++c) {
    s += std::to_string(m.offsets[c + 1] - m.offsets[c]);
    for (int k = m.offsets[c]; k < m.offsets[c + 1]; ++k)
      s += " " + std::to_string(m.connectivity[static_cast<std::size_t>(k)]);
    s += "\n";
  }
  auto section = [&](const std::vector<VtkArray>& arrays, const char* head, std::size_t count) {
    if (arrays.empty()) return;
    s += std::string(head) + " " + std::to_string(count) + "\n";
    for (const VtkArray& a : arrays) {
      const char* type = a.integer ? "int" : "double";
      if (a.components == 1)
        s += "SCALARS " + a.name + " " + type + " 1\nLOOKUP_TABLE default\n";
      else
        s += "VECTORS " + a.name + " " + type + "\n";
      append_values(s, a);
    }
  };
  section(m.cell_data, "CELL_DATA", m.cell_count());
  section(m.point_data, "POINT_DATA", m.point_count());
  return s;
}

VtkSeries::VtkSeries(std::string dir, std::string name) : dir_(std::move(dir)), name_(std::move(name)) {
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec) throw OutputError("cannot create directory " + dir_ + ": " + ec.message());
}

VtkSeries::VtkSeries(std::string dir, std::string name, std::vector<double> times)
    : VtkSeries(std::move(dir), std::move(name)) {
  times_ = std::move(times);
}

std::string VtkSeries::frame_file(const std::string& name, std::size_t frame) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "_%06zu.vtu", frame);
  return name + buf;
}

std::string VtkSeries::collection_path() const { return (fs::path(dir_) / (name_ + ".pvd")).string(); }

void VtkSeries::add(double time, const VtkMesh& mesh) {
  const std::string path = (fs::path(dir_) / frame_file(times_.size())).string();
  write_file_atomic(path, vtu_text(mesh, time, path));
  times_.push_back(time);
}

void VtkSeries::write_collection() const {
  std::string s = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                  "  <Collection>\n";
  for (std::size_t i = 0; i < times_.size(); ++i)
    s += "    <DataSet timestep=\"" + format_number(times_[i]) + "\" group=\"\" part=\"0\" file=\"" +
         xml_escaped(frame_file(i)) + "\"/>\n";
  s += "  </Collection>\n</VTKFile>\n";
  write_file_atomic(collection_path(), s);
}

}  // namespace dda::io
