#ifndef hati_model_solid_description_h
#define hati_model_solid_description_h

#include <deal.II/base/point.h>

#include <array>
#include <string>
#include <vector>

namespace hati
{
using namespace dealii;

/**
 * The 3D solids of a frame model and how they hold to the beams, as plain
 * data (doc/user_guide.md "Solids and ties"): the `Model/Frame` entries
 * `Solids`, `Solid element degree`, `Ties`, `Solid supports`, `Rigid
 * links`, `Solid cuts` and the solid items of `Monitor nodes`.
 * FrameDescription holds one of these; FrameSolids builds the meshes, the
 * constraints, the cuts and the monitors from it.
 */
struct SolidDescription
{
  /** A solid: a generated block or box girder, or a Gmsh hexahedral mesh. */
  struct Solid
  {
    std::string name;
    /** `box`, `box girder` or `mesh`. */
    std::string kind;
    /** box: two opposite corners; box girder: the two ends of its axis (m). */
    Point<3> x0, x1;
    /** box: the cells along x, y, z (-). */
    std::array<unsigned int, 3> cells{{1, 1, 1}};
    /** box girder: outer width (local y) and height (local z), m. */
    double width = 0., height = 0.;
    /** box girder: web and flange thicknesses (m), one element each. */
    double web_thickness = 0., flange_thickness = 0.;
    /** box girder: in-plane element size of the plates (m). */
    double element_size = 0.;
    /**
     * box girder: spacing of the transverse diaphragms (m, web thickness
     * thick, also at both ends); 0: none.
     */
    double diaphragm_spacing = 0.;
    /** mesh: the Gmsh file (ASCII 4.1, hexahedra only). */
    std::string file;
    std::string material;
  };

  /**
   * A plane `x_axis = value` of a solid's boundary, optionally only the part
   * within `radius` of a point of it (faces whose centre lies within), or
   * only a box girder's walls on it.
   */
  struct FacePlane
  {
    std::string solid;
    /** 0, 1, 2 for x, y, z (global axes). */
    unsigned int axis = 0;
    double value = 0.; ///< m
    /** m; negative: the whole plane. */
    double radius = -1.;
    /**
     * box girder: only the faces of its walls (webs and flanges), not those
     * of the diaphragms inside them (an end diaphragm's outer face).
     */
    bool walls = false;
  };

  /** A beam node tied to a face of a solid (B1, doc/theory.md B1). */
  struct Tie
  {
    std::string name, node;
    FacePlane face;
  };

  /** A rigid link: the slave node follows the master rigidly. */
  struct RigidLink
  {
    std::string name, master, slave;
  };

  /**
   * A cross-section cut of a solid, the plane `axis = value` in the solid's
   * local axes (solid_local_axes()), whose section forces are written to
   * `section_forces.csv` (SolidCuts, doc/theory.md 11.5).
   */
  struct Cut
  {
    std::string name, solid;
    /** 0, 1, 2 for x, y, z (the solid's local axes). */
    unsigned int axis = 0;
    /** The plane's coordinate along that local axis (m, from the global origin). */
    double value = 0.;
  };

  /** A monitor point of history.csv at the solid's node nearest to @p point. */
  struct Monitor
  {
    std::string name, solid;
    /** The requested point (m, global axes). */
    Point<3> point;
  };

  std::vector<Solid> solids;
  /** Degree p of the solid elements FE_Q(p)^3 (1 ... 4). */
  unsigned int degree = 2;
  std::vector<Tie> ties;
  /** Faces whose every translation is fixed. */
  std::vector<FacePlane> supports;
  std::vector<RigidLink> rigid_links;
  /** `Solid cuts`: cross-sections whose section forces are output. */
  std::vector<Cut> cuts;
  /** `Monitor nodes` items `name: solid, x, y, z`. */
  std::vector<Monitor> monitors;

  /** Whether any solid is given. */
  bool empty() const { return solids.empty(); }
};
} // namespace hati

#endif
