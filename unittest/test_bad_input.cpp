// The package's bad-input suite: every style, command, keyword, material file and data file
// format of SPH_SOIL given a wrong or suspicious input, each case asserting the exact error or
// warning text. Registered at 1 and 2 ranks: the errors are collective (raised on every rank)
// except those of data files, which the rank that reads the atom raises (1 rank only).
#include "sph_soil_testing.h"

#include <cstdlib>
#include <fstream>
#include <regex>

using namespace LAMMPS_NS;
using namespace SPHSoilTesting;

namespace {

struct BadInput {
  std::string name;                  // the test's name
  std::string setup;                 // a set-up of the fixture, see prepare()
  std::vector<std::string> before;   // commands after the set-up
  std::string command;               // the command that must stop (or warn)
  std::string message;               // the exact text of the error (or warning)
  bool warning = false;              // a warning: the command succeeds
  bool one_rank = false;             // an error of one rank (error->one): 1 rank only
  // where LAMMPS itself rejects the input first, or words its message differently, in
  // another release: the exact text of that message
  std::string lammps_message = "";
};

// a material file for the file cases
const char *const FILES[][2] = {
    {"good.soil", "sand soil 1850 1.5e6 0.3 45 0 0\nrock wall\n"},
    {"short.soil", "# a comment\nsand soil 1850 1.5e6 0.3 45 0\n"},
    {"twice.soil", "sand soil 1850 1.5e6 0.3 45 0 0\nsand wall\n"},
    {"empty.soil", "# nothing but comments\n\n"},
    {"kind.soil", "sand clay 1850 1.5e6 0.3 45 0 0\n"},
    {"word.soil", "sand soil 1850 1.5e6 0.3 forty-five 0 0\n"},
    {"nan.soil", "sand soil 1850 nan 0.3 45 0 0\n"},
};

// a data file with one atom; `atom` is its Atoms line, `velocity` its Velocities line
std::string data_file(const std::string &atom, const std::string &velocity = "")
{
  std::string text = "bad data file\n\n1 atoms\n1 atom types\n\n0 1 xlo xhi\n0 1 ylo yhi\n"
                     "-0.5 0.5 zlo zhi\n\nAtoms # sph/soil\n\n" + atom + "\n";
  if (!velocity.empty()) text += "\nVelocities\n\n" + velocity + "\n";
  return text;
}

std::string escape(const std::string &text)
{
  static const std::regex special(R"([.^$|()\[\]{}*+?\\])");
  return std::regex_replace(text, special, R"(\$&)");
}

const std::string SOIL = "pair_coeff 1 1 soil 2650 0.7e6 0.3 19.8 0 0";

std::vector<BadInput> cases()
{
  std::vector<BadInput> c;
  auto error = [&](std::string name, std::string setup, std::vector<std::string> before,
                   std::string command, std::string message) {
    c.push_back({name, setup, before, command, message, false, false});
  };
  auto warning = [&](std::string name, std::string setup, std::vector<std::string> before,
                     std::string command, std::string message) {
    c.push_back({name, setup, before, command, message, true, false});
  };
  auto data = [&](std::string name, std::string atom, std::string velocity, std::string message) {
    c.push_back({name, "data", {"write bad.data " + data_file(atom, velocity)}, "read_data bad.data",
                 message, false, true});
  };
  // a number out of the double range: ours, or LAMMPS's own message for `text`
  auto out_of_range = [&](std::string name, std::string setup, std::vector<std::string> before,
                          std::string command, std::string message, std::string text) {
    c.push_back({name, setup, before, command, message, false, false,
                 "Floating point number " + text + " in input script or data file is out of range"});
  };

  // ---- atom_style sph/soil
  error("AtomStyleArguments", "none", {}, "atom_style sph/soil extra",
        "Illegal atom_style sph/soil command: it takes no arguments, got 'extra'");

  // ---- sph_soil/set
  error("SetBeforeBox", "none", {}, "sph_soil/set all h 1.0",
        "sph_soil/set command before simulation box is defined");
  error("SetWithoutAtomStyle", "none", {"region box block 0 1 0 1 0 1", "create_box 1 box"},
        "sph_soil/set all h 1.0", "sph_soil/set command requires atom_style sph/soil");
  error("SetTooFewArguments", "patch", {}, "sph_soil/set all",
        "Illegal sph_soil/set command: expected 'sph_soil/set group-ID keyword value ...'");
  error("SetUnknownGroup", "patch", {}, "sph_soil/set nosuchgroup h 1",
        "Could not find sph_soil/set group ID nosuchgroup");
  error("SetUnknownKeyword", "patch", {}, "sph_soil/set all colour 3",
        "Illegal sph_soil/set command: unknown keyword colour (allowed: mass, h, density, level, "
        "stress, strain, geostatic, pore_pressure, wall, nowall)");
  error("SetMissingValue", "patch", {}, "sph_soil/set all h 0.01 density",
        "Illegal sph_soil/set command: keyword density needs 1 value(s)");
  error("SetMassZero", "patch", {}, "sph_soil/set all mass 0",
        "Illegal sph_soil/set mass value 0 for atom 1: must be > 0");
  out_of_range("SetMassInfinite", "patch", {}, "sph_soil/set all mass 1e400",
        "Illegal sph_soil/set mass 1e400: must be a finite number", "1e400");
  // a word that is no number: the command, keyword, value and range, not LAMMPS's parser's
  // "Expected floating point parameter" alone
  error("SetPorePressureNotANumber", "patch", {}, "sph_soil/set all pore_pressure nan",
        "Illegal sph_soil/set pore_pressure nan: must be a finite number or v_name (an equal- or "
        "atom-style variable)");
  error("SetMassNotANumber", "patch", {}, "sph_soil/set all mass inf",
        "Illegal sph_soil/set mass inf: must be a finite number > 0 or v_name (an equal- or "
        "atom-style variable)");
  error("SetLevelNotAnInteger", "patch", {}, "sph_soil/set all level 1.5",
        "Illegal sph_soil/set level 1.5: must be an integer in 0 to 30");
  error("SetGeostaticNotANumber", "patch", {}, "sph_soil/set all geostatic 0.3 dense 10 0.5",
        "Illegal sph_soil/set geostatic density dense: must be a finite number > 0");
  error("SetHNegative", "patch", {}, "sph_soil/set all h -0.5",
        "Illegal sph_soil/set h value -0.5 for atom 1: must be > 0");
  error("SetDensityFromAtomVariable", "patch", {"variable bad atom 1.0-0.01*id"},
        "sph_soil/set all density v_bad", "Illegal sph_soil/set density value 0 for atom 100: must be > 0");
  error("SetDensityVariableInfinite", "patch", {"variable big equal 1e300*1e300"},
        "sph_soil/set all density v_big", "Illegal sph_soil/set density value inf for atom 1: must be > 0");
  error("SetUnknownVariable", "patch", {}, "sph_soil/set all h v_nosuchvar",
        "Variable name nosuchvar for sph_soil/set h does not exist");
  error("SetStringVariable", "patch", {"variable word string abc"}, "sph_soil/set all h v_word",
        "Variable word for sph_soil/set h must be equal-style or atom-style");
  error("SetLevelNegative", "patch", {}, "sph_soil/set all level -1",
        "Illegal sph_soil/set level -1: must be in 0 to 30");
  error("SetLevelTooDeep", "patch", {}, "sph_soil/set all level 31",
        "Illegal sph_soil/set level 31: must be in 0 to 30");
  error("SetStressTooFewValues", "patch", {}, "sph_soil/set all stress 1 2 3",
        "Illegal sph_soil/set command: keyword stress needs 6 value(s)");
  out_of_range("SetStressInfinite", "patch", {}, "sph_soil/set all stress -1e400 0 0 0 0 0",
        "Illegal sph_soil/set stress -1e400: must be a finite number", "-1e400");
  error("SetStressOutOfPlaneShearIn2D", "patch", {}, "sph_soil/set all stress -1 -1 -1 0 5 0",
        "Illegal sph_soil/set stress: the xz component must be 0 in 2D (plane strain), got 5 for atom 1");
  error("SetStrainOutOfPlaneShearIn2D", "patch", {}, "sph_soil/set all strain 0 0 0 0 0 0.1",
        "Illegal sph_soil/set strain: the yz component must be 0 in 2D (plane strain), got 0.1 for atom 1");
  error("SetGeostaticK0", "patch", {}, "sph_soil/set all geostatic 0.3 2000 10 -1",
        "Illegal sph_soil/set geostatic K0 -1: must be in [0, 10]");
  error("SetGeostaticDensity", "patch", {}, "sph_soil/set all geostatic 0.3 0 10 0.5",
        "Illegal sph_soil/set geostatic density 0: must be > 0");
  error("SetGeostaticGravity", "patch", {}, "sph_soil/set all geostatic 0.3 2000 -9.81 0.5",
        "Illegal sph_soil/set geostatic gravity -9.81: must be >= 0");
  out_of_range("SetGeostaticSurfaceInfinite", "patch", {}, "sph_soil/set all geostatic 1e400 2000 10 0.5",
        "Illegal sph_soil/set geostatic surface 1e400: must be a finite number", "1e400");
  error("SetWallNormalZero", "patch", {}, "sph_soil/set all wall 0 0 0 0 0 0",
        "Illegal sph_soil/set wall: the normal (0 0 0) must be non-zero");
  error("SetWallNormalOutOfPlane", "patch", {}, "sph_soil/set all wall 0 0 0 0 1 1",
        "Illegal sph_soil/set wall: the normal must lie in the xy plane in 2D");
  out_of_range("SetWallPointInfinite", "patch", {}, "sph_soil/set all wall 0 1e999 0 0 1 0",
        "Illegal sph_soil/set wall point 1e999: must be a finite number", "1e999");

  // ---- pair_style sph/soil
  error("PairUnknownKeyword", "patch", {}, "pair_style sph/soil gamma 1",
        "Illegal pair_style sph/soil keyword gamma (allowed: alpha, beta, viscosity_h0, wall, kernel, "
        "artificial_stress, continuity, gradient_correction, density_diffusion, stress_diffusion)");
  error("PairStressDiffusion", "patch", {}, "pair_style sph/soil stress_diffusion 2",
        "Illegal pair_style sph/soil stress_diffusion 2: must be in [0, 1]");
  error("PairDensityDiffusion", "patch", {}, "pair_style sph/soil density_diffusion -0.1",
        "Illegal pair_style sph/soil density_diffusion -0.1: must be in [0, 1]");
  error("PairContinuity", "patch", {}, "pair_style sph/soil continuity density",
        "Illegal pair_style sph/soil continuity density: must be volume or mass");
  error("PairGradientCorrection", "patch", {}, "pair_style sph/soil gradient_correction 1",
        "Illegal pair_style sph/soil gradient_correction 1: must be no, yes or full");
  error("PairViscosityH0Negative", "patch", {}, "pair_style sph/soil viscosity_h0 -0.001",
        "Illegal pair_style sph/soil viscosity_h0 -0.001: must be >= 0");
  error("PairKernel", "patch", {}, "pair_style sph/soil kernel gaussian",
        "Illegal pair_style sph/soil kernel gaussian: must be one of cubic, wendland2");
  error("PairKeywordWithoutValue", "patch", {}, "pair_style sph/soil alpha",
        "Illegal pair_style sph/soil command: keyword alpha needs a value");
  error("PairAlphaNegative", "patch", {}, "pair_style sph/soil alpha -1",
        "Illegal pair_style sph/soil alpha -1: must be >= 0");
  out_of_range("PairAlphaInfinite", "patch", {}, "pair_style sph/soil alpha 1e400",
        "Illegal pair_style sph/soil alpha 1e400: must be a finite number >= 0", "1e400");
  error("PairAlphaNotANumber", "patch", {}, "pair_style sph/soil alpha one",
        "Illegal pair_style sph/soil alpha one: must be a finite number >= 0");
  error("PairBetaNegative", "patch", {}, "pair_style sph/soil beta -0.5",
        "Illegal pair_style sph/soil beta -0.5: must be >= 0");
  error("PairWall", "patch", {}, "pair_style sph/soil wall sticky",
        "Illegal pair_style sph/soil wall sticky: must be noslip or freeslip");
  error("PairArtificialStress", "patch", {}, "pair_style sph/soil artificial_stress -0.1",
        "Illegal pair_style sph/soil artificial_stress -0.1: must be in [0, 1]");
  error("PairFitMoved", "patch", {}, "pair_style sph/soil fit associated",
        "Illegal pair_style sph/soil keyword fit: the Drucker-Prager fit is now a parameter of the "
        "material ('soil rho0 drucker_prager K nu phi psi c fit associated' in pair_coeff or a material "
        "file); by default it is the fit exact for the dilatancy angle");

  // ---- pair_coeff: materials on the command line and in files
  error("CoeffTooFewArguments", "patch", {}, "pair_coeff 1 1",
        "Incorrect args for pair_coeff sph/soil: expected 'I I soil rho0 model parameters' (models: "
        "drucker_prager K nu phi psi c [fit exact|associated|nonassociated] [tension T]; "
        "mohr_coulomb K nu phi psi c [tension T]), 'I I wall', 'I I water rho_w K_w' or '* * file "
        "name1 ... name2'");
  error("CoeffSoilParameterCount", "patch", {}, "pair_coeff 1 1 soil 2650 0.7e6 0.3 19.8 0",
        "Incorrect args for pair_coeff sph/soil: material of type(s) 1: drucker_prager needs 5 "
        "parameters (K nu phi psi c), got 4");
  error("CoeffUnknownModel", "patch", {}, "pair_coeff 1 1 soil 2650 cam_clay 0.7e6 0.3 19.8 0 0",
        "Incorrect args for pair_coeff sph/soil: material of type(s) 1: unknown model 'cam_clay' "
        "(allowed: drucker_prager, mohr_coulomb)");
  error("CoeffMohrCoulombOption", "patch", {},
        "pair_coeff 1 1 soil 2650 mohr_coulomb 0.7e6 0.3 19.8 0 0 fit exact",
        "material of type(s) 1: mohr_coulomb: unknown option 'fit' (allowed on a soil line after the "
        "model's parameters: tension; for a saturated soil: porosity, permeability, water_density, "
        "water_modulus, permeability_law)");
  // a drained wall's word on a soil: every word a soil line takes (from the models' usages and
  // the pore water's table), and where the word belongs
  error("CoeffDrainedSoil", "patch", {}, "pair_coeff 1 1 soil 2650 0.7e6 0.3 19.8 0 0 drained",
        "material of type(s) 1: drucker_prager: unknown option 'drained' (allowed on a soil line "
        "after the model's parameters: fit, tension; for a saturated soil: porosity, permeability, "
        "water_density, water_modulus, permeability_law); 'drained' is a word of a wall ('wall ... "
        "drained')");
  error("CoeffFitValue", "patch", {},
        "pair_coeff 1 1 soil 2650 drucker_prager 0.7e6 0.3 19.8 0 0 fit tresca",
        "material of type(s) 1: drucker_prager fit 'tresca': must be exact, associated or nonassociated");
  error("CoeffNoExactFit", "patch", {}, "pair_coeff 1 1 soil 2650 drucker_prager 0.7e6 0.3 19.8 15 0",
        "material of type(s) 1: drucker_prager fit exact: no plane-strain fit is exact for dilatancy "
        "angle psi = 15 degrees");
  error("CoeffTensionNegative", "patch", {},
        "pair_coeff 1 1 soil 2650 drucker_prager 0.7e6 0.3 19.8 0 1e4 tension -5",
        "material of type(s) 1: drucker_prager tension = -5: the tensile strength must be >= 0 Pa");
  error("CoeffTensionBeyondApex", "patch", {},
        "pair_coeff 1 1 soil 2650 drucker_prager 0.7e6 0.3 19.8 0 1e4 tension 1e5",
        "material of type(s) 1: drucker_prager tension = 100000: the tensile strength must be in [0, "
        "27776.1] Pa, the mean stress at the apex of the cone k_c / (3 alpha_phi) of this phi and c "
        "(the apex limits the tension already)");
  error("CoeffDensity", "patch", {}, "pair_coeff 1 1 soil 0 0.7e6 0.3 19.8 0 0",
        "material of type(s) 1: density rho0 = 0 must be finite and > 0");
  error("CoeffBulkModulus", "patch", {}, "pair_coeff 1 1 soil 2650 -1 0.3 19.8 0 0",
        "material of type(s) 1: drucker_prager bulk modulus K = -1 must be finite and > 0");
  error("CoeffPoissonRatioHigh", "patch", {}, "pair_coeff 1 1 soil 2650 0.7e6 0.5 19.8 0 0",
        "material of type(s) 1: drucker_prager Poisson ratio nu = 0.5 must be in (-1, 0.5)");
  error("CoeffPoissonRatioLow", "patch", {}, "pair_coeff 1 1 soil 2650 0.7e6 -1 19.8 0 0",
        "material of type(s) 1: drucker_prager Poisson ratio nu = -1 must be in (-1, 0.5)");
  error("CoeffFrictionAngle", "patch", {}, "pair_coeff 1 1 soil 2650 0.7e6 0.3 90 0 0",
        "material of type(s) 1: drucker_prager friction angle phi = 90 must be in [0, 90) degrees");
  error("CoeffFrictionAngleNegative", "patch", {}, "pair_coeff 1 1 soil 2650 0.7e6 0.3 -5 0 0",
        "material of type(s) 1: drucker_prager friction angle phi = -5 must be in [0, 90) degrees");
  error("CoeffDilatancyAngle", "patch", {}, "pair_coeff 1 1 soil 2650 0.7e6 0.3 19.8 25 0",
        "material of type(s) 1: drucker_prager dilatancy angle psi = 25 must be in [0, phi = 19.8]");
  error("CoeffCohesion", "patch", {}, "pair_coeff 1 1 soil 2650 0.7e6 0.3 19.8 0 -1",
        "material of type(s) 1: drucker_prager cohesion c = -1 must be finite and >= 0");
  error("CoeffInfinite", "patch", {}, "pair_coeff 1 1 soil 2650 1e400 0.3 19.8 0 0",
        "material of type(s) 1: drucker_prager parameter K: '1e400' is not a finite number");
  error("CoeffWallUnknownOption", "patch", {}, "pair_coeff 2 2 wall 3",
        "material of type(s) 2: unknown wall option '3' (allowed: noslip, freeslip, friction <mu>, "
        "delta <degrees>, adhesion <c_a>, boundary mirror|extrapolate, drained)");
  error("CoeffWallFriction", "patch", {}, "pair_coeff 2 2 wall friction -1",
        "material of type(s) 2: wall friction coefficient mu = -1 must be finite and >= 0");
  error("CoeffWallFrictionNaN", "patch", {}, "pair_coeff 2 2 wall friction nan",
        "material of type(s) 2: wall friction coefficient mu = nan must be finite and >= 0");
  error("CoeffWallDelta", "patch", {}, "pair_coeff 2 2 wall delta -3",
        "material of type(s) 2: wall delta friction angle (degrees) = -3 must be finite and in [0, 90)");
  error("CoeffWallAdhesion", "patch", {}, "pair_coeff 2 2 wall delta 20 adhesion inf",
        "material of type(s) 2: wall adhesion value c_a (stress units) = inf must be finite and >= 0");
  // ---- saturated soil, free water, drained walls
  const std::string saturated = "pair_coeff 1 1 soil 2650 0.7e6 0.3 19.8 0 0 ";
  error("CoeffPorosityAlone", "patch", {}, saturated + "porosity 0.4",
        "material of type(s) 1: a saturated soil needs both porosity and permeability (missing: "
        "permeability)");
  error("CoeffPorosityOutOfRange", "patch", {}, saturated + "porosity 1.2 permeability 1e-4",
        "material of type(s) 1: pore water porosity = 1.2 must be finite and in (0, 1)");
  error("CoeffPermeabilityNegative", "patch", {}, saturated + "porosity 0.4 permeability -1",
        "material of type(s) 1: pore water permeability = -1 must be finite and >= 0 (hydraulic "
        "conductivity, m/s)");
  error("CoeffWaterDensity", "patch", {}, saturated + "porosity 0.4 permeability 1e-4 water_density -1",
        "material of type(s) 1: pore water water_density = -1 must be finite and > 0 (kg/m^3)");
  error("CoeffWaterModulus", "patch", {}, saturated + "porosity 0.4 permeability 1e-4 water_modulus 0",
        "material of type(s) 1: pore water water_modulus = 0 must be finite and > 0 (Pa)");
  error("CoeffSaturatedTooLight", "patch", {},
        "pair_coeff 1 1 soil 300 0.7e6 0.3 19.8 0 0 porosity 0.4 permeability 1e-4",
        "material of type(s) 1: the saturated density rho0 = 300 must exceed porosity * "
        "water_density = 400 (rho0 of a saturated soil is the mass of grains and water per volume)");
  error("CoeffWaterModulusMissing", "patch", {}, "pair_coeff 2 2 water 1000",
        "material of type(s) 2: water needs its bulk modulus K_w (Pa) after its density, got 0 value(s)");
  error("CoeffWaterModulusNegative", "patch", {}, "pair_coeff 2 2 water 1000 -2e7",
        "material of type(s) 2: water bulk modulus K_w = -2e7 must be finite and > 0 (Pa)");
  error("CoeffWaterDensityNegative", "patch", {}, "pair_coeff 2 2 water -1000 2e7",
        "material of type(s) 2: water needs its density rho_w, finite and > 0, got -1000");
  // a saturated soil's words on free water, and a value too many
  error("CoeffWaterPorosity", "patch", {}, "pair_coeff 2 2 water 1000 porosity 0.4",
        "material of type(s) 2: water takes no 'porosity' (free water is 'water rho_w K_w'); "
        "porosity is a word of a saturated soil: 'soil rho0 model parameters porosity n "
        "permeability k'");
  error("CoeffWaterPermeability", "patch", {}, "pair_coeff 2 2 water 1000 2e7 permeability 1e-4",
        "material of type(s) 2: water takes no 'permeability' (free water is 'water rho_w K_w'); "
        "permeability is a word of a saturated soil: 'soil rho0 model parameters porosity n "
        "permeability k'");
  error("CoeffWaterExtraValue", "patch", {}, "pair_coeff 2 2 water 1000 2e7 0.5",
        "material of type(s) 2: water takes one value after its density, its bulk modulus K_w (Pa) "
        "('water rho_w K_w'), got 2: 2e7 0.5");
  error("CoeffWallDrainedTwice", "patch", {}, "pair_coeff 2 2 wall drained drained",
        "material of type(s) 2: wall drained given twice");
  error("DrySoilWithPorePressure", "walls", {"sph_soil/set soil pore_pressure 100"}, "run 0 post no",
        "Pair sph/soil: 80 particle(s) of dry soil carry a pore pressure (atom 21 of type 1: 100); "
        "only a saturated soil (a material with porosity and permeability) or a drained wall has "
        "one: set it to 0 with 'sph_soil/set <group> pore_pressure 0'");
  out_of_range("SetPorePressureInfinite", "patch", {}, "sph_soil/set all pore_pressure 1e400",
        "Illegal sph_soil/set pore_pressure 1e400: must be a finite number", "1e400");
  error("SetGeostaticWaterShort", "patch", {}, "sph_soil/set all geostatic 0.3 2000 10 0.5 water 0.3",
        "Illegal sph_soil/set geostatic water: needs the water table's level and the water's "
        "density ('water level rho_w')");
  error("SetGeostaticWaterDensity", "patch", {}, "sph_soil/set all geostatic 0.3 2000 10 0.5 water 0.3 0",
        "Illegal sph_soil/set geostatic water density 0: must be > 0");
  error("FixTimestepAboveDiffusionLimit", "walls",
        {saturated + "porosity 0.4 permeability 1e-1 water_modulus 2e7", "timestep 1e-6"},
        "run 0 post no",
        "Fix sph/soil: timestep 1e-06 exceeds the stability limit 2.82432e-08 = 0.1 * min(h)^2 / D, "
        "D = 509.858 the pore pressure's largest diffusivity k K_w / (gamma_w n); use a smaller "
        "timestep or 'cfl 0.1'");
  error("CoeffUnknownKind", "patch", {}, "pair_coeff 1 1 clay 2650 0.7e6 0.3 19.8 0 0",
        "Incorrect args for pair_coeff sph/soil: unknown material kind 'clay' for types 1 1 "
        "(allowed: soil, wall, water; a material file takes '* * file name1 ... name2')");
  error("CoeffMixedTypes", "patch", {}, "pair_coeff 1 2 soil 2650 0.7e6 0.3 19.8 0 0",
        "a material belongs to atom types, so both type arguments must be the same (got 1 2)");
  error("CoeffTypeOutOfRange", "patch", {}, "pair_coeff 3 3 wall", "Numeric index 3 is out of bounds (1-2)");
  error("FileNameCount", "patch", {}, "pair_coeff * * good.soil sand",
        "a material file needs one name (or NULL) per atom type, 2 expected, 1 given");
  // NULL leaves a type to another style of pair_style hybrid; NULL for every type sets nothing
  error("FileAllNull", "patch", {}, "pair_coeff * * good.soil NULL NULL",
        "Incorrect args for pair_coeff sph/soil: every type of 'pair_coeff * * good.soil' is NULL, "
        "which gives no type a material (NULL leaves a type to another style of pair_style "
        "hybrid); name one of the file's materials (sand, rock) for each type of pair_style "
        "sph/soil");
  error("FileMissing", "patch", {}, "pair_coeff * * nosuchfile.soil sand rock",
        "Cannot open material file nosuchfile.soil for pair_coeff sph/soil");
  error("FileNameNotInFile", "patch", {}, "pair_coeff * * good.soil granite rock",
        "pair_coeff sph/soil: material granite for atom type 1 is not in file good.soil");
  error("FileParameterCount", "patch", {}, "pair_coeff * * short.soil sand NULL",
        "Invalid material file short.soil for pair_coeff sph/soil: line 2: material sand: "
        "drucker_prager needs 5 parameters (K nu phi psi c), got 4");
  error("FileDefinedTwice", "patch", {}, "pair_coeff * * twice.soil sand sand",
        "Invalid material file twice.soil for pair_coeff sph/soil: line 2: material sand is defined twice");
  error("FileEmpty", "patch", {}, "pair_coeff * * empty.soil sand sand",
        "Invalid material file empty.soil for pair_coeff sph/soil: no material defined");
  error("FileUnknownKind", "patch", {}, "pair_coeff * * kind.soil sand sand",
        "Invalid material file kind.soil for pair_coeff sph/soil: line 1: material sand: unknown kind "
        "'clay' (allowed: soil, wall, water)");
  error("FileNotANumber", "patch", {}, "pair_coeff * * word.soil sand sand",
        "Invalid material file word.soil for pair_coeff sph/soil: line 1: material sand: drucker_prager parameter phi: "
        "'forty-five' "
        "is not a finite number");

  // ---- set-ups that a run rejects
  error("RunWithoutH", "box", {"create_atoms 1 box", "sph_soil/set all mass 0.265 density 2650",
                               "pair_style sph/soil", SOIL, "pair_coeff 2 2 wall",
                               "fix integrate all sph/soil"},
        "run 0 post no",
        "Pair sph/soil: atom 1 has smoothing length h <= 0; set it with 'sph_soil/set <group> h <value>'");
  error("RunTypeWithoutMaterial", "patch", {SOIL, "fix integrate all sph/soil"}, "run 0 post no",
        "All pair coeffs are not set");
  error("RunTimestepTooLarge", "patch", {SOIL, "pair_coeff 2 2 wall", "fix integrate all sph/soil",
                                         "timestep 1e-3"},
        "run 0 post no",
        "Fix sph/soil: timestep 0.001 exceeds the stability limit 0.000116184 = 0.2 * min(h) / c_p; "
        "use a smaller timestep or 'cfl 0.1'");
  error("RunWallWithoutPlane", "walls", {"sph_soil/set floor nowall"}, "run 0 post no",
        "Pair sph/soil: 20 wall particle(s) have no wall plane (atom 1 of type 2 at 0.005 0.005 0); "
        "set it with 'sph_soil/set <group> wall px py pz nx ny nz'");
  error("RunWallPlaneBehindSoil", "walls", {"sph_soil/set floor wall 0 0.02 0 0 -1 0"},
        "run 0 post no",
        "Pair sph/soil: 20 wall particle(s) lie in front of their wall plane (atom 1: distance -0.015 "
        "along the normal 0 -1 0); the normal given to 'sph_soil/set <group> wall' must point into "
        "the soil, with the wall particles behind the plane");
  error("RunExtrapolatedWallFreeSlip", "walls", {"pair_coeff 2 2 wall freeslip boundary extrapolate"},
        "run 0 post no",
        "Pair sph/soil: wall type 2 has boundary extrapolate with freeslip: an extrapolated wall is "
        "no-slip (free slip and friction need the plane of 'boundary mirror')");
  error("RunExtrapolatedWallFriction", "walls", {"pair_coeff 2 2 wall delta 20 boundary extrapolate"},
        "run 0 post no",
        "Pair sph/soil: wall type 2 has boundary extrapolate with friction: an extrapolated wall is "
        "no-slip (free slip and friction need the plane of 'boundary mirror')");
  error("RunTwoIntegrators", "walls", {"fix again soil sph/soil"}, "run 0 post no",
        "Fix sph/soil integrate and again both integrate 80 particle(s) (e.g. atom 21); integrate each "
        "particle with one fix");
  error("RunWithoutPairStyle", "box", {"create_atoms 1 single 0.5 0.5 0", "fix integrate all sph/soil"},
        "run 0 post no", "Fix sph/soil requires pair_style sph/soil");

  // ---- fix sph/soil
  error("FixWithoutAtomStyle", "none", {"region box block 0 1 0 1 0 1", "create_box 1 box"},
        "fix f all sph/soil", "Fix sph/soil requires atom_style sph/soil");
  error("FixUnknownKeyword", "patch", {}, "fix f all sph/soil courant 0.1",
        "Illegal fix sph/soil keyword courant (allowed: cfl, dtmax, stepping, others)");
  error("FixOthersUnknown", "patch", {}, "fix f all sph/soil others warn",
        "Illegal fix sph/soil others warn (allowed: error, allow)");
  error("FixSteppingUnknown", "patch", {}, "fix f all sph/soil stepping individual",
        "Illegal fix sph/soil stepping individual (allowed: global, level)");
  error("FixKeywordWithoutValue", "patch", {}, "fix f all sph/soil cfl",
        "Illegal fix sph/soil command: keyword cfl needs a value");
  error("FixCflTooLarge", "patch", {}, "fix f all sph/soil cfl 2",
        "Illegal fix sph/soil cfl 2: must be in (0, 1]");
  out_of_range("FixCflInfinite", "patch", {}, "fix f all sph/soil cfl 1e999",
        "Illegal fix sph/soil cfl 1e999: must be a finite number in (0, 1]", "1e999");
  error("FixCflNotANumber", "patch", {}, "fix f all sph/soil cfl nan",
        "Illegal fix sph/soil cfl nan: must be a finite number in (0, 1]");
  error("FixDtmaxNegative", "patch", {}, "fix f all sph/soil cfl 0.1 dtmax -1",
        "Illegal fix sph/soil dtmax -1: must be > 0");
  error("FixDtmaxWithoutCfl", "patch", {}, "fix f all sph/soil dtmax 1e-5",
        "Illegal fix sph/soil dtmax 1e-05: it bounds the adaptive time step, which needs 'cfl C' too");
  warning("FixCflAboveMeasuredStable", "patch", {}, "fix f all sph/soil cfl 0.5",
          "Fix sph/soil cfl 0.5: above 0.2, the largest value measured stable (a geostatic column); "
          "expect the run to go unstable, 0.1 to 0.2 is usual");
  warning("FixGroupWithoutSoil", "walls", {"unfix integrate", "fix walls floor sph/soil"},
          "run 0 post no",
          "Fix sph/soil walls: group floor holds no soil particle (wall particles are never "
          "integrated): this fix moves nothing");

  // a geostatic state on the yield surface (phi 19.8: Drucker-Prager's default fit needs K0 >=
  // 0.58 here): at once where the materials are known, else at the run
  warning("GeostaticOnYieldSurface", "walls", {}, "sph_soil/set soil geostatic 0.1 2650 9.81 0.5",
          "sph_soil/set geostatic: K0 = 0.5 puts 80 particle(s) on or outside their material's "
          "yield surface (atom 21 of type 1");
  warning("GeostaticOnYieldSurfaceAtTheRun", "patch",
          {"sph_soil/set all geostatic 0.1 2650 9.81 0.5", SOIL, "pair_coeff 2 2 wall"},
          "run 0 post no",
          "sph_soil/set geostatic: K0 = 0.5 puts 100 particle(s) on or outside their material's "
          "yield surface (atom 1 of type 1");

  // ---- warnings of the pair style at a run
  // soil 2 mm off a drained floor, whose images follow it by half the 2 mm skin only
  warning("SoilLiftedBeyondTheDrainedWallsReach", "walls",
          {"change_box all boundary p f p", "pair_coeff 2 2 wall drained", "neighbor 0.002 bin",
           "displace_atoms soil move 0 0.002 0 units box"},
          "run 0 post no",
          "Pair sph/soil: soil has lifted 0.002 off a drained wall at step 0, more than half the "
          "neighbour skin (0.001): the wall no longer follows it, and its water pushes less as the "
          "gap widens (a larger skin, command neighbor, follows further)");
  warning("NeighModifyExcludeIgnored", "walls", {"neigh_modify exclude type 2 2"}, "run 0 post no",
          "Pair sph/soil builds its own neighbour list: neigh_modify exclude has no effect on it");
  warning("DensityFarFromReference", "walls", {"sph_soil/set soil density 2000 mass 0.2"},
          "run 0 post no",
          "Pair sph/soil: 80 soil particle(s) have a density more than 10% away from their material's "
          "rho0 (atom 21: 2000 against 2650); is 'sph_soil/set <group> density' missing?");
  warning("SmoothingLengthFarFromSpacing", "walls", {"sph_soil/set soil mass 1"}, "run 0 post no",
          "Pair sph/soil: 80 particle(s) have h/d outside [0.9, 3], with d = (m/rho)^(1/2) the spacing "
          "that their mass and density give (atom 21: h/d = 0.618 from h 0.012, m 1, rho 2650); usual "
          "is 1.2 to 2: check 'sph_soil/set ... mass ... density ... h'");

  warning("CoincidingParticles", "walls",
          {"create_atoms 1 single 5.5 5.5 0.0", "group twice id 101",
           "sph_soil/set twice mass 0.265 h 0.012 density 2650"},
          "run 0 post no",
          "Pair sph/soil: 1 pair(s) of particles closer than 1e-6 h (atoms 56 and 101 at 0.055 0.055 "
          "0): particles at the same place, created or read twice?");
  // in 2D two particles apart in z alone (a lattice finer than the box's thickness makes several
  // planes) are at the same place for the pair sums
  warning("CoincidingParticlesIn2DApartInZ", "walls",
          {"create_atoms 1 single 5.5 5.5 0.0", "group twice id 101",
           "sph_soil/set twice mass 0.265 h 0.012 density 2650", "set atom 101 z 0.003"},
          "run 0 post no",
          "Pair sph/soil: 1 pair(s) of particles closer than 1e-6 h (atoms 56 and 101 at 0.055 0.055 "
          "0): particles at the same place, created or read twice?");

  // ---- fix sph/soil/refine
  error("RefineWithoutAtomStyle", "none", {"region box block 0 1 0 1 0 1", "create_box 1 box"},
        "fix r all sph/soil/refine 10", "Fix sph/soil/refine requires atom_style sph/soil");
  error("RefineTooFewArguments", "patch", {}, "fix r all sph/soil/refine",
        "Illegal fix sph/soil/refine command: expected 'fix ID group sph/soil/refine N keyword value ...'");
  error("RefineEveryZero", "patch", {}, "fix r all sph/soil/refine 0",
        "Illegal fix sph/soil/refine N 0: must be >= 1");
  error("RefineEveryNotAnInteger", "patch", {}, "fix r all sph/soil/refine ten",
        "Illegal fix sph/soil/refine N ten: must be an integer >= 1");
  error("RefineThresholdNegative", "patch", {}, "fix r all sph/soil/refine 10 threshold -1",
        "Illegal fix sph/soil/refine threshold -1: must be >= 0");
  out_of_range("RefineThresholdInfinite", "patch", {}, "fix r all sph/soil/refine 10 threshold 1e400",
        "Illegal fix sph/soil/refine threshold 1e400: must be a finite number >= 0", "1e400");
  error("RefineSeparation", "patch", {}, "fix r all sph/soil/refine 10 separation 1",
        "Illegal fix sph/soil/refine separation 1: must be in (0, 1)");
  error("RefineSeparationZero", "patch", {}, "fix r all sph/soil/refine 10 separation 0",
        "Illegal fix sph/soil/refine separation 0: must be in (0, 1)");
  error("RefineSmoothing", "patch", {}, "fix r all sph/soil/refine 10 smoothing 1.5",
        "Illegal fix sph/soil/refine smoothing 1.5: must be in (0, 1)");
  error("RefineDref", "patch", {}, "fix r all sph/soil/refine 10 dref 0",
        "Illegal fix sph/soil/refine dref 0: must be > 0");
  error("RefineBuffer", "patch", {}, "fix r all sph/soil/refine 10 buffer 1.5",
        "Illegal fix sph/soil/refine buffer 1.5: must be in [0, 1]");
  error("StaticRefineBuffer", "patch", {}, "sph_soil/refine all buffer -0.5",
        "Illegal sph_soil/refine buffer -0.5: must be in [0, 1]");
  error("RefineEaseZero", "patch", {}, "fix r all sph/soil/refine 10 ease 0",
        "Illegal fix sph/soil/refine ease 0: must be > 0");
  error("RefineEaseWord", "patch", {}, "fix r all sph/soil/refine 10 ease soon",
        "Illegal fix sph/soil/refine ease soon: must be a time > 0 or no");
  error("RefineMaxlevel", "patch", {}, "fix r all sph/soil/refine 10 maxlevel 31",
        "Illegal fix sph/soil/refine maxlevel 31: must be in 1 to 30");
  error("RefineMaxlevelZero", "patch", {}, "fix r all sph/soil/refine 10 maxlevel 0",
        "Illegal fix sph/soil/refine maxlevel 0: must be in 1 to 30");
  error("RefineMergeZero", "patch", {}, "fix r all sph/soil/refine 10 merge 0",
        "Illegal fix sph/soil/refine merge 0: must be > 0");
  error("RefineMergeWord", "patch", {}, "fix r all sph/soil/refine 10 merge yes",
        "Illegal fix sph/soil/refine merge yes: must be a hold time > 0 or no");
  error("RefineTimestepTooLargeAfterSplit", "patch",
        {SOIL, "pair_coeff 2 2 wall", "sph_soil/set all strain 0.3 0 0 0 0 0",
         "fix integrate all sph/soil", "fix refine all sph/soil/refine 1", "timestep 1.0e-4"},
        "run 2 post no",
        "Fix sph/soil/refine: after splitting at step 1 the timestep 0.0001 exceeds the stability "
        "limit 5.80921e-05 = 0.2 * min(h) / c_p; use 'cfl 0.1' in fix sph/soil (adaptive step) or a "
        "timestep <= 5.80921e-05");
  error("RefineEveryOffTheLevelsSteps", "patch",
        {SOIL, "pair_coeff 2 2 wall", "fix integrate all sph/soil cfl 0.1 stepping level",
         "fix refine all sph/soil/refine 10 maxlevel 2"},
        "run 0 post no",
        "Fix sph/soil/refine N 10: with fix sph/soil stepping level, N must be a multiple of "
        "2^maxlevel = 4, the steps at which all levels are synchronised");
  error("RefineRegion", "patch", {}, "fix r all sph/soil/refine 10 region nowhere",
        "fix sph/soil/refine region nowhere does not exist");
  error("RefineSince", "patch", {}, "fix r all sph/soil/refine 10 since birth",
        "Illegal fix sph/soil/refine since birth: must be split or start");
  error("RefineUnknownKeyword", "patch", {}, "fix r all sph/soil/refine 10 ratio 2",
        "Illegal fix sph/soil/refine keyword ratio (allowed: criterion, region, buffer, threshold, since, separation, "
        "smoothing, dref, maxlevel, merge, ease)");
  error("RefineUnknownCriterion", "patch", {}, "fix r all sph/soil/refine 10 criterion stress",
        "Illegal fix sph/soil/refine criterion stress (allowed: strain, all, v_name)");
  error("RefineKeywordOfAnotherCriterion", "patch", {}, "fix r all sph/soil/refine 10 criterion all threshold 0.1",
        "Illegal fix sph/soil/refine threshold: a keyword of criterion strain, not of criterion all");
  error("RefineCriterionAfterItsKeywords", "patch", {}, "fix r all sph/soil/refine 10 threshold 0.1 criterion all",
        "Illegal fix sph/soil/refine criterion all: give it before threshold, a keyword of criterion strain");
  error("RefineVariableMissing", "walls", {"fix r soil sph/soil/refine 10 criterion v_nope"}, "run 0 post no",
        "fix sph/soil/refine criterion v_nope: variable nope does not exist");
  error("RefineVariableNotAtomStyle", "walls",
        {"variable flat equal 1", "fix r soil sph/soil/refine 10 criterion v_flat"}, "run 0 post no",
        "fix sph/soil/refine criterion v_flat: variable flat must be atom-style");
  error("RefineKeywordWithoutValue", "patch", {}, "fix r all sph/soil/refine 10 threshold",
        "Illegal fix sph/soil/refine command: keyword threshold needs a value");
  error("RefineWithoutIntegrator", "walls", {"unfix integrate", "fix r soil sph/soil/refine 10"},
        "run 0 post no", "Fix sph/soil/refine requires fix sph/soil");
  error("RefineWallParticles", "walls", {"fix r all sph/soil/refine 10"}, "run 0 post no",
        "Fix sph/soil/refine: group all contains 20 wall particles (e.g. type 2); refine soil "
        "particles only");
  warning("RefineUnstableParameters", "walls", {"fix r soil sph/soil/refine 10 separation 0.7"},
          "run 0 post no",
          "Fix sph/soil/refine: separation 0.7 and smoothing 0.5 (h/d = 1.2) are in the unstable "
          "region for d_ij/d_ref = 1.0 (unstable (Cond. 2)): expect clumps and cracks under "
          "compression; see doc/refinement_parameters.rst");

  // ---- sph_soil/refine
  error("StaticRefineBeforeBox", "none", {}, "sph_soil/refine all",
        "sph_soil/refine command before simulation box is defined");
  error("StaticRefineWithoutAtomStyle", "none", {"region box block 0 1 0 1 0 1", "create_box 1 box"},
        "sph_soil/refine all", "sph_soil/refine command requires atom_style sph/soil");
  error("StaticRefineUnknownGroup", "patch", {}, "sph_soil/refine nogroup",
        "Could not find sph_soil/refine group ID nogroup");
  error("StaticRefineSeparation", "patch", {}, "sph_soil/refine all separation 1.2",
        "Illegal sph_soil/refine separation 1.2: must be in (0, 1)");
  error("StaticRefineSmoothing", "patch", {}, "sph_soil/refine all smoothing -0.5",
        "Illegal sph_soil/refine smoothing -0.5: must be in (0, 1)");
  error("StaticRefineRegion", "patch", {}, "sph_soil/refine all region nowhere",
        "sph_soil/refine region nowhere does not exist");
  error("StaticRefineUnknownKeyword", "patch", {}, "sph_soil/refine all maxlevel 2",
        "Illegal sph_soil/refine keyword maxlevel (allowed: criterion, region, buffer, threshold, since, separation, "
        "smoothing, dref)");
  error("StaticRefineUnknownCriterion", "patch", {}, "sph_soil/refine all criterion 0.5",
        "Illegal sph_soil/refine criterion 0.5 (allowed: strain, all, v_name)");
  error("StaticRefineWithoutPairStyle", "box",
        {"create_atoms 1 box", "sph_soil/set all mass 0.265 h 0.012 density 2650"}, "sph_soil/refine all",
        "sph_soil/refine command requires pair_style sph/soil");
  error("StaticRefineWallParticles", "walls", {}, "sph_soil/refine all",
        "sph_soil/refine: group all contains 20 wall particles; refine soil particles only");
  error("StaticRefineOutOfTheBox", "fixedbox", {}, "sph_soil/refine all separation 0.9",
        "sph_soil/refine: splitting 19 particle(s) would put daughters outside the box through a fixed "
        "boundary (atom 1: a daughter at -0.0045 -0.0045 0); keep the split particles separation * "
        "d_p / 2 away from fixed boundaries (e.g. with a region), or make the boundary shrink-wrapped");

  // ---- compute sph/soil/atom
  error("ComputeWithoutAtomStyle", "none", {"region box block 0 1 0 1 0 1", "create_box 1 box"},
        "compute c all sph/soil/atom", "Compute sph/soil/atom requires atom_style sph/soil");
  error("ComputeUnknownValue", "patch", {}, "compute c all sph/soil/atom stress",
        "Illegal compute sph/soil/atom value stress (allowed: sxx syy szz sxy sxz syz pressure "
        "pore_pressure total_sxx total_syy total_szz drained_inflow sqrtJ2 strain yielded density h "
        "level neighbours shear_strain shear_strain_rate step_period)");

  // ---- data files (the rank that reads the atom raises the error)
  data("DataMassNegative", "1 1 -1.0 0.1 1000 0 0.5 0.5 0", "",
       "Invalid mass -1 of atom 1 in Atoms section of data file: must be finite and > 0");
  c.push_back({"DataMassInfinite", "data",
               {"write bad.data " + data_file("1 1 1e400 0.1 1000 0 0.5 0.5 0")}, "read_data bad.data",
               "Invalid mass inf of atom 1 in Atoms section of data file: must be finite and > 0",
               false, true, "Floating point number 1e400 in input script or data file is out of range"});
  data("DataSmoothingLength", "1 1 1.0 -0.1 1000 0 0.5 0.5 0", "",
       "Invalid smoothing length h -0.1 of atom 1 in Atoms section of data file: must be >= 0");
  data("DataDensity", "1 1 1.0 0.1 0 0 0.5 0.5 0", "",
       "Invalid density 0 of atom 1 in Atoms section of data file: must be > 0");
  data("DataLevelNegative", "1 1 1.0 0.1 1000 -2 0.5 0.5 0", "",
       "Invalid refinement level -2 of atom 1 in Atoms section of data file: must be in 0 to 30");
  data("DataLevelTooDeep", "1 1 1.0 0.1 1000 31 0.5 0.5 0", "",
       "Invalid refinement level 31 of atom 1 in Atoms section of data file: must be in 0 to 30");
  c.push_back({"DataStressInfinite", "data",
               {"write bad.data " + data_file("1 1 1.0 0.1 1000 0 0.5 0.5 0", "1 0 0 0 -1e400 0 0 0 0 0")},
               "read_data bad.data",
               "Invalid velocity or stress of atom 1 in Velocities section of data file: must be finite "
               "(got velocity 0 0 0, stress -inf 0 0 0 0 0)",
               false, true, "Floating point number -1e400 in input script or data file is out of range"});
  // ---- what a new user trips over (issue 26): each stops with a message that names the cause
  error("MaterialFileNotANumber", "patch", {}, "pair_coeff * * nan.soil sand NULL",
        "Invalid material file nan.soil for pair_coeff sph/soil: line 1: material sand: "
        "drucker_prager parameter K: 'nan' is not a finite number");
  error("DensityNeverSet", "walls",
        {"sph_soil/set soil density 1 geostatic 0.1 2650 9.81 0.5",
         "fix down soil gravity 9.81 vector 0 -1 0"},
        "run 20 post no",
        "Fix sph/soil: 80 soil particle(s) have a density below exp(-1) = 0.368 times their "
        "material's rho0, the least a soil particle can have (atom 21: 1 against rho0 2650); set "
        "it with 'sph_soil/set <group> density'");
  error("MohrCoulombTensionAtTheApex", "walls",
        {"pair_coeff 1 1 soil 2650 mohr_coulomb 0.7e6 0.3 30 0 1e4",
         "sph_soil/set soil stress 17300 17300 17300 0 0 0", "group one id 45",
         "velocity one set 1e308 1e308 0 units box"},
        "run 10 post no",
        "soil particle(s) are in tension at the apex of their yield surface, where SPH is unstable: "
        "give the soil a tension cut-off ('tension 0' of its model)");
  error("SoilBehindAWall", "walls", {"set atom 25 y 0.018", "group one id 25",
                                     "velocity one set 1e308 1e308 0 units box"},
        "run 10 post no",
        "soil particle(s) are behind a wall's plane: the soil crossed a wall (thicker walls, or a "
        "smaller time step)");
  error("HugeSmoothingLength", "patch", {SOIL, "pair_coeff 2 2 wall", "sph_soil/set all h 100"}, "run 0 post no",
        "Pair sph/soil: h/d up to 1e+04 gives each particle about");
  error("RefinementBeyondTheMemory", "patch",
        {SOIL, "pair_coeff 2 2 wall", "fix integrate all sph/soil cfl 0.1", "fix refine all sph/soil/refine 1 criterion all maxlevel 30",
         "shell putenv SPH_SOIL_MEMORY_LIMIT=1e9"},
        "run 10 post no",
        "and SPH_SOIL_MEMORY_LIMIT gives it 1 GB); lower maxlevel or limit the refinement to a "
        "region");
  warning("GeostaticAcrossGravity", "walls",
          {"sph_soil/set soil geostatic 0.1 2650 9.81 0.5 vertical x",
           "fix down soil gravity 9.81 vector 0 -1 0"},
          "run 0 post no",
          "Pair sph/soil: sph_soil/set geostatic put the overburden along x but gravity points along "
          "y (0 -9.81 0): add 'vertical y' to geostatic");
  // soil that fix sph/soil integrates and another fix moves too (issue 47): each fix named
  const std::string moved_twice =
      " both move 80 particle(s) (e.g. atom 21 of type 1): fix sph/soil integrates soil and free "
      "water, and a particle that two fixes move moves twice per step; make a structure of wall "
      "particles (pair_coeff I I wall), which fix sph/soil never moves, or add 'others allow' to "
      "fix sph/soil integrate if fix ";
  error("SoilInARigidBody", "walls", {"fix body soil rigid single"}, "run 0 post no",
        "Fix sph/soil integrate and fix body (rigid)" + moved_twice + "body is meant to move them too");
  error("SoilInARigidNveBody", "walls", {"fix body soil rigid/nve single"}, "run 0 post no",
        "Fix sph/soil integrate and fix body (rigid/nve)" + moved_twice + "body is meant to move them too");
  error("SoilUnderFixMove", "walls", {"fix lift all move linear 0 0.1 0 units box"}, "run 0 post no",
        "Fix sph/soil integrate and fix lift (move)" + moved_twice + "lift is meant to move them too");
  error("SoilUnderFixNve", "walls", {"fix again soil nve"}, "run 0 post no",
        "Fix sph/soil integrate and fix again (nve)" + moved_twice + "again is meant to move them too");
  // ('others allow': the user means it; LAMMPS warns of atoms integrated twice itself)
  warning("SoilUnderFixNveAllowed", "walls",
          {"unfix integrate", "fix integrate soil sph/soil others allow", "fix again soil nve"},
          "run 0 post no", "One or more atoms are time integrated more than once");
  warning("SoilInARigidBodyWithoutIntegrator", "walls", {"unfix integrate", "fix body soil rigid single"},
          "run 0 post no",
          "Fix body (rigid) moves soil particles that no fix sph/soil integrates as a rigid body, "
          "whose stress and density never change: a structure is made of wall particles "
          "(pair_coeff I I wall), soil particles are integrated by fix sph/soil");
  // A line with a wrong count of values: LAMMPS counts them before the atom style sees the line
  // (Atom::data_atoms, data_vels, in every release from 29Sep2021 to 4Jul2026), so the message
  // is LAMMPS's, which shows the line; the columns are in doc/atom_style_sph_soil.rst, where
  // LAMMPS's error page sends the user (its "data file" error, err0002)
  c.push_back({"DataColumnCount", "data", {"write bad.data " + data_file("1 1 1.0 0.1 1000 0 0.5 0.5")},
               "read_data bad.data", "Incorrect format in Atoms section of data file: 1 1 1.0 0.1 1000 0 "
               "0.5 0.5", false, true, "Incorrect atom format in data file"});
  c.push_back({"DataVelocityColumnCount", "data",
               {"write bad.data " + data_file("1 1 1.0 0.1 1000 0 0.5 0.5 0", "1 0 0 0 -1 -1")},
               "read_data bad.data", "Incorrect format in Velocities section of data file: 1 0 0 0 -1 -1",
               false, true, "Incorrect velocity format in data file"});
  return c;
}

class BadInputs : public SoilTest, public ::testing::WithParamInterface<BadInput> {
 protected:

