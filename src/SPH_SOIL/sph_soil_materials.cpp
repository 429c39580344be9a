/* ----------------------------------------------------------------------
   SPH_SOIL package for LAMMPS: the materials of pair_style sph/soil (see the header)
------------------------------------------------------------------------- */

#include "sph_soil_materials.h"

#include "comm.h"
#include "soil_models.h"
#include "sph_soil_compat.h"
#include "utils.h"

#include <cstdlib>
#include <cstring>

using namespace LAMMPS_NS;
using SPHSoil::SoilMaterial;

/* ---------------------------------------------------------------------- */

void SPHSoilMaterials::allocate(int ntypes)
{
  materials.assign(ntypes + 1, SoilMaterial());
  has_material.assign(ntypes + 1, 0);
}

void SPHSoilMaterials::set(int type, const SoilMaterial &material)
{
  materials[type] = material;
  has_material[type] = 1;
}

double SPHSoilMaterials::max_wave_speed() const
{
  double c = 0.0;
  for (int type = 1; type < (int) materials.size(); type++)
    if (has(type)) c = MAX(c, materials[type].wave_speed());
  return c;
}

/* ----------------------------------------------------------------------
   pair_coeff * * file.soil name1 ... nameN     (NULL: type not handled)
   pair_coeff I I soil rho0 [model] parameters...
   pair_coeff I I wall
------------------------------------------------------------------------- */

void SPHSoilMaterials::coeff(int narg, char **arg)
{
  const int ntypes = (int) materials.size() - 1;
  if (narg < 3)
    SPHSoilCompat::error_all(
        lmp, FLERR,
        "Incorrect args for pair_coeff sph/soil: expected 'I I soil rho0 model "
        "parameters' (models: {}), 'I I wall', 'I I water rho_w K_w' or '* * file name1 ... "
        "name{}'",
        SPHSoil::model_usages(), ntypes);

  if (strcmp(arg[2], "soil") == 0 || strcmp(arg[2], "wall") == 0 || strcmp(arg[2], "water") == 0) {
    int ilo, ihi, jlo, jhi;
    utils::bounds(FLERR, arg[0], 1, ntypes, ilo, ihi, error);
    utils::bounds(FLERR, arg[1], 1, ntypes, jlo, jhi, error);
    if (ilo != jlo || ihi != jhi)
      SPHSoilCompat::error_all(
          lmp, FLERR,
          "Incorrect args for pair_coeff sph/soil: a material belongs to atom types, "
          "so both type arguments must be the same (got {} {})",
          arg[0], arg[1]);
    const std::vector<std::string> words(arg + 2, arg + narg);
    const std::string name = fmt::format("of type(s) {}", arg[0]);
    for (int type = ilo; type <= ihi; type++) set_from_words(type, name, words);
    return;
  }

  if (strcmp(arg[0], "*") != 0 || strcmp(arg[1], "*") != 0)
    SPHSoilCompat::error_all(
        lmp, FLERR,
        "Incorrect args for pair_coeff sph/soil: unknown material kind '{}' for "
        "types {} {} (allowed: soil, wall, water; a material file takes '* * file name1 ... "
        "name{}')",
        arg[2], arg[0], arg[1], ntypes);
  if (narg != 3 + ntypes)
    SPHSoilCompat::error_all(
        lmp, FLERR,
        "Incorrect args for pair_coeff sph/soil: a material file needs one name (or "
        "NULL) per atom type, {} expected, {} given",
        ntypes, narg - 3);
  std::vector<SoilMaterial> list;
  read_file(arg[2], list);
  // NULL leaves a type to another pair style of pair_style hybrid (the LAMMPS convention); a
  // line of NULLs only would set nothing at all, and LAMMPS would say at the run only that
  // coefficients are missing
  int named = 0;
  for (int type = 1; type <= ntypes; type++) named += strcmp(arg[2 + type], "NULL") != 0;
  if (named == 0) {
    std::string names;
    for (const auto &m : list) names += (names.empty() ? "" : ", ") + m.name;
    SPHSoilCompat::error_all(
        lmp, FLERR,
        "Incorrect args for pair_coeff sph/soil: every type of 'pair_coeff * * {}' is NULL, "
        "which gives no type a material (NULL leaves a type to another style of pair_style "
        "hybrid); name one of the file's materials ({}) for each type of pair_style sph/soil",
        arg[2], names);
  }
  for (int type = 1; type <= ntypes; type++) {
    const char *name = arg[2 + type];
    if (strcmp(name, "NULL") == 0) continue;
    const SoilMaterial *found = nullptr;
    for (const auto &m : list)
      if (m.name == name) found = &m;
    if (!found)
      SPHSoilCompat::error_all(
          lmp, FLERR, "pair_coeff sph/soil: material {} for atom type {} is not in file {}", name,
          type, arg[2]);
    set(type, *found);
  }
}

