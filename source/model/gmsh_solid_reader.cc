#include <deal.II/base/exceptions.h>
#include <deal.II/base/geometry_info.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>

#include <hati/base/input_file.h>
#include <hati/base/messages.h>
#include <hati/model/gmsh_solid_reader.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace hati
{
namespace
{
/** Largest count or tag accepted (-). */

/** The Gmsh element types skipped (boundary entities) and their node counts. */
const std::map<long, unsigned int> skipped_types = {{15, 1}, {1, 2}, {2, 3}, {3, 4}};

/** The hexahedra of a Gmsh ASCII file, read line by line. */
class HexahedronReader
{
public:
  HexahedronReader(const std::string &filename, const std::string &where)
      : label(where + ": '" + filename + "'"), in(filename)
  {
    AssertThrow(in, ExcMessage(where + ": cannot open the mesh file '" + filename + "'"));
  }

  /** Read the file: the nodes and the hexahedra (deal.II's vertex order). */
  void read();

  /** The vertices and cells read (each hexahedron with a positive Jacobian). */
  std::vector<Point<3>> vertices;
  std::vector<CellData<3>> cells;

  /** Throw "<label>, line <n>: <what>". */
  void fail(const std::string &what) const
  {
    AssertThrow(false,
                ExcMessage(label + ", line " + std::to_string(number) + ": " + what));
  }

private:
  std::string line()
  {
    std::string l;
    if (!std::getline(in, l))
      fail("unexpected end of the file (cut short?)");
    ++number;
    if (!l.empty() && l.back() == '\r')
      l.pop_back();
    return l;
  }

  /** The numbers of the next line, at least @p n of them. */
  std::vector<double> numbers(const unsigned int n)
  {
    const std::string l = line();
    std::istringstream s(l);
    std::vector<double> v;
    double x;
    while (s >> x)
      v.push_back(x);
    if (v.size() < n || !s.eof())
      fail("expected " + std::to_string(n) + " numbers or more, got '" + l.substr(0, 80) +
           "'");
    return v;
  }

  /** @p x as an integer from @p lo to @p hi. */
  long
  integer(const double x, const long lo, const long hi, const std::string &what) const
  {
    if (!(x == std::floor(x) && x >= double(lo) && x <= double(hi)))
    {
      std::ostringstream s;
      s << what << " must be an integer from " << lo << " to " << hi << ", got " << x;
      fail(s.str());
    }
    return static_cast<long>(x);
  }

  void read_format();
  void read_nodes();
  void read_elements();
  /** Element @p id of Gmsh type @p type, its nodes from v[first]. */
  void add_element(const long id,
                   const long type,
                   const std::vector<double> &v,
                   const std::size_t first);
  /** The section must end with @p end. */
  void expect(const std::string &end)
  {
    if (line() != end)
      fail("expected " + end + " (a count of the section does not match its lines)");
  }

  const std::string label;
  std::ifstream in;
  unsigned int number = 0;
  double version = 0.;
  std::map<long, unsigned int> vertex_index;     // node tag -> vertex
  std::set<std::vector<unsigned int>> hexahedra; // the sorted vertices of each
};

void HexahedronReader::read()
{
  std::string l;
  while (std::getline(in, l))
  {
    ++number;
    if (!l.empty() && l.back() == '\r')
      l.pop_back();
    if (l == "$MeshFormat")
      read_format();
    else if (l == "$Nodes")
      read_nodes();
    else if (l == "$Elements")
      read_elements();
    else if (number == 1)
      fail("not a Gmsh mesh: it does not start with $MeshFormat");
  }
  if (cells.empty())
    fail("the file holds no hexahedron (Gmsh element type 5)");
}

void HexahedronReader::read_format()
{
  const auto v = numbers(2);
  version = v[0];
  if (!((version >= 2. && version < 3.) || version == 4.1))
  {
    std::ostringstream s;
    s << "Gmsh format " << version << " is not read: save it as ASCII format 4.1 or 2.2";
    fail(s.str());
  }
  if (v[1] != 0.)
    fail("a binary Gmsh file: save it as ASCII (format 4.1 or 2.2)");
  expect("$EndMeshFormat");
}

void HexahedronReader::read_nodes()
{
  if (version == 0.)
    fail("$Nodes before $MeshFormat");
  if (!vertices.empty())
    fail("a second $Nodes section");
  // the tags and coordinates of one block of n nodes (format 4.1) or of the
  // section (format 2.2, "tag x y z" lines)
  auto add = [&](const long tag, const std::vector<double> &x, const std::size_t k)
  {
    if (!(std::isfinite(x[k]) && std::isfinite(x[k + 1]) && std::isfinite(x[k + 2])))
      fail("the coordinates of node " + std::to_string(tag) + " are not finite");
    for (unsigned int d = 0; d < 3; ++d)
      if (std::abs(x[k + d]) > max_file_coordinate)
        fail("the coordinates of node " + std::to_string(tag) +
             " are out of range (|x| <= 1e6 m expected)");
    if (!vertex_index.emplace(tag, vertices.size()).second)
      fail("node " + std::to_string(tag) + " is defined twice");
    vertices.emplace_back(x[k], x[k + 1], x[k + 2]);
  };
  if (version < 3.)
  {
    const long n = integer(numbers(1)[0], 0, max_file_count, "the number of nodes");
    for (long i = 0; i < n; ++i)
    {
      const auto v = numbers(4);
      add(integer(v[0], 1, max_file_count, "a node tag"), v, 1);
    }
  }
  else
  {
    const auto h = numbers(4); // blocks, nodes, smallest and largest tag
    const long n_blocks = integer(h[0], 0, max_file_count, "the number of node blocks");
    const long n_nodes = integer(h[1], 0, max_file_count, "the number of nodes");
    for (long b = 0; b < n_blocks; ++b)
    {
      // dimension, entity, parametric, nodes; the tags, then the coordinates
      const long n = integer(numbers(4)[3], 0, max_file_count, "the number of nodes");
      std::vector<long> tags;
      for (long i = 0; i < n; ++i)
        tags.push_back(integer(numbers(1)[0], 1, max_file_count, "a node tag"));
      for (long i = 0; i < n; ++i)
        add(tags[i], numbers(3), 0);
    }
    if (long(vertices.size()) != n_nodes)
      fail("the blocks hold " + std::to_string(vertices.size()) + " nodes, the header " +
           std::to_string(n_nodes));
  }
  expect("$EndNodes");
}

void HexahedronReader::read_elements()
{
  if (version == 0.)
    fail("$Elements before $MeshFormat");
  if (version < 3.)
  {
    const long n = integer(numbers(1)[0], 0, max_file_count, "the number of elements");
    for (long i = 0; i < n; ++i)
    {
      // number, type, number of tags, the tags, the nodes
      const auto v = numbers(3);
      const long n_tags = integer(v[2], 0, 1000, "the number of tags");
      add_element(integer(v[0], 0, max_file_count, "an element number"),
                  integer(v[1], 0, max_file_count, "an element type"),
                  v,
                  3 + n_tags);
    }
  }
  else
  {
    const auto h = numbers(4); // blocks, elements, smallest and largest tag
    const long n_blocks =
        integer(h[0], 0, max_file_count, "the number of element blocks");
    const long n_elements = integer(h[1], 0, max_file_count, "the number of elements");
    long read = 0;
    for (long b = 0; b < n_blocks; ++b)
    {
      const auto block = numbers(4); // dimension, entity, type, elements
      const long type = integer(block[2], 0, max_file_count, "an element type");
      const long n = integer(block[3], 0, max_file_count, "the number of elements");
      for (long i = 0; i < n; ++i, ++read)
      {
        const auto v = numbers(1);
        add_element(integer(v[0], 0, max_file_count, "an element tag"), type, v, 1);
      }
    }
    if (read != n_elements)
      fail("the blocks hold " + std::to_string(read) + " elements, the header " +
           std::to_string(n_elements));
  }
  expect("$EndElements");
}

/**
 * The Jacobian determinants at the eight corners of a hexahedron of
 * deal.II's vertex order (vertex i + 2 j + 4 k at the corner (i, j, k)).
 */
std::array<double, 8> corner_jacobians(const std::vector<Point<3>> &x,
                                       const std::vector<unsigned int> &v)
{
  std::array<double, 8> det;
  for (unsigned int c = 0; c < 8; ++c)
  {
    std::array<Tensor<1, 3>, 3> edge;
    for (unsigned int d = 0; d < 3; ++d)
    {
      const unsigned int bit = 1u << d;
      edge[d] = (x[v[c ^ bit]] - x[v[c]]) * ((c & bit) ? -1. : 1.);
    }
    det[c] = edge[0] * cross_product_3d(edge[1], edge[2]);
  }
  return det;
}

void HexahedronReader::add_element(const long id,
                                   const long type,
                                   const std::vector<double> &v,
                                   const std::size_t first)
{
  const std::string element = "element " + std::to_string(id);
  const auto skipped = skipped_types.find(type);
  if (skipped != skipped_types.end())
  {
    if (v.size() < first + skipped->second)
      fail(element + ": too few nodes");
    return;
  }
  if (type != 5)
    fail(element + " is of Gmsh type " + std::to_string(type) +
         (type == 4 ? " (a tetrahedron)" : "") +
         ": only hexahedral meshes are read (8-node hexahedra, type 5; points, lines, "
         "triangles and quadrilaterals are skipped)");
  if (v.size() != first + 8)
    fail(element + " (a hexahedron) must have 8 nodes, not " +
         std::to_string(long(v.size()) - long(first)));
  CellData<3> cell(8);
  for (unsigned int i = 0; i < 8; ++i)
  {
    const long tag = integer(v[first + i], 1, max_file_count, "a node tag");
    const auto it = vertex_index.find(tag);
    if (it == vertex_index.end())
      fail(element + ": node " + std::to_string(tag) + " is not in $Nodes");
    cell.vertices[GeometryInfo<3>::ucd_to_deal[i]] = it->second;
  }
  // a hexahedron turned inside out is mirrored; one with corners of both
  // signs or a zero Jacobian (collapsed, twisted) cannot be used
  auto det = corner_jacobians(vertices, cell.vertices);
  if (std::all_of(det.begin(), det.end(), [](const double d) { return d < 0.; }))
  {
    for (unsigned int c = 0; c < 8; c += 2)
      std::swap(cell.vertices[c], cell.vertices[c + 1]);
    det = corner_jacobians(vertices, cell.vertices);
  }
  if (!std::all_of(det.begin(), det.end(), [](const double d) { return d > 0.; }))
    fail(element + " (a hexahedron) is collapsed or twisted: its Jacobian is not "
                   "positive at every corner");
  std::vector<unsigned int> sorted = cell.vertices;
  std::sort(sorted.begin(), sorted.end());
  if (!hexahedra.insert(sorted).second)
    fail(element + " (a hexahedron) has the same eight nodes as an earlier one");
  cells.push_back(cell);
}
} // namespace

void read_gmsh_hexahedra(const std::string &filename,
                         const std::string &where,
                         Triangulation<3> &triangulation)
{
  require_regular_file(filename, where, "mesh");
  HexahedronReader reader(filename, where);
  reader.read();
  SubCellData none;
  GridTools::delete_unused_vertices(reader.vertices, reader.cells, none);
  try
  {
    GridTools::consistently_order_cells(reader.cells);
    triangulation.create_triangulation(reader.vertices, reader.cells, none);
  }
  catch (const std::exception &e)
  {
    AssertThrow(false,
                ExcMessage(where + ": '" + filename +
                           "': the hexahedra do not form a "
                           "mesh deal.II accepts: " +
                           one_line_message(e).substr(0, 200)));
  }
}
} // namespace hati