  // the fixture's set-ups:
  //  none:     units si only
  //  box:      2D, atom_style sph/soil, a box with 2 types, no atoms
  //  patch:    + a periodic 10 x 10 lattice of soil (type 1, spacing 1 cm), mass, h, density,
  //            pair_style sph/soil (no coefficients), material files in the working directory
  //  walls:    + the bottom two rows wall particles (type 2, group floor, plane y = 0.02),
  //            materials, fix integrate on the soil, a time step
  //  fixedbox: the patch in a box with fixed boundaries, fully set up
  //  data:     atom_style sph/soil
  void prepare(const std::string &setup)
  {
    if (setup == "none") return;
    if (setup == "data") return command("atom_style sph/soil");
    command("dimension 2");
    command(setup == "fixedbox" ? "boundary f f p" : "boundary p p p");
    command("atom_style sph/soil");
    command("atom_modify map array");
    // (on the fixed box, lattice sites on its lower edges)
    command(setup == "fixedbox" ? "lattice sq 0.01" : "lattice sq 0.01 origin 0.5 0.5 0.0");
    command("region box block 0 10 0 10 -0.5 0.5");
    command("create_box 2 box");
    if (setup == "box") return;
    command("create_atoms 1 box");
    command("sph_soil/set all mass 0.265 h 0.012 density 2650");
    command("pair_style sph/soil");
    if (rank() == 0)
      for (const auto &file : FILES) std::ofstream(file[0]) << file[1];
    MPI_Barrier(MPI_COMM_WORLD);
    if (setup == "patch") return;
    command(SOIL);
    command("pair_coeff 2 2 wall");
    command("timestep 1e-5");
    if (setup == "fixedbox") return;
    command("region bottom block INF INF 0 2 INF INF");
    command("set region bottom type 2");
    command("group floor type 2");
    command("group soil type 1");
    command("sph_soil/set floor wall 0.0 0.02 0.0 0.0 1.0 0.0");
    command("fix integrate soil sph/soil");
  }

