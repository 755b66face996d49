#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <hati/model/frame.h>
#include <hati/model/frame_solids.h>
#include <hati/model/memory_estimate.h>
#include <hati/model/solid_cuts.h>
#include <hati/model/solid_tie.h>

#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace hati
{
namespace
{

/** The name of every member of @p frame, in order. */
std::vector<std::string> member_names(const FrameDescription &frame)
{
  std::vector<std::string> names;
  for (const auto &m : frame.members)
    names.push_back(m.name);
  return names;
}

/** The name of every cut of a solid of @p frame, in order. */
std::vector<std::string> cut_names(const FrameDescription &frame)
{
  std::vector<std::string> names;
  for (const auto &c : frame.solids.cuts)
    names.push_back(c.name);
  return names;
}

/** @p frame, after FrameDescription::validate() accepted it. */
const FrameDescription &validated(const FrameDescription &frame)
{
  frame.validate();
  return frame;
}
} // namespace

struct Frame::MeshLayout
{
  std::vector<Point<3>> vertices;
  std::vector<CellData<1>> cell_data;
  /** The vertices of every named node, in member order. */
  std::map<std::string, std::vector<unsigned int>> node_vertices;
  /** Per cell: (member, element), its first vertex, its position along the member. */
  std::vector<std::pair<unsigned int, unsigned int>> cell_member;
  std::vector<unsigned int> cell_start;
  std::vector<double> cell_position;
};

Frame::Frame(const FrameDescription &description)
    : frame(validated(description)), fe(FE_Q<1, 3>(1), 6),
      section_force_output(member_names(description),
                           description.section_force_members,
                           cut_names(description)),
      beam_stresses(member_names(description), stressed_member_sections(frame))
{
}

Frame::~Frame() = default;

void Frame::select_part(const std::vector<unsigned char> &parts, const int part)
{
  Model::select_part(parts, part);
  // each link eliminated, rows of the explicit part, or across the interface
  if (!links.empty() && triangulation.n_active_cells() > 0)
  {
    place_links(part);
    close_constraints();
  }
}

bool Frame::node_explicit(const std::string &node) const
{
  if (parts.empty())
    return false;
  for (const unsigned int c : node_cells.at(node))
    if (parts[c] == 0)
      return true;
  return false;
}

void Frame::close_constraints()
{
  constraints.clear();
  constraints.copy_from(open_constraints);
  for (unsigned int k = 0; k < links.size(); ++k)
  {
    // bilateral rows of the explicit scheme (add_link_rows()); across the
    // interface of a decomposed model (interface_rows()); eliminated otherwise
    if (links_as_rows || (k < link_sides.size() && link_sides[k] != LinkSide::eliminated))
      continue;
    for (unsigned int c = 0; c < 6; ++c)
      AssertThrow(!constraints.is_constrained(links[k].slave[c]),
                  ExcMessage("Model/Frame/Ties, Rigid links: '" + links[k].name +
                             "': its node is already held (a support, a tie or the slave "
                             "of a rigid link)"));
    add_constraint_lines(links[k], constraints);
  }
  constraints.close();
}

void Frame::create_mesh()
{
  const auto &P = frame;
  {
    // refuse before allocating: 6 DoFs per vertex, 3 blocks of 6 x 6 per row
    double n_cells = 0.;
    for (const auto &member : P.members)
      n_cells += member.n_elements;
    const double n_vertices = n_cells + P.members.size();
    check_memory_estimate(
        "Model/Frame/Members", n_cells, 6. * n_vertices, 108. * n_vertices);
  }
  // every member its own vertices; remember the end vertices at each node
  MeshLayout layout;
  for (unsigned int m = 0; m < P.members.size(); ++m)
  {
    const auto &member = P.members[m];
    auto &vertices = layout.vertices;
    const unsigned int base = vertices.size();
    if (member.path.empty())
    {
      const Point<3> x1 = P.nodes.at(member.start), x2 = P.nodes.at(member.end);
      for (unsigned int i = 0; i <= member.n_elements; ++i)
        vertices.push_back(x1 + (x2 - x1) * (double(i) / member.n_elements));
      layout.node_vertices[member.start].push_back(base);
      layout.node_vertices[member.end].push_back(base + member.n_elements);
    }
    else // from a mesh file: every node along the member may be a joint
      for (unsigned int i = 0; i < member.path.size(); ++i)
      {
        vertices.push_back(P.nodes.at(member.path[i]));
        layout.node_vertices[member.path[i]].push_back(base + i);
      }
    double position = 0.;
    for (unsigned int i = 0; i < member.n_elements; ++i)
    {
      CellData<1> c;
      c.vertices = {base + i, base + i + 1};
      c.material_id = m;
      layout.cell_data.push_back(c);
      layout.cell_member.emplace_back(m, i);
      layout.cell_start.push_back(base + i);
      layout.cell_position.push_back(position);
      position += vertices[base + i].distance(vertices[base + i + 1]);
    }
  }
  triangulation.create_triangulation(layout.vertices, layout.cell_data, SubCellData());
  dof_handler.reinit(triangulation);
  dof_handler.distribute_dofs(fe);

  std::vector<std::vector<unsigned int>> vertex_cells;
  set_up_cells(layout, vertex_cells);
  set_up_constraints(layout, vertex_cells);
}

void Frame::set_up_cells(const MeshLayout &layout,
                         std::vector<std::vector<unsigned int>> &vertex_cells)
{
  const auto &P = frame;
  // DoFs of every vertex, and the cells in creation order
  vertex_dofs.assign(layout.vertices.size(), {});
  vertex_cells.assign(layout.vertices.size(), {});
  cells.clear();
  for (const auto &cell : dof_handler.active_cell_iterators())
  {
    FrameCell info;
    std::tie(info.member, info.element) = layout.cell_member[cell->active_cell_index()];
    const auto &member = P.members[info.member];
    // local x from the member's start to its end, whatever the cell's orientation
    const unsigned int first =
        cell->vertex_index(0) == layout.cell_start[cell->active_cell_index()] ? 0 : 1;
    info.position = layout.cell_position[cell->active_cell_index()];
    for (unsigned int v = 0; v < 2; ++v)
      vertex_cells[cell->vertex_index(v)].push_back(cell->active_cell_index());
    for (unsigned int v = 0; v < 2; ++v)
      for (unsigned int c = 0; c < 6; ++c)
      {
        vertex_dofs[cell->vertex_index(v)][c] = cell->vertex_dof_index(v, c);
        info.dofs[6 * (v == first ? 0 : 1) + c] = cell->vertex_dof_index(v, c);
      }
    Tensor<1, 3> y_ref = member.y_reference;
    const Tensor<1, 3> axis = cell->vertex(1) - cell->vertex(0);
    if (y_ref.norm() == 0.)
    {
      y_ref[1] = 1.;
      if (std::abs(axis[1]) > (1. - 1e-9) * axis.norm())
        y_ref = Tensor<1, 3>({1., 0., 0.});
    }
    info.length = cell->vertex(0).distance(cell->vertex(1));
    try
    {
      info.rotation = frame_rotation(cell->vertex(first), cell->vertex(1 - first), y_ref);
    }
    catch (const std::exception &)
    {
      AssertThrow(
          false,
          ExcMessage("Model/Frame/Members: member '" + member.name +
                     "': its section orientation vector is parallel to the member"));
    }
    const FrameSection &section = P.sections.at(member.section);
    const FrameMaterial &material = P.materials.at(member.material);
    info.stiffness = local_stiffness(info.length, section, material);
    info.mass = local_consistent_mass(info.length, section, material);
    cells.push_back(info);
  }
}

void Frame::set_up_constraints(const MeshLayout &layout,
                               const std::vector<std::vector<unsigned int>> &vertex_cells)
{
  constraints.clear();
  node_dofs.clear();
  node_cells.clear();
  for (const auto &[node, list] : layout.node_vertices)
    for (const unsigned int v : list)
      node_cells[node].insert(
          node_cells[node].end(), vertex_cells[v].begin(), vertex_cells[v].end());
  const std::set<std::string> hinged(frame.hinged_joints.begin(),
                                     frame.hinged_joints.end());
  for (const auto &[node, list] : layout.node_vertices)
  {
    node_dofs[node] = vertex_dofs[list[0]];
    for (unsigned int k = 1; k < list.size(); ++k)
      for (unsigned int c = 0; c < (hinged.count(node) ? 3u : 6u); ++c)
      {
        const auto slave = vertex_dofs[list[k]][c], master = vertex_dofs[list[0]][c];
        constraints.add_line(slave);
        constraints.add_entry(slave, master, 1.);
      }
  }
  for (const auto &s : frame.supports)
    for (unsigned int c = 0; c < 6; ++c)
      if (s.stiffness[c] == 0. && !constraints.is_constrained(node_dofs[s.node][c]))
        constraints.add_line(node_dofs[s.node][c]);
  // the nodes only a rope holds: six DoFs each after the mesh's, their
  // data owned with the rope's hook point; the solids' DoFs after them
  n_mesh_dofs = dof_handler.n_dofs();
  n_beam_dofs = n_mesh_dofs + 6 * frame.rope_only_nodes().size();
  add_link_constraints();
  close_constraints();
  types::global_dof_index next = n_mesh_dofs;
  for (const auto &node : frame.rope_only_nodes())
  {
    for (unsigned int c = 0; c < 6; ++c)
      node_dofs[node][c] = next++;
    for (const auto &r : frame.ropes)
      if (r.other_node == node)
      {
        node_cells[node] = node_cells.at(r.node);
        break;
      }
  }
}

void Frame::add_link_constraints()
{
  links.clear();
  link_nodes.clear();
  link_sides.clear();
  for (const auto &l : frame.solids.rigid_links)
  {
    links.push_back({l.name,
                     node_dofs.at(l.slave),
                     rigid_link_rows(node_dofs.at(l.master),
                                     frame.nodes.at(l.master),
                                     frame.nodes.at(l.slave))});
    link_nodes.push_back(l.slave);
  }
  if (!frame.solids.empty())
  {
    solids = std::make_unique<FrameSolids>(frame, n_beam_dofs);
    solids->add_supports(constraints);
    for (auto &tie : solids->ties(node_dofs))
      links.push_back(std::move(tie));
    for (const auto &tie : frame.solids.ties)
      link_nodes.push_back(tie.node);
  }
  // the joints and supports; the links are added per subdomain (close_constraints())
  open_constraints.clear();
  open_constraints.copy_from(constraints);
}

std::vector<bool> Frame::excited_members(const CommonModelParameters &common) const
{
  const auto &P = frame;
  std::vector<bool> excited(P.members.size(), common.excited_members.empty());
  for (const auto &name : common.excited_members)
  {
    unsigned int m = 0;
    while (m < P.members.size() && P.members[m].name != name)
      ++m;
    AssertThrow(m < P.members.size(),
                ExcMessage("Loading/Excited members: no member named '" + name + "'"));
    excited[m] = true;
  }
  return excited;
}

bool Frame::node_excited(const std::string &node, const std::vector<bool> &excited) const
{
  for (const unsigned int c : node_cells.at(node))
    if (excited[cells[c].member])
      return true;
  return false;
}

void Frame::build(const CommonModelParameters &common, DiscreteSystem &system)
{
  gravity = common.gravity;

  if (triangulation.n_active_cells() == 0)
  {
    links_as_rows = common.links_as_rows;
    create_mesh();
  }
  const unsigned int n = n_beam_dofs + (solids ? solids->n_dofs() : 0);
  system.reinit(n);

  make_pattern(system);
  system.stiffness.reinit(system.stiffness_pattern);
  system.consistent_mass.reinit(system.stiffness_pattern);

  for (auto &mi : system.mass_influence)
    mi.reinit(n);
  // base excitation on some members only (Loading/Excited members)
  const std::vector<bool> excited = excited_members(common);
  const bool restricted = !common.excited_members.empty();
  if (restricted)
  {
    for (auto &mi : system.excited_mass_influence)
      mi.reinit(n);
    system.excited_lumped_mass.reinit(n);
  }
  double omega2 = 0.;
  double mass = 0.; // of the part built
  assemble_cells(excited, restricted, system, omega2, mass);
  if (solids)
  {
    AssertThrow(!restricted,
                ExcMessage("Loading/Excited members: not available for a frame with "
                           "solids (the whole model is excited)"));
    // in a decomposed model, the solid cells of the part (after the beams'
    // in parts, cell_centres())
    std::vector<bool> owned;
    if (selected_part >= 0)
      for (unsigned int c = triangulation.n_active_cells(); c < parts.size(); ++c)
        owned.push_back(parts[c] == selected_part);
    solids->assemble(constraints, system, omega2, mass, owned);
    if (frame.solids.degree == 1)
      system.warnings.push_back(
          "Model/Frame/Solid element degree = 1: linear hexahedra lock in bending (a "
          "plate one element thick gives about 1/3 of its deflection); use 2");
  }
  if (!links.empty() && !links_as_rows)
    system.lumped_mass_refusal =
        "Model/Frame/Ties, Rigid links: eliminated as constraints, which a lumped "
        "(diagonal) mass cannot carry: use Method = CD-Lagrange (bilateral rows) or "
        "Newmark with Mass = consistent";
  const std::vector<double> spring = add_springs(system);
  add_point_masses(excited, restricted, system);
  for (const auto &p : frame.point_masses)
    if (owns_node(node_cells.at(p.node)))
      mass += p.mass;
  if (selected_part < 0)
    total_mass = mass;

  for (unsigned int i = 0; i < n; ++i)
    system.fixed[i] = held(i);

  // critical step bound: elements, plus the springs (Weyl's inequality:
  // lambda_max(M^-1 (K_e + K_s)) <= element bound + max k_i / m_i), plus
  // the ropes (R1: a bar of stiffness k between the two masses)
  double spring_bound = 0.;
  for (unsigned int i = 0; i < n; ++i)
    if (spring[i] > 0. && !system.fixed[i])
      spring_bound = std::max(spring_bound, spring[i] / system.lumped_mass[i]);
  const double rope_bound = add_ropes(system);
  system.omega_max_bound = std::sqrt(omega2 + spring_bound + rope_bound);

  add_loads(common, system);
  add_contacts(common, system);
  add_flanges(system);
  add_link_rows(system);
  add_monitors(system);
}

void Frame::assemble_cells(const std::vector<bool> &excited,
                           const bool restricted,
                           DiscreteSystem &system,
                           double &omega2,
                           double &mass) const
{
  FullMatrix<double> kg(12, 12), mg(12, 12);
  Vector<double> lumped_cell(12), mass_influence_cell(12);
  std::vector<types::global_dof_index> dofs(12);
  for (unsigned int c = 0; c < cells.size(); ++c)
  {
    if (!cell_selected(c))
      continue;
    const auto &info = cells[c];
    const auto &member = frame.members[info.member];
    const FrameSection &section = frame.sections.at(member.section);
    const FrameMaterial &material = frame.materials.at(member.material);
    kg = to_global(local_stiffness(info.length, section, material), info.rotation);
    mg = to_global(local_consistent_mass(info.length, section, material), info.rotation);
    // lumped: diagonal of T^T D T, so that it stays diagonal in global axes
    const auto &R = info.rotation;
    const auto D = local_lumped_mass(info.length, section, material);
    for (unsigned int b = 0; b < 4; ++b)
      for (unsigned int i = 0; i < 3; ++i)
      {
        double d = 0.;
        for (unsigned int k = 0; k < 3; ++k)
          d += R[k][i] * R[k][i] * D[3 * b + k];
        lumped_cell[3 * b + i] = d;
      }
    std::copy(info.dofs.begin(), info.dofs.end(), dofs.begin());
    constraints.distribute_local_to_global(kg, dofs, system.stiffness);
    constraints.distribute_local_to_global(mg, dofs, system.consistent_mass);
    constraints.distribute_local_to_global(lumped_cell, dofs, system.lumped_mass);
    // M r_d element by element, so that the inertia coupled to supported
    // DoFs is kept (the condensed matrix has lost it)
    for (unsigned int d = 0; d < 3; ++d)
    {
      for (unsigned int i = 0; i < 12; ++i)
        mass_influence_cell[i] = mg(i, d) + mg(i, 6 + d);
      constraints.distribute_local_to_global(
          mass_influence_cell, dofs, system.mass_influence[d]);
      if (restricted && excited[info.member])
        constraints.distribute_local_to_global(
            mass_influence_cell, dofs, system.excited_mass_influence[d]);
    }
    if (restricted && excited[info.member])
      constraints.distribute_local_to_global(
          lumped_cell, dofs, system.excited_lumped_mass);
    // an element whose every DoF is held at zero (a support; not the
    // slaves of a link, which move) never vibrates: left out of the bound
    bool clamped = true;
    for (const auto i : info.dofs)
    {
      const auto *entries = constraints.get_constraint_entries(i);
      clamped = clamped && constraints.is_constrained(i) &&
                (entries == nullptr || entries->empty());
    }
    if (!clamped)
      omega2 =
          std::max(omega2,
                   element_omega_squared(
                       kg, std::vector<double>(lumped_cell.begin(), lumped_cell.end())));
    mass += material.rho * section.A * info.length;
  }
}

void Frame::make_pattern(DiscreteSystem &system) const
{
  const unsigned int n = system.n_dofs();
  DynamicSparsityPattern dsp(n, n);
  if (solids)
  {
    // the ties couple the beam nodes to solid DoFs: condense cell by cell
    std::vector<types::global_dof_index> dofs(12);
    for (const auto &cell : cells)
    {
      std::copy(cell.dofs.begin(), cell.dofs.end(), dofs.begin());
      constraints.add_entries_local_to_global(dofs, dsp, false);
    }
    solids->add_pattern(constraints, dsp);
  }
  else
  {
    DynamicSparsityPattern mesh(n_mesh_dofs, n_mesh_dofs);
    DoFTools::make_sparsity_pattern(dof_handler, mesh, constraints, false);
    if (frame.ropes.empty())
    {
      system.stiffness_pattern.copy_from(mesh);
      return;
    }
    for (unsigned int i = 0; i < n_mesh_dofs; ++i)
      for (auto it = mesh.begin(i); it != mesh.end(i); ++it)
        dsp.add(i, it->column());
  }
  // with ropes: the DoFs of the rope-only nodes (their diagonal) and the
  // couplings of each rope's translations (its tangent, R1)
  for (unsigned int i = n_mesh_dofs; i < n_beam_dofs; ++i)
    dsp.add(i, i);
  for (const auto &r : frame.ropes)
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        for (const auto &[p, q] : {std::make_pair(r.node, r.other_node),
                                   std::make_pair(r.other_node, r.node),
                                   std::make_pair(r.node, r.node),
                                   std::make_pair(r.other_node, r.other_node)})
          dsp.add(node_dofs.at(p)[a], node_dofs.at(q)[b]);
  system.stiffness_pattern.copy_from(dsp);
}

double Frame::add_ropes(DiscreteSystem &system) const
{
  for (const auto &r : frame.ropes)
  {
    std::vector<unsigned int> rope_cells = node_cells.at(r.node);
    rope_cells.insert(rope_cells.end(),
                      node_cells.at(r.other_node).begin(),
                      node_cells.at(r.other_node).end());
    if (!owns_node(rope_cells))
      continue;
    Rope rope;
    rope.name = r.name;
    for (unsigned int d = 0; d < 3; ++d)
    {
      const auto h = node_dofs.at(r.node)[d], p = node_dofs.at(r.other_node)[d];
      rope.hook_dofs[d] = held(h) ? numbers::invalid_dof_index : h;
      rope.load_dofs[d] = held(p) ? numbers::invalid_dof_index : p;
    }
    rope.reference_chord = frame.nodes.at(r.other_node) - frame.nodes.at(r.node);
    rope.stiffness = r.stiffness;
    rope.rest_length = r.rest_length > 0. ? r.rest_length : rope.reference_chord.norm();
    system.ropes.push_back(rope);
  }
  return rope_omega_squared_bound(system.ropes, system.lumped_mass, system.fixed);
}

std::vector<Point<3>> Frame::cell_centres() const
{
  // the beam cells, then the solid cells (a decomposition assigns both)
  std::vector<Point<3>> centres(triangulation.n_active_cells());
  for (const auto &cell : triangulation.active_cell_iterators())
    centres[cell->active_cell_index()] = cell->center();
  if (solids)
    for (const auto &c : solids->cell_centres())
      centres.push_back(c);
  return centres;
}

double Frame::size() const
{
  const auto box = GridTools::compute_bounding_box(triangulation);
  const double beams =
      box.get_boundary_points().first.distance(box.get_boundary_points().second);
  return solids ? std::max(beams, solids->size()) : beams;
}

std::vector<std::string> Frame::cell_members() const
{
  // the beam cells' members, then the solid cells' solids
  std::vector<std::string> names(cells.size());
  for (unsigned int c = 0; c < cells.size(); ++c)
    names[c] = frame.members[cells[c].member].name;
  if (solids)
    for (const unsigned int s : solids->cell_solids())
      names.push_back(solids->solid_name(s));
  return names;
}

std::string Frame::section_forces_header() const { return section_force_output.header(); }

void Frame::write_section_forces(std::ostream *out,
                                 const double time,
                                 const Vector<double> &U,
                                 const Vector<double> *functional_values) const
{
  if (frame.section_force_members.empty() && frame.solids.cuts.empty())
    return;
  Vector<double> u(U);
  constraints.distribute(u);
  section_force_output.write(out, time, u, cells, gravity);
  if (solids)
    solids->cuts().write(out,
                         time,
                         u,
                         gravity,
                         section_force_output,
                         functional_values ? functional_values->data() : nullptr);
}

std::vector<SparseRow> Frame::output_functionals() const
{
  if (!solids)
    return {};
  // write_section_forces() distributes the constraints before the cuts'
  // rows read u: each constrained DoF's coefficient goes to its sources
  // (closed, homogeneous constraints: one level)
  std::vector<SparseRow> rows = solids->cuts().rows();
  for (SparseRow &row : rows)
  {
    std::map<types::global_dof_index, double> folded;
    for (unsigned int i = 0; i < row.dofs.size(); ++i)
      if (const auto *entries = constraints.get_constraint_entries(row.dofs[i]))
      {
        AssertThrow(constraints.get_inhomogeneity(row.dofs[i]) == 0., ExcInternalError());
        for (const auto &[source, weight] : *entries)
          folded[source] += weight * row.coefficients[i];
      }
      else if (!constraints.is_constrained(row.dofs[i]))
        folded[row.dofs[i]] += row.coefficients[i];
    row.dofs.clear();
    row.coefficients.clear();
    for (const auto &[dof, coefficient] : folded)
    {
      row.dofs.push_back(dof);
      row.coefficients.push_back(coefficient);
    }
  }
  return rows;
}

std::vector<types::global_dof_index> Frame::section_force_dofs() const
{
  std::vector<types::global_dof_index> dofs;
  for (const auto &name : frame.section_force_members)
    for (const auto &cell : cells)
      if (frame.members[cell.member].name == name)
        dofs.insert(dofs.end(), cell.dofs.begin(), cell.dofs.end());
  // write_section_forces() distributes the constraints: their sources too
  // (closed constraints: one level)
  const std::size_t n_read = dofs.size();
  for (std::size_t k = 0; k < n_read; ++k)
    if (const auto *entries = constraints.get_constraint_entries(dofs[k]))
      for (const auto &entry : *entries)
        dofs.push_back(entry.first);
  std::sort(dofs.begin(), dofs.end());
  dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
  return dofs;
}

DofDescription Frame::describe_dof(const types::global_dof_index dof) const
{
  static const char *const components[6] = {"ux", "uy", "uz", "rx", "ry", "rz"};
  for (const auto &[node, dofs] : node_dofs)
    for (unsigned int c = 0; c < 6; ++c)
      if (dofs[c] == dof)
        return {components[c], "node '" + node + "'", c >= 3};
  for (const auto &cell : cells)
    for (unsigned int k = 0; k < 12; ++k)
      if (cell.dofs[k] == dof)
      {
        std::ostringstream where;
        where << "member '" << frame.members[cell.member].name << "', "
              << cell.position + (k < 6 ? 0. : cell.length) << " m from its start";
        return {components[k % 6], where.str(), k % 6 >= 3};
      }
  return {};
}

std::string Frame::description() const
{
  std::ostringstream s;
  unsigned int ne = 0;
  for (const auto &m : frame.members)
    ne += m.n_elements;
  s << "3D frame: " << frame.nodes.size() << " nodes, " << frame.members.size()
    << " members, " << ne << " Timoshenko elements, ";
  if (solids)
    s << solids->description() << ", ";
  s << "mass " << total_mass << " kg";
  return s.str();
}
} // namespace hati
