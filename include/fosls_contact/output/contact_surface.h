#ifndef fosls_contact_output_contact_surface_h
#define fosls_contact_output_contact_surface_h

#include <deal.II/numerics/data_out_faces.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <fosls_contact/scene/scene.h>

namespace FoslsContact
{
  /**
   * The contact boundary as a surface of its own for ParaView
   * (contact_surface_0000.pvtu): the faces of the owned cells on Gamma_C,
   * with the contact pressure -(sigma n_b).n, the normal displacement u.n
   * and the remaining gap g - u.n (0 where the body touches the obstacle),
   * in the scene's units (the solution and mapping of
   * Postprocessor::solution_in_scene_units()). A surface of its own,
   * because these quantities live on the boundary only; the contact table
   * (contact.csv) has them at the vertices.
   */
  template <int dim>
  class ContactSurface : public DataOutFaces<dim>
  {
  public:
    explicit ContactSurface(const Scene<dim> &scene);

    using FaceDescriptor = typename DataOutFaces<dim>::FaceDescriptor;
    /** The contact faces of the owned active cells. */
    FaceDescriptor first_face() override;
    FaceDescriptor next_face(const FaceDescriptor &face) override;

    /** The fields, point by point on the contact faces. */
    class Fields : public DataPostprocessor<dim>
    {
    public:
      explicit Fields(const Scene<dim> &scene);
      void evaluate_vector_field(const DataPostprocessorInputs::Vector<dim> &inputs,
                                 std::vector<Vector<double>> &computed) const override;
      std::vector<std::string> get_names() const override;
      UpdateFlags              get_needed_update_flags() const override;

    private:
      const Scene<dim> &scene;
    };

  private:
    /** The first contact face of @p cell from face @p f on, or of a later cell. */
    FaceDescriptor find(typename Triangulation<dim>::active_cell_iterator cell,
                        unsigned int                                      f) const;

    const Scene<dim> &scene;
  };
} // namespace FoslsContact

#endif
