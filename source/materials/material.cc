#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/materials/material.h>
#include <lithostress/materials/rheology.h>

#include <algorithm>
#include <sstream>

namespace lithostress
{
  double
  Material::shear_modulus() const
  {
    return youngs_modulus / (2.0 * (1.0 + poissons_ratio));
  }

  double
  Material::lame_lambda() const
  {
    return youngs_modulus * poissons_ratio /
           ((1.0 + poissons_ratio) * (1.0 - 2.0 * poissons_ratio));
  }

  void
  MaterialLibrary::declare_parameters(ParameterHandler &prm,
                                      ParameterHandler *first_pass)
  {
    const std::vector<std::string> names =
      ParameterFile::names_from(first_pass, {"Materials"}, "Names", {"rock"});
    prm.enter_subsection("Materials");
    prm.declare_entry("Names",
                      "rock",
                      Patterns::List(Patterns::Anything()),
                      "Comma separated names of the materials; each gets a "
                      "subsection of this name.");
    for (const std::string &name : names)
      {
        prm.enter_subsection(name);
        prm.declare_entry("Material id",
                          "",
                          Patterns::Anything(),
                          "Cell material id this material applies to. Leave "
                          "empty to take the id of the mesh region (Gmsh "
                          "physical group, layer) with the material's name.");
        prm.declare_entry("Young's modulus",
                          "1e11",
                          Patterns::Double(),
                          "Young's modulus E [Pa], > 0 and at most 1e20.");
        prm.declare_entry("Poisson's ratio",
                          "0.25",
                          Patterns::Double(),
                          "Poisson's ratio, -1 < nu < 0.5.");
        prm.declare_entry("Density",
                          "0",
                          Patterns::Double(),
                          "Density rho [kg/m^3], >= 0.");
        prm.declare_entry("Tensile strength",
                          "0",
                          Patterns::Double(),
                          "Tensile strength T [Pa] for the Griffith failure "
                          "test, >= 0.");
        prm.declare_entry("Viscosity",
                          "0",
                          Patterns::Double(),
                          "Maxwell viscosity eta [Pa s]; 0 = purely elastic.");
        prm.declare_entry(
          "Rheology",
          "automatic",
          Patterns::Selection("automatic|" + RheologyRegistry<2>::names()),
          "The rock law: " + RheologyRegistry<2>::documentation() +
            "; automatic: maxwell if a Viscosity is given, "
            "elastic otherwise.");
        RheologyRegistry<2>::declare_parameters(prm);
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }

  void
  MaterialLibrary::parse_parameters(ParameterHandler &prm)
  {
    all.clear();
    id_given.clear();
    prm.enter_subsection("Materials");
    const std::vector<std::string> names = split_list(prm.get("Names"));
    if (names.empty())
      throw_input_error("Materials/Names", "no material is named");
    for (const std::string &name : names)
      {
        const std::string where = "Materials/" + name + "/";
        prm.enter_subsection(name);
        Material m;
        m.name               = name;
        m.youngs_modulus     = prm.get_double("Young's modulus");
        m.poissons_ratio     = prm.get_double("Poisson's ratio");
        m.density            = prm.get_double("Density");
        m.tensile_strength   = prm.get_double("Tensile strength");
        m.viscosity          = prm.get_double("Viscosity");
        m.rheology           = prm.get("Rheology");
        const std::string id = Utilities::trim(prm.get("Material id"));
        prm.leave_subsection();

        if (!(m.youngs_modulus > 0))
          throw_input_error(where + "Young's modulus",
                            "must be positive, got " +
                              std::to_string(m.youngs_modulus));
        // Rocks have 1e9-2e11 Pa; far larger moduli overflow the single
        // precision of the matrix-free multigrid's levels (3.4e38).
        if (!(m.youngs_modulus <= 1e20))
          {
            std::ostringstream value;
            value << m.youngs_modulus;
            throw_input_error(where + "Young's modulus",
                              "must be at most 1e20 Pa (rocks: 1e9 to 2e11 "
                              "Pa), got " +
                                value.str());
          }
        if (!(m.poissons_ratio > -1.0 && m.poissons_ratio < 0.5))
          throw_input_error(where + "Poisson's ratio",
                            "must lie in (-1, 0.5), got " +
                              std::to_string(m.poissons_ratio));
        if (m.density < 0)
          throw_input_error(where + "Density", "must not be negative");
        if (m.tensile_strength < 0)
          throw_input_error(where + "Tensile strength", "must not be negative");
        if (m.viscosity < 0)
          throw_input_error(where + "Viscosity", "must not be negative");
        if (m.rheology == "automatic")
          m.rheology = m.viscosity > 0 ? "maxwell" : "elastic";
        if (id.empty())
          {
            m.id = numbers::invalid_material_id;
            id_given.push_back(false);
          }
        else
          {
            int value = -1;
            try
              {
                std::size_t used = 0;
                value            = std::stoi(id, &used);
                if (used != id.size())
                  value = -1;
              }
            catch (const std::exception &)
              {
              }
            if (value < 0 || static_cast<unsigned int>(value) >=
                               numbers::invalid_material_id)
              throw_input_error(where + "Material id",
                                "<" + id +
                                  "> is not a non-negative integer id");
            m.id = static_cast<types::material_id>(value);
            id_given.push_back(true);
          }
        all.push_back(m);
      }
    prm.leave_subsection();
  }

  void
  MaterialLibrary::resolve(
    const std::map<std::string, types::material_id> &named_regions,
    const std::set<types::material_id>              &ids_in_mesh)
  {
    index_of_id.clear();
    for (unsigned int i = 0; i < all.size(); ++i)
      {
        if (!id_given[i])
          {
            const auto region = named_regions.find(all[i].name);
            if (region == named_regions.end())
              throw_input_error("Materials/" + all[i].name + "/Material id",
                                "is empty and the mesh has no region named <" +
                                  all[i].name + ">");
            all[i].id = region->second;
          }
        if (index_of_id.count(all[i].id) != 0)
          throw_input_error("Materials/" + all[i].name + "/Material id",
                            "id " + std::to_string(all[i].id) +
                              " is already used by material <" +
                              all[index_of_id[all[i].id]].name + ">");
        index_of_id[all[i].id] = i;
      }
    for (const types::material_id id : ids_in_mesh)
      if (index_of_id.count(id) == 0)
        throw_input_error("Materials",
                          "the mesh has cells with material id " +
                            std::to_string(id) +
                            " but no material has this id");
  }

  const Material &
  MaterialLibrary::operator()(const types::material_id id) const
  {
    const auto it = index_of_id.find(id);
    Assert(it != index_of_id.end(),
           ExcMessage("No material with id " + std::to_string(id)));
    return all[it->second];
  }

  bool
  MaterialLibrary::has(const types::material_id id) const
  {
    return index_of_id.count(id) != 0;
  }

  const std::vector<Material> &
  MaterialLibrary::materials() const
  {
    return all;
  }

  double
  MaterialLibrary::largest_youngs_modulus() const
  {
    double E = 0;
    for (const Material &m : all)
      E = std::max(E, m.youngs_modulus);
    return E;
  }
} // namespace lithostress