  // (a case may set the node's memory limit with shell putenv: it must not reach the next)
  void TearDown() override
  {
    unsetenv("SPH_SOIL_MEMORY_LIMIT");
    SoilTest::TearDown();
  }

  void run_before(const std::vector<std::string> &lines)
  {
    for (const auto &line : lines) {
      if (line.compare(0, 6, "write ") == 0) {    // write FILE TEXT
        const auto space = line.find(' ', 6);
        if (rank() == 0) std::ofstream(line.substr(6, space - 6)) << line.substr(space + 1);
        MPI_Barrier(MPI_COMM_WORLD);
      } else {
        command(line);
      }
    }
  }
};

}    // namespace

TEST_P(BadInputs, StopsOrWarnsWithTheExactMessage)
{
  const BadInput &c = GetParam();
  if (c.one_rank && nprocs() > 1) GTEST_SKIP() << "an error of the rank that reads the atom";
  HIDE_OUTPUT([&] {
    prepare(c.setup);
    run_before(c.before);
  });
  if (c.warning) {
    std::string thrown;
    ::testing::internal::CaptureStdout();
    try {
      command(c.command);
    } catch (LAMMPSException &e) {
      thrown = e.what();
    }
    const std::string output = ::testing::internal::GetCapturedStdout();
    EXPECT_EQ(thrown, "") << "a warning was expected, not an error";
    if (rank() == 0) EXPECT_THAT(output, ::testing::HasSubstr("WARNING: " + c.message));
  } else if (c.lammps_message.empty()) {
    EXPECT_LAMMPS_ERROR(".*" + escape(c.message) + ".*", command(c.command));
  } else {
    EXPECT_LAMMPS_ERROR(".*(" + escape(c.message) + "|" + escape(c.lammps_message) + ").*",
                        command(c.command));
  }
}

