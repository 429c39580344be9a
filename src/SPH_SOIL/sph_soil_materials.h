/* -*- c++ -*- ----------------------------------------------------------
   SPH_SOIL package for LAMMPS: the materials of pair_style sph/soil, per atom
   type, as pair_coeff sets them (in the input, or from a material file through
   LAMMPS's potential-file search) and as restart files keep them. The
   materials themselves are pure (soil_material.h).
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOIL_MATERIALS_H
#define LMP_SPH_SOIL_MATERIALS_H

#include "pointers.h"
#include "soil_material.h"

#include <cstdio>
#include <vector>

namespace LAMMPS_NS {

class SPHSoilMaterials : protected Pointers {
 public:
  explicit SPHSoilMaterials(class LAMMPS *lmp) : Pointers(lmp) {}

  // room for types 1..ntypes, none set
  void allocate(int ntypes);
  // pair_coeff's arguments: 'I I soil rho0 model parameters', 'I I wall options', 'I I water
  // rho_w K_w', or
  // '* * file name1 ... nameN'
  void coeff(int narg, char **arg);

  bool has(int type) const { return has_material[type] != 0; }
  const SPHSoil::SoilMaterial &of(int type) const { return materials[type]; }
  // the constitutive model of a soil type, nullptr for walls and types without material
  const SPHSoil::ConstitutiveModel *model(int type) const { return materials[type].model.get(); }
  bool is_wall(int type) const { return has(type) && materials[type].is_wall(); }
  // the largest P-wave speed of the soils
  double max_wave_speed() const;
  // index 0..ntypes
  const std::vector<SPHSoil::SoilMaterial> &all() const { return materials; }
  const std::vector<int> &set_flags() const { return has_material; }

  // every type's material by its words; read on rank 0 and broadcast
  void write_restart(FILE *fp) const;
  void read_restart(FILE *fp);

 private:
  std::vector<SPHSoil::SoilMaterial> materials;
  std::vector<int> has_material;
  void set(int type, const SPHSoil::SoilMaterial &material);
  void read_file(const char *file, std::vector<SPHSoil::SoilMaterial> &list);
  void set_from_words(int type, const std::string &name, const std::vector<std::string> &words);
};

}    // namespace LAMMPS_NS

#endif
