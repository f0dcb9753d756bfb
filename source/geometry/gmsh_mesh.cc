#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/geometry/gmsh_mesh.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

namespace lithostress
{
  namespace
  {
    /** A 2-D element of a Gmsh file (type 2, a triangle, or 3, a
     * quadrilateral): its number and its nodes. */
    struct MshElement
    {
      long              number = 0;
      int               type   = 0;
      std::vector<long> nodes;
    };

    /** The next line of @p in that is not blank, trimmed; false at the end
     * of the file. */
    bool
    next_line(std::istream &in, std::string &line)
    {
      while (std::getline(in, line))
        {
          line = Utilities::trim(line);
          if (!line.empty())
            return true;
        }
      return false;
    }

    /** The numbers on @p line. */
    template <typename Number>
    std::vector<Number>
    numbers_on(const std::string &line)
    {
      std::istringstream  text(line);
      std::vector<Number> numbers;
      Number              x;
      while (text >> x)
        numbers.push_back(x);
      return numbers;
    }

    /** The next line's first number if the line has at least @p n
     * numbers, else -1. */
    long
    count_on_next_line(std::istream &in, const unsigned int n = 1)
    {
      std::string line;
      if (!next_line(in, line))
        return -1;
      const auto numbers = numbers_on<long>(line);
      return numbers.size() >= n ? numbers[0] : -1;
    }

    /** The nodes of a `$Nodes` section of MSH 2 (`id x y z` lines); false
     * if it is cut short. */
    bool
    read_msh2_nodes(std::istream &in, std::map<long, Point<2>> &nodes)
    {
      const long  n = count_on_next_line(in);
      std::string line;
      for (long i = 0; i < n; ++i)
        {
          if (!next_line(in, line))
            return false;
          const auto x = numbers_on<double>(line);
          if (x.size() < 3)
            return false;
          nodes[static_cast<long>(x[0])] = Point<2>(x[1], x[2]);
        }
      return n >= 0;
    }

    /** The nodes of a `$Nodes` section of MSH 4.1 (entity blocks of node
     * tags, then their coordinates); false if it is cut short. */
    bool
    read_msh41_nodes(std::istream &in, std::map<long, Point<2>> &nodes)
    {
      const long  n_blocks = count_on_next_line(in, 4);
      std::string line;
      for (long b = 0; b < n_blocks; ++b)
        {
          if (!next_line(in, line))
            return false;
          const auto header = numbers_on<long>(line);
          if (header.size() < 4)
            return false;
          std::vector<long> tags;
          for (long i = 0; i < header[3]; ++i)
            {
              if (!next_line(in, line) || numbers_on<long>(line).empty())
                return false;
              tags.push_back(numbers_on<long>(line)[0]);
            }
          for (const long tag : tags)
            {
              if (!next_line(in, line))
                return false;
              const auto x = numbers_on<double>(line);
              if (x.size() < 2)
                return false;
              nodes[tag] = Point<2>(x[0], x[1]);
            }
        }
      return n_blocks >= 0;
    }

    /** The 2-D elements of an `$Elements` section of MSH 2 (`id type
     * n_tags tags... nodes...` lines); false if it is cut short. */
    bool
    read_msh2_elements(std::istream &in, std::vector<MshElement> &elements)
    {
      const long  n = count_on_next_line(in);
      std::string line;
      for (long i = 0; i < n; ++i)
        {
          if (!next_line(in, line))
            return false;
          const auto v = numbers_on<long>(line);
          if (v.size() < 3 ||
              v.size() < 3 + static_cast<std::size_t>(std::max(0L, v[2])))
            return false;
          if (v[1] != 2 && v[1] != 3)
            continue;
          MshElement element;
          element.number = v[0];
          element.type   = v[1];
          element.nodes.assign(v.begin() + 3 + v[2], v.end());
          elements.push_back(element);
        }
      return n >= 0;
    }