// not bad input: NULL in a material file's line leaves the type to another style of pair_style
// hybrid, which takes it (the LAMMPS convention, as for eam/alloy files)
TEST_F(SoilTest, NullInAMaterialFileLeavesTheTypeToAnotherHybridStyle)
{
  HIDE_OUTPUT([&] {
    for (const auto &line :
         {"dimension 2", "boundary p p p", "atom_style sph/soil", "atom_modify map array",
          "lattice sq 0.01 origin 0.5 0.5 0.0", "region box block 0 10 0 10 -0.5 0.5",
          "create_box 2 box", "create_atoms 1 box", "region top block INF INF 8 10 INF INF",
          "set region top type 2", "sph_soil/set all mass 0.265 h 0.012 density 1850"})
      command(line);
    if (rank() == 0) std::ofstream("good.soil") << FILES[0][1];
    MPI_Barrier(MPI_COMM_WORLD);
    command("pair_style hybrid sph/soil zero 0.02");
    command("pair_coeff * * sph/soil good.soil sand NULL");
    command("pair_coeff 1 2 zero");
    command("pair_coeff 2 2 zero");
    command("fix integrate all sph/soil");
    command("timestep 1e-5");
  });
  std::string thrown;
  ::testing::internal::CaptureStdout();
  try {
    command("run 1 post no");
  } catch (LAMMPSException &e) {
    thrown = e.what();
  }
  ::testing::internal::GetCapturedStdout();
  EXPECT_EQ(thrown, "");
}

INSTANTIATE_TEST_SUITE_P(SPHSoil, BadInputs, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<BadInput> &info) { return info.param.name; });
