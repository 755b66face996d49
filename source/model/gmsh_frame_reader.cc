#include <deal.II/base/exceptions.h>

#include <hati/base/input_file.h>
#include <hati/model/gmsh_frame_reader.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

namespace hati
{
namespace
{
/** "<entry>: " (the parameter that names the file), or nothing. */
std::string entry_prefix(const std::string &entry)
{
  return entry.empty() ? "" : entry + ": ";
}

/** Largest node tag, element count or entry count accepted (-). */
/** Largest physical or entity tag (they are `int` in Gmsh). */
constexpr long max_tag = std::numeric_limits<int>::max();

/** Line-by-line reader that knows where it is, for the error messages. */
class Reader
{
public:
  /** Errors start with "<entry>: mesh file '<filename>'". */
  Reader(const std::string &filename, const std::string &entry)
      : label(entry_prefix(entry) + "mesh file '" + filename + "'"), in(filename)
  {
    AssertThrow(
        in,
        ExcMessage(entry_prefix(entry) + "cannot open the mesh file '" + filename + "'"));
  }

  /** The next line (throws at the end of the file). */
  std::string line()
  {
    std::string l;
    AssertThrow(std::getline(in, l), ExcMessage(where() + "unexpected end of file"));
    ++number;
    if (!l.empty() && l.back() == '\r')
      l.pop_back();
    return l;
  }

  bool next(std::string &l)
  {
    if (!std::getline(in, l))
      return false;
    ++number;
    if (!l.empty() && l.back() == '\r')
      l.pop_back();
    return true;
  }

  /** Numbers of the next line, at least @p n of them. */
  std::vector<double> numbers(const unsigned int n)
  {
    const std::string l = line();
    std::istringstream s(l);
    std::vector<double> v;
    double x;
    while (s >> x)
      v.push_back(x);
    AssertThrow(v.size() >= n && (s.eof() || v.size() >= n),
                ExcMessage(where() + "expected at least " + std::to_string(n) +
                           " numbers, got '" + l + "'"));
    return v;
  }

  /**
   * @p x (a number read from the current line) as an integer from @p lo to
   * @p hi; an error naming the line and @p what otherwise (a fraction, a
   * value out of range or not finite).
   */
  long
  integer(const double x, const long lo, const long hi, const std::string &what) const
  {
    if (!(x == std::floor(x) && x >= double(lo) && x <= double(hi)))
    {
      std::ostringstream s;
      s << where() << what << " must be an integer from " << lo << " to " << hi
        << ", got " << x;
      AssertThrow(false, ExcMessage(s.str()));
    }
    return static_cast<long>(x);
  }

  /** Number of lines read so far. */
  unsigned int line_number() const { return number; }

  std::string where() const { return label + ", line " + std::to_string(number) + ": "; }

private:
  const std::string label;
  std::ifstream in;
  unsigned int number = 0;
};
/** The sections of a Gmsh file, gathered for the frame's nodes and members. */
class MeshData
{
public:
  /** @p entry: the parameter that names the file (errors start with it). */
  MeshData(const std::string &filename, const std::string &entry)
      : label(entry_prefix(entry) + "mesh file '" + filename + "'"), r(filename, entry)
  {
  }

  /** Read every section the frame needs; others are skipped. */
  void read()
  {
    std::string l;
    while (r.next(l))
    {
      if (l == "$MeshFormat")
        read_format();
      else if (l == "$PhysicalNames")
        read_physical_names();
      else if (l == "$Entities")
        read_entities();
      else if (l == "$Nodes")
        read_nodes();
      else if (l == "$Elements")
      {
        read_elements();
        has_elements = true;
      }
    }
    AssertThrow(version > 0.,
                ExcMessage(label + ": no $MeshFormat section (not a Gmsh file?)"));
    // e.g. a file cut after its $Nodes
    AssertThrow(has_elements,
                ExcMessage(label + ": no $Elements section in its " +
                           std::to_string(r.line_number()) +
                           " lines: the file is cut short or holds no elements"));
  }

  /** The named nodes and the members as node chains. */
  GmshFrame frame();

private:
  void read_format()
  {
    const auto v = r.numbers(1);
    version = v[0];
    AssertThrow(version == 2.2 || (version >= 4.0 && version < 5.0),
                ExcMessage(r.where() + "Gmsh format " + std::to_string(version) +
                           " is not supported: write format 2.2 or 4.1 (ASCII)"));
    AssertThrow(v.size() < 2 || v[1] == 0,
                ExcMessage(r.where() + "binary Gmsh files are not supported"));
  }

