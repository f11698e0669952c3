#ifndef fosls_contact_output_contact_surface_h
#define fosls_contact_output_contact_surface_h

#include <deal.II/numerics/data_out_faces.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <fosls_contact/output/contact_table.h>
#include <fosls_contact/scene/scene.h>

#include <map>

namespace FoslsContact
{
  /**
   * The contact boundary as a surface of its own for ParaView
   * (contact_surface_0000.pvtu): the faces of the owned cells on Gamma_C,
   * with the values of contact.csv at their vertices, under its names
   * (ContactTable::local_rows()): contact_pressure = -sigma_nn, the
   * normal displacement u_n, the initial gap g, the remaining gap g - u_n
   * and in_contact (1 where u_n = g), in the scene's units; and
   * face_pressure, the face's own -(sigma n_b).n. RT0's normal traction is
   * constant on each face and jumps between faces; contact.csv gives a
   * vertex the mean of its faces, which is what the zone's peak and mean
   * pressure are made of, while the face values are what integrates to
   * the contact force exactly (the vertex means smear the zone's edge by
   * a face: on the steel cylinder's 2-level mesh their integral is 40%
   * off the force, on the 5-level square less than 1e-3: solver/
   * output_fields). A surface of its own,
   * because these quantities live on the boundary only.
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
      /**
       * @p rows: ContactTable::local_rows() of the solution shown, by
       * vertex index; kept by reference.
       */
      Fields(const Scene<dim> &                                              scene,
             const std::map<unsigned int, typename ContactRow<dim>::Values> &rows,
             const bool                                                      friction);
      void evaluate_vector_field(const DataPostprocessorInputs::Vector<dim> &inputs,
                                 std::vector<Vector<double>> &computed) const override;
      /**
       * With friction also the rows' slip and tangential_traction (vectors)
       * and friction_status (ContactRow).
       */
      std::vector<std::string> get_names() const override;
      std::vector<DataComponentInterpretation::DataComponentInterpretation>
                  get_data_component_interpretation() const override;
      UpdateFlags get_needed_update_flags() const override;

    private:
      const Scene<dim> &                                              scene;
      const std::map<unsigned int, typename ContactRow<dim>::Values> &rows;
      const bool                                                      friction;
    };

  private:
    /** The first contact face of @p cell from face @p f on, or of a later cell. */
    FaceDescriptor find(typename Triangulation<dim>::active_cell_iterator cell,
                        unsigned int                                      f) const;

    const Scene<dim> &scene;
  };
} // namespace FoslsContact

#endif