void SPHSoilMaterials::set_from_words(int type, const std::string &name,
                                      const std::vector<std::string> &words)
{
  SoilMaterial material;
  std::string problem;
  if (!SPHSoil::material_from_words(name, words, material, problem))
    SPHSoilCompat::error_all(lmp, FLERR, "Incorrect args for pair_coeff sph/soil: {}", problem);
  set(type, material);
}

/* ----------------------------------------------------------------------
   read a material file on rank 0 (through LAMMPS's potential-file search)
------------------------------------------------------------------------- */

void SPHSoilMaterials::read_file(const char *file, std::vector<SoilMaterial> &list)
{
  std::string text;
  int ok = 1;
  if (comm->me == 0) {
    // LAMMPS's search (current directory, then its potentials directory), then
    // $LAMMPS_POTENTIALS (which Debian's LAMMPS build no longer consults), then the
    // package's own potentials/ directory when the build knows it
    std::string path = utils::get_potential_file_path(file);
    std::vector<std::string> fallbacks;
    if (const char *env = getenv("LAMMPS_POTENTIALS")) fallbacks.emplace_back(env);
#ifdef SPH_SOIL_POTENTIALS_DIR
    fallbacks.emplace_back(SPH_SOIL_POTENTIALS_DIR);
#endif
    for (const auto &dir : fallbacks) {
      if (!path.empty()) break;
      const std::string candidate = dir + "/" + file;
      if (FILE *probe = fopen(candidate.c_str(), "r")) {
        fclose(probe);
        path = candidate;
      }
    }
    FILE *fp = path.empty() ? nullptr : fopen(path.c_str(), "r");
    if (!fp) {
      ok = 0;
    } else {
      char buffer[4096];
      size_t n;
      while ((n = fread(buffer, 1, sizeof(buffer), fp)) > 0) text.append(buffer, n);
      fclose(fp);
    }
  }
  MPI_Bcast(&ok, 1, MPI_INT, 0, world);
  if (!ok)
    SPHSoilCompat::error_all(lmp, FLERR, "Cannot open material file {} for pair_coeff sph/soil",
                             file);
  int length = text.size();
  MPI_Bcast(&length, 1, MPI_INT, 0, world);
  text.resize(length);
  MPI_Bcast(&text[0], length, MPI_CHAR, 0, world);
  std::string problem;
  if (!SPHSoil::parse_material_file(text, list, problem))
    SPHSoilCompat::error_all(lmp, FLERR, "Invalid material file {} for pair_coeff sph/soil: {}",
                             file, problem);
}

/* ----------------------------------------------------------------------
   restart files: per type a flag, then the material's name and its words
------------------------------------------------------------------------- */

namespace {
void write_string(FILE *fp, const std::string &s)
{
  const int n = (int) s.size();
  fwrite(&n, sizeof(int), 1, fp);
  fwrite(s.data(), sizeof(char), n, fp);
}
}    // namespace

void SPHSoilMaterials::write_restart(FILE *fp) const
{
  for (int type = 1; type < (int) materials.size(); type++) {
    fwrite(&has_material[type], sizeof(int), 1, fp);
    if (!has(type)) continue;
    const SoilMaterial &m = materials[type];
    write_string(fp, m.name);
    const int nwords = (int) m.words.size();
    fwrite(&nwords, sizeof(int), 1, fp);
    for (const auto &word : m.words) write_string(fp, word);
  }
}

void SPHSoilMaterials::read_restart(FILE *fp)
{
  const int me = comm->me;
  auto read_int = [&]() {
    int value = 0;
    if (me == 0) utils::sfread(FLERR, &value, sizeof(int), 1, fp, nullptr, error);
    MPI_Bcast(&value, 1, MPI_INT, 0, world);
    return value;
  };
  auto read_string = [&]() {
    const int n = read_int();
    std::string s(n, ' ');
    if (me == 0 && n > 0) utils::sfread(FLERR, &s[0], sizeof(char), n, fp, nullptr, error);
    if (n > 0) MPI_Bcast(&s[0], n, MPI_CHAR, 0, world);
    return s;
  };
  for (int type = 1; type < (int) materials.size(); type++) {
    if (!read_int()) continue;
    const std::string name = read_string();
    std::vector<std::string> words(read_int());
    for (auto &word : words) word = read_string();
    set_from_words(type, name, words);
  }
}