  void read_physical_names()
  {
    const long n =
        r.integer(r.numbers(1)[0], 0, max_file_count, "the number of physical names");
    for (long i = 0; i < n; ++i)
    {
      const std::string t = r.line();
      std::istringstream s(t);
      int dim = -1, tag = -1;
      s >> dim >> tag;
      const auto q1 = t.find('"'), q2 = t.rfind('"');
      AssertThrow(s && q1 != std::string::npos && q2 > q1,
                  ExcMessage(r.where() + "expected 'dimension tag \"name\"'"));
      const std::string name = t.substr(q1 + 1, q2 - q1 - 1);
      if (dim == 1)
        curve_names[tag] = name;
      else if (dim == 0)
        point_names[tag] = name;
    }
  }

  void read_entities()
  {
    const auto counts = r.numbers(4);
    for (unsigned int dim = 0; dim < 4; ++dim)
    {
      const long n = r.integer(counts[dim], 0, max_file_count, "the number of entities");
      for (long i = 0; i < n; ++i)
      {
        const auto v = r.numbers(dim == 0 ? 5 : 8);
        // point: tag x y z nphys phys...; others: tag 6 bounds nphys phys...
        const std::size_t first = dim == 0 ? 4 : 7;
        const int tag = r.integer(v[0], -max_tag, max_tag, "the entity tag");
        const long np =
            r.integer(v[first], 0, max_file_count, "the number of physical tags");
        AssertThrow(v.size() >= first + 1 + np,
                    ExcMessage(r.where() + "truncated entity line"));
        for (long k = 0; k < np; ++k)
          entity_physicals[dim][tag].push_back(
              r.integer(v[first + 1 + k], -max_tag, max_tag, "a physical tag"));
      }
    }
  }

  /** A node's coordinates, refused (file and line) beyond max_file_coordinate. */
  Point<3> checked_point(const double x, const double y, const double z) const
  {
    for (const double c : {x, y, z})
      AssertThrow(std::isfinite(c) && std::abs(c) <= max_file_coordinate,
                  ExcMessage(r.where() +
                             "a node coordinate is out of range (|x| <= 1e6 m "
                             "expected)"));
    return Point<3>(x, y, z);
  }

  void read_nodes()
  {
    if (version < 4.)
    {
      const long n = r.integer(r.numbers(1)[0], 0, max_file_count, "the number of nodes");
      for (long i = 0; i < n; ++i)
      {
        const auto v = r.numbers(4);
        node_coordinates[r.integer(v[0], 0, max_file_count, "the node tag")] =
            checked_point(v[1], v[2], v[3]);
      }
      return;
    }
    const auto h = r.numbers(4);
    const long n_blocks = r.integer(h[0], 0, max_file_count, "the number of node blocks");
    for (long b = 0; b < n_blocks; ++b)
    {
      const auto block = r.numbers(4); // dim entity parametric n
      AssertThrow(block[2] == 0,
                  ExcMessage(r.where() + "parametric nodes are not supported"));
      const long n = r.integer(block[3], 0, max_file_count, "the number of nodes");
      std::vector<long> tags;
      for (long i = 0; i < n; ++i)
        tags.push_back(r.integer(r.numbers(1)[0], 0, max_file_count, "the node tag"));
      for (long i = 0; i < n; ++i)
      {
        const auto x = r.numbers(3);
        node_coordinates[tags[i]] = checked_point(x[0], x[1], x[2]);
      }
    }
  }

  /** A line (type 1) or point (type 15) element of the @p physicals groups. */
  void add_element(const int type, const std::vector<int> &physicals, const double *nodes)
  {
    const long a = r.integer(nodes[0], 0, max_file_count, "the element's node tag");
    const long b =
        type == 1 ? r.integer(nodes[1], 0, max_file_count, "the element's node tag") : a;
    for (const int p : physicals)
    {
      if (type == 1)
        lines[p].emplace_back(a, b);
      else if (type == 15)
        named_node_tag[a] = p;
    }
  }

