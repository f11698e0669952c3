#include <deal.II/base/utilities.h>

#include <fosls_contact/parameters/hertz_comparison.h>
#include <fosls_contact/parameters/value_parsing.h>

namespace FoslsContact
{
  namespace Parameters
  {
    void
    HertzComparison::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Hertz comparison");
      prm.declare_entry("Shape",
                        "none",
                        Patterns::Selection("none|cylinder|sphere"),
                        "none, or the Hertz contact this scene is: cylinder (a "
                        "cylinder of radius R on a plane, in plane strain, forces per "
                        "unit length: in 2D its cross-section, in 3D a cylinder of "
                        "Length along Axis) or sphere (3D: a sphere of radius R on a "
                        "plane). One of the two bodies is rigid, the other has the "
                        "scene's material. The run prints Hertz's contact half-width "
                        "(radius) a and peak pressure p0 for the computed force, "
                        "against the computed contact edge, peak pressure and the "
                        "relative l2 error of the pressure at the contact vertices, "
                        "and writes them to summary.json (\"hertz\"), which "
                        "scripts/plot.py draws. A cylinder in 2D or a sphere in 3D "
                        "with Coulomb friction is compared with Cattaneo and "
                        "Mindlin's solution for the computed tangential force too "
                        "(its stick zone and tangential traction; summary.json "
                        "\"cattaneo_mindlin\").");
      prm.declare_entry("Radius",
                        "0",
                        Patterns::Double(0),
                        "R, in the scene's units.");
      prm.declare_entry("Contact point",
                        "0, 0",
                        Patterns::List(Patterns::Double(), 2, 3),
                        "The first point of contact (the center of the contact zone; "
                        "in 3D for a cylinder a point of the contact line), in the "
                        "scene's coordinates; distances are measured from it in the "
                        "plane of contact (for a cylinder in 3D: from the contact "
                        "line).");
      prm.declare_entry("Force factor",
                        "1",
                        Patterns::Double(0),
                        "The force of the full contact per computed force, > 0: a "
                        "model of a symmetric part computes a part of the force, "
                        "Hertz's formulas need the whole: 4 for a quarter model of a "
                        "sphere (two symmetry planes through the contact point), 2 "
                        "for a half model. Hertz's F is the computed normal force "
                        "times this factor (divided by Length for a cylinder in 3D).");
      prm.declare_entry("Axis",
                        "0, 0, 1",
                        Patterns::List(Patterns::Double(), 3, 3),
                        "Cylinder in 3D: the direction of its axis (the contact "
                        "line).");
      prm.declare_entry("Length",
                        "0",
                        Patterns::Double(0),
                        "Cylinder in 3D: the length of the contact line of the full "
                        "model, in the scene's units: Hertz's force per unit length "
                        "is F times Force factor divided by it.");
      prm.leave_subsection();
    }

    void
    HertzComparison::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Hertz comparison");
      const std::string s = prm.get("Shape");
      shape         = s == "none" ? Shape::none : s == "cylinder" ? Shape::cylinder : Shape::sphere;
      radius        = prm.get_double("Radius");
      contact_point = parse_double_list(prm.get("Contact point"));
      force_factor  = prm.get_double("Force factor");
      axis          = parse_double_list(prm.get("Axis"));
      length        = prm.get_double("Length");
      prm.leave_subsection();
      if (shape == Shape::none)
        return;
      AssertThrow(radius > 0,
                  ExcMessage("parameter 'Hertz comparison/Radius' must be > 0 with a Shape"));
      AssertThrow(force_factor > 0,
                  ExcMessage("parameter 'Hertz comparison/Force factor' must be > 0"));
    }
  } // namespace Parameters
} // namespace FoslsContact