    /** The 2-D elements of an `$Elements` section of MSH 4.1 (entity
     * blocks of one element type, `tag nodes...` lines); false if it is
     * cut short. */
    bool
    read_msh41_elements(std::istream &in, std::vector<MshElement> &elements)
    {
      const long  n_blocks = count_on_next_line(in, 4);
      std::string line;
      for (long b = 0; b < n_blocks; ++b)
        {
          if (!next_line(in, line))
            return false;
          const auto header = numbers_on<long>(line);
          if (header.size() < 4)
            return false;
          for (long i = 0; i < header[3]; ++i)
            {
              if (!next_line(in, line))
                return false;
              const auto v = numbers_on<long>(line);
              if (v.empty())
                return false;
              if (header[2] != 2 && header[2] != 3)
                continue;
              MshElement element;
              element.number = v[0];
              element.type   = header[2];
              element.nodes.assign(v.begin() + 1, v.end());
              elements.push_back(element);
            }
        }
      return n_blocks >= 0;
    }
  } // namespace

  template <int dim>
  void
  GmshMesh<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Gmsh");
    prm.declare_entry("Mesh file",
                      "",
                      Patterns::Anything(),
                      "Path of a quadrilateral Gmsh .msh file (ASCII, format "
                      "2 or 4), relative to the working directory.");
    prm.declare_entry("Circular arcs",
                      "",
                      Patterns::Anything(),
                      "Boundary parts that are circular arcs, with their "
                      "centres: `name: x, y; name2: x, y` [length unit].");
    prm.declare_entry("Fault curves",
                      "",
                      Patterns::Anything(),
                      "Physical curves of the mesh that are faults (interior "
                      "lines; MSH format 2): each becomes a fault of that "
                      "name, with its interface law in `Faults`. An end "
                      "inside the mesh is a buried tip: the fault is "
                      "continued to the boundary along the mesh's edges, "
                      "as straight as they run, by a welded extension.");
    prm.declare_entry("Fault arc centres",
                      "",
                      Patterns::Anything(),
                      "Fault curves that are circular arcs, with their "
                      "centres: `name: x, y; name2: x, y` [length unit].");
    prm.declare_entry("Concentric arcs",
                      "",
                      Patterns::Anything(),
                      "Circles about one centre on which mesh lines lie, "
                      "inside the body or on its boundary: `x, y: r1, r2, "
                      "...` [length unit]. Every line whose two vertices lie "
                      "on one of them follows it under refinement (polar "
                      "manifold; its cells transfinite interpolation), as "
                      "the slab's layers of the subduction zone (§7.2) do.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  GmshMesh<dim>::parse_parameters(ParameterHandler &prm, const double s)
  {
    scale       = s;
    length_unit = prm.get("Length unit");
    prm.enter_subsection("Gmsh");
    mesh_file                           = prm.get("Mesh file");
    const std::string              text = prm.get("Circular arcs");
    const std::vector<std::string> fault_names =
      split_list(prm.get("Fault curves"));
    const std::string fault_arcs = prm.get("Fault arc centres");
    const std::string concentric = prm.get("Concentric arcs");
    prm.leave_subsection();
    if (mesh_file.empty())
      throw_input_error("Geometry/Gmsh/Mesh file", "is empty");
    if (!std::ifstream(mesh_file))
      throw_input_error("Geometry/Gmsh/Mesh file",
                        "cannot open the mesh file <" + mesh_file + ">");
    read_physical_names();
    arcs.clear();
    for (const std::string &item : split_list(text, ';'))
      {
        const auto colon = item.find(':');
        if (colon == std::string::npos)
          throw_input_error("Geometry/Gmsh/Circular arcs",
                            "<" + item + "> is not of the form name: x, y");
        const std::string name = Utilities::trim(item.substr(0, colon));
        if (boundary_names.count(name) == 0)
          throw_input_error("Geometry/Gmsh/Circular arcs",
                            "the mesh has no boundary part <" + name + ">");
        const auto centre = parse_point_list<dim>(item.substr(colon + 1),
                                                  "Geometry/Gmsh/Circular arcs",
                                                  scale);
        arcs.emplace_back(name, centre[0]);
      }

    faults.clear();
    fault_tags.clear();
    for (const std::string &name : fault_names)
      {
        if (boundary_names.count(name) == 0)
          throw_input_error("Geometry/Gmsh/Fault curves",
                            "the mesh has no physical curve <" + name + ">");
        FaultTrace trace;
        trace.name = name;
        faults.push_back(trace);
        fault_tags.insert(boundary_names.at(name));
      }
    std::map<std::string, Point<dim>> centres;
    for (const std::string &item : split_list(fault_arcs, ';'))
      {
        const auto colon = item.find(':');
        if (colon == std::string::npos)
          throw_input_error("Geometry/Gmsh/Fault arc centres",
                            "<" + item + "> is not of the form name: x, y");
        const std::string name = Utilities::trim(item.substr(0, colon));
        if (std::find(fault_names.begin(), fault_names.end(), name) ==
            fault_names.end())
          throw_input_error("Geometry/Gmsh/Fault arc centres",
                            "<" + name + "> is not one of the Fault curves");
        centres[name] = parse_point_list<dim>(item.substr(colon + 1),
                                              "Geometry/Gmsh/Fault arc centres",
                                              scale)[0];
      }
    read_file_cells();
    if (!faults.empty())
      read_fault_curves(centres);

    concentric_radii.clear();
    if (!Utilities::trim(concentric).empty())
      {
        const std::string entry = "Geometry/Gmsh/Concentric arcs";
        const auto        colon = concentric.find(':');
        if (colon == std::string::npos)
          throw_input_error(entry,
                            "<" + concentric +
                              "> is not of the form x, y: r1, r2, ...");
        concentric_centre =
          parse_point_list<dim>(concentric.substr(0, colon), entry, scale)[0];
        for (const std::string &r : split_list(concentric.substr(colon + 1)))
          {
            concentric_radii.push_back(parse_number(r, entry) * scale);
            if (!(concentric_radii.back() > 0))
              throw_input_error(entry, "radii must be positive");
          }
        if (concentric_radii.empty())
          throw_input_error(entry, "gives no radius");
      }
  }

  namespace
  {
    /** The nodes of the 2-node lines @p segments (over @p nodes) chained
     * into one unbranched open line from its upper end (the left one if
     * level) down; throws InputError naming @p what if they branch, close
     * or refer to a missing node. */
    std::vector<long>
    chain_segments(const std::vector<std::pair<long, long>> &segments,
                   const std::map<long, Point<2>>           &nodes,
                   const std::string                        &what)
    {
      const std::string entry = "Geometry/Gmsh/Fault curves";
      // Chain the segments: a single unbranched line from end to end.
      std::map<long, std::vector<long>> next;
      for (const auto &[a, b] : segments)
        {
          if (nodes.count(a) == 0 || nodes.count(b) == 0)
            throw_input_error(entry, what + " refers to a missing node");
          next[a].push_back(b);
          next[b].push_back(a);
        }
      std::vector<long> ends;
      for (const auto &[node, neighbours] : next)
        {
          if (neighbours.size() > 2)
            throw_input_error(entry, what + " branches at a node");
          if (neighbours.size() == 1)
            ends.push_back(node);
        }
      if (ends.size() != 2)
        throw_input_error(entry,
                          what + " is not one open line (it is closed or "
                                 "in pieces)");
      // From the upper end (the left one if level) down.
      const auto upper = [&](const long a, const long b) {
        const Point<2> &p = nodes.at(a), &q = nodes.at(b);
        return p[1] > q[1] || (p[1] == q[1] && p[0] < q[0]);
      };
      long              node     = upper(ends[0], ends[1]) ? ends[0] : ends[1];
      long              previous = -1;
      std::vector<long> chain    = {node};
      while (true)
        {
          long following = -1;
          for (const long n : next[node])
            if (n != previous)
              following = n;
          if (following < 0)
            break;
          previous = node;
          node     = following;
          chain.push_back(node);
        }
      return chain;
    }
  } // namespace

  template <int dim>
  void
  GmshMesh<dim>::read_fault_curves(
    const std::map<std::string, Point<dim>> &centres)
  {
    const std::string        entry = "Geometry/Gmsh/Fault curves";
    std::ifstream            in(mesh_file);
    std::string              line;
    std::map<long, Point<2>> nodes;
    std::map<int, std::vector<std::pair<long, long>>> lines;
    double                                            version = 0;
    while (std::getline(in, line))
      {
        line = Utilities::trim(line);
        if (line == "$MeshFormat")
          in >> version;
        else if (line == "$Nodes")
          {
            if (version >= 3)
              throw_input_error(entry,
                                "fault curves need a mesh file in MSH format "
                                "2 (<" +
                                  mesh_file +
                                  "> is format 4: export it with gmsh "
                                  "-format msh22)");
            long n = 0;
            in >> n;
            for (long i = 0; i < n; ++i)
              {
                long   id = 0;
                double x = 0, y = 0, z = 0;
                in >> id >> x >> y >> z;
                nodes[id] = Point<2>(x * scale, y * scale);
              }
          }
        else if (line == "$Elements")
          {
            long n = 0;
            in >> n;
            std::getline(in, line);
            for (long i = 0; i < n && std::getline(in, line); ++i)
              {
                std::istringstream element(line);
                long               id   = 0;
                int                type = 0, n_tags = 0, tag = 0;
                element >> id >> type >> n_tags;
                std::vector<int> tags(n_tags);
                for (int &t : tags)
                  element >> t;
                if (n_tags > 0)
                  tag = tags[0];
                if (fault_tags.count(tag) == 0)
                  continue;
                if (type != 1)
                  throw_input_error(entry,
                                    "the fault curves must be 2-node lines "
                                    "(Gmsh element type 1), element " +
                                      std::to_string(id) + " has type " +
                                      std::to_string(type));
                long a = 0, b = 0;
                element >> a >> b;
                lines[tag].emplace_back(a, b);
              }
          }
      }
    // Ends inside the mesh: welded extensions to the boundary along its
    // edges, clear of every fault curve.
    const MeshEdges edges = mesh_edges();
    std::set<long>  avoid;
    for (const auto &[tag, tag_segments] : lines)
      for (const auto &[a, b] : tag_segments)
        avoid.insert({a, b});
    for (FaultTrace &fault : faults)
      {
        const auto       &segments = lines[boundary_names.at(fault.name)];
        const std::string what     = "the physical curve <" + fault.name + ">";
        if (segments.empty())
          throw_input_error(entry, what + " has no line elements");
        const std::vector<long> chain = chain_segments(segments, nodes, what);
        if (chain.size() != segments.size() + 1)
          throw_input_error(entry,
                            what + " is not one open line (it is in pieces)");
        const std::vector<long>
          up   = extension_to_boundary(edges, chain, true, avoid, what),
          down = extension_to_boundary(edges, chain, false, avoid, what);
        std::vector<Point<2>> vertices;
        for (auto n = up.rbegin(); n != up.rend(); ++n)
          vertices.push_back(nodes[*n]);
        for (const long n : chain)
          vertices.push_back(nodes[n]);
        for (const long n : down)
          vertices.push_back(nodes[n]);
        if (centres.count(fault.name) != 0 && (!up.empty() || !down.empty()))
          throw_input_error("Geometry/Gmsh/Fault arc centres",
                            "the curved fault <" + fault.name +
                              "> must run from boundary to boundary (a "
                              "buried tip needs a straight-sided fault)");
        const auto centre = centres.find(fault.name);
        Point<2>   c;
        if (centre != centres.end())
          {
            c               = Point<2>(centre->second[0], centre->second[1]);
            const double r0 = vertices.front().distance(c);
            for (const Point<2> &v : vertices)
              if (std::abs(v.distance(c) - r0) > 1e-6 * r0)
                throw_input_error("Geometry/Gmsh/Fault arc centres",
                                  "the vertices of <" + fault.name +
                                    "> are not on one circle about this "
                                    "centre");
          }
        fault.set_polyline(vertices, centre != centres.end(), c);
        const auto length = [&](const unsigned int from,
                                const unsigned int to) {
          double l = 0;
          for (unsigned int i = from; i < to; ++i)
            l += vertices[i].distance(vertices[i + 1]);
          return l;
        };
        fault.begin_s = length(0, up.size());
        if (!down.empty())
          fault.end_s = length(0, up.size() + chain.size() - 1);
      }
  }

  template <int dim>
  typename GmshMesh<dim>::MeshEdges
  GmshMesh<dim>::mesh_edges() const
  {
    MeshEdges                            edges;
    std::map<std::pair<long, long>, int> cells_at_edge;
    for (const FileCell &cell : file_cells)
      if (cell.checkable)
        for (unsigned int v = 0; v < 4; ++v)
          {
            const long a = cell.nodes[v], b = cell.nodes[(v + 1) % 4];
            edges.next[a].insert(b);
            edges.next[b].insert(a);
            ++cells_at_edge[std::minmax(a, b)];
            edges.position[a] = cell.corners[v];
          }
    for (const auto &[edge, count] : cells_at_edge)
      if (count == 1)
        edges.boundary.insert({edge.first, edge.second});
    return edges;
  }

  template <int dim>
  std::vector<long>
  GmshMesh<dim>::extension_to_boundary(const MeshEdges         &edges,
                                       const std::vector<long> &chain,
                                       const bool               upper,
                                       const std::set<long>    &avoid,
                                       const std::string       &what) const
  {
    const auto &[next, boundary, position] = edges;
    long node = upper ? chain.front() : chain.back();
    if (next.count(node) == 0 || boundary.count(node) != 0)
      return {};
    const long   from    = upper ? chain[1] : chain[chain.size() - 2];
    Tensor<1, 2> heading = position.at(node) - position.at(from);
    // Onwards along the edge that turns least, until the boundary.
    std::vector<long> extension;
    std::set<long>    visited(chain.begin(), chain.end());
    while (boundary.count(node) == 0)
      {
        long   best        = -1;
        double straightest = 0.5;
        for (const long n : next.at(node))
          {
            if (visited.count(n) != 0 || avoid.count(n) != 0)
              continue;
            const Tensor<1, 2> step = position.at(n) - position.at(node);
            const double       cosine =
              step * heading / (step.norm() * heading.norm());
            if (cosine > straightest)
              {
                straightest = cosine;
                best        = n;
              }
          }
        if (best < 0)
          {
            std::ostringstream where;
            where << what << "'s " << (upper ? "upper" : "lower") << " end at ("
                  << position.at(node) / scale
                  << ") lies inside the mesh, and the mesh has no edges that "
                     "continue the fault to the boundary (within 60 degrees "
                     "of its direction, clear of other faults): add them, or "
                     "draw the fault to the boundary";
            throw_input_error("Geometry/Gmsh/Fault curves", where.str());
          }
        heading = position.at(best) - position.at(node);
        visited.insert(best);
        extension.push_back(best);
        node = best;
      }
    return extension;
  }

  template <int dim>
  std::string
  GmshMesh<dim>::text_without_fault_lines() const
  {
    std::ifstream      in(mesh_file);
    std::ostringstream out;
    std::string        line;
    while (std::getline(in, line))
      {
        out << line << '\n';
        if (Utilities::trim(line) != "$Elements")
          continue;
        long n = 0;
        std::getline(in, line);
        n = std::stol(line);
        std::vector<std::string> kept;
        for (long i = 0; i < n && std::getline(in, line); ++i)
          {
            std::istringstream element(line);
            long               id   = 0;
            int                type = 0, n_tags = 0, tag = -1;
            element >> id >> type >> n_tags;
            if (n_tags > 0)
              element >> tag;
            if (!(type == 1 && fault_tags.count(tag) != 0))
              kept.push_back(line);
          }
        out << kept.size() << '\n';
        for (const std::string &k : kept)
          out << k << '\n';
      }
    return out.str();
  }

  template <int dim>
  std::vector<FaultTrace>
  GmshMesh<dim>::fault_traces() const
  {
    return faults;
  }

  template <int dim>
  void
  GmshMesh<dim>::read_physical_names()
  {
    boundary_names.clear();
    region_names.clear();
    std::ifstream in(mesh_file);
    std::string   line;
    while (std::getline(in, line))
      if (Utilities::trim(line) == "$PhysicalNames")
        {
          unsigned int n = 0;
          in >> n;
          for (unsigned int i = 0; i < n; ++i)
            {
              int         group_dim = 0, tag = 0;
              std::string name;
              in >> group_dim >> tag;
              std::getline(in, name);
              name = Utilities::trim(name);
              if (name.size() >= 2 && name.front() == '"')
                name = name.substr(1, name.size() - 2);
              if (group_dim == dim)
                region_names[name] = tag;
              else if (group_dim == dim - 1)
                boundary_names[name] = tag;
            }
          break;
        }
  }

  template <int dim>
  void
  GmshMesh<dim>::read_file_cells()
  {
    file_cells.clear();
    std::ifstream            in(mesh_file);
    std::string              line;
    double                   version = 0;
    std::map<long, Point<2>> nodes;
    std::vector<MshElement>  elements;
    bool                     complete = true;
    while (complete && std::getline(in, line))
      {
        line = Utilities::trim(line);
        if (line == "$MeshFormat" && std::getline(in, line))
          std::istringstream(line) >> version;
        else if (line == "$Nodes")
          complete = (version >= 2 && version < 3) ? read_msh2_nodes(in, nodes)
                     : version == 4.1              ? read_msh41_nodes(in, nodes)
                                                   : false;
        else if (line == "$Elements")
          complete = (version >= 2 && version < 3)
                       ? read_msh2_elements(in, elements)
                     : version == 4.1 ? read_msh41_elements(in, elements)
                                      : false;
      }
    if (!complete)
      return;
    for (const MshElement &element : elements)
      {
        FileCell cell;
        cell.number    = element.number;
        cell.checkable = element.type == 3 && element.nodes.size() == 4;
        for (unsigned int v = 0; v < element.nodes.size() && cell.checkable;
             ++v)
          {
            const auto node = nodes.find(element.nodes[v]);
            cell.checkable  = node != nodes.end();
            cell.nodes[v]   = element.nodes[v];
            if (cell.checkable)
              cell.corners[v] =
                Point<2>(node->second[0] * scale, node->second[1] * scale);
          }
        file_cells.push_back(cell);
      }
  }

  template <int dim>
  void
  GmshMesh<dim>::check_sections() const
  {
    std::ifstream            text(mesh_file);
    std::string              line;
    std::vector<std::string> open_sections;
    unsigned int             number = 0;
    while (std::getline(text, line))
      {
        ++number;
        line = Utilities::trim(line);
        if (line.size() < 2 || line[0] != '$')
          continue;
        if (line.compare(0, 4, "$End") == 0)
          {
            if (open_sections.empty() || open_sections.back() != line.substr(4))
              throw_input_error("Geometry/Gmsh/Mesh file",
                                "<" + mesh_file + ">: line " +
                                  std::to_string(number) + " (" + line +
                                  ") closes a section that is not open");
            open_sections.pop_back();
          }
        else
          open_sections.push_back(line.substr(1));
      }
    if (!open_sections.empty())
      throw_input_error("Geometry/Gmsh/Mesh file",
                        "<" + mesh_file + "> is truncated: its $" +
                          open_sections.back() + " section has no $End" +
                          open_sections.back() + " (the file ends at line " +
                          std::to_string(number) + ")");
  }

  template <int dim>
  void
  GmshMesh<dim>::check_element_shapes() const
  {
    std::vector<Quadrilateral>       cells;
    std::vector<std::array<long, 4>> nodes;
    std::vector<unsigned int>        index;
    for (unsigned int i = 0; i < file_cells.size(); ++i)
      if (file_cells[i].checkable)
        {
          cells.push_back(file_cells[i].corners);
          nodes.push_back(file_cells[i].nodes);
          index.push_back(i);
        }
    check_quadrilaterals(cells,
                         nodes,
                         mesh_entry(),
                         scale,
                         length_unit,
                         [&](const unsigned int i) {
                           return cell_name(index[i]);
                         });
  }

  template <int dim>
  void
  GmshMesh<dim>::read_triangulation(
    parallel::distributed::Triangulation<dim> &tria) const
  {
    // Same mesh smoothing: copy_triangulation() takes it from the copy.
    Triangulation<dim> serial(tria.get_mesh_smoothing());
    GridIn<dim>        grid_in;
    grid_in.attach_triangulation(serial);
    std::ifstream      file(mesh_file);
    std::istringstream filtered(faults.empty() ? std::string()
                                               : text_without_fault_lines());
    std::istream      &in =
      faults.empty() ? static_cast<std::istream &>(file) : filtered;
    try
      {
        grid_in.read_msh(in);
      }
    catch (const ExceptionBase &exc)
      {
        throw_input_error("Geometry/Gmsh/Mesh file",
                          "cannot read <" + mesh_file +
                            ">: " + one_line_message(exc));
      }
    if (!serial.all_reference_cells_are_hyper_cube())
      throw_input_error("Geometry/Gmsh/Mesh file",
                        "<" + mesh_file +
                          "> has triangles; lithostress needs quadrilaterals "
                          "(use Recombine in Gmsh)");
    if (scale != 1.0)
      GridTools::scale(scale, serial);
    tria.copy_triangulation(serial);
  }

  template <int dim>
  void
  GmshMesh<dim>::attach_boundary_arcs(
    parallel::distributed::Triangulation<dim> &tria) const
  {
    for (unsigned int k = 0; k < arcs.size(); ++k)
      {
        const types::boundary_id b       = boundary_names.at(arcs[k].first);
        const types::manifold_id arc_id  = 2 * k + 1;
        const types::manifold_id cell_id = 2 * k + 2;
        for (const auto &cell : tria.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && face->boundary_id() == b)
              {
                cell->set_manifold_id(cell_id);
                for (const auto &f : cell->face_iterators())
                  if (f->manifold_id() == numbers::flat_manifold_id)
                    f->set_manifold_id(cell_id);
                face->set_manifold_id(arc_id);
              }
        tria.set_manifold(arc_id, PolarManifold<dim>(arcs[k].second));
      }
  }

  template <int dim>
  void
  GmshMesh<dim>::attach_fault_arcs(
    parallel::distributed::Triangulation<dim> &tria) const
  {
    for (unsigned int j = 0; j < faults.size(); ++j)
      {
        const FaultTrace &fault = faults[j];
        if (!fault.has_arc)
          continue;
        const types::manifold_id arc_id    = 2 * (arcs.size() + j) + 1;
        const types::manifold_id cell_id   = arc_id + 1;
        const double             tolerance = 1e-9 * fault.arc_radius;
        for (const auto &cell : tria.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (!face->at_boundary() &&
                fault.distance_to(Point<2>(face->vertex(0)[0],
                                           face->vertex(0)[1])) < tolerance &&
                fault.distance_to(
                  Point<2>(face->vertex(1)[0], face->vertex(1)[1])) < tolerance)
              {
                cell->set_manifold_id(cell_id);
                for (const auto &f : cell->face_iterators())
                  if (f->manifold_id() == numbers::flat_manifold_id)
                    f->set_manifold_id(cell_id);
                face->set_manifold_id(arc_id);
              }
        Point<dim> centre;
        centre[0] = fault.arc_centre[0];
        centre[1] = fault.arc_centre[1];
        tria.set_manifold(arc_id, PolarManifold<dim>(centre));
      }
  }

  template <int dim>
  void
  GmshMesh<dim>::attach_concentric_arcs(
    parallel::distributed::Triangulation<dim> &tria) const
  {
    if (concentric_radii.empty())
      return;
    const types::manifold_id concentric_id =
      2 * (arcs.size() + faults.size()) + 1;
    const auto on_a_circle = [&](const auto &face) {
      const double r0 = face->vertex(0).distance(concentric_centre),
                   r1 = face->vertex(1).distance(concentric_centre);
      for (const double r : concentric_radii)
        if (std::abs(r0 - r) < 1e-9 * r && std::abs(r1 - r) < 1e-9 * r)
          return true;
      return false;
    };
    unsigned int n_lines = 0;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (on_a_circle(face))
          {
            // Its cell's other lines, flat or on another transfinite
            // interpolation (even ids), follow this one's.
            cell->set_manifold_id(concentric_id + 1);
            for (const auto &f : cell->face_iterators())
              if (f->manifold_id() == numbers::flat_manifold_id ||
                  f->manifold_id() % 2 == 0)
                f->set_manifold_id(concentric_id + 1);
            face->set_manifold_id(concentric_id);
            ++n_lines;
          }
    if (n_lines == 0)
      throw_input_error("Geometry/Gmsh/Concentric arcs",
                        "no line of the mesh lies on these circles");
    tria.set_manifold(concentric_id, PolarManifold<dim>(concentric_centre));
  }

  template <int dim>
  void
  GmshMesh<dim>::attach_transfinite_interpolation(
    parallel::distributed::Triangulation<dim> &tria) const
  {
    for (unsigned int k = 0; k < arcs.size(); ++k)
      {
        TransfiniteInterpolationManifold<dim> transfinite;
        transfinite.initialize(tria);
        tria.set_manifold(2 * k + 2, transfinite);
      }
    for (unsigned int j = 0; j < faults.size(); ++j)
      if (faults[j].has_arc)
        {
          TransfiniteInterpolationManifold<dim> transfinite;
          transfinite.initialize(tria);
          tria.set_manifold(2 * (arcs.size() + j) + 2, transfinite);
        }
    if (!concentric_radii.empty())
      {
        TransfiniteInterpolationManifold<dim> transfinite;
        transfinite.initialize(tria);
        tria.set_manifold(2 * (arcs.size() + faults.size()) + 2, transfinite);
      }
  }

  template <int dim>
  void
  GmshMesh<dim>::create_coarse_mesh(
    parallel::distributed::Triangulation<dim> &tria) const
  {
    // Every $Section must end: a file cut off (a copy or a mesher that
    // stopped half-way) is named as such, not by what the reader trips on.
    check_sections();
    check_element_shapes();
    read_triangulation(tria);
    // Manifolds: boundary arcs, curved faults, concentric circles, in
    // this order of ids; the transfinite interpolations of their cells
    // once every id is set.
    attach_boundary_arcs(tria);
    attach_fault_arcs(tria);
    attach_concentric_arcs(tria);
    attach_transfinite_interpolation(tria);
  }

  template <int dim>
  std::string
  GmshMesh<dim>::mesh_entry() const
  {
    return "Geometry/Gmsh/Mesh file";
  }

  template <int dim>
  std::string
  GmshMesh<dim>::cell_name(const unsigned int index) const
  {
    if (index < file_cells.size())
      return "<" + mesh_file + ">: element " +
             std::to_string(file_cells[index].number);
    return GeometryModel<dim>::cell_name(index);
  }

  template <int dim>
  std::map<std::string, types::boundary_id>
  GmshMesh<dim>::boundary_parts() const
  {
    std::map<std::string, types::boundary_id> parts;
    for (const auto &[name, id] : boundary_names)
      if (fault_tags.count(id) == 0)
        parts[name] = id;
    return parts;
  }

  template <int dim>
  std::map<std::string, types::material_id>
  GmshMesh<dim>::named_regions() const
  {
    return region_names;
  }

  template class GmshMesh<2>;

  LITHOSTRESS_REGISTER_GEOMETRY(
    GmshMesh,
    "gmsh",
    "a Gmsh mesh with physical groups as parts, regions and faults")
} // namespace lithostress