  void read_elements()
  {
    if (version < 4.)
    {
      const long n =
          r.integer(r.numbers(1)[0], 0, max_file_count, "the number of elements");
      for (long i = 0; i < n; ++i)
      {
        const auto v = r.numbers(3); // id type ntags tags... nodes...
        const int type = r.integer(v[1], -max_tag, max_tag, "the element type");
        const long ntags = r.integer(v[2], 0, max_file_count, "the number of tags");
        const std::size_t nn = type == 1 ? 2 : (type == 15 ? 1 : 0);
        AssertThrow(v.size() >= 3 + ntags + nn,
                    ExcMessage(r.where() + "truncated element"));
        if (nn == 0 || ntags == 0 || v[3] == 0) // no physical group
          continue;
        add_element(type,
                    {int(r.integer(v[3], -max_tag, max_tag, "the physical tag"))},
                    &v[3 + ntags]);
      }
      return;
    }
    const auto h = r.numbers(4);
    const long n_blocks =
        r.integer(h[0], 0, max_file_count, "the number of element blocks");
    for (long b = 0; b < n_blocks; ++b)
    {
      const auto block = r.numbers(4); // dim entity type n
      const int dim = r.integer(block[0], 0, 3, "the entity dimension"),
                entity = r.integer(block[1], -max_tag, max_tag, "the entity tag"),
                type = r.integer(block[2], -max_tag, max_tag, "the element type");
      const long n = r.integer(block[3], 0, max_file_count, "the number of elements");
      const auto &physicals = entity_physicals[dim][entity];
      for (long i = 0; i < n; ++i)
      {
        const auto v = r.numbers(2);
        if ((type == 1 && v.size() >= 3) || (type == 15 && v.size() >= 2))
          add_element(type, physicals, &v[1]);
      }
    }
  }

  /** The physical point name of node @p tag, or `@<tag>`. */
  std::string node_name(const long tag)
  {
    const auto it = named_node_tag.find(tag);
    if (it != named_node_tag.end() && point_names.count(it->second))
      return point_names[it->second];
    return "@" + std::to_string(tag);
  }

  Point<3> coordinates(const long tag) const
  {
    const auto it = node_coordinates.find(tag);
    AssertThrow(it != node_coordinates.end(),
                ExcMessage(label + ": element node " + std::to_string(tag) +
                           " is not in $Nodes"));
    return it->second;
  }

  /**
   * The chain of node names of the member @p name made of @p segments (its
   * nodes added to @p frame): an error if it branches, is closed or is not
   * connected.
   */
  std::vector<std::string> chain(const std::string &name,
                                 const std::vector<std::pair<long, long>> &segments,
                                 GmshFrame &frame);

  const std::string label;
  Reader r;
  double version = 0.;
  bool has_elements = false;
  std::map<int, std::string> curve_names, point_names; // physical tag -> name
  std::map<long, Point<3>> node_coordinates;
  std::map<int, std::vector<std::pair<long, long>>> lines; // physical tag -> lines
  std::map<long, int> named_node_tag;                      // node -> physical point tag
  std::map<int, std::vector<int>> entity_physicals[4];     // v4: entity -> physical tags
};

std::vector<std::string>
MeshData::chain(const std::string &name,
                const std::vector<std::pair<long, long>> &segments,
                GmshFrame &frame)
{
  std::map<long, std::vector<long>> adjacent;
  for (const auto &[a, b] : segments)
  {
    adjacent[a].push_back(b);
    adjacent[b].push_back(a);
  }
  long start = -1;
  for (const auto &[node, list] : adjacent)
  {
    AssertThrow(list.size() <= 2,
                ExcMessage(label + ": member '" + name + "' branches at node " +
                           std::to_string(node) +
                           "; split it into one physical curve per branch"));
    if (list.size() == 1 && start < 0)
      start = node;
  }
  AssertThrow(start >= 0,
              ExcMessage(label + ": member '" + name +
                         "' is a closed loop; split it into open physical curves"));
  std::vector<std::string> path;
  std::set<long> visited;
  for (long node = start, previous = -1; node >= 0;)
  {
    visited.insert(node);
    path.push_back(node_name(node));
    frame.nodes[path.back()] = coordinates(node);
    long next = -1;
    for (const long n : adjacent[node])
      if (n != previous && !visited.count(n))
        next = n;
    previous = node;
    node = next;
  }
  AssertThrow(
      visited.size() == adjacent.size(),
      ExcMessage(label + ": member '" + name + "' is not one connected chain; split it"));
  return path;
}

GmshFrame MeshData::frame()
{
  GmshFrame frame;
  for (const auto &[tag, name] : point_names)
    for (const auto &[node, p] : named_node_tag)
      if (p == tag)
        frame.nodes[name] = coordinates(node);

  for (const auto &[tag, segments] : lines)
  {
    AssertThrow(
        curve_names.count(tag),
        ExcMessage(label + ": physical curve " + std::to_string(tag) +
                   " has no name; name every member, e.g. Physical Curve(\"girder\")"));
    const std::string &name = curve_names[tag];
    frame.members[name] = chain(name, segments, frame);
  }
  AssertThrow(!frame.members.empty(),
              ExcMessage(label + ": no named physical curve of line elements"));
  return frame;
}
} // namespace

GmshFrame read_gmsh_frame(const std::string &filename, const std::string &entry)
{
  // stat first: opening a FIFO would block, a device would never end
  require_regular_file(filename, entry, "mesh");
  MeshData mesh(filename, entry);
  mesh.read();
  return mesh.frame();
}
} // namespace hati
